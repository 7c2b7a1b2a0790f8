/// @file translate/source_walk.hpp
/// The source side of a translation: walks a program's blocks in order with their modal state
/// and turns each into a `source_step` — a block to copy, to pass through, that failed, or a
/// motion with its tool tip and tool axis in the source workpiece frame:
///
///     tip_source_mm = programmed X Y Z (tool-tip tracking on)
///     u_source      = tool_axis(from, commanded angles)      (K1), (G1)   — `nc_source`
///                   | the written vector (GOTO/x,y,z,i,j,k)               — `cl_source`
///
/// Every block is first checked against the source machine (`source_checks.hpp`: axis words
/// it lacks, values outside its travel). Motion without tool-tip tracking, an unknown tip, a
/// feed move at F0 (at its F word), or an arc that cannot be mapped is an error at the block; a rotary axis with no value yet is
/// refused (`unset-rotary`, which `--allow` turns into taking it as 0); a block not understood or
/// in machine coordinates passes through with a warning. Between controls whose cutter radius
/// compensation starts differently (LinuxCNC and the others), each start-up and cancel must run
/// straight on (`compensation_ends.hpp`). The walker runs once per pass:
/// diagnostics go to the result in the first only.
/// @code
///   kin5::translate_detail::source_walker walk(kin5::translate_detail::nc_source{kin5::machines::sajo_12000p::model});
///   walk.configure({source_language, 0.0005_deg}, {});
///   for (const auto& b : nc.blocks) {
///     const auto s = walk.next(b, &result, true);
///     if (s.what == source_step::kind::motion) use(s.tip_source_mm, s.u_source);
///   }
/// @endcode
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../kinematics/forward.hpp"
#include "../kinematics/inverse_pose.hpp"
#include "../kinematics/matchability.hpp"
#include "../program/block.hpp"
#include "../program/modal.hpp"
#include "../program/units.hpp"
#include "allowances.hpp"
#include "arc_plane.hpp"
#include "compensation_ends.hpp"
#include "diagnostic_text.hpp"
#include "machine_moves.hpp"
#include "options.hpp"
#include "source_checks.hpp"
#include "tool_lengths.hpp"
#include "untracked.hpp"

