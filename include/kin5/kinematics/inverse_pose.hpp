/// @file inverse_pose.hpp
/// Inverse kinematics of the whole machine: a tool tip and tool axis in the workpiece frame →
/// every set of axis values X Y Z and rotary angles (machine coordinates) that puts the tool
/// there, each flagged within or outside the travel of all the axes.
///
/// The rotary angles are every solution of `inverse` for the tool axis turned into the table
/// frame, u = R_W u_w; each fixes the linear axis values in closed form (G7):
///
///     x = D⁻¹ ( T(θ) W p − H(θ) g ),   g = −(L + ℓ) t
///
/// so there are exactly as many pose solutions as orientation solutions. A solution whose
/// rotary angles are within travel but whose slides are not carries the largest excess in mm.
/// @code
///   kin5::run_inputs in{.tool_length_mm = 100.0};
///   for (const auto& s : kin5::inverse<kin5::machines::ac_trunnion>({{10, 20, 5}, {0, 0.6, 0.8}}, in))
///     if (s.within_travel) { /* s.joints.xyz_mm, s.joints.rotary */ }
/// @endcode
#pragma once

#include <cstddef>
#include <optional>

#include "inverse.hpp"

namespace kin5 {

/// One solution of the pose inverse: every axis value, in machine coordinates.
template <std::size_t N>
struct basic_joint_solution {
  basic_axis_position<N> joints{};  ///< linear values (mm) and commanded rotary angles (radians)
  bool within_travel = false;       ///< every rotary and every linear axis within travel
  bool rotary_within_travel = false;
  double linear_excess_mm = 0.0;    ///< largest excess of a linear value over its travel; 0 within
  int branch = 0;                   ///< 0 for the + branch of (G3), 1 for the − branch
};

/// Every solution for one tool pose.
template <std::size_t N, std::size_t Capacity>
struct basic_pose_result {
  static constexpr std::size_t capacity = Capacity;

  /// `reachable` or `pole` when some solution is within the travel of every axis.
  reach_status status = reach_status::unreachable;
  radians gap{};  ///< orientation gap, as `inverse` reports it; 0 when the tool axis is reachable
  /// When the tool axis is reachable but no solution keeps the slides within travel: the least,
  /// over the solutions with the rotary axes within travel, of the largest linear excess, mm.
  double linear_excess_mm = 0.0;
  std::array<basic_joint_solution<N>, Capacity> items{};
  std::size_t count = 0;

  constexpr const basic_joint_solution<N>* begin() const { return items.data(); }
  constexpr const basic_joint_solution<N>* end() const { return items.data() + count; }
  constexpr std::size_t size() const { return count; }
  constexpr const basic_joint_solution<N>& operator[](std::size_t i) const { return items[i]; }
  constexpr bool reachable() const { return status != reach_status::unreachable; }
  /// The first solution within the travel of every axis, if any.
  constexpr std::optional<basic_axis_position<N>> first_within_travel() const {
    for (const auto& s : *this)
      if (s.within_travel) return s.joints;
    return std::nullopt;
  }
};

/// The pose inverse of a machine known at run time.
using pose_values = basic_pose_result<2, max_solutions_any>;
/// The pose inverse for machine type M.
template <machine_description M>
using pose_result = basic_pose_result<rotary_count<M>, max_solutions<M>()>;

/// (G7): the linear axis values that put the tip at `part_point_mm` (the tip in the table frame
/// at the zero pose, W p) with the rotary angles `rotary`.
template <std::size_t N>
constexpr vec3 linear_axes_for(const machine_model& m, const std::array<radians, N>& rotary, const vec3& part_point_mm,
                               const run_inputs& in) noexcept {
  const vec3 slides = tables_carry(m, rotary, part_point_mm) - heads_carry(m, rotary, tip_at_zero(m, in));
  return m.linear_inverse * slides;
}

/// Every set of axis values of machine `m` that puts the tool at `target` (workpiece frame),
/// written into `out` (N >= m.rotary_count), replacing what it held: a controller may keep one
/// result and reuse it on every call.
template <std::size_t N, std::size_t Capacity>
constexpr void inverse_into(const machine_model& m, const tool_pose& target, const run_inputs& in,
                            const inverse_options& options, basic_pose_result<N, Capacity>& out) noexcept {
  out.count = 0;  // the header only: the items past `count` are not read
  out.linear_excess_mm = 0.0;
  basic_inverse_result<N, Capacity> rotary{};
  inverse_into(m, in.work_offset.map_direction(normalized(target.axis)), options, rotary);
  out.gap = rotary.gap;
  const vec3 part_point = in.work_offset.map_point(target.tip_mm);
  bool any_within = false, any_rotary_within = false;
  double least_excess = 0.0;
  for (const auto& s : rotary) {
    basic_joint_solution<N> j{};
    j.joints.rotary = s.angles;
    j.joints.xyz_mm = linear_axes_for(m, s.angles, part_point, in);
    const std::array<double, 3> x{j.joints.xyz_mm.x, j.joints.xyz_mm.y, j.joints.xyz_mm.z};
    for (std::size_t i = 0; i < 3; ++i) {
      const double e = m.linear(i).travel.excess_mm(x[i]);
      j.linear_excess_mm = e > j.linear_excess_mm ? e : j.linear_excess_mm;
    }
    if (j.linear_excess_mm <= options.linear_slack_mm) j.linear_excess_mm = 0.0;
    j.rotary_within_travel = s.within_travel;
    j.within_travel = s.within_travel && j.linear_excess_mm == 0.0;
    j.branch = s.branch;
    out.items[out.count++] = j;
    any_within = any_within || j.within_travel;
    if (s.within_travel) {
      least_excess = !any_rotary_within || j.linear_excess_mm < least_excess ? j.linear_excess_mm : least_excess;
      any_rotary_within = true;
    }
  }
  out.status = any_within ? rotary.status : reach_status::unreachable;
  out.linear_excess_mm = any_within ? 0.0 : least_excess;
}

/// Every set of axis values of machine `m` that puts the tool at `target`: (G7).
constexpr pose_values inverse(const machine_model& m, const tool_pose& target, const run_inputs& in,
                              const inverse_options& options = {}) noexcept {
  pose_values out{};
  inverse_into(m, target, in, options, out);
  return out;
}

/// Every set of axis values of machine type M that puts the tool at `target`.
template <machine M>
constexpr pose_result<M> inverse(const tool_pose& target, const run_inputs& in,
                                  const inverse_options& options = {}) noexcept {
  pose_result<M> out{};
  inverse_into(M::model, target, in, options, out);
  return out;
}

}  // namespace kin5
