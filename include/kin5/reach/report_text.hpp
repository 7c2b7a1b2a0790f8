/// @file reach/report_text.hpp
/// A program's report (`program_report.hpp`) and its setup search (`setup_search.hpp`) as
/// Markdown, CSV or JSON, and the setup as the `--setup-rotation` option `kin5 translate` reads.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "program_report.hpp"
#include "setup_search.hpp"
#include "table_text.hpp"

namespace kin5::reach {

/// R as the nine numbers of `--setup-rotation`, row by row: exact integers for an axis-aligned
/// rotation, 15 significant digits otherwise (R Rᵀ = I well within the 1e-9 translate checks).
inline std::string rotation_option(const mat3& r) {
  std::string out;
  for (const auto& row : r.row)
    for (double v : {row.x, row.y, row.z}) {
      char buf[40];
      const double rounded = std::round(v);
      std::snprintf(buf, sizeof buf, "%.15g", std::abs(v - rounded) < 1e-12 ? rounded + 0.0 : v);
      if (!out.empty()) out += ',';
      out += buf;
    }
  return out;
}

/// The angle (degrees) and unit axis of rotation R.
inline std::pair<double, vec3> axis_angle(const mat3& r) {
  const double c = std::clamp((r.row[0].x + r.row[1].y + r.row[2].z - 1.0) / 2.0, -1.0, 1.0);
  const double angle = std::acos(c);
  vec3 axis{r.row[2].y - r.row[1].z, r.row[0].z - r.row[2].x, r.row[1].x - r.row[0].y};
  if (norm(axis) < 1e-6) {  // 0° or 180°: the axis is the largest column of R + I
    const mat3 s{{r.row[0] + unit_x, r.row[1] + unit_y, r.row[2] + unit_z}};
    axis = s.column(0);
    for (int j = 1; j < 3; ++j)
      if (norm(s.column(j)) > norm(axis)) axis = s.column(j);
  }
  if (norm(axis) < 1e-12) axis = unit_z;
  return {angle * 180.0 / pi, normalized(axis)};
}

/// "a turn of 90° about (1, 0, 0)".
inline std::string turn_text(const mat3& r) {
  const auto [angle, axis] = axis_angle(r);
  using text_detail::fixed;
  if (angle < 1e-9) return "no turn (the identity)";
  return "a turn of " + fixed(angle, 3) + "\u00b0 about (" + fixed(axis.x, 4) + ", " + fixed(axis.y, 4) + ", " +
         fixed(axis.z, 4) + ")";
}

/// A number as `kin5 translate` reads it back exactly enough: 15 significant digits.
inline std::string option_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", v + 0.0);
  return buf;
}

/// The command that translates with setup rotation `rotation` instead of the pair's default;
/// with the work offset given (`r.placed`), also the setup offset `offset_mm` and the tool
/// length and work offset, so that `translate` checks the slides against the linear travel.
inline std::string translate_command(const program_report& r, const mat3& rotation, const vec3& offset_mm = {}) {
  std::string o = "kin5 translate --from " + r.from + " --to " + r.to + " --setup-rotation " + rotation_option(rotation);
  auto triple = [](const vec3& v) { return option_number(v.x) + "," + option_number(v.y) + "," + option_number(v.z); };
  if (r.placed) {
    o += " --setup-offset " + triple(offset_mm);
    if (r.target_inputs.tool_length_mm != 0.0) o += " --tool-length " + option_number(r.target_inputs.tool_length_mm);
    o += " --work-offset " + triple(r.target_inputs.work_offset.translation_mm);
  }
  if (!r.work_offset_map_option.empty()) o += " --work-offset-map " + r.work_offset_map_option;
  for (const std::string& entry : r.tool_map_options) o += " --tool-map " + entry;
  return o + " " + (r.file.empty() ? "-" : r.file);
}