namespace kin5::translate_detail {

inline constexpr std::string_view tcp_off_message =
    "motion without tool-tip tracking (TCP): its tool tip depends on where the part sits and on the "
    "tool length; give the source's --source-work-offset and --source-tool-length to read it as machine "
    "coordinates, or switch TCP on (TRAORI, M128, G43.4) before the first motion";
inline constexpr std::string_view rotary_tcp_off_message =
    "rotary motion without tool-tip tracking (TCP): its tool tip depends on where the part sits and on "
    "the tool length; give the source's --source-work-offset and --source-tool-length to read it as "
    "machine coordinates";

/// One input block after the source side: what it is and, for a motion, its pose.
struct source_step {
  /// `machine`: a move of the linear axes in machine coordinates (`from_home_mm`), written as the
  /// target's own; a rotary positioning in machine coordinates is a `motion` with `positioning`.
  enum class kind { copy, passthrough, motion, failed, machine };
  kind what = kind::copy;
  /// A `machine` step: where X, Y, Z end, mm from each axis' home (machine_moves.hpp).
  std::array<std::optional<double>, 3> from_home_mm{};
  /// A motion step that only turns the rotary axes, in machine coordinates, with the tool
  /// retracted and no tool-tip tracking: its meaning is the tool axis `u_source` alone (no tip).
  bool positioning = false;
  /// A `machine` step along the tool axis to the end of travel (M140 MB MAX), no `from_home_mm`.
  bool to_limit = false;
  vec3 tip_source_mm{};                      ///< tool tip, source workpiece frame
  vec3 u_source = unit_z;                    ///< tool axis, source workpiece frame, unit
  std::array<double, 2> rotary_source_deg{};  ///< source commanded angles, machine order (K16)
  std::size_t rotary_count = 0;               ///< how many of `rotary_source_deg` (0: a vector)
  std::array<char, 2> rotary_letters{};       ///< the letters of `rotary_source_deg`
  /// The source's commanded angles before the block (degrees, machine order), when all are known.
  std::optional<std::array<double, 2>> rotary_start_deg;
  /// Under tool-tip tracking, when a rotary axis turns by `sweep_angle` or more from
  /// `rotary_start_deg`: the tool axis (source frame, unit) at s = j/n, j = 1 … n−1, of the
  /// control's linear move of the angles, n = `sweep_samples` (the path a least move of the
  /// target would not take: the other way round, or none for a full turn).
  std::vector<vec3> sweep;
  bool principal = true;                      ///< set when classified (the second pass)
  program::motion_kind motion = program::motion_kind::linear;
  bool rapid = false;
  program::feed_unit feed_mode = program::feed_unit::per_minute;
  std::optional<double> feed_mm_per_min;      ///< F in effect, when `feed_mode` is per minute
  std::optional<double> feed_inverse_per_min; ///< F in effect, when `feed_mode` is inverse time (1/min)
  std::optional<vec3> start_source_mm;        ///< tool tip before the block, when known
  arc_path arc_source;                        ///< a circular motion's arc, source frame
  /// Read as machine coordinates (TCP off): tip and axis by (G9); the rotary axes may move.
  bool untracked = false;
  /// TCP off, every rotary axis at 0 (the source's zero pose, `at_zero_pose`): the point
  /// programmed is the tip in the part's frame, as with tracking; the target tracks it.
  bool zero_pose = false;
  /// An untracked block whose rotary axes move, cut into pieces (untracked.hpp): the tip and
  /// axis at the end of every piece but the last (whose end is the block's own), in order.
  std::vector<tool_pose> pieces;
  bool rotary_moves = false;  ///< an untracked block whose rotary axes move from a known start
  /// An untracked block at a feed per minute: its time (min), (K16) over the machine axes / F.
  std::optional<double> block_time_min;
  /// The tool-table entry whose length is in effect (tool_lengths.hpp), when known.
  std::optional<long long> length_entry;
  /// Cutter radius compensation (G41/G42, RL/RR) is on after the block: the target checks that
  /// it can keep the side (docs/dialects/compensation.md).
  bool compensated = false;
};

/// A rotary move of this much or more in one tracked block is a sweep (`source_step::sweep`):
/// a least move of the target's axes would go the other way round.
inline constexpr degrees sweep_angle{180.0};

/// How many equal steps `source_step::sweep` cuts a move of `largest` degrees into: 8 per half
/// turn (steps of at most 22.5°), so that each step is far from a half turn.
inline std::size_t sweep_samples(double largest_deg) {
  return 8 * static_cast<std::size_t>(std::max(1.0, std::ceil(largest_deg / 180.0)));
}

/// The tool axes of machine `m` (unit) at s = j/n, j = 1 … n−1, as its commanded angles move
/// linearly from `start_deg` to `end_deg` (degrees, machine order), when one of them moves by
/// `sweep_angle` or more; empty otherwise.
inline std::vector<vec3> sweep_of(const machine_model& m, const std::array<double, 2>& start_deg,
                                  const std::array<double, 2>& end_deg) {
  double largest_deg = 0.0;
  for (std::size_t i = 0; i < m.rotary_count; ++i) largest_deg = std::max(largest_deg, std::abs(end_deg[i] - start_deg[i]));
  if (largest_deg < sweep_angle.value) return {};
  const std::size_t n = sweep_samples(largest_deg);
  std::vector<vec3> axes;
  axes.reserve(n - 1);
  for (std::size_t j = 1; j < n; ++j) {
    kin5::rotary_values angles{};
    for (std::size_t i = 0; i < m.rotary_count; ++i)
      angles[i] = to_radians(degrees{start_deg[i] + double(j) / double(n) * (end_deg[i] - start_deg[i])});
    axes.push_back(tool_axis(m, angles));
  }
  return axes;
}

/// The source pose of a motion step as a report shows it: "A=-77.954 B=3.536" (degrees, letters
/// in alphabetical order), or "I=… J=… K=…" for a tool-axis vector.
inline std::string angles_text(const source_step& s) {
  if (s.rotary_count == 0)
    return "I=" + fixed(s.u_source.x, 7) + " J=" + fixed(s.u_source.y, 7) + " K=" + fixed(s.u_source.z, 7);
  std::string text;
  for (char letter : {'A', 'B', 'C'})
    for (std::size_t i = 0; i < s.rotary_count; ++i)
      if (s.rotary_letters[i] == letter) {
        if (!text.empty()) text += ' ';
        text += std::string(1, letter) + "=" + fixed(s.rotary_source_deg[i], 3);
      }
  return text;
}

/// What block `b` says besides its motion that takes effect at a moment of the block (tool,
/// spindle, M functions, state words, the program end), if anything: such a block cannot be cut
/// into pieces without choosing that moment.
inline const char* words_of_a_whole_block(const program::block& b) {
  if (b.program_end) return "the program end";
  if (b.tool || b.tool_name) return "a tool";
  if (b.spindle_rpm) return "a spindle speed";
  if (program::says_m_function(b)) return "an M function";
  if (!b.state.empty()) return "a tool, spindle, coolant, offset, plane, dwell or stop word";
  if (!b.kept_words.empty()) return "a kept word";
  return nullptr;
}

/// Source side of an NC program of machine `from`: angles → tool axis by (G1).
struct nc_source {
  machine_model from;
  /// The source's work offset and tool length: given, motion without tool-tip tracking is read
  /// as machine coordinates (untracked.hpp); empty, it is refused.
  std::optional<run_inputs> untracked{};
  /// How far (mm) the tip of a subdivided untracked block may stray from the source's path.
  double tolerance_mm = 0.005;
  /// Each tool's length (tool_lengths.hpp); `untracked`'s length is then the one for a tool
  /// without an entry, when `lengths.single_mm` says so.
  tool_lengths lengths{};
  static constexpr bool needs_tcp = true;
  static constexpr bool has_angles = true;
  /// Values rounded into a tool axis: one per rotary axis (angle_tolerance.hpp).
  std::size_t rounded_values() const { return from.rotary_count; }
  /// The checks of block `b` against `from` (source_checks.hpp); false on an error.
  bool check(const program::block& b, const source_context& ctx) const { return check_source_axes(from, b, ctx); }
  /// `kinematics`: whether to compute the tool axis and the branch (else only the angles).
  /// `notes`: refusals, by name (a rotary axis with no value yet: `unset-rotary`).
  std::optional<std::string> pose(const program::modal_state& before, const program::modal_state& modal,
                                  source_step& s, std::string& warned, std::vector<program::diagnostic>& notes,
                                  const program::block& b, bool kinematics) const {
    if (modal.tool_axis) {  // a tool-axis vector written in the program (G43.5 IJK, LN TX TY TZ)
      s.u_source = *modal.tool_axis;
      s.rotary_count = 0;
      return std::nullopt;
    }
    kin5::rotary_values angles{};
    s.rotary_count = from.rotary_count;
    for (std::size_t i = 0; i < from.rotary_count; ++i) {
      const char letter = to_char(from.rotary(i).letter);
      const auto v_deg = modal.value(letter);
      if (!v_deg && warned.find(letter) == std::string::npos) {
        warned.push_back(letter);
        notes.push_back({b.where,
                         std::string("rotary axis ") + letter +
                             " has no value yet: its pose would be a guess (--allow unset-rotary takes it as 0, "
                             "the zero pose)",
                         "unset-rotary", "--allow unset-rotary"});
      }
      s.rotary_letters[i] = letter;
      s.rotary_source_deg[i] = v_deg.value_or(0.0);
      angles[i] = to_radians(degrees{s.rotary_source_deg[i]});
    }
    std::array<double, 2> start_deg{};
    bool start_known = true;
    for (std::size_t i = 0; i < from.rotary_count; ++i) {
      const auto v_deg = before.value(s.rotary_letters[i]);
      start_known = start_known && v_deg.has_value();
      start_deg[i] = v_deg.value_or(0.0);
    }
    if (start_known) s.rotary_start_deg = start_deg;
    if (!kinematics) return std::nullopt;
    s.u_source = tool_axis(from, angles);
    s.principal = on_principal_branch(from, angles, s.u_source);
    if (start_known && modal.tcp) s.sweep = sweep_of(from, start_deg, s.rotary_source_deg);
    return std::nullopt;
  }
};

/// Source side of APT CL data: the tool axis is written (GOTO/x,y,z,i,j,k); +Z until the first.
struct cl_source {
  static constexpr bool needs_tcp = false;
  static constexpr bool has_angles = false;
  /// Values rounded into a tool axis: the vector.
  std::size_t rounded_values() const { return 1; }
  /// CL data names no machine axes: nothing to check against a machine.
  bool check(const program::block&, const source_context&) const { return true; }
  std::optional<std::string> pose(const program::modal_state&, const program::modal_state& modal, source_step& s,
                                  std::string&, std::vector<program::diagnostic>&, const program::block&, bool) const {
    s.u_source = modal.tool_axis.value_or(unit_z);
    if (!(norm(s.u_source) > 0.5)) return std::string("tool-axis vector of zero length");
    return std::nullopt;
  }
};

/// The source side: walks the program's blocks in order with their modal state and turns each
/// into a step. Diagnostics go to `out` when given (the first pass), else nowhere (the second
/// pass, which sees the same blocks again).
template <class Source>
class source_walker {
 public:
  explicit source_walker(Source source = {}) : source_(std::move(source)) {
    if constexpr (Source::needs_tcp) {
      lengths_ = tool_length_tracker(source_.lengths, "--source-tool-length");
      if (source_.untracked) in_ = *source_.untracked;
    }
  }
  /// The source side it walks with.
  const Source& source() const { return source_; }

