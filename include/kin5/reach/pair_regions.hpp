/// @file reach/pair_regions.hpp
/// The regions of a source machine's pose space that a target translates directly, only on the
/// source's other branch, or not at all — along one line of poses at a time: the source's fixed
/// axis held at one value (a *row*), its carried axis swept over its travel. (A one-rotary
/// source has a single row, its only axis swept.)
///
/// Along a row the tool axis turns about the carried axis a, so its latitude about d = Rᵀ p_d
/// follows the latitude equation (G2), κ(ψ) = d′ · R(a, ψ) t with d′ = R(p_s, −ψp) d, and the
/// row leaves the target's band where κ crosses the cosine of a band edge: roots (G3) in closed
/// form. The source's branch changes where ψq − δ crosses 0 or π. Between consecutive such
/// points the class is constant; each piece is classified once (`pair_geometry`). Targets whose
/// fixed axis does not turn freely have no band: their boundaries are found by a scan of the row
/// and bisection on `inverse`.
///
/// SAJO 12000P → DMU 80P, every B: other branch on [−120°, −90°), direct on [−90°, 0°],
/// unreachable on (0°, 30°] with worst gap 30° — Tian et al. 2010 §1.1, with the outer two
/// labelled the other way round there (errata E5, E6).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "pair_geometry.hpp"

namespace kin5::reach {

/// What happens at a point of a row (bit flags).
enum point_kind : unsigned {
  travel_end = 1u,       ///< an end of the swept axis' travel
  source_branch = 2u,    ///< the source's (G3) branches meet (ψq = δ or δ + π)
  source_pole = 4u,      ///< the source's tool axis is ±p_s (S2)
  target_edge = 8u,      ///< the tool axis is on an edge of the target's band
  target_pole = 16u,     ///< the tool axis is ±p_d on the target (S2)
  scanned = 32u,         ///< found by bisection on `inverse` (no band)
};

/// One interval of the swept axis with a single class. Angles are commanded, radians.
struct region {
  double lo = 0.0, hi = 0.0;
  bool lo_included = true, hi_included = true;
  matchability match = matchability::direct;
  double worst_gap_rad = 0.0;     ///< largest gap in the interval (unreachable), radians
  double worst_gap_at_rad = 0.0;  ///< where it is reached
};

/// A point of a row: a region boundary or a pole inside a region.
struct row_point {
  double at = 0.0;  ///< commanded angle of the swept axis, radians
  unsigned kinds = 0;
  bool boundary = false;  ///< the class changes here
};

/// One row: the fixed axis' value (none for a one-rotary source) and its regions in order.
struct pose_row {
  std::optional<double> fixed;  ///< commanded angle of the source's fixed axis, radians
  std::vector<region> regions;
  std::vector<row_point> points;  ///< boundaries and poles, in order
};

namespace detail {

/// Adds every 2π shift of `psi` (an angle of the swept axis' ψ) that lies in the commanded range.
inline void add_shifts(std::vector<row_point>& out, double psi, double sense, commanded_range r, unsigned kind) {
  const double c = sense * psi;
  for (double v = c + 2.0 * pi * std::ceil((r.lo - c) / (2.0 * pi) - 1e-12); v <= r.hi + 1e-12; v += 2.0 * pi)
    out.push_back({std::clamp(v, r.lo, r.hi), kind, false});
}

/// Commanded angles of source `from` on the row at swept value s.
inline rotary_values pose_on_row(const machine_model& from, const pose_row& row, double s) {
  rotary_values a{};
  if (from.rotary_count == 2) a[0] = {*row.fixed};
  a[from.rotary_count - 1] = {s};
  return a;
}

/// The direction d′ = R(p_s, −ψp) Rᵀ p_d of the row: the target's fixed axis seen from the
/// source's carried axis.
inline vec3 row_direction(const pair_geometry& g, const pose_row& row) {
  const machine_model& from = g.from();
  if (from.rotary_count == 2) return rotate(from.rotary(0).direction, from.rotary(0).psi({-*row.fixed}), g.target_axis_in_source);
  return g.target_axis_in_source;
}

/// The candidate points of a row: travel ends, branch meets and poles of the source, and, on a
/// band target, the roots of κ(ψ) = cos(edge) and κ = ±1.
inline std::vector<row_point> candidate_points(const pair_geometry& g, const pose_row& row) {
  const machine_model& from = g.from();
  const rotary_axis& swept = from.rotary(from.rotary_count - 1);
  const commanded_range r = range_of(swept);
  const double sense = swept.psi_per_commanded();
  std::vector<row_point> pts{{r.lo, travel_end, false}, {r.hi, travel_end, false}};
  if (from.rotary_count == 2) {
    const latitude_curve own = carried_curve(from, from.rotary(0).direction);
    const unsigned top = std::abs(own.c0 + own.rho - 1.0) < 1e-12 ? source_pole : 0u;
    const unsigned bottom = std::abs(own.c0 - own.rho + 1.0) < 1e-12 ? source_pole : 0u;
    add_shifts(pts, own.delta.value, sense, r, source_branch | top);
    add_shifts(pts, own.delta.value + pi, sense, r, source_branch | bottom);
  }
  if (!g.band_target) return pts;
  const latitude_curve curve = carried_curve(from, row_direction(g, row));
  auto add_roots = [&](double k, unsigned kind) {
    std::size_t n = 0;
    const auto roots = curve.roots(k, n);
    for (std::size_t i = 0; i < n; ++i) add_shifts(pts, roots[i], sense, r, kind);
  };
  for (double edge : g.target_band.edges()) add_roots(std::cos(edge), target_edge);
  if (g.target_band.contains(0.0, 0.0)) add_roots(1.0, target_pole);
  if (g.target_band.contains(pi, 0.0)) add_roots(-1.0, target_pole);
  return pts;
}

/// Sorts points, merging those within 1e-12 (their kinds or-ed).
inline std::vector<row_point> sorted_points(std::vector<row_point> pts) {
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.at < b.at; });
  std::vector<row_point> out;
  for (const auto& p : pts) {
    if (!out.empty() && p.at - out.back().at <= 1e-12) out.back().kinds |= p.kinds;
    else out.push_back(p);
  }
  return out;
}

