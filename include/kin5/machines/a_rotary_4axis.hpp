/// @file machines/a_rotary_4axis.hpp
/// Four-axis machine with a rotary table A about +X (patent CN1624613). Commanded angles are ISO
/// tool-relative (ψ).
///
///     u = R(X, A) · ẑ = (0, −sin A, cos A)                                   (K25)/(K26)
///
/// Only tool axes with u·X = 0 are reachable; others are reported with their gap |u_x| in angle.
/// The A axis lies 150 mm below the reference point (kin5's choice, docs/catalog.md); the
/// patent's fixture offset is a work offset (run_inputs).
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model a_rotary_4axis_model = machine_model::from({
    .id = "a-rotary-4axis",
    .structure = "4-axis: rotary table A about +X (part)",
    .linear = cartesian_axes({-500.0, 500.0}, {-200.0, 200.0}, {-400.0, 0.0}),
    .rotary = {rotary_axis{axis_letter::A, mount::table, unit_x, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, -150.0}}}});

struct a_rotary_4axis : machine_type<a_rotary_4axis_model> {};
static_assert(check_machine<a_rotary_4axis>());

}  // namespace kin5::machines
