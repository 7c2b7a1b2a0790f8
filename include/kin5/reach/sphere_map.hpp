/// @file reach/sphere_map.hpp
/// The map of a pair: every tool axis of the sphere, in the source's workpiece frame, coloured by
/// how the target takes it (`orientation_class`, unreachable ones shaded by their gap), drawn
/// as two discs in Lambert's azimuthal equal-area projection — the hemisphere k ≥ 0 about +Z
/// and k ≤ 0 about −Z, both seen from +Z (x right, y up) — so that equal areas on the map are
/// equal solid angles. The cells are classified in closed form (`pair_geometry`).
///
/// Projection of a unit u = (x, y, z) on the disc of its hemisphere (radius √2 at the equator):
///     (X, Y) = √(2 / (1 + |z|)) · (x, y).
/// Its inverse, for ρ² = X² + Y² ≤ 2: |z| = 1 − ρ²/2, (x, y) = √(1 − ρ²/4) · (X, Y).
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "pair_geometry.hpp"

namespace kin5::reach {

/// The colour classes of a map cell (index into `map_palette`).
enum class map_colour : unsigned char {
  outside,          ///< not on the disc
  not_on_source,
  direct,
  other_branch,
  either_branch,
  gap_5,            ///< unreachable, gap ≤ 5°
  gap_15,           ///< 5° < gap ≤ 15°
  gap_45,           ///< 15° < gap ≤ 45°
  gap_more,         ///< gap > 45°
};
inline constexpr std::size_t map_colour_count = 9;

/// Fill colour and legend text of each `map_colour`.
struct palette_entry {
  const char* fill;
  const char* label;
};
inline constexpr std::array<palette_entry, map_colour_count> map_palette{{
    {"#ffffff", ""},
    {"#d9d9d9", "not held by the source"},
    {"#1a9850", "direct"},
    {"#7b3294", "other branch"},
    {"#5ab4ac", "either branch (the source pose decides)"},
    {"#fdae61", "unreachable, gap up to 5\u00b0"},
    {"#f46d43", "unreachable, gap 5\u00b0 to 15\u00b0"},
    {"#d73027", "unreachable, gap 15\u00b0 to 45\u00b0"},
    {"#a50026", "unreachable, gap over 45\u00b0"},
}};

/// The colour of a class and gap.
inline map_colour colour_of(orientation_class c, radians gap) {
  switch (c) {
    case orientation_class::not_on_source: return map_colour::not_on_source;
    case orientation_class::direct: return map_colour::direct;
    case orientation_class::other_branch: return map_colour::other_branch;
    case orientation_class::either_branch: return map_colour::either_branch;
    case orientation_class::unreachable: break;
  }
  const double g = to_degrees(gap).value;
  return g <= 5.0 ? map_colour::gap_5 : (g <= 15.0 ? map_colour::gap_15 : (g <= 45.0 ? map_colour::gap_45 : map_colour::gap_more));
}

/// Lambert projection of a unit vector onto the disc of its hemisphere (upper: z ≥ 0).
struct disc_point {
  bool upper = true;
  double x = 0.0, y = 0.0;  ///< in [−√2, √2]
};

inline disc_point project(const vec3& u, bool upper) {
  const double s = std::sqrt(2.0 / (1.0 + std::abs(u.z)));
  return {upper, s * u.x, s * u.y};
}

/// The unit vector of disc coordinates (X, Y), ρ ≤ √2, on the upper or lower hemisphere.
inline vec3 unproject(double x, double y, bool upper) {
  const double rho2 = x * x + y * y;
  const double s = std::sqrt(std::max(0.0, 1.0 - 0.25 * rho2));
  const double z = 1.0 - 0.5 * rho2;
  return {s * x, s * y, upper ? z : -z};
}

/// A raster of both discs: `cells_across` cells along each disc's diameter.
struct sphere_raster {
  int cells_across = 90;
  /// [disc][row][column], row 0 at the top (+Y); disc 0 upper, 1 lower.
  std::array<std::vector<map_colour>, 2> cells;
  /// Cells per colour over both discs (`outside` not counted).
  std::array<long, map_colour_count> count{};

