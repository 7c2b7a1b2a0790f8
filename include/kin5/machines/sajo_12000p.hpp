/// @file machines/sajo_12000p.hpp
/// SAJO 12000P (Tian et al. 2010, machine M1): a rotary table B about +Y carrying the part and a
/// perpendicular head A about +X. Commanded angles are ISO tool-relative (ψ).
///
///     u = R(Y, B) · R(X, A) · ẑ = (cos A sin B, −sin A, cos A cos B)        (K1) = Tian et al. 2010, eq. (8)
///
/// The paper gives no A limits, only A₁ < −90° and A₂ > 0°; kin5 uses A ∈ [−120°, 30°].
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

struct sajo_12000p {
  static constexpr std::string_view id = "sajo-12000p";
  static constexpr std::string_view structure = "head-table: table B about +Y (part), head A about +X";
  static constexpr vec3 tool_reference = unit_z;
  static constexpr std::array rotary{
      rotary_axis{axis_letter::B, mount::table, unit_y, angle_sense::tool_relative, rotary_travel::endless()},
      rotary_axis{axis_letter::A, mount::head, unit_x, angle_sense::tool_relative,
                  rotary_travel::between({-120.0}, {30.0})}};
};
static_assert(check_machine<sajo_12000p>());

}  // namespace kin5::machines
