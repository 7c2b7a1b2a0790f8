// Laws P3-P17 for Tian et al. 2010 (docs/equations.md; paper/tian2010.hpp), with the general solver
// where the identity is about what a machine can reach.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cmath>

#include <kin5/kinematics/inverse.hpp>
#include <kin5/machines/catalog.hpp>
#include <kin5/paper/tian2010.hpp>

#include "generators.hpp"

using namespace kin5::paper::tian2010;
using kin5::vec3;
using paper_test::angle_diff_deg;
using paper_test::max_abs_diff;
using paper_test::near;
using paper_test::uniform;

namespace {

// Independent forward chains (Eigen angle-axis): (K1) u_s = R(Y, b) R(X, a) ẑ and
// (K5) u_d = R(Z, c) R(p, b) ẑ with p = (0, 1, 1)/√2.
vec3 m1_chain(double a_deg, double b_deg) {
  return paper_test::eigen_rotate(kin5::unit_y, b_deg, paper_test::eigen_rotate(kin5::unit_x, a_deg, kin5::unit_z));
}
vec3 m2_chain(double b_deg, double c_deg) {
  return paper_test::eigen_rotate(kin5::unit_z, c_deg, paper_test::eigen_rotate({0, 1, 1}, b_deg, kin5::unit_z));
}

}  // namespace

// Compile-time: the printed case table of [000:7] is wrong exactly where E1 says.
static_assert(eq7_b_printed(-1.0, 1.0).count == 0, "E1: i<0, k>0 matches no printed case");
static_assert(eq7_b_printed(-1.0, -1.0).count == 2, "E1: i<0, k<0 matches printed cases 3 and 4");
static_assert(eq7_b_corrected(-1.0, 1.0).count == 1 && eq7_b_corrected(-1.0, -1.0).count == 1);
static_assert(region_of(-90.0) == region::direct && region_of(0.0) == region::direct);
static_assert(region_of(-90.000001) == region::flip_c && region_of(0.000001) == region::none);

TEST_CASE("P1/P2 Tian 2010 closed forms equal the rotation chains", "[paper][tian2010]") {
  rc::prop("(K1) = [000:8] equals R(Y,b)R(X,a)z", [] {
    const double a = *uniform(-180.0, 180.0), b = *uniform(-720.0, 720.0);
    RC_ASSERT(max_abs_diff(eq8_tool_axis(a, b), m1_chain(a, b)) < 1e-12);
  });
  rc::prop("(K5) = [000:14] equals R(Z,c)R(p,b)z", [] {
    const double b = *uniform(-180.0, 360.0), c = *uniform(-720.0, 720.0);
    RC_ASSERT(max_abs_diff(eq14_tool_axis(b, c), m2_chain(b, c)) < 1e-12);
  });
}

TEST_CASE("P3 M1 round trip (K2) after (K1)", "[paper][tian2010]") {
  rc::prop("IK(FK(a, b)) = (a, b mod 360) for a in (-90, 90)", [] {
    const double a = *rc::gen::oneOf(uniform(-89.9999, 89.9999), near(-90.0, 1e-2), near(90.0, 1e-2));
    RC_PRE(std::fabs(a) < 90.0 - 1e-9);
    const double b = *uniform(-720.0, 720.0);
    const auto s = k2_inverse(eq8_tool_axis(a, b));
    RC_ASSERT(std::fabs(s.a_deg - a) < 1e-9);
    RC_ASSERT(angle_diff_deg(s.b_deg, b) < 1e-9);
    RC_ASSERT(s.b_deg >= 0.0);
    RC_ASSERT(s.b_deg < 360.0);
  });
  rc::prop("FK(IK(u)) = u off the poles +-Y", [] {
    const vec3 u = *paper_test::unit_vector();
    RC_PRE(std::fabs(u.y) < 1.0 - 1e-12);
    const auto s = k2_inverse(u);
    RC_ASSERT(max_abs_diff(eq8_tool_axis(s.a_deg, s.b_deg), u) < 1e-12);
  });
  SECTION("E2: the printed pole rule a = -90 is right only for u = +Y") {
    CHECK(eq6_a_printed_deg({0, 1, 0}) == -90.0);
    CHECK(eq6_a_printed_deg({0, -1, 0}) == -90.0);  // as printed; the tool axis needs +90
    CHECK(k2_a_deg({0, -1, 0}) == Approx(90.0).margin(1e-12));
    CHECK(max_abs_diff(eq8_tool_axis(k2_a_deg({0, -1, 0}), 0.0), {0, -1, 0}) < 1e-15);
    CHECK(max_abs_diff(eq8_tool_axis(eq6_a_printed_deg({0, -1, 0}), 0.0), {0, -1, 0}) > 1.9);
  }
  rc::prop("printed [000:6] equals (K2) a off the poles", [] {
    const vec3 u = *paper_test::unit_vector();
    RC_PRE(u.x * u.x + u.z * u.z > 0.0);
    RC_ASSERT(std::fabs(eq6_a_printed_deg(u) - k2_a_deg(u)) < 1e-10);
  });
}

