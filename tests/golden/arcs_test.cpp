// Circular moves: exact when the rotary axes stand still, the plane mapped through the setup
// rotation; hand-derived expected values.
#include <cmath>

#include <catch2/catch.hpp>

#include <kin5/kin5.hpp>

#include "program_builder.hpp"

using kin5::machines::dmu_80p;
using kin5::machines::sajo_12000p;
using kin5::program::arc_plane;
using kin5::program::motion_kind;

namespace {

// SAJO, tool at A = a_deg (−90°: along +Y_s), G17 arc from (10, 0, 5) to (0, 10, 5) about (0, 0, 5).
kin5::program::program sajo_arc(motion_kind direction, double a_deg = -90.0) {
  auto p = kin5::test::tcp_program(kin5::program::id_of<kin5::program::siemens::dialect>(), "arc.mpf");
  kin5::test::add_motion(p, {10, 0, 5, a_deg, 0.0, std::nullopt, 800.0});
  auto& arc = kin5::test::add_motion(p, {0, 10, 5, std::nullopt, std::nullopt, std::nullopt, std::nullopt}, direction);
  arc.arc = kin5::program::arc_words{arc_plane::xy, kin5::vec3{0, 0, 5}, std::nullopt};
  return p;
}

}  // namespace

TEST_CASE("G17 arc on the SAJO becomes a G18 arc on the DMU 80P, same direction") {
  // T(x, y, z) = (−x, z, y): start (−10, 5, 0), end (0, 5, 10), centre (0, 5, 0); normal
  // T·Z_s = +Y_d, so the plane is ZX (G18) and the sense about the normal is kept. Check of the
  // sense by hand: a right-handed quarter turn about +Y takes (−1, 0, 0) to (0, 0, 1), i.e. the
  // start radius onto the end radius — a counter-clockwise (G3) arc, like the source.
  for (motion_kind direction : {motion_kind::arc_ccw, motion_kind::arc_cw}) {
    const auto t = kin5::translate<sajo_12000p, dmu_80p>(sajo_arc(direction), {});
    REQUIRE(t.ok());
    REQUIRE(t.output.blocks.size() == 3);
    const auto& b = t.output.blocks[2];
    CHECK(b.motion == direction);
    REQUIRE(b.arc.has_value());
    CHECK(b.arc->plane == arc_plane::zx);
    REQUIRE(b.arc->centre_mm.has_value());
    CHECK(kin5::norm(*b.arc->centre_mm - kin5::vec3{0, 5, 0}) <= 1e-12);
    CHECK(std::abs(*b.axes.x_mm - 0.0) <= 1e-12);
    CHECK(std::abs(*b.axes.z_mm - 10.0) <= 1e-12);
    CHECK_FALSE(b.axes.has_rotary());  // the rotary axes stand still
    CHECK(b.feed == std::nullopt);     // tcp: F as written (modal 800)
  }
}

TEST_CASE("an arc whose normal maps to a negative axis changes direction") {
  // Setup: half turn about X, so Z → −Z: G17 stays G17 but clockwise and counter-clockwise swap.
  // The tool (A = 0: +Z) becomes −Z, which the SAJO reaches at B = 180°.
  const kin5::rigid_transform flip{kin5::rotation(kin5::unit_x, kin5::radians{kin5::pi}), {}};
  const auto t = kin5::translate<sajo_12000p, sajo_12000p>(sajo_arc(motion_kind::arc_ccw, 0.0), kin5::test::options(kin5::feed_policy::tcp, kin5::program::id_of<kin5::program::heidenhain::dialect>(), flip));
  REQUIRE(t.ok());
  const auto& b = t.output.blocks[2];
  CHECK(b.motion == motion_kind::arc_cw);
  CHECK(b.arc->plane == arc_plane::xy);
  // End (0, 10, 5) → (0, −10, −5); centre (0, 0, 5) → (0, 0, −5).
  CHECK(std::abs(*b.axes.y_mm - -10.0) <= 1e-12);
  CHECK(kin5::norm(*b.arc->centre_mm - kin5::vec3{0, 0, -5}) <= 1e-12);
}

TEST_CASE("an arc plane without a principal image is an error, never linearised") {
  const kin5::rigid_transform tilt{kin5::rotation(kin5::unit_x, kin5::radians{0.5}), {}};
  const auto t = kin5::translate<sajo_12000p, sajo_12000p>(sajo_arc(motion_kind::arc_ccw, 0.0), kin5::test::options(kin5::feed_policy::tcp, kin5::program::id_of<kin5::program::heidenhain::dialect>(), tilt));
  REQUIRE_FALSE(t.ok());
  REQUIRE(t.errors.size() == 1);
  CHECK(t.errors[0].where.line == 3);
  CHECK(t.errors[0].message.rfind("circular move cannot be mapped: plane", 0) == 0);
}

TEST_CASE("an arc during which the rotary axes move is an error") {
  auto p = sajo_arc(motion_kind::arc_ccw);
  p.blocks[2].axes.b_deg = 10.0;
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(p, {});
  REQUIRE_FALSE(t.ok());
  CHECK(t.errors.at(0).where.line == 3);
  CHECK(t.errors.at(0).message.rfind("circular move cannot be mapped", 0) == 0);
}
