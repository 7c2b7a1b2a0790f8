/// @file paper/degree_trig.hpp
/// Trigonometry in degrees, as the source papers write their formulas, for the `kin5::paper`
/// headers. Thin wrappers over `kin5::math`, so they work in constant expressions.
///
///     sin_deg(30) == 0.5      atan_deg(1) == 45      wrap360_deg(-90) == 270
///
/// `atan_deg` is the one-argument arctangent (range (−90°, 90°)) the papers print; `atan2_deg`
/// is the quadrant-correct form the corrections use (docs/errata.md).
#pragma once

#include "../core/math.hpp"

namespace kin5::paper {

/// Degrees per radian.
inline constexpr double deg_per_rad = 180.0 / pi;

constexpr double sin_deg(double x_deg) { return math::sin(x_deg / deg_per_rad); }
constexpr double cos_deg(double x_deg) { return math::cos(x_deg / deg_per_rad); }
/// One-argument arctangent in degrees, (−90°, 90°); ±∞ gives ±90°.
constexpr double atan_deg(double x) { return math::atan2(x, 1.0) * deg_per_rad; }
/// Two-argument arctangent in degrees, (−180°, 180°].
constexpr double atan2_deg(double y, double x) { return math::atan2(y, x) * deg_per_rad; }
/// arcsin in degrees; NaN outside [−1, 1], as the printed formulas would fail there.
constexpr double asin_deg(double x) { return math::asin(x) * deg_per_rad; }
/// arccos in degrees; NaN outside [−1, 1].
constexpr double acos_deg(double x) { return math::acos(x) * deg_per_rad; }

/// `x_deg` reduced modulo 360° into [0°, 360°).
constexpr double wrap360_deg(double x_deg) {
  const double turns = x_deg / 360.0;
  auto n = static_cast<long long>(turns);  // toward zero
  if (static_cast<double>(n) > turns) --n;  // floor
  double r = x_deg - 360.0 * static_cast<double>(n);
  if (r < 0.0) r += 360.0;
  if (r >= 360.0) r -= 360.0;
  return r;
}

/// `x_deg` reduced modulo 360° into (−180°, 180°] (`wrap180`, docs/theory.md).
constexpr double wrap180_deg(double x_deg) {
  const double r = wrap360_deg(x_deg);
  return r > 180.0 ? r - 360.0 : r;
}

}  // namespace kin5::paper