TEST_CASE("P4 P5 M1 second branch (K3) and antipode (K4)", "[paper][tian2010]") {
  rc::prop("FK(-180-a, b+180) = FK(a, b)", [] {
    const sajo_angles_deg s{*uniform(-180.0, 180.0), *uniform(-360.0, 360.0)};
    const sajo_angles_deg t = k3_second_branch(s);
    RC_ASSERT(t.a_deg == -180.0 - s.a_deg);
    RC_ASSERT(max_abs_diff(m1_chain(t.a_deg, t.b_deg), m1_chain(s.a_deg, s.b_deg)) < 1e-12);
  });
  rc::prop("FK(-a, b+180) = -FK(a, b)", [] {
    const sajo_angles_deg s{*uniform(-180.0, 180.0), *uniform(-360.0, 360.0)};
    const sajo_angles_deg t = k4_antipode(s);
    RC_ASSERT(max_abs_diff(m1_chain(t.a_deg, t.b_deg), -m1_chain(s.a_deg, s.b_deg)) < 1e-12);
  });
}

TEST_CASE("P6 M2 round trip (K7)-(K9) after (K5)", "[paper][tian2010]") {
  rc::prop("IK(FK(b, c)) = (b, c mod 360) for b in (0, 180]", [] {
    const double b = *rc::gen::oneOf(uniform(1e-3, 180.0), near(0.0, 1e-2), near(180.0, 1e-2));
    RC_PRE(b > 1e-9 && b <= 180.0);
    const double c = *uniform(-720.0, 720.0);
    const auto s = k7_k9_inverse(eq14_tool_axis(b, c));
    RC_ASSERT(s.has_value());
    // k = (1 + cos b)/2 is rounded by ~1e-16, which moves b by ~1e-16/(180° − b) near b = 180°.
    // c_t = atan2(√(2k), √(1−k)) inherits the same ~1e-16/(180° − b).
    const double near_limit = paper_test::conditioned_tol_deg(std::fmax((180.0 - b) * paper_test::deg, 1e-9));
    RC_ASSERT(std::fabs(s->b_deg - b) < near_limit);
    RC_ASSERT(angle_diff_deg(s->c_deg, c) < near_limit + 1e-9 / b);
  });
  rc::prop("printed [000:10] and [000:13] agree with (K7) and (K9) away from the pole", [] {
    const double b = *uniform(1.0, 180.0), c = *uniform(-720.0, 720.0);
    const vec3 u = eq14_tool_axis(b, c);
    RC_ASSERT(std::fabs(eq10_b_deg(u.z) - b) < 1e-6);
    const auto printed_c = eq13_c_deg(u);
    RC_ASSERT(printed_c.has_value());
    RC_ASSERT(angle_diff_deg(*printed_c, c) < 1e-6);
    RC_ASSERT(angle_diff_deg(*printed_c, k9_c_deg(u)) < 1e-6);
  });
  rc::prop("FK(IK(u)) = u on the upper hemisphere minus +Z", [] {
    const vec3 u = *rc::gen::oneOf(paper_test::unit_vector_z_between(0.0, 1.0),
                                   paper_test::unit_vector_z_between(1.0 - 1e-6, 1.0));
    RC_PRE(u.z < 1.0);
    const auto s = k7_k9_inverse(u);
    RC_ASSERT(s.has_value());
    RC_ASSERT(max_abs_diff(eq14_tool_axis(s->b_deg, s->c_deg), u) < 1e-12);
  });
}

