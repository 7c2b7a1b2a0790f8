// P25: kin5's general two-axis solver ((G1)-(G5)) specialised to each catalog machine
// equals the corrected paper formula for it, over random poses, near poles and at reach limits.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cmath>

#include <kin5/kinematics/inverse.hpp>
#include <kin5/machines/catalog.hpp>
#include <kin5/paper/cn1624613.hpp>
#include <kin5/paper/ji_ac_table.hpp>
#include <kin5/paper/liu_dmu50v.hpp>
#include <kin5/paper/tian2010.hpp>

#include "generators.hpp"

namespace km = kin5::machines;
namespace tian = kin5::paper::tian2010;
namespace ji = kin5::paper::ji_ac_table;
namespace liu = kin5::paper::liu_dmu50v;
namespace cn = kin5::paper::cn1624613;
using kin5::vec3;
using paper_test::angle_diff_deg;
using paper_test::max_abs_diff;
using paper_test::rad;
using paper_test::to_deg;
using paper_test::uniform;

namespace {

// Whether `result` holds a solution equal (mod 360°, within tol_deg) to the paper's angles given
// in M::rotary order; its within-travel flag is returned through `within`.
template <class M, class Result>
bool has_solution(const Result& result, std::array<double, kin5::rotary_count<M>> seed_deg, double tol_deg,
                  bool* within = nullptr) {
  for (const auto& s : result) {
    bool same = true;
    for (std::size_t i = 0; i < kin5::rotary_count<M>; ++i)
      same = same && angle_diff_deg(to_deg(s.angles[i]), seed_deg[i]) < tol_deg;
    if (same) {
      if (within) *within = s.within_travel;
      return true;
    }
  }
  return false;
}

}  // namespace

TEST_CASE("P25 forward: kin5::tool_axis equals each paper's closed form", "[paper][solver]") {
  rc::prop("sajo-12000p = (K1), dmu-80p = (K5), ac-trunnion = (K18), dmu-50v = (K22), a-rotary = R(X,A)z", [] {
    const double a = *uniform(-180.0, 180.0), b = *uniform(-360.0, 360.0);
    RC_ASSERT(max_abs_diff(kin5::tool_axis<km::sajo_12000p>({rad(b), rad(a)}), tian::eq8_tool_axis(a, b)) < 1e-12);
    RC_ASSERT(max_abs_diff(kin5::tool_axis<km::dmu_80p>({rad(b), rad(a)}), tian::eq14_tool_axis(a, b)) < 1e-12);
    RC_ASSERT(max_abs_diff(kin5::tool_axis<km::ac_trunnion>({rad(b), rad(a)}), ji::k18_tool_axis(a, b)) < 1e-12);
    RC_ASSERT(max_abs_diff(kin5::tool_axis<km::dmu_50v>({rad(b), rad(a)}), liu::k22_tool_axis(a, b)) < 1e-12);
    RC_ASSERT(max_abs_diff(kin5::tool_axis<km::a_rotary_4axis>({rad(a)}), vec3{0, -std::sin(rad(a).value), std::cos(rad(a).value)}) < 1e-12);
  });
}

TEST_CASE("P25 sajo-12000p: the solver gives [000:6-7] (K2) and its second branch (K3)", "[paper][solver]") {
  rc::prop("both branches, away from and near the poles +-Y", [] {
    const vec3 u = *rc::gen::oneOf(paper_test::unit_vector(), paper_test::near_direction(kin5::unit_y, 0.1),
                                   paper_test::near_direction(-kin5::unit_y, 0.1));
    const double off_pole = std::hypot(u.x, u.z);
    RC_PRE(off_pole > 1e-9);
    const double tol = 1e-9 + 2e-13 / off_pole;
    const auto k2 = tian::k2_inverse(u);
    const auto k3 = tian::k3_second_branch(k2);
    const auto r = kin5::inverse<km::sajo_12000p>(u);
    bool within = false;
    RC_ASSERT(has_solution<km::sajo_12000p>(r, {k2.b_deg, k2.a_deg}, tol, &within));
    RC_ASSERT(within == (k2.a_deg >= -120.0 && k2.a_deg <= 30.0));
    RC_ASSERT(has_solution<km::sajo_12000p>(r, {k3.b_deg, k3.a_deg}, tol));
  });
}

