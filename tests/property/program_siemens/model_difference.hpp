/// @file model_difference.hpp
/// Field-by-field comparison of two read programs for the Siemens tests and fuzz target.
/// `where` and `text` are ignored, except the text of passthrough blocks (their content).
/// Numbers may differ by `tolerance` (0: exact). Returns the first difference, or "".
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include <kin5/program/block.hpp>

namespace kin5::test::siemens_check {

inline std::string block_difference(const program::block& a, const program::block& b, double tolerance) {
  const auto near = [&](const std::optional<double>& p, const std::optional<double>& q, double t) {
    if (p.has_value() != q.has_value()) return false;
    return !p || std::abs(*p - *q) <= t + 1e-12 * std::abs(*p);
  };
  const auto near_vec = [&](const std::optional<vec3>& p, const std::optional<vec3>& q, double t) {
    if (p.has_value() != q.has_value()) return false;
    return !p || (near(p->x, q->x, t) && near(p->y, q->y, t) && near(p->z, q->z, t));
  };
  const double t = tolerance;
  if (a.passthrough != b.passthrough) return "passthrough";
  if (a.passthrough && a.text != b.text) return "passthrough text";
  if (a.number != b.number) return "number";
  if (a.program_begin != b.program_begin) return "program_begin";
  if (a.program_end != b.program_end) return "program_end";
  if (a.comment != b.comment) return "comment '" + a.comment.value_or("<none>") + "' vs '" + b.comment.value_or("<none>") + "'";
  if (a.tcp != b.tcp) return "tcp";
  if (a.feed_mode != b.feed_mode) return "feed_mode";
  if (a.metric != b.metric) return "metric";
  if (a.tool != b.tool) return "tool";
  if (!near(a.spindle_rpm, b.spindle_rpm, t)) return "spindle_rpm";
  if (a.m_codes != b.m_codes) return "m_codes";
  if (a.motion != b.motion) return "motion";
  if (!near(a.axes.x_mm, b.axes.x_mm, t)) return "x";
  if (!near(a.axes.y_mm, b.axes.y_mm, t)) return "y";
  if (!near(a.axes.z_mm, b.axes.z_mm, t)) return "z";
  if (!near(a.axes.a_deg, b.axes.a_deg, t)) return "a";
  if (!near(a.axes.b_deg, b.axes.b_deg, t)) return "b";
  if (!near(a.axes.c_deg, b.axes.c_deg, t)) return "c";
  if (!near_vec(a.axes.tool_axis, b.axes.tool_axis, t)) return "tool_axis";
  if (a.arc.has_value() != b.arc.has_value()) return "arc";
  if (a.arc) {
    if (a.arc->plane != b.arc->plane) return "arc plane";
    // The centre comes back from a rounded offset added to a rounded start point.
    if (!near_vec(a.arc->centre_mm, b.arc->centre_mm, 2 * t)) return "arc centre";
    if (!near(a.arc->radius_mm, b.arc->radius_mm, t)) return "arc radius";
  }
  if (!near(a.feed, b.feed, t)) return "feed";
  if (a.feed_rapid != b.feed_rapid) return "feed_rapid";
  if (a.machine_coordinates != b.machine_coordinates) return "machine_coordinates";
  if (a.kept_words != b.kept_words) return "kept_words";
  return {};
}

inline std::string program_difference(const program::program& a, const program::program& b, double tolerance = 0) {
  if (a.blocks.size() != b.blocks.size())
    return "block count " + std::to_string(a.blocks.size()) + " vs " + std::to_string(b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    const std::string d = block_difference(a.blocks[i], b.blocks[i], tolerance);
    if (!d.empty()) return "block " + std::to_string(i + 1) + " ('" + a.blocks[i].text + "' / '" + b.blocks[i].text + "'): " + d;
  }
  return {};
}

}  // namespace kin5::test::siemens_check
