/// @file bench/closed_forms.hpp
/// The specialised closed-form inverse of each catalog machine, typed directly from docs/papers.md
/// or, where no paper gives one, derived by hand from the machine's (G1) (docs/catalog.md), as the
/// baseline `inverse<M>` is measured against.
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
/// | bc-trunnion           | B = ±acos k, C = atan2(j, i) or atan2(−j, −i)             |
/// | ab-trunnion           | (K2) and (K3), the tool axes of sajo-12000p                |
/// | bc-nutating-table     | B = 2·atan2(√(1−k), √k), C = atan2(√(2k), √(1−k)) − atan2(j, i); |
/// |                       | second branch B → −B, and C with −atan2(√(2k), √(1−k))    |
/// | xyzac-trt             | (K19), the tool axes of ac-trunnion                       |
/// | xyzbc-trt             | B = ±acos k, C = atan2(j, −i) or atan2(−j, i)             |
///
/// Every catalog machine must have one: `require_closed_forms` fails the build, naming the
/// machine, when one is missing.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>

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

/// The closed form of machine M: one specialisation per catalog machine, with
/// `static closed_result<rotary_count<M>> solve(const vec3& u)`. The primary template has none.
template <class M>
struct closed_form {};

/// Whether machine M has a closed form here.
template <class M>
concept has_closed_form = requires(const vec3& u) { closed_form<M>::solve(u); };

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

/// Trunnion, rotary = {C, B} tool-relative, u = (cos C sin B, sin C sin B, cos B) (G1 of the
/// machine, docs/catalog.md): B = ±acos k, C = atan2(j, i) for +, atan2(−j, −i) for −.
/// B ∈ [−120°, 120°].
template <>
struct closed_form<machines::bc_trunnion> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    const double b = std::atan2(std::sqrt(u.x * u.x + u.y * u.y), u.z);
    const double c = std::atan2(u.y, u.x);
    const bool in = b <= 120.0 * deg;
    r.add({c, b}, in);
    r.add({wrap(c + pi), -b}, in);
    return r;
  }
};

/// A/B trunnion, rotary = {B faceplate, A tilting table} tool-relative: the tool axes of M1,
/// u = (cos A sin B, −sin A, cos A cos B), so (K2) a = −atan2(j, √(i²+k²)), b = atan2(i, k) and
/// (K3) (a, b) → (±180° − a, b + 180°). A ∈ [−110°, 110°]: the second branch only for |a| ≥ 70°.
template <>
struct closed_form<machines::ab_trunnion> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    const double a = -std::atan2(u.y, std::sqrt(u.x * u.x + u.z * u.z));
    const double b = std::atan2(u.x, u.z);
    r.add({b, a}, true);
    const double a2 = wrap(pi - a);
    r.add({wrap(b + pi), a2}, std::fabs(a2) <= 110.0 * deg);
    return r;
  }
};

/// Nutating table, rotary = {C, B} physical, u = R(Z, −C) v with
/// v = R(n, −B) ẑ = ((1 − cos B)/2, sin B/√2, (1 + cos B)/2), n = (1, 0, 1)/√2 (G1 of the
/// machine): k = (1 + cos B)/2, so B = ±acos(2k − 1) = ±2·atan2(√(1−k), √k), reachable for
/// k ≥ 0. On the + branch v has azimuth c_t = atan2(sin B/√2, 1 − k) = atan2(√(2k), √(1−k)),
/// and turning by −C carries it to u's: C = c_t − atan2(j, i); on the − branch C = −c_t −
/// atan2(j, i). The − branch (B < 0) is outside B ∈ [0°, 180°]. 1 − k = (i² + j²)/(1 + k).
template <>
struct closed_form<machines::bc_nutating_table> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    if (u.z < 0) return r;
    const double one_minus_k = (u.x * u.x + u.y * u.y) / (1.0 + u.z);
    const double b = 2.0 * std::atan2(std::sqrt(one_minus_k), std::sqrt(u.z));
    const double ct = std::atan2(std::sqrt(2.0 * u.z), std::sqrt(one_minus_k));
    const double az = std::atan2(u.y, u.x);
    r.add({wrap(ct - az), b}, true);
    r.add({wrap(-ct - az), -b}, false);
    return r;
  }
};

/// LinuxCNC's xyzac-trt, rotary = {C, A} physical: the tool axes of the A/C trunnion,
/// u = (sin A sin C, sin A cos C, cos A), so (K19) a = ±acos k, c = atan2(i, j) (+180° for −).
/// A ∈ [−100°, 50°]: the + branch for a ≤ 50°, the − branch for a ≤ 100°.
template <>
struct closed_form<machines::xyzac_trt> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    const double a = std::atan2(std::sqrt(u.x * u.x + u.y * u.y), u.z);
    const double c = std::atan2(u.x, u.y);
    r.add({c, a}, a <= 50.0 * deg);
    r.add({wrap(c + pi), -a}, a <= 100.0 * deg);
    return r;
  }
};

/// LinuxCNC's xyzbc-trt, rotary = {C, B} physical, u = (−sin B cos C, sin B sin C, cos B) (G1 of
/// the machine): B = ±acos k, C = atan2(j, −i) for +, atan2(−j, i) for −. B ∈ [−100°, 50°]: the
/// + branch for b ≤ 50°, the − branch for b ≤ 100°.
template <>
struct closed_form<machines::xyzbc_trt> {
  static closed_result<2> solve(const vec3& u) {
    closed_result<2> r;
    const double b = std::atan2(std::sqrt(u.x * u.x + u.y * u.y), u.z);
    const double c = std::atan2(u.y, -u.x);
    r.add({c, b}, b <= 50.0 * deg);
    r.add({wrap(c + pi), -b}, b <= 100.0 * deg);
    return r;
  }
};

/// Fails the build, naming M in the compiler's "required from" note, when M has no closed form.
template <class M>
consteval bool require_closed_form() {
  static_assert(has_closed_form<M>,
                "a catalog machine has no closed form in bench/closed_forms.hpp (the machine is M in the "
                "instantiation note): derive it from the machine's (G1) and add closed_form<M>");
  return has_closed_form<M>;
}

/// True when every catalog machine has a closed form; otherwise the build fails in
/// `require_closed_form`, once per machine without one.
template <class... Ms>
consteval bool require_closed_forms(std::tuple<Ms...>*) {
  return (require_closed_form<Ms>() && ...);
}

static_assert(require_closed_forms(static_cast<machines::catalog*>(nullptr)));

}  // namespace kin5::bench
