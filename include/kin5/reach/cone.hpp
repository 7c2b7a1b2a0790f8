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

/// Smallest and largest angle between the tool axis and a direction, with the angles reaching
/// them (chain order; `[1]` unused on a 4-axis machine).
struct angle_range {
  radians smallest{}, largest{};
  rotary_values at_smallest{}, at_largest{};
  bool converged = false;
};

/// The range of ∠(d, u) over the travel of machine `m`.
inline angle_range angle_range_to(const machine_model& m, const vec3& d_in, int starts_per_axis = 3) {
  const vec3 d = normalized(d_in);
  std::vector<double> lower, upper;
  detail::travel_box(m, lower, upper);
  const auto starts = detail::grid_starts(lower, upper, starts_per_axis);
  auto solve = [&](double sign) {
    const objective f = [&m, &d, sign](const std::vector<double>& x, std::vector<double>& gradient,
                                       std::vector<double>& hessian) {
      return detail::linear_in_axis(m, x, d, sign, gradient, hessian);
    };
    return minimize_in_box(f, lower, upper, starts);
  };
  const box_minimum nearest = solve(-1.0);   // maximise d·u: smallest angle
  const box_minimum farthest = solve(+1.0);  // minimise d·u: largest angle
  angle_range out;
  out.at_smallest = detail::angles_of(nearest.x);
  out.at_largest = detail::angles_of(farthest.x);
  out.smallest = angle_between(d, tool_axis(m, out.at_smallest));
  out.largest = angle_between(d, tool_axis(m, out.at_largest));
  out.converged = nearest.converged && farthest.converged;
  return out;
}

/// `angle_range_to` of machine type M.
template <machine M>
angle_range angle_range_to(const vec3& d, int starts_per_axis = 3) {
  return angle_range_to(M::model, d, starts_per_axis);
}

}  // namespace kin5::reach
