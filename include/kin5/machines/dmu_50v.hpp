/// @file machines/dmu_50v.hpp
/// DMU 50V (Liu 2010): a table B turning about (0, −1, 1)/√2, at 45° in the YZ plane, carrying
/// a rotary table C about +Z that holds the part. Commanded angles as Liu 2010's inverse
/// (eqs 1–5) uses them: B is the physical table angle, C the tool-relative one.
///
///     u = R(Z, C) · R((0,1,−1)/√2, B) · ẑ                                   (K22)
///
/// B ∈ [0°, 180°]: the tool reaches the closed upper hemisphere; at B = 180° it is −Y.
#pragma once

#include "../kinematics/machine.hpp"

namespace kin5::machines {

struct dmu_50v {
  static constexpr std::string_view id = "dmu-50v";
  static constexpr std::string_view structure = "table-table: 45-degree table B about (0,-1,1)/sqrt2 carrying rotary table C about +Z (part)";
  static constexpr vec3 tool_reference = unit_z;
  static constexpr std::array rotary{
      rotary_axis{axis_letter::C, mount::table, unit_z, angle_sense::tool_relative, rotary_travel::endless()},
      rotary_axis{axis_letter::B, mount::table, {0.0, -0.70710678118654752, 0.70710678118654752},
                  angle_sense::physical, rotary_travel::between({0.0}, {180.0})}};
};
static_assert(check_machine<dmu_50v>());

}  // namespace kin5::machines
