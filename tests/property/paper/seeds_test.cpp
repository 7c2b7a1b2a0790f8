// Laws P26-P29 for Ji, CN1624613 and Liu 2010 (docs/equations.md; paper/ji_ac_table.hpp,
// paper/cn1624613.hpp, paper/liu_dmu50v.hpp).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cmath>

#include <kin5/paper/cn1624613.hpp>
#include <kin5/paper/ji_ac_table.hpp>
#include <kin5/paper/liu_dmu50v.hpp>

#include "generators.hpp"

using kin5::vec3;
using paper_test::angle_diff_deg;
using paper_test::eigen_rotate;
using paper_test::max_abs_diff;
using paper_test::uniform;

// ---------------------------------------------------------------------------------------------
// Ji: A/C dual table

TEST_CASE("P26 Ji: (K18) is the chain and printed [001:12] swaps i and j", "[paper][ji][errata]") {
  using namespace kin5::paper::ji_ac_table;
  rc::prop("(K18) = R(Z, -c) R(X, -a) z", [] {
    const double a = *uniform(-180.0, 180.0), c = *uniform(-360.0, 360.0);
    const vec3 chain = eigen_rotate(kin5::unit_z, -c, eigen_rotate(kin5::unit_x, -a, kin5::unit_z));
    RC_ASSERT(max_abs_diff(k18_tool_axis(a, c), chain) < 1e-12);
  });
  rc::prop("printed [001:12] = (K18) with i and j exchanged (E10)", [] {
    const double a = *uniform(-180.0, 180.0), c = *uniform(-360.0, 360.0);
    const vec3 k18 = k18_tool_axis(a, c), printed = eq12_tool_axis_printed(a, c);
    RC_ASSERT(max_abs_diff(printed, vec3{k18.y, k18.x, k18.z}) < 1e-15);
  });
  SECTION("E10: the printed vector is not the chain's where sin a (sin c - cos c) != 0") {
    const vec3 chain = eigen_rotate(kin5::unit_z, -30.0, eigen_rotate(kin5::unit_x, -40.0, kin5::unit_z));
    CHECK(max_abs_diff(eq12_tool_axis_printed(40.0, 30.0), chain) > 0.2);
  }
  rc::prop("both branches of (K19) reproduce u", [] {
    const vec3 u = *paper_test::unit_vector();
    RC_PRE(std::fabs(u.z) < 1.0 - 1e-12);
    const auto branches = k19_inverse(u);
    RC_ASSERT(branches[0].a_deg >= 0.0);
    RC_ASSERT(branches[1].a_deg <= 0.0);
    for (const auto& s : branches) RC_ASSERT(max_abs_diff(k18_tool_axis(s.a_deg, s.c_deg), u) < 1e-12);
  });
  rc::prop("E11: [001:13] has no fixed pairing of +-arccos k with k in {0, 1}", [] {
    // Take [001:12] as the definition, as the paper does; which candidate reproduces u
    // depends on the sign of i.
    const double a = *uniform(1.0, 179.0), c = *uniform(-180.0, 180.0);
    const vec3 u = eq12_tool_axis_printed(a, c);
    RC_PRE(std::fabs(u.x) > 1e-6);
    const auto cand = eq13_candidates_printed(u);
    auto works = [&](const ac_angles_deg& s) { return max_abs_diff(eq12_tool_axis_printed(s.a_deg, s.c_deg), u) < 1e-9; };
    if (u.x > 0) {
      RC_ASSERT(works(cand[0]));   // (+arccos k, k = 0)
      RC_ASSERT(!works(cand[1]));  // (+arccos k, k = 1)
      RC_ASSERT(works(cand[3]));   // (-arccos k, k = 1)
    } else {
      RC_ASSERT(!works(cand[0]));
      RC_ASSERT(works(cand[1]));
      RC_ASSERT(works(cand[2]));   // (-arccos k, k = 0)
    }
  });
}

