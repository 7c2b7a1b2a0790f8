/// @file paper/liu_dmu50v.hpp
/// Liu 2010 (DMU 50V post-processor): the inverse of a dual table with a 45° B axis,
/// as printed and corrected.
///
/// Machine: a table B about (0, −1, 1)/√2 (range [0°, 180°]) carries a table C about +Z. As
/// eqs [003:1-5] use the angles, u = R(Z, C) R(n′, B) ẑ with n′ = (0, 1, −1)/√2 (K22).
/// Tool axis n = (a_x, a_y, a_z), unit, a_z ≥ 0. Degrees in and out. Example (docs/golden.md):
/// @code
///   using namespace kin5::paper::liu_dmu50v;
///   vec3 u = normalized({-1, 1, 1});
///   eq3_b_deg(u.z);   // 81.100571
///   k24_c_deg(u);     // 166.173952; eq5_c_printed(u) gives 256.17… (E17)
/// @endcode
#pragma once

#include "../core/vec.hpp"
#include "case_table.hpp"
#include "degree_trig.hpp"

namespace kin5::paper::liu_dmu50v {

/// [003:2]: OM = ½(−j + k) + (√2/2)((√2/2) cos B (j + k) + sin B i), i.e.
/// R(n′, B) ẑ = (sin B/√2, −(1 − cos B)/2, (1 + cos B)/2) (K22).
constexpr vec3 eq2_om(double b_deg) {
  constexpr double half_sqrt2 = 0.70710678118654752;
  const double cb = cos_deg(b_deg), sb = sin_deg(b_deg);
  // (√2/2)(√2/2) is written 1/2, so that B = 180° gives a_z = 0 exactly.
  return {half_sqrt2 * sb, -0.5 + 0.5 * cb, 0.5 + 0.5 * cb};
}

/// (K22): u = R(Z, C) · [003:2](B), the tool axis eqs [003:4-5] invert.
constexpr vec3 k22_tool_axis(double b_deg, double c_deg) {
  const vec3 om = eq2_om(b_deg);
  const double cc = cos_deg(c_deg), sc = sin_deg(c_deg);
  return {cc * om.x - sc * om.y, sc * om.x + cc * om.y, om.z};
}

/// (K23) = [003:3]: B = arccos(2 a_z − 1) ∈ [0°, 180°].
constexpr double eq3_b_deg(double a_z) { return acos_deg(2.0 * a_z - 1.0); }

namespace detail {
// arcsin((1 − a_z)/a_xy), the C″ term shared by every case of [003:5].
constexpr double eq5_c2_deg(const vec3& n) {
  return asin_deg((1.0 - n.z) / math::sqrt(n.x * n.x + n.y * n.y));
}
constexpr case_table_result eq5_cases(const vec3& n, bool corrected) {
  const double c2 = eq5_c2_deg(n);
  const double ax = n.x, ay = n.y;
  const double t = ax != 0.0 ? atan_deg(math::abs(ay / ax)) : 90.0;
  case_table_result r{};
  if (ax > 0 && ay > 0) r.add(1, c2 + t);
  if (ax == 0 && ay > 0) r.add(2, c2 + 90.0);
  if (ax < 0 && ay > 0) r.add(3, corrected ? c2 + 180.0 - t : c2 + t + 180.0);
  if (ax < 0 && ay == 0) r.add(4, c2 + 180.0);
  if (ax < 0 && ay < 0) r.add(5, c2 + t - 180.0);
  if (ax == 0 && ay < 0) r.add(6, c2 - 90.0);
  if (ax > 0 && ay < 0) r.add(7, c2 - t);
  if (ax > 0 && ay == 0) r.add(8, c2);
  return r;
}
}  // namespace detail

/// [003:4-5] as printed: eight cases by the signs of a_x, a_y. Case 3 (a_x < 0, a_y > 0) reads
/// arcsin(…) + arctan|a_y/a_x| + 180°, which is wrong (E17); a_x = a_y = 0 has no case.
constexpr case_table_result eq5_c_printed(const vec3& n) { return detail::eq5_cases(n, false); }

/// [003:4-5] corrected (E17): case 3 reads arcsin(…) + 180° − arctan|a_y/a_x|.
constexpr case_table_result eq5_c_corrected(const vec3& n) { return detail::eq5_cases(n, true); }

/// (K24): C = arcsin((1 − a_z)/a_xy) + atan2(a_y, a_x), the closed form of corrected [003:5].
/// The arcsin argument is clamped to 1 against rounding at a_z = 0; at the pole a_xy = 0 the
/// result is NaN (C is free there).
constexpr double k24_c_deg(const vec3& n) {
  const double s = (1.0 - n.z) / math::sqrt(n.x * n.x + n.y * n.y);
  return asin_deg(s > 1.0 ? 1.0 : s) + atan2_deg(n.y, n.x);
}

}  // namespace kin5::paper::liu_dmu50v