  map_colour at(int disc, int row, int column) const {
    return cells[disc][static_cast<std::size_t>(row * cells_across + column)];
  }
  /// Share of the sphere per colour (each cell is the same solid angle).
  double share(map_colour c) const {
    long total = 0;
    for (std::size_t i = 1; i < map_colour_count; ++i) total += count[i];
    return total ? static_cast<double>(count[static_cast<std::size_t>(c)]) / static_cast<double>(total) : 0.0;
  }
};

/// Classifies the centre of every cell of both discs.
inline sphere_raster rasterize(const pair_geometry& g, int cells_across = 90) {
  sphere_raster out;
  out.cells_across = cells_across;
  const double span = 2.0 * std::sqrt(2.0), cell = span / cells_across;
  for (int disc = 0; disc < 2; ++disc) {
    out.cells[disc].assign(static_cast<std::size_t>(cells_across * cells_across), map_colour::outside);
    for (int row = 0; row < cells_across; ++row)
      for (int col = 0; col < cells_across; ++col) {
        const double x = -std::sqrt(2.0) + (col + 0.5) * cell, y = std::sqrt(2.0) - (row + 0.5) * cell;
        if (x * x + y * y > 2.0) continue;
        radians gap{};
        const orientation_class c = g.classify_orientation(unproject(x, y, disc == 0), &gap);
        const map_colour m = colour_of(c, gap);
        out.cells[disc][static_cast<std::size_t>(row * cells_across + col)] = m;
        ++out.count[static_cast<std::size_t>(m)];
      }
  }
  return out;
}

/// How a curve on the map is drawn.
enum class curve_style : unsigned char { target_edge, source_branch, source_travel, source_circle };

/// A curve on the sphere, already split by hemisphere into projected polylines.
struct map_curve {
  curve_style style{};
  std::vector<std::vector<disc_point>> pieces;
  std::vector<map_colour> colours;  ///< per piece, for `source_circle` (the class along it)
};

/// The circle of unit vectors at angle θ from unit d, split into runs on each hemisphere (the
/// equator crossing interpolated into both runs). `colour_of_point`, if given, also splits runs
/// where the colour changes.
template <class ColourOf>
map_curve circle_on_map(const vec3& d, double theta, curve_style style, ColourOf colour_of_point, int samples = 720) {
  const vec3 helper = std::abs(d.x) < 0.9 ? unit_x : unit_y;
  const vec3 e1 = normalized(cross(d, helper)), e2 = cross(d, e1);
  auto at = [&](int i) {
    const double phi = 2.0 * pi * i / samples;
    return std::cos(theta) * d + std::sin(theta) * (std::cos(phi) * e1 + std::sin(phi) * e2);
  };
  map_curve out{style, {}, {}};
  std::vector<disc_point> run;
  map_colour run_colour = map_colour::outside;
  auto flush = [&] {
    if (run.size() > 1) out.pieces.push_back(run), out.colours.push_back(run_colour);
    run.clear();
  };
  for (int i = 0; i <= samples; ++i) {
    const vec3 u = at(i);
    const bool upper = u.z >= 0.0;
    const map_colour c = colour_of_point(u);
    if (!run.empty() && (run.back().upper != upper || c != run_colour)) {
      const vec3 prev = at(i - 1);
      vec3 joint = u;
      if (run.back().upper != upper) {  // the equator between prev and u
        const double f = prev.z / (prev.z - u.z);
        joint = normalized(prev + f * (u - prev));
        joint.z = 0.0;
      }
      run.push_back(project(joint, run.back().upper));
      flush();
      run.push_back(project(joint, upper));
    }
    run_colour = c;
    run.push_back(project(u, upper));
  }
  flush();
  return out;
}

/// A marked point: a pole of the source or of the target.
struct map_marker {
  bool source = true;  ///< source pole (else target pole)
  vec3 u{};
};

/// The boundary curves of a pair, where they have a closed form: the target's band edges about
/// Rᵀ p_d, and, about p_s, where the source's branches meet and where its carried axis ends its
/// travel. A one-rotary source holds a single circle, drawn coloured by class.
inline std::vector<map_curve> boundary_curves(const pair_geometry& g) {
  std::vector<map_curve> out;
  auto plain = [](const vec3&) { return map_colour::outside; };
  auto interior = [](double th) { return th > 1e-9 && th < pi - 1e-9; };
  if (g.band_target)
    for (double edge : g.target_band.edges())
      if (interior(edge)) out.push_back(circle_on_map(g.target_axis_in_source, edge, curve_style::target_edge, plain));
  if (!g.band_source) return out;
  const machine_model& from = g.from();
  const vec3 p = from.rotary(0).direction;
  if (from.rotary_count == 1) {
    const double theta = angle_between(p, from.tool_reference()).value;
    out.push_back(circle_on_map(p, theta, curve_style::source_circle, [&](const vec3& u) {
      radians gap{};
      const orientation_class c = g.classify_orientation(u, &gap);
      return colour_of(c == orientation_class::not_on_source ? orientation_class::direct : c, gap);
    }));
  } else {
    const latitude_curve own = carried_curve(from, p);
    const rotary_axis& q = from.rotary(1);
    const commanded_range r = range_of(q);
    auto latitude = [&](double psi) { return math::acos(math::clamp(own.kappa({psi}), -1.0, 1.0)); };
    for (double meet : {own.delta.value, own.delta.value + pi}) {
      const double c = q.psi_per_commanded() * meet;
      const double shifted = c + 2.0 * pi * std::ceil((r.lo - c) / (2.0 * pi) - 1e-12);
      if (shifted <= r.hi + 1e-12 && interior(latitude(meet)))
        out.push_back(circle_on_map(p, latitude(meet), curve_style::source_branch, plain));
    }
    if (!q.travel.continuous)
      for (double end : {r.lo, r.hi})
        if (interior(latitude(q.psi({end}).value)))
          out.push_back(circle_on_map(p, latitude(q.psi({end}).value), curve_style::source_travel, plain));
  }
  return out;
}

/// The poles to mark: ±p_s where the source holds them, ±Rᵀ p_d where the target reaches them.
inline std::vector<map_marker> pole_markers(const pair_geometry& g) {
  std::vector<map_marker> out;
  if (g.from().rotary_count == 2) {
    const vec3 p = g.from().rotary(0).direction;
    for (const vec3& u : {p, -1.0 * p})
      if (g.source_branches(u) != 0) out.push_back({true, u});
  }
  if (g.band_target) {
    if (g.target_band.contains(0.0, 1e-12)) out.push_back({false, g.target_axis_in_source});
    if (g.target_band.contains(pi, 1e-12)) out.push_back({false, -1.0 * g.target_axis_in_source});
  }
  return out;
}

}  // namespace kin5::reach
