/// @file machines/a_rotary_4axis.hpp
/// Four-axis machine with a rotary table A about +X (patent CN1624613, without its fixture offset).
/// Commanded angles are ISO tool-relative (ψ).
///
///     u = R(X, A) · ẑ = (0, −sin A, cos A)                                   (K25), (K26)
///
/// Only tool axes with u·X = 0 are reachable; others are reported with their gap |u_x| in angle.
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

struct a_rotary_4axis {
  static constexpr std::string_view id = "a-rotary-4axis";
  static constexpr std::string_view structure = "4-axis: rotary table A about +X (part)";
  static constexpr vec3 tool_reference = unit_z;
  static constexpr std::array rotary{
      rotary_axis{axis_letter::A, mount::table, unit_x, angle_sense::tool_relative, rotary_travel::endless()}};
};
static_assert(check_machine<a_rotary_4axis>());

}  // namespace kin5::machines
