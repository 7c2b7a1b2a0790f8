// The golden values and Table 1 of Tian et al. 2010 (docs/golden.md, P18), through the paper
// headers and through kin5's general solver. Every number is typed from docs/golden.md, where
// they were computed independently of kin5; angles in degrees.
#include <catch2/catch.hpp>

#include <cmath>

#include <kin5/kinematics/inverse.hpp>
#include <kin5/machines/catalog.hpp>
#include <kin5/paper/ji_ac_table.hpp>
#include <kin5/paper/liu_dmu50v.hpp>
#include <kin5/paper/tian2010.hpp>

#include "generators.hpp"

namespace km = kin5::machines;
namespace tian = kin5::paper::tian2010;
using kin5::vec3;
using paper_test::angle_diff_deg;
using paper_test::max_abs_diff;
using paper_test::rad;
using paper_test::to_deg;

namespace {

constexpr double golden_tol_deg = 1e-6;
constexpr double golden_tol_vec = 1e-9;

// The solution of `result` within travel whose angles (M::rotary order) are nearest `expected`.
template <class M>
double distance_to_nearest(const kin5::inverse_result<M>& result, std::array<double, kin5::rotary_count<M>> expected,
                           bool within_only = true) {
  double best = 1e9;
  for (const auto& s : result) {
    if (within_only && !s.within_travel) continue;
    double d = 0.0;
    for (std::size_t i = 0; i < kin5::rotary_count<M>; ++i) d = std::fmax(d, angle_diff_deg(to_deg(s.angles[i]), expected[i]));
    best = std::fmin(best, d);
  }
  return best;
}

// M1 pose → M2 angles (B_d, C_d) through the general solver: u_s = FK_s, u_d = T u_s, IK_d.
double solver_m1_to_m2_distance(double a_s, double b_s, double b_d, double c_d) {
  const vec3 u_d = tian::k11_map(kin5::tool_axis<km::sajo_12000p>({rad(b_s), rad(a_s)}));
  return distance_to_nearest<km::dmu_80p>(kin5::inverse<km::dmu_80p>(u_d), {c_d, b_d});
}

}  // namespace

TEST_CASE("golden values: M1 -> M2 translations", "[paper][golden]") {
  SECTION("(a, b) = (-45, 30)") {
    const vec3 u_s = tian::eq8_tool_axis(-45, 30);
    CHECK(max_abs_diff(u_s, {0.353553391, 0.707106781, 0.612372436}) < golden_tol_vec);
    CHECK(max_abs_diff(tian::k11_map(u_s), {-0.353553391, 0.612372436, 0.707106781}) < golden_tol_vec);
    const auto d = tian::eq19_m1_to_m2_printed(-45, 30);
    CHECK(d->b_deg == Approx(65.530199).margin(golden_tol_deg));
    CHECK(d->c_deg == Approx(95.530199).margin(golden_tol_deg));
    CHECK(tian::k12_corrected(-45, 30).angles.c_deg == Approx(95.530199).margin(golden_tol_deg));
    CHECK(solver_m1_to_m2_distance(-45, 30, 65.530199, 95.530199) < golden_tol_deg);
  }
  SECTION("(-10, 200) and (-89, 123)") {
    CHECK(tian::eq19_m1_to_m2_printed(-10, 200)->b_deg == Approx(130.745757).margin(golden_tol_deg));
    CHECK(tian::eq19_m1_to_m2_printed(-10, 200)->c_deg == Approx(232.954835).margin(golden_tol_deg));
    CHECK(solver_m1_to_m2_distance(-10, 200, 130.745757, 232.954835) < golden_tol_deg);
    CHECK(tian::eq19_m1_to_m2_printed(-89, 123)->b_deg == Approx(1.414232).margin(golden_tol_deg));
    CHECK(tian::eq19_m1_to_m2_printed(-89, 123)->c_deg == Approx(212.499981).margin(golden_tol_deg));
    CHECK(tian::k12_corrected(-89, 123).angles.b_deg == Approx(1.414232).margin(golden_tol_deg));
    CHECK(tian::k12_corrected(-89, 123).angles.c_deg == Approx(212.499981).margin(golden_tol_deg));
    CHECK(solver_m1_to_m2_distance(-89, 123, 1.414232, 212.499981) < golden_tol_deg);
  }
  SECTION("flip region (-100, 20) and (-135, 0): printed C_d is 180 deg off (E6)") {
    const auto d = tian::eq19_m1_to_m2_printed(-100, 20);
    CHECK(d->b_deg == Approx(14.160202).margin(golden_tol_deg));
    CHECK(d->c_deg == Approx(104.980852).margin(golden_tol_deg));
    const auto fixed = tian::k12_corrected(-100, 20);
    CHECK(fixed.rule == tian::region::flip_c);
    CHECK(fixed.angles.b_deg == Approx(14.160202).margin(golden_tol_deg));
    CHECK(fixed.angles.c_deg == Approx(284.980852).margin(golden_tol_deg));
    CHECK(solver_m1_to_m2_distance(-100, 20, 14.160202, 284.980852) < golden_tol_deg);
    CHECK(solver_m1_to_m2_distance(-100, 20, 14.160202, 104.980852) > 179.0);

    CHECK(tian::eq19_m1_to_m2_printed(-135, 0)->b_deg == Approx(65.530199).margin(golden_tol_deg));
    CHECK(tian::k12_corrected(-135, 0).angles.c_deg == Approx(245.530199).margin(golden_tol_deg));
    CHECK(solver_m1_to_m2_distance(-135, 0, 65.530199, 245.530199) < golden_tol_deg);
  }
}