TEST_CASE("P25 dmu-80p: the solver gives [000:10-13] (K7)-(K9)", "[paper][solver]") {
  rc::prop("upper hemisphere, near the pole +Z and the reach limit k = 0", [] {
    const vec3 u = *rc::gen::oneOf(paper_test::unit_vector_z_between(0.0, 1.0),
                                   paper_test::near_direction(kin5::unit_z, 0.1),
                                   paper_test::unit_vector_z_between(0.0, 1e-6));
    const double off_pole = std::hypot(u.x, u.y);
    RC_PRE(off_pole > 1e-9);
    const auto seed = tian::k7_k9_inverse(u);
    RC_ASSERT(seed.has_value());
    const auto r = kin5::inverse<km::dmu_80p>(u);
    RC_ASSERT(r.reachable());
    // At the reach limit k -> 0 (S3) B and C are square-root conditioned: the solver works from
    // theta = angle(p, u), which cannot resolve k below ~1e-16, i.e. ~1e-8 rad in B. There the
    // angles are compared loosely and every solution must still reproduce u.
    const bool at_limit = u.z < 1e-6;
    bool within = false;
    RC_ASSERT(has_solution<km::dmu_80p>(r, {seed->c_deg, seed->b_deg}, 1e-9 + 2e-13 / off_pole + (at_limit ? 1e-5 : 0.0), &within));
    RC_ASSERT(within);
    for (const auto& s : r)
      if (s.within_travel) RC_ASSERT(max_abs_diff(kin5::tool_axis<km::dmu_80p>(s.angles), u) < 1e-12);
  });
}

TEST_CASE("P25 sajo-12000p to dmu-80p: corrected (K12) with the region rule equals the solver", "[paper][solver]") {
  rc::prop("a_s over the SAJO travel [-120, 30], near the pole -90 and the reach limit 0", [] {
    const double a = *rc::gen::oneOf(uniform(-120.0, 30.0), paper_test::near(-90.0, 1.0), paper_test::near(0.0, 1.0));
    const double b = *uniform(-180.0, 180.0);
    RC_PRE(std::fabs(a + 90.0) > 1e-6 && std::fabs(a) > 1e-6);
    const auto fixed = tian::k12_corrected(a, b);
    const vec3 u_d = tian::k11_map(kin5::tool_axis<km::sajo_12000p>({rad(b), rad(a)}));
    const auto r = kin5::inverse<km::dmu_80p>(u_d);
    if (a > 0.0) {
      RC_ASSERT(fixed.rule == tian::region::none);
      RC_ASSERT(!r.reachable());
      RC_ASSERT(std::fabs(to_deg(r.gap) - fixed.gap_deg) < 1e-9);
      return;
    }
    RC_ASSERT(fixed.rule == (a < -90.0 ? tian::region::flip_c : tian::region::direct));
    // C_d is ill-conditioned at the pole a = -90 (B_d -> 0): ~1e-16/|a + 90| rad.
    const double tol = paper_test::conditioned_tol_deg(std::fabs(a + 90.0) * paper_test::deg);
    bool within = false;
    RC_ASSERT(has_solution<km::dmu_80p>(r, {fixed.angles.c_deg, fixed.angles.b_deg}, tol, &within));
    RC_ASSERT(within);
  });
}

TEST_CASE("P25 ac-trunnion: the solver gives both branches of (K19)", "[paper][solver]") {
  rc::prop("both branches, flagged by the A travel [-120, 120]", [] {
    const vec3 u = *rc::gen::oneOf(paper_test::unit_vector(), paper_test::near_direction(kin5::unit_z, 0.1),
                                   paper_test::near_direction(-kin5::unit_z, 0.1));
    const double off_pole = std::hypot(u.x, u.y);
    RC_PRE(off_pole > 1e-9);
    const double tol = 1e-9 + 2e-13 / off_pole;
    const auto r = kin5::inverse<km::ac_trunnion>(u);
    for (const auto& s : ji::k19_inverse(u)) {
      bool within = false;
      RC_ASSERT(has_solution<km::ac_trunnion>(r, {s.c_deg, s.a_deg}, tol, &within));
      RC_ASSERT(within == (std::fabs(s.a_deg) <= 120.0));
    }
  });
}

