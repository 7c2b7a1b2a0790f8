/// @file matchability.hpp
/// Whether a block of one machine can be run on another (docs/matchability.md, generalised to any pair):
///
/// * `direct`: the source pose lies on the source machine's principal branch (branch 0 of
///   `inverse<From>` gives it back) and the target reaches the tool axis;
/// * `other_branch`: the target reaches it, but the source pose is on the source's other
///   branch, (K3). For SAJO → DMU 80P that is A_s ∈ [As1, −90°), where Tian et al. 2010, eq. (19)
///   puts C_d 180° off (E6, P13); solving the tool axis, as kin5 does, is exact there too;
/// * `unreachable`: no target solution within travel; the gap is the angle from the tool axis
///   to the target's reach. SAJO A_s ∈ (0°, As2] has gap exactly A_s on the DMU 80P (P14).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "inverse.hpp"

namespace kin5 {

/// How a source block maps to the target machine (see the file comment).
enum class matchability { direct, other_branch, unreachable };

constexpr std::string_view name(matchability m) {
  switch (m) {
    case matchability::direct: return "direct";
    case matchability::other_branch: return "other-branch";
    case matchability::unreachable: return "unreachable";
  }
  return "?";
}

/// Whether commanded angles `source` of machine `m`, whose tool axis is `u` (= `tool_axis(m, source)`),
/// lie on its principal branch: branch 0 of the solution (G3)/(G4) for `u` gives them back,
/// modulo 360°, to `tolerance` (travel plays no part). At a pole the free angle is kept, so a
/// pole pose is principal when its carried angle is. A one-rotary machine has a single branch.
template <std::size_t N>
constexpr bool on_principal_branch(const machine_model& m, const std::array<radians, N>& source, const vec3& u,
                                   radians tolerance = {1e-7}) {
  if constexpr (N < 2) {
    return true;
  } else {
    if (m.rotary_count < 2) return true;
    pole_policy policy = pole_policy::keep(source[0]);
    policy.psi_p = m.rotary(0).psi(policy.psi_p);  // as `inverse` reads it
    const two_axis_solution raw = m.orientation.solve(u, policy, inverse_options{}.reach_tolerance);
    if (raw.count == 0) return false;
    const std::array<radians, 2> branch0{m.rotary(0).commanded(raw.branch[0].psi_p),
                                         m.rotary(1).commanded(raw.branch[0].psi_q)};
    bool same = true;
    for (std::size_t i = 0; i < 2; ++i)
      same = same && math::abs(math::wrap_pi(branch0[i].value - source[i].value)) <= tolerance.value;
    return same;
  }
}

/// `on_principal_branch` for machine type M.
template <machine M>
constexpr bool on_principal_branch(const rotary_angles<M>& source, const vec3& u, radians tolerance = {1e-7}) {
  return on_principal_branch(M::model, source, u, tolerance);
}

/// `on_principal_branch` for angles whose tool axis is not at hand.
template <machine M>
constexpr bool on_principal_branch(const rotary_angles<M>& source, radians tolerance = {1e-7}) {
  return on_principal_branch<M>(source, tool_axis<M>(source), tolerance);
}

/// The class of one block: `source_principal` from `on_principal_branch`, `target_reachable`
/// from the target's `inverse` (a solution within travel).
constexpr matchability classify(bool source_principal, bool target_reachable) {
  if (!target_reachable) return matchability::unreachable;
  return source_principal ? matchability::direct : matchability::other_branch;
}

/// The class of source angles of machine `from` (chain order) on machine `to`, tool axes mapped
/// by `target_R_source`. `gap`, when given, receives the angle to the target's reach (0 when
/// reachable).
template <std::size_t N>
constexpr matchability classify(const machine_model& from, const machine_model& to, const std::array<radians, N>& source,
                                const mat3& target_R_source, radians* gap = nullptr) {
  const vec3 u = tool_axis(from, source);
  const auto target = inverse(to, target_R_source * u);
  if (gap) *gap = target.reachable() ? radians{0.0} : target.gap;
  return classify(on_principal_branch(from, source, u), target.reachable());
}

/// `classify` of machine types From → To.
template <machine From, machine To>
constexpr matchability classify(const rotary_angles<From>& source, const mat3& target_R_source,
                                radians* gap = nullptr) {
  return classify(From::model, To::model, source, target_R_source, gap);
}

}  // namespace kin5