  /// Sets the program's dialect and angle tolerance (`ctx.out` is ignored) and the refusals
  /// allowed; before the first `next`.
  void configure(const source_context& ctx, const allowances& allow) {
    context_ = ctx;
    allow_ = allow;
    entries_differ_ = program::controller_of(ctx.language).tangent_compensation_entry !=
                      program::controller_of(ctx.output).tangent_compensation_entry;
  }

  /// The step of block `b`; `kinematics`: whether to compute the tool axis and
  /// `source_step::principal` of a motion step (else only its angles).
  source_step next(const program::block& b, translation* out, bool kinematics) {
    const program::cutter_side was = modal_.radius_compensation.value_or(program::cutter_side::off);
    source_step s = step(b, out, kinematics);
    if (entries_differ_) follow_compensation_ends(b, was, s, report{out, &allow_});
    return s;
  }

 private:
  /// The step of block `b`, as `next` gives it.
  source_step step(const program::block& b, translation* out, bool kinematics) {
    const report to{out, &allow_};
    if constexpr (Source::needs_tcp)
      if (b.tcp && *b.tcp != modal_.tcp) rebase_on_switch(*b.tcp);
    // APT's FEDRAT/INVERS holds for the moves after it, where an NC move in G93 needs its own F.
    if (program::capabilities_of(context_.language).cl_data) modal_.inverse_time_feed_used = false;
    const program::modal_state before = modal_;
    modal_.apply(b);
    source_step s;
    s.length_entry = length_entry(modal_);
    if constexpr (Source::needs_tcp)  // where a tool change or another length leaves the tip is not known
      if (source_.untracked && (program::changes_tool(b) || s.length_entry != length_entry(before))) last_tip_.reset();
    source_context ctx = context_;
    ctx.out = out;
    const bool kept_ok = b.kept_words.empty() || check_kept_words(b, ctx);
    const bool offset_ok = !b.state.work_offset || check_work_offset(b, ctx);
    const bool speed_ok = !b.spindle_rpm || check_spindle_speed(b, ctx);
    const bool dwell_ok = !b.state.dwell_s || check_dwell(b, ctx);
    const bool tool_ok = !b.tool_name || check_tool_name(b, ctx);
    s.compensated = modal_.radius_compensation && *modal_.radius_compensation != program::cutter_side::off;
    if (!compensation_ok(b, s.compensated, to) || !kept_ok || !offset_ok || !speed_ok || !dwell_ok || !tool_ok ||
        (program::says_m_function(b) && !check_m_codes(b, ctx)) ||
        (b.moves() && !source_.check(b, ctx))) {
      s.what = source_step::kind::failed;
      return s;
    }
    if (b.machine_coordinates && (b.moves() || b.machine_reference == program::machine_position::tool_axis_limit)) {
      if constexpr (Source::has_angles) {
        machine_step(b, before, s, to, kinematics);
      } else {  // CL data name no machine
        s.what = source_step::kind::failed;
        to.fail(at(b, "a move in machine coordinates is not translated from CL data"));
      }
      return s;
    }
    if (b.machine_coordinates || b.passthrough) {
      if (!b.framing && !b.assignment) last_tip_.reset();  // the tool position after it is unknown
      s.what = source_step::kind::passthrough;
      if (b.machine_coordinates)
        to.warn(at(b, "machine-coordinate move passed through unchanged, not through kinematics; the tool "
                      "position after it is unknown"));
      else if (!b.framing && !b.assignment)  // a tape mark or a parameter's number is understood
        to.warn(at(b, "block not understood: passed through unchanged"));
      return s;
    }
    if (!b.moves()) {  // copy; an arc centre on its own is mapped like the points of its arc
      if constexpr (Source::needs_tcp)
        if (untracked_now() && b.arc && b.arc->centre_mm && !untracked_centre(b, s, to)) s.what = source_step::kind::failed;
      return s;
    }
    if (is_positioning(b)) {
      positioning_step(b, before, s, to, kinematics);
      return s;
    }
    s.what = source_step::kind::failed;
    if (!tool_tip(b, before, s, to)) return s;
    if (!s.rapid && modal_.feed == 0.0) {  // LinuxCNC: "Cannot do g1 with zero feed rate"
      to.fail({b.feed == 0.0 ? feed_word_at(b) : b.where,
               b.feed == 0.0 ? "feed move with F0: a zero feed rate never reaches the end point"
                             : "feed move at a zero feed rate (F0 or FEDRAT/0 in effect): it never reaches the end point"});
      return s;
    }
    std::vector<program::diagnostic> notes;
    // A compensated move's tool axis is checked in both passes, so both give the same steps.
    if (auto error = source_.pose(before, modal_, s, warned_letters_, notes, b, kinematics || s.compensated)) {
      to.fail(at(b, *error));
      return s;
    }
    for (auto& note : notes) to.refuse(std::move(note));
    if (s.compensated && !compensated_pose_ok(b, s, to)) return s;
    s.feed_mode = modal_.feed_mode;
    if (modal_.feed_mode == program::feed_unit::per_minute) s.feed_mm_per_min = modal_.feed;
    else s.feed_inverse_per_min = modal_.feed;
    if (program::is_arc(s.motion) && !arc_of(b, before, s, to)) return s;
    if constexpr (Source::needs_tcp) {
      if (s.untracked && !untracked_tip(b, before, s, to)) return s;
      if (!s.untracked && last_tip_ && last_untracked_) s.start_source_mm = last_tip_;  // TCP switched on
    }
    last_tip_ = s.tip_source_mm, last_untracked_ = s.untracked;
    s.what = source_step::kind::motion;
    retracted_ = false;  // the tool has moved in the part's frame: it may be near the part again
    return s;
  }

