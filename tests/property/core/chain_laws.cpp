// The whole-machine law suite (G6)–(G8), run for every catalog machine: forward against the
// Eigen chain of homogeneous transforms (translations included), FK∘IK and IK∘FK of the pose
// inverse, poles, linear travel at and beyond its limits, the side of a slide, the untracked
// program point, and the value API against the template API.
#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/eigen.hpp>
#include <kin5/kin5.hpp>
#include <kin5/machines/every_machine.hpp>

#include "generators.hpp"

namespace {

using namespace kin5;

double distance(const vec3& a, const vec3& b) { return std::sqrt(squared_norm(a - b)); }
double circular_distance(double x, double y) { return std::abs(std::remainder(x - y, 2.0 * pi)); }

/// The Eigen chain's tip and axis for axis values q.
template <machine M>
tool_pose oracle(const axis_position<M>& q, const run_inputs& in) {
  const Eigen::Isometry3d work_T_tool = eigen::chain_work_T_tool<M>(q, in);
  return {eigen::to_kin5(Eigen::Vector3d(work_T_tool.translation())),
          eigen::to_kin5(Eigen::Vector3d(work_T_tool.linear() * eigen::to_eigen(M::tool_reference)))};
}

/// Whether q (linear within 1e-7 mm, continuous axes modulo 2π, bounded by value) is listed.
template <machine M>
bool listed(const pose_result<M>& r, const axis_position<M>& q) {
  for (const auto& s : r) {
    bool same = distance(s.joints.xyz_mm, q.xyz_mm) <= 1e-7;
    for (std::size_t i = 0; i < rotary_count<M>; ++i)
      same = same && (M::rotary[i].travel.continuous ? circular_distance(s.joints.rotary[i].value, q.rotary[i].value)
                                                    : std::abs(s.joints.rotary[i].value - q.rotary[i].value)) <= 1e-9;
    if (same) return true;
  }
  return false;
}

/// Angular distance from u to the nearest singular latitude (poles ±p, cone edges), as in
/// machine_laws.cpp: written from the definitions.
template <machine M>
double distance_to_singular(const vec3& u) {
  const vec3 p = M::rotary[0].direction, t = M::tool_reference;
  const double theta = std::acos(std::clamp(dot(p, u), -1.0, 1.0));
  double d = std::min(theta, pi - theta);
  if constexpr (rotary_count<M> == 2) {
    const vec3 q = M::rotary[1].direction;
    const double pq = std::acos(std::clamp(dot(p, q), -1.0, 1.0)), qt = std::acos(std::clamp(dot(q, t), -1.0, 1.0));
    d = std::min({d, std::abs(theta - std::abs(pq - qt)), std::abs(theta - std::min(pq + qt, 2.0 * pi - pq - qt))});
  }
  return d;
}

/// A copy of M's model made at run time, as a machine file would give it.
template <machine M>
machine_model runtime_copy() {
  volatile double keep = 1.0;  // defeats constant folding of the copy
  machine_geometry g = M::model.geometry;
  g.tool.pivot_length_mm *= keep;
  return machine_model::from(g);
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("(G6) forward equals the Eigen chain with translations", "[core][chain]",
                        kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("tip to 1e-9 mm, axis to 1e-12, any axis values, tool length and work offset", [] {
    const auto q = *rc::gen::oneOf(test::axis_values_within<M>(), test::axis_values_anywhere<M>());
    const run_inputs in = *test::run_inputs_any();
    const tool_pose pose = forward<M>(q, in), chain = oracle<M>(q, in);
    RC_ASSERT(distance(pose.tip_mm, chain.tip_mm) <= 1e-9);
    RC_ASSERT(distance(pose.axis, chain.axis) <= 1e-12);
  });
  rc::prop("the side of a slide does not move the tip (the oracle builds both chains)", [] {
    const auto q = *test::axis_values_within<M>();
    const run_inputs in = *test::run_inputs_any();
    machine_geometry flipped = M::model.geometry;
    for (auto& a : flipped.linear) a.side = *rc::gen::arbitrary<bool>() ? mount::head : mount::table;
    const machine_model other = machine_model::from(flipped);
    const Eigen::Isometry3d a = eigen::chain_work_T_tool(M::model, q, in), b = eigen::chain_work_T_tool(other, q, in);
    RC_ASSERT((a.translation() - b.translation()).norm() <= 1e-9);
    RC_ASSERT(distance(forward(other, q, in).tip_mm, forward<M>(q, in).tip_mm) == 0.0);
  });
  rc::prop("with every rotary axis at zero the tip is the slides less work offset and tool (G8)", [] {
    auto q = *test::axis_values_within<M>();
    q.rotary = {};
    const run_inputs in = *test::run_inputs_any();
    const vec3 tip = oracle<M>(q, in).tip_mm;
    RC_ASSERT(distance(untracked_point(M::model, q.xyz_mm, in), tip) <= 1e-9);
    RC_ASSERT(distance(axes_for_untracked_point(M::model, tip, in), q.xyz_mm) <= 1e-9);
  });
}

TEMPLATE_LIST_TEST_CASE("(G7) pose inverse: FK∘IK = id and IK∘FK lists the generating axis values",
                        "[core][chain]", kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("every listed solution reproduces the tip (1e-8 mm) and the axis (1e-12)", [] {
    const auto q = *test::axis_values_within<M>();
    const run_inputs in = *test::run_inputs_any();
    const tool_pose target = oracle<M>(q, in);
    const auto r = inverse<M>(target, in);
    RC_ASSERT(r.size() > 0u);
    const double pole = norm(cross(M::rotary[0].direction, in.work_offset.map_direction(target.axis)));
    for (const auto& s : r) {
      const tool_pose back = oracle<M>(s.joints, in);
      RC_ASSERT(distance(back.tip_mm, target.tip_mm) <= 1e-8);
      const double clamp_tol = 1e-9;  // angles clamped onto a limit from travel_slack
      RC_ASSERT(distance(back.axis, target.axis) <= 1e-12 + clamp_tol + (r.status == reach_status::pole ? 2 * pole : 0.0));
    }
  });
  rc::prop("the generating values are listed, flagged within travel exactly when the slides are", [] {
    const auto q = *test::axis_values_within<M>();
    const run_inputs in = *test::run_inputs_any();
    const tool_pose target = oracle<M>(q, in);
    RC_PRE(distance_to_singular<M>(in.work_offset.map_direction(target.axis)) > 1e-5);
    const auto r = inverse<M>(target, in);
    RC_ASSERT(listed<M>(r, q));
    for (const auto& s : r) {
      bool linear_inside = true;
      const double x[3] = {s.joints.xyz_mm.x, s.joints.xyz_mm.y, s.joints.xyz_mm.z};
      double excess = 0.0;
      for (std::size_t i = 0; i < 3; ++i) {
        const auto& t = M::linear[i].travel;
        const double e = std::max({0.0, t.lower_mm - x[i], x[i] - t.upper_mm});
        excess = std::max(excess, e);
        linear_inside = linear_inside && e <= inverse_options{}.linear_slack_mm;
      }
      RC_ASSERT(s.within_travel == (s.rotary_within_travel && linear_inside));
      RC_ASSERT(std::abs(s.linear_excess_mm - (linear_inside ? 0.0 : excess)) <= 1e-12);
    }
    RC_ASSERT(r.reachable());  // q itself is within every travel
  });
  rc::prop("for any rotary angles, (G7) puts the tip exactly on the target", [] {
    const auto q = *test::axis_values_anywhere<M>();
    const run_inputs in = *test::run_inputs_any();
    const vec3 p{*test::real_in(-500, 500), *test::real_in(-500, 500), *test::real_in(-500, 500)};
    axis_position<M> joints{linear_axes_for(M::model, q.rotary, in.work_offset.map_point(p), in), q.rotary};
    RC_ASSERT(distance(oracle<M>(joints, in).tip_mm, p) <= 1e-8);
  });
}

TEMPLATE_LIST_TEST_CASE("(G7) at the poles and at the linear limits", "[core][chain]", kin5::machines::every_machine) {
  using M = TestType;
  rc::prop("near and at ±p every solution still puts the tip on the target", [] {
    const vec3 u = *test::near_axis(M::rotary[0].direction);
    const tool_pose target{{*test::real_in(-100, 100), *test::real_in(-100, 100), *test::real_in(-100, 100)}, u};
    const run_inputs in{*test::real_in(0, 200), {}};
    const auto r = inverse<M>(target, in);
    for (const auto& s : r) RC_ASSERT(distance(oracle<M>(s.joints, in).tip_mm, target.tip_mm) <= 1e-8);
  });
  rc::prop("slides exactly at a limit are within travel; 1e-3 mm beyond is outside, excess reported", [] {
    auto q = *test::axis_values_within<M>();
    const std::size_t axis = *rc::gen::inRange<std::size_t>(0, 3);
    const bool upper = *rc::gen::arbitrary<bool>();
    const auto& t = M::linear[axis].travel;
    double* x[3] = {&q.xyz_mm.x, &q.xyz_mm.y, &q.xyz_mm.z};
    *x[axis] = upper ? t.upper_mm : t.lower_mm;
    const run_inputs in{*test::real_in(0, 200), {}};
    const tool_pose target = oracle<M>(q, in);
    RC_PRE(distance_to_singular<M>(target.axis) > 1e-5);
    // The slides of (G7) carry the rotary round-off times the lever arm (~1e-11 rad × 1 m), so a
    // pose made exactly at a limit can come back ~1e-8 mm beyond it: allow 1e-6 mm here.
    inverse_options slack{};
    slack.linear_slack_mm = 1e-6;
    const auto at = inverse<M>(target, in, slack);
    RC_ASSERT(listed<M>(at, q));
    RC_ASSERT(at.reachable());
    *x[axis] += upper ? 1e-3 : -1e-3;
    const auto beyond = inverse<M>(oracle<M>(q, in), in, slack);
    bool found = false;
    for (const auto& s : beyond)
      if (std::abs(s.joints.xyz_mm.x - q.xyz_mm.x) + std::abs(s.joints.xyz_mm.y - q.xyz_mm.y) +
              std::abs(s.joints.xyz_mm.z - q.xyz_mm.z) <= 1e-7) {
        found = true;
        RC_ASSERT(!s.within_travel);
        RC_ASSERT(std::abs(s.linear_excess_mm - 1e-3) <= 1e-7);  // as `listed`: angle round-off × lever arm
      }
    RC_ASSERT(found);
  });
}

TEMPLATE_LIST_TEST_CASE("the value API is the template API", "[core][chain]", kin5::machines::every_machine) {
  using M = TestType;
  const machine_model m = runtime_copy<M>();
  rc::prop("inverse, forward and the pose inverse agree exactly with a model built at run time", [&] {
    const auto q = *test::axis_values_anywhere<M>();
    const run_inputs in = *test::run_inputs_any();
    axis_values v{q.xyz_mm, {}};
    for (std::size_t i = 0; i < rotary_count<M>; ++i) v.rotary[i] = q.rotary[i];
    const tool_pose a = forward<M>(q, in), b = forward(m, v, in);
    RC_ASSERT(a.tip_mm == b.tip_mm);
    RC_ASSERT(a.axis == b.axis);
    const auto ra = inverse<M>(a.axis), rb = inverse(m, a.axis);
    RC_ASSERT(ra.size() == rb.size());
    RC_ASSERT(ra.status == rb.status);
    for (std::size_t k = 0; k < ra.size(); ++k)
      for (std::size_t i = 0; i < rotary_count<M>; ++i) RC_ASSERT(ra[k].angles[i] == rb[k].angles[i]);
    const auto pa = inverse<M>(a, in), pb = inverse(m, a, in);
    RC_ASSERT(pa.size() == pb.size());
    for (std::size_t k = 0; k < pa.size(); ++k) {
      RC_ASSERT(pa[k].joints.xyz_mm == pb[k].joints.xyz_mm);
      RC_ASSERT(pa[k].within_travel == pb[k].within_travel);
    }
  });
}
