/// @file reach/sphere_svg.hpp
/// Writes a pair's sphere map (`sphere_map.hpp`) as a standalone SVG: the two discs, the
/// boundary curves, the pole markers and a legend that always lists every colour. Cells are
/// merged into one path per colour (a rectangle per run of equal cells in a row) and drawn with
/// crisp edges, so each class keeps its exact colour on screen; the cells the rim cuts are
/// painted as their inner neighbour and clipped to the disc, which leaves no white at the rim. The text is the same bytes on
/// every run: fixed formatting, nothing that depends on time or locale.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "sphere_map.hpp"

namespace kin5::reach {

/// The words on a map.
struct map_text {
  std::string title;      ///< e.g. "sajo-12000p → dmu-80p"
  std::string subtitle;   ///< frame, projection, setup
  std::vector<std::string> notes;  ///< lines under the legend
};

namespace svg_detail {

inline constexpr double disc_radius_px = 150.0;
inline constexpr double disc_y_px = 250.0;
inline constexpr std::array<double, 2> disc_x_px{185.0, 525.0};
inline constexpr double width_px = 1040.0, height_px = 470.0;

inline std::string num(double v, int decimals = 1) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  return s.find_first_not_of("-0.") == std::string::npos ? s.substr(s[0] == '-' ? 1 : 0) : s;
}

/// Pixel position of a disc point.
inline std::array<double, 2> to_px(const disc_point& p) {
  const double k = disc_radius_px / std::sqrt(2.0);
  return {disc_x_px[p.upper ? 0 : 1] + k * p.x, disc_y_px - k * p.y};
}

inline std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

/// The colour to paint cell (row, col) of `disc`: its class; for a cell whose centre is off the
/// disc but which overlaps it, the class of its neighbour nearest the disc's centre, so that the
/// clipped cells fill the disc up to its rim.
inline map_colour paint_of(const sphere_raster& r, int disc, int row, int col) {
  const map_colour own = r.at(disc, row, col);
  const double n = r.cells_across, half = n / 2.0;
  if (own != map_colour::outside) return own;
  const double dx = std::max(0.0, std::abs(col + 0.5 - half) - 0.5), dy = std::max(0.0, std::abs(row + 0.5 - half) - 0.5);
  if (dx * dx + dy * dy >= half * half) return own;
  map_colour best = own;
  double best_d = 1e300;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j) {
      const int rr = row + i, cc = col + j;
      if (rr < 0 || cc < 0 || rr >= r.cells_across || cc >= r.cells_across || r.at(disc, rr, cc) == map_colour::outside)
        continue;
      const double d = std::hypot(cc + 0.5 - half, rr + 0.5 - half);
      if (d < best_d) best_d = d, best = r.at(disc, rr, cc);
    }
  return best;
}

inline void cells(std::string& out, const sphere_raster& r) {
  const double cell = 2.0 * disc_radius_px / r.cells_across;
  for (int disc = 0; disc < 2; ++disc) {
    const std::string id = "disc" + std::to_string(disc);
    out += "<clipPath id=\"" + id + "\"><circle cx=\"" + num(disc_x_px[disc]) + "\" cy=\"" + num(disc_y_px) + "\" r=\"" +
           num(disc_radius_px) + "\"/></clipPath>\n<g clip-path=\"url(#" + id + ")\">\n";
    out += "<g shape-rendering=\"crispEdges\" transform=\"translate(" + num(disc_x_px[disc] - disc_radius_px) + " " +
           num(disc_y_px - disc_radius_px) + ") scale(" + num(cell, 6) + ")\">\n";
    for (std::size_t c = 1; c < map_colour_count; ++c) {
      std::string d;
      auto is_c = [&](int row, int col) { return static_cast<std::size_t>(paint_of(r, disc, row, col)) == c; };
      for (int row = 0; row < r.cells_across; ++row)
        for (int col = 0; col < r.cells_across;) {
          if (!is_c(row, col)) { ++col; continue; }
          int end = col;
          while (end < r.cells_across && is_c(row, end)) ++end;
          const std::string run = std::to_string(end - col);
          d += 'M';
          d += std::to_string(col);
          d += ' ';
          d += std::to_string(row);
          d += 'h';
          d += run;
          d += "v1h-";
          d += run;
          d += 'z';
          col = end;
        }
      if (!d.empty()) out += std::string("<path fill=\"") + map_palette[c].fill + "\" d=\"" + d + "\"/>\n";
    }
    out += "</g>\n</g>\n";
  }
}

