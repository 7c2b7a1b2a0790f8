/// @file solver.hpp
/// The general closed-form inverse for a tool axis turned by two rotary axes (docs/theory.md):
///
///     u = R(p, ψp) · R(q, ψq) · t                                             (G1)
///
/// `two_axis_geometry` holds p, q, t and the derived constants of (G2); `solve` returns
/// both branches (G3) with their ψp (G4), the reach test (G5) and the pole policy (S2).
/// Everything is in radians and unit vectors, and works in constant expressions.
///
/// Precision: near the reach boundary (S3) and the pole (S2), the square root of (G3) is formed
/// from angles, `ρ² − (κ−c₀)² = (cos θmin − cos θ)(cos θ − cos θmax)`, each factor as a product of
/// sines, so ψq keeps full relative precision where arccos would lose half the digits.
#pragma once

#include <array>
#include <cstddef>

#include "../core/units.hpp"
#include "../core/vec.hpp"

namespace kin5 {

/// Whether a tool axis can be reached, and how (S2), (S4).
enum class reach_status {
  reachable,    ///< one or more solutions within the axes' travel
  pole,         ///< u = ±p (S2): ψp is free and was chosen by the pole policy
  unreachable,  ///< no solution within travel; see the angular gap
};

/// How to choose ψp at a pole (S2), where every ψp gives the same tool axis.
struct pole_policy {
  enum class kind { keep, approach };
  kind rule = kind::keep;
  radians psi_p{};        ///< `keep`: the ψp to keep (usually the previous block's)
  vec3 approach_direction{};  ///< `approach`: the direction from which u comes to the pole

  /// Keep ψp, typically the value of the previous block.
  static constexpr pole_policy keep(radians psi_p_value) noexcept { return {kind::keep, psi_p_value, {}}; }
  /// ψp is the limit of (G4) as u approaches the pole along `direction` (a vector not parallel
  /// to p). This generalises the convention of Tian et al. 2010 (c_t → 90°, P16): pass the direction in
  /// which the source machine's tool axis leaves the pole.
  static constexpr pole_policy approach(const vec3& direction) noexcept { return {kind::approach, {}, direction}; }
};

/// ψp and ψq of one branch, radians, not wrapped.
struct branch_angles {
  radians psi_p{};
  radians psi_q{};
};

/// The result of `two_axis_geometry::solve`: zero, one or two branches.
struct two_axis_solution {
  reach_status status = reach_status::unreachable;
  radians gap{};          ///< angle from u to the reachable cone (G5), 0 when reachable
  std::size_t count = 0;  ///< 0 (unreachable), 1 (on the reach boundary S3) or 2
  std::array<branch_angles, 2> branch{};
};

/// Geometry of a two-rotary-axis chain and the derived constants of (G2).
struct two_axis_geometry {
  vec3 p{};  ///< axis fixed in the workpiece frame (unit)
  vec3 q{};  ///< axis carried by p, at the zero pose (unit)
  vec3 t{};  ///< tool axis at the zero pose (unit)
  double c0{}, alpha{}, beta{}, rho{};
  radians delta{};
  radians theta_min{}, theta_max{};  ///< reachable range of ∠(p, u) with ψq unlimited (G5)
  double cos_delta{}, sin_delta{};    ///< cos δ = α/ρ, sin δ = β/ρ
  vec3 q_cross_t{};                    ///< q × t, for R(q, ψq) t without trigonometry
  double q_dot_t{};
  /// p ⊥ q and q ⊥ t: the branches are then related by ψp− = ψp+ + π (G4′, see `branch_pair`).
  bool orthogonal_chain = false;

  static constexpr two_axis_geometry make(const vec3& p, const vec3& q, const vec3& t) {
    two_axis_geometry g{p, q, t};
    g.c0 = dot(p, q) * dot(q, t);
    g.alpha = dot(p, t) - g.c0;
    g.beta = dot(p, cross(q, t));
    g.rho = math::sqrt(g.alpha * g.alpha + g.beta * g.beta);
    g.delta = {math::atan2(g.beta, g.alpha)};
    g.cos_delta = g.rho > 0 ? g.alpha / g.rho : 1.0;
    g.sin_delta = g.rho > 0 ? g.beta / g.rho : 0.0;
    g.q_cross_t = cross(q, t);
    g.q_dot_t = dot(q, t);
    g.orthogonal_chain = math::abs(dot(p, q)) < 1e-15 && math::abs(g.q_dot_t) < 1e-15;
    const double pq = angle_between(p, q).value, qt = angle_between(q, t).value;
    g.theta_min = {math::abs(pq - qt)};
    const double sum = pq + qt;
    g.theta_max = {sum < 2.0 * pi - sum ? sum : 2.0 * pi - sum};
    return g;
  }