TEST_CASE("P29 Ji: side-milling error bounds (K20), (K21)", "[paper][ji]") {
  using namespace kin5::paper::ji_ac_table;
  CHECK(eq3_convex_error_mm(5.0, 40.0, 0.0) == Approx(0.0).margin(1e-12));
  CHECK(eq4_concave_error_mm(5.0, 40.0, 0.0) == Approx(0.0).margin(1e-12));
  // Circle construction in the normal plane at P = 0: tool axis at R n1, the curvature centre of
  // the guide curve at -R2 n2 (convex) or +R2 n2 (concave); the error is R minus the smallest
  // distance from the tool axis to that circle, found by a sampled search refined by ternary search.
  auto construction = [](double r, double r2, double alpha_deg, bool convex) {
    const double al = alpha_deg * paper_test::deg;
    const double tx = 0.0, ty = r;                                   // tool axis, n1 = (0, 1)
    const double s = convex ? -r2 : r2;
    const double ox = s * std::sin(al), oy = s * std::cos(al);      // centre, n2 = (sin a, cos a)
    auto dist = [&](double th) { return std::hypot(ox + r2 * std::cos(th) - tx, oy + r2 * std::sin(th) - ty); };
    const int n = 3600;
    int best = 0;
    for (int i = 1; i < n; ++i)
      if (dist(2 * M_PI * i / n) < dist(2 * M_PI * best / n)) best = i;
    double lo = 2 * M_PI * (best - 1) / n, hi = 2 * M_PI * (best + 1) / n;
    for (int it = 0; it < 200; ++it) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (dist(m1) < dist(m2)) {
        hi = m2;
      } else {
        lo = m1;
      }
    }
    return r - dist(0.5 * (lo + hi));
  };
  rc::prop("(K20) and (K21) equal the circle construction", [&] {
    const double r = *uniform(1.0, 20.0), r2 = *uniform(20.0, 500.0), alpha = *uniform(0.0, 30.0);
    RC_ASSERT(std::fabs(eq3_convex_error_mm(r, r2, alpha) - construction(r, r2, alpha, true)) < 1e-9);
    RC_ASSERT(std::fabs(eq4_concave_error_mm(r, r2, alpha) - construction(r, r2, alpha, false)) < 1e-9);
    RC_ASSERT(eq3_convex_error_mm(r, r2, alpha) >= -1e-12);
    RC_ASSERT(eq4_concave_error_mm(r, r2, alpha) >= -1e-12);
  });
}

// ---------------------------------------------------------------------------------------------
// Liu 2010: DMU 50V

