/// @file machines/ac_trunnion.hpp
/// A/C trunnion (Ji): a tilting table A about +X, fixed on the bed, carrying a rotary table C
/// about +Z that holds the part. Commanded angles are physical table angles (φ), so ψ = −φ for
/// both axes.
///
///     u = R(Z, −C) · R(X, −A) · ẑ = (sin A sin C, sin A cos C, cos A)        (K18)
///
/// Positions are kin5's choice (docs/catalog.md): both axes meet 200 mm below the reference point.
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model ac_trunnion_model = machine_model::from({
    .id = "ac-trunnion",
    .structure = "table-table: tilting table A about +X carrying rotary table C about +Z (part)",
    .linear = cartesian_axes({-350.0, 350.0}, {-300.0, 300.0}, {-500.0, 0.0}),
    .rotary = {rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::physical, rotary_travel::endless(),
                           {0.0, 0.0, -200.0}},
               rotary_axis{axis_letter::A, mount::table, unit_x, angle_sense::physical,
                           rotary_travel::between({-120.0}, {120.0}), {0.0, 0.0, -200.0}}}});

struct ac_trunnion : machine_type<ac_trunnion_model> {};
static_assert(check_machine<ac_trunnion>());

}  // namespace kin5::machines
