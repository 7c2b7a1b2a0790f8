/// @file machines/xyzac_trt.hpp
/// LinuxCNC's `xyzac-trt` simulation machine (configs/sim/axis/vismach/5axis/table-rotary-tilting,
/// kinematics module xyzac-trt-kins; LinuxCNC manual, "5-Axis Kinematics", xyzac-trt with
/// rotary axis offsets): a tilting table A about +X carrying a rotary table C about +Z. LinuxCNC
/// turns both tables right-handed by the commanded angle (physical sense, opposite to ISO).
///
///     u = R(Z, −C) · R(X, −A) · ẑ = (sin A sin C, sin A cos C, cos A)
///
/// Published geometry: rotation point (0, 0, 0), y-offset D_y = 20 mm and z-offset D_z = 10 mm
/// of the A axis from it (the C axis passes through the rotation point), tool offset = the tool
/// length (a run-time input here). X, Y, Z place the gauge point (pivot length 0). Travel from
/// the simulation's INI file: X ±200, Y ±100, Z ±120 mm, A [−100°, 50°], C ±36000° (taken as
/// continuous). LinuxCNC's world coordinates are the tip plus the tool length along +Z.
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model xyzac_trt_model = machine_model::from({
    .id = "xyzac-trt",
    .structure = "table-table (LinuxCNC sim): tilting table A about +X carrying rotary table C about +Z (part)",
    .linear = cartesian_axes({-200.0, 200.0}, {-100.0, 100.0}, {-120.0, 120.0}),
    .rotary = {rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::physical, rotary_travel::endless(),
                           {0.0, 0.0, 0.0}},
               rotary_axis{axis_letter::A, mount::table, unit_x, angle_sense::physical,
                           rotary_travel::between({-100.0}, {50.0}), {0.0, 20.0, 10.0}}}});

struct xyzac_trt : machine_type<xyzac_trt_model> {};
static_assert(check_machine<xyzac_trt>());

}  // namespace kin5::machines
