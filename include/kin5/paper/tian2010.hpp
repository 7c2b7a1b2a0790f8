/// @file paper/tian2010.hpp
/// Tian, Ren, Shi, Li 2010 (Tian et al. 2010): the formulas of the SAJO 12000P (M1: table B_s about +Y,
/// head A_s about +X) ↔ DMU 80P (M2: table C_d about +Z, head B_d about (0,1,1)/√2) translation,
/// as printed and, where docs/errata.md lists an erratum, corrected.
///
/// Degrees in and out, as the paper writes them; tool axes are unit vectors (i, j, k) in the
/// workpiece frame of the machine named. Names carry the paper's equation, `[000:n]` (eq. (n)), and the
/// project's tag, `(Kn)` (docs/equations.md). `_printed` is the formula exactly as printed, errors included; `_corrected`
/// is the fixed form. Example (docs/golden.md):
/// @code
///   auto d = kin5::paper::tian2010::eq19_m1_to_m2_printed(-45.0, 30.0);  // (B_d, C_d) = (65.530199, 95.530199)
///   auto s = kin5::paper::tian2010::eq18_m2_to_m1(d->b_deg, d->c_deg);   // (A_s, B_s) = (−45, 30)
/// @endcode
/// These are cross-checks for kin5's general solver ((G1)–(G5)), not the translator itself.
#pragma once

#include <optional>

#include "../core/vec.hpp"
#include "case_table.hpp"
#include "degree_trig.hpp"

