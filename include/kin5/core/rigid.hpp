/// @file rigid.hpp
/// `rigid_transform`: a proper rotation and a translation in millimetres, `a_T_b`, mapping
/// coordinates in frame b to coordinates in frame a.
///
/// Names carry the frames, so that a product reads as a chain: `a_T_b * b_T_c` is `a_T_c`.
/// Directions are mapped by the rotation alone (`map_direction`), points by both (`map_point`).
#pragma once

#include "vec.hpp"

namespace kin5 {

struct rigid_transform {
  mat3 rotation = mat3::identity();  ///< proper orthogonal, det = +1
  vec3 translation_mm{};             ///< origin of frame b, in frame a, millimetres

  static constexpr rigid_transform identity() noexcept { return {}; }

  /// A point given in frame b, in frame a (millimetres).
  constexpr vec3 map_point(const vec3& b_point_mm) const { return rotation * b_point_mm + translation_mm; }
  /// A direction given in frame b, in frame a.
  constexpr vec3 map_direction(const vec3& b_direction) const { return rotation * b_direction; }

  /// b_T_a from a_T_b.
  constexpr rigid_transform inverse() const {
    const mat3 rt = rotation.transposed();
    return {rt, -(rt * translation_mm)};
  }

  /// a_T_c = a_T_b * b_T_c.
  friend constexpr rigid_transform operator*(const rigid_transform& a_T_b, const rigid_transform& b_T_c) {
    return {a_T_b.rotation * b_T_c.rotation, a_T_b.map_point(b_T_c.translation_mm)};
  }
};

}  // namespace kin5