TEST_CASE("P7 M2 reach is the upper hemisphere and the gap below is arcsin(-k)", "[paper][tian2010]") {
  rc::prop("k of (K5) is (1 + cos b)/2 in [0, 1]", [] {
    const double b = *uniform(0.0, 180.0), c = *uniform(-360.0, 360.0);
    const vec3 u = eq14_tool_axis(b, c);
    RC_ASSERT(std::fabs(u.z - (1.0 + std::cos(b * paper_test::deg)) / 2.0) < 1e-15);
    RC_ASSERT(u.z >= 0.0);
    RC_ASSERT(u.z <= 1.0);
  });
  rc::prop("k < 0 is unreachable, with gap arcsin(-k)", [] {
    const vec3 u = *paper_test::unit_vector_z_between(-1.0, -1e-6);
    RC_ASSERT(!k7_k9_inverse(u).has_value());
    const auto r = kin5::inverse<kin5::machines::dmu_80p>(u);
    RC_ASSERT(!r.reachable());
    RC_ASSERT(std::fabs(r.gap.value - std::asin(-u.z)) < 1e-12);
  });
}

TEST_CASE("P8 Tian 2010 case tables equal their atan2 forms", "[paper][tian2010]") {
  SECTION("corrected [000:7] on the four half-axes") {
    CHECK(*eq7_b_corrected(0, 1).value() == 0.0);
    CHECK(*eq7_b_corrected(1, 0).value() == 90.0);
    CHECK(*eq7_b_corrected(0, -1).value() == 180.0);
    CHECK(*eq7_b_corrected(-1, 0).value() == 270.0);
    CHECK(eq7_b_corrected(0, 0).count == 0);  // the pole: b is free
  }
  rc::prop("corrected [000:7] = atan2(i, k) mod 360 on all four quadrants", [] {
    const vec3 u = *paper_test::unit_vector();
    const auto r = eq7_b_corrected(u.x, u.z);
    RC_ASSERT(r.count == 1u);
    RC_ASSERT(std::fabs(r.value_deg[0] - k2_b_deg(u)) < 1e-12);
  });
  SECTION("[000:13] bracket on the half-axes and diagonals") {
    CHECK(*eq13_bracket(0, 1).value() == 0.0);
    CHECK(*eq13_bracket(1, 0).value() == -90.0);
    CHECK(*eq13_bracket(0, -1).value() == -180.0);
    CHECK(*eq13_bracket(-1, 0).value() == 90.0);
    CHECK(*eq13_bracket(1, 1).value() == Approx(-45.0).margin(1e-12));
    CHECK(*eq13_bracket(-1, 1).value() == Approx(45.0).margin(1e-12));
    CHECK(*eq13_bracket(1, -1).value() == Approx(-135.0).margin(1e-12));
    CHECK(*eq13_bracket(-1, -1).value() == Approx(135.0).margin(1e-12));
    CHECK(eq13_bracket(0, 0).count == 0);
  }
  rc::prop("[000:13] bracket has exactly one case and equals wrap180(atan2(j, i) - 90) mod 360", [] {
    const vec3 u = *paper_test::unit_vector();
    const auto r = eq13_bracket(u.x, u.y);
    RC_ASSERT(r.count == 1u);
    const double expected = std::remainder(std::atan2(u.y, u.x) / paper_test::deg - 90.0, 360.0);
    RC_ASSERT(angle_diff_deg(r.value_deg[0], expected) < 1e-12);
    RC_ASSERT(r.value_deg[0] >= -180.0);
    RC_ASSERT(r.value_deg[0] < 180.0);
  });
}