  Source source_;
  program::modal_state modal_;
  std::string warned_letters_;  // rotary axes already warned about as having no value
  source_context context_;
  allowances allow_;
  std::optional<vec3> last_tip_;  // tip of the last motion (source workpiece frame), while known
  bool retracted_ = false;        // Z has gone to its home since the last motion in the part's frame
  bool last_untracked_ = false;   // whether that motion was read as machine coordinates
  std::optional<std::optional<program::work_offset>> untracked_offset_;  // work offset of the first untracked motion
  tool_length_tracker lengths_;  // the tool length of each untracked motion
  run_inputs in_{};              // the source's placement with the length in effect
  bool entries_differ_ = false;          // the two controls start compensation differently
  compensation_ends compensation_ends_;  // their start-ups and cancels

  /// Where diagnostics go: the result of the first pass, or nowhere.
  struct report {
    translation* out;
    const allowances* allow;
    void warn(program::diagnostic d) const {
      if (out) out->warnings.push_back(std::move(d));
    }
    void fail(program::diagnostic d) const {
      if (out) out->errors.push_back(std::move(d));
    }
    void refuse(program::diagnostic d) const {
      if (out) out->refuse(std::move(d), *allow);
    }
  };

  /// The step of block `b` in machine coordinates (machine_moves.hpp): a move of the linear axes
  /// from their homes, or a rotary positioning with the tool retracted and no tool-tip tracking,
  /// read as the tool axis it ends at. The tool's place in the part's frame is unknown after
  /// either: the next motion must give X, Y and Z (an approach).
  void machine_step(const program::block& b, const program::modal_state& before, source_step& s, const report& to,
                    bool kinematics) {
    s.what = source_step::kind::failed;
    last_tip_.reset();
    if (b.machine_reference == program::machine_position::tool_axis_limit) return tool_axis_retract(b, s);
    machine_move move;
    if (auto why = read_machine_move(b, source_.from, modal_.distance == program::distance_mode::incremental, move))
      return to.fail(at(b, *why));
    // G28 runs at rapid; the others in the motion mode in effect (FMAX: rapid).
    const auto kind = modal_.motion_of(b);
    s.motion = kind.value_or(program::motion_kind::rapid);
    s.rapid = b.machine_reference == program::machine_position::reference_point || b.feed_rapid ||
              s.motion == program::motion_kind::rapid;
    if (s.rapid) s.motion = program::motion_kind::rapid;
    const std::string what = program::machine_position_name(b.machine_reference);
    if (program::is_arc(s.motion)) return to.fail(at(b, what + " on a circle is not translated"));
    if (!s.rapid && (modal_.feed_mode != program::feed_unit::per_minute || !modal_.feed || !(*modal_.feed > 0.0)))
      return to.fail(at(b, what + " at a feed needs a feed per minute in effect (F, G94)"));
    if (!s.rapid) s.feed_mm_per_min = modal_.feed;
    if (!move.has_rotary()) {
      s.what = source_step::kind::machine;
      s.from_home_mm = move.from_home_mm;
      if (move.retracts()) retracted_ = true;
      return;
    }
    // X and Y may move with it (`G91 G28 X0 Y0 B0`): Z stays where the retract left it.
    const char* why = move.from_home_mm[2] ? "it also moves Z: give the retract a block of its own before it"
                      : !s.rapid       ? "it runs at a feed, not at rapid"
                      : modal_.tcp     ? "tool-tip tracking is on"
                      : !retracted_    ? "the tool is not retracted (no move of Z to its home since the last move in "
                                         "the part's frame), so it may be near the part"
                                       : nullptr;
    if (why) {
      return to.fail(at(b, what + " that turns the rotary axes is translated only as a positioning of the retracted "
                                  "tool, at rapid, without tool-tip tracking: " + why));
    }
    s.from_home_mm = move.from_home_mm;
    modal_.a_deg = move.rotary_deg[0] ? move.rotary_deg[0] : before.a_deg;
    modal_.b_deg = move.rotary_deg[1] ? move.rotary_deg[1] : before.b_deg;
    modal_.c_deg = move.rotary_deg[2] ? move.rotary_deg[2] : before.c_deg;
    positioning_step(b, before, s, to, kinematics);
  }

