/// @file model_difference.hpp
/// The one comparison of two program models for the dialect laws and the fuzz targets: field by
/// field, ignoring where each block came from and its source text, except the text of a
/// passthrough block (its content). Returns the first difference in words, or "" when none.
///
/// `comparison` says how strict: numbers within `tolerance` (plus `relative` × the value, for
/// the last bit of a decimal read back), block numbers compared or not (a writer that numbers
/// blocks itself), source locations and text compared or not (a generator that knows them).
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include <kin5/program/block.hpp>
#include <kin5/program/text.hpp>

namespace kin5::test {

/// How two models must agree (see the file comment).
struct comparison {
  double tolerance = 0;      ///< absolute, in the value's unit (mm, degrees, mm/min, 1/min)
  double relative = 1e-12;   ///< times |value|, added to `tolerance`
  bool block_numbers = true; ///< compare N / Heidenhain block numbers
  bool locations = false;    ///< compare each block's `where` and `text`
  /// The second model was written by a writer that frames every program (Heidenhain: BEGIN PGM
  /// first, END PGM last): an opening first block or closing last block the first model lacks
  /// is not a difference.
  bool framed = false;
};

namespace detail {

/// A passthrough block's text without a leading block number (Heidenhain's `12 `): its content
/// once a writer has renumbered the blocks.
inline std::string_view without_block_number(std::string_view text) {
  std::size_t k = 0;  // lines of blanks and `~` before the number go with it (`  ~\n14 Q1=2`)
  for (std::size_t e = 0;; k = ++e) {
    while (e < text.size() && (program::is_space(text[e]) || text[e] == '~')) ++e;
    if (e >= text.size() || text[e] != '\n') break;
  }
  while (k < text.size() && program::is_space(text[k])) ++k;
  std::size_t d = k;
  while (d < text.size() && program::is_digit(text[d])) ++d;
  if (d == k) {
    k = 0;
    while (k < text.size() && program::is_space(text[k])) ++k;
    return text.substr(k);
  }
  while (d < text.size() && program::is_space(text[d])) ++d;
  return text.substr(d);
}

struct number_check {
  comparison c;
  bool operator()(const std::optional<double>& p, const std::optional<double>& q, double scale = 1) const {
    if (p.has_value() != q.has_value()) return false;
    return !p || std::abs(*p - *q) <= scale * c.tolerance * (1.0 + 1e-9) + c.relative * std::abs(*p);
  }
  bool operator()(const std::optional<vec3>& p, const std::optional<vec3>& q, double scale = 1) const {
    if (p.has_value() != q.has_value()) return false;
    return !p || ((*this)(p->x, q->x, scale) && (*this)(p->y, q->y, scale) && (*this)(p->z, q->z, scale));
  }
};

/// The first difference in what a block says about the program (no motion), or "".
inline std::string header_difference(const program::block& a, const program::block& b, const comparison& c) {
  const number_check near{c};
  if (c.block_numbers && a.number != b.number) return "number";
  if (a.program_begin != b.program_begin) return "program_begin";
  if (a.program_end != b.program_end) return "program_end";
  if (a.comment != b.comment) return "comment '" + a.comment.value_or("<none>") + "' vs '" + b.comment.value_or("<none>") + "'";
  if (a.tcp != b.tcp) return "tcp";
  if (a.feed_mode != b.feed_mode) return "feed_mode";
  if (a.metric != b.metric) return "metric";
  if (a.tool != b.tool) return "tool";
  if (a.tool_name != b.tool_name) return "tool_name";
  if (!near(a.spindle_rpm, b.spindle_rpm)) return "spindle_rpm";
  if (a.m_codes != b.m_codes) return "m_codes";
  if (a.state != b.state) return "state";
  if (a.alarm != b.alarm) return "alarm";
  return {};
}

/// The first difference in what a block says about motion, or "".
inline std::string motion_difference(const program::block& a, const program::block& b, const comparison& c) {
  const number_check near{c};
  if (a.motion != b.motion) return "motion";
  if (!near(a.axes.x_mm, b.axes.x_mm)) return "x";
  if (!near(a.axes.y_mm, b.axes.y_mm)) return "y";
  if (!near(a.axes.z_mm, b.axes.z_mm)) return "z";
  if (!near(a.axes.a_deg, b.axes.a_deg)) return "a";
  if (!near(a.axes.b_deg, b.axes.b_deg)) return "b";
  if (!near(a.axes.c_deg, b.axes.c_deg)) return "c";
  if (!near(a.axes.tool_axis, b.axes.tool_axis)) return "tool_axis";
  if (a.arc.has_value() != b.arc.has_value()) return "arc presence";
  if (a.arc) {
    if (a.arc->plane != b.arc->plane) return "arc plane";
    // A centre is rebuilt from a rounded offset and a rounded start point: allow both roundings.
    if (!near(a.arc->centre_mm, b.arc->centre_mm, 2)) return "arc centre";
    if (!near(a.arc->radius_mm, b.arc->radius_mm)) return "arc radius";
  }
  if (!near(a.feed, b.feed)) return "feed";
  if (a.feed_rapid != b.feed_rapid) return "feed_rapid";
  if (a.machine_coordinates != b.machine_coordinates) return "machine_coordinates";
  return {};
}

}  // namespace detail

/// "" when blocks `a` and `b` say the same under `c`, else the first field that differs.
inline std::string block_difference(const program::block& a, const program::block& b, const comparison& c = {}) {
  if (std::string d = detail::header_difference(a, b, c); !d.empty()) return d;
  if (std::string d = detail::motion_difference(a, b, c); !d.empty()) return d;
  if (a.kept_words != b.kept_words) return "kept_words";
  if (a.passthrough != b.passthrough) return "passthrough";
  const bool whole_text = c.locations || c.block_numbers;
  if (a.passthrough && (whole_text ? a.text != b.text
                                   : detail::without_block_number(a.text) != detail::without_block_number(b.text)))
    return "passthrough text '" + a.text + "' vs '" + b.text + "'";
  if (c.locations && !(a.where == b.where)) return "where";
  if (c.locations && a.text != b.text) return "text '" + a.text + "' vs '" + b.text + "'";
  return {};
}

/// "" when `a` and `b` hold the same blocks under `c`, else which block and field differ.
inline std::string model_difference(const program::program& a, const program::program& b, const comparison& c = {}) {
  std::size_t first = 0, end = b.blocks.size();  // b's blocks to compare
  if (c.framed) {
    const auto& ab = a.blocks;
    if (end > 0 && b.blocks[0].program_begin && (ab.empty() || !ab[0].program_begin)) ++first;
    if (end > first && b.blocks[end - 1].program_end && (ab.empty() || !ab.back().program_end)) --end;
  }
  if (a.blocks.size() != end - first)
    return "block count " + std::to_string(a.blocks.size()) + " vs " + std::to_string(end - first);
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    const program::block& bb = b.blocks[first + i];
    const std::string d = block_difference(a.blocks[i], bb, c);
    if (!d.empty()) return "block " + std::to_string(i + 1) + " ('" + a.blocks[i].text + "' vs '" + bb.text + "'): " + d;
  }
  return {};
}

}  // namespace kin5::test