TEST_CASE("P9 printed [000:7] has a gap on b in (270, 360) and an overlap on (180, 270)", "[paper][tian2010][errata]") {
  rc::prop("gap: no printed case holds for b in (270, 360)", [] {
    const double a = *uniform(-89.0, 89.0), b = *uniform(270.0 + 1e-6, 360.0 - 1e-6);
    const vec3 u = eq8_tool_axis(a, b);
    RC_ASSERT(eq7_b_printed(u.x, u.z).count == 0u);
    RC_ASSERT(std::fabs(*eq7_b_corrected(u.x, u.z).value() - b) < 1e-9);
  });
  rc::prop("overlap: printed cases 3 and 4 both hold for b in (180, 270), giving b and 540 - b", [] {
    const double a = *uniform(-89.0, 89.0), b = *uniform(180.0 + 1e-6, 270.0 - 1e-6);
    const vec3 u = eq8_tool_axis(a, b);
    const auto r = eq7_b_printed(u.x, u.z);
    RC_ASSERT(r.count == 2u);
    RC_ASSERT(r.case_no[0] == 3);
    RC_ASSERT(r.case_no[1] == 4);
    RC_ASSERT(std::fabs(r.value_deg[0] - b) < 1e-9);
    RC_ASSERT(std::fabs(r.value_deg[1] - (540.0 - b)) < 1e-9);
  });
  rc::prop("printed [000:7] is right on b in [0, 180]", [] {
    const double a = *uniform(-89.0, 89.0), b = *uniform(0.0, 180.0 - 1e-6);
    const vec3 u = eq8_tool_axis(a, b);
    const auto r = eq7_b_printed(u.x, u.z);
    RC_ASSERT(r.count == 1u);
    RC_ASSERT(angle_diff_deg(r.value_deg[0], b) < 1e-9);
  });
}

TEST_CASE("P10 P11 the frame map T (K10)/(K11)", "[paper][tian2010]") {
  const kin5::mat3 t = dmu_T_sajo;
  CHECK(t == t.transposed());
  CHECK(t * t == kin5::mat3::identity());
  CHECK(kin5::determinant(t) == 1.0);
  CHECK(sajo_T_dmu == dmu_T_sajo);
  for (const vec3& v : {kin5::unit_x, kin5::unit_y, kin5::unit_z, vec3{0.3, -0.4, 0.8}})
    CHECK(max_abs_diff(t * v, paper_test::eigen_rotate({0, 1, 1}, 180.0, v)) < 1e-15);
  CHECK(t * kin5::unit_y == kin5::unit_z);
  CHECK(t * kin5::unit_x == -kin5::unit_x);
  CHECK(t * kin5::unit_z == kin5::unit_y);
  rc::prop("(x_d, y_d, z_d) = (-x_s, z_s, y_s) and distances are kept", [] {
    const vec3 p{*uniform(-1e3, 1e3), *uniform(-1e3, 1e3), *uniform(-1e3, 1e3)};
    const vec3 q{*uniform(-1e3, 1e3), *uniform(-1e3, 1e3), *uniform(-1e3, 1e3)};
    RC_ASSERT(k11_map(p) == (vec3{-p.x, p.z, p.y}));
    RC_ASSERT(k11_map(k11_map(p)) == p);
    RC_ASSERT(std::fabs(kin5::norm(k11_map(p) - k11_map(q)) - kin5::norm(p - q)) < 1e-12);
  });
}

