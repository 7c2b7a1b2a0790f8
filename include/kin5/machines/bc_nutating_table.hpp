/// @file machines/bc_nutating_table.hpp
/// Nutating B/C table: a table B turning about n = (1, 0, 1)/√2, at 45° in the XZ plane, carrying
/// a rotary table C about +Z that holds the part. Commanded angles are physical table angles (φ),
/// so ψ = −φ for both axes.
///
///     u = R(Z, −C) · R(n, −B) · ẑ,   R(n, −B) ẑ = ((1 − cos B)/2, sin B/√2, (1 + cos B)/2)    (G1)
///
/// B ∈ [0°, 180°] sweeps the tool from +Z to +X on a 45° cone, so the upper hemisphere is reached. Both axes pass through (0, 0, −250)
/// mm; travels are kin5's choice (docs/catalog.md).
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model bc_nutating_table_model = machine_model::from({
    .id = "bc-nutating-table",
    .structure = "table-table: 45-degree table B about (1,0,1)/sqrt2 carrying rotary table C about +Z (part)",
    .linear = cartesian_axes({-300.0, 300.0}, {-300.0, 300.0}, {-450.0, 0.0}),
    .rotary = {rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::physical, rotary_travel::endless(),
                           {0.0, 0.0, -250.0}},
               rotary_axis{axis_letter::B, mount::table, {0.70710678118654752, 0.0, 0.70710678118654752},
                           angle_sense::physical, rotary_travel::between({0.0}, {180.0}), {0.0, 0.0, -250.0}}}});

struct bc_nutating_table : machine_type<bc_nutating_table_model> {};
static_assert(check_machine<bc_nutating_table>());

}  // namespace kin5::machines
