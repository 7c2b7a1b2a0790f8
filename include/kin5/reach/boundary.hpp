/// @file reach/boundary.hpp
/// Where along a one-parameter family of source poses the target stops being able to follow:
/// bisection on "the numerically nearest reachable axis is within tolerance" (docs/reach.md).
///
/// Example: SAJO 12000P → DMU 80P, source A swept with B fixed: the boundary is A = 0°.
#pragma once

#include <functional>

#include "nearest_tool_axis.hpp"

namespace kin5::reach {

/// The parameter s in [reachable_at, unreachable_at] where `family(s)` (a tool axis in the
/// target frame) stops being reachable on machine `to`, to within `resolution` (same unit as s).
/// Requires family(reachable_at) reachable and family(unreachable_at) not.
inline double reach_boundary(const machine_model& to, const std::function<vec3(double)>& family, double reachable_at,
                             double unreachable_at, double resolution, radians tolerance = {1e-6}) {
  auto reachable = [&](double s) { return nearest_reachable_axis(to, family(s)).gap.value <= tolerance.value; };
  double good = reachable_at, bad = unreachable_at;
  while (std::abs(bad - good) > resolution) {
    const double mid = 0.5 * (good + bad);
    (reachable(mid) ? good : bad) = mid;
  }
  return 0.5 * (good + bad);
}

/// `reach_boundary` on machine type To.
template <machine To>
double reach_boundary(const std::function<vec3(double)>& family, double reachable_at, double unreachable_at,
                      double resolution, radians tolerance = {1e-6}) {
  return reach_boundary(To::model, family, reachable_at, unreachable_at, resolution, tolerance);
}

}  // namespace kin5::reach
