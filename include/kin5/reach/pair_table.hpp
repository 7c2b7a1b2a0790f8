/// @file reach/pair_table.hpp
/// Everything kin5 says about one ordered pair of machines, gathered for the writers
/// (`table_text.hpp`, `sphere_svg.hpp`): the regions of the source's poses row by row, how much
/// of the source's pose space and of the sphere each class covers, and, on chosen rows, every
/// boundary and worst gap found a second time with Ipopt (`pair_check.hpp`).
///
/// Rows: when the regions cannot depend on the source's fixed axis (a one-rotary source, or a
/// band target whose fixed axis the setup maps onto the source's), one row; otherwise the fixed
/// axis every 30° (endless) or at 13 even steps of its travel. Ipopt checks the first row and
/// the middle one.
#pragma once

#include <array>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../core/rigid.hpp"
#include "pair_check.hpp"
#include "sphere_map.hpp"

namespace kin5::reach {

/// Text describing a machine's rotary axes: "B endless, A [-120, 30]".
inline std::string travel_text(const machine_model& m) {
  std::string out;
  for (std::size_t i = 0; i < m.rotary_count; ++i) {
    const rotary_axis& a = m.rotary(i);
    if (!out.empty()) out += ", ";
    out += to_char(a.letter);
    if (a.travel.continuous) {
      out += " endless";
    } else {
      char buf[64];
      std::snprintf(buf, sizeof buf, " [%g, %g]", a.travel.lower.value, a.travel.upper.value);
      out += buf;
    }
  }
  return out;
}

/// One ordered pair, analysed.
struct pair_table {
  std::string from, to;                  ///< catalog ids
  std::string from_structure, to_structure, from_travel, to_travel;
  char fixed_letter = 0;                 ///< the source's fixed axis (0 for a one-rotary source)
  char swept_letter = 0;                 ///< the axis each row sweeps
  rigid_transform setup;                 ///< target_T_source
  bool default_setup = true;
  bool band_target = true, band_source = true;
  bool rows_independent = false;         ///< one row stands for every value of the fixed axis
  std::vector<pose_row> rows;
  std::vector<std::vector<value_check>> checks;  ///< per row; empty when not checked
  std::vector<value_check> branch_checks;        ///< the source's branch boundaries
  std::array<double, 3> pose_share{};            ///< by `matchability`, share of the pose box
  std::array<double, map_colour_count> sphere_share{};  ///< by `map_colour`, share of the sphere
  double worst_gap_rad = 0.0;                        ///< over the rows and 360 more, radians
  sphere_raster raster;
  std::vector<map_curve> curves;
  std::vector<map_marker> markers;
};

namespace detail {

/// Values of the fixed axis of `from` for the table's rows (commanded, radians).
inline std::vector<double> row_values(const machine_model& from, int endless_step_deg = 30, int bounded_steps = 12) {
  const rotary_axis& p = from.rotary(0);
  std::vector<double> out;
  if (p.travel.continuous) {
    for (int v = -180; v < 180; v += endless_step_deg) out.push_back(to_radians(degrees{double(v)}).value);
  } else {
    const commanded_range r = range_of(p);
    for (int k = 0; k <= bounded_steps; ++k) out.push_back(r.lo + (r.hi - r.lo) * k / bounded_steps);
  }
  return out;
}

/// Share of each class over one row's swept range.
inline std::array<double, 3> row_share(const pose_row& row) {
  std::array<double, 3> out{};
  double total = 0.0;
  for (const auto& r : row.regions) {
    out[static_cast<std::size_t>(r.match)] += r.hi - r.lo;
    total += r.hi - r.lo;
  }
  if (total > 0)
    for (auto& v : out) v /= total;
  else if (!row.regions.empty())
    out[static_cast<std::size_t>(row.regions.front().match)] = 1.0;
  return out;
}

/// Share of each class over the pose box (one row, or the mean of 360 evenly spaced rows), and
/// the largest gap met on those rows.
inline std::pair<std::array<double, 3>, double> pose_share(const pair_geometry& g, const pair_table& t) {
  auto worst_of = [](const pose_row& row) {
    double w = 0.0;
    for (const auto& r : row.regions) w = std::max(w, r.worst_gap_rad);
    return w;
  };
  if (t.rows_independent) return {row_share(t.rows.front()), worst_of(t.rows.front())};
  const commanded_range r = range_of(g.from().rotary(0));
  std::array<double, 3> out{};
  double worst = 0.0;
  constexpr int n = 360;
  for (int k = 0; k < n; ++k) {
    const pose_row row = row_regions(g, r.lo + (r.hi - r.lo) * (k + 0.5) / n);
    const auto s = row_share(row);
    for (std::size_t i = 0; i < 3; ++i) out[i] += s[i] / n;
    worst = std::max(worst, worst_of(row));
  }
  return {out, worst};
}

}  // namespace detail

/// Analyses `from` → `to` under `setup`; with `with_ipopt`, also the Ipopt checks.
inline pair_table make_pair_table(const machine_model& from, const machine_model& to, const rigid_transform& setup,
                                  bool is_default_setup, bool with_ipopt = true) {
  const pair_geometry g(from, to, setup.rotation);
  pair_table t;
  t.from = from.geometry.id, t.to = to.geometry.id;
  t.from_structure = from.geometry.structure, t.to_structure = to.geometry.structure;
  t.from_travel = travel_text(from), t.to_travel = travel_text(to);
  t.fixed_letter = from.rotary_count == 2 ? to_char(from.rotary(0).letter) : 0;
  t.swept_letter = to_char(from.rotary(from.rotary_count - 1).letter);
  t.setup = setup, t.default_setup = is_default_setup;
  t.band_target = g.band_target, t.band_source = g.band_source;
  t.rows_independent = from.rotary_count == 1 ||
                       (g.band_target && norm(cross(g.target_axis_in_source, from.rotary(0).direction)) < 1e-12);
  const std::vector<double> values = t.rows_independent ? std::vector<double>{0.0} : detail::row_values(from);
  for (double v : values) t.rows.push_back(row_regions(g, v));
  t.checks.resize(t.rows.size());
  if (with_ipopt) {
    t.branch_checks = check_branch_boundaries(from);
    t.checks.front() = check_row(g, t.rows.front());
    if (t.rows.size() > 1) t.checks[t.rows.size() / 2] = check_row(g, t.rows[t.rows.size() / 2]);
  }
  std::tie(t.pose_share, t.worst_gap_rad) = detail::pose_share(g, t);
  for (const auto& row : t.rows)
    for (const auto& r : row.regions) t.worst_gap_rad = std::max(t.worst_gap_rad, r.worst_gap_rad);
  t.raster = rasterize(g);
  for (std::size_t c = 0; c < map_colour_count; ++c) t.sphere_share[c] = t.raster.share(static_cast<map_colour>(c));
  t.curves = boundary_curves(g);
  t.markers = pole_markers(g);
  return t;
}

}  // namespace kin5::reach