inline const char* stroke_of(curve_style s) {
  switch (s) {
    case curve_style::target_edge: return "stroke=\"#000000\" stroke-width=\"1.8\"";
    case curve_style::source_branch: return "stroke=\"#000000\" stroke-width=\"1.3\" stroke-dasharray=\"7 4\"";
    case curve_style::source_travel: return "stroke=\"#000000\" stroke-width=\"1.3\" stroke-dasharray=\"2 3\"";
    case curve_style::source_circle: return "stroke-width=\"3\"";
  }
  return "";
}

inline void curves(std::string& out, const std::vector<map_curve>& cs) {
  for (const auto& c : cs)
    for (std::size_t i = 0; i < c.pieces.size(); ++i) {
      std::string pts;
      for (const auto& p : c.pieces[i]) {
        const auto px = to_px(p);
        if (!pts.empty()) pts += ' ';
        pts += num(px[0]);
        pts += ',';
        pts += num(px[1]);
      }
      std::string colour;
      if (c.style == curve_style::source_circle)
        colour = std::string(" stroke=\"") + map_palette[static_cast<std::size_t>(c.colours[i])].fill + "\"";
      out += std::string("<polyline fill=\"none\" ") + stroke_of(c.style) + colour + " points=\"" + pts + "\"/>\n";
    }
}

inline void marker(std::string& out, bool source, double x, double y) {
  if (source)
    out += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"6\" fill=\"#ffffff\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
  else
    out += "<path d=\"M" + num(x) + " " + num(y - 4.5) + "l4.5 4.5l-4.5 4.5l-4.5 -4.5z\" fill=\"#000000\"/>\n";
}

inline void markers(std::string& out, const std::vector<map_marker>& ms) {
  for (const auto& m : ms)
    for (bool upper : {true, false}) {
      if ((upper && m.u.z < -1e-12) || (!upper && m.u.z > 1e-12)) continue;
      const auto px = to_px(project(m.u, upper));
      marker(out, m.source, px[0], px[1]);
    }
}

/// Dots for tool axes; an axis on the equator shows on both discs. Repeated dots are drawn once.
inline void points(std::string& out, const std::vector<vec3>& us) {
  std::vector<std::string> seen;
  for (const vec3& u : us)
    for (bool upper : {true, false}) {
      if ((upper && u.z < -1e-12) || (!upper && u.z > 1e-12)) continue;
      const auto px = to_px(project(normalized(u), upper));
      std::string dot = "<circle cx=\"" + num(px[0]) + "\" cy=\"" + num(px[1]) +
                        "\" r=\"2.5\" fill=\"#000000\" stroke=\"#ffffff\" stroke-width=\"0.8\"/>\n";
      if (std::find(seen.begin(), seen.end(), dot) != seen.end()) continue;
      seen.push_back(dot);
      out += dot;
    }
}

