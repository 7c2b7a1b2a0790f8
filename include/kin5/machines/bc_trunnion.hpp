/// @file machines/bc_trunnion.hpp
/// B/C trunnion: a tilting table B about +Y, fixed on the bed, carrying a rotary table C about +Z
/// that holds the part. Commanded angles are ISO tool-relative (ψ = commanded).
///
///     u = R(Z, C) · R(Y, B) · ẑ = (cos C sin B, sin C sin B, cos B)            (G1)
///
/// Both axes meet 160 mm below the reference point; travels are kin5's choice (docs/catalog.md).
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model bc_trunnion_model = machine_model::from({
    .id = "bc-trunnion",
    .structure = "table-table: tilting table B about +Y carrying rotary table C about +Z (part)",
    .linear = cartesian_axes({-300.0, 300.0}, {-250.0, 250.0}, {-450.0, 0.0}),
    .rotary = {rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, -160.0}},
               rotary_axis{axis_letter::B, mount::table, unit_y, angle_sense::tool_relative,
                           rotary_travel::between({-120.0}, {120.0}), {0.0, 0.0, -160.0}}}});

struct bc_trunnion : machine_type<bc_trunnion_model> {};
static_assert(check_machine<bc_trunnion>());

}  // namespace kin5::machines