TEST_CASE("P27 Liu 2010: [003:2], (K23)-(K24) and the printed case table", "[paper][liu][errata]") {
  using namespace kin5::paper::liu_dmu50v;
  rc::prop("[003:2] = R((0,1,-1)/sqrt2, B) z", [] {
    const double b = *uniform(-180.0, 360.0);
    RC_ASSERT(max_abs_diff(eq2_om(b), eigen_rotate({0, 1, -1}, b, kin5::unit_z)) < 1e-12);
  });
  rc::prop("(K22) = R(Z, C) R(n', B) z", [] {
    const double b = *uniform(0.0, 180.0), c = *uniform(-360.0, 360.0);
    const vec3 chain = eigen_rotate(kin5::unit_z, c, eigen_rotate({0, 1, -1}, b, kin5::unit_z));
    RC_ASSERT(max_abs_diff(k22_tool_axis(b, c), chain) < 1e-12);
  });
  rc::prop("(K23)-(K24) round trip for B in (0, 180]", [] {
    const double b = *rc::gen::oneOf(uniform(0.01, 180.0), paper_test::near(180.0, 1.0));
    RC_PRE(b >= 0.01 && b <= 180.0);
    const double c = *uniform(-720.0, 720.0);
    const vec3 u = k22_tool_axis(b, c);
    // arccos(2a_z − 1) and arcsin((1 − a_z)/a_xy) are evaluated near −1 and 1 as B → 180°.
    const double tol = paper_test::conditioned_tol_deg(std::fmax((180.0 - b) * paper_test::deg, 1e-9), 1e-6);
    RC_ASSERT(std::fabs(eq3_b_deg(u.z) - b) < tol);
    RC_ASSERT(angle_diff_deg(k24_c_deg(u), c) < tol);
  });
  rc::prop("corrected [003:5] = (K24) on every case", [] {
    const vec3 u = *rc::gen::oneOf(paper_test::unit_vector_z_between(0.0, 0.999),
                                   rc::gen::apply([](double z, int axis) {
                                     const double r = std::sqrt(1 - z * z);
                                     const vec3 dirs[4] = {{r, 0, z}, {0, r, z}, {-r, 0, z}, {0, -r, z}};
                                     return dirs[axis];
                                   }, uniform(0.0, 0.999), rc::gen::resize(100, rc::gen::inRange(0, 4))));
    const auto r = eq5_c_corrected(u);
    RC_ASSERT(r.count == 1u);
    RC_ASSERT(angle_diff_deg(r.value_deg[0], k24_c_deg(u)) < 1e-9);
  });
  rc::prop("printed [003:5] fails exactly in the quadrant a_x < 0, a_y > 0 (E17)", [] {
    const vec3 u = *paper_test::unit_vector_z_between(0.0, 0.999);
    const auto r = eq5_c_printed(u);
    RC_ASSERT(r.count == 1u);
    const double error = std::remainder(r.value_deg[0] - k24_c_deg(u), 360.0);
    if (u.x < 0 && u.y > 0) {
      RC_ASSERT(std::fabs(error - 2.0 * std::atan(std::fabs(u.y / u.x)) / paper_test::deg) < 1e-9);
      if (std::fabs(u.y / u.x) > 0.01) RC_ASSERT(max_abs_diff(k22_tool_axis(eq3_b_deg(u.z), r.value_deg[0]), u) > 1e-6);
    } else {
      RC_ASSERT(std::fabs(error) < 1e-9);
      RC_ASSERT(max_abs_diff(k22_tool_axis(eq3_b_deg(u.z), r.value_deg[0]), u) < 1e-6);
    }
  });
  SECTION("the printed table has no case for a_x = a_y = 0") {
    CHECK(eq5_c_printed({0, 0, 1}).count == 0);
    CHECK(eq5_c_corrected({0, 0, 1}).count == 0);
  }
  SECTION("E17 example: C = 150 comes back wrong from the printed table") {
    const vec3 u = k22_tool_axis(60.0, 150.0);
    CHECK(u.x < 0);
    CHECK(u.y > 0);
    CHECK(*eq5_c_corrected(u).value() == Approx(150.0).margin(1e-9));
    CHECK(std::fabs(*eq5_c_printed(u).value() - 150.0) > 10.0);
  }
}

// ---------------------------------------------------------------------------------------------
// Patent CN1624613: 4-axis post-processor

