/// @file vec.hpp
/// `vec3` and `mat3`: literal aggregates with public members, usable in constant expressions.
///
/// Column-vector convention throughout (docs/theory.md, conventions): `m * v` rotates `v`. A matrix printed in a
/// paper for row vectors is the transpose of the one used here.
#pragma once

#include <array>

#include "math.hpp"

namespace kin5 {

/// A 3-vector. Whether it is a position (millimetres) or a direction (unitless) is said by the
/// name of the variable that holds it: `tip_mm`, `axis`.
struct vec3 {
  double x{}, y{}, z{};

  friend constexpr bool operator==(const vec3&, const vec3&) = default;
  constexpr vec3 operator-() const { return {-x, -y, -z}; }
  friend constexpr vec3 operator+(const vec3& a, const vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend constexpr vec3 operator-(const vec3& a, const vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend constexpr vec3 operator*(double k, const vec3& a) { return {k * a.x, k * a.y, k * a.z}; }
  friend constexpr vec3 operator*(const vec3& a, double k) { return k * a; }
};

constexpr double dot(const vec3& a, const vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr vec3 cross(const vec3& a, const vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double squared_norm(const vec3& a) { return dot(a, a); }
constexpr double norm(const vec3& a) { return math::sqrt(dot(a, a)); }
/// `a / |a|`; the zero vector stays zero.
constexpr vec3 normalized(const vec3& a) {
  const double n = norm(a);
  return n > 0 ? (1.0 / n) * a : a;
}

/// The angle between two nonzero vectors, accurate near 0 and π (atan2 of |a×b| and a·b).
constexpr radians angle_between(const vec3& a, const vec3& b) {
  return {math::atan2(norm(cross(a, b)), dot(a, b))};
}

inline constexpr vec3 unit_x{1, 0, 0};
inline constexpr vec3 unit_y{0, 1, 0};
inline constexpr vec3 unit_z{0, 0, 1};

/// A 3×3 matrix stored by rows.
struct mat3 {
  std::array<vec3, 3> row{};

  friend constexpr bool operator==(const mat3&, const mat3&) = default;
  constexpr vec3 column(int j) const {
    return j == 0 ? vec3{row[0].x, row[1].x, row[2].x}
         : j == 1 ? vec3{row[0].y, row[1].y, row[2].y}
                  : vec3{row[0].z, row[1].z, row[2].z};
  }
  static constexpr mat3 identity() noexcept { return {{vec3{1, 0, 0}, vec3{0, 1, 0}, vec3{0, 0, 1}}}; }
  static constexpr mat3 from_columns(const vec3& c0, const vec3& c1, const vec3& c2) {
    return {{vec3{c0.x, c1.x, c2.x}, vec3{c0.y, c1.y, c2.y}, vec3{c0.z, c1.z, c2.z}}};
  }
  constexpr mat3 transposed() const { return from_columns(row[0], row[1], row[2]); }
  friend constexpr vec3 operator*(const mat3& m, const vec3& v) {
    return {dot(m.row[0], v), dot(m.row[1], v), dot(m.row[2], v)};
  }
  friend constexpr mat3 operator*(const mat3& a, const mat3& b) {
    const mat3 bt = b.transposed();
    return {{vec3{dot(a.row[0], bt.row[0]), dot(a.row[0], bt.row[1]), dot(a.row[0], bt.row[2])},
             vec3{dot(a.row[1], bt.row[0]), dot(a.row[1], bt.row[1]), dot(a.row[1], bt.row[2])},
             vec3{dot(a.row[2], bt.row[0]), dot(a.row[2], bt.row[1]), dot(a.row[2], bt.row[2])}}};
  }
};

constexpr double determinant(const mat3& m) { return dot(m.row[0], cross(m.row[1], m.row[2])); }

/// Rodrigues' formula: the right-handed rotation of `v` by `angle` about the unit vector `n`
/// (docs/theory.md, conventions): `v cosθ + (n×v) sinθ + n (n·v)(1−cosθ)`.
constexpr vec3 rotate(const vec3& n, radians angle, const vec3& v) {
  const double c = math::cos(angle.value), s = math::sin(angle.value);
  return c * v + s * cross(n, v) + ((1.0 - c) * dot(n, v)) * n;
}

/// The matrix R(n, θ) of the right-handed rotation by θ about the unit vector n.
constexpr mat3 rotation(const vec3& n, radians angle) {
  return mat3::from_columns(rotate(n, angle, unit_x), rotate(n, angle, unit_y), rotate(n, angle, unit_z));
}

}  // namespace kin5
