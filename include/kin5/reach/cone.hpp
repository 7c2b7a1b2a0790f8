/// @file reach/cone.hpp
/// The range of angles a machine's tool axis can make with a fixed direction, found numerically:
/// minimise and maximise `d · u(angles)` over the travel: a target's reach cone, or the image of a
/// source's travel about a direction.
///
/// For the DMU 80P and d = ẑ the range is [0°, 90°] (closed form (G5) with ∠(p,q) = ∠(q,t) = 45°);
/// for the SAJO 12000P and d = Y it is [0°, 90° + A₂].
#pragma once

#include "nearest_tool_axis.hpp"

namespace kin5::reach {

/// Smallest and largest angle between the tool axis and a direction, with the angles reaching them.
template <machine M>
struct angle_range {
  radians smallest{}, largest{};
  rotary_angles<M> at_smallest{}, at_largest{};
  bool converged = false;
};

/// The range of ∠(d, u) over the travel of M.
template <machine M>
angle_range<M> angle_range_to(const vec3& d_in, int starts_per_axis = 3) {
  const vec3 d = normalized(d_in);
  std::vector<double> lower, upper;
  detail::travel_box<M>(lower, upper);
  const auto starts = detail::grid_starts(lower, upper, starts_per_axis);
  auto solve = [&](double sign) {
    const objective f = [&d, sign](const std::vector<double>& x, std::vector<double>& gradient,
                                   std::vector<double>& hessian) {
      return detail::linear_in_axis<M>(x, d, sign, gradient, hessian);
    };
    return minimize_in_box(f, lower, upper, starts);
  };
  const box_minimum nearest = solve(-1.0);   // maximise d·u: smallest angle
  const box_minimum farthest = solve(+1.0);  // minimise d·u: largest angle
  angle_range<M> out;
  for (std::size_t i = 0; i < rotary_count<M>; ++i) {
    out.at_smallest[i] = {nearest.x[i]};
    out.at_largest[i] = {farthest.x[i]};
  }
  out.smallest = angle_between(d, tool_axis<M>(out.at_smallest));
  out.largest = angle_between(d, tool_axis<M>(out.at_largest));
  out.converged = nearest.converged && farthest.converged;
  return out;
}

}  // namespace kin5::reach
