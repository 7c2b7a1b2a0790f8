// What the source says of each block (`basic_block_source`): a target whose axes are the
// source's keeps the source's own angles, whole turns, branch switches and poles included; and
// a source sweep of 180° or more is followed, without the source's angles, by a move whose tool
// axis passes every sample of the sweep whenever the target has one.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/kinematics.hpp>
#include <kin5/kinematics/branch_plan.hpp>

#include "angle_generators.hpp"

namespace {

using namespace kin5;

/// The tool axes at s = j/n, j = 1 … n−1, of M's angles moving linearly from `from` to `to`,
/// n = 8 per half turn of the largest move, when one axis moves by 180° or more; else none.
template <machine M>
std::vector<vec3> sweep(const rotary_angles<M>& from, const rotary_angles<M>& to) {
  double largest = 0.0;
  for (std::size_t i = 0; i < rotary_count<M>; ++i) largest = std::max(largest, std::abs(to[i].value - from[i].value));
  if (largest < pi) return {};
  const std::size_t n = 8 * static_cast<std::size_t>(std::ceil(largest / pi));
  std::vector<vec3> axes;
  for (std::size_t j = 1; j < n; ++j) {
    rotary_angles<M> at{};
    for (std::size_t i = 0; i < rotary_count<M>; ++i)
      at[i] = radians{from[i].value + double(j) / double(n) * (to[i].value - from[i].value)};
    axes.push_back(tool_axis<M>(at));
  }
  return axes;
}

/// Whether M's angles moving linearly from `from` to `to` pass within `tolerance` (radians) of
/// every axis of `samples`, taken at s = j/n, j = 1 … n−1.
template <machine M>
bool follows(const rotary_angles<M>& from, const rotary_angles<M>& to, const std::vector<vec3>& samples,
             double tolerance) {
  const double n = double(samples.size() + 1);
  for (std::size_t j = 0; j < samples.size(); ++j) {
    rotary_angles<M> at{};
    for (std::size_t i = 0; i < rotary_count<M>; ++i)
      at[i] = radians{from[i].value + double(j + 1) / n * (to[i].value - from[i].value)};
    if (!(angle_between(tool_axis<M>(at), samples[j]).value <= tolerance)) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("a target whose axes are the source's keeps the source's own angles") {
  machines::for_each_machine([]<class M>() {
    rc::prop(std::string("the source's path planned on ") + std::string(M::id), [] {
      const auto n = *rc::gen::inRange<std::size_t>(1, 9);
      std::vector<rotary_angles<M>> source;
      for (std::size_t k = 0; k < n; ++k) source.push_back(test::angles_with_turns<M>(true));
      rotary_planner<M> planner;
      std::vector<std::vector<vec3>> sweeps(n);
      for (std::size_t k = 0; k < n; ++k) {
        if (k > 0) sweeps[k] = sweep<M>(source[k - 1], source[k]);
        planner.add(tool_axis<M>(source[k]), {source[k], sweeps[k]});
      }
      const auto plan = planner.finish();
      for (std::size_t k = 0; k < n; ++k) {
        RC_ASSERT(plan.angles[k].has_value());
        RC_ASSERT(!plan.sweep_lost[k]);
        RC_ASSERT(plan.source[k]);
        for (std::size_t i = 0; i < rotary_count<M>; ++i)
          RC_ASSERT(std::abs((*plan.angles[k])[i].value - source[k][i].value) <= 1e-9);
      }
    });
  });
}

TEST_CASE("a source sweep is followed whenever the target can, without the source's angles") {
  machines::for_each_machine([]<class M>() {
    rc::prop(std::string("sweeps of the source followed on ") + std::string(M::id), [] {
      const auto n = *rc::gen::inRange<std::size_t>(2, 7);
      std::vector<rotary_angles<M>> source;
      for (std::size_t k = 0; k < n; ++k) {
        source.push_back(test::angles_with_turns<M>(false));
        if constexpr (rotary_count<M> == 2) {  // off the poles, whose free angle the tool axis does not say
          const vec3 u = tool_axis<M>(source.back());
          const vec3 p = M::model.orientation.p;
          RC_PRE(angle_between(u, p).value > 1e-3 && angle_between(u, -p).value > 1e-3);
        }
      }
      rotary_planner<M> planner;
      std::vector<std::vector<vec3>> sweeps(n);
      for (std::size_t k = 0; k < n; ++k) {
        if (k > 0) sweeps[k] = sweep<M>(source[k - 1], source[k]);
        planner.add(tool_axis<M>(source[k]), {std::nullopt, sweeps[k]});
      }
      const auto plan = planner.finish();
      for (std::size_t k = 1; k < n; ++k) {
        RC_ASSERT(!plan.sweep_lost[k]);  // the source's own move is one that follows
        RC_ASSERT(follows<M>(*plan.angles[k - 1], *plan.angles[k], sweeps[k], 2e-6));
      }
    });
  });
}

TEST_CASE("a sweep the target cannot follow is marked, not shortened") {
  // A full turn of the SAJO's B table about the part (A at −30°) on the DMU 50V under the
  // identity setup: its C table turns about Z, not about Y, so no move of its axes follows.
  using S = machines::sajo_12000p;
  using T = machines::dmu_50v;
  const rotary_angles<S> from{to_radians(degrees{0.0}), to_radians(degrees{-30.0})};
  const rotary_angles<S> to{to_radians(degrees{360.0}), to_radians(degrees{-30.0})};
  const std::vector<vec3> samples = sweep<S>(from, to);
  REQUIRE(samples.size() == 15);
  rotary_planner<T> planner;
  planner.add(tool_axis<S>(from));
  planner.add(tool_axis<S>(to), {std::nullopt, samples});
  const auto plan = planner.finish();
  CHECK(!plan.sweep_lost[0]);
  CHECK(plan.sweep_lost[1]);
}