TEST_CASE("P12 P13 P14 (K12) per matchability region", "[paper][tian2010]") {
  rc::prop("P12: a in [-90, 0]: FK_d(K12(a, b)) = T FK_s(a, b)", [] {
    const double a = *rc::gen::oneOf(uniform(-90.0, 0.0), near(-90.0, 1.0), near(0.0, 1.0));
    RC_PRE(a >= -90.0 && a <= 0.0);
    const double b = *uniform(0.0, 360.0);
    const vec3 target = k11_map(m1_chain(a, b));
    const auto printed = eq19_m1_to_m2_printed(a, b);
    RC_ASSERT(printed.has_value());
    // Printed arccos(−1 − 2 sin a) is ill-conditioned at the pole: ~1e-16/|a + 90°| rad.
    const double tol = 1e-12 + 1e-15 / (std::fabs(a + 90.0) * paper_test::deg);
    RC_ASSERT(max_abs_diff(m2_chain(printed->b_deg, printed->c_deg), target) < tol);
    const auto fixed = k12_corrected(a, b);
    RC_ASSERT(fixed.rule == region::direct);
    RC_ASSERT(max_abs_diff(m2_chain(fixed.angles.b_deg, fixed.angles.c_deg), target) < 1e-12);
  });
  rc::prop("P13: a in (-180, -90): C_d + 180 is right, printed C_d is not (E6)", [] {
    const double a = *rc::gen::oneOf(uniform(-180.0 + 1e-9, -90.0), near(-90.0, 1.0));
    RC_PRE(a > -180.0 && a < -90.0);
    const double b = *uniform(0.0, 360.0);
    const vec3 target = k11_map(m1_chain(a, b));
    const auto printed = eq19_m1_to_m2_printed(a, b);
    RC_ASSERT(printed.has_value());
    const double tol = 1e-12 + 1e-15 / (std::fabs(a + 90.0) * paper_test::deg);
    RC_ASSERT(max_abs_diff(m2_chain(printed->b_deg, printed->c_deg + 180.0), target) < tol);
    // The printed C_d turns the tool the other way round the table axis.
    const double horizontal = std::hypot(target.x, target.y);
    RC_ASSERT(std::fabs(kin5::norm(m2_chain(printed->b_deg, printed->c_deg) - target) - 2.0 * horizontal) < 2.0 * tol);
    const auto fixed = k12_corrected(a, b);
    RC_ASSERT(fixed.rule == region::flip_c);
    RC_ASSERT(max_abs_diff(m2_chain(fixed.angles.b_deg, fixed.angles.c_deg), target) < 1e-12);
  });
  rc::prop("P14: a in (0, 180): unreachable for every b, gap arcsin(sin a)", [] {
    const double a = *rc::gen::oneOf(uniform(1e-9, 180.0 - 1e-9), near(0.0, 1.0));
    RC_PRE(a > 0.0 && a < 180.0);
    const double b = *uniform(0.0, 360.0);
    const vec3 target = k11_map(m1_chain(a, b));
    RC_ASSERT(target.z < 0.0);
    RC_ASSERT(!eq19_m1_to_m2_printed(a, b).has_value());
    const auto fixed = k12_corrected(a, b);
    RC_ASSERT(fixed.rule == region::none);
    const double expected_gap = a <= 90.0 ? a : 180.0 - a;
    RC_ASSERT(std::fabs(fixed.gap_deg - expected_gap) < 1e-12);
    // The nearest reachable pose is at the gap from the target.
    const vec3 nearest = m2_chain(fixed.angles.b_deg, fixed.angles.c_deg);
    RC_ASSERT(std::fabs(kin5::angle_between(nearest, target).value / paper_test::deg - expected_gap) < 1e-9);
    const auto solved = kin5::inverse<kin5::machines::dmu_80p>(target);
    RC_ASSERT(!solved.reachable());
    RC_ASSERT(std::fabs(paper_test::to_deg(solved.gap) - expected_gap) < 1e-9);
  });
  SECTION("region boundaries at -90 and 0") {
    CHECK(region_of(-90.0) == region::direct);
    CHECK(region_of(-90.0 - 1e-12) == region::flip_c);
    CHECK(region_of(0.0) == region::direct);
    CHECK(region_of(1e-12) == region::none);
    CHECK(region_of(-180.0) == region::flip_c);
    CHECK(region_of(270.0) == region::direct);  // = -90
    CHECK(k12_corrected(0.0, 30.0).angles.b_deg == Approx(180.0).margin(1e-12));
    CHECK(k12_corrected(0.0, 30.0).angles.c_deg == Approx(30.0).margin(1e-12));
  }
}

