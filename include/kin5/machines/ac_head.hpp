/// @file machines/ac_head.hpp
/// Head-head machine (Li, Chen, Liu 2013): a head C about +Z on the ram carrying a head A about
/// +X. Head angles are physical, so ψ = commanded.
///
///     u = R(Z, C) · R(X, A) · ẑ                                               (G1)
///
/// C ∈ [−360°, 360°] is bounded but wider than a turn: a pose may be reached at two or three
/// values of C, and `inverse` lists each. Both head axes pass through the pivot; 150 mm pivot
/// length (kin5's choice, docs/catalog.md).
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model ac_head_model = machine_model::from({
    .id = "ac-head",
    .structure = "head-head: head C about +Z carrying head A about +X",
    .linear = cartesian_axes({-1000.0, 1000.0}, {-800.0, 800.0}, {-600.0, 0.0}, mount::head, mount::head,
                             mount::head),
    .rotary = {rotary_axis{axis_letter::C, mount::head, unit_z, angle_sense::tool_relative,
                           rotary_travel::between({-360.0}, {360.0}), {0.0, 0.0, 0.0}},
               rotary_axis{axis_letter::A, mount::head, unit_x, angle_sense::tool_relative,
                           rotary_travel::between({-110.0}, {110.0}), {0.0, 0.0, 0.0}}},
    .tool = {unit_z, 150.0}});

struct ac_head : machine_type<ac_head_model> {};
static_assert(check_machine<ac_head>());

}  // namespace kin5::machines
