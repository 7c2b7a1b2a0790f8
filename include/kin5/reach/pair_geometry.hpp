/// @file reach/pair_geometry.hpp
/// Matchability of a machine pair in closed form: which source poses and which tool axes a
/// target machine reaches, and on which branch the source holds them.
///
/// When a machine's fixed axis p turns freely (endless, or at least 360° of travel), what it
/// reaches depends on the latitude ∠(p, u) alone (G5): a set of latitudes (`reach_band`), one
/// share per (G3) branch (`branch_bands`). A pair is then decided by two latitudes:
///
///     target reaches u_s   ⇔  ∠(p_d, R u_s) = ∠(Rᵀ p_d, u_s) lies in the target's band;
///     source pose principal ⇔  ψq − δ ∈ [0, π] (mod 2π): branch 0 of (G3) is δ + arccos(…).
///
/// with R = target_R_source (the setup). For Tian et al. 2010's pair (SAJO 12000P → DMU 80P,
/// R = (K10) = eqs (15)-(17)), Rᵀ ẑ_d = Y_s, so the test is −sin A_s ≥ 0: the paper's A = 0°.
/// Machines whose p is bounded to less than a turn are decided by `inverse` instead (exact
/// reachability; the gap it gives is then an upper bound). Machines are `machine_model` values,
/// so one compiled analysis serves every pair, catalog machines and machine files alike.
#pragma once

#include <array>

#include "../kinematics/inverse.hpp"
#include "../kinematics/matchability.hpp"
#include "latitude.hpp"

namespace kin5::reach {

/// A commanded-angle range of a rotary axis, radians: its travel, or [−π, π] when endless.
struct commanded_range {
  double lo = -pi;
  double hi = pi;
};

constexpr commanded_range range_of(const rotary_axis& a) {
  if (a.travel.continuous) return {};
  return {to_radians(a.travel.lower).value, to_radians(a.travel.upper).value};
}

/// Whether the fixed axis p of machine `m` turns freely: endless, or bounded to at least one turn.
constexpr bool fixed_axis_turns_freely(const machine_model& m) {
  const auto& t = m.rotary(0).travel;
  return t.continuous || t.upper.value - t.lower.value >= 360.0;
}

/// The latitude curve of the carried axis of `m` (q for two rotary axes, p for one) about direction d.
inline latitude_curve carried_curve(const machine_model& m, const vec3& d) {
  return latitude_curve::make(d, m.rotary(m.rotary_count - 1).direction, m.tool_reference());
}

/// ψ range of the last axis of `m` over its travel (ψ = ±commanded, by its sense).
inline commanded_range carried_psi_range(const machine_model& m) {
  const auto& axis = m.rotary(m.rotary_count - 1);
  const commanded_range r = range_of(axis);
  const double a = axis.psi({r.lo}).value, b = axis.psi({r.hi}).value;
  return {std::min(a, b), std::max(a, b)};
}

/// The latitudes ∠(p, u) of the tool axes `m` reaches within travel, per (G3) branch: on a
/// two-rotary machine [0] is branch 0 (ψq − δ ∈ [0, π]) and [1] branch 1; on a one-rotary
/// machine [0] is the single latitude ∠(p, t) and [1] is empty. Meaningful when p turns freely.
inline std::array<angle_set, 2> branch_bands(const machine_model& m) {
  const vec3 p = m.rotary(0).direction;
  if (m.rotary_count == 1) {
    const double theta = angle_between(p, m.tool_reference()).value;
    return {angle_set::between(theta, theta), angle_set{}};
  }
  const commanded_range psi = carried_psi_range(m);
  return latitudes_by_half_turn(carried_curve(m, p), psi.lo, psi.hi);
}

/// Every latitude ∠(p, u) `m` reaches within travel (both branches): (G5) narrowed to q's travel.
inline angle_set reach_band(const machine_model& m) {
  auto bands = branch_bands(m);
  for (const auto& part : bands[1].parts()) bands[0].add(part.lo, part.hi);
  return bands[0];
}

/// Whether commanded angles of `m` lie on its principal branch, in closed form: ψq − δ ∈ [0, π]
/// modulo 2π (branch 0 of (G3) is δ + arccos(…) ∈ [δ, δ + π]). One rotary axis: always.
inline bool principal_pose(const machine_model& m, const rotary_values& commanded) {
  if (m.rotary_count == 1) return true;
  const double delta = carried_curve(m, m.rotary(0).direction).delta.value;
  const double w = math::wrap_pi(m.rotary(1).psi(commanded[1]).value - delta);
  return w >= -1e-12;
}

/// How a tool axis of the source shows on the target (for the sphere maps).
enum class orientation_class : unsigned char {
  not_on_source,  ///< the source cannot hold this tool axis within its travel
  direct,         ///< target reaches it; the source holds it only on its principal branch
  other_branch,   ///< target reaches it; the source holds it only on its other branch
  either_branch,  ///< target reaches it; the source holds it on both branches
  unreachable,    ///< the source holds it, the target cannot
};

/// The closed-form view of a pair `from` → `to` under the setup rotation target_R_source. Holds
/// the two models by address: they must outlive it (a catalog model always does).
class pair_geometry {
 public:
  /// A tool axis within this angle of the target's reach counts as reached, as in `inverse`.
  static constexpr double tolerance = 1e-9;

