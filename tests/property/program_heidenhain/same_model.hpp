/// @file same_model.hpp
/// Exact comparison of two Heidenhain readings, block by block, ignoring `where` and `text`
/// (a passthrough block's text is compared without its block number: that is its content).
/// Block numbers are compared only when asked: the writer renumbers from 0.
#pragma once

#include <string>

#include <kin5/program/block.hpp>
#include <kin5/program/text.hpp>

namespace kin5::test {

/// A passthrough block's text without the leading block number.
inline std::string heidenhain_body(const std::string& text) {
  using kin5::program::is_digit;
  using kin5::program::is_space;
  std::size_t k = 0;
  while (k < text.size() && is_space(text[k])) ++k;
  std::size_t d = k;
  while (d < text.size() && is_digit(text[d])) ++d;
  if (d > k)
    while (d < text.size() && is_space(text[d])) ++d;
  else
    d = k;
  return text.substr(d);
}

/// "" when the blocks hold the same model, else the first field that differs.
inline std::string heidenhain_block_difference(const program::block& a, const program::block& b, bool numbers) {
  if (numbers && a.number != b.number) return "number";
  if (a.program_begin != b.program_begin) return "program_begin";
  if (a.program_end != b.program_end) return "program_end";
  if (a.comment != b.comment) return "comment '" + a.comment.value_or("<none>") + "' vs '" + b.comment.value_or("<none>") + "'";
  if (a.tcp != b.tcp) return "tcp";
  if (a.feed_mode != b.feed_mode) return "feed_mode";
  if (a.metric != b.metric) return "metric";
  if (a.tool != b.tool) return "tool";
  if (a.spindle_rpm != b.spindle_rpm) return "spindle_rpm";
  if (a.m_codes != b.m_codes) return "m_codes";
  if (a.motion != b.motion) return "motion";
  if (a.axes.x_mm != b.axes.x_mm || a.axes.y_mm != b.axes.y_mm || a.axes.z_mm != b.axes.z_mm) return "linear axes";
  if (a.axes.a_deg != b.axes.a_deg || a.axes.b_deg != b.axes.b_deg || a.axes.c_deg != b.axes.c_deg) return "rotary axes";
  if (a.axes.tool_axis != b.axes.tool_axis) return "tool_axis";
  if (a.arc.has_value() != b.arc.has_value()) return "arc presence";
  if (a.arc) {
    if (a.arc->plane != b.arc->plane) return "arc plane";
    if (a.arc->centre_mm != b.arc->centre_mm) return "arc centre";
    if (a.arc->radius_mm != b.arc->radius_mm) return "arc radius";
  }
  if (a.feed != b.feed) return "feed";
  if (a.feed_rapid != b.feed_rapid) return "feed_rapid";
  if (a.machine_coordinates != b.machine_coordinates) return "machine_coordinates";
  if (a.kept_words != b.kept_words) return "kept_words";
  if (a.passthrough != b.passthrough) return "passthrough";
  if (a.passthrough && heidenhain_body(a.text) != heidenhain_body(b.text))
    return "passthrough text '" + a.text + "' vs '" + b.text + "'";
  return {};
}

/// "" when `a` and `b` hold the same blocks, else which block and field differ.
inline std::string heidenhain_difference(const program::program& a, const program::program& b, bool numbers) {
  if (a.blocks.size() != b.blocks.size())
    return "block count " + std::to_string(a.blocks.size()) + " vs " + std::to_string(b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    const std::string d = heidenhain_block_difference(a.blocks[i], b.blocks[i], numbers);
    if (!d.empty())
      return "block " + std::to_string(i + 1) + " ('" + a.blocks[i].text + "' vs '" + b.blocks[i].text + "'): " + d;
  }
  return {};
}

}  // namespace kin5::test
