// Branch choice on a path through the SAJO's pole (u = +Y_s, A = −90°): the planner crosses to
// the other branch instead of turning the table half a turn, and says so with the line.
#include <cmath>

#include <catch2/catch.hpp>

#include <kin5/kin5.hpp>

#include "program_builder.hpp"

using kin5::machines::sajo_12000p;

TEST_CASE("a path through the SAJO pole switches branch instead of a half turn of B, with a warning") {
  // CL path: the tool tilts from A = −80° to A = −100° at B = 40° (as angles of the SAJO).
  // Staying on one branch costs 180° of B (e.g. (−80°, 40°) → (−80°, 220°)); switching costs
  // 20° of A (K3).
  auto u = [](double a, double b) {
    return kin5::tool_axis<sajo_12000p>({kin5::to_radians(kin5::degrees{b}), kin5::to_radians(kin5::degrees{a})});
  };
  kin5::program::program cl;
  cl.language = kin5::program::id_of<kin5::program::apt::dialect>();
  cl.file = "pole.cl";
  const double a_values[] = {-80.0, -100.0};
  for (double a : a_values) {
    auto& b = kin5::test::add_block(cl);
    b.motion = kin5::program::motion_kind::linear;
    b.axes.x_mm = 0.0, b.axes.y_mm = 0.0, b.axes.z_mm = 0.0;
    b.axes.tool_axis = u(a, 40.0);
  }
  const auto t = kin5::post<sajo_12000p>(cl, kin5::program::id_of<kin5::program::siemens::dialect>());
  REQUIRE(t.ok());
  REQUIRE(t.output.blocks.size() == 2);
  // Two optimal paths tie (K3 mirrors A about −90° and turns B by 180°): (−80°, 40°) → (−100°, 40°)
  // and (−100°, 220°) → (−80°, 220°). Either way: 20° of travel, a branch switch, the same axes.
  const auto& first = t.output.blocks[0].axes;
  const auto& second = t.output.blocks[1].axes;
  const double travel = std::abs(*second.a_deg - *first.a_deg) + std::abs(*second.b_deg - *first.b_deg);
  CHECK(std::abs(travel - 20.0) <= 1e-9);
  CHECK(std::abs(std::abs(*second.a_deg - *first.a_deg) - 20.0) <= 1e-9);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& w = t.output.blocks[k].axes;
    CHECK(kin5::norm(u(*w.a_deg, *w.b_deg) - u(a_values[k], 40.0)) <= 1e-12);
  }
  REQUIRE(t.warnings.size() == 1);
  CHECK(t.warnings[0].where.line == 2);
  CHECK(t.warnings[0].message.find("branch switch") != std::string::npos);
}

TEST_CASE("a run of pole blocks takes the free angle of its non-pole neighbour") {
  // DMU 80P: tool along +Z is its pole (B = 0, C free). Five vertical blocks, then B = 30°, C = 70°.
  // The vertical blocks take C = 70° from the block after them: the only travel is 30° of B.
  using kin5::machines::dmu_80p;
  kin5::program::program cl;
  cl.language = kin5::program::id_of<kin5::program::apt::dialect>();
  cl.file = "vertical.cl";
  for (int k = 0; k < 6; ++k) {
    auto& b = kin5::test::add_block(cl);
    b.motion = kin5::program::motion_kind::linear;
    b.axes.x_mm = k, b.axes.y_mm = 0.0, b.axes.z_mm = 0.0;
    b.axes.tool_axis = k < 5 ? kin5::unit_z
                             : kin5::tool_axis<dmu_80p>({kin5::to_radians(kin5::degrees{70.0}),
                                                         kin5::to_radians(kin5::degrees{30.0})});
  }
  const auto t = kin5::post<dmu_80p>(cl, kin5::program::id_of<kin5::program::heidenhain::dialect>());
  REQUIRE(t.ok());
  REQUIRE(t.output.blocks.size() == 6);
  for (std::size_t k = 0; k < 6; ++k) {
    CAPTURE(k);
    CHECK(std::abs(*t.output.blocks[k].axes.c_deg - 70.0) <= 1e-9);
    CHECK(std::abs(*t.output.blocks[k].axes.b_deg - (k < 5 ? 0.0 : 30.0)) <= 1e-9);
  }
}