inline std::string report_markdown(const program_report& r, const std::optional<setup_search_result>& search,
                                   const std::optional<chosen_setup>& chosen) {
  using text_detail::deg;
  using text_detail::fixed;
  std::string o = "# " + r.from + " \u2192 " + r.to + ": " + r.file + "\n\n";
  o += "Setup: " + std::string(r.default_setup ? "the pair's default, " : "") + turn_text(r.setup.rotation) + ".\n\n";
  o += "| class | motion blocks |\n|---|---|\n| direct | " + std::to_string(r.per_class[0]) + " |\n| other branch | " +
       std::to_string(r.per_class[1]) + " |\n| unreachable | " + std::to_string(r.per_class[2]) + " |\n\n";
  if (!r.unreachable.empty()) {
    o += "Unreachable blocks:\n\n| lines | blocks | worst gap (deg) |\n|---|---|---|\n";
    for (const auto& u : r.unreachable)
      o += "| " + std::to_string(u.first_line) + (u.last_line != u.first_line ? "\u2013" + std::to_string(u.last_line) : "") +
           " | " + std::to_string(u.blocks) + " | " + deg(u.worst_gap_rad, 3) + " |\n";
    o += "\n";
  }
  o += "Rotary travel on " + r.to + " (reachable blocks, as the translator plans them):\n\n";
  o += "| axis | from (deg) | to (deg) | travel of the axis |\n|---|---|---|---|\n";
  for (const auto& s : r.rotary)
    o += "| " + std::string(1, s.letter) + " | " + fixed(s.lo_deg, 3) + " | " + fixed(s.hi_deg, 3) + " | " +
         (s.bounded ? "[" + fixed(s.travel_lo_deg, 0) + ", " + fixed(s.travel_hi_deg, 0) + "]" +
                          (s.lo_deg < s.travel_lo_deg - 1e-6 || s.hi_deg > s.travel_hi_deg + 1e-6 ? " exceeded" : "")
                    : std::string("endless")) + " |\n";
  o += "\nTotal rotary movement: " + deg(r.rotary_travel_rad, 3) + "\u00b0.\n\n";
  if (r.has_tips)
    o += "Tool tips in the " + r.to + " workpiece frame: X [" + fixed(r.tip_lo_mm.x, 3) + ", " + fixed(r.tip_hi_mm.x, 3) +
         "], Y [" + fixed(r.tip_lo_mm.y, 3) + ", " + fixed(r.tip_hi_mm.y, 3) + "], Z [" + fixed(r.tip_lo_mm.z, 3) + ", " +
         fixed(r.tip_hi_mm.z, 3) + "] mm: a stroke of " + fixed(r.tip_hi_mm.x - r.tip_lo_mm.x, 3) + " \u00d7 " +
         fixed(r.tip_hi_mm.y - r.tip_lo_mm.y, 3) + " \u00d7 " + fixed(r.tip_hi_mm.z - r.tip_lo_mm.z, 3) + " mm.\n\n";
  if (!r.linear.empty()) {
    const vec3 w = r.target_inputs.work_offset.translation_mm;
    o += "Linear travel on " + r.to + " (reachable blocks, slides (G7) with the planned angles; tool length " +
         fixed(r.target_inputs.tool_length_mm, 3) + " mm, work offset (" + fixed(w.x, 3) + ", " + fixed(w.y, 3) + ", " +
         fixed(w.z, 3) + ") mm" + (r.placed ? "" : ", the workpiece origin at the machine's origin: only the strokes are checked") +
         "):\n\n| axis | from (mm) | to (mm) | stroke (mm) | travel of the axis (mm) |\n|---|---|---|---|---|\n";
    for (const auto& s : r.linear)
      o += "| " + std::string(1, s.letter) + " | " + fixed(s.lo_mm, 3) + " | " + fixed(s.hi_mm, 3) + " | " +
           fixed(s.hi_mm - s.lo_mm, 3) + " of " + fixed(s.travel_hi_mm - s.travel_lo_mm, 3) + " | [" + fixed(s.travel_lo_mm, 3) +
           ", " + fixed(s.travel_hi_mm, 3) + "]" + (s.exceeded() ? " exceeded" : "") + " |\n";
    o += "\n";
  }
  if (!r.other_errors.empty())
    o += std::to_string(r.other_errors.size()) + " other errors stop a translation; `kin5 translate` lists them.\n\n";
  if (!search) return o;
  o += "## Setup search\n\n" + std::to_string(search->tried.size() - search->refined) +
       " rotations tried (the current setup and the axis-aligned ones), " + std::to_string(search->refined) +
       " refined with Ipopt; " + std::to_string(search->ranked.size()) + " reach every block.\n\n";
  if (search->ranked.empty())
    return o + "No rotation reaches every block: the tool axes do not fit in the target's reach however the part is "
               "turned. The closest, " + turn_text(search->closest.rotation) + ", leaves " +
           std::to_string(search->closest.unreachable) + " unreachable (worst gap " + deg(search->closest.worst_gap_rad, 3) +
           "\u00b0).\n";
  if (!chosen)
    return o + "None of the " + std::to_string(search->ranked.size()) +
           " translates the whole program within the target's travel: with each, the program has constructs the "
           "turned setup cannot carry, or " +
           (r.placed ? "no place of the part on the table keeps every slide within its travel"
                     : "a stroke is longer than its axis' travel") +
           ". `kin5 translate` with the one of least travel says which:\n\n```\n" +
           translate_command(r, search->ranked.front().rotation, r.setup.translation_mm) + "\n```\n";
  const auto& b = chosen->candidate;
  const auto& w = chosen->report;
  o += "Best: " + turn_text(b.rotation) + (b.axis_aligned ? " (axis-aligned)" : " (refined)") +
       "; total rotary movement " + deg(b.travel_rad, 3) + "\u00b0";
  if (r.placed) {
    const vec3 d = chosen->offset_mm - r.setup.translation_mm;
    o += chosen->offset_moved ? "; the part moved by (" + fixed(d.x, 3) + ", " + fixed(d.y, 3) + ", " + fixed(d.z, 3) +
                                    ") mm, the least move that keeps every slide " + fixed(offset_margin_mm, 2) +
                                    " mm within its travel"
                              : "; every slide within its travel where the part is";
  }
  o += ". Translated with it: " + std::to_string(w.per_class[0]) + " direct, " + std::to_string(w.per_class[1]) +
       " other branch, " + std::to_string(w.per_class[2]) + " unreachable";
  o += chosen->passed_over ? "; " + std::to_string(chosen->passed_over) +
                                 " rotations of less travel were passed over, as the program does not translate with "
                                 "them (" + chosen->first_reason + ").\n\n"
                           : ".\n\n";
  if (r.placed && !w.linear.empty()) {
    o += "Slides with it:";
    for (const auto& s : w.linear)
      o += std::string(s.letter == w.linear.front().letter ? " " : ", ") + s.letter + " [" + fixed(s.lo_mm, 3) + ", " +
           fixed(s.hi_mm, 3) + "]";
    o += " mm.\n\n";
  }
  o += "```\n" + translate_command(r, b.rotation, chosen->offset_mm) + "\n```\n";
  return o;
}

