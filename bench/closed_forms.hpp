/// @file bench/closed_forms.hpp
/// The specialised closed-form inverse of each catalog machine, typed directly from docs/papers.md,
/// as the baseline `inverse<M>` is measured against.
///
/// Each `closed_form<M>::solve(u)` returns the same set `inverse<M>` returns for a unit tool
/// axis u away from the poles: both branches of (G3), commanded angles in `M::rotary` order,
/// continuous axes in (−π, π], bounded axes at every 360° shift within travel, and a
/// within-travel flag. Pole policies and the unreachable gap are left out: the benchmark's
/// inputs are reachable and away from the poles.
///
/// | machine               | formulas                                                  |
/// |-----------------------|-----------------------------------------------------------|
/// | sajo-12000p (M1)      | (K2) and its second branch (K3)                           |
/// | dmu-80p (M2)          | (K7)–(K9); second branch b → −b, c_t → −c_t               |
/// | ac-trunnion           | (K19)                                                     |
/// | dmu-50v               | (K23)–(K24); second branch B → −B                          |
/// | a-rotary-4axis        | (K25) with this machine's sign, A = atan2(−u_y, u_z)      |
/// | ac-head               | A = ±acos k, C = atan2(i, −j) or atan2(−i, j), C ± 360°   |
/// | b-head-a-tilted-table | derived in docs/performance.md: B = 45° + asin κ or       |
/// |                       | 225° − asin κ with κ = (i − k)/√2; A = ±90° − atan2((i+k)/√2, j) |
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include <kin5/kin5.hpp>

namespace kin5::bench {

/// Up to 8 solutions, commanded radians in `M::rotary` order.
template <std::size_t N>
struct closed_result {
  std::array<std::array<double, N>, 8> angles{};
  std::array<bool, 8> within{};
  std::size_t count = 0;

  void add(std::array<double, N> a, bool in) {
    angles[count] = a;
    within[count] = in;
    ++count;
  }
};

inline constexpr double deg = pi / 180.0;

/// x reduced into (−π, π].
inline double wrap(double x) {
  x = std::remainder(x, 2.0 * pi);
  return x <= -pi ? x + 2.0 * pi : x;
}

template <class M>
struct closed_form;

/// M1, rotary = {B table, A head}: (K2) a = −atan2(j, √(i²+k²)), b = atan2(i, k);
/// (K3) (a, b) → (−180° − a, b + 180°). A ∈ [−120°, 30°].
template <>
struct closed_form<machines::sajo_12000p> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    const double a = -std::atan2(u.y, std::sqrt(u.x * u.x + u.z * u.z));
    const double b = std::atan2(u.x, u.z);
    r.add({b, a}, a >= -120.0 * deg && a <= 30.0 * deg);
    const double a2 = -pi - a;
    r.add({wrap(b + pi), a2}, a2 >= -120.0 * deg);
    return r;
  }
};

/// M2, rotary = {C table, B head}: (K7) b = 2·atan2(√(1−k), √k), (K8) c_t = atan2(√(2k), √(1−k)),
/// (K9) c = c_t + wrap180(atan2(j, i) − 90°). The − branch (b < 0) is outside B ∈ [0°, 180°].
template <>
struct closed_form<machines::dmu_80p> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    if (u.z < 0) return r;
    const double one_minus_k = (u.x * u.x + u.y * u.y) / (1.0 + u.z);
    const double b = 2.0 * std::atan2(std::sqrt(one_minus_k), std::sqrt(u.z));
    const double ct = std::atan2(std::sqrt(2.0 * u.z), std::sqrt(one_minus_k));
    const double az = wrap(std::atan2(u.y, u.x) - 0.5 * pi);
    r.add({wrap(ct + az), b}, true);
    r.add({wrap(-ct + az), -b}, false);
    return r;
  }
};

