// The whole-program branch choice: never worse than the greedy nearest choice, equal to a
// brute-force optimum on short paths, continuous axes unwrapped next to the previous block.
#include <functional>
#include <random>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kinematics.hpp>
#include <kin5/kinematics/branch_plan.hpp>

#include "angle_generators.hpp"

namespace {

using namespace kin5;

/// Tool axes of random in-travel poses of M, none at a pole nor within ten times `pole_zone` of
/// one (there the planner plans the pole itself, with the free angle kept: (P31), pole_laws.cpp).
template <machine M>
std::vector<vec3> reachable_axes(std::size_t max) {
  const auto n = *rc::gen::inRange<std::size_t>(1, max + 1);
  std::vector<vec3> axes;
  for (std::size_t k = 0; k < n; ++k) {
    const vec3 u = tool_axis<M>(*test::angles_within<M>(0.5));
    RC_PRE(inverse<M>(u).status == reach_status::reachable);
    if constexpr (rotary_count<M> == 2) {
      constexpr auto g = geometry<M>();
      RC_PRE(angle_between(u, g.p).value > 10 * pole_zone.value && angle_between(u, -g.p).value > 10 * pole_zone.value);
    }
    axes.push_back(u);
  }
  return axes;
}

template <machine M>
double travel_of(const std::vector<rotary_angles<M>>& path) {
  return total_rotary_travel<M>(std::span<const rotary_angles<M>>(path));
}

/// Greedy: the first within-travel solution, then always the nearest to the previous block.
template <machine M>
std::vector<rotary_angles<M>> greedy(const std::vector<vec3>& axes) {
  std::vector<rotary_angles<M>> out;
  for (const vec3& u : axes) {
    const auto r = inverse<M>(u);
    out.push_back(out.empty() ? *r.first_within_travel() : *nearest_within_travel<M>(r, out.back()));
  }
  return out;
}

/// Brute force: every combination of within-travel solutions, continuous axes unwrapped next
/// to the previous block; the least total travel.
template <machine M>
double brute_force(const std::vector<vec3>& axes) {
  std::vector<std::vector<rotary_angles<M>>> options;
  for (const vec3& u : axes) {
    options.emplace_back();
    for (const auto& s : inverse<M>(u))
      if (s.within_travel) options.back().push_back(s.angles);
  }
  double best = 1e300;
  std::vector<rotary_angles<M>> path;
  std::function<void(std::size_t)> walk = [&](std::size_t k) {
    if (k == options.size()) {
      best = std::min(best, travel_of<M>(path));
      return;
    }
    for (const auto& a : options[k]) {
      path.push_back(path.empty() ? a : unwrap_continuous<M>(a, path.back()));
      walk(k + 1);
      path.pop_back();
    }
  };
  walk(0);
  return best;
}

template <machine M>
std::vector<rotary_angles<M>> chosen(const rotary_path<M>& p) {
  std::vector<rotary_angles<M>> out;
  for (const auto& a : p.angles) out.push_back(*a);
  return out;
}

}  // namespace

TEST_CASE("the planned path is never worse than greedy and equals the brute-force optimum") {
  machines::for_each_machine([]<class M>() {
    rc::prop(std::string("DP optimal on ") + std::string(M::id), [] {
      const auto axes = reachable_axes<M>(6);
      const auto plan = plan_rotary_path<M>(std::span<const vec3>(axes));
      const auto path = chosen<M>(plan);
      RC_ASSERT(path.size() == axes.size());
      for (std::size_t k = 0; k < axes.size(); ++k) {
        RC_ASSERT(norm(tool_axis<M>(path[k]) - axes[k]) <= 1e-9);  // each choice is a solution
        for (std::size_t i = 0; i < rotary_count<M>; ++i) {
          if (!M::rotary[i].travel.continuous) {
            RC_ASSERT(M::rotary[i].travel.contains(path[k][i], radians{1e-9}));
          } else if (k > 0) {  // unwrapped to the nearest 360° multiple of the previous block
            RC_ASSERT(std::abs(path[k][i].value - path[k - 1][i].value) <= pi + 1e-12);
          }
        }
      }
      const double dp = travel_of<M>(path);
      RC_ASSERT(std::abs(dp - plan.travel_rad) <= 1e-9);
      RC_ASSERT(dp <= travel_of<M>(greedy<M>(axes)) + 1e-9);
      RC_ASSERT(std::abs(dp - brute_force<M>(axes)) <= 1e-9);
    });
  });
}

TEST_CASE("the planner beats the greedy choice on some paths (it is not greedy)") {
  // Random 3-block paths of in-travel poses, fixed seed: on some machine there must be a path
  // where greedy (first solution, then nearest) travels more than the planner, whose result is
  // the brute-force optimum.
  std::mt19937 random(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t strictly_better = 0;
  machines::for_each_machine([&]<class M>() {
    for (int trial = 0; trial < 300; ++trial) {
      std::vector<vec3> axes;
      for (int k = 0; k < 3; ++k) {
        rotary_angles<M> a{};
        for (std::size_t i = 0; i < rotary_count<M>; ++i) {
          const auto& t = M::rotary[i].travel;
          const double lo = t.continuous ? -180.0 : t.lower.value, hi = t.continuous ? 180.0 : t.upper.value;
          a[i] = to_radians(degrees{lo + (hi - lo) * unit(random)});
        }
        axes.push_back(tool_axis<M>(a));
      }
      const auto plan = plan_rotary_path<M>(std::span<const vec3>(axes));
      const double dp = travel_of<M>(chosen<M>(plan));
      REQUIRE(std::abs(dp - brute_force<M>(axes)) <= 1e-9);
      if (dp < travel_of<M>(greedy<M>(axes)) - 1e-6) ++strictly_better;
    }
  });
  CHECK(strictly_better > 0);
}

TEST_CASE("at a pole the free angle is the neighbour's: no move of the fixed axis") {
  using M = machines::dmu_80p;  // pole: tool along +Z (B = 0), C free
  auto u = [](double b, double c) { return tool_axis<M>({to_radians(degrees{c}), to_radians(degrees{b})}); };
  const std::vector<vec3> axes{u(30, 70), unit_z, u(30, 70)};
  const auto plan = plan_rotary_path<M>(std::span<const vec3>(axes));
  REQUIRE(plan.angles[1].has_value());
  CHECK(std::abs(to_degrees((*plan.angles[1])[0]).value - 70.0) <= 1e-9);  // C kept at 70°
  CHECK(std::abs(to_degrees((*plan.angles[1])[1]).value - 0.0) <= 1e-9);   // B = 0
  CHECK(std::abs(plan.travel_rad - 2.0 * to_radians(degrees{30.0}).value) <= 1e-9);
}
