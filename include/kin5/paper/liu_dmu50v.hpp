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

#include <array>
#include <cstddef>

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

// ---------------------------------------------------------------------------------------------
// The workpiece transform [003:6]-[003:10]: row vectors [x y z 1], translations in the last row.

/// A 4×4 matrix for row vectors, stored by rows.
struct row_mat4 {
  std::array<std::array<double, 4>, 4> m{};

  friend constexpr row_mat4 operator*(const row_mat4& a, const row_mat4& b) {
    row_mat4 out{};
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = 0; j < 4; ++j)
        for (std::size_t k = 0; k < 4; ++k) out.m[i][j] += a.m[i][k] * b.m[k][j];
    return out;
  }
  /// [x y z 1]·M, the first three entries.
  constexpr vec3 apply(const vec3& p) const {
    const double r[4] = {p.x, p.y, p.z, 1.0};
    double o[3] = {0.0, 0.0, 0.0};
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 4; ++k) o[j] += r[k] * m[k][j];
    return {o[0], o[1], o[2]};
  }
};

/// A 3×3 row-vector matrix as a 4×4 one.
constexpr row_mat4 linear4(const std::array<std::array<double, 3>, 3>& a) {
  row_mat4 out{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) out.m[i][j] = a[i][j];
  out.m[3][3] = 1.0;
  return out;
}

/// [003:6] T₁ and [003:9] T₂: the translation by (dx, dy, dz) in the last row.
constexpr row_mat4 translation4(const vec3& d) {
  row_mat4 out = linear4({{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  out.m[3] = {d.x, d.y, d.z, 1.0};
  return out;
}

/// [003:7] as printed: R₂ = F₁·M(B)·F₂. Its first factor has (3,3) = −cos 45°, which makes it
/// singular, and its middle factor [[cos B, 0, sin B], [−sin B, cos B, 0], [0, 0, 1]] is not
/// orthogonal (E19).
constexpr row_mat4 eq7_r2_printed(double b_deg) {
  constexpr double h = 0.70710678118654752;
  const double c = cos_deg(b_deg), s = sin_deg(b_deg);
  return linear4({{{1, 0, 0}, {0, h, -h}, {0, h, -h}}}) * linear4({{{c, 0, s}, {-s, c, 0}, {0, 0, 1}}}) *
         linear4({{{1, 0, 0}, {0, h, h}, {0, -h, h}}});
}

/// [003:7] corrected (E19): (3,3) = +cos 45° and the middle factor [[cos B, sin B, 0],
/// [−sin B, cos B, 0], [0, 0, 1]]; R₂ is then the right-handed turn by +B about (0, −1, 1)/√2.
constexpr row_mat4 eq7_r2_corrected(double b_deg) {
  constexpr double h = 0.70710678118654752;
  const double c = cos_deg(b_deg), s = sin_deg(b_deg);
  return linear4({{{1, 0, 0}, {0, h, -h}, {0, h, h}}}) * linear4({{{c, s, 0}, {-s, c, 0}, {0, 0, 1}}}) *
         linear4({{{1, 0, 0}, {0, h, h}, {0, -h, h}}});
}

/// [003:8] as printed: R₁, the part turned right-handed by +C about Z. Eqs [003:4-5] need the
/// tool to turn by +C relative to the part, i.e. the part by −C (E20).
constexpr row_mat4 eq8_r1_printed(double c_deg) {
  const double c = cos_deg(c_deg), s = sin_deg(c_deg);
  return linear4({{{c, s, 0}, {-s, c, 0}, {0, 0, 1}}});
}

/// [003:8] corrected (E20): the part turned by −C, R₁ transposed.
constexpr row_mat4 eq8_r1_corrected(double c_deg) {
  const double c = cos_deg(c_deg), s = sin_deg(c_deg);
  return linear4({{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}});
}

/// [003:10] as printed: [X Y Z 1] = [x_w y_w z_w 1]·T₁·R₁·R₂·T₂ with T₁ = T(x₀, y₀, z₀ − H) and
/// T₂ = T(−x₀, −y₀, −z₀ + H); (x₀, y₀, z₀) the workpiece origin in the machine frame, H the z of
/// the point where the B axis meets the Z axis, mm. The result is relative to the unturned
/// workpiece origin, not the machine origin (E21): (G8).
constexpr vec3 eq10_point_printed(const vec3& p_mm, const vec3& origin_mm, double h_mm, double b_deg, double c_deg) {
  const vec3 d{origin_mm.x, origin_mm.y, origin_mm.z - h_mm};
  return (translation4(d) * eq8_r1_printed(c_deg) * eq7_r2_printed(b_deg) * translation4(-d)).apply(p_mm);
}

/// [003:10] corrected (E19, E20).
constexpr vec3 eq10_point_corrected(const vec3& p_mm, const vec3& origin_mm, double h_mm, double b_deg, double c_deg) {
  const vec3 d{origin_mm.x, origin_mm.y, origin_mm.z - h_mm};
  return (translation4(d) * eq8_r1_corrected(c_deg) * eq7_r2_corrected(b_deg) * translation4(-d)).apply(p_mm);
}

}  // namespace kin5::paper::liu_dmu50v
