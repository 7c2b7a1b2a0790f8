/// @file paper/cn1624613.hpp
/// Patent CN1624613 (4-axis post-processor, VB source): the A angle of a tool axis,
/// the point transform with a fixture offset, the incremental A output and the dynamic feed,
/// written as the code computes them.
///
/// Machine: a rotary table A about +X. A cutter-location point is a tip p (mm) and a tool axis
/// u; angles are degrees. Example (docs/papers.md, CN1624613):
/// @code
///   using namespace kin5::paper::cn1624613;
///   cl_point p1{{0, 0, 0}, {0, 0, 1}}, p2{{2, 0, 0}, kin5::rotate(kin5::unit_x, kin5::to_radians(kin5::degrees{10}), {0, 0, 1})};
///   feed_word(k28_feed_corrected(p1, p2, 1000.0, 20.0, 1500.0));   // "F1223.607"
/// @endcode
/// `_printed` keeps the code's test for "no previous vector" (sum of components == 0, E15);
/// `_corrected` tests all three components.
#pragma once

#include <cstdio>
#include <string>

#include "../core/vec.hpp"
#include "degree_trig.hpp"

namespace kin5::paper::cn1624613 {

/// (K25): A = atan2(u_y, u_z) mod 360° ∈ [0°, 360°). u_x is ignored; u ∥ ±X gives 0.
constexpr double k25_a_deg(const vec3& u) { return wrap360_deg(atan2_deg(u.y, u.z)); }

/// (K25) as the `VrCalculation` quadrant code does it (E14: its intent, not its typos):
/// one arctangent per quadrant, the half-axes set to 0°, 90°, 180°, 270°, and 0° for y = z = 0.
constexpr double vr_calculation_deg(double x, double y, double z) {
  static_cast<void>(x);  // the code never reads X
  if (y > 0) {
    if (z > 0) return atan_deg(y / z);                     // first quadrant
    if (z < 0) return atan_deg(math::abs(z) / y) + 90.0;   // second quadrant
    return 90.0;                                           // on +Y
  }
  if (y < 0) {
    if (z > 0) return atan_deg(z / math::abs(y)) + 270.0;  // fourth quadrant
    if (z < 0) return atan_deg(math::abs(y) / math::abs(z)) + 180.0;  // third quadrant
    return 270.0;                                          // on −Y
  }
  if (z < 0) return 180.0;  // on −Z
  return 0.0;               // on +Z, or the zero vector (the array element keeps its 0)
}

/// A fixture offset: a shift in mm added to every point and an angle in degrees added to A.
struct fixture_offset {
  vec3 shift_mm{};
  double a_deg{};
};

/// One output move of the post-processor: X, Y, Z in mm and the commanded A in degrees.
struct move4 {
  vec3 xyz_mm{};
  double a_deg{};
};

/// (K26) `Calculation_Move`: p′ = R(X, +A)(p + Δxyz), A_cmd = −A + ΔA, with A = (K25)(u) when
/// multi-axis output is on and 0 otherwise. R(X, A) turns u onto +ẑ.
constexpr move4 k26_move(const vec3& tip_mm, const vec3& u, const fixture_offset& offset = {},
                         bool multi_axis = true) {
  const vec3 p = tip_mm + offset.shift_mm;
  const double a = multi_axis ? vr_calculation_deg(u.x, u.y, u.z) : 0.0;
  const double ca = cos_deg(a), sa = sin_deg(a);
  return {{p.x, p.y * ca - p.z * sa, p.y * sa + p.z * ca}, -a + offset.a_deg};
}

/// (K27) `AddMove`: the incremental move current − previous, with ΔA wrapped into
/// [−180°, 180°] (a difference of exactly ±180° is kept).
constexpr move4 k27_increment(const move4& current, const move4& previous) {
  double da = current.a_deg - previous.a_deg;
  if (da > 180.0) da = -360.0 + da;
  if (da < -180.0) da = 360.0 + da;
  return {current.xyz_mm - previous.xyz_mm, da};
}

/// A cutter-location point: tool tip (mm) and tool axis.
struct cl_point {
  vec3 tip_mm{};
  vec3 u{};
};

namespace detail {
// `stirspeed` after the angle θ is known.
constexpr double stirspeed(double theta_deg, double length_mm, double feed, double r, double max_feed) {
  if (theta_deg > 180.0) theta_deg = 360.0 - theta_deg;
  if (theta_deg == 0.0 || length_mm == 0.0 || r == 0.0) return feed;
  const double v = (math::sqrt((theta_deg / length_mm) / (5.0 * r)) + 1.0) * feed;
  return v > max_feed ? max_feed : v;
}
constexpr double distance_mm(const cl_point& p1, const cl_point& p2) {
  const vec3 d = p2.tip_mm - p1.tip_mm;
  return math::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}
}  // namespace detail

/// (K28) `stirspeed` as printed: L = |p₂ − p₁| (mm), θ = |A(u₂) − A(u₁)| folded to ≤ 180°, or
/// θ = |A(u₂)| when u₁x + u₁y + u₁z = 0 (E15: also true of unit vectors such as (0, √½, −√½));
/// V = F if θ = 0, L = 0 or R = 0, else min(MaxF, F·(1 + √((θ/L)/(5R)))). mm/min.
constexpr double k28_feed_printed(const cl_point& p1, const cl_point& p2, double feed_mm_per_min,
                                  double r, double max_feed_mm_per_min) {
  const double a2 = vr_calculation_deg(p2.u.x, p2.u.y, p2.u.z);
  const double theta = p1.u.x + p1.u.y + p1.u.z == 0.0
                           ? math::abs(a2)
                           : math::abs(a2 - vr_calculation_deg(p1.u.x, p1.u.y, p1.u.z));
  return detail::stirspeed(theta, detail::distance_mm(p1, p2), feed_mm_per_min, r, max_feed_mm_per_min);
}

/// (K28) with E15 fixed: "no previous vector" is u₁ = (0, 0, 0), all three components tested.
constexpr double k28_feed_corrected(const cl_point& p1, const cl_point& p2, double feed_mm_per_min,
                                    double r, double max_feed_mm_per_min) {
  const double a2 = vr_calculation_deg(p2.u.x, p2.u.y, p2.u.z);
  const bool no_previous = p1.u.x == 0.0 && p1.u.y == 0.0 && p1.u.z == 0.0;
  const double theta = no_previous ? math::abs(a2) : math::abs(a2 - vr_calculation_deg(p1.u.x, p1.u.y, p1.u.z));
  return detail::stirspeed(theta, detail::distance_mm(p1, p2), feed_mm_per_min, r, max_feed_mm_per_min);
}

/// The output word of (K28): "F" and the feed with three decimals, e.g. "F1223.607".
inline std::string feed_word(double feed_mm_per_min) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "F%.3f", feed_mm_per_min);
  return buffer;
}

}  // namespace kin5::paper::cn1624613