  /// (G1): the tool axis for relative angles ψp, ψq.
  constexpr vec3 tool_axis(radians psi_p, radians psi_q) const {
    return rotate(p, psi_p, rotate(q, psi_q, t));
  }

  /// Angle from u to the set of axes reachable with ψq unlimited (G5); 0 inside.
  constexpr radians workspace_gap(const vec3& u) const { return latitude_gap(angle_between(p, u).value); }


  /// Every solution of (G1) for the unit tool axis u. A u within `tolerance` of the reachable
  /// cone is treated as on it. At a pole (|p × u| ≤ `pole_radius`) ψp follows `policy`.
  constexpr two_axis_solution solve(const vec3& u_in, const pole_policy& policy = {},
                                    radians tolerance = {1e-9}, double pole_radius = 1e-10) const {
    two_axis_solution out{};
    const vec3 u = normalized(u_in);
    double kappa_minus_c0 = dot(p, u) - c0;
    double s = 0.0;
    if (rho - math::abs(kappa_minus_c0) > 1e-3 * rho) {
      // Inside the band (G5), away from its edges: reachable, not a pole (poles lie on the
      // boundary), and ρ² − (κ−c₀)² = (ρ − (κ−c₀))(ρ + (κ−c₀)) with both factors ≥ 1e-3 ρ, so
      // the rounding of κ (1e-16) costs s at most ~1e-13 relative.
      s = math::sqrt((rho - kappa_minus_c0) * (rho + kappa_minus_c0));
      out.status = reach_status::reachable;
      out.count = 2;
      const double half_opening = math::atan2(s, kappa_minus_c0);
      branch_pair(u, kappa_minus_c0, s, half_opening, out);
      return out;
    }
    const double theta_u = angle_between(p, u).value;  // ∠(p, u), used for the gap and (G3)
    out.gap = latitude_gap(theta_u);
    if (out.gap.value > tolerance.value) return out;  // S4: no ψq gives this latitude
    out.gap = {0.0};

    // (G2)-(G3) near the boundary: ρ² − (κ−c₀)² as (cos θmin − cos θ)(cos θ − cos θmax), each
    // factor a product of sines, so that ψq keeps its precision where arccos would not.
    const double theta = math::clamp(theta_u, theta_min.value, theta_max.value);
    const double to_top = 2.0 * math::sin(0.5 * (theta + theta_min.value)) * math::sin(0.5 * (theta - theta_min.value));
    const double to_bottom = 2.0 * math::sin(0.5 * (theta_max.value + theta)) * math::sin(0.5 * (theta_max.value - theta));
    const double prod = to_top * to_bottom;
    s = prod > 0 ? math::sqrt(prod) : 0.0;
    kappa_minus_c0 = math::cos(theta) - c0;
    const double half_opening = math::atan2(s, kappa_minus_c0);
    const radians psi_q_plus{delta.value + half_opening};
    const radians psi_q_minus{delta.value - half_opening};

    const bool at_pole = norm(cross(p, u)) <= pole_radius;
    out.status = at_pole ? reach_status::pole : reach_status::reachable;
    if (!at_pole) {
      branch_pair(u, kappa_minus_c0, s, half_opening, out);
      out.count = s > 0 ? 2 : 1;  // on the boundary (S3) the branches merge
      return out;
    }
    if (policy.rule == pole_policy::kind::keep) {
      out.branch[0] = {policy.psi_p, psi_q_plus};
      out.count = 1;
      return out;
    }
    // Approach: w leaves the pole along σ (q × w) as ψq moves away from its boundary value;
    // σ = +1 for the + branch at the top of the cone (κ − c₀ > 0), and flips at the bottom.
    const double sigma = kappa_minus_c0 >= 0 ? 1.0 : -1.0;
    const vec3 v = policy.approach_direction - dot(p, policy.approach_direction) * p;
    const vec3 w = rotate(q, psi_q_plus, t);
    const vec3 tangent = cross(q, w);
    const vec3 tangent_perp = tangent - dot(p, tangent) * p;
    out.branch[0] = {signed_angle_about_p(sigma * tangent_perp, v), psi_q_plus};
    out.branch[1] = {signed_angle_about_p(-sigma * tangent_perp, v), psi_q_minus};
    out.count = 2;
    return out;
  }