/// Adds the class changes of a row on a target without a band: a scan in steps of at most
/// 0.25°, each change located by bisection on the class to 1e-13 rad.
inline void add_scanned_points(const pair_geometry& g, const pose_row& row, std::vector<row_point>& pts) {
  const commanded_range r = range_of(g.from().rotary(g.from().rotary_count - 1));
  const int n = static_cast<int>(std::ceil((r.hi - r.lo) / to_radians(degrees{0.25}).value));
  auto cls = [&](double s) { return g.classify_pose(pose_on_row(g.from(), row, s)); };
  double prev = r.lo;
  matchability prev_class = cls(prev);
  for (int i = 1; i <= n; ++i) {
    const double x = r.lo + (r.hi - r.lo) * i / n;
    const matchability c = cls(x);
    if (c != prev_class) {
      double a = prev, b = x;
      while (b - a > 1e-13) {
        const double m = 0.5 * (a + b);
        (cls(m) == prev_class ? a : b) = m;
      }
      pts.push_back({0.5 * (a + b), scanned, false});
    }
    prev = x, prev_class = c;
  }
}

}  // namespace detail

/// Largest gap over [lo, hi] of a row, and where: on a band target at the ends or where the
/// latitude is extreme (ψ − δ′ = kπ); otherwise by a scan and golden-section refinement.
inline std::pair<double, double> worst_gap(const pair_geometry& g, const pose_row& row, double lo, double hi) {
  const machine_model& from = g.from();
  auto gap = [&](double s) {
    radians out{};
    g.classify_pose(detail::pose_on_row(from, row, s), &out);
    return out.value;
  };
  std::vector<double> xs{lo, hi};
  const int n = g.band_target ? 0 : 64;
  for (int i = 1; i < n; ++i) xs.push_back(lo + (hi - lo) * i / n);
  if (g.band_target) {
    std::vector<row_point> extremes;
    const latitude_curve curve = carried_curve(from, detail::row_direction(g, row));
    const rotary_axis& swept = from.rotary(from.rotary_count - 1);
    for (double e : {curve.delta.value, curve.delta.value + pi})
      detail::add_shifts(extremes, e, swept.psi_per_commanded(), {lo, hi}, 0);
    for (const auto& e : extremes) xs.push_back(e.at);
  }
  double best = -1.0, at = lo;
  for (double x : xs)
    if (const double v = gap(x); v > best) best = v, at = x;
  if (!g.band_target) {  // golden section about the best scanned point
    const double h = (hi - lo) / n;
    double a = std::max(lo, at - h), b = std::min(hi, at + h);
    constexpr double phi = 0.6180339887498949;
    for (int i = 0; i < 80; ++i) {
      const double x1 = b - phi * (b - a), x2 = a + phi * (b - a);
      const bool left = gap(x1) > gap(x2);
      (left ? b : a) = left ? x2 : x1;
    }
    if (const double v = gap(0.5 * (a + b)); v > best) best = v, at = 0.5 * (a + b);
  }
  return {best, at};
}

/// The regions of the row with the source's fixed axis at `fixed` (commanded, radians; ignored
/// for a one-rotary source).
inline pose_row row_regions(const pair_geometry& g, double fixed = 0.0) {
  pose_row row;
  if (g.from().rotary_count == 2) row.fixed = fixed;
  std::vector<row_point> pts = detail::candidate_points(g, row);
  if (!g.band_target) detail::add_scanned_points(g, row, pts);
  pts = detail::sorted_points(std::move(pts));
  auto cls = [&](double s) { return g.classify_pose(detail::pose_on_row(g.from(), row, s)); };
  // Pieces: point, open gap, point, …, point; merged while the class stays the same.
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const matchability at_point = cls(pts[i].at);
    if (row.regions.empty() || row.regions.back().match != at_point) {
      if (!row.regions.empty()) pts[i].boundary = true;
      row.regions.push_back({pts[i].at, pts[i].at, true, true, at_point});
    }
    row.regions.back().hi = pts[i].at;
    row.regions.back().hi_included = true;
    if (i + 1 == pts.size()) break;
    const matchability between = cls(0.5 * (pts[i].at + pts[i + 1].at));
    if (between != at_point) {
      pts[i].boundary = true;
      row.regions.push_back({pts[i].at, pts[i + 1].at, false, false, between});
    }
    row.regions.back().hi = pts[i + 1].at;
    row.regions.back().hi_included = false;
  }
  for (auto& reg : row.regions)
    if (reg.match == matchability::unreachable) std::tie(reg.worst_gap_rad, reg.worst_gap_at_rad) = worst_gap(g, row, reg.lo, reg.hi);
  for (const auto& p : pts)
    if (p.boundary || (p.kinds & (source_pole | target_pole))) row.points.push_back(p);
  return row;
}

}  // namespace kin5::reach
