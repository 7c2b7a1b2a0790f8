/// @file machines/xyzbc_trt.hpp
/// LinuxCNC's `xyzbc-trt` simulation machine (configs/sim/axis/vismach/5axis/table-rotary-tilting,
/// kinematics module xyzbc-trt-kins; LinuxCNC manual, "5-Axis Kinematics", xyzbc-trt with
/// rotary axis offsets): a tilting table B about +Y carrying a rotary table C about +Z. LinuxCNC
/// turns both tables right-handed by the commanded angle (physical sense, opposite to ISO).
///
///     u = R(Z, −C) · R(Y, −B) · ẑ = (−sin B cos C, sin B sin C, cos B)
///
/// Published geometry: rotation point (0, 0, 0), x-offset D_x = −20 mm and z-offset D_z = −15 mm
/// of the B axis from it (the C axis passes through the rotation point), tool offset = the tool
/// length (a run-time input here). X, Y, Z place the gauge point (pivot length 0). Travel from
/// the simulation's INI file: X ±200, Y ±100, Z ±120 mm, B [−100°, 50°] (joint limits),
/// C ±36000° (taken as continuous).
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model xyzbc_trt_model = machine_model::from({
    .id = "xyzbc-trt",
    .structure = "table-table (LinuxCNC sim): tilting table B about +Y carrying rotary table C about +Z (part)",
    .linear = cartesian_axes({-200.0, 200.0}, {-100.0, 100.0}, {-120.0, 120.0}),
    .rotary = {rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::physical, rotary_travel::endless(),
                           {0.0, 0.0, 0.0}},
               rotary_axis{axis_letter::B, mount::table, unit_y, angle_sense::physical,
                           rotary_travel::between({-100.0}, {50.0}), {-20.0, 0.0, -15.0}}}});

struct xyzbc_trt : machine_type<xyzbc_trt_model> {};
static_assert(check_machine<xyzbc_trt>());

}  // namespace kin5::machines
