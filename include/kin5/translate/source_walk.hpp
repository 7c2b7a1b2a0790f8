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
/// in machine coordinates passes through with a warning. The walker runs once per pass:
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

#include <array>
#include <charconv>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../kinematics/forward.hpp"
#include "../kinematics/matchability.hpp"
#include "../program/block.hpp"
#include "../program/modal.hpp"
#include "allowances.hpp"
#include "arc_plane.hpp"
#include "options.hpp"
#include "source_checks.hpp"

namespace kin5::translate_detail {

/// `v` with `decimals` decimals, never "-0.000".
inline std::string fixed(double v, int decimals) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  std::string s(buf, r.ptr);
  if (s.find_first_not_of("-0.") == std::string::npos && s.front() == '-') s.erase(0, 1);  // no "-0.000"
  return s;
}

/// A diagnostic at block `b`.
inline program::diagnostic at(const program::block& b, std::string message) { return {b.where, std::move(message)}; }

/// Where the F word of block `b` starts: the first `F` (`f`) outside comments and strings that
/// begins a word and is not the start of a longer one (FMAX, FEDRAT); the block's start when
/// there is none (APT: the F is a FEDRAT statement of its own).
inline program::source_location feed_word_at(const program::block& b) {
  const std::string_view t = b.text;
  auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  std::size_t lead = 0;  // the text of a Heidenhain block starts at column 1, before `where`
  while (lead < t.size() && (t[lead] == ' ' || t[lead] == '\t')) ++lead;
  std::size_t line = b.where.line, column = b.where.column - std::min(lead, b.where.column - 1);
  char closing = 0;  // inside a comment or string until this byte
  for (std::size_t i = 0; i < t.size(); ++i, ++column) {
    const char c = t[i];
    if (c == '\n') {
      ++line, column = 0, closing = closing == '\n' ? 0 : closing;
      continue;
    }
    if (closing) {
      if (c == closing) closing = 0;
    } else if (c == '(' || c == '"') {
      closing = c == '(' ? ')' : '"';
    } else if (c == ';') {
      closing = '\n';
    } else if ((c == 'F' || c == 'f') && (i == 0 || !letter(t[i - 1])) && (i + 1 == t.size() || !letter(t[i + 1]))) {
      return {b.where.file, line, column};
    }
  }
  return b.where;
}

inline constexpr std::string_view tcp_off_message =
    "motion without tool-tip tracking (TCP): its tool tip depends on the machine geometry, which "
    "kin5 does not model yet; switch TCP on (TRAORI, M128, G43.4) before the first motion";
inline constexpr std::string_view rotary_tcp_off_message =
    "rotary motion without tool-tip tracking (TCP) needs the machine geometry, which kin5 does not "
    "model yet";

/// One input block after the source side: what it is and, for a motion, its pose.
struct source_step {
  enum class kind { copy, passthrough, motion, failed };
  kind what = kind::copy;
  vec3 tip_source_mm{};                      ///< tool tip, source workpiece frame
  vec3 u_source = unit_z;                    ///< tool axis, source workpiece frame, unit
  std::array<double, 2> rotary_source_deg{};  ///< source commanded angles, machine order (K16)
  std::size_t rotary_count = 0;               ///< how many of `rotary_source_deg` (0: a vector)
  std::array<char, 2> rotary_letters{};       ///< the letters of `rotary_source_deg`
  bool principal = true;                      ///< set when classified (the second pass)
  program::motion_kind motion = program::motion_kind::linear;
  bool rapid = false;
  program::feed_unit feed_mode = program::feed_unit::per_minute;
  std::optional<double> feed_mm_per_min;      ///< F in effect, when `feed_mode` is per minute
  std::optional<vec3> start_source_mm;        ///< tool tip before the block, when known
  arc_path arc_source;                        ///< a circular motion's arc, source frame
};

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

