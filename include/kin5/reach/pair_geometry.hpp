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
/// reachability; the gap it gives is then an upper bound).
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

/// Whether M's fixed axis p turns freely: endless, or bounded to at least one full turn.
template <machine M>
constexpr bool fixed_axis_turns_freely() {
  const auto& t = M::rotary[0].travel;
  return t.continuous || t.upper.value - t.lower.value >= 360.0;
}

/// The latitude curve of M's carried axis (q for two rotary axes, p for one) about direction d.
template <machine M>
latitude_curve carried_curve(const vec3& d) {
  return latitude_curve::make(d, M::rotary[rotary_count<M> - 1].direction, M::tool_reference);
}

/// ψ range of M's last axis over its travel (ψ = ±commanded, by its sense).
template <machine M>
commanded_range carried_psi_range() {
  const auto& axis = M::rotary[rotary_count<M> - 1];
  const commanded_range r = range_of(axis);
  const double a = axis.psi({r.lo}).value, b = axis.psi({r.hi}).value;
  return {std::min(a, b), std::max(a, b)};
}

/// The latitudes ∠(p, u) of the tool axes M reaches within travel, per (G3) branch: on a
/// two-rotary machine [0] is branch 0 (ψq − δ ∈ [0, π]) and [1] branch 1; on a one-rotary
/// machine [0] is the single latitude ∠(p, t) and [1] is empty. Meaningful when p turns freely.
template <machine M>
std::array<angle_set, 2> branch_bands() {
  const vec3 p = M::rotary[0].direction;
  if constexpr (rotary_count<M> == 1) {
    const double theta = angle_between(p, M::tool_reference).value;
    return {angle_set::between(theta, theta), angle_set{}};
  } else {
    const commanded_range psi = carried_psi_range<M>();
    return latitudes_by_half_turn(carried_curve<M>(p), psi.lo, psi.hi);
  }
}

/// Every latitude ∠(p, u) M reaches within travel (both branches): (G5) narrowed to q's travel.
template <machine M>
angle_set reach_band() {
  auto bands = branch_bands<M>();
  for (const auto& part : bands[1].parts()) bands[0].add(part.lo, part.hi);
  return bands[0];
}

/// Whether commanded angles of M lie on its principal branch, in closed form: ψq − δ ∈ [0, π]
/// modulo 2π (branch 0 of (G3) is δ + arccos(…) ∈ [δ, δ + π]). One rotary axis: always.
template <machine M>
bool principal_pose(const rotary_angles<M>& commanded) {
  if constexpr (rotary_count<M> == 1) {
    return true;
  } else {
    const double delta = carried_curve<M>(M::rotary[0].direction).delta.value;
    const double w = math::wrap_pi(M::rotary[1].psi(commanded[1]).value - delta);
    return w >= -1e-12;
  }
}

/// How a tool axis of the source shows on the target (for the sphere maps).
enum class orientation_class : unsigned char {
  not_on_source,  ///< the source cannot hold this tool axis within its travel
  direct,         ///< target reaches it; the source holds it only on its principal branch
  other_branch,   ///< target reaches it; the source holds it only on its other branch
  either_branch,  ///< target reaches it; the source holds it on both branches
  unreachable,    ///< the source holds it, the target cannot
};

/// The closed-form view of a pair From → To under the setup rotation target_R_source.
template <machine From, machine To>
struct pair_geometry {
  /// A tool axis within this angle of the target's reach counts as reached, as in `inverse`.
  static constexpr double tolerance = 1e-9;

  mat3 target_R_source = mat3::identity();
  vec3 target_axis_in_source{};  ///< Rᵀ p_d
  bool band_target = fixed_axis_turns_freely<To>();
  bool band_source = fixed_axis_turns_freely<From>();
  angle_set target_band = reach_band<To>();
  std::array<angle_set, 2> source_bands = branch_bands<From>();

  explicit pair_geometry(const mat3& r = mat3::identity())
      : target_R_source(r), target_axis_in_source(r.transposed() * To::rotary[0].direction) {}

  /// Angle from R u_s to what the target reaches: 0 when reached. Exact on band targets; an
  /// upper bound otherwise (`inverse`).
  radians target_gap(const vec3& u_s) const {
    if (band_target) {
      const double g = target_band.gap(angle_between(target_axis_in_source, u_s).value);
      return {g <= tolerance ? 0.0 : g};
    }
    const auto r = inverse<To>(target_R_source * u_s);
    return r.reachable() ? radians{0.0} : r.gap;
  }

  /// The matchability class of a source pose, and its gap.
  matchability classify_pose(const rotary_angles<From>& commanded, radians* gap = nullptr) const {
    const radians g = target_gap(tool_axis<From>(commanded));
    if (gap) *gap = g;
    return classify(principal_pose<From>(commanded), g.value == 0.0);
  }

  /// Which source branches hold u_s within travel: bit 0 branch 0, bit 1 branch 1.
  unsigned source_branches(const vec3& u_s) const {
    unsigned bits = 0;
    if (band_source) {
      const double theta = angle_between(From::rotary[0].direction, u_s).value;
      for (unsigned b = 0; b < 2; ++b)
        if (source_bands[b].contains(theta, tolerance)) bits |= 1u << b;
      return bits;
    }
    for (const auto& s : inverse<From>(u_s))
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
};

}  // namespace kin5::reach
