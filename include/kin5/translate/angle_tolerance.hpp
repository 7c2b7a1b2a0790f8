/// @file translate/angle_tolerance.hpp
/// The angle tolerance of a run: how far a rounded value may lie outside an edge and still count
/// as on it. A program writes each angle rounded to its last decimal, so the value it means lies
/// within half a unit of that place, 0.5·10⁻ᵈ degrees for d decimals:
///
///     tolerance = --angle-tolerance, else 0.5·10⁻ᵈ° (d: the most decimals of any A B C word),
///                 at most 0.0005° (a program of whole degrees is exact, not accurate to 1°)
///
/// It is used twice. A source rotary value outside its axis' travel by no more than it is on
/// the edge (`source_checks.hpp`). A target tool axis within `tool_axis_tolerance` of the
/// target's reach, or a target angle that far past a travel limit, is on the edge (and clamped
/// to it): rounding each of n source angles by δ turns the tool axis by at most δ each (a rotation by δ moves a unit vector by at most δ), so by at
/// most n·δ in all. CL data (APT)
/// writes the tool axis as a vector: a component rounded by 0.5·10⁻ᵈ turns it by at most
/// √3·0.5·10⁻ᵈ radians.
/// @code
///   const kin5::degrees t = kin5::default_angle_tolerance(read.resolution);  // 3 decimals: 0.0005°
///   const kin5::radians slack = kin5::tool_axis_tolerance(t, 2);            // two rotary axes
/// @endcode
#pragma once

#include <cmath>
#include <cstddef>

#include "../core/units.hpp"
#include "../program/resolution.hpp"

namespace kin5 {

/// The widest default tolerance: half a unit of the third decimal of a degree.
inline constexpr degrees widest_default_angle_tolerance{0.0005};

/// Half a unit of the last place of `decimals` decimals, at most `widest_default_angle_tolerance`.
inline degrees half_unit_deg(int decimals) {
  const double half = 0.5 * std::pow(10.0, -decimals);
  return {half < widest_default_angle_tolerance.value ? half : widest_default_angle_tolerance.value};
}

/// The default tolerance of a program that writes its numbers as `r` says (see the file
/// comment): from its angles, else from its tool-axis vectors, else 0.0005°.
inline degrees default_angle_tolerance(const program::number_resolution& r) {
  if (r.angle_decimals) return half_unit_deg(*r.angle_decimals);
  if (r.vector_decimals) {
    const double turn_deg = std::sqrt(3.0) * 0.5 * std::pow(10.0, -*r.vector_decimals) * (180.0 / pi);
    return {turn_deg < widest_default_angle_tolerance.value ? turn_deg : widest_default_angle_tolerance.value};
  }
  return widest_default_angle_tolerance;
}

/// How far the tool axis may be off when each of `rounded_values` source values (rotary angles;
/// 1 for a CL vector) is within `tolerance`: their sum.
constexpr radians tool_axis_tolerance(degrees tolerance, std::size_t rounded_values) {
  return to_radians(degrees{tolerance.value * static_cast<double>(rounded_values == 0 ? 1 : rounded_values)});
}

}  // namespace kin5
