/// @file translate/arc_plane.hpp
/// Geometry of circular moves between two workpiece frames: the normal of a plane (G17 → +Z,
/// G18 → +Y, G19 → +X), the principal plane a rotated normal lands on (if any: the setup must
/// map an arc's plane onto XY, ZX or YZ of the target, else the arc cannot be written), a
/// vector's component along a plane's normal, an arc's centre from its signed radius, and the
/// length of an arc's tool-tip path (for inverse-time feed). Points are in millimetres, in
/// whatever frame the caller names.
/// @code
///   using namespace kin5::translate_detail;
///   const vec3 n_target = target_T_source.map_direction(plane_normal(plane_source));
///   if (const auto mapped = principal_plane(n_target))
///     use(mapped->first, mapped->second);  // the target plane, and whether its normal is −
/// @endcode
#pragma once

#include <cmath>
#include <optional>
#include <string_view>
#include <utility>

#include "../core/math.hpp"
#include "../core/vec.hpp"
#include "../program/block.hpp"

namespace kin5::translate_detail {

/// The unit normal of plane `p`: XY → +Z, ZX → +Y, YZ → +X.
inline vec3 plane_normal(program::arc_plane p) {
  return p == program::arc_plane::xy ? unit_z : (p == program::arc_plane::zx ? unit_y : unit_x);
}

/// The principal plane whose normal is ±`n`, and whether it is −, if `n` is a principal axis.
inline std::optional<std::pair<program::arc_plane, bool>> principal_plane(const vec3& n) {
  constexpr double tol = 1e-9;
  if (math::abs(math::abs(n.z) - 1.0) < tol) return std::pair{program::arc_plane::xy, n.z < 0};
  if (math::abs(math::abs(n.y) - 1.0) < tol) return std::pair{program::arc_plane::zx, n.y < 0};
  if (math::abs(math::abs(n.x) - 1.0) < tol) return std::pair{program::arc_plane::yz, n.x < 0};
  return std::nullopt;
}

/// "XY (G17)", "ZX (G18)" or "YZ (G19)", for messages.
inline std::string_view plane_name(program::arc_plane p) {
  return p == program::arc_plane::xy ? "XY (G17)" : (p == program::arc_plane::zx ? "ZX (G18)" : "YZ (G19)");
}

/// The component of `v` along the normal of plane `p` (z for XY, y for ZX, x for YZ).
inline double normal_component(const vec3& v, program::arc_plane p) {
  return p == program::arc_plane::xy ? v.z : (p == program::arc_plane::zx ? v.y : v.x);
}

/// Sets the component of `v` along the normal of plane `p` to `value`.
inline void set_normal_component(vec3& v, program::arc_plane p, double value) {
  (p == program::arc_plane::xy ? v.z : (p == program::arc_plane::zx ? v.y : v.x)) = value;
}

/// A circular move as the tool tip runs it: plane, sense, and centre or signed radius.
struct arc_path {
  program::arc_plane plane = program::arc_plane::xy;
  bool clockwise = false;               ///< G2 / DR− about +normal
  std::optional<vec3> centre_mm;        ///< absolute, in the plane of the start point
  std::optional<double> radius_mm;      ///< signed radius (CR, R) when no centre is given
};

/// The centre (mm) of arc `arc` from `start_mm` to `end_mm`, at the start's height along the
/// normal: its own, or the one its signed radius gives (positive: the arc of at most 180°,
/// negative: the longer one, as G2/G3 R and Heidenhain CR); none when the radius is more than
/// 0.005 mm short of half the chord, or the chord is empty.
inline std::optional<vec3> arc_centre_mm(const arc_path& arc, const vec3& start_mm, const vec3& end_mm) {
  const double height_mm = normal_component(start_mm, arc.plane);
  if (arc.centre_mm) {
    vec3 c = *arc.centre_mm;
    set_normal_component(c, arc.plane, height_mm);
    return c;
  }
  if (!arc.radius_mm) return std::nullopt;
  vec3 chord = end_mm - start_mm;
  set_normal_component(chord, arc.plane, 0.0);
  const double half_mm = norm(chord) / 2.0, r_mm = math::abs(*arc.radius_mm);
  if (!(half_mm > 0.0) || half_mm > r_mm + 0.005) return std::nullopt;
  const double h_mm = std::sqrt(std::fmax(0.0, r_mm * r_mm - half_mm * half_mm));
  const bool left = arc.clockwise == (*arc.radius_mm < 0);  // left of the chord, about +normal
  return start_mm + 0.5 * chord + (left ? h_mm : -h_mm) * normalized(cross(plane_normal(arc.plane), chord));
}

/// Length (mm) of the tool-tip path of arc `arc` from `start_mm` to `end_mm` (all in one
/// frame), helical rise included; a full circle when start and end coincide about a centre.
inline double arc_length_mm(const arc_path& arc, const vec3& start_mm, const vec3& end_mm) {
  const vec3 n = plane_normal(arc.plane);
  const double rise_mm = dot(end_mm - start_mm, n);
  const vec3 a = (start_mm - dot(start_mm, n) * n), b = (end_mm - dot(end_mm, n) * n);
  double radius_mm = 0.0, sweep_rad = 0.0;
  if (arc.centre_mm) {
    const vec3 c = *arc.centre_mm - dot(*arc.centre_mm, n) * n;
    radius_mm = norm(a - c);
    sweep_rad = std::atan2(dot(n, cross(a - c, b - c)), dot(a - c, b - c));  // ccw angle in (−π, π]
    if (arc.clockwise) sweep_rad = -sweep_rad;
    if (sweep_rad <= 0) sweep_rad += 2.0 * pi;  // a full circle when start == end
  } else if (arc.radius_mm) {
    radius_mm = math::abs(*arc.radius_mm);
    const double half = math::clamp(norm(b - a) / (2.0 * radius_mm), 0.0, 1.0);
    sweep_rad = 2.0 * std::asin(half);
    if (*arc.radius_mm < 0) sweep_rad = 2.0 * pi - sweep_rad;
  }
  return std::sqrt(radius_mm * sweep_rad * radius_mm * sweep_rad + rise_mm * rise_mm);
}

}  // namespace kin5::translate_detail