  /// `M140 MB MAX` (block `b`): along the tool axis, away from the part, to the end of travel.
  /// The tool axis is the part's, which a translation keeps: the target retracts along its own
  /// (nc_target.hpp), whatever the source's heads stand at.
  void tool_axis_retract(const program::block& b, source_step& s) {
    (void)b;
    modal_.x_mm.reset(), modal_.y_mm.reset(), modal_.z_mm.reset();
    s.what = source_step::kind::machine;
    s.to_limit = true;
    s.rapid = true;
    s.motion = program::motion_kind::rapid;
    retracted_ = true;
  }

  /// Whether block `b` turns only rotary axes, at rapid, without tool-tip tracking, with the tool
  /// retracted, where motion without tracking is not read as machine coordinates: a positioning
  /// (the CAM safe-start idiom: retract, orient the tool, then tracking on and an approach).
  bool is_positioning(const program::block& b) const {
    if constexpr (Source::needs_tcp) {
      const auto kind = modal_.motion_of(b);
      return retracted_ && !modal_.tcp && !untracked_now() && b.axes.has_rotary() && !b.axes.has_linear() &&
             !b.axes.tool_axis && (b.feed_rapid || kind == program::motion_kind::rapid);
    }
    return false;
  }

  /// The step of a positioning whose angles `modal_` holds: its tool axis, no tip. The part has
  /// turned under the tool (or the tool over the part), so where the tip is in the part's frame
  /// is not known: the next motion must give X, Y and Z.
  void positioning_step(const program::block& b, const program::modal_state& before, source_step& s,
                        const report& to, bool kinematics) {
    s.what = source_step::kind::failed;
    last_tip_.reset();
    modal_.x_mm.reset(), modal_.y_mm.reset(), modal_.z_mm.reset();
    s.positioning = true;
    s.rapid = true;
    s.motion = program::motion_kind::rapid;
    std::vector<program::diagnostic> notes;
    if (auto error = source_.pose(before, modal_, s, warned_letters_, notes, b, kinematics)) return to.fail(at(b, *error));
    for (auto& note : notes) to.refuse(std::move(note));
    s.what = source_step::kind::motion;
  }

