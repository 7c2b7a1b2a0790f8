/// @file machines/dmu_50v.hpp
/// DMU 50V (Liu 2010): a table B turning about (0, −1, 1)/√2, at 45° in the YZ plane, carrying a
/// rotary table C about +Z that holds the part. Commanded angles as Liu's inverse (eqs 1–5) uses
/// them: B is the physical table angle, C the tool-relative one.
///
///     u = R(Z, C) · R((0,1,−1)/√2, B) · ẑ                                   (K22)
///
/// B ∈ [0°, 180°]: the tool reaches the closed upper hemisphere; at B = 180° it is −Y. Both
/// table axes pass through the point where the B axis meets the Z axis, at height H below the
/// machine reference point; the paper gives H only as a symbol, kin5 takes H = −300 mm
/// (docs/catalog.md).
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

/// H of Liu 2010, eqs (6)–(10): the z of the point where the B axis meets the Z axis, mm.
inline constexpr double dmu_50v_h_mm = -300.0;

inline constexpr machine_model dmu_50v_model = machine_model::from({
    .id = "dmu-50v",
    .structure = "table-table: 45-degree table B about (0,-1,1)/sqrt2 carrying rotary table C about +Z (part)",
    .linear = cartesian_axes({-250.0, 250.0}, {-225.0, 225.0}, {-400.0, 0.0}),
    .rotary = {rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, dmu_50v_h_mm}},
               rotary_axis{axis_letter::B, mount::table, {0.0, -0.70710678118654752, 0.70710678118654752},
                           angle_sense::physical, rotary_travel::between({0.0}, {180.0}), {0.0, 0.0, dmu_50v_h_mm}}}});

struct dmu_50v : machine_type<dmu_50v_model> {};
static_assert(check_machine<dmu_50v>());

}  // namespace kin5::machines
