/// @file paper/ji_ac_table.hpp
/// Ji (side milling of ruled surfaces): the A/C dual-table tool axis and its inverse,
/// as printed and corrected, and the side-milling error bounds.
///
/// Machine: a tilting table A about +X on the bed carries a rotary table C about +Z that holds
/// the part; a and c are *physical* table angles in degrees. The chain [001:6] with the
/// matrices [001:9-10] gives u = R(Z, −c) R(X, −a) ẑ (K18). Example (docs/golden.md):
/// @code
///   auto u = kin5::paper::ji_ac_table::k18_tool_axis(37.0, 121.0);  // (0.515856159, −0.309957651, 0.798635510)
///   auto s = kin5::paper::ji_ac_table::k19_inverse(u);               // (37, 121) and (−37, 301)
/// @endcode
#pragma once

#include <array>

#include "../core/vec.hpp"
#include "degree_trig.hpp"

namespace kin5::paper::ji_ac_table {

/// Physical A/C table angles, degrees.
struct ac_angles_deg {
  double a_deg{};  ///< tilting table A about +X
  double c_deg{};  ///< rotary table C about +Z, carried by A
};

/// [001:12] as printed: (i, j, k) = (sin a cos c, sin a sin c, cos a). i and j are swapped (E10).
constexpr vec3 eq12_tool_axis_printed(double a_deg, double c_deg) {
  return {sin_deg(a_deg) * cos_deg(c_deg), sin_deg(a_deg) * sin_deg(c_deg), cos_deg(a_deg)};
}

/// (K18): u = R(Z, −c) R(X, −a) ẑ = (sin a sin c, sin a cos c, cos a), what [001:6] and
/// [001:9-10] actually give (E10 corrected).
constexpr vec3 k18_tool_axis(double a_deg, double c_deg) {
  return {sin_deg(a_deg) * sin_deg(c_deg), sin_deg(a_deg) * cos_deg(c_deg), cos_deg(a_deg)};
}

/// (K19): both inverse branches of (K18), paired by sign:
/// (+arccos k, atan2(i, j)) and (−arccos k, atan2(i, j) + 180°). At the poles k = ±1 c is free
/// (whatever atan2 gives for the two zero components).
constexpr std::array<ac_angles_deg, 2> k19_inverse(const vec3& u) {
  const double a = acos_deg(math::clamp(u.z, -1.0, 1.0));
  const double c = atan2_deg(u.x, u.y);
  return {ac_angles_deg{a, c}, ac_angles_deg{-a, c + 180.0}};
}

/// [001:13] as printed: a = ±arccos k, c = arctan(j/i) − kπ with k ∈ {0, 1}. The paper does not
/// say which sign goes with which k (E11), so all four combinations are returned, in the order
/// (+, k=0), (+, k=1), (−, k=0), (−, k=1). Which ones reproduce u depends on the sign of i.
constexpr std::array<ac_angles_deg, 4> eq13_candidates_printed(const vec3& u) {
  const double a = acos_deg(u.z);
  const double c = atan_deg(u.y / u.x);
  return {ac_angles_deg{a, c}, ac_angles_deg{a, c - 180.0}, ac_angles_deg{-a, c}, ac_angles_deg{-a, c - 180.0}};
}

/// [001:11]: the tool tip in the workpiece frame from the slide positions r_s (relative to the
/// initial state, where the tip is at the workpiece origin) and the intersection r_m of the two
/// table axes (workpiece frame), physical angles a, c in degrees, mm: the chain [001:5]
/// T(r_m) R_z(−c) R_x(−a) T(r_s − r_m) written out, (G6).
constexpr vec3 eq11_tip(const vec3& r_s_mm, const vec3& r_m_mm, double a_deg, double c_deg) {
  const double ca = cos_deg(a_deg), sa = sin_deg(a_deg), cc = cos_deg(c_deg), sc = sin_deg(c_deg);
  const vec3 d = r_s_mm - r_m_mm;
  return {r_m_mm.x + d.x * cc + d.y * ca * sc + d.z * sa * sc,
          r_m_mm.y - d.x * sc + d.y * ca * cc + d.z * sa * cc,
          r_m_mm.z - d.y * sa + d.z * ca};
}

/// (K20) = [001:3]: largest side-milling error on a convex ruled surface, mm:
/// E = R + R₂ − √(R² + R₂² + 2 R R₂ cos α). R tool radius, R₂ curvature radius of the guide curve
/// at P₂, α the angle between the surface normals at the ends of the ruling.
constexpr double eq3_convex_error_mm(double tool_radius_mm, double curvature_radius_mm, double alpha_deg) {
  const double r = tool_radius_mm, r2 = curvature_radius_mm;
  return r + r2 - math::sqrt(r * r + r2 * r2 + 2.0 * r * r2 * cos_deg(alpha_deg));
}

/// (K21) = [001:4]: the same bound on a concave surface (assumes R ≤ R₂), mm:
/// E = R − R₂ + √(R² + R₂² − 2 R R₂ cos α).
constexpr double eq4_concave_error_mm(double tool_radius_mm, double curvature_radius_mm, double alpha_deg) {
  const double r = tool_radius_mm, r2 = curvature_radius_mm;
  return r - r2 + math::sqrt(r * r + r2 * r2 - 2.0 * r * r2 * cos_deg(alpha_deg));
}

}  // namespace kin5::paper::ji_ac_table