 private:
  // Both branches of (G3)/(G4) from sin and cos of the half opening φ = atan2(s, κ − c₀):
  // ψq± = δ ± φ, and w± = R(q, ψq±) t by Rodrigues with cos(δ ± φ), sin(δ ± φ) formed from
  // cos δ, sin δ, cos φ, sin φ — one atan2 per branch (for ψp) and none for w.
  //
  // (G4′) On an orthogonal chain (p ⊥ q, q ⊥ t) w runs on the great circle normal to q, which
  // contains p; its two points at latitude κ are mirror images across p, so their projections
  // normal to p are opposite and ψp− = ψp+ + π. One atan2 fewer, and the law suite checks it
  // against (G4) on every orthogonal catalog machine.
  constexpr void branch_pair(const vec3& u, double kappa_minus_c0, double s, double half_opening,
                             two_axis_solution& out) const {
    const double r = math::sqrt(s * s + kappa_minus_c0 * kappa_minus_c0);
    const double cos_phi = r > 0 ? kappa_minus_c0 / r : 1.0, sin_phi = r > 0 ? s / r : 0.0;
    // (G4) on the projections themselves: w·u − (p·w)(p·u) would cancel near the pole.
    const vec3 u_perp = u - dot(p, u) * p;
    const int computed = orthogonal_chain ? 1 : 2;
    for (int b = 0; b < computed; ++b) {
      const double sign = b == 0 ? 1.0 : -1.0;
      const double c = cos_delta * cos_phi - sign * sin_delta * sin_phi;  // cos(δ ± φ)
      const double sn = sin_delta * cos_phi + sign * cos_delta * sin_phi;  // sin(δ ± φ)
      const vec3 w = c * t + sn * q_cross_t + ((1.0 - c) * q_dot_t) * q;
      out.branch[b] = {signed_angle_about_p(w - dot(p, w) * p, u_perp), {delta.value + sign * half_opening}};
    }
    if (orthogonal_chain) {
      const double psi_p = out.branch[0].psi_p.value;
      out.branch[1] = {{psi_p > 0 ? psi_p - pi : psi_p + pi}, {delta.value - half_opening}};
    }
  }

  // Angle from the latitude θ = ∠(p, u) to [θmin, θmax] (G5); 0 inside.
  constexpr radians latitude_gap(double theta) const {
    if (theta < theta_min.value) return {theta_min.value - theta};
    if (theta > theta_max.value) return {theta - theta_max.value};
    return {0.0};
  }
  constexpr radians signed_angle_about_p(const vec3& from, const vec3& to) const {
    return {math::atan2(dot(p, cross(from, to)), dot(from, to))};
  }
};

/// A single rotary axis turning the tool (a 4-axis machine): u = R(p, ψp) t. Reachable only
/// where ∠(p, u) = ∠(p, t).
struct one_axis_geometry {
  vec3 p{};
  vec3 t{};

  static constexpr one_axis_geometry make(const vec3& p, const vec3& t) { return {p, t}; }

  constexpr vec3 tool_axis(radians psi_p) const { return rotate(p, psi_p, t); }

  constexpr radians workspace_gap(const vec3& u) const {
    return {math::abs(angle_between(p, u).value - angle_between(p, t).value)};
  }

  /// The unique ψp, or `unreachable` with the latitude gap.
  constexpr two_axis_solution solve(const vec3& u_in, radians tolerance = {1e-9}) const {
    two_axis_solution out{};
    const vec3 u = normalized(u_in);
    // Exactly on the latitude of t (to 1e-12 in p·u) needs no angle; otherwise measure the gap.
    if (math::abs(dot(p, u) - dot(p, t)) > 1e-12) {
      out.gap = workspace_gap(u);
      if (out.gap.value > tolerance.value) return out;
    }
    out.gap = {0.0};
    const vec3 t_perp = t - dot(p, t) * p, u_perp = u - dot(p, u) * p;
    out.branch[0] = {{math::atan2(dot(p, cross(t_perp, u_perp)), dot(t_perp, u_perp))}, {0.0}};
    out.count = 1;
    out.status = reach_status::reachable;
    return out;
  }
};

}  // namespace kin5
