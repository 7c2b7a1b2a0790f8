/// @file reach/setup_search.hpp
/// Re-fixturing: the rotation R = target_T_source of the part on the target that makes every
/// tool axis of a program reachable, with the least rotary travel. Beyond Tian et al. 2010,
/// whose §1.1 leaves blocks with A_s > 0 untranslatable (erratum E5: only turning the part over
/// helps).
///
/// 1. The 24 axis-aligned rotations (the part turned by quarter turns on its faces) are tried in
///    a fixed order, the pair's default first. For each, every block's gap comes from the
///    closed form (`pair_geometry`); where all are zero, the translator's branch planner
///    (`plan_rotary_path`) gives the total rotary travel Σ|Δ|.
/// 2. On a band target, two continuous refinements with Ipopt, each over R(ω) = Rz(ω₂) Ry(ω₁)
///    Rx(ω₀) R_k, with the penalty
///        P(ω) = Σᵢ max(0, κᵢ − cos(θ_lo + m))² + max(0, cos(θ_hi − m) − κᵢ)²,   κᵢ = p_d · R(ω) uᵢ,
///    the squared distance of each block's latitude from the target's band shrunk by m = 0.01°:
///    a. when no axis-aligned rotation reaches every block, minimise P from the four closest to
///       it (exact gradient and Hessian), which finds a rotation that does if there is one near;
///    b. from the four feasible rotations of least travel, minimise travel + 10⁴ P within 30° of
///       each (central differences of the planned travel, quasi-Newton): the planner's travel is
///       piecewise smooth in ω, its pieces joined where a branch choice changes.
/// 3. Every rotation that reaches all blocks, ranked by travel. Whether a translation with it
///    succeeds also depends on what else the program holds (a plane selection or an arc needs an
///    axis-aligned setup): `make_program_report` with the rotation says, and `kin5 match` takes
///    the first of the ranking that translates.
///
/// Rotations only: where the part must sit for its slides to stay within the linear travel is
/// `setup_offset.hpp`, which `choose_setup` (program_report.hpp) asks for each rotation.
#pragma once

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <span>
#include <tuple>
#include <vector>

#include "../kinematics/branch_plan.hpp"
#include "../translate/translate.hpp"
#include "box_minimizer.hpp"
#include "pair_geometry.hpp"

