/// @file reach/nearest_tool_axis.hpp
/// The tool axis a machine can reach nearest to a requested one, found numerically: minimise
/// 1 − u(angles) · v over the axes' travel: the per-block gap, found without the closed form.
///
/// The closed form in `inverse` gives the same gap exactly when only the carried axis is bounded;
/// this solver is the independent check, and the exact answer when both are bounded. Every
/// function takes the machine as a `machine_model` value; the template form passes `M::model`.
#pragma once

#include <cmath>
#include <vector>

#include "../kinematics/forward.hpp"
#include "box_minimizer.hpp"

namespace kin5::reach {

/// The nearest reachable tool axis to `v`.
struct nearest_axis {
  rotary_values angles{};  ///< commanded angles in chain order, within travel (`[1]` unused on a 4-axis machine)
  vec3 axis{};             ///< the tool axis they give
  radians gap{};           ///< angle between `axis` and the requested direction
  bool converged = false;
};

namespace detail {

/// Box of commanded angles (radians): the travel, or one full turn each way for endless axes.
inline void travel_box(const machine_model& m, std::vector<double>& lower, std::vector<double>& upper) {
  for (std::size_t i = 0; i < m.rotary_count; ++i) {
    const rotary_axis& a = m.rotary(i);
    lower.push_back(a.travel.continuous ? -2.0 * pi : to_radians(a.travel.lower).value);
    upper.push_back(a.travel.continuous ? 2.0 * pi : to_radians(a.travel.upper).value);
  }
}

/// u(θ) with its first and second derivatives in the commanded angles θ. With w = R(q, ψq) t:
/// ∂u/∂ψp = p × u, ∂u/∂ψq = R(p, ψp)(q × w), ∂²u/∂ψp² = p × (p × u),
/// ∂²u/∂ψp∂ψq = p × ∂u/∂ψq, ∂²u/∂ψq² = R(p, ψp)(q × (q × w)); each scaled by dψ/dθ.
struct axis_derivatives {
  vec3 u{};
  std::array<vec3, 2> d1{};
  std::array<std::array<vec3, 2>, 2> d2{};
};

inline axis_derivatives tool_axis_derivatives(const machine_model& m, const std::vector<double>& x) {
  axis_derivatives out;
  const auto& p_axis = m.rotary(0);
  const vec3 p = p_axis.direction;
  const double sp = p_axis.psi_per_commanded();
  const radians psi_p = p_axis.psi({x[0]});
  vec3 w = m.tool_reference();
  if (m.rotary_count == 2) {
    const auto& q_axis = m.rotary(1);
    const vec3 q = q_axis.direction;
    const double sq = q_axis.psi_per_commanded();
    w = rotate(q, q_axis.psi({x[1]}), m.tool_reference());
    out.d1[1] = sq * rotate(p, psi_p, cross(q, w));
    out.d2[1][1] = (sq * sq) * rotate(p, psi_p, cross(q, cross(q, w)));
    out.d2[0][1] = out.d2[1][0] = sp * cross(p, out.d1[1]);
  }
  out.u = rotate(p, psi_p, w);
  out.d1[0] = sp * cross(p, out.u);
  out.d2[0][0] = (sp * sp) * cross(p, cross(p, out.u));
  return out;
}

/// The objective `sign · d·u(θ)` with its gradient and Hessian.
inline double linear_in_axis(const machine_model& m, const std::vector<double>& x, const vec3& d, double sign,
                             std::vector<double>& gradient, std::vector<double>& hessian) {
  const auto der = tool_axis_derivatives(m, x);
  const std::size_t n = m.rotary_count;
  for (std::size_t i = 0; i < n; ++i) {
    gradient[i] = sign * dot(der.d1[i], d);
    for (std::size_t j = 0; j < n; ++j) hessian[i * n + j] = sign * dot(der.d2[i][j], d);
  }
  return sign * dot(der.u, d);
}

/// A grid of starting points over the box, `per_axis` per axis.
inline std::vector<std::vector<double>> grid_starts(const std::vector<double>& lower, const std::vector<double>& upper,
                                                    int per_axis) {
  std::vector<std::vector<double>> starts{{}};
  for (std::size_t i = 0; i < lower.size(); ++i) {
    std::vector<std::vector<double>> next;
    for (const auto& s : starts)
      for (int k = 0; k < per_axis; ++k) {
        auto t = s;
        t.push_back(lower[i] + (upper[i] - lower[i]) * (k + 0.5) / per_axis);
        next.push_back(t);
      }
    starts = next;
  }
  return starts;
}

/// The commanded angles of a box point (radians), in chain order.
inline rotary_values angles_of(const std::vector<double>& x) {
  rotary_values out{};
  for (std::size_t i = 0; i < x.size() && i < out.size(); ++i) out[i] = {x[i]};
  return out;
}

}  // namespace detail

/// Minimises 1 − u·v over the travel of machine `m` from each of `starts` (commanded angles,
/// radians); `v` need not be unit.
inline nearest_axis nearest_reachable_axis_from(const machine_model& m, const vec3& v_in,
                                                const std::vector<std::vector<double>>& starts) {
  const vec3 v = normalized(v_in);
  std::vector<double> lower, upper;
  detail::travel_box(m, lower, upper);
  const objective f = [&m, &v](const std::vector<double>& x, std::vector<double>& gradient,
                               std::vector<double>& hessian) {
    return 1.0 + detail::linear_in_axis(m, x, v, -1.0, gradient, hessian);  // 1 − u·v
  };
  const box_minimum best = minimize_in_box(f, lower, upper, starts);
  nearest_axis out;
  out.angles = detail::angles_of(best.x);
  out.axis = tool_axis(m, out.angles);
  out.gap = angle_between(out.axis, v);
  out.converged = best.converged;
  return out;
}

/// Minimises 1 − u·v over the travel of machine `m` from a grid of `starts_per_axis` starts per axis.
inline nearest_axis nearest_reachable_axis(const machine_model& m, const vec3& v, int starts_per_axis = 3) {
  std::vector<double> lower, upper;
  detail::travel_box(m, lower, upper);
  return nearest_reachable_axis_from(m, v, detail::grid_starts(lower, upper, starts_per_axis));
}

/// `nearest_reachable_axis` of machine type M.
template <machine M>
nearest_axis nearest_reachable_axis(const vec3& v, int starts_per_axis = 3) {
  return nearest_reachable_axis(M::model, v, starts_per_axis);
}

}  // namespace kin5::reach
