/// @file forward.hpp
/// Forward kinematics: axis values → tool tip and tool axis in the workpiece frame.
///
/// `tool_axis(m, angles)` is (G1), each commanded angle turned into ψ by its axis' sense.
/// `forward(m, q, inputs)` is the whole chain (G6): the linear and rotary axis values q in
/// machine coordinates, with the tool length and work offset of `inputs`, give the tip (mm) and
/// the unit tool axis in the workpiece frame. `untracked_point` is (G8): the XYZ a program
/// without tool-tip tracking writes for the same slides. Each has a template form for machine
/// types (`tool_axis<M>`, `forward<M>`) that forwards to it with `M::model`.
/// @code
///   using namespace kin5::literals;
///   kin5::vec3 u = kin5::tool_axis<kin5::machines::dmu_80p>({kin5::to_radians(0_deg), kin5::to_radians(90_deg)});
///   // u == (1/√2, 1/2, 1/2)   (K5)
/// @endcode
#pragma once

#include <array>
#include <cstddef>

#include "../core/rigid.hpp"
#include "machine.hpp"
#include "solver.hpp"

namespace kin5 {

/// A tool pose in the workpiece frame.
struct tool_pose {
  vec3 tip_mm{};  ///< tool tip, millimetres
  vec3 axis{};    ///< unit tool axis, from the tip towards the spindle
};

/// The values of a machine's axes: X, Y, Z in mm and the commanded rotary angles in chain order
/// (workpiece to tool), radians. In machine coordinates X, Y, Z are the slide positions (G6);
/// under tool-tip tracking a program writes the tip itself there.
template <std::size_t N>
struct basic_axis_position {
  vec3 xyz_mm{};
  std::array<radians, N> rotary{};
};

/// Rotary angles of a machine known at run time: room for two, in chain order; a 4-axis machine
/// uses `[0]` and leaves `[1]` at zero.
using rotary_values = std::array<radians, 2>;
/// Axis values of a machine known at run time.
using axis_values = basic_axis_position<2>;
/// Axis values of machine type M.
template <machine_description M>
using axis_position = basic_axis_position<rotary_count<M>>;

/// What the chain needs besides the machine and the axis values (docs/theory.md, "The model").
struct run_inputs {
  double tool_length_mm = 0.0;  ///< gauge point to tool tip, along the tool axis
  rigid_transform work_offset{};  ///< machine_T_work at the zero pose: G54 shift, fixture turn
};

/// The solver geometry of a two-rotary machine type: p, q and t of (G1).
template <machine M>
  requires(rotary_count<M> == 2)
constexpr const two_axis_geometry& geometry() {
  return M::model.orientation;
}

/// The solver geometry of a one-rotary (4-axis) machine type.
template <machine M>
  requires(rotary_count<M> == 1)
constexpr const one_axis_geometry& geometry() {
  return M::model.orientation_single;
}

/// (G1): the unit tool axis u in the workpiece frame (W = identity) for commanded rotary angles.
template <std::size_t N>
constexpr vec3 tool_axis(const machine_model& m, const std::array<radians, N>& commanded) noexcept {
  if constexpr (N >= 2) {
    if (m.rotary_count == 2) return m.orientation.tool_axis(m.rotary(0).psi(commanded[0]), m.rotary(1).psi(commanded[1]));
  }
  return m.orientation_single.tool_axis(m.rotary(0).psi(commanded[0]));
}

/// (G1) for machine type M.
template <machine M>
constexpr vec3 tool_axis(const rotary_angles<M>& commanded) noexcept {
  return tool_axis(M::model, commanded);
}

/// `x` turned by rotary axis `a` through the physical angle φ about its line.
constexpr vec3 turn_about(const rotary_axis& a, radians phi, const vec3& x) noexcept {
  return a.point_mm + rotate(a.direction, phi, x - a.point_mm);
}

/// T(θ)x: where the tables carry the point x of the part (both in the machine frame).
template <std::size_t N>
constexpr vec3 tables_carry(const machine_model& m, const std::array<radians, N>& commanded, vec3 x) noexcept {
  for (std::size_t i = 0; i < m.rotary_count && i < N; ++i)  // innermost table first
    if (m.rotary(i).side == mount::table) x = turn_about(m.rotary(i), m.rotary(i).physical(commanded[i]), x);
  return x;
}

/// T(θ)⁻¹x: the point of the part (at the zero pose) that the tables bring to x.
template <std::size_t N>
constexpr vec3 tables_undo(const machine_model& m, const std::array<radians, N>& commanded, vec3 x) noexcept {
  for (std::size_t i = m.rotary_count < N ? m.rotary_count : N; i-- > 0;)  // outermost table first
    if (m.rotary(i).side == mount::table) x = turn_about(m.rotary(i), -m.rotary(i).physical(commanded[i]), x);
  return x;
}

/// H(θ)x: where the heads carry the point x of the spindle.
template <std::size_t N>
constexpr vec3 heads_carry(const machine_model& m, const std::array<radians, N>& commanded, vec3 x) noexcept {
  for (std::size_t i = m.rotary_count < N ? m.rotary_count : N; i-- > 0;)  // innermost head first
    if (m.rotary(i).side == mount::head) x = turn_about(m.rotary(i), m.rotary(i).physical(commanded[i]), x);
  return x;
}

/// g: the tool tip at the zero pose relative to the reference point, −(L + ℓ)t.
constexpr vec3 tip_at_zero(const machine_model& m, const run_inputs& in) noexcept {
  return -(m.geometry.tool.pivot_length_mm + in.tool_length_mm) * m.tool_reference();
}

/// (G6): tool tip and unit tool axis in the workpiece frame for axis values `q` in machine
/// coordinates, the tool length and the work offset of `in`.
template <std::size_t N>
constexpr tool_pose forward(const machine_model& m, const basic_axis_position<N>& q,
                            const run_inputs& in = {}) noexcept {
  const vec3 machine_tip = m.linear_displacement(q.xyz_mm) + heads_carry(m, q.rotary, tip_at_zero(m, in));
  const rigid_transform work_T_machine = in.work_offset.inverse();
  return {work_T_machine.map_point(tables_undo(m, q.rotary, machine_tip)),
          work_T_machine.map_direction(tool_axis(m, q.rotary))};
}

/// (G6) for machine type M.
template <machine M>
constexpr tool_pose forward(const axis_position<M>& q, const run_inputs& in = {}) noexcept {
  return forward(M::model, q, in);
}

/// (G8): the XYZ (workpiece frame, mm) that a program without tool-tip tracking writes for the
/// linear axis values `xyz_mm`: the tip as if every rotary axis stood at zero.
constexpr vec3 untracked_point(const machine_model& m, const vec3& xyz_mm, const run_inputs& in = {}) noexcept {
  return in.work_offset.inverse().map_point(m.linear_displacement(xyz_mm) + tip_at_zero(m, in));
}

/// (G8) solved for the linear axis values: the slides a control without tool-tip tracking drives
/// to for the programmed point `program_mm`.
constexpr vec3 axes_for_untracked_point(const machine_model& m, const vec3& program_mm,
                                        const run_inputs& in = {}) noexcept {
  return m.linear_inverse * (in.work_offset.map_point(program_mm) - tip_at_zero(m, in));
}

}  // namespace kin5