TEST_CASE("P28 CN1624613: (K25) angle, (K26) move, (K27) increment", "[paper][cn1624613]") {
  using namespace kin5::paper::cn1624613;
  SECTION("VrCalculation on the half-axes") {
    CHECK(vr_calculation_deg(0, 0, 1) == 0.0);
    CHECK(vr_calculation_deg(0, 1, 0) == 90.0);
    CHECK(vr_calculation_deg(0, 0, -1) == 180.0);
    CHECK(vr_calculation_deg(0, -1, 0) == 270.0);
    CHECK(vr_calculation_deg(1, 0, 0) == 0.0);   // u along X
    CHECK(vr_calculation_deg(-1, 0, 0) == 0.0);
    CHECK(k25_a_deg({1, 0, 0}) == 0.0);
  }
  rc::prop("(K25) = atan2(u_y, u_z) mod 360 = the quadrant code", [] {
    const vec3 u = *paper_test::unit_vector();
    const double expected = std::fmod(std::atan2(u.y, u.z) / paper_test::deg + 360.0, 360.0);
    RC_ASSERT(angle_diff_deg(k25_a_deg(u), expected) < 1e-12);
    RC_ASSERT(angle_diff_deg(vr_calculation_deg(u.x, u.y, u.z), expected) < 1e-12);
    RC_ASSERT(vr_calculation_deg(u.x, u.y, u.z) >= 0.0);
    RC_ASSERT(vr_calculation_deg(u.x, u.y, u.z) < 360.0);
  });
  rc::prop("(K26) turns u onto +z and moves points by R(X, A)(p + offset)", [] {
    const vec3 u = *paper_test::unit_vector();
    RC_PRE(std::hypot(u.y, u.z) > 1e-9);
    const move4 axis = k26_move(u, u);
    RC_ASSERT(max_abs_diff(axis.xyz_mm, vec3{u.x, 0.0, std::hypot(u.y, u.z)}) < 1e-12);
    const fixture_offset off{{*uniform(-5, 5), *uniform(-5, 5), *uniform(-5, 5)}, *uniform(-10, 10)};
    const vec3 p{*uniform(-200, 200), *uniform(-200, 200), *uniform(-200, 200)};
    const move4 m = k26_move(p, u, off);
    const double a = vr_calculation_deg(u.x, u.y, u.z);
    RC_ASSERT(max_abs_diff(m.xyz_mm, eigen_rotate(kin5::unit_x, a, p + off.shift_mm)) < 1e-9);
    RC_ASSERT(std::fabs(m.a_deg - (-a + off.a_deg)) < 1e-12);
    const move4 flat = k26_move(p, u, off, false);
    RC_ASSERT(flat.xyz_mm == p + off.shift_mm);
    RC_ASSERT(flat.a_deg == off.a_deg);
  });
  rc::prop("(K27) the increment is A2 - A1 wrapped into [-180, 180]", [] {
    const move4 m1{{*uniform(-9, 9), 0, 0}, *uniform(-360.0, 0.0)}, m2{{*uniform(-9, 9), 0, 0}, *uniform(-360.0, 0.0)};
    const move4 d = k27_increment(m2, m1);
    RC_ASSERT(d.a_deg >= -180.0);
    RC_ASSERT(d.a_deg <= 180.0);
    RC_ASSERT(angle_diff_deg(d.a_deg, m2.a_deg - m1.a_deg) < 1e-12);
    RC_ASSERT(d.xyz_mm.x == m2.xyz_mm.x - m1.xyz_mm.x);
  });
  CHECK(k27_increment({{}, 350.0}, {{}, 10.0}).a_deg == -20.0);
  CHECK(k27_increment({{}, 10.0}, {{}, 350.0}).a_deg == 20.0);
  CHECK(k27_increment({{}, 190.0}, {{}, 10.0}).a_deg == 180.0);
}