  /// Motion kind, tool tip and start point of motion block `b`; false (an error) when
  /// tool-tip tracking is off or the tip is not known.
  bool tool_tip(const program::block& b, const program::modal_state& before, source_step& s, const report& to) {
    const bool zero_pose = Source::needs_tcp && !modal_.tcp && !untracked_now() && at_zero_pose(before);
    if (Source::needs_tcp && !modal_.tcp && !untracked_now() && !zero_pose) {
      to.fail(at(b, std::string(b.axes.has_rotary() ? rotary_tcp_off_message : tcp_off_message)));
      return false;
    }
    if (untracked_now() && modal_.length_compensation == false) {  // G49, Siemens D0
      to.fail(at(b, "motion without tool-tip tracking while tool length compensation is off (G49, D0): the point "
                    "programmed is the spindle's gauge point, not the tool tip; switch compensation on (G43 H, D1) "
                    "before machine-coordinate motion"));
      return false;
    }
    if (modal_.tcp && modal_.length_compensation == false) {  // Siemens D0, then TRAORI
      to.fail(at(b, "motion under tool-tip tracking while tool length compensation is off (D0): the point "
                    "programmed is the spindle's gauge point, not the tool tip; switch compensation on (D1) first"));
      return false;
    }
    if (const auto plane = modal_.working_plane; plane && *plane != program::arc_plane::xy &&
        program::controller_of(context_.language).plane_turns_tool_length && modal_.length_compensation != false) {
      to.fail(at(b, std::string("motion under ") + (*plane == program::arc_plane::zx ? "G18" : "G19") +
                        " while tool length compensation may be on: the 840D applies the tool length along " +
                        (*plane == program::arc_plane::zx ? "Y" : "X") + " (and turns the tool orientation under "
                        "TRAORI), not along the tool axis kin5 reads; program the move under G17"));
      return false;
    }
    const auto kind = modal_.motion_of(b);
    if (!kind) to.warn(at(b, "no motion mode in effect; taken as linear (G1)"));
    s.motion = kind.value_or(program::motion_kind::linear);
    s.rapid = s.motion == program::motion_kind::rapid || b.feed_rapid;
    std::string missing;
    for (char letter : {'X', 'Y', 'Z'})
      if (!modal_.value(letter)) missing += letter;
    if (!missing.empty()) {
      to.fail(at(b, "the tool tip is not known: no value yet for " + missing +
                        " (the first motion must give the full position)"));
      return false;
    }
    s.tip_source_mm = {*modal_.x_mm, *modal_.y_mm, *modal_.z_mm};
    if (before.x_mm && before.y_mm && before.z_mm) s.start_source_mm = vec3{*before.x_mm, *before.y_mm, *before.z_mm};
    s.untracked = Source::needs_tcp && !modal_.tcp && !zero_pose;
    s.zero_pose = zero_pose;
    return true;
  }

  /// Whether motion without tool-tip tracking from modal state `before` to `modal_` is at the
  /// source machine's zero pose: every rotary axis at a commanded angle of 0 (or whole turns)
  /// before and after, and the tool length on (G43 H, D1, …). There the rotary axes turn
  /// nothing: the part's frame is the machine's, shifted by the work offset the tracking would
  /// use too, and the length applies along the tool axis, so the point programmed is the tool tip
  /// in the part's frame, with tracking or without. Anywhere else the tip depends on where the part
  /// sits on the rotary axes (the message says which options give that).
  bool at_zero_pose(const program::modal_state& before) const {
    if constexpr (Source::needs_tcp) {
      if (modal_.length_compensation != true) return false;
      const auto zero = [](const std::optional<double>& deg) {
        return deg && std::fmod(std::abs(*deg), 360.0) == 0.0;
      };
      for (std::size_t i = 0; i < source_.from.rotary_count; ++i) {
        const char letter = to_char(source_.from.rotary(i).letter);
        if (!zero(before.value(letter)) || !zero(modal_.value(letter))) return false;
      }
      return true;
    }
    return false;
  }

  /// Cutter radius compensation at block `b` (`on`: in effect after it), where the target
  /// could cut another contour (docs/dialects/compensation.md): outside the XY plane (G17, a TNC's
  /// tool axis Z). False, with an error at the block, when refused.
  bool compensation_ok(const program::block& b, bool on, const report& to) const {
    const bool switched_on = b.state.radius_compensation && *b.state.radius_compensation != program::cutter_side::off;
    if (!switched_on && !(on && b.moves())) return true;
    if (modal_.working_plane != program::arc_plane::xy) {
      to.fail(at(b, std::string("cutter radius compensation outside the XY plane (") +
                        (!modal_.working_plane ? "no G17 in effect" : *modal_.working_plane == program::arc_plane::zx ? "G18" : "G19") +
                        "): kin5 translates it only in the XY plane, where every control offsets alike"));
      return false;
    }
    return true;
  }

  /// Between controls whose entry moves differ (LinuxCNC's ends tangent to the entry line, the
  /// others' at the contour's start): the start-up or cancel of compensation that block `b`
  /// (side `was` before it, step `s`) shows not to run straight on, refused at the block that
  /// switched (compensation_ends.hpp). Points are known to a unit of the last decimal written,
  /// and never taken as coarser than 0.001 (mm or inch).
  void follow_compensation_ends(const program::block& b, program::cutter_side was, const source_step& s,
                                const report& to) {
    if (s.what == source_step::kind::failed) return compensation_ends_.reset();
    std::optional<planar_move> moved;
    if (s.what == source_step::kind::motion)
      moved = planar_move{s.start_source_mm, s.tip_source_mm, program::is_arc(s.motion) ? &s.arc_source : nullptr};
    const double delta_mm = std::pow(10.0, -std::max(context_.linear_decimals.value_or(3), 3)) *
                            (modal_.metric == false ? program::mm_per_inch : 1.0);
    const auto refusal =
        compensation_ends_.follow(b, was, modal_.radius_compensation.value_or(program::cutter_side::off), moved,
                                  says_nothing(b), delta_mm);
    if (refusal)
      to.fail({refusal->where, "cutter radius compensation between " + std::string(program::name(context_.language)) +
                                   " and " + std::string(program::name(context_.output)) + ": " + refusal->reason});
  }

  /// A move under cutter radius compensation: its programmed point must be the tool tip (not
  /// read as machine coordinates) and the tool must stand along Z (a tilted tool needs 3-D
  /// compensation: G41.2, CUT3DC, LN blocks). False, with an error at the block, when refused.
  bool compensated_pose_ok(const program::block& b, const source_step& s, const report& to) const {
    const double tolerance = std::max(to_radians(context_.tolerance).value, 1e-9);
    const char* why = s.untracked ? "the move is read as machine coordinates: there is no contour to offset"
                      : norm(s.u_source - unit_z) > tolerance
                          ? "the tool axis is not along Z (a tilted tool needs 3-D compensation, which is not translated)"
                          : nullptr;
    if (why) to.fail(at(b, std::string("cutter radius compensation: ") + why));
    return why == nullptr;
  }

