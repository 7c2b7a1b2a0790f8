/// @file reach/program_report.hpp
/// What a target machine makes of one program: its motion blocks per class, the unreachable
/// ones as runs of lines with their worst gap, the rotary travel the target needs (the
/// translator's own branch plan), the tool-tip range in the target's workpiece frame, and the
/// slide values (G7) each reachable block needs against the target's linear travel.
/// Classes and gaps come from `translate` itself, so the report and a translation never
/// disagree; the tool axes come from `reverse` (one per motion block written as a GOTO).
/// @code
///   const auto r = kin5::reach::make_program_report(from, to, nc, kin5::default_setup(from.geometry.id, to.geometry.id), true);
///   std::cout << kin5::reach::report_markdown(r);
/// @endcode
#pragma once

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "../kinematics/branch_plan.hpp"
#include "../kinematics/inverse_pose.hpp"
#include "../translate/translate.hpp"
#include "pair_geometry.hpp"
#include "setup_offset.hpp"
#include "setup_search.hpp"

namespace kin5::reach {

/// Consecutive unreachable motion blocks (no reachable motion block between them).
struct unreachable_run {
  std::size_t first_line = 0, last_line = 0;
  std::size_t blocks = 0;
  double worst_gap_rad = 0.0;  ///< radians
};

/// The range of one target rotary axis over the planned path, degrees, and its travel.
struct axis_span {
  char letter = 0;
  double lo_deg = 0.0, hi_deg = 0.0;
  bool bounded = false;
  double travel_lo_deg = 0.0, travel_hi_deg = 0.0;
};

/// The range of one target linear axis over the reachable blocks, mm, and its travel.
struct slide_span {
  char letter = 0;
  double lo_mm = 0.0, hi_mm = 0.0;
  double travel_lo_mm = 0.0, travel_hi_mm = 0.0;
  bool placed = false;  ///< the work offset was given: the range itself is checked, not only its length
  /// Placed: the range leaves the travel; not placed: the stroke is longer than the travel.
  bool exceeded() const {
    if (!placed) return hi_mm - lo_mm > travel_hi_mm - travel_lo_mm + 1e-6;
    return lo_mm < travel_lo_mm - 1e-6 || hi_mm > travel_hi_mm + 1e-6;
  }
};

/// One motion block on the target: its tip (target workpiece frame) and, when reachable, the
/// planned rotary angles (radians) and the slide values X, Y, Z they need (G7), mm.
struct block_on_target {
  std::size_t line = 0;
  vec3 tip_mm{};
  bool reachable = false;
  std::array<double, 2> rotary_rad{};
  vec3 slides_mm{};
};

/// One program on one target under one setup.
struct program_report {
  std::string file, from, to;
  rigid_transform setup;
  bool default_setup = true;
  std::array<std::size_t, 3> per_class{};  ///< by `matchability`
  std::vector<unreachable_run> unreachable;
  std::vector<axis_span> rotary;            ///< the target's rotary axes, over reachable blocks
  double rotary_travel_rad = 0.0;               ///< planned Σ|Δ|, radians
  bool has_tips = false;
  vec3 tip_lo_mm{}, tip_hi_mm{};                  ///< tool tips in the target's workpiece frame, mm
  std::vector<program::diagnostic> other_errors;  ///< what else stops a translation
  std::vector<vec3> source_axes;            ///< tool axes of the motion blocks, source frame
  run_inputs target_inputs;                 ///< tool length and work offset on the target
  bool placed = false;                      ///< the work offset was given (else the machine's origin)
  std::string work_offset_map_option;       ///< `--work-offset-map` text repeated in a printed command, or empty
  std::vector<std::string> tool_map_options;  ///< each `--tool-map` entry, repeated in a printed command
  std::vector<block_on_target> blocks;      ///< the motion blocks, as `source_axes`
  std::vector<slide_span> linear;           ///< X, Y, Z over the reachable blocks (none reachable: empty)
  /// Whether some slide leaves its travel.
  bool linear_exceeded() const {
    for (const auto& s : linear)
      if (s.exceeded()) return true;
    return false;
  }
  std::size_t motion_blocks() const { return per_class[0] + per_class[1] + per_class[2]; }
};

namespace detail {

inline std::vector<unreachable_run> runs_of(const std::vector<block_report>& reports) {
  std::vector<unreachable_run> out;
  bool open = false;
  for (const auto& r : reports) {
    if (r.match != matchability::unreachable) {
      open = false;
      continue;
    }
    if (!open) out.push_back({r.where.line, r.where.line, 0, 0.0});
    open = true;
    auto& run = out.back();
    run.last_line = r.where.line;
    ++run.blocks;
    run.worst_gap_rad = std::max(run.worst_gap_rad, r.gap.value);
  }
  return out;
}

inline std::vector<axis_span> spans_of(const machine_model& to, const rotary_path_values& path) {
  std::vector<axis_span> out;
  for (std::size_t i = 0; i < to.rotary_count; ++i) {
    const auto& axis = to.rotary(i);
    axis_span s{to_char(axis.letter), 0.0, 0.0, !axis.travel.continuous, axis.travel.lower.value, axis.travel.upper.value};
    bool first = true;
    for (const auto& a : path.angles) {
      if (!a) continue;
      const double v = to_degrees((*a)[i]).value;
      s.lo_deg = first ? v : std::min(s.lo_deg, v);
      s.hi_deg = first ? v : std::max(s.hi_deg, v);
      first = false;
    }
    out.push_back(s);
  }
  return out;
}

/// The slide values of each reachable block with the planned angles (G7), and their ranges.
inline void place_slides(const machine_model& to, program_report& out, const rotary_path_values& path) {
  std::array<double, 3> lo{}, hi{};
  bool any = false;
  for (std::size_t i = 0; i < out.blocks.size(); ++i) {
    auto& b = out.blocks[i];
    if (!path.angles[i]) continue;
    b.reachable = true;
    for (std::size_t k = 0; k < to.rotary_count; ++k) b.rotary_rad[k] = (*path.angles[i])[k].value;
    b.slides_mm = linear_axes_for(to, *path.angles[i], out.target_inputs.work_offset.map_point(b.tip_mm),
                                  out.target_inputs);
    const std::array<double, 3> x{b.slides_mm.x, b.slides_mm.y, b.slides_mm.z};
    for (std::size_t k = 0; k < 3; ++k) lo[k] = any ? std::min(lo[k], x[k]) : x[k], hi[k] = any ? std::max(hi[k], x[k]) : x[k];
    any = true;
  }
  if (!any) return;
  for (std::size_t k = 0; k < 3; ++k) {
    const linear_axis& a = to.linear(k);
    out.linear.push_back({to_char(a.letter), lo[k], hi[k], a.travel.lower_mm, a.travel.upper_mm, out.placed});
  }
}

}  // namespace detail

/// The report of program `nc` (of machine `from`) on machine `to` under `setup`; `target_inputs`
/// place the slides: the tool length, and where the workpiece frame sits on the target (the
/// translation of its work offset; how the part is turned is the setup's rotation, so the
/// offset's rotation is not used). `placed`: the work offset is the part's real place, so the
/// slides are checked against the travel's ends; otherwise only their strokes against its length.
inline program_report make_program_report(const machine_model& from, const machine_model& to,
                                          const program::program& nc, const rigid_transform& setup,
                                          bool is_default_setup, const run_inputs& target_inputs = {},
                                          bool placed = false, const work_offset_map& work_offsets = {},
                                          const tool_map& tool_numbers = {}) {
  program_report out;
  out.target_inputs = target_inputs;
  out.placed = placed;
  out.target_inputs.work_offset.rotation = mat3::identity();
  out.file = nc.file, out.from = from.geometry.id, out.to = to.geometry.id;
  out.setup = setup, out.default_setup = is_default_setup;
  translate_options options;
  options.setup = setup;
  options.common.work_offsets = work_offsets;
  options.common.tool_numbers = tool_numbers;
  const translation t = translate(from, to, nc, options);
  out.per_class = t.per_class;
  out.unreachable = detail::runs_of(t.reports);
  std::set<std::size_t> unreachable_lines;
  for (const auto& r : t.reports)
    if (r.match == matchability::unreachable) unreachable_lines.insert(r.where.line);
  for (const auto& e : t.errors)
    if (!unreachable_lines.count(e.where.line)) out.other_errors.push_back(e);
  const translation cl = reverse(from, nc);
  std::vector<vec3> target_axes;
  for (const auto& b : cl.output.blocks) {
    if (!b.axes.tool_axis) continue;
    const vec3 u = normalized(*b.axes.tool_axis);
    out.source_axes.push_back(u);
    target_axes.push_back(setup.rotation * u);
    const vec3 tip = setup.map_point({b.axes.x_mm.value_or(0.0), b.axes.y_mm.value_or(0.0), b.axes.z_mm.value_or(0.0)});
    out.tip_lo_mm = out.has_tips ? vec3{std::min(out.tip_lo_mm.x, tip.x), std::min(out.tip_lo_mm.y, tip.y), std::min(out.tip_lo_mm.z, tip.z)} : tip;
    out.tip_hi_mm = out.has_tips ? vec3{std::max(out.tip_hi_mm.x, tip.x), std::max(out.tip_hi_mm.y, tip.y), std::max(out.tip_hi_mm.z, tip.z)} : tip;
    out.has_tips = true;
    out.blocks.push_back({b.where.line, tip});
  }
  const rotary_path_values path = plan_rotary_path(to, target_axes);
  out.rotary = detail::spans_of(to, path);
  out.rotary_travel_rad = path.travel_rad;
  detail::place_slides(to, out, path);
  return out;
}

/// The setup a search proposes for a program: the first rotation of the ranking with which the
/// whole program translates, the offset that keeps its slides within travel, and the report.
struct chosen_setup {
  setup_candidate candidate;
  vec3 offset_mm{};             ///< the setup's translation, mm (target workpiece frame)
  bool offset_moved = false;    ///< `setup_offset_shift` moved the part from the offset asked for
  program_report report;
  std::size_t passed_over = 0;  ///< rotations of less travel whose translation fails otherwise
  std::string first_reason;     ///< the first error of the first one passed over
};

namespace detail {

/// With the work offset given: the least shift of the part that brings report `r`'s slides
/// within travel (every block reachable), or nothing.
inline std::optional<vec3> shift_into_travel(const machine_model& to, const program_report& r) {
  std::vector<vec3> tips;
  std::vector<rotary_values> angles;
  for (const auto& b : r.blocks) {
    if (!b.reachable) return std::nullopt;
    tips.push_back(b.tip_mm);
    angles.push_back({radians{b.rotary_rad[0]}, radians{b.rotary_rad[1]}});
  }
  return setup_offset_shift(to, tips, angles, r.target_inputs);
}

}  // namespace detail

/// Tries `search.ranked` in order (offset: the setup's translation asked for, mm): the first
/// with which the program translates and every slide stays within its travel. With the work
/// offset given (`placed`), a rotation whose slides leave the travel is tried again with the
/// part shifted by the least amount that brings them back (`setup_offset_shift`).
inline std::optional<chosen_setup> choose_setup(const machine_model& from, const machine_model& to,
                                                const program::program& nc, const setup_search_result& search,
                                                const vec3& offset_mm, const run_inputs& target_inputs = {},
                                                bool placed = false, const work_offset_map& work_offsets = {},
                                                const tool_map& tool_numbers = {}) {
  chosen_setup out;
  auto report_with = [&](const mat3& rotation, const vec3& offset) {
    return make_program_report(from, to, nc, {rotation, offset}, false, target_inputs, placed, work_offsets,
                               tool_numbers);
  };
  for (const auto& c : search.ranked) {
    vec3 offset = offset_mm;
    program_report r = report_with(c.rotation, offset);
    if (placed && r.unreachable.empty() && r.other_errors.empty() && r.linear_exceeded())
      if (const auto shift = detail::shift_into_travel(to, r)) {
        offset = offset + *shift;
        r = report_with(c.rotation, offset);
      }
    if (r.unreachable.empty() && r.other_errors.empty() && !r.linear_exceeded()) {
      out.candidate = c;
      out.offset_mm = offset;
      out.offset_moved = norm(offset - offset_mm) > 0.0;
      out.report = std::move(r);
      return out;
    }
    if (out.passed_over++ == 0)
      out.first_reason = !r.other_errors.empty() ? r.other_errors.front().message
                         : !r.unreachable.empty() ? "blocks unreachable"
                         : placed                 ? "no place of the part keeps every slide within its travel"
                                                  : "a stroke is longer than its axis' travel";
  }
  return std::nullopt;
}

}  // namespace kin5::reach