inline void frame(std::string& out) {
  const char* names[2] = {"k \u2265 0 (about +Z)", "k \u2264 0 (about \u2212Z, seen from +Z)"};
  for (int disc = 0; disc < 2; ++disc) {
    const double cx = disc_x_px[disc], cy = disc_y_px, r = disc_radius_px;
    for (double polar : {30.0, 60.0}) {  // graticule: 30° and 60° from the disc's centre
      const double rr = r * std::sqrt(2.0) * std::sin(polar * pi / 360.0);
      out += "<circle cx=\"" + num(cx) + "\" cy=\"" + num(cy) + "\" r=\"" + num(rr) +
             "\" fill=\"none\" stroke=\"#888888\" stroke-width=\"0.6\" stroke-dasharray=\"1 3\"/>\n";
    }
    out += "<circle cx=\"" + num(cx) + "\" cy=\"" + num(cy) + "\" r=\"" + num(r) +
           "\" fill=\"none\" stroke=\"#444444\" stroke-width=\"1\"/>\n";
    out += "<text x=\"" + num(cx + r + 4) + "\" y=\"" + num(cy + 4) + "\">+X</text>\n";
    out += "<text x=\"" + num(cx - 8) + "\" y=\"" + num(cy - r - 6) + "\">+Y</text>\n";
    out += "<text x=\"" + num(cx) + "\" y=\"" + num(cy + r + 22) + "\" text-anchor=\"middle\">" + names[disc] + "</text>\n";
  }
}

inline void legend(std::string& out, const map_text& text) {
  double y = 78.0;
  const double x = 715.0;
  for (std::size_t c = 2; c < map_colour_count + 1; ++c) {  // classes, then "not held"
    const std::size_t i = c == map_colour_count ? 1 : c;
    out += "<rect x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"22\" height=\"14\" fill=\"" + map_palette[i].fill +
           "\" stroke=\"#444444\" stroke-width=\"0.5\"/>\n";
    out += "<text x=\"" + num(x + 30) + "\" y=\"" + num(y + 11) + "\">" + map_palette[i].label + "</text>\n";
    y += 21.0;
  }
  const char* lines[3][2] = {{"target reach edge", "target_edge"},
                             {"source branches meet", "source_branch"},
                             {"source travel end", "source_travel"}};
  const curve_style styles[3] = {curve_style::target_edge, curve_style::source_branch, curve_style::source_travel};
  for (int i = 0; i < 3; ++i) {
    out += std::string("<line x1=\"") + num(x) + "\" y1=\"" + num(y + 7) + "\" x2=\"" + num(x + 22) + "\" y2=\"" +
           num(y + 7) + "\" " + stroke_of(styles[i]) + "/>\n";
    out += "<text x=\"" + num(x + 30) + "\" y=\"" + num(y + 11) + "\">" + lines[i][0] + "</text>\n";
    y += 21.0;
  }
  marker(out, true, x + 11, y + 7);
  out += "<text x=\"" + num(x + 30) + "\" y=\"" + num(y + 11) + "\">source pole (S2)</text>\n";
  y += 21.0;
  marker(out, false, x + 11, y + 7);
  out += "<text x=\"" + num(x + 30) + "\" y=\"" + num(y + 11) + "\">target pole (S2)</text>\n";
  y += 30.0;
  for (const auto& note : text.notes) {
    out += "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" font-size=\"11\">" + escape(note) + "</text>\n";
    y += 16.0;
  }
}

}  // namespace svg_detail

/// The SVG document of a map; `points`, if any, are drawn as dots (a program's tool axes).
inline std::string sphere_svg(const sphere_raster& raster, const std::vector<map_curve>& curves,
                              const std::vector<map_marker>& markers, const map_text& text,
                              const std::vector<vec3>& points = {}) {
  using namespace svg_detail;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width_px) + "\" height=\"" + num(height_px) +
         "\" viewBox=\"0 0 " + num(width_px) + " " + num(height_px) +
         "\" font-family=\"DejaVu Sans, Verdana, sans-serif\" font-size=\"12\">\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  out += "<text x=\"20\" y=\"30\" font-size=\"19\" font-weight=\"bold\">" + escape(text.title) + "</text>\n";
  out += "<text x=\"20\" y=\"52\">" + escape(text.subtitle) + "</text>\n";
  cells(out, raster);
  frame(out);
  svg_detail::curves(out, curves);
  svg_detail::markers(out, markers);
  svg_detail::points(out, points);
  legend(out, text);
  out += "</svg>\n";
  return out;
}

}  // namespace kin5::reach