TEST_CASE("P15 (K13) and (K12) invert each other", "[paper][tian2010]") {
  rc::prop("(K13)(K12)(a, b) = (a, b) on [-90, 0] x [0, 360)", [] {
    const double a = *rc::gen::oneOf(uniform(-89.9, 0.0), near(0.0, 1.0));
    RC_PRE(a >= -89.9 && a <= 0.0);
    const double b = *uniform(0.0, 360.0 - 1e-9);
    const auto d = eq19_m1_to_m2_printed(a, b);
    RC_ASSERT(d.has_value());
    const auto s = eq18_m2_to_m1(d->b_deg, d->c_deg);
    RC_ASSERT(std::fabs(s.a_deg - a) < 1e-9);
    RC_ASSERT(std::fabs(s.b_deg - b) < 1e-9);
  });
  rc::prop("near the pole a -> -90 the round trip keeps the tool axis", [] {
    const double a = *near(-90.0, 0.1);
    RC_PRE(a >= -90.0 && a <= 0.0);
    const double b = *uniform(0.0, 360.0);
    const auto d = eq19_m1_to_m2_printed(a, b);
    RC_ASSERT(d.has_value());
    const auto s = eq18_m2_to_m1(d->b_deg, d->c_deg);
    RC_ASSERT(max_abs_diff(m1_chain(s.a_deg, s.b_deg), m1_chain(a, b)) < 1e-7);
  });
  rc::prop("(K12)(K13)(B, C) = (B, C mod 360) on (0, 180] x R", [] {
    const double bd = *rc::gen::oneOf(uniform(0.01, 180.0), near(180.0, 1.0));
    RC_PRE(bd >= 0.01 && bd <= 180.0);
    const double cd = *uniform(-720.0, 720.0);
    const auto s = eq18_m2_to_m1(bd, cd);
    RC_ASSERT(s.a_deg >= -90.0);
    RC_ASSERT(s.a_deg <= 0.0);
    const auto d = eq19_m1_to_m2_printed(s.a_deg, s.b_deg);
    RC_ASSERT(d.has_value());
    // Both formulas pass through k_d = (1 + cos B_d)/2, rounded by ~1e-16 near B_d = 180°.
    const double tol = paper_test::conditioned_tol_deg(std::fmax((180.0 - bd) * paper_test::deg, 1e-9));
    RC_ASSERT(std::fabs(d->b_deg - bd) < tol);
    RC_ASSERT(angle_diff_deg(d->c_deg, cd) < tol);
  });
}

TEST_CASE("P16 pole conventions are the continuous limits", "[paper][tian2010]") {
  CHECK(eq19_m1_to_m2_printed(-90.0, 17.0)->b_deg == 0.0);
  CHECK(eq19_m1_to_m2_printed(-90.0, 17.0)->c_deg == 17.0 + 90.0);
  CHECK(eq18_m2_to_m1(0.0, 17.0).a_deg == -90.0);
  CHECK(eq18_m2_to_m1(0.0, 17.0).b_deg == 17.0 - 90.0);
  CHECK(k12_corrected(-90.0, 17.0).angles.c_deg == Approx(107.0).margin(1e-12));
  rc::prop("(K12) C_d -> b + 90 linearly as a -> -90 from above", [] {
    const double eps = *paper_test::log_uniform(-4.0, -0.5);
    const double b = *uniform(0.0, 360.0);
    const double c = eq19_m1_to_m2_printed(-90.0 + eps, b)->c_deg;
    RC_ASSERT(std::fabs(c - (b + 90.0)) <= eps);
    RC_ASSERT(std::fabs(k12_corrected(-90.0 + eps, b).angles.c_deg - (b + 90.0)) <= eps);
  });
  rc::prop("(K13) B_s -> C_d - 90 linearly as B_d -> 0", [] {
    const double eps = *paper_test::log_uniform(-4.0, -0.5);
    const double c = *uniform(0.0, 360.0);
    const auto s = eq18_m2_to_m1(eps, c);
    RC_ASSERT(std::fabs(s.b_deg - (c - 90.0)) <= eps);
    RC_ASSERT(std::fabs(s.a_deg + 90.0) <= eps);
  });
}

