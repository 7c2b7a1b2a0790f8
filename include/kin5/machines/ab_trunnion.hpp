/// @file machines/ab_trunnion.hpp
/// A/B trunnion: a tilting table A about +X, fixed on the bed, carrying a rotary table B about +Y
/// (a faceplate) that holds the part. Commanded angles are ISO tool-relative (ψ = commanded).
///
///     u = R(Y, B) · R(X, A) · ẑ = (cos A sin B, −sin A, cos A cos B)           (G1)
///
/// The same tool axes as `sajo-12000p`, reached with both axes on the table side. Positions and
/// travels are kin5's choice (docs/catalog.md): the B faceplate axis 120 mm above the A axis.
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model ab_trunnion_model = machine_model::from({
    .id = "ab-trunnion",
    .structure = "table-table: tilting table A about +X carrying rotary table B about +Y (part)",
    .linear = cartesian_axes({-300.0, 300.0}, {-300.0, 300.0}, {-450.0, 0.0}),
    .rotary = {rotary_axis{axis_letter::B, mount::table, unit_y, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, -130.0}},
               rotary_axis{axis_letter::A, mount::table, unit_x, angle_sense::tool_relative,
                           rotary_travel::between({-110.0}, {110.0}), {0.0, 0.0, -250.0}}}});

struct ab_trunnion : machine_type<ab_trunnion_model> {};
static_assert(check_machine<ab_trunnion>());

}  // namespace kin5::machines