  /// Tool-tip tracking switched on (`on`) or off: an axis the next block does not program stays
  /// where it stands, so the modal X Y Z become the current position in the new reading — the
  /// tip, or the program point (G8) of the slides (G7) — when motion is read both ways.
  void rebase_on_switch(bool on) {
    if (!source_.untracked || !last_tip_) return;
    vec3 p = *last_tip_;
    if (!on) {
      const auto angles = angles_of(modal_);
      if (!angles) return;
      const run_inputs& in = in_;
      p = untracked_point(source_.from, linear_axes_for(source_.from, *angles, in.work_offset.map_point(p), in), in);
    }
    modal_.x_mm = p.x, modal_.y_mm = p.y, modal_.z_mm = p.z;
  }

  /// Whether motion now is read as machine coordinates: TCP off and the source's placement known.
  bool untracked_now() const {
    if constexpr (Source::needs_tcp) return !modal_.tcp && source_.untracked.has_value();
    return false;
  }

  /// The commanded angles (radians, chain order) of modal state `m`, if every rotary axis has a value.
  std::optional<kin5::rotary_values> angles_of(const program::modal_state& m) const {
    kin5::rotary_values angles{};
    for (std::size_t i = 0; i < source_.from.rotary_count; ++i) {
      const auto v_deg = m.value(to_char(source_.from.rotary(i).letter));
      if (!v_deg) return std::nullopt;
      angles[i] = to_radians(degrees{*v_deg});
    }
    return angles;
  }

  /// The placement of untracked motion block `b` in `in_`: the length of the tool in effect
  /// where it matters (a head turns the tool: tool_lengths.hpp), and the work offset the source's
  /// one was given for, the first untracked motion's, where that matters (a table carries the
  /// part); false, with an error, when either is not known.
  bool place(const program::block& b, const report& to) {
    bool head = false, table = false;
    for (std::size_t i = 0; i < source_.from.rotary_count; ++i)
      (source_.from.rotary(i).side == mount::head ? head : table) = true;
    if (!untracked_offset_) untracked_offset_ = modal_.work_offset;
    if (table && *untracked_offset_ != modal_.work_offset) {
      to.fail(at(b, "motion without tool-tip tracking with another work offset than the first: --source-work-offset "
                    "gives one"));
      return false;
    }
    if (!head) return true;  // the tool turns with no axis: its length moves tip and program point alike (G8)
    std::string why;
    const auto length = lengths_.length_mm(length_entry(modal_), why);
    if (!length) to.fail(at(b, "motion without tool-tip tracking: " + why));
    else in_.tool_length_mm = *length;
    return length.has_value();
  }

  /// Tip and axis of untracked motion block `b` (G9), its start, its arc, its pieces when its
  /// rotary axes move, and its time; false, with an error, when it cannot be read.
  bool untracked_tip(const program::block& b, const program::modal_state& before, source_step& s, const report& to) {
    const machine_model& m = source_.from;
    const run_inputs& in = in_;
    if (s.rotary_count == 0) {
      to.fail(at(b, "a tool-axis vector without tool-tip tracking cannot be read as machine coordinates"));
      return false;
    }
    if (!place(b, to)) return false;
    untracked_move move;
    move.end_mm = s.tip_source_mm;
    for (std::size_t i = 0; i < s.rotary_count; ++i) move.end[i] = to_radians(degrees{s.rotary_source_deg[i]});
    const auto start_angles = angles_of(before);
    const bool start_known = last_tip_ && start_angles && s.start_source_mm;
    if (start_known) {
      move.start = *start_angles;
      // After a TCP block the slides stand where its tip put them: their program point (G8).
      move.start_mm = last_untracked_ ? *s.start_source_mm
                                      : untracked_point(m, linear_axes_for(m, move.start, in.work_offset.map_point(*last_tip_), in), in);
    }
    // Angles that stand still move the tip rigidly, from wherever it was (G9).
    const bool turns = start_angles ? *start_angles != move.end : true;
    const tool_pose end = untracked_pose(m, move.end_mm, move.end, in);
    s.tip_source_mm = end.tip_mm, s.u_source = end.axis;
    s.start_source_mm = start_known ? std::optional<vec3>(move.at(m, in, 0.0).tip_mm) : std::nullopt;
    if (start_known && !s.rapid && s.feed_mm_per_min && *s.feed_mm_per_min > 0.0) {
      std::array<double, 2> delta_deg{};
      for (std::size_t i = 0; i < s.rotary_count; ++i) delta_deg[i] = to_degrees(move.end[i] - move.start[i]).value;
      s.block_time_min = block_length(move.end_mm - move.start_mm, std::span<const double>(delta_deg.data(), s.rotary_count)) /
                         *s.feed_mm_per_min;
    } else if (start_known && !s.rapid && s.feed_mode == program::feed_unit::inverse_time && b.feed && *b.feed > 0.0) {
      s.block_time_min = 1.0 / *b.feed;  // inverse time: F is 1 / the block's time in minutes
    }
    if (program::is_arc(s.motion)) return untracked_arc(b, move.end, s, to);
    if (!turns) return true;
    s.rotary_moves = start_known;
    if (!start_known) {
      if (s.rapid) return true;  // a positioning move from an unknown place: only its end is programmed
      to.fail(at(b, "feed move without tool-tip tracking whose rotary axes move from an unknown start: the path "
                    "of its tool tip is not known"));
      return false;
    }
    if (!s.rapid && !s.block_time_min) {
      to.fail(at(b, "feed move without tool-tip tracking whose rotary axes move, in inverse time without its own F: "
                    "its time is not known"));
      return false;
    }
    if (const char* words = words_of_a_whole_block(b)) {
      to.fail(at(b, std::string("rotary move without tool-tip tracking that also says ") + words +
                        ": where it takes effect among the block's pieces is not translated; give it a block of its own"));
      return false;
    }
    const auto n = pieces_within(m, in, move, source_.tolerance_mm);
    if (!n) {
      to.fail(at(b, "rotary move without tool-tip tracking needs more than 100000 pieces to stay within --tolerance"));
      return false;
    }
    // And no piece turning an axis by `sweep_angle` or more, which a target's least move would
    // take the other way round (a turn about an axis through the tip keeps the tip within any
    // tolerance): each piece's tool axis then says its turn.
    double largest_deg = 0.0;
    for (std::size_t i = 0; i < s.rotary_count; ++i)
      largest_deg = std::max(largest_deg, std::abs(to_degrees(move.end[i] - move.start[i]).value));
    const std::size_t count = std::max(*n, static_cast<std::size_t>(largest_deg / sweep_angle.value) + 1);
    for (std::size_t k = 1; k < count; ++k) s.pieces.push_back(move.at(m, in, double(k) / double(count)));
    return true;
  }

