/// @file generators.hpp
/// RapidCheck generators for what the kinematics needs: reals in a range (uniform at every
/// size), angles, unit vectors, directions near a pole, per-machine rotary angles drawn
/// uniformly, exactly at a travel limit, or a tiny step inside or outside it, whole axis values
/// (slides and rotary axes), and run-time inputs (tool length, work offset).
#pragma once

#include <cmath>
#include <cstdint>
#include <ostream>
#include <vector>

#include <rapidcheck.h>

#include <kin5/kin5.hpp>

namespace kin5 {
/// How RapidCheck prints kin5 values in counterexamples.
inline void showValue(radians r, std::ostream& os) { os << r.value << " rad"; }
inline void showValue(const vec3& v, std::ostream& os) { os << '(' << v.x << ", " << v.y << ", " << v.z << ')'; }
}  // namespace kin5

namespace kin5::test {

/// Uniform in [lo, hi], independent of RapidCheck's size (which would otherwise bunch draws
/// near lo); shrinks towards lo.
inline rc::Gen<double> real_in(double lo, double hi) {
  constexpr std::int64_t steps = std::int64_t{1} << 52;
  return rc::gen::resize(100, rc::gen::map(rc::gen::inRange<std::int64_t>(0, steps + 1), [lo, hi](std::int64_t k) {
    const double f = static_cast<double>(k) / static_cast<double>(steps);
    return lo + (hi - lo) * f;
  }));
}

/// An angle in radians, uniform in [lo, hi].
inline rc::Gen<radians> angle_in(double lo, double hi) {
  return rc::gen::map(real_in(lo, hi), [](double a) { return radians{a}; });
}

/// 10^e for e uniform in [lo_exp, hi_exp]: tiny values spread over many decades.
inline rc::Gen<double> log_uniform(double lo_exp, double hi_exp) {
  return rc::gen::map(real_in(lo_exp, hi_exp), [](double e) { return std::pow(10.0, e); });
}

/// A unit vector, uniform on the sphere (z uniform, azimuth uniform).
inline rc::Gen<vec3> unit_vector() {
  return rc::gen::apply(
      [](double z, double phi) {
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return vec3{r * std::cos(phi), r * std::sin(phi), z};
      },
      real_in(-1.0, 1.0), real_in(-pi, pi));
}

/// A unit vector perpendicular to the unit vector n (uniform on that circle).
inline vec3 perpendicular(const vec3& n, double phi) {
  const vec3 helper = std::abs(n.x) < 0.6 ? unit_x : unit_y;
  const vec3 e1 = normalized(cross(n, helper));
  const vec3 e2 = cross(n, e1);
  return std::cos(phi) * e1 + std::sin(phi) * e2;
}

/// A unit vector at angle `eps` (radians) from the unit vector n, in direction `phi` around it.
inline vec3 tilted(const vec3& n, double eps, double phi) {
  return std::cos(eps) * n + std::sin(eps) * perpendicular(n, phi);
}

/// A unit vector within 1e-12 .. 1e-3 rad of +n or −n, or exactly on it.
inline rc::Gen<vec3> near_axis(const vec3& n) {
  return rc::gen::apply(
      [n](bool flip, double eps, double phi, bool exact) {
        const vec3 m = flip ? -n : n;
        return exact ? m : tilted(m, eps, phi);
      },
      rc::gen::arbitrary<bool>(), log_uniform(-12.0, -3.0), real_in(-pi, pi),
      rc::gen::weightedOneOf<bool>({{1, rc::gen::just(true)}, {4, rc::gen::just(false)}}));
}

/// How a commanded angle is drawn for one axis.
inline rc::Gen<radians> axis_angle_within(const rotary_axis& a) {
  if (a.travel.continuous) return angle_in(-pi, pi);
  const double lo = to_radians(a.travel.lower).value, hi = to_radians(a.travel.upper).value;
  return rc::gen::weightedOneOf<radians>({
      {4, angle_in(lo, hi)},
      {1, rc::gen::just(radians{lo})},
      {1, rc::gen::just(radians{hi})},
      {1, rc::gen::map(log_uniform(-12.0, -4.0), [lo](double e) { return radians{lo + e}; })},
      {1, rc::gen::map(log_uniform(-12.0, -4.0), [hi](double e) { return radians{hi - e}; })},
  });
}

/// Commanded angles of M within travel: uniform, exactly at a limit, or a tiny step inside.
template <machine M>
rc::Gen<rotary_angles<M>> angles_within() {
  if constexpr (rotary_count<M> == 2) {
    return rc::gen::apply([](radians a, radians b) { return rotary_angles<M>{a, b}; },
                          axis_angle_within(M::rotary[0]), axis_angle_within(M::rotary[1]));
  } else {
    return rc::gen::map(axis_angle_within(M::rotary[0]), [](radians a) { return rotary_angles<M>{a}; });
  }
}

/// Commanded angles of M anywhere in [−2π, 2π] for every axis, ignoring travel.
template <machine M>
rc::Gen<rotary_angles<M>> angles_anywhere() {
  if constexpr (rotary_count<M> == 2) {
    return rc::gen::apply([](radians a, radians b) { return rotary_angles<M>{a, b}; }, angle_in(-2 * pi, 2 * pi),
                          angle_in(-2 * pi, 2 * pi));
  } else {
    return rc::gen::map(angle_in(-2 * pi, 2 * pi), [](radians a) { return rotary_angles<M>{a}; });
  }
}

/// A linear axis value within travel: uniform, exactly at a limit, or a tiny step inside.
inline rc::Gen<double> linear_value_within(const linear_axis& a) {
  const double lo = a.travel.lower_mm, hi = a.travel.upper_mm;
  return rc::gen::weightedOneOf<double>({
      {4, real_in(lo, hi)},
      {1, rc::gen::just(lo)},
      {1, rc::gen::just(hi)},
      {1, rc::gen::map(log_uniform(-9.0, -3.0), [lo](double e) { return lo + e; })},
      {1, rc::gen::map(log_uniform(-9.0, -3.0), [hi](double e) { return hi - e; })},
  });
}

/// Axis values of M within every travel.
template <machine M>
rc::Gen<axis_position<M>> axis_values_within() {
  return rc::gen::apply(
      [](double x, double y, double z, rotary_angles<M> a) { return axis_position<M>{{x, y, z}, a}; },
      linear_value_within(M::linear[0]), linear_value_within(M::linear[1]), linear_value_within(M::linear[2]),
      angles_within<M>());
}

/// Axis values of M anywhere: slides in [−1000, 1000] mm, rotary axes in [−2π, 2π].
template <machine M>
rc::Gen<axis_position<M>> axis_values_anywhere() {
  return rc::gen::apply(
      [](double x, double y, double z, rotary_angles<M> a) { return axis_position<M>{{x, y, z}, a}; },
      real_in(-1000, 1000), real_in(-1000, 1000), real_in(-1000, 1000), angles_anywhere<M>());
}

/// A rigid transform: a rotation about a random axis and a shift in [−500, 500] mm; one in four
/// a pure shift, one in eight the identity.
inline rc::Gen<rigid_transform> rigid_any() {
  return rc::gen::apply(
      [](int kind, vec3 axis, double angle, double x, double y, double z) {
        if (kind == 0) return rigid_transform::identity();
        return rigid_transform{kind <= 2 ? mat3::identity() : rotation(axis, radians{angle}), vec3{x, y, z}};
      },
      rc::gen::inRange(0, 8), unit_vector(), real_in(-pi, pi), real_in(-500, 500), real_in(-500, 500),
      real_in(-500, 500));
}

/// Run-time inputs: a tool length in [0, 300] mm (0 one time in five) and a work offset.
inline rc::Gen<run_inputs> run_inputs_any() {
  return rc::gen::apply([](double length, bool zero, rigid_transform w) { return run_inputs{zero ? 0.0 : length, w}; },
                        real_in(0, 300), rc::gen::weightedOneOf<bool>({{1, rc::gen::just(true)}, {4, rc::gen::just(false)}}),
                        rigid_any());
}

}  // namespace kin5::test