TEST_CASE("P28 CN1624613: (K28) dynamic feed", "[paper][cn1624613][feed]") {
  using namespace kin5::paper::cn1624613;
  // u1 = +z (A = 0), u2 = R(X, -10) z (A = 10), L = 2 mm.
  const cl_point p1{{0, 0, 0}, {0, 0, 1}};
  const cl_point p2{{2, 0, 0}, eigen_rotate(kin5::unit_x, -10.0, {0, 0, 1})};
  SECTION("worked example values") {
    CHECK(feed_word(k28_feed_printed(p1, p2, 1000.0, 20.0, 1500.0)) == "F1223.607");
    CHECK(feed_word(k28_feed_corrected(p1, p2, 1000.0, 20.0, 1500.0)) == "F1223.607");
    CHECK(k28_feed_corrected(p1, p2, 1000.0, 20.0, 1500.0) == Approx(1000.0 * (1.0 + std::sqrt(0.05))).epsilon(1e-14));
    CHECK(feed_word(k28_feed_printed(p1, p2, 1000.0, 0.01, 1500.0)) == "F1500.000");
    CHECK(feed_word(k28_feed_corrected(p1, p2, 1000.0, 0.01, 1500.0)) == "F1500.000");
    // u at A = 350: |350 - 0| = 350 folds to 10, the same boost.
    const cl_point p3{{2, 0, 0}, eigen_rotate(kin5::unit_x, 10.0, {0, 0, 1})};
    CHECK(vr_calculation_deg(p3.u.x, p3.u.y, p3.u.z) == Approx(350.0).epsilon(1e-14));
    CHECK(feed_word(k28_feed_printed(p1, p3, 1000.0, 20.0, 1500.0)) == "F1223.607");
  }
  SECTION("no boost for theta = 0, L = 0 or R = 0") {
    const cl_point same_axis{{2, 0, 0}, {0, 0, 1}};
    const cl_point same_point{{0, 0, 0}, p2.u};
    CHECK(feed_word(k28_feed_corrected(p1, same_axis, 1000.0, 20.0, 1500.0)) == "F1000.000");
    CHECK(feed_word(k28_feed_corrected(p1, same_point, 1000.0, 20.0, 1500.0)) == "F1000.000");
    CHECK(feed_word(k28_feed_corrected(p1, p2, 1000.0, 0.0, 1500.0)) == "F1000.000");
  }
  SECTION("E15: a unit u1 whose components sum to 0 is taken as 'no previous vector'") {
    const double h = std::sqrt(0.5);
    const cl_point q1{{0, 0, 0}, {0, h, -h}};  // A = 135
    const cl_point q2{{2, 0, 0}, {0, 1, 0}};   // A = 90, so theta = 45
    CHECK(q1.u.x + q1.u.y + q1.u.z == 0.0);
    const double corrected = k28_feed_corrected(q1, q2, 1000.0, 20.0, 1e9);
    const double printed = k28_feed_printed(q1, q2, 1000.0, 20.0, 1e9);
    CHECK(corrected == Approx(1000.0 * (1.0 + std::sqrt((45.0 / 2.0) / 100.0))).epsilon(1e-14));
    CHECK(printed == Approx(1000.0 * (1.0 + std::sqrt((90.0 / 2.0) / 100.0))).epsilon(1e-14));
    // With a true "no previous vector" both use |A(u2)|.
    const cl_point none{{0, 0, 0}, {0, 0, 0}};
    CHECK(k28_feed_printed(none, q2, 1000.0, 20.0, 1e9) == k28_feed_corrected(none, q2, 1000.0, 20.0, 1e9));
  }
  rc::prop("(K28) = min(MaxF, F (1 + sqrt((theta/L)/(5R)))) with theta folded to <= 180", [] {
    const double a1 = *uniform(-179.0, 179.0), a2 = *uniform(-179.0, 179.0);
    const cl_point q1{{*uniform(-50, 50), *uniform(-50, 50), *uniform(-50, 50)}, eigen_rotate(kin5::unit_x, -a1, kin5::unit_z)};
    const cl_point q2{{*uniform(-50, 50), *uniform(-50, 50), *uniform(-50, 50)}, eigen_rotate(kin5::unit_x, -a2, kin5::unit_z)};
    const double f = *uniform(100.0, 5000.0), r = *uniform(0.1, 50.0), max_f = *uniform(100.0, 20000.0);
    const double theta = angle_diff_deg(a1, a2);
    const double l = kin5::norm(q2.tip_mm - q1.tip_mm);
    RC_PRE(theta > 1e-9 && l > 1e-9);
    const double expected = std::fmin(max_f, f * (1.0 + std::sqrt((theta / l) / (5.0 * r))));
    RC_ASSERT(std::fabs(k28_feed_corrected(q1, q2, f, r, max_f) - expected) < 1e-9 * expected);
    RC_ASSERT(k28_feed_corrected(q1, q2, f, r, max_f) <= max_f);
  });
}
