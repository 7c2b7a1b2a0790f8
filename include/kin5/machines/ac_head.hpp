/// @file machines/ac_head.hpp
/// Head-head machine (Li, Chen, Liu 2013): a head C about +Z on the ram carrying a head A about +X.
/// Head angles are physical, so ψ = commanded.
///
///     u = R(Z, C) · R(X, A) · ẑ                               (docs/papers.md, Li et al. 2013)
///
/// C ∈ [−360°, 360°] is bounded but wider than a turn: a pose may be reached at two or three
/// values of C, and `inverse` lists each.
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

struct ac_head {
  static constexpr std::string_view id = "ac-head";
  static constexpr std::string_view structure = "head-head: head C about +Z carrying head A about +X";
  static constexpr vec3 tool_reference = unit_z;
  static constexpr std::array rotary{
      rotary_axis{axis_letter::C, mount::head, unit_z, angle_sense::tool_relative,
                  rotary_travel::between({-360.0}, {360.0})},
      rotary_axis{axis_letter::A, mount::head, unit_x, angle_sense::tool_relative,
                  rotary_travel::between({-110.0}, {110.0})}};
};
static_assert(check_machine<ac_head>());

}  // namespace kin5::machines
