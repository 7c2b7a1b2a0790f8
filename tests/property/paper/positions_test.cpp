// The papers' position formulas against the general chain (G6)–(G8) on their domains: Tian et
// al. 2010 eqs (1)–(5) (TCP displacement of the SAJO 12000P), Liu 2010 eqs (6)–(10) (DMU 50V
// workpiece transform), Ji eq (11) (A/C table), and the patent's fixture-offset move (K26).
// Each printed form is shown to be the chain of a machine whose one angle sense is flipped (the
// erratum), and the corrected form the chain of the catalog machine.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cmath>

#include <kin5/kinematics.hpp>
#include <kin5/paper/cn1624613.hpp>
#include <kin5/paper/ji_ac_table.hpp>
#include <kin5/paper/liu_dmu50v.hpp>
#include <kin5/paper/tian2010.hpp>

#include "generators.hpp"

using kin5::vec3;
using paper_test::max_abs_diff;
using paper_test::uniform;

namespace {

kin5::radians rad(double deg) { return kin5::to_radians(kin5::degrees{deg}); }

rc::Gen<vec3> point(double half_width) {
  return rc::gen::apply([](double x, double y, double z) { return vec3{x, y, z}; }, uniform(-half_width, half_width),
                        uniform(-half_width, half_width), uniform(-half_width, half_width));
}

/// (G8) for the tip p with rotary angles `rotary`: the slides from (G7), then the untracked point.
kin5::vec3 chain_untracked(const kin5::machine_model& m, const kin5::rotary_values& rotary, const vec3& p,
                           const kin5::run_inputs& in) {
  const vec3 slides = kin5::linear_axes_for(m, rotary, in.work_offset.map_point(p), in);
  return kin5::untracked_point(m, slides, in);
}

/// `g` with its first rotary axis through `point` and, when `flip`, the other angle sense.
kin5::machine_model variant(kin5::machine_geometry g, std::size_t axis, bool flip, const vec3& point_mm,
                            bool move_point = true) {
  if (move_point) g.rotary[axis].point_mm = point_mm;
  if (flip)
    g.rotary[axis].sense = g.rotary[axis].sense == kin5::angle_sense::physical ? kin5::angle_sense::tool_relative
                                                                            : kin5::angle_sense::physical;
  return kin5::machine_model::from(g);
}

}  // namespace

TEST_CASE("Tian et al. 2010 eqs (1)-(5): the TCP displacement is (G8) of the SAJO 12000P", "[paper][tian][chain]") {
  using namespace kin5::paper::tian2010;
  const auto& sajo = kin5::machines::sajo_12000p::model;
  const double pivot = sajo.geometry.tool.pivot_length_mm;
  // The paper turns the table about its centre at the machine origin.
  const auto catalog_sense = variant(sajo.geometry, 0, false, {0, 0, 0});
  const auto table_turns_plus_b = variant(sajo.geometry, 0, true, {0, 0, 0});
  rc::prop("printed (5) = (G8) with the table turning +B; corrected (5) = (G8) of the catalog machine", [&] {
    const vec3 v = *point(300), v0 = *point(300);
    const double tool = *uniform(0, 300), a = *uniform(-120, 30), b = *uniform(-360, 360);
    const kin5::run_inputs in{tool, {kin5::mat3::identity(), v0}};
    const kin5::rotary_values angles{rad(b), rad(a)};  // chain order: B, A
    RC_ASSERT(max_abs_diff(eq5_v_prime_printed(v, v0, pivot + tool, a, b),
                           chain_untracked(table_turns_plus_b, angles, v, in)) < 1e-9);
    RC_ASSERT(max_abs_diff(eq5_v_prime_corrected(v, v0, pivot + tool, a, b),
                           chain_untracked(catalog_sense, angles, v, in)) < 1e-9);
  });
  SECTION("E4: the printed table sign moves the point wherever the table turns it") {
    const vec3 v{40, 10, -25}, v0{100, -20, 60};
    CHECK(max_abs_diff(eq5_v_prime_printed(v, v0, 300, -30, 25), eq5_v_prime_corrected(v, v0, 300, -30, 25)) > 10.0);
    CHECK(max_abs_diff(eq5_v_prime_printed(v, v0, 300, -30, 0), eq5_v_prime_corrected(v, v0, 300, -30, 0)) < 1e-12);
  }
  rc::prop("E3: (4) with the row vector [0 0 -l] is (0, l sin A, l (1 - cos A))", [] {
    const double l = *uniform(0, 500), a = *uniform(-180, 180);
    const double s = std::sin(a * kin5::pi / 180), c = std::cos(a * kin5::pi / 180);
    RC_ASSERT(max_abs_diff(eq4_va(l, eq3_ma(a)), vec3{0, l * s, l * (1 - c)}) < 1e-12);
  });
}