  /// The arc of untracked block `b` at the fixed angles `angles`: its centre and plane carried
  /// by the chain's rigid map (G9); false, with an error, when the plane lands on no principal one.
  bool untracked_arc(const program::block& b, const kin5::rotary_values& angles, source_step& s, const report& to) const {
    const machine_model& m = source_.from;
    const run_inputs& in = in_;
    arc_path& arc = s.arc_source;
    const vec3 origin = untracked_pose(m, {}, angles, in).tip_mm;
    const auto mapped = principal_plane(untracked_pose(m, plane_normal(arc.plane), angles, in).tip_mm - origin);
    if (!mapped) {
      to.fail(at(b, "circular move without tool-tip tracking cannot be mapped: the rotary axes turn its plane " +
                        std::string(plane_name(arc.plane)) + " onto no principal plane"));
      return false;
    }
    if (arc.centre_mm) arc.centre_mm = untracked_pose(m, *arc.centre_mm, angles, in).tip_mm;
    arc.plane = mapped->first;
    if (mapped->second) {
      arc.clockwise = !arc.clockwise;
      s.motion = arc.clockwise ? program::motion_kind::arc_cw : program::motion_kind::arc_ccw;
    }
    return true;
  }

  /// An arc centre on its own (Heidenhain CC) while motion is untracked: carried like its arc's
  /// points, in `s.arc_source.centre_mm`; false, with an error, when its plane would turn.
  bool untracked_centre(const program::block& b, source_step& s, const report& to) const {
    const auto angles = angles_of(modal_);
    const machine_model& m = source_.from;
    const run_inputs& in = in_;
    const vec3 n = plane_normal(b.arc->plane);
    const bool same_plane = angles && norm(untracked_pose(m, n, *angles, in).tip_mm - untracked_pose(m, {}, *angles, in).tip_mm - n) < 1e-9;
    if (!same_plane) {
      to.fail(at(b, "circle centre without tool-tip tracking cannot be mapped: the rotary axes are unset or turn its plane"));
      return false;
    }
    s.untracked = true;
    s.arc_source.centre_mm = untracked_pose(m, *b.arc->centre_mm, *angles, in).tip_mm;
    return true;
  }

  /// The arc of circular block `b` (plane, centre or radius); false (an error) when it cannot
  /// be mapped: rotary axes moving, start unknown, or neither centre nor radius.
  bool arc_of(const program::block& b, const program::modal_state& before, source_step& s, const report& to) const {
    arc_path& arc = s.arc_source;
    arc.plane = b.arc ? b.arc->plane : modal_.plane.value_or(program::arc_plane::xy);
    arc.clockwise = s.motion == program::motion_kind::arc_cw;
    arc.radius_mm = b.arc ? b.arc->radius_mm : std::nullopt;
    if (!arc.radius_mm) arc.centre_mm = (b.arc && b.arc->centre_mm) ? b.arc->centre_mm : modal_.arc_centre_mm;
    const bool rotary_moves = b.axes.tool_axis.has_value() || (b.axes.a_deg && b.axes.a_deg != before.a_deg) ||
                              (b.axes.b_deg && b.axes.b_deg != before.b_deg) ||
                              (b.axes.c_deg && b.axes.c_deg != before.c_deg);
    const char* why = rotary_moves           ? "the rotary axes move during it"
                      : !s.start_source_mm   ? "its start point is not known"
                      : !arc.centre_mm && !arc.radius_mm ? "no centre or radius"
                                                         : nullptr;
    if (why) {
      to.fail(at(b, std::string("circular move cannot be mapped: ") + why));
      return false;
    }
    if (arc.centre_mm) set_normal_component(*arc.centre_mm, arc.plane, normal_component(*s.start_source_mm, arc.plane));
    return true;
  }
};

}  // namespace kin5::translate_detail