TEST_CASE("P25 dmu-50v: the solver gives [003:3] (K23) and corrected [003:5] (K24)", "[paper][solver]") {
  rc::prop("upper hemisphere, near the pole +Z and the reach limit a_z = 0", [] {
    const vec3 u = *rc::gen::oneOf(paper_test::unit_vector_z_between(0.0, 0.999),
                                   paper_test::near_direction(kin5::unit_z, 0.1),
                                   paper_test::unit_vector_z_between(0.0, 1e-6));
    const double off_pole = std::hypot(u.x, u.y);
    RC_PRE(off_pole > 1e-9);
    // [003:3] is an arccos: precise to about 1e-8 rad / sqrt(distance to its ends).
    const double tol = 1e-9 + 2e-13 / off_pole + 1e-5 * (u.z < 1e-6 || u.z > 0.999);
    const auto r = kin5::inverse<km::dmu_50v>(u);
    bool within = false;
    RC_ASSERT(has_solution<km::dmu_50v>(r, {liu::k24_c_deg(u), liu::eq3_b_deg(u.z)}, tol, &within));
    RC_ASSERT(within);
    const auto corrected = liu::eq5_c_corrected(u).value();
    RC_ASSERT(corrected.has_value());
    RC_ASSERT(has_solution<km::dmu_50v>(r, {*corrected, liu::eq3_b_deg(u.z)}, tol));
  });
}

TEST_CASE("P25 a-rotary-4axis: the solver gives (K25)/(K26) A_cmd = -A", "[paper][solver]") {
  rc::prop("tool axes in the YZ plane", [] {
    const double t = *uniform(-180.0, 180.0);
    const vec3 u{0.0, std::sin(rad(t).value), std::cos(rad(t).value)};
    const auto r = kin5::inverse<km::a_rotary_4axis>(u);
    RC_ASSERT(r.reachable());
    const auto move = cn::k26_move({0, 0, 0}, u);
    RC_ASSERT(has_solution<km::a_rotary_4axis>(r, {move.a_deg}, 1e-9));
    RC_ASSERT(has_solution<km::a_rotary_4axis>(r, {-cn::k25_a_deg(u)}, 1e-9));
  });
  rc::prop("a tool axis off the YZ plane is unreachable, gap asin|u_x|", [] {
    const vec3 u = *paper_test::unit_vector();
    RC_PRE(std::fabs(u.x) > 1e-6);
    const auto r = kin5::inverse<km::a_rotary_4axis>(u);
    RC_ASSERT(!r.reachable());
    RC_ASSERT(std::fabs(r.gap.value - std::asin(std::fabs(u.x))) < 1e-9);
  });
}

TEST_CASE("P25 b-head-a-tilted-table (Li et al. 2013): both branches reproduce u", "[paper][solver]") {
  // rho = 1, c0 = 0: with B unlimited the whole sphere is reachable. With B in [-120, 120] the
  // latitude p.w = sin(B - 45 deg) stays in [-1, sin 75 deg], so axes within 15 deg of the
  // A direction p are out of reach, by 15 deg - angle(p, u).
  rc::prop("reachable at least 15 deg from the A axis; every solution reproduces u", [] {
    const vec3 a_axis = kin5::normalized({1, 0, -1});
    const vec3 u = *rc::gen::oneOf(paper_test::unit_vector(), paper_test::near_direction(a_axis, 0.5));
    RC_PRE(kin5::norm(kin5::cross(a_axis, u)) > 1e-9);
    const double from_axis_deg = to_deg(kin5::angle_between(a_axis, u));
    RC_PRE(std::fabs(from_axis_deg - 15.0) > 1e-6);
    const auto r = kin5::inverse<km::b_head_a_tilted_table>(u);
    if (from_axis_deg < 15.0) {
      RC_ASSERT(!r.reachable());
      RC_ASSERT(std::fabs(to_deg(r.gap) - (15.0 - from_axis_deg)) < 1e-9);
      return;
    }
    RC_ASSERT(r.reachable());
    RC_ASSERT(r.size() >= 2u);
    for (const auto& s : r) {
      // Independent chain: u = R(a_T, -A) R(Y, B) z.
      const vec3 chain = paper_test::eigen_rotate(a_axis, -to_deg(s.angles[0]),
                                                  paper_test::eigen_rotate(kin5::unit_y, to_deg(s.angles[1]), kin5::unit_z));
      // inverse() clamps a B within travel_slack (1e-9 rad) beyond ±120° onto the limit.
      const bool clamped = std::fabs(std::fabs(to_deg(s.angles[1])) - 120.0) < 1e-6;
      RC_ASSERT(max_abs_diff(chain, u) < (clamped ? 1e-9 : 1e-12));
    }
  });
}