TEST_CASE("Liu 2010 eqs (6)-(10): the workpiece transform is (G8) of the DMU 50V", "[paper][liu][chain]") {
  using namespace kin5::paper::liu_dmu50v;
  const auto& dmu = kin5::machines::dmu_50v::model;
  const double h = kin5::machines::dmu_50v_h_mm;
  const auto c_physical = variant(dmu.geometry, 0, true, {}, false);
  rc::prop("corrected (10) = (G8) of dmu-50v; printed R1 with corrected R2 = (G8) with C physical (E20)", [&] {
    const vec3 p = *point(300), origin = *point(300);
    const double b = *uniform(0, 180), c = *uniform(-360, 360);
    const kin5::run_inputs in{0.0, {kin5::mat3::identity(), origin}};
    const kin5::rotary_values angles{rad(c), rad(b)};  // chain order: C, B
    RC_ASSERT(max_abs_diff(eq10_point_corrected(p, origin, h, b, c), chain_untracked(dmu, angles, p, in)) < 1e-9);
    const vec3 d{origin.x, origin.y, origin.z - h};
    const vec3 e20_only = (translation4(d) * eq8_r1_printed(c) * eq7_r2_corrected(b) * translation4(-d)).apply(p);
    RC_ASSERT(max_abs_diff(e20_only, chain_untracked(c_physical, angles, p, in)) < 1e-9);
  });
  SECTION("E19: the printed R2 is singular, its middle factor not orthogonal") {
    const row_mat4 r = eq7_r2_printed(30.0);
    const double det = r.m[0][0] * (r.m[1][1] * r.m[2][2] - r.m[1][2] * r.m[2][1]) -
                       r.m[0][1] * (r.m[1][0] * r.m[2][2] - r.m[1][2] * r.m[2][0]) +
                       r.m[0][2] * (r.m[1][0] * r.m[2][1] - r.m[1][1] * r.m[2][0]);
    CHECK(std::abs(det) < 1e-15);
    CHECK(max_abs_diff(eq10_point_printed({10, 20, 30}, {50, 60, 70}, h, 30, 40),
                       eq10_point_corrected({10, 20, 30}, {50, 60, 70}, h, 30, 40)) > 1.0);
  }
  rc::prop("E21: at B = C = 0, (10) gives the point itself, in the workpiece frame", [&] {
    const vec3 p = *point(300), origin = *point(300);
    RC_ASSERT(max_abs_diff(eq10_point_corrected(p, origin, h, 0, 0), p) < 1e-9);
  });
}

TEST_CASE("Ji eq (11): the A/C table position formula is (G6)", "[paper][ji][chain]") {
  using namespace kin5::paper::ji_ac_table;
  const auto& ac = kin5::machines::ac_trunnion::model;
  rc::prop("tip = forward of an A/C table whose axes meet at r_m, slides r_s", [&] {
    const vec3 r_s = *point(300), r_m = *point(300);
    const double a = *uniform(-120, 120), c = *uniform(-360, 360);
    kin5::machine_geometry g = ac.geometry;
    g.rotary[0].point_mm = r_m;
    g.rotary[1].point_mm = r_m;
    const auto m = kin5::machine_model::from(g);
    const kin5::axis_values q{r_s, {rad(c), rad(a)}};  // chain order: C, A
    RC_ASSERT(max_abs_diff(eq11_tip(r_s, r_m, a, c), kin5::forward(m, q).tip_mm) < 1e-9);
  });
  SECTION("a sign error in (11) would show: a quarter turn of A about the origin") {
    CHECK(max_abs_diff(eq11_tip({0, 10, 0}, {0, 0, 0}, 90, 0), vec3{0, 0, -10}) < 1e-12);
  }
}

TEST_CASE("patent CN1624613 (K26): the fixture-offset move is (G7) with the fixture as work offset",
          "[paper][cn1624613][chain]") {
  using namespace kin5::paper::cn1624613;
  const auto& four = kin5::machines::a_rotary_4axis::model;
  const auto about_origin = variant(four.geometry, 0, false, {0, 0, 0});
  rc::prop("XYZ of (K26) = slides + g, A of (K26) = the rotary solution", [&] {
    const vec3 p = *point(300), shift = *point(50);
    const double alpha = *uniform(-180, 180), da = *uniform(-10, 10), tool = *uniform(0, 200);
    const vec3 u{0.0, std::sin(alpha * kin5::pi / 180), std::cos(alpha * kin5::pi / 180)};
    const move4 move = k26_move(p, u, {shift, da});
    const kin5::mat3 turn = kin5::rotation(kin5::unit_x, rad(da));
    const kin5::run_inputs in{tool, {turn, turn * shift}};
    const auto r = kin5::inverse(about_origin, kin5::tool_pose{p, u}, in);
    RC_ASSERT(r.size() == 1u);
    const vec3 tip_machine = r[0].joints.xyz_mm - tool * kin5::unit_z;
    RC_ASSERT(max_abs_diff(tip_machine, move.xyz_mm) < 1e-9);
    const double a_deg = r[0].joints.rotary[0].value * 180 / kin5::pi;
    RC_ASSERT(std::abs(std::remainder(a_deg - move.a_deg, 360.0)) < 1e-9);
  });
}