namespace kin5::paper::tian2010 {

/// M1 (SAJO 12000P) rotary angles, ISO tool-relative, degrees.
struct sajo_angles_deg {
  double a_deg{};  ///< A_s, head about +X_s
  double b_deg{};  ///< B_s, table about +Y_s
};

/// M2 (DMU 80P) rotary angles, ISO tool-relative, degrees.
struct dmu_angles_deg {
  double b_deg{};  ///< B_d, head about (0,1,1)/√2
  double c_deg{};  ///< C_d, table about +Z_d
};

// ---------------------------------------------------------------------------------------------
// Tool-tip tracking displacement of M1, [000:1]-[000:5]. Row vectors, as printed: `v·M`.

/// A row vector times a matrix printed for row vectors: v·M = Mᵀ v.
constexpr vec3 row_times(const vec3& v, const mat3& m) { return m.transposed() * v; }

/// [000:1] as printed: M_b, the table turn ΔB_s about Y_s (row-vector form). It turns a point
/// of the part right-handed by +ΔB_s, while [000:8] needs the table to turn by −b (E4).
constexpr mat3 eq1_mb_printed(double db_deg) {
  const double c = cos_deg(db_deg), s = sin_deg(db_deg);
  return {{vec3{c, 0.0, -s}, vec3{0.0, 1.0, 0.0}, vec3{s, 0.0, c}}};
}

/// [000:1] corrected (E4): the table turns by −ΔB_s, as [000:8] needs; the printed matrix
/// transposed.
constexpr mat3 eq1_mb_corrected(double db_deg) { return eq1_mb_printed(db_deg).transposed(); }

/// [000:3]: M_a, the head swing ΔA_s about X_s (row-vector form): R(X, +ΔA_s), as [000:8] needs.
constexpr mat3 eq3_ma(double da_deg) {
  const double c = cos_deg(da_deg), s = sin_deg(da_deg);
  return {{vec3{1.0, 0.0, 0.0}, vec3{0.0, c, s}, vec3{0.0, -s, c}}};
}

/// [000:2]: v_b = (v + v₀)(M_b − E), the displacement of the part point by the table; v the tip
/// in the workpiece frame, v₀ the workpiece origin in the machine frame (table centre at the
/// machine origin), mm.
constexpr vec3 eq2_vb(const vec3& v_mm, const vec3& v0_mm, const mat3& mb) {
  const vec3 r = v_mm + v0_mm;
  return row_times(r, mb) - r;
}

/// [000:4]: v_a = [0 0 −l](M_a − E), the displacement of the tip by the head, l the distance from
/// the tip to the swing centre, mm. The paper prints the row vector with a fourth entry 1 (E3).
constexpr vec3 eq4_va(double l_mm, const mat3& ma) {
  const vec3 tip{0.0, 0.0, -l_mm};
  return row_times(tip, ma) - tip;
}

/// [000:5] as printed: v′ = v + v_b − v_a with M_b of [000:1] as printed (table turning +ΔB_s,
/// E4), the head swing of [000:3], angles in degrees: the point a program without tool-tip
/// tracking writes, (G8).
constexpr vec3 eq5_v_prime_printed(const vec3& v_mm, const vec3& v0_mm, double l_mm, double a_deg, double b_deg) {
  return v_mm + eq2_vb(v_mm, v0_mm, eq1_mb_printed(b_deg)) - eq4_va(l_mm, eq3_ma(a_deg));
}

/// [000:5] corrected (E3, E4): the same with the table turning by −b, consistent with [000:8]
/// and the tool-relative angles of the SAJO's programs.
constexpr vec3 eq5_v_prime_corrected(const vec3& v_mm, const vec3& v0_mm, double l_mm, double a_deg, double b_deg) {
  return v_mm + eq2_vb(v_mm, v0_mm, eq1_mb_corrected(b_deg)) - eq4_va(l_mm, eq3_ma(a_deg));
}

// ---------------------------------------------------------------------------------------------
// M1: perpendicular head + table, (K1)–(K4) (docs/papers.md)

/// (K1) = [000:8]: u_s = (cos(−a) sin b, sin(−a), cos(−a) cos b), written as printed.
constexpr vec3 eq8_tool_axis(double a_deg, double b_deg) {
  return {cos_deg(-a_deg) * sin_deg(b_deg), sin_deg(-a_deg), cos_deg(-a_deg) * cos_deg(b_deg)};
}

/// [000:6] as printed: a = −arctan(j/√(i²+k²)), and "a = −90° when i²+k² = 0" (E2: wrong for
/// u = −Y_s, where a = +90°).
constexpr double eq6_a_printed_deg(const vec3& u) {
  const double ik2 = u.x * u.x + u.z * u.z;
  if (ik2 == 0.0) return -90.0;
  return -atan_deg(u.y / math::sqrt(ik2));
}

/// (K2) a = −atan2(j, √(i²+k²)) ∈ [−90°, 90°]: [000:6] with its pole rule corrected (E2).
constexpr double k2_a_deg(const vec3& u) { return -atan2_deg(u.y, math::sqrt(u.x * u.x + u.z * u.z)); }

namespace detail {
// [000:7]: "when k_s = 0, take arctan|i_s/k_s| = 90°".
constexpr double eq7_atan_abs_deg(double i, double k) {
  return k == 0.0 ? 90.0 : atan_deg(math::abs(i / k));
}
}  // namespace detail

/// [000:7] as printed: the four quadrant cases of b_s, with case 4 reading "i < 0, k ≤ 0" (E1).
/// Gap for i<0, k>0 (b ∈ (270°, 360°)); overlap of cases 3 and 4 for i<0, k<0 (b ∈ (180°, 270°)).
constexpr case_table_result eq7_b_printed(double i, double k) {
  const double t = detail::eq7_atan_abs_deg(i, k);
  case_table_result r{};
  if (i >= 0 && k > 0) r.add(1, t);
  if (i > 0 && k <= 0) r.add(2, 180.0 - t);
  if (i <= 0 && k < 0) r.add(3, 180.0 + t);
  if (i < 0 && k <= 0) r.add(4, 360.0 - t);
  return r;
}

/// [000:7] corrected (E1): case 4 reads "i < 0, k ≥ 0". Exactly one case holds except at the
/// pole i = k = 0, where none does.
constexpr case_table_result eq7_b_corrected(double i, double k) {
  const double t = detail::eq7_atan_abs_deg(i, k);
  case_table_result r{};
  if (i >= 0 && k > 0) r.add(1, t);
  if (i > 0 && k <= 0) r.add(2, 180.0 - t);
  if (i <= 0 && k < 0) r.add(3, 180.0 + t);
  if (i < 0 && k >= 0) r.add(4, 360.0 - t);
  return r;
}

/// (K2) b = atan2(i, k) mod 360° ∈ [0°, 360°): the closed form of corrected [000:7].
constexpr double k2_b_deg(const vec3& u) { return wrap360_deg(atan2_deg(u.x, u.z)); }

/// (K2) inverse of M1 on the branch a ∈ [−90°, 90°]. At the poles u = ±Y_s, b is arbitrary
/// (whatever atan2 gives for the two zero components).
constexpr sajo_angles_deg k2_inverse(const vec3& u) { return {k2_a_deg(u), k2_b_deg(u)}; }

/// (K3) the second solution branch, (a, b) → (−180° − a, b + 180°): same tool axis.
constexpr sajo_angles_deg k3_second_branch(sajo_angles_deg s) { return {-180.0 - s.a_deg, s.b_deg + 180.0}; }

/// (K4) the antipodal map, (a, b) → (−a, b + 180°): the reversed tool axis −u (E5).
constexpr sajo_angles_deg k4_antipode(sajo_angles_deg s) { return {-s.a_deg, s.b_deg + 180.0}; }

// ---------------------------------------------------------------------------------------------
// M2: 45° tilted head + table, (K5)–(K9) (docs/papers.md)

/// (K5) = [000:14]: u_d = (√2/2 sin b cos c − (1−cos b)/2 sin c,
///                          √2/2 sin b sin c + (1−cos b)/2 cos c,  (1+cos b)/2).
constexpr vec3 eq14_tool_axis(double b_deg, double c_deg) {
  constexpr double half_sqrt2 = 0.70710678118654752;
  const double sb = sin_deg(b_deg), cb = cos_deg(b_deg), sc = sin_deg(c_deg), cc = cos_deg(c_deg);
  return {half_sqrt2 * sb * cc - (1.0 - cb) / 2.0 * sc, half_sqrt2 * sb * sc + (1.0 - cb) / 2.0 * cc,
          (1.0 + cb) / 2.0};
}

/// (K7) = [000:10]: b_d = arccos(2k − 1) ∈ [0°, 180°]. NaN for k outside [0, 1].
constexpr double eq10_b_deg(double k) { return acos_deg(2.0 * k - 1.0); }

/// (K7), precise near the pole: b_d = 2·atan2(√(1−k), √k) with 1−k = (i²+j²)/(1+k).
/// NaN for k < 0 (below M2's reach, P7).
constexpr double k7_b_deg(const vec3& u) {
  const double one_minus_k = (u.x * u.x + u.y * u.y) / (1.0 + u.z);
  return 2.0 * atan2_deg(math::sqrt(one_minus_k), math::sqrt(u.z));
}

/// (K8) = [000:12]: c_t = arctan √(2k/(1−k)) ∈ [0°, 90°], and "c_t = 90° when k = 1".
constexpr double eq12_ct_deg(double k) {
  if (k == 1.0) return 90.0;
  return atan_deg(math::sqrt(2.0 * k / (1.0 - k)));
}

/// (K8), precise near the pole: c_t = atan2(√(2k), √(1−k)), 1−k = (i²+j²)/(1+k).
constexpr double k8_ct_deg(const vec3& u) {
  const double one_minus_k = (u.x * u.x + u.y * u.y) / (1.0 + u.z);
  return atan2_deg(math::sqrt(2.0 * u.z), math::sqrt(one_minus_k));
}

/// The bracket of [000:13] (K9), as printed: four cases in (i, j), "arctan|i/j| = 90° when j = 0".
/// No erratum: exactly one case holds except at i = j = 0. Range [−180°, 180°).
constexpr case_table_result eq13_bracket(double i, double j) {
  const double t = j == 0.0 ? 90.0 : atan_deg(math::abs(i / j));
  case_table_result r{};
  if (i <= 0 && j > 0) r.add(1, t);
  if (i > 0 && j >= 0) r.add(2, -t);
  if (i >= 0 && j < 0) r.add(3, -180.0 + t);
  if (i < 0 && j <= 0) r.add(4, 180.0 - t);
  return r;
}

/// [000:13] as printed: c_d = c_t + bracket, c_t from [000:12]. Empty at the pole i = j = 0.
constexpr std::optional<double> eq13_c_deg(const vec3& u) {
  const auto bracket = eq13_bracket(u.x, u.y).value();
  if (!bracket) return std::nullopt;
  return eq12_ct_deg(u.z) + *bracket;
}

/// (K9): c_d = c_t + wrap180(atan2(j, i) − 90°) ∈ (c_t − 180°, c_t + 180°], c_t from (K8).
constexpr double k9_c_deg(const vec3& u) { return k8_ct_deg(u) + wrap180_deg(atan2_deg(u.y, u.x) - 90.0); }

/// (K7)-(K9) inverse of M2. Empty when k < 0 (unreachable, P7). At the pole u = +Z_d,
/// b = 0 and c is arbitrary.
constexpr std::optional<dmu_angles_deg> k7_k9_inverse(const vec3& u) {
  if (u.z < 0.0) return std::nullopt;
  return dmu_angles_deg{k7_b_deg(u), k9_c_deg(u)};
}

// ---------------------------------------------------------------------------------------------
// The correspondence M1 ↔ M2, (K10)–(K11) (docs/papers.md)

/// (K10) = [000:15-17]: T = T_ds = T_sd, maps M1 workpiece coordinates to M2's and back
/// (T = Tᵀ = T⁻¹, det T = +1: the 180° turn about (0,1,1)/√2).
inline constexpr mat3 dmu_T_sajo{{vec3{-1, 0, 0}, vec3{0, 0, 1}, vec3{0, 1, 0}}};
/// (K10): the same matrix read the other way.
inline constexpr mat3 sajo_T_dmu = dmu_T_sajo;

/// (K11): (x_d, y_d, z_d) = (−x_s, z_s, y_s); tool axes map by the same matrix.
constexpr vec3 k11_map(const vec3& v_sajo) { return dmu_T_sajo * v_sajo; }

// ---------------------------------------------------------------------------------------------
// Translation formulas, (K12)–(K14) (docs/papers.md)

/// (K13) = [000:18], M2 → M1: A_s = −arcsin((1 + cos B_d)/2),
/// B_s = C_d − arctan(√2 sin B_d / (1 − cos B_d)), and "B_s = C_d − 90° when B_d = 0".
/// Valid on all of M2's range; the output is not normalised (E7).
constexpr sajo_angles_deg eq18_m2_to_m1(double b_d_deg, double c_d_deg) {
  const double a_s = -asin_deg((1.0 + cos_deg(b_d_deg)) / 2.0);
  if (b_d_deg == 0.0) return {a_s, c_d_deg - 90.0};
  constexpr double sqrt2 = 1.4142135623730951;
  return {a_s, c_d_deg - atan_deg(sqrt2 * sin_deg(b_d_deg) / (1.0 - cos_deg(b_d_deg)))};
}

/// (K12) = [000:19] as printed, M1 → M2: B_d = arccos(−1 − 2 sin A_s),
/// C_d = B_s + arctan √(−2 sin A_s / (1 + sin A_s)), and "C_d = B_s + 90° when A_s = −90°".
/// Right for A_s ∈ [−90°, 0°]; C_d is 180° off for A_s ∈ (−180°, −90°) (E6). Empty where the
/// arccos argument leaves [−1, 1] (A_s ∈ (0°, 180°)): the printed formula has no value there.
constexpr std::optional<dmu_angles_deg> eq19_m1_to_m2_printed(double a_s_deg, double b_s_deg) {
  const double s = sin_deg(a_s_deg);
  const double arg = -1.0 - 2.0 * s;
  if (!(arg >= -1.0 && arg <= 1.0)) return std::nullopt;
  const double b_d = acos_deg(arg);
  if (a_s_deg == -90.0) return dmu_angles_deg{b_d, b_s_deg + 90.0};
  return dmu_angles_deg{b_d, b_s_deg + atan_deg(math::sqrt(-2.0 * s / (1.0 + s)))};
}

/// Which rule of docs/matchability.md translates an M1 pose: it depends on A_s alone.
enum class region {
  direct,  ///< A_s ∈ [−90°, 0°]: (K12) as printed
  flip_c,  ///< A_s ∈ [−180°, −90°): B_d from (K12), C_d = (K12) + 180° (E6)
  none,    ///< A_s ∈ (0°, 180°): k_d = −sin A_s < 0, unreachable for every B_s (E5)
};

/// The region (docs/matchability.md) for A_s, taken modulo 360° into (−180°, 180°].
constexpr region region_of(double a_s_deg) {
  const double a = wrap180_deg(a_s_deg);
  if (a >= -90.0 && a <= 0.0) return region::direct;
  if (a > 0.0 && a < 180.0) return region::none;
  return region::flip_c;
}

/// The result of the corrected M1 → M2 translation.
struct m1_to_m2 {
  region rule = region::none;
  /// The M2 angles (not normalised, E7). For `none`: the nearest reachable pose, B_d = 180° and
  /// C_d = B_s (A_s ≤ 90°) or B_s + 180° (A_s > 90°).
  dmu_angles_deg angles{};
  /// Angle from T·u_s to M2's reach, degrees: 0, or arcsin(sin A_s) for `none`, which is A_s on
  /// (0°, 90°] (docs/matchability.md) and 180° − A_s beyond.
  double gap_deg = 0.0;
};

/// (K12) corrected (E5, E6, docs/matchability.md): the region rule, with B_d and c_t in forms that keep
/// full precision near the pole A_s = −90° (1 + sin A_s = 2 sin²((A_s + 90°)/2)).
/// At A_s = −90° it gives C_d = B_s + 90°, the printed convention and the continuous limit.
constexpr m1_to_m2 k12_corrected(double a_s_deg, double b_s_deg) {
  const region rule = region_of(a_s_deg);
  if (rule == region::none) {
    const double a = wrap180_deg(a_s_deg);
    return a <= 90.0 ? m1_to_m2{rule, {180.0, b_s_deg}, a} : m1_to_m2{rule, {180.0, b_s_deg + 180.0}, 180.0 - a};
  }
  const double minus_sin_a = -sin_deg(a_s_deg);  // = k_d ≥ 0
  const double sqrt_minus_sin = math::sqrt(minus_sin_a > 0.0 ? minus_sin_a : 0.0);
  const double sqrt_one_plus_sin = math::sqrt(2.0) * math::abs(sin_deg(0.5 * (a_s_deg + 90.0)));
  // cos B_d = −1 − 2 sin a, so tan(B_d/2) = √(1 + sin a) / √(−sin a).
  const double b_d = 2.0 * atan2_deg(sqrt_one_plus_sin, sqrt_minus_sin);
  const double c_t = atan2_deg(math::sqrt(2.0) * sqrt_minus_sin, sqrt_one_plus_sin);
  const double flip = rule == region::flip_c ? 180.0 : 0.0;
  return {rule, {b_d, b_s_deg + c_t + flip}, 0.0};
}

// ---------------------------------------------------------------------------------------------
// Feed, (K15)–(K17) (docs/papers.md)

/// One NC block of a five-axis program: linear axes in mm, the 4th and 5th rotary axes in
/// degrees (M1: B_s, A_s; M2: C_d, B_d).
struct block5 {
  double x_mm{}, y_mm{}, z_mm{};
  double fourth_deg{}, fifth_deg{};
};

/// (K16) = [000:21-22]: the "integrated" block distance, √(Δx² + Δy² + Δz² + Δ4th² + Δ5th²),
/// millimetres and degrees added as if they were one unit.
constexpr double eq21_block_distance(const block5& previous, const block5& current) {
  const double dx = current.x_mm - previous.x_mm, dy = current.y_mm - previous.y_mm,
               dz = current.z_mm - previous.z_mm, d4 = current.fourth_deg - previous.fourth_deg,
               d5 = current.fifth_deg - previous.fifth_deg;
  return math::sqrt(dx * dx + dy * dy + dz * dz + d4 * d4 + d5 * d5);
}

/// (K15) = [000:20]: time per block, t = l / f (minutes for f in mm/min).
constexpr double eq20_block_time_min(double block_distance, double feed_mm_per_min) {
  return block_distance / feed_mm_per_min;
}

/// (K17) = [000:23]: f_d = f_s · l_d / l_s, keeping the block time of (K15).
constexpr double eq23_feed_mm_per_min(double f_s_mm_per_min, double l_s, double l_d) {
  return f_s_mm_per_min * l_d / l_s;
}

/// (K17) = [000:23] from the two blocks on each machine.
constexpr double eq23_feed_mm_per_min(double f_s_mm_per_min, const block5& sajo_previous, const block5& sajo_current,
                                      const block5& dmu_previous, const block5& dmu_current) {
  return eq23_feed_mm_per_min(f_s_mm_per_min, eq21_block_distance(sajo_previous, sajo_current),
                              eq21_block_distance(dmu_previous, dmu_current));
}

}  // namespace kin5::paper::tian2010
