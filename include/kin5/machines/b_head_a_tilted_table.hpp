/// @file machines/b_head_a_tilted_table.hpp
/// Head-table machine with a tilted table axis (Li, Chen, Liu 2013): a table A turning about
/// (1, 0, −1)/√2 and a head B about +Y. A is a physical table angle (ψ = −A), B a head angle.
///
///     u = R((1,0,−1)/√2, −A) · R(Y, B) · ẑ                                    (G1)
///
/// ρ = 1, c₀ = 0: with B unlimited the whole sphere is reachable. With B ∈ [−120°, 120°] the
/// latitude p·w = sin(B − 45°) stays in [−1, sin 75°], so axes within 15° of p are not.
/// Positions are kin5's choice (docs/catalog.md): table axis through (0, 0, −400) mm, head B
/// through the pivot, 180 mm pivot length.
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model b_head_a_tilted_table_model = machine_model::from({
    .id = "b-head-a-tilted-table",
    .structure = "head-table: table A about (1,0,-1)/sqrt2 (part), head B about +Y",
    .linear = cartesian_axes({-500.0, 500.0}, {-400.0, 400.0}, {-500.0, 0.0}),
    .rotary = {rotary_axis{axis_letter::A, mount::table, {0.70710678118654752, 0.0, -0.70710678118654752},
                           angle_sense::physical, rotary_travel::endless(), {0.0, 0.0, -400.0}},
               rotary_axis{axis_letter::B, mount::head, unit_y, angle_sense::tool_relative,
                           rotary_travel::between({-120.0}, {120.0}), {0.0, 0.0, 0.0}}},
    .tool = {unit_z, 180.0}});

struct b_head_a_tilted_table : machine_type<b_head_a_tilted_table_model> {};
static_assert(check_machine<b_head_a_tilted_table>());

}  // namespace kin5::machines
