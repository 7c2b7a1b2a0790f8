/// @file branch.hpp
/// Choosing among the solutions of `inverse`: keep those within travel, unwrap continuous axes
/// to the 360° multiple nearest a previous block, and pick the solution nearest to it.
///
/// "Nearest" is the largest single-axis move first, then the sum of moves (both in radians).
/// Moves within `travel_tie` (1e-9 rad) of each other count as equal, so that rounding never
/// decides between two branches that tilt by the same amount; full ties keep the solver's order
/// (the + branch of G3 first). Whole-program choice, which may prefer a larger move now to
/// avoid a branch switch later, lives in `branch_plan.hpp`.
#pragma once

#include <optional>

#include "inverse.hpp"

namespace kin5 {

/// `angles` with every continuous axis moved by a multiple of 2π to lie nearest `previous`.
/// Bounded axes are left as they are (their shifts are separate solutions).
template <machine M>
constexpr rotary_angles<M> unwrap_continuous(rotary_angles<M> angles, const rotary_angles<M>& previous) {
  for (std::size_t i = 0; i < rotary_count<M>; ++i)
    if (M::rotary[i].travel.continuous) angles[i] = math::unwrap_near(angles[i], previous[i]);
  return angles;
}

/// Rotary travel from `from` to `to`: {largest single-axis move, sum of moves}, radians.
template <machine M>
constexpr std::array<double, 2> rotary_travel_between(const rotary_angles<M>& from, const rotary_angles<M>& to) {
  double largest = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < rotary_count<M>; ++i) {
    const double d = math::abs(to[i].value - from[i].value);
    largest = d > largest ? d : largest;
    sum += d;
  }
  return {largest, sum};
}

/// Two rotary travels (from `rotary_travel_between`) closer than this, radians, count as equal.
inline constexpr double travel_tie = 1e-9;

/// Whether travel `a` is shorter than `b`: a smaller largest move, or the same largest move (to
/// `travel_tie`) and a smaller sum.
constexpr bool shorter_travel(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  if (a[0] < b[0] - travel_tie) return true;
  if (a[0] > b[0] + travel_tie) return false;
  return a[1] < b[1] - travel_tie;
}

/// The solution within travel nearest to `previous`, continuous axes unwrapped next to it.
/// Empty when no solution lies within travel.
template <machine M>
constexpr std::optional<rotary_angles<M>> nearest_within_travel(const inverse_result<M>& result,
                                                                const rotary_angles<M>& previous) {
  std::optional<rotary_angles<M>> best;
  std::array<double, 2> best_cost{};
  for (const auto& s : result) {
    if (!s.within_travel) continue;
    const rotary_angles<M> candidate = unwrap_continuous<M>(s.angles, previous);
    const auto cost = rotary_travel_between<M>(previous, candidate);
    if (!best || shorter_travel(cost, best_cost)) {
      best = candidate;
      best_cost = cost;
    }
  }
  return best;
}

}  // namespace kin5