namespace kin5::reach {

/// The 24 proper rotations that permute and flip the coordinate axes, identity first.
inline std::vector<mat3> axis_aligned_rotations() {
  std::vector<mat3> out;
  const std::array<std::array<int, 3>, 6> perms{{{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  const vec3 e[3] = {unit_x, unit_y, unit_z};
  for (const auto& p : perms)
    for (int signs = 0; signs < 8; ++signs) {
      mat3 m{};
      for (int r = 0; r < 3; ++r) m.row[r] = ((signs >> r) & 1 ? -1.0 : 1.0) * e[p[static_cast<std::size_t>(r)]];
      if (determinant(m) > 0) out.push_back(m);
    }
  return out;
}

/// One rotation evaluated on a program's tool axes.
struct setup_candidate {
  mat3 rotation = mat3::identity();
  bool axis_aligned = true;
  std::size_t unreachable = 0;  ///< blocks the target cannot reach
  double worst_gap_rad = 0.0;       ///< radians
  double travel_rad = 0.0;          ///< planned total rotary travel Σ|Δ|, radians (all reachable)
  bool feasible() const { return unreachable == 0; }
};

/// What the search found.
struct setup_search_result {
  std::vector<setup_candidate> tried;     ///< every rotation evaluated, in order
  std::optional<setup_candidate> best;    ///< reaches every block with the least travel
  std::vector<setup_candidate> ranked;    ///< every one that reaches all blocks, least travel first
  setup_candidate closest;                ///< fewest unreachable blocks, then smallest worst gap
  std::size_t refined = 0;                ///< refinements run (Ipopt)
};

/// Evaluates rotation R of pair `from` → `to` on the tool axes `axes` (source frame, unit,
/// program order).
inline setup_candidate evaluate_setup(const machine_model& from, const machine_model& to, const mat3& r,
                                      std::span<const vec3> axes, bool axis_aligned) {
  const pair_geometry g(from, to, r);
  setup_candidate c{r, axis_aligned};
  std::vector<vec3> target;
  for (const vec3& u : axes) {
    const double gap = g.target_gap(u).value;
    if (gap > 0) ++c.unreachable, c.worst_gap_rad = std::max(c.worst_gap_rad, gap);
    target.push_back(r * u);
  }
  if (c.feasible()) c.travel_rad = plan_rotary_path(to, target).travel_rad;
  return c;
}

namespace detail {

/// Rz(ω₂) Kz^{n₂} Ry(ω₁) Ky^{n₁} Rx(ω₀) Kx^{n₀} w, with K_a v = a × v: v(ω) and its derivatives
/// (K_a commutes with R(a, ·)).
inline vec3 turned(const std::array<double, 3>& w_angles, const std::array<int, 3>& order, vec3 w) {
  const vec3 axes[3] = {unit_x, unit_y, unit_z};
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < order[static_cast<std::size_t>(j)]; ++k) w = cross(axes[j], w);
    w = rotate(axes[j], {w_angles[static_cast<std::size_t>(j)]}, w);
  }
  return w;
}

/// The penalty of step 2 over unique axes w (already turned by R_k), its gradient and Hessian.
inline double band_penalty(const std::vector<double>& x, const std::vector<vec3>& ws, const vec3& p,
                           double kappa_hi, double kappa_lo, std::vector<double>& g, std::vector<double>& h) {
  const std::array<double, 3> om{x[0], x[1], x[2]};
  std::fill(g.begin(), g.end(), 0.0);
  std::fill(h.begin(), h.end(), 0.0);
  double f = 0.0;
  for (const vec3& w : ws) {
    const double kappa = dot(p, turned(om, {0, 0, 0}, w));
    const double excess = kappa > kappa_hi ? kappa - kappa_hi : (kappa < kappa_lo ? kappa - kappa_lo : 0.0);
    if (excess == 0.0) continue;
    f += excess * excess;
    std::array<double, 3> d1{};
    for (int i = 0; i < 3; ++i) {
      std::array<int, 3> o{};
      o[static_cast<std::size_t>(i)] = 1;
      d1[static_cast<std::size_t>(i)] = dot(p, turned(om, o, w));
    }
    for (int i = 0; i < 3; ++i) {
      g[static_cast<std::size_t>(i)] += 2.0 * excess * d1[static_cast<std::size_t>(i)];
      for (int j = 0; j < 3; ++j) {
        std::array<int, 3> o{};
        ++o[static_cast<std::size_t>(i)], ++o[static_cast<std::size_t>(j)];
        const double d2 = dot(p, turned(om, o, w));
        h[static_cast<std::size_t>(3 * i + j)] += 2.0 * (d1[static_cast<std::size_t>(i)] * d1[static_cast<std::size_t>(j)] + excess * d2);
      }
    }
  }
  return f;
}

/// Distinct axes of a program (to 1e-9), so that long programs cost no more than their shapes.
inline std::vector<vec3> distinct_axes(std::span<const vec3> axes) {
  std::map<std::tuple<long long, long long, long long>, vec3> seen;
  for (const vec3& u : axes)
    seen.emplace(std::tuple{std::llround(u.x * 1e9), std::llround(u.y * 1e9), std::llround(u.z * 1e9)}, u);
  std::vector<vec3> out;
  for (const auto& [key, u] : seen) out.push_back(u);
  return out;
}

/// The rotation of step 2 from ω, about the target frame's axes.
inline mat3 turn_of(const std::vector<double>& x) {
  const std::array<double, 3> om{x[0], x[1], x[2]};
  return mat3::from_columns(turned(om, {0, 0, 0}, unit_x), turned(om, {0, 0, 0}, unit_y), turned(om, {0, 0, 0}, unit_z));
}

/// κ bounds of the band shrunk by m = 0.01° (a side that reaches a pole has none: ±2).
inline std::pair<double, double> kappa_bounds(const angle_set& band) {
  const double margin = to_radians(degrees{0.01}).value;
  const double lo = band.parts().front().lo, hi = band.parts().back().hi;
  return {lo > 1e-12 ? std::cos(std::min(lo + margin, hi)) : 2.0, hi < pi - 1e-12 ? std::cos(std::max(hi - margin, lo)) : -2.0};
}

/// Step 2a from rotation `start` on target `to`: the penalty alone; the refined rotation.
inline mat3 refine_setup(const machine_model& to, const mat3& start, const std::vector<vec3>& distinct,
                         const angle_set& band) {
  const auto [kappa_hi, kappa_lo] = kappa_bounds(band);
  std::vector<vec3> ws;
  for (const vec3& u : distinct) ws.push_back(start * u);
  const vec3 p = to.rotary(0).direction;
  const objective f = [&](const std::vector<double>& x, std::vector<double>& g, std::vector<double>& h) {
    return band_penalty(x, ws, p, kappa_hi, kappa_lo, g, h);
  };
  const box_minimum m = minimize_in_box(f, {-pi, -pi, -pi}, {pi, pi, pi}, {{0.0, 0.0, 0.0}});
  return m.x.empty() ? start : turn_of(m.x) * start;
}

/// Step 2b from rotation `start` on target `to`: least planned travel, blocks kept in the
/// shrunk band.
inline mat3 refine_travel(const machine_model& to, const mat3& start, std::span<const vec3> axes,
                          const angle_set& band) {
  const auto [kappa_hi, kappa_lo] = kappa_bounds(band);
  const vec3 p = to.rotary(0).direction;
  std::vector<vec3> turned_axes(axes.size());
  auto value = [&](const std::vector<double>& x) {
    const mat3 r = turn_of(x) * start;
    double penalty = 0.0;
    for (std::size_t i = 0; i < axes.size(); ++i) {
      turned_axes[i] = r * axes[i];
      const double kappa = dot(p, turned_axes[i]);
      const double e = kappa > kappa_hi ? kappa - kappa_hi : (kappa < kappa_lo ? kappa - kappa_lo : 0.0);
      penalty += e * e;
    }
    return plan_rotary_path(to, turned_axes).travel_rad + 1e4 * penalty;
  };
  const objective f = [&](const std::vector<double>& x, std::vector<double>& g, std::vector<double>&) {
    constexpr double h = 1e-6;
    for (std::size_t j = 0; j < 3; ++j) {
      auto a = x, b = x;
      a[j] += h, b[j] -= h;
      g[j] = (value(a) - value(b)) / (2.0 * h);
    }
    return value(x);
  };
  const double reach = to_radians(degrees{30.0}).value;
  const box_minimum m = minimize_in_box(f, {-reach, -reach, -reach}, {reach, reach, reach}, {{0.0, 0.0, 0.0}},
                                        hessian::quasi_newton);
  return m.x.empty() ? start : turn_of(m.x) * start;
}

}  // namespace detail

/// Searches a setup rotation of pair `from` → `to` for the tool axes `axes` (source frame,
/// program order), starting with `preferred` (the pair's default or the current setup).
inline setup_search_result search_setup(const machine_model& from, const machine_model& to, std::span<const vec3> axes,
                                        const mat3& preferred) {
  setup_search_result out;
  auto equal = [](const mat3& a, const mat3& b) {
    return norm(a.row[0] - b.row[0]) + norm(a.row[1] - b.row[1]) + norm(a.row[2] - b.row[2]) < 1e-12;
  };
  bool preferred_aligned = false;
  for (const mat3& r : axis_aligned_rotations()) preferred_aligned = preferred_aligned || equal(r, preferred);
  out.tried.push_back(evaluate_setup(from, to, preferred, axes, preferred_aligned));
  for (const mat3& r : axis_aligned_rotations())
    if (!equal(r, preferred)) out.tried.push_back(evaluate_setup(from, to, r, axes, true));
  const pair_geometry g(from, to);
  if (g.band_target && !g.target_band.empty()) {
    auto indices = [&](auto&& better) {
      std::vector<std::size_t> order(out.tried.size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
      std::stable_sort(order.begin(), order.end(), better);
      order.resize(std::min<std::size_t>(4, order.size()));
      return order;
    };
    auto badness = [&](std::size_t i) { return std::pair{out.tried[i].unreachable, out.tried[i].worst_gap_rad}; };
    const bool any_feasible = std::any_of(out.tried.begin(), out.tried.end(), [](const auto& c) { return c.feasible(); });
    if (!any_feasible) {  // 2a
      const std::vector<vec3> distinct = detail::distinct_axes(axes);
      for (std::size_t i : indices([&](std::size_t a, std::size_t b) { return badness(a) < badness(b); })) {
        const mat3 refined = detail::refine_setup(to, out.tried[i].rotation, distinct, g.target_band);
        out.tried.push_back(evaluate_setup(from, to, refined, axes, false));
        ++out.refined;
      }
    }
    auto travel = [&](std::size_t i) { return out.tried[i].feasible() ? out.tried[i].travel_rad : 1e300; };
    for (std::size_t i : indices([&](std::size_t a, std::size_t b) { return travel(a) < travel(b); })) {  // 2b
      if (!out.tried[i].feasible()) continue;
      const mat3 refined = detail::refine_travel(to, out.tried[i].rotation, axes, g.target_band);
      out.tried.push_back(evaluate_setup(from, to, refined, axes, false));
      ++out.refined;
    }
  }
  out.closest = out.tried.front();
  for (const auto& c : out.tried)
    if (c.feasible()) out.ranked.push_back(c);
  std::stable_sort(out.ranked.begin(), out.ranked.end(), [](const auto& a, const auto& b) { return a.travel_rad < b.travel_rad - 1e-9; });
  if (!out.ranked.empty()) out.best = out.ranked.front();
  for (const auto& c : out.tried) {
    if (std::pair{c.unreachable, c.worst_gap_rad} < std::pair{out.closest.unreachable, out.closest.worst_gap_rad}) out.closest = c;
  }
  return out;
}

}  // namespace kin5::reach