TEST_CASE("golden values: M2 forward and the second (G3) branch", "[paper][golden]") {
  CHECK(max_abs_diff(tian::eq14_tool_axis(90, 0), {0.707106781, 0.5, 0.5}) < golden_tol_vec);
  CHECK(max_abs_diff(tian::eq14_tool_axis(180, 0), {0, 1, 0}) < golden_tol_vec);
  const vec3 u = tian::eq14_tool_axis(60, 45);
  CHECK(max_abs_diff(u, {0.256236007, 0.609789397, 0.75}) < golden_tol_vec);
  CHECK(max_abs_diff(kin5::tool_axis<km::dmu_80p>({rad(45), rad(60)}), {0.256236007, 0.609789397, 0.75}) < golden_tol_vec);
  const auto r = kin5::inverse<km::dmu_80p>(u);
  CHECK(distance_to_nearest<km::dmu_80p>(r, {45, 60}) < golden_tol_deg);
  // (C, B) = (−90.584691, −60): a solution of the maths, outside B's travel [0, 180].
  bool found_outside = false;
  for (const auto& s : r)
    if (!s.within_travel && angle_diff_deg(to_deg(s.angles[0]), -90.584691) < golden_tol_deg &&
        angle_diff_deg(to_deg(s.angles[1]), -60) < golden_tol_deg)
      found_outside = true;
  CHECK(found_outside);
}

