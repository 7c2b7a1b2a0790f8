/// @file segment_distance.hpp
/// The distances the path laws measure with, written out here rather than taken from the
/// library: point to point, and point to the closed segment a–b (the foot of the perpendicular,
/// clamped to the ends; a degenerate segment is its point).
#pragma once

#include <algorithm>
#include <cmath>

#include <kin5/kin5.hpp>

namespace kin5::test {

inline double distance(const vec3& a, const vec3& b) { return std::sqrt(squared_norm(a - b)); }

inline double to_segment(const vec3& p, const vec3& a, const vec3& b) {
  const vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * ab);
}

}  // namespace kin5::test
