/// @file machines/sajo_12000p.hpp
/// SAJO 12000P (Tian et al. 2010, machine M1): a rotary table B about +Y carrying the part and a
/// perpendicular head A about +X. Commanded angles are ISO tool-relative (ψ).
///
///     u = R(Y, B) · R(X, A) · ẑ = (cos A sin B, −sin A, cos A cos B)        (K1) = Tian et al. 2010, eq. (8)
///
/// The paper gives no A limits, only A₁ < −90° and A₂ > 0°, and no positions; kin5 chooses
/// A ∈ [−120°, 30°], the B table centre 650 mm in front of the head pivot, a 250 mm pivot length
/// and the travels below (docs/catalog.md).
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

inline constexpr machine_model sajo_12000p_model = machine_model::from({
    .id = "sajo-12000p",
    .structure = "head-table: table B about +Y (part), head A about +X",
    .linear = cartesian_axes({-800.0, 800.0}, {-600.0, 600.0}, {-900.0, 100.0}),
    .rotary = {rotary_axis{axis_letter::B, mount::table, unit_y, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, -650.0}},
               rotary_axis{axis_letter::A, mount::head, unit_x, angle_sense::tool_relative,
                           rotary_travel::between({-120.0}, {30.0}), {0.0, 0.0, 0.0}}},
    .tool = {unit_z, 250.0}});

struct sajo_12000p : machine_type<sajo_12000p_model> {};
static_assert(check_machine<sajo_12000p>());

}  // namespace kin5::machines