TEST_CASE("P17 table equivariance (K14)", "[paper][tian2010]") {
  rc::prop("(K12)(a, b + beta) = (K12)(a, b) + (0, beta), also through the general solver", [] {
    const double a = *uniform(-89.0, -1.0), b = *uniform(0.0, 360.0), beta = *uniform(-360.0, 360.0);
    const auto d0 = eq19_m1_to_m2_printed(a, b), d1 = eq19_m1_to_m2_printed(a, b + beta);
    RC_ASSERT(std::fabs(d1->b_deg - d0->b_deg) < 1e-12);
    RC_ASSERT(std::fabs(d1->c_deg - (d0->c_deg + beta)) < 1e-9);
    using kin5::machines::dmu_80p;
    const auto s0 = kin5::inverse<dmu_80p>(k11_map(m1_chain(a, b))).first_within_travel();
    const auto s1 = kin5::inverse<dmu_80p>(k11_map(m1_chain(a, b + beta))).first_within_travel();
    RC_ASSERT(s0.has_value());
    RC_ASSERT(s1.has_value());
    RC_ASSERT(std::fabs(paper_test::to_deg((*s1)[1]) - paper_test::to_deg((*s0)[1])) < 1e-9);
    RC_ASSERT(angle_diff_deg(paper_test::to_deg((*s1)[0]), paper_test::to_deg((*s0)[0]) + beta) < 1e-9);
  });
}

TEST_CASE("(K15)-(K17) feed as printed in [000:20-23]", "[paper][tian2010][feed]") {
  // A synthetic block pair: 3-4-0 mm linear step and a 12 deg rotary step on one machine,
  // the same linear step and 5 deg on the other.
  const block5 s0{0, 0, 0, 0, 0}, s1{3, 4, 0, 12, 0};
  const block5 d0{0, 0, 0, 0, 0}, d1{-3, 0, 4, 0, 5};
  CHECK(eq21_block_distance(s0, s1) == Approx(13.0).epsilon(1e-15));
  CHECK(eq21_block_distance(d0, d1) == Approx(std::sqrt(50.0)).epsilon(1e-15));
  CHECK(eq23_feed_mm_per_min(1000.0, s0, s1, d0, d1) == Approx(1000.0 * std::sqrt(50.0) / 13.0).epsilon(1e-15));
  CHECK(eq20_block_time_min(13.0, 1000.0) ==
        Approx(eq20_block_time_min(std::sqrt(50.0), eq23_feed_mm_per_min(1000.0, 13.0, std::sqrt(50.0)))).epsilon(1e-15));
  rc::prop("(K17) keeps the block time (K15); linear-only moves keep the feed", [] {
    const block5 p{*uniform(-100, 100), *uniform(-100, 100), *uniform(-100, 100), *uniform(-90, 0), *uniform(0, 360)};
    const block5 q{*uniform(-100, 100), *uniform(-100, 100), *uniform(-100, 100), *uniform(-90, 0), *uniform(0, 360)};
    const double f = *uniform(10.0, 10000.0);
    const block5 pd{-p.x_mm, p.z_mm, p.y_mm, 0, 0}, qd{-q.x_mm, q.z_mm, q.y_mm, 0, 0};
    const block5 ps{p.x_mm, p.y_mm, p.z_mm, 0, 0}, qs{q.x_mm, q.y_mm, q.z_mm, 0, 0};
    RC_ASSERT(std::fabs(eq23_feed_mm_per_min(f, ps, qs, pd, qd) - f) < 1e-9 * f);
    const double ls = eq21_block_distance(p, q), ld = eq21_block_distance(pd, qd);
    const double fd = eq23_feed_mm_per_min(f, ls, ld);
    RC_ASSERT(std::fabs(eq20_block_time_min(ld, fd) - eq20_block_time_min(ls, f)) < 1e-12 * (1.0 + ls / f));
  });
}
