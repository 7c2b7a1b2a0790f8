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

/// `angles` with every continuous axis of `m` moved by a multiple of 2π to lie nearest
/// `previous`. Bounded axes are left as they are (their shifts are separate solutions).
template <std::size_t N>
constexpr std::array<radians, N> unwrap_continuous(const machine_model& m, std::array<radians, N> angles,
                                                   const std::array<radians, N>& previous) {
  for (std::size_t i = 0; i < m.rotary_count && i < N; ++i)
    if (m.rotary(i).travel.continuous) angles[i] = math::unwrap_near(angles[i], previous[i]);
  return angles;
}

/// `unwrap_continuous` for machine type M.
template <machine M>
constexpr rotary_angles<M> unwrap_continuous(const rotary_angles<M>& angles, const rotary_angles<M>& previous) {
  return unwrap_continuous(M::model, angles, previous);
}

/// Rotary travel from `from` to `to`: {largest single-axis move, sum of moves}, radians.
template <std::size_t N>
constexpr std::array<double, 2> rotary_travel_between(const std::array<radians, N>& from, const std::array<radians, N>& to) {
  double largest = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < N; ++i) {
    const double d = math::abs(to[i].value - from[i].value);
    largest = d > largest ? d : largest;
    sum += d;
  }
  return {largest, sum};
}

/// `rotary_travel_between` for machine type M.
template <machine M>
constexpr std::array<double, 2> rotary_travel_between(const rotary_angles<M>& from, const rotary_angles<M>& to) {
  return rotary_travel_between<rotary_count<M>>(from, to);
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
/// Empty when no solution lies within travel. (Unused slots of a 4-axis machine's arrays stay
/// zero on both sides, so they add no travel.)
template <std::size_t N, std::size_t Capacity>
constexpr std::optional<std::array<radians, N>> nearest_within_travel(const machine_model& m,
                                                                      const basic_inverse_result<N, Capacity>& result,
                                                                      const std::array<radians, N>& previous) {
  std::optional<std::array<radians, N>> best;
  std::array<double, 2> best_cost{};
  for (const auto& s : result) {
    if (!s.within_travel) continue;
    const std::array<radians, N> candidate = unwrap_continuous(m, s.angles, previous);
    const auto cost = rotary_travel_between(previous, candidate);
    if (!best || shorter_travel(cost, best_cost)) {
      best = candidate;
      best_cost = cost;
    }
  }
  return best;
}

/// `nearest_within_travel` for machine type M.
template <machine M>
constexpr std::optional<rotary_angles<M>> nearest_within_travel(const inverse_result<M>& result,
                                                                const rotary_angles<M>& previous) {
  return nearest_within_travel(M::model, result, previous);
}

}  // namespace kin5
