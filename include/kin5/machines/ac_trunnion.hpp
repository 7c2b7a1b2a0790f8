/// @file machines/ac_trunnion.hpp
/// A/C trunnion (Ji, side milling): a tilting table A about +X, fixed on the bed, carrying a rotary
/// table C about +Z that holds the part. Commanded angles are physical table angles (φ), so
/// ψ = −φ for both axes.
///
///     u = R(Z, −C) · R(X, −A) · ẑ = (sin A sin C, sin A cos C, cos A)        (K18)
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

struct ac_trunnion {
  static constexpr std::string_view id = "ac-trunnion";
  static constexpr std::string_view structure = "table-table: tilting table A about +X carrying rotary table C about +Z (part)";
  static constexpr vec3 tool_reference = unit_z;
  static constexpr std::array rotary{
      rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::physical, rotary_travel::endless()},
      rotary_axis{axis_letter::A, mount::table, unit_x, angle_sense::physical,
                  rotary_travel::between({-120.0}, {120.0})}};
};
static_assert(check_machine<ac_trunnion>());

}  // namespace kin5::machines
