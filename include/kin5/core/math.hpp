/// @file math.hpp
/// Elementary functions usable in constant expressions: sqrt, sin, cos, atan2, asin, acos, and
/// angle wrapping.
///
/// At run time each function forwards to `<cmath>`. During constant evaluation (where
/// `<cmath>` is not `constexpr` in C++20) it uses its own argument reduction and series, accurate
/// to a few units in the last place on the ranges kin5 needs. Tests compare both paths.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "units.hpp"

namespace kin5::math {

namespace detail {

constexpr double fabs(double x) { return x < 0 ? -x : x; }

// Nearest integer (ties away from zero), for |x| < 2^52.
constexpr double round_half_away(double x) {
  const double a = fabs(x) + 0.5;
  const auto n = static_cast<long long>(a);
  const double r = static_cast<double>(n);
  return x < 0 ? -r : r;
}

constexpr double sqrt(double x) {
  if (!(x > 0)) return x == 0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  if (x == std::numeric_limits<double>::infinity()) return x;
  // Scale into [0.25, 4) by powers of 4, so Newton needs few steps from 1.
  double scale = 1.0;
  while (x >= 4.0) { x *= 0.25; scale *= 2.0; }
  while (x < 0.25) { x *= 4.0; scale *= 0.5; }
  double r = 1.0;
  for (int i = 0; i < 8; ++i) r = 0.5 * (r + x / r);
  return r * scale;
}

// sin and cos on |r| <= pi/4 by Taylor series to the 21st/22nd order.
constexpr double sin_reduced(double r) {
  const double r2 = r * r;
  double term = r, sum = r;
  for (int n = 1; n <= 11; ++n) {
    term *= -r2 / ((2.0 * n) * (2.0 * n + 1.0));
    sum += term;
  }
  return sum;
}
constexpr double cos_reduced(double r) {
  const double r2 = r * r;
  double term = 1.0, sum = 1.0;
  for (int n = 1; n <= 11; ++n) {
    term *= -r2 / ((2.0 * n - 1.0) * (2.0 * n));
    sum += term;
  }
  return sum;
}

// x = k·pi/2 + r with |r| <= pi/4 (Cody–Waite: pi/2 split into three parts of 33 significant
// bits, so each k·part is exact and r keeps full precision for |k| < 2^20, |x| < 1.6e6).
struct reduced { double r; long long quadrant; };
constexpr reduced reduce_half_pi(double x) {
  constexpr double half_pi_1 = 1.57079632673412561417e+00;
  constexpr double half_pi_2 = 6.07710050630396597660e-11;
  constexpr double half_pi_3 = 2.02226624871116645580e-21;
  constexpr double half_pi_3_tail = 8.47842766036889956997e-32;
  const double k = round_half_away(x / 1.5707963267948966);
  const double r = (((x - k * half_pi_1) - k * half_pi_2) - k * half_pi_3) - k * half_pi_3_tail;
  auto q = static_cast<long long>(k) % 4;
  if (q < 0) q += 4;
  return {r, q};
}

constexpr double sin(double x) {
  const auto [r, q] = reduce_half_pi(x);
  switch (q) {
    case 0: return sin_reduced(r);
    case 1: return cos_reduced(r);
    case 2: return -sin_reduced(r);
    default: return -cos_reduced(r);
  }
}
constexpr double cos(double x) {
  const auto [r, q] = reduce_half_pi(x);
  switch (q) {
    case 0: return cos_reduced(r);
    case 1: return -sin_reduced(r);
    case 2: return -cos_reduced(r);
    default: return sin_reduced(r);
  }
}

// atan on [0, inf): reduce to |x| <= tan(pi/12), then the odd series.
constexpr double atan_nonneg(double x) {
  constexpr double sqrt3 = 1.7320508075688772;
  bool invert = false;
  if (x > 1.0) { x = 1.0 / x; invert = true; }
  bool shifted = false;
  if (x > 0.2679491924311227) {  // tan(pi/12)
    x = (x * sqrt3 - 1.0) / (sqrt3 + x);
    shifted = true;
  }
  const double x2 = x * x;
  double term = x, sum = x;
  for (int n = 1; n <= 16; ++n) {
    term *= -x2;
    sum += term / (2.0 * n + 1.0);
  }
  if (shifted) sum += pi / 6.0;
  if (invert) sum = pi / 2.0 - sum;
  return sum;
}

constexpr double atan2(double y, double x) {
  if (x == 0 && y == 0) return 0.0;
  if (x == 0) return y > 0 ? pi / 2 : -pi / 2;
  const double a = atan_nonneg(fabs(y) / fabs(x));
  if (x > 0) return y < 0 ? -a : a;
  return y < 0 ? -(pi - a) : pi - a;
}

}  // namespace detail

constexpr double abs(double x) { return detail::fabs(x); }

constexpr double sqrt(double x) {
  if (std::is_constant_evaluated()) return detail::sqrt(x);
  return std::sqrt(x);
}
constexpr double sin(double x) {
  if (std::is_constant_evaluated()) return detail::sin(x);
  return std::sin(x);
}
constexpr double cos(double x) {
  if (std::is_constant_evaluated()) return detail::cos(x);
  return std::cos(x);
}
constexpr double atan2(double y, double x) {
  if (std::is_constant_evaluated()) return detail::atan2(y, x);
  return std::atan2(y, x);
}
/// asin through atan2, exact at ±1, for x in [-1, 1].
constexpr double asin(double x) { return atan2(x, sqrt((1.0 - x) * (1.0 + x))); }
/// acos through atan2, exact at ±1, for x in [-1, 1].
constexpr double acos(double x) { return atan2(sqrt((1.0 - x) * (1.0 + x)), x); }

constexpr double clamp(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

/// x reduced modulo 2π into (−π, π].
constexpr double wrap_pi(double x) {
  constexpr double two_pi = 2.0 * pi;
  double r = x - two_pi * detail::round_half_away(x / two_pi);
  if (r <= -pi) r += two_pi;
  if (r > pi) r -= two_pi;
  return r;
}
constexpr radians wrap_pi(radians a) { return {wrap_pi(a.value)}; }

/// The value congruent to `a` modulo 2π that lies nearest to `reference`.
constexpr radians unwrap_near(radians a, radians reference) {
  return {reference.value + wrap_pi(a.value - reference.value)};
}

}  // namespace kin5::math
