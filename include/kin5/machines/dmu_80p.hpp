/// @file machines/dmu_80p.hpp
/// DMU 80P (Tian et al. 2010, machine M2): a rotary table C about +Z carrying the part and a head
/// B tilted at 45°, turning about p = (0, 1, 1)/√2. Commanded angles are ISO tool-relative (ψ).
///
///     u = R(Z, C) · R((0,1,1)/√2, B) · ẑ                                  (K5) = Tian et al. 2010, eq. (14)
///
/// B ∈ [0°, 180°]: the tool reaches the closed upper hemisphere k ≥ 0 (K6). Positions are kin5's
/// choice (docs/catalog.md): the head axis through the pivot, 200 mm pivot length, the C table
/// centre 500 mm below the pivot.
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model dmu_80p_model = machine_model::from({
    .id = "dmu-80p",
    .structure = "head-table: table C about +Z (part), 45-degree head B about (0,1,1)/sqrt2",
    .linear = cartesian_axes({-400.0, 400.0}, {-350.0, 350.0}, {-600.0, 0.0}),
    .rotary = {rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, -500.0}},
               rotary_axis{axis_letter::B, mount::head, {0.0, 0.70710678118654752, 0.70710678118654752},
                           angle_sense::tool_relative, rotary_travel::between({0.0}, {180.0}), {0.0, 0.0, 0.0}}},
    .tool = {unit_z, 200.0}});

struct dmu_80p : machine_type<dmu_80p_model> {};
static_assert(check_machine<dmu_80p>());

}  // namespace kin5::machines