/// One line per run of unreachable blocks.
inline std::string report_csv(const program_report& r) {
  std::string o = "file,first_line,last_line,blocks,worst_gap_deg\n";
  for (const auto& u : r.unreachable)
    o += r.file + "," + std::to_string(u.first_line) + "," + std::to_string(u.last_line) + "," +
         std::to_string(u.blocks) + "," + text_detail::deg(u.worst_gap_rad) + "\n";
  return o;
}

inline std::string report_json(const program_report& r, const std::optional<chosen_setup>& chosen) {
  using text_detail::deg;
  using text_detail::fixed;
  std::string o = "{\"file\": \"" + r.file + "\", \"source\": \"" + r.from + "\", \"target\": \"" + r.to +
                  "\",\n \"per_class\": {\"direct\": " + std::to_string(r.per_class[0]) + ", \"other_branch\": " +
                  std::to_string(r.per_class[1]) + ", \"unreachable\": " + std::to_string(r.per_class[2]) +
                  "},\n \"unreachable\": [";
  for (std::size_t i = 0; i < r.unreachable.size(); ++i) {
    const auto& u = r.unreachable[i];
    o += std::string(i ? ", " : "") + "{\"first_line\": " + std::to_string(u.first_line) + ", \"last_line\": " +
         std::to_string(u.last_line) + ", \"blocks\": " + std::to_string(u.blocks) + ", \"worst_gap_deg\": " +
         deg(u.worst_gap_rad) + "}";
  }
  o += "],\n \"rotary\": [";
  for (std::size_t i = 0; i < r.rotary.size(); ++i) {
    const auto& s = r.rotary[i];
    o += std::string(i ? ", " : "") + "{\"axis\": \"" + std::string(1, s.letter) + "\", \"from_deg\": " + fixed(s.lo_deg, 6) +
         ", \"to_deg\": " + fixed(s.hi_deg, 6) + "}";
  }
  o += "], \"rotary_travel_deg\": " + deg(r.rotary_travel_rad) + ",\n \"linear\": [";
  for (std::size_t i = 0; i < r.linear.size(); ++i) {
    const auto& s = r.linear[i];
    o += std::string(i ? ", " : "") + "{\"axis\": \"" + std::string(1, s.letter) + "\", \"from_mm\": " + fixed(s.lo_mm, 6) +
         ", \"to_mm\": " + fixed(s.hi_mm, 6) + ", \"travel_from_mm\": " + fixed(s.travel_lo_mm, 6) +
         ", \"travel_to_mm\": " + fixed(s.travel_hi_mm, 6) + ", \"exceeded\": " + (s.exceeded() ? "true" : "false") + "}";
  }
  o += "]";
  if (chosen)
    o += ",\n \"setup\": {\"rotation\": [" + rotation_option(chosen->candidate.rotation) + "], \"offset_mm\": [" +
         option_number(chosen->offset_mm.x) + ", " + option_number(chosen->offset_mm.y) + ", " +
         option_number(chosen->offset_mm.z) + "], \"axis_aligned\": " +
         (chosen->candidate.axis_aligned ? "true" : "false") + ", \"rotary_travel_deg\": " +
         deg(chosen->candidate.travel_rad) + "}";
  else if (!r.unreachable.empty() || (r.placed && r.linear_exceeded()))
    o += ",\n \"setup\": null";
  return o + "}\n";
}

}  // namespace kin5::reach