  pair_geometry(const machine_model& from, const machine_model& to, const mat3& r = mat3::identity())
      : target_R_source(r),
        target_axis_in_source(r.transposed() * to.rotary(0).direction),
        band_target(fixed_axis_turns_freely(to)),
        band_source(fixed_axis_turns_freely(from)),
        target_band(reach_band(to)),
        source_bands(branch_bands(from)),
        from_(&from),
        to_(&to) {}

  const machine_model& from() const { return *from_; }
  const machine_model& to() const { return *to_; }

  mat3 target_R_source;
  vec3 target_axis_in_source;  ///< Rᵀ p_d
  bool band_target;
  bool band_source;
  angle_set target_band;
  std::array<angle_set, 2> source_bands;

  /// Angle from R u_s to what the target reaches: 0 when reached. Exact on band targets; an
  /// upper bound otherwise (`inverse`).
  radians target_gap(const vec3& u_s) const {
    if (band_target) {
      const double g = target_band.gap(angle_between(target_axis_in_source, u_s).value);
      return {g <= tolerance ? 0.0 : g};
    }
    const auto r = inverse(*to_, target_R_source * u_s);
    return r.reachable() ? radians{0.0} : r.gap;
  }

  /// The matchability class of a source pose (commanded angles, chain order), and its gap.
  matchability classify_pose(const rotary_values& commanded, radians* gap = nullptr) const {
    const radians g = target_gap(tool_axis(*from_, commanded));
    if (gap) *gap = g;
    return classify(principal_pose(*from_, commanded), g.value == 0.0);
  }

  /// Which source branches hold u_s within travel: bit 0 branch 0, bit 1 branch 1.
  unsigned source_branches(const vec3& u_s) const {
    unsigned bits = 0;
    if (band_source) {
      const double theta = angle_between(from_->rotary(0).direction, u_s).value;
      for (unsigned b = 0; b < 2; ++b)
        if (source_bands[b].contains(theta, tolerance)) bits |= 1u << b;
      return bits;
    }
    for (const auto& s : inverse(*from_, u_s))
      if (s.within_travel) bits |= 1u << s.branch;
    return bits;
  }

  /// The class of a source tool axis, and its gap when the target cannot reach it.
  orientation_class classify_orientation(const vec3& u_s, radians* gap = nullptr) const {
    const unsigned bits = source_branches(u_s);
    if (gap) *gap = {0.0};
    if (bits == 0) return orientation_class::not_on_source;
    const radians g = target_gap(u_s);
    if (g.value > 0.0) {
      if (gap) *gap = g;
      return orientation_class::unreachable;
    }
    return bits == 1 ? orientation_class::direct
                     : (bits == 2 ? orientation_class::other_branch : orientation_class::either_branch);
  }

 private:
  const machine_model* from_;
  const machine_model* to_;
};

}  // namespace kin5::reach
