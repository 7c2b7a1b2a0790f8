/// @file machines/b_head_a_tilted_table.hpp
/// Head-table machine with a tilted table axis (Li, Chen, Liu 2013): a table A turning about
/// (1, 0, −1)/√2 and a head B about +Y. A is a physical table angle (ψ = −A), B a head angle.
///
///     u = R((1,0,−1)/√2, −A) · R(Y, B) · ẑ                     (docs/papers.md, Li et al. 2013)
///
/// ρ = 1, c₀ = 0 (G2): with B unlimited the whole sphere is reachable. With B ∈ [−120°, 120°]
/// the latitude p·w = sin(B − 45°) stays in [−1, sin 75°], so axes within 15° of p are not.
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

struct b_head_a_tilted_table {
  static constexpr std::string_view id = "b-head-a-tilted-table";
  static constexpr std::string_view structure = "head-table: table A about (1,0,-1)/sqrt2 (part), head B about +Y";
  static constexpr vec3 tool_reference = unit_z;
  static constexpr std::array rotary{
      rotary_axis{axis_letter::A, mount::table, {0.70710678118654752, 0.0, -0.70710678118654752},
                  angle_sense::physical, rotary_travel::endless()},
      rotary_axis{axis_letter::B, mount::head, unit_y, angle_sense::tool_relative,
                  rotary_travel::between({-120.0}, {120.0})}};
};
static_assert(check_machine<b_head_a_tilted_table>());

}  // namespace kin5::machines
