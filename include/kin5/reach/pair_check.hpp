/// @file reach/pair_check.hpp
/// The regions of `pair_regions.hpp` found a second way, numerically with Ipopt and without the
/// closed forms (G3)/(G5):
///
/// * a **branch boundary** is where the source's latitude ∠(p_s, u) is extreme along its carried
///   axis: minimise and maximise p_s · u over that axis from several starts; interior optima are
///   the boundaries (closed form: ψq = δ and δ + π);
/// * a **reach boundary** is where the gap to the target's reach (Ipopt, `nearest_tool_axis`)
///   falls to zero: the gap is sampled at three poses inside the unreachable region next to the
///   boundary and its quadratic interpolant extrapolated to zero (the gap leaves zero linearly
///   across a boundary the row crosses);
/// * the **worst gap** of an unreachable region is the Ipopt gap at the pose where the closed form
///   puts it.
///
/// For SAJO 12000P → DMU 80P these give A = −90° (branch), A = 0° (reach) and a gap of 30° at
/// A = 30°, as Tian et al. 2010 §1.1 and its eq (19) imply (errata E5, E6).
#pragma once

#include <string>
#include <vector>

#include "nearest_tool_axis.hpp"
#include "pair_regions.hpp"

namespace kin5::reach {

/// One value found both ways, radians.
struct value_check {
  std::string what;     ///< e.g. "reach boundary", "branch boundary", "worst gap"
  double closed = 0.0;  ///< closed form
  double numeric = 0.0; ///< Ipopt
  bool degenerate = false;  ///< a pole or a touching boundary: compare cosines, not angles
  bool found = true;        ///< false when Ipopt gave no value (then `numeric` is meaningless)
  double at = 0.0;          ///< for a worst gap: the swept angle where it is (radians)
};

/// Whether a check agrees: |closed − numeric| ≤ tolerance, or, at a degenerate point, the cosines
/// agree to `tolerance` (the angle is then determined only to about √tolerance).
inline bool agrees(const value_check& c, double tolerance) {
  if (!c.found) return false;
  if (std::abs(c.closed - c.numeric) <= tolerance) return true;
  return c.degenerate && std::abs(std::cos(c.closed) - std::cos(c.numeric)) <= tolerance;
}

namespace detail {

/// The commanded angles of the carried axis of `from` (two rotary axes) where ∠(p_s, u) is
/// extreme, by Ipopt: minimise ±p_s · R(q, ψq) t over the carried axis' travel from `starts`
/// evenly spread starts. Optima on the travel ends are dropped; the rest are returned sorted,
/// duplicates merged.
inline std::vector<double> latitude_extremes_numeric(const machine_model& from, int starts = 6) {
  const rotary_axis& q = from.rotary(1);
  const commanded_range r = range_of(q);
  const vec3 p = from.rotary(0).direction, axis = q.direction, t = from.tool_reference();
  const double sq = q.psi_per_commanded();
  std::vector<double> out;
  for (double sign : {1.0, -1.0}) {
    const objective f = [&](const std::vector<double>& x, std::vector<double>& g, std::vector<double>& h) {
      const vec3 w = rotate(axis, q.psi({x[0]}), t);
      g[0] = sign * sq * dot(p, cross(axis, w));
      h[0] = sign * sq * sq * dot(p, cross(axis, cross(axis, w)));
      return sign * dot(p, w);
    };
    for (int k = 0; k < starts; ++k) {
      const box_minimum m = minimize_in_box(f, {r.lo}, {r.hi}, {{r.lo + (r.hi - r.lo) * (k + 0.5) / starts}});
      const double x = m.x[0];
      if (!m.converged || x - r.lo < 1e-6 || r.hi - x < 1e-6) continue;
      bool known = false;
      for (double y : out) known = known || std::abs(y - x) < 1e-6;
      if (!known) out.push_back(x);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace detail

/// The branch boundaries of `from` found by Ipopt beside the closed form δ, δ + π (commanded).
inline std::vector<value_check> check_branch_boundaries(const machine_model& from) {
  std::vector<value_check> out;
  if (from.rotary_count == 2) {
    std::vector<row_point> closed;
    const latitude_curve own = carried_curve(from, from.rotary(0).direction);
    const double sense = from.rotary(1).psi_per_commanded();
    const commanded_range r = range_of(from.rotary(1));
    for (double e : {own.delta.value, own.delta.value + pi}) detail::add_shifts(closed, e, sense, r, 0);
    const std::vector<double> numeric = detail::latitude_extremes_numeric(from);
    for (const auto& c : closed) {
      if (c.at - r.lo < 1e-6 || r.hi - c.at < 1e-6) continue;  // on a travel end: not a boundary
      value_check v{"branch boundary", c.at, 0.0, false, false};
      for (double x : numeric)
        if (!v.found || std::abs(x - c.at) < std::abs(v.numeric - c.at)) v.numeric = x, v.found = true;
      out.push_back(v);
    }
  }
  return out;
}

/// The Ipopt gap to the target's reach of the source pose at `s` on `row`, started from `starts`
/// (or a 3 × 3 grid when empty); the optimum is written back to `starts` for the next call. The
/// gap has a local minimum on each side of a tilting axis' travel (xyzac-trt: A at −100° and
/// at +50°); an odd grid puts an endless axis' starts at three distinct orientations, where an
/// even one over its two turns repeats them (−180° and +180°) and can miss the global minimum.
inline double numeric_gap(const pair_geometry& g, const pose_row& row, double s,
                          std::vector<std::vector<double>>& starts) {
  const vec3 v = g.target_R_source * tool_axis(g.from(), detail::pose_on_row(g.from(), row, s));
  if (starts.empty()) {
    std::vector<double> lower, upper;
    detail::travel_box(g.to(), lower, upper);
    starts = detail::grid_starts(lower, upper, 3);
  }
  const auto n = nearest_reachable_axis_from(g.to(), v, starts);
  std::vector<double> x;
  for (std::size_t i = 0; i < g.to().rotary_count; ++i) x.push_back(n.angles[i].value);
  starts = {x};
  return n.gap.value;
}

/// The reach boundary at `closed` (between regions a and b of the row, one unreachable) found
/// from the Ipopt gap alone: sampled at closed + σh, closed + 2σh, closed + 3σh into the
/// unreachable region (h = 0.02°, less in a short region), the quadratic through the three
/// samples extrapolated to zero gap.
inline value_check check_reach_boundary(const pair_geometry& g, const pose_row& row, double closed,
                                        const region& unreachable) {
  const double into = unreachable.lo >= closed - 1e-12 ? 1.0 : -1.0;
  const double room = into > 0 ? unreachable.hi - closed : closed - unreachable.lo;
  const double h = std::min(to_radians(degrees{0.02}).value, room / 4.0);
  std::vector<std::vector<double>> starts;
  std::array<double, 3> gap{};
  for (int i = 2; i >= 0; --i) gap[i] = numeric_gap(g, row, closed + into * (i + 1) * h, starts);
  // Newton form of the quadratic through (1, g0), (2, g1), (3, g2), evaluated for its root
  // nearest 0 in units of h: g(x) = g0 + d1 (x − 1) + d2 (x − 1)(x − 2).
  const double d1 = gap[1] - gap[0], d2 = 0.5 * (gap[2] - 2.0 * gap[1] + gap[0]);
  // Solve d2 x² + (d1 − 3 d2) x + (g0 − d1 + 2 d2) = 0 for the root nearest 0 by Newton from 0.
  double x = 0.0;
  for (int it = 0; it < 50; ++it) {
    const double f = gap[0] + d1 * (x - 1.0) + d2 * (x - 1.0) * (x - 2.0);
    const double df = d1 + d2 * (2.0 * x - 3.0);
    if (!(std::abs(df) > 1e-300)) break;
    x -= f / df;
  }
  value_check out{"reach boundary", closed, closed + into * x * h};
  out.found = std::isfinite(out.numeric) && gap[0] > 0.0;
  // A boundary the row only touches (slope ~ 0) fixes the angle to about √ε only.
  out.degenerate = std::abs(d1) < 1e-3 * h;
  return out;
}

/// Every Ipopt check of one row: its reach boundaries and the worst gap of each unreachable region.
inline std::vector<value_check> check_row(const pair_geometry& g, const pose_row& row) {
  std::vector<value_check> out;
  const auto& regs = row.regions;
  for (std::size_t i = 0; i < regs.size(); ++i) {
    if (regs[i].match != matchability::unreachable) continue;
    if (i > 0 && regs[i - 1].match != matchability::unreachable)
      out.push_back(check_reach_boundary(g, row, regs[i].lo, regs[i]));
    if (i + 1 < regs.size() && regs[i + 1].match != matchability::unreachable)
      out.push_back(check_reach_boundary(g, row, regs[i].hi, regs[i]));
    std::vector<std::vector<double>> starts;
    {
      std::vector<double> lower, upper;
      detail::travel_box(g.to(), lower, upper);
      starts = detail::grid_starts(lower, upper, 3);
    }
    const double numeric = numeric_gap(g, row, regs[i].worst_gap_at_rad, starts);
    out.push_back({"worst gap", regs[i].worst_gap_rad, numeric, false, true, regs[i].worst_gap_at_rad});
  }
  return out;
}

}  // namespace kin5::reach