/// A/C trunnion, rotary = {C, A} physical: (K19) a = ±acos k, c = atan2(i, j) (+180° for −).
/// A ∈ [−120°, 120°].
template <>
struct closed_form<machines::ac_trunnion> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    const double a = std::atan2(std::sqrt(u.x * u.x + u.y * u.y), u.z);
    const double c = std::atan2(u.x, u.y);
    const bool in = a <= 120.0 * deg;
    r.add({c, a}, in);
    r.add({wrap(c + pi), -a}, in);
    return r;
  }
};

/// DMU 50V, rotary = {C tool-relative, B physical}: (K23) B = 2·atan2(√(1−k), √k);
/// (K24) C = asin((1−k)/a_xy) + atan2(j, i), with (1−k)/a_xy = a_xy/(1+k).
/// The − branch (B < 0) is outside B ∈ [0°, 180°]; its C is atan2(j, i) − 180° − asin(…).
template <>
struct closed_form<machines::dmu_50v> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    if (u.z < 0) return r;
    const double axy = std::sqrt(u.x * u.x + u.y * u.y);
    const double b = 2.0 * std::atan2(std::sqrt(axy * axy / (1.0 + u.z)), std::sqrt(u.z));
    const double s = std::asin(std::fmin(axy / (1.0 + u.z), 1.0));
    const double az = std::atan2(u.y, u.x);
    r.add({wrap(az + s), b}, true);
    r.add({wrap(az - pi - s), -b}, false);
    return r;
  }
};

/// Four-axis A table about +X, u = (0, −sin A, cos A): A = atan2(−u_y, u_z) (K25 with the
/// opposite sign of CN1624613's A); reachable only when u_x = 0.
template <>
struct closed_form<machines::a_rotary_4axis> {
  static closed_result<1> solve(const vec3& u) {
    closed_result<1> r;
    if (std::fabs(u.x) > 1e-9) return r;
    r.add({std::atan2(-u.y, u.z)}, true);
    return r;
  }
};

/// Head-head, rotary = {C, A}, u = (sin A sin C, −sin A cos C, cos A):
/// A = ±acos k, C = atan2(i, −j) for +, atan2(−i, j) for −; C ∈ [−360°, 360°] gives each C
/// again 360° away; A ∈ [−110°, 110°].
template <>
struct closed_form<machines::ac_head> {
  static void add_shifts(closed_result<2>& r, double c, double a, bool in) {
    r.add({c, a}, in);
    if (!in) return;
    if (c >= 0) r.add({c - 2.0 * pi, a}, true);
    if (c <= 0) r.add({c + 2.0 * pi, a}, true);
  }
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    const double a = std::atan2(std::sqrt(u.x * u.x + u.y * u.y), u.z);
    const bool in = a <= 110.0 * deg;
    add_shifts(r, std::atan2(u.x, -u.y), a, in);
    add_shifts(r, std::atan2(-u.x, u.y), -a, in);
    return r;
  }
};

/// Head-table with a tilted table axis a_T = (1, 0, −1)/√2, rotary = {A physical, B head}:
/// a_T·u = sin(B − 45°) = κ, so B = 45° + asin κ or 225° − asin κ. About a_T, with the frame
/// e₁ = Y, e₂ = a_T × Y = (1, 0, 1)/√2, R(Y, B)ẑ sits at azimuth ±90° and u at
/// atan2((i + k)/√2, j); A = −ψ = ±90° − atan2((i + k)/√2, j). B ∈ [−120°, 120°].
template <>
struct closed_form<machines::b_head_a_tilted_table> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    constexpr double inv_sqrt2 = 0.70710678118654752;
    const double lat = std::asin(std::fmax(-1.0, std::fmin(1.0, (u.x - u.z) * inv_sqrt2)));
    const double phi_u = std::atan2((u.x + u.z) * inv_sqrt2, u.y);
    const double b1 = 0.25 * pi + lat;
    const double b2 = wrap(1.25 * pi - lat);
    r.add({wrap(0.5 * pi - phi_u), b1}, b1 <= 120.0 * deg);
    r.add({wrap(-0.5 * pi - phi_u), b2}, b2 >= -120.0 * deg && b2 <= 120.0 * deg);
    return r;
  }
};

}  // namespace kin5::bench