/// Source side of an NC program of machine `from`: angles → tool axis by (G1).
struct nc_source {
  machine_model from;
  static constexpr bool needs_tcp = true;
  static constexpr bool has_angles = true;
  /// Values rounded into a tool axis: one per rotary axis (angle_tolerance.hpp).
  std::size_t rounded_values() const { return from.rotary_count; }
  /// The checks of block `b` against `from` (source_checks.hpp); false on an error.
  bool check(const program::block& b, const source_context& ctx) const { return check_source_axes(from, b, ctx); }
  /// `kinematics`: whether to compute the tool axis and the branch (else only the angles).
  /// `notes`: refusals, by name (a rotary axis with no value yet: `unset-rotary`).
  std::optional<std::string> pose(const program::modal_state& modal, source_step& s, std::string& warned,
                                  std::vector<program::diagnostic>& notes, const program::block& b,
                                  bool kinematics) const {
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
    if (!kinematics) return std::nullopt;
    s.u_source = tool_axis(from, angles);
    s.principal = on_principal_branch(from, angles, s.u_source);
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
  std::optional<std::string> pose(const program::modal_state& modal, source_step& s, std::string&,
                                  std::vector<program::diagnostic>&, const program::block&, bool) const {
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
  explicit source_walker(Source source = {}) : source_(std::move(source)) {}
  /// The source side it walks with.
  const Source& source() const { return source_; }

  /// Sets the program's dialect and angle tolerance (`ctx.out` is ignored) and the refusals
  /// allowed; before the first `next`.
  void configure(const source_context& ctx, const allowances& allow) {
    context_ = ctx;
    allow_ = allow;
  }

  /// The step of block `b`; `kinematics`: whether to compute the tool axis and
  /// `source_step::principal` of a motion step (else only its angles).
  source_step next(const program::block& b, translation* out, bool kinematics) {
    const report to{out, &allow_};
    const program::modal_state before = modal_;
    modal_.apply(b);
    source_step s;
    source_context ctx = context_;
    ctx.out = out;
    const bool kept_ok = b.kept_words.empty() || check_kept_words(b, ctx);
    const bool offset_ok = !b.state.work_offset || check_work_offset(b, ctx);
    if (!kept_ok || !offset_ok || (!b.m_codes.empty() && !check_m_codes(b, ctx)) ||
        (b.moves() && !source_.check(b, ctx))) {
      s.what = source_step::kind::failed;
      return s;
    }
    if (b.machine_coordinates && b.moves()) {  // the source machine's own axes: nothing on another
      s.what = source_step::kind::failed;
      to.fail(at(b, "a move in machine coordinates (G53, G28, G30, SUPA, M91, M92) is not translated: the source "
                    "machine's axis positions mean nothing on another machine"));
      return s;
    }
    if (b.machine_coordinates || b.passthrough) {
      s.what = source_step::kind::passthrough;
      to.warn(at(b, b.machine_coordinates ? "machine-coordinate move passed through unchanged, not through "
                                            "kinematics; the tool position after it is unknown"
                                          : "block not understood: passed through unchanged"));
      return s;
    }
    if (!b.moves()) return s;  // copy
    s.what = source_step::kind::failed;
    if (!tool_tip(b, before, s, to)) return s;
    if (!s.rapid && modal_.feed == 0.0) {  // LinuxCNC: "Cannot do g1 with zero feed rate"
      to.fail({b.feed == 0.0 ? feed_word_at(b) : b.where,
               b.feed == 0.0 ? "feed move with F0: a zero feed rate never reaches the end point"
                             : "feed move at a zero feed rate (F0 or FEDRAT/0 in effect): it never reaches the end point"});
      return s;
    }
    std::vector<program::diagnostic> notes;
    if (auto error = source_.pose(modal_, s, warned_letters_, notes, b, kinematics)) {
      to.fail(at(b, *error));
      return s;
    }
    for (auto& note : notes) to.refuse(std::move(note));
    s.feed_mode = modal_.feed_mode;
    if (modal_.feed_mode == program::feed_unit::per_minute) s.feed_mm_per_min = modal_.feed;
    if (program::is_arc(s.motion) && !arc_of(b, before, s, to)) return s;
    s.what = source_step::kind::motion;
    return s;
  }

 private:
  Source source_;
  program::modal_state modal_;
  std::string warned_letters_;  // rotary axes already warned about as having no value
  source_context context_;
  allowances allow_;

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

  /// Motion kind, tool tip and start point of motion block `b`; false (an error) when
  /// tool-tip tracking is off or the tip is not known.
  bool tool_tip(const program::block& b, const program::modal_state& before, source_step& s, const report& to) {
    if (Source::needs_tcp && !modal_.tcp) {
      to.fail(at(b, std::string(b.axes.has_rotary() || modal_.rotary_moved ? rotary_tcp_off_message
                                                                             : tcp_off_message)));
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