TEST_CASE("golden values: Ji, Liu 2010, Li et al. 2013", "[paper][golden]") {
  SECTION("Ji: a = 37, c = 121") {
    const vec3 u = kin5::paper::ji_ac_table::k18_tool_axis(37, 121);
    CHECK(max_abs_diff(u, {0.515856159, -0.309957651, 0.798635510}) < golden_tol_vec);
    const auto s = kin5::paper::ji_ac_table::k19_inverse(u);
    CHECK(s[0].a_deg == Approx(37).margin(golden_tol_deg));
    CHECK(s[0].c_deg == Approx(121).margin(golden_tol_deg));
    CHECK(s[1].a_deg == Approx(-37).margin(golden_tol_deg));
    CHECK(s[1].c_deg == Approx(301).margin(golden_tol_deg));
    const auto r = kin5::inverse<km::ac_trunnion>(u);
    CHECK(distance_to_nearest<km::ac_trunnion>(r, {121, 37}) < golden_tol_deg);
    CHECK(distance_to_nearest<km::ac_trunnion>(r, {301, -37}) < golden_tol_deg);
  }
  SECTION("Liu 2010: u = (-1, 1, 1)/sqrt3 and u ~ (0.3, -0.4, 0.8)") {
    using namespace kin5::paper::liu_dmu50v;
    const vec3 u1 = kin5::normalized({-1, 1, 1});
    CHECK(eq3_b_deg(u1.z) == Approx(81.100571).margin(golden_tol_deg));
    CHECK(k24_c_deg(u1) == Approx(166.173952).margin(golden_tol_deg));
    CHECK(*eq5_c_corrected(u1).value() == Approx(166.173952).margin(golden_tol_deg));
    CHECK(distance_to_nearest<km::dmu_50v>(kin5::inverse<km::dmu_50v>(u1), {166.173952, 81.100571}) < golden_tol_deg);
    const vec3 u2 = kin5::normalized({0.3, -0.4, 0.8});
    CHECK(eq3_b_deg(u2.z) == Approx(45.893313).margin(golden_tol_deg));
    CHECK(k24_c_deg(u2) == Approx(-36.463855).margin(golden_tol_deg));
    CHECK(*eq5_c_printed(u2).value() == Approx(-36.463855).margin(golden_tol_deg));
    CHECK(distance_to_nearest<km::dmu_50v>(kin5::inverse<km::dmu_50v>(u2), {-36.463855, 45.893313}) < golden_tol_deg);
  }
  SECTION("Li et al. 2013 head-table: u ~ (0.2, 0.3, 0.9)") {
    // (psi_table, theta_B) = (158.908642, 255.698971) or (-21.091358, 14.301029); A = -psi.
    const auto r = kin5::inverse<km::b_head_a_tilted_table>(kin5::normalized({0.2, 0.3, 0.9}));
    CHECK(distance_to_nearest<km::b_head_a_tilted_table>(r, {-158.908642, 255.698971}) < golden_tol_deg);
    CHECK(distance_to_nearest<km::b_head_a_tilted_table>(r, {21.091358, 14.301029}) < golden_tol_deg);
  }
}

namespace {

// Table 1 of Tian et al. 2010 (docs/golden.md): SAJO G1 X Y Z A B and DMU L X Y Z B C. F not used
// (docs/golden.md, "Table 1 feed column").
struct table1_row {
  double xs, ys, zs, as, bs;
  double xd, yd, zd, bd, cd;
};
constexpr table1_row table1[] = {
    {-34.983, 9.100, 118.526, -77.954, 3.536, 34.983, 118.526, 9.100, 17.067, 87.479},
    {-33.824, 9.118, 117.545, -77.913, 4.027, 33.824, 117.545, 9.118, 17.126, 87.950},
    {-32.674, 9.153, 116.558, -77.918, 4.588, 32.674, 116.558, 9.153, 17.118, 88.513},
    {-31.531, 9.203, 115.567, -77.963, 5.158, 31.531, 115.567, 9.203, 17.054, 89.106},
};
constexpr double table1_tol_deg = 0.001;

}  // namespace

TEST_CASE("P18 Table 1 of Tian et al. 2010 through (K10)-(K13) and the general solver", "[paper][golden][table1]") {
  for (const auto& row : table1) {
    CAPTURE(row.as, row.bs);
    // Linear axes: exact.
    CHECK(tian::k11_map({row.xs, row.ys, row.zs}) == vec3{row.xd, row.yd, row.zd});
    CHECK(tian::k11_map({row.xd, row.yd, row.zd}) == vec3{row.xs, row.ys, row.zs});
    // (K12) forward and (K13) back.
    const auto d = tian::eq19_m1_to_m2_printed(row.as, row.bs);
    REQUIRE(d.has_value());
    CHECK(std::fabs(d->b_deg - row.bd) < table1_tol_deg);
    CHECK(std::fabs(d->c_deg - row.cd) < table1_tol_deg);
    const auto s = tian::eq18_m2_to_m1(row.bd, row.cd);
    CHECK(std::fabs(s.a_deg - row.as) < table1_tol_deg);
    CHECK(std::fabs(s.b_deg - row.bs) < table1_tol_deg);
    // General solver, both directions.
    CHECK(solver_m1_to_m2_distance(row.as, row.bs, row.bd, row.cd) < table1_tol_deg);
    const vec3 u_s = tian::k11_map(kin5::tool_axis<km::dmu_80p>({rad(row.cd), rad(row.bd)}));
    CHECK(distance_to_nearest<km::sajo_12000p>(kin5::inverse<km::sajo_12000p>(u_s), {row.bs, row.as}) < table1_tol_deg);
  }
}
