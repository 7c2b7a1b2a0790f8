/// @file forward.hpp
/// Forward kinematics of a machine type: commanded axis values → tool pose in the workpiece
/// frame.
///
/// `tool_axis<M>(angles)` is (G1) with each commanded angle turned into ψ by its axis' sense.
/// `forward<M>(position)` adds the tool tip: under tool-tip tracking (TRAORI, M128, G43.4) the
/// programmed X, Y, Z *are* the tip in the workpiece frame, in millimetres.
/// @code
///   using namespace kin5::literals;
///   kin5::vec3 u = kin5::tool_axis<kin5::machines::dmu_80p>({kin5::to_radians(90_deg), kin5::radians{0}});
///   // u == (1/√2, 1/2, 1/2)   (docs/golden.md)
/// @endcode
#pragma once

#include "machine.hpp"
#include "solver.hpp"

namespace kin5 {

/// A tool pose in the workpiece frame.
struct tool_pose {
  vec3 tip_mm{};  ///< tool tip, millimetres
  vec3 axis{};    ///< unit tool axis, from the tip towards the spindle
};

/// Linear and rotary axis values of machine M as programmed under tool-tip tracking.
template <machine M>
struct axis_position {
  vec3 xyz_mm{};              ///< programmed X, Y, Z in millimetres (the tool tip under TCP)
  rotary_angles<M> rotary{};  ///< commanded rotary angles in `M::rotary` order, radians
};

/// The solver geometry of a two-rotary machine: p, q and t of (G1).
template <machine M>
  requires(rotary_count<M> == 2)
constexpr two_axis_geometry geometry() {
  return two_axis_geometry::make(M::rotary[0].direction, M::rotary[1].direction, M::tool_reference);
}

/// The solver geometry of a one-rotary (4-axis) machine.
template <machine M>
  requires(rotary_count<M> == 1)
constexpr one_axis_geometry geometry() {
  return one_axis_geometry::make(M::rotary[0].direction, M::tool_reference);
}

/// The unit tool axis u in the workpiece frame for commanded rotary angles, (G1).
template <machine M>
constexpr vec3 tool_axis(const rotary_angles<M>& commanded) {
  if constexpr (rotary_count<M> == 2) {
    constexpr auto g = geometry<M>();  // a constant of M: never rebuilt at run time
    return g.tool_axis(M::rotary[0].psi(commanded[0]), M::rotary[1].psi(commanded[1]));
  } else {
    constexpr auto g = geometry<M>();
    return g.tool_axis(M::rotary[0].psi(commanded[0]));
  }
}

/// Forward kinematics under tool-tip tracking: the tip is the programmed XYZ, the axis is (G1).
template <machine M>
constexpr tool_pose forward(const axis_position<M>& q) {
  return {q.xyz_mm, tool_axis<M>(q.rotary)};
}

}  // namespace kin5
