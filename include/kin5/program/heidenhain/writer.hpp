/// @file program/heidenhain/writer.hpp
/// Blocks written as Heidenhain conversational text: one line per block (a `TOOL CALL` or `CC`
/// line first when another dialect's block needs one), numbered 0, 1, 2, … as the control
/// requires; source block numbers are not written. Every program opens with `BEGIN PGM name
/// MM|INCH` and closes with `END PGM` of that name (`finish`), the frame the control reads a
/// program in: another dialect's frame (`%`, `;$PATH=…`; its name from `O`, `%_N_…`, PARTNO)
/// is never copied as text, and a source end (M2, M30, FINI) is an `M2`/`M30` before it; a block
/// of another dialect after that end is refused unless it is only a comment (program_end.hpp).
/// A block without coordinates is never an `L`
/// (the control's L needs its end point): a feed-only block's F goes to the next move without an
/// F, a rapid-only block's FMAX to the next move; a block left with nothing Heidenhain can say
/// (APT `UNITS/MM`, `RAPID`, a read `L F800`) becomes a comment carrying its source text. A
/// dwell is Cycle 9: `CYCL DEF 9.0 DWELL TIME`, `CYCL DEF 9.1 DWELL t`.
/// Round trip: `read(write(p))` equals `p` except `where`, `text` and `number`, for programs whose
/// L blocks all have coordinates.
#pragma once

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../machine_position_text.hpp"
#include "../cutter_radius.hpp"
#include "../lexing.hpp"
#include "../machine_functions.hpp"
#include "../number.hpp"
#include "../program_end.hpp"
#include "../program_name.hpp"
#include "../text.hpp"
#include "../tool_length.hpp"
#include "../units.hpp"
#include "../work_offsets.hpp"
#include "lexer.hpp"
#include "tcpm_options.hpp"
#include "tool_name.hpp"
#include "write_options.hpp"

namespace kin5::program::heidenhain {

/// The error number written for another dialect's alarm stop: `FN 14: ERROR = 1`, among the
/// numbers 0 … 299 whose text is the control's plain "FN 14: ERROR CODE n", naming no cause of
/// its own (docs/dialects/heidenhain.md).
inline constexpr long long default_alarm_number = 1;

/// Writes blocks as Heidenhain conversational text one at a time, numbering them from 0 and
/// remembering the working plane, the last circle centre and the program name, so a program of
/// any length is written in constant memory. `write(program)` below is this writer applied to
/// every block.
class writer {
 public:
  /// A writer for blocks read from `source` (another dialect's passthrough text and kept words
  /// go into comments); `file` names the program in messages for blocks without a location.
  explicit writer(dialect_id source, std::string file = {}, const write_options& chosen = {})
      : same_(source == id_named("heidenhain")), program_file_(std::move(file)), options_(chosen) {}

  /// Appends the lines of block `b` to `out`. Throws `std::invalid_argument` naming the block
  /// (`file:line`) when it cannot be written in Heidenhain.
  void write(std::string& out, const block& b_mm) {
    const std::size_t bi = index_++;
    line_count_ = 0;
    const bool dwell_header = dwell_header_;  // the block before was a read CYCL DEF 9.0
    dwell_header_ = false;
    if (b_mm.framing) return;  // always another dialect's (`%`, `;$PATH=`): BEGIN/END PGM stand for it
    if (closed_) return after_end(b_mm, bi);
    if (!same_ && source_end_.after_end(b_mm)) return comment_after_end(out, b_mm);
    const bool opens = !begin_name_ && b_mm.program_begin && !b_mm.passthrough;
    if (!begin_name_ && !opens) open(out, options_.program_name);
    if (b_mm.passthrough) return passthrough(out, b_mm);
    if (b_mm.alarm) {  // a line of its own, before the block's other words (the alarm acts first)
      alarm(out, b_mm);
      if (b_mm.only_alarm()) return;
    }
    if (b_mm.state.dwell_s) return dwell(out, b_mm, bi, dwell_header);
    if (b_mm.feed_mode == feed_unit::inverse_time) fail(b_mm, bi, "inverse-time feed (G93)");
    if (opens) {
      begin_name_ = program_name(b_mm.program_begin);
      begin_unit(!b_mm.metric.value_or(options_.program_metric.value_or(true)));
      add("BEGIN PGM " + *begin_name_ + unit_word());
    }  // a later unit word says nothing: every block is written in BEGIN PGM's unit (`in_program_unit`)
    const block b = in_program_unit(b_mm);
    length_check(b, bi);
    radius_check(b, bi);
    if (b.state.work_offset) preset_selection(b, *b.state.work_offset, bi);
    state_words(b, bi);
    const bool dropped = carry_feed(b);
    const bool moves = is_move(b);
    std::vector<std::string> kept = b.kept_words;  // written verbatim (same dialect) or into the comment
    std::vector<std::string> foreign;
    if (!same_) foreign.swap(kept);
    const bool change = !same_ && changes_tool(b);
    if (change) tool_change(b, moves, bi);
    else if (b.tool && !same_) add("TOOL DEF " + std::to_string(*b.tool));  // selected, not changed
    if (!change && (((b.tool || b.tool_name) && same_) || b.spindle_rpm)) tool_call(b, moves, kept, bi, same_);
    if (b.tool) selected_tool_ = *b.tool, selected_name_.reset();
    if (b.tool_name) selected_name_ = *b.tool_name, selected_tool_.reset();
    const bool limit = b.machine_coordinates && b.machine_reference == machine_position::tool_axis_limit;
    if (b.machine_coordinates && b.machine_reference != machine_position::machine_zero && !limit &&
        !(same_ && b.machine_reference == machine_position::builder_position && std::find(b.m_codes.begin(), b.m_codes.end(), 92) != b.m_codes.end()))
      fail(b, bi, unwritable_machine_position(b));
    if (limit && (moves || b.tcp)) fail(b, bi, "M140 MB MAX with a move or a TCP switch in one block");
    const std::string m_words = (limit ? " M140 MB MAX" : "") + m_functions(b, bi) + end_word(b);
    if (b.tcp && options_.tcp) {
      // A chosen form replaces a read FUNCTION TCPM's options, which mean what M128 means.
      if (same_ && *b.tcp) std::erase_if(kept, is_tcpm_option);
      if (function_tcpm()) add(*b.tcp ? tcpm : reset_tcpm);
    }
    const bool arc = b.motion == motion_kind::arc_cw || b.motion == motion_kind::arc_ccw;
    if (b.arc && b.arc->centre_mm && !b.motion && b.axes.empty()) {
      add(cc_line(*b.arc));
    } else if (moves) {
      motion_line(b, kept, m_words, bi);
    } else if (b.tcp && *b.tcp && same_ && !options_.tcp && !kept.empty() && !says_m_function(b) &&
               !b.machine_coordinates) {
      std::string l = "FUNCTION TCPM";
      for (const std::string& w : kept) l += " " + w;
      kept.clear();
      add(l);
    } else if (!m_words.empty()) {
      add(std::string_view(m_words).substr(1));
    }
    if (b.arc && b.arc->centre_mm && !arc && (b.motion || !b.axes.empty()))
      fail(b, bi, "circle centre on a block that is not an arc");
    kept.insert(kept.end(), foreign.begin(), foreign.end());
    if (b.tcp) tcp_on_ = *b.tcp;
    if (b.program_end && same_) {  // END PGM: the text ends; `finish` writes the closing line
      closed_ = true;
      if (line_count_ == 0 && kept.empty()) return void(end_comment_ = b.comment);
    }
    emit(out, b, kept, dropped);
  }

  /// Appends the closing `END PGM name MM|INCH` to `out`, with BEGIN PGM's name (the control
  /// pairs them by name) and the comment of the source's END PGM line. Nothing for a program
  /// without a block.
  void finish(std::string& out) {
    if (!begin_name_) return;
    out += std::to_string(number_++) + " END PGM " + *begin_name_ + unit_word();
    if (end_comment_) {
      std::string c = *end_comment_;
      std::replace(c.begin(), c.end(), '\n', ' ');
      std::replace(c.begin(), c.end(), '\r', ' ');
      out += " ;" + without_continuation(c);
    }
    out += '\n';
    begin_name_.reset();
  }

 private:
  bool same_;  // the blocks were read as Heidenhain
  std::string program_file_;
  write_options options_;
  std::size_t index_ = 0;  // of the next block, for messages about blocks without a location
  long long number_ = 0;   // the next block number written
  arc_plane plane_ = arc_plane::xy;
  std::optional<vec3> centre_;
  std::optional<std::string> begin_name_;  // set once BEGIN PGM is written
  std::optional<std::string> end_comment_; // the comment on the source's END PGM line
  bool closed_ = false;                    // a Heidenhain END PGM was read: the program text ends
  source_end source_end_;                  // where another dialect's program stops running
  std::optional<bool> inch_;  // the unit BEGIN PGM said (INCH: true)
  std::optional<long long> selected_tool_;  // the last tool number written or selected
  std::optional<std::string> selected_name_;  // the last tool name selected (then no number)
  modal_state source_;                      // the source program's state after the block (another dialect's)
  std::optional<cutter_side> pending_radius_;  // RL/RR/R0 for the next move's L block
  cutter_side radius_written_ = cutter_side::off;  // the compensation the written text leaves in effect
  bool tcp_on_ = false;                     // M128 / FUNCTION TCPM in effect after the last block
  // From a coordinate-less block of another dialect, for the next move that has no F of its own.
  std::optional<double> pending_feed_;
  bool pending_rapid_ = false;
  // The source's motion mode is G0 (ISO, Siemens, LinuxCNC: modal; an L is one block's own).
  bool modal_rapid_ = false;
  std::vector<std::string> lines_;  // the block's lines, reused from block to block (see `add`)
  std::size_t line_count_ = 0;
  std::string line_;                // the motion line being built
  bool dwell_header_ = false;       // the last block written was a read `CYCL DEF 9.0` (passed through)

  /// Opens a program whose first block names none: `BEGIN PGM` with the name known ahead (or
  /// `PGM`) and the program's unit, a line of its own (TNC 620 User's Manual 10/2017 §4.2 p. 154:
  /// the first block is BEGIN PGM, name and unit, the last END PGM; docs/dialects/heidenhain.md).
  void open(std::string& out, const std::optional<std::string>& name) {
    begin_name_ = program_name(name);
    begin_unit(!options_.program_metric.value_or(true));
    out += std::to_string(number_++) + " BEGIN PGM " + *begin_name_ + unit_word() + "\n";
  }

  /// A G-code or APT program end (M2, M30, FINI) as the M function that ends the program run on
  /// a TNC (` M2`, else ` M30`); a Heidenhain END PGM is the frame's closing line instead.
  std::string end_word(const block& b) const {
    if (!b.program_end || same_) return {};
    return *b.program_end == "M2" ? " M2" : " M30";
  }

  /// A block after a Heidenhain END PGM: the control reads no further, so a blank line is
  /// dropped and anything else refused (it cannot come before the closing line unchanged).
  void after_end(const block& b, std::size_t bi) const {
    if (b.text.find_first_not_of(" \t\f\v\r\n") == std::string::npos && b.passthrough) return;
    fail(b, bi, "block after END PGM (the control reads a program only up to its END PGM)");
  }

  /// A block of another dialect after its end with no effect (`source_end`): its comment, if any,
  /// on a line of its own before END PGM.
  void comment_after_end(std::string& out, const block& b) {
    if (!b.comment || b.comment->empty()) return;
    std::string c = *b.comment;
    std::replace(c.begin(), c.end(), '\n', ' ');
    std::replace(c.begin(), c.end(), '\r', ' ');
    out += std::to_string(number_++) + " ;" + without_continuation(c) + "\n";
  }

  /// The program's unit, said once by BEGIN PGM: INCH makes lengths inches (one decimal more)
  /// and F 1/10 inch/min (TNC 620 User's Manual, "Feed rate F"; docs/dialects/heidenhain.md).
  void begin_unit(bool inch) {
    if (inch && !inch_.value_or(false)) options_.linear_decimals += 1;
    if (!inch && inch_.value_or(false)) options_.linear_decimals -= 1;
    inch_ = inch;
  }
  std::string unit_word() const { return inch_.value_or(false) ? " INCH" : " MM"; }

  /// `b` with its lengths and F in the program's unit (inches and 1/10 inch/min after BEGIN PGM
  /// … INCH). A TNC program has one unit, its BEGIN PGM's: a block of another dialect that
  /// changes the unit (Siemens `G700` after motion) is written in it too, exactly, since the
  /// model holds millimetres.
  block in_program_unit(const block& b) const {
    block u = b;
    if (!inch_.value_or(false)) return u;
    mm_to_inches(u, false);
    if (u.feed) *u.feed /= mm_per_inch / 10.0;
    return u;
  }

  [[noreturn]] void fail(const block& b, std::size_t bi, const std::string& what) const {
    const std::string at = b.where.line ? b.where.file + ":" + std::to_string(b.where.line)
                                        : (program_file_.empty() ? "block " : program_file_ + ": block ") +
                                              std::to_string(bi);
    throw std::invalid_argument(at + ": block cannot be written in heidenhain: " + what);
  }

  void add(std::string_view text) {
    if (line_count_ == lines_.size()) lines_.emplace_back();
    lines_[line_count_++].assign(text);
  }

  /// Appends ` X+1.5` to a line.
  static void put(std::string& l, std::string_view letters, double v, int decimals) {
    l += ' ';
    l.append(letters.data(), letters.size());
    append_number(l, v, decimals, true);
  }

  /// A passthrough block: its text (same dialect, without its block number) or a comment.
  void passthrough(std::string& out, const block& b) {
    std::string body = b.text;
    if (same_) {
      // Lines of blanks and `~` before the block number (`  ~\n14 Q1=2`) are dropped with it:
      // kept, they would continue the new number's line onto the old number. Without a number
      // after them they stay (`0 ~` then the text reads back as the same text).
      std::size_t k = 0;
      for (std::size_t e = 0;; k = ++e) {
        while (e < body.size() && (is_space(body[e]) || body[e] == '~')) ++e;
        if (e >= body.size() || body[e] != '\n') break;
      }
      k = lexing::skip_blanks(body, k);
      std::size_t d = k;
      while (d < body.size() && is_digit(body[d])) ++d;
      body.erase(0, d > k ? lexing::skip_blanks(body, d) : lexing::skip_blanks(body, 0));
      std::string words;  // upper case, without blanks: is it Cycle 9's header?
      for (char c : body.substr(0, 24))
        if (!is_space(c)) words += to_upper(c);
      dwell_header_ = words.rfind("CYCLDEF9.0", 0) == 0;
    } else {
      std::replace(body.begin(), body.end(), '\n', ' ');
      std::replace(body.begin(), body.end(), '\r', ' ');
      body = ";" + without_continuation(body);
    }
    out += std::to_string(number_++) + " " + body + "\n";
  }

  /// A program name: one word (`program_end` of a G-code dialect may hold its end word, no name).
  std::string program_name(const std::optional<std::string>& n) const {
    const bool named = n && !n->empty() && *n != "M2" && *n != "M30";
    std::string name = named ? *n : begin_name_.value_or("");
    if (name.empty()) name = "PGM";
    for (char& c : name)  // blanks and `;` become `_`
      if (is_space(c) || c == ';' || lexing::is_control(c)) c = '_';
    return name;
  }

  /// A block that moves: coordinates, or an arc, with a motion word, a rapid or a feed.
  static bool is_move(const block& b) {
    const bool coordless = b.axes.empty() && !b.arc;
    return !coordless && (b.motion || !b.axes.empty() || b.feed_rapid || (b.feed && !(b.tool || b.tool_name || b.spindle_rpm)));
  }

  /// An L needs end-point coordinates: a feed-only or rapid-only block (APT `FEDRAT/…`, `RAPID`;
  /// a lone G0 or F; a read `L F800`) is not written as `L F…` / `L FMAX`. Its F, modal here too,
  /// goes to the next move without one; its rapid to the next move as FMAX. True for such a block.
  bool carry_feed(const block& b) {
    const bool coordless = b.axes.empty() && !b.arc;
    if (!coordless) return false;
    if (b.feed && !(b.tool || b.tool_name || b.spindle_rpm)) pending_feed_ = b.feed;
    if (b.motion) modal_rapid_ = *b.motion == motion_kind::rapid;
    if (b.motion == motion_kind::rapid || b.feed_rapid) pending_rapid_ = true;
    else if (b.motion || b.feed) pending_rapid_ = false;
    return b.motion || b.feed_rapid || (b.feed && !(b.tool || b.tool_name || b.spindle_rpm));
  }

  /// A tool change of another dialect (M6, `LOADTL`): `TOOL CALL n Z S… F…`, the spindle along Z
  /// (the G-code dialects and APT name no spindle axis), with TCP switched off before it and on
  /// again after it when TCP is on (the TNC refuses a TOOL CALL under M128: TNC 640 User's
  /// Manual, M128 / FUNCTION TCPM). n is the block's T or the tool selected before (`T5` … `M6`).
  void tool_change(const block& b, bool moves, std::size_t bi) {
    const std::optional<long long> tool = b.tool ? b.tool : b.tool_name ? std::nullopt : selected_tool_;
    const std::optional<std::string> name = b.tool_name ? b.tool_name : b.tool ? std::nullopt : selected_name_;
    if (!tool && !name) fail(b, bi, "tool change (M6) without a tool number");
    if (tool && *tool < 0) fail(b, bi, "tool number " + std::to_string(*tool) + " cannot be written");
    if (tcp_on_) add(function_tcpm() ? reset_tcpm : "M129");
    std::string l = "TOOL CALL " + (tool ? std::to_string(*tool) : quoted_tool_name(b, *name, bi)) + " Z";
    plane_ = arc_plane::xy;
    if (b.spindle_rpm) l += " S" + format_number(*b.spindle_rpm, rate(*b.spindle_rpm, "spindle speed"));
    if (b.feed && !moves) l += " F" + format_number(*b.feed, rate(*b.feed));
    add(l);
    if (tcp_on_ && !b.tcp) add(function_tcpm() ? tcpm : "M128");
  }

  /// Absolute positions are what the writer's text always says (no `I` prefix: TNC 640 User's
  /// Manual, "Absolute/incremental coordinates"), so G90 needs no word; incremental positioning
  /// is refused. Radius compensation switched on or off waits for the next move (`radius_word`).
  /// The working plane needs no word either: `TOOL CALL … Z` makes it XY, every circle names its
  /// own plane in its CC line, and a radius arc (CR) outside XY is refused where it stands
  /// (`arc_keyword`), so a G18 or G19 leaves nothing the text would read otherwise.
  void state_words(const block& b, std::size_t bi) const {
    const auto& s = b.state;
    if (s.distance == distance_mode::incremental) fail(b, bi, "incremental positioning (G91)");
  }

  /// Another dialect's cutter radius compensation: a TNC compensates with the called tool's
  /// radius, R + DR (iTNC 530 DIN/ISO User's Manual 6/2010 §5.3 "Tool compensation", p. 183), so
  /// a radius of another register (ISO `G41 D5` with tool 1 called) is refused at the block that
  /// says it and at each move under it, as is a change of side without `R0` between (the TNC
  /// manuals describe switching on from `R0` only). The side goes on the block's move, or waits
  /// for the next.
  void radius_check(const block& b, std::size_t bi) {
    const auto& side = b.state.radius_compensation;
    if (!same_ && radius_in_effect(source_) == tool_radius::other && ((side && *side != cutter_side::off) || is_motion(b)))
      fail(b, bi, "cutter radius compensation " + radius_register_text(source_) +
                      " (a TNC compensates with the called tool's own radius, from TOOL CALL)");
    const cutter_side now = pending_radius_.value_or(radius_written_);
    if (!same_ && side && *side != cutter_side::off && now != cutter_side::off && *side != now)
      fail(b, bi, "cutter radius compensation changes side without being switched off (G40, R0) between: a TNC "
                  "switches RL/RR on from R0");
    if (side) pending_radius_ = *side == radius_written_ ? std::nullopt : side;
  }

  /// `RL`, `RR` or `R0` on the straight-line block `l` of the move after a switch: a TNC switches
  /// radius compensation only there (TNC 620 ISO Programming User's Manual 340 56x-02, "Radius
  /// compensation", p. 154: not in a circle block; iTNC 530 §5.3 p. 183: R0 in a straight line
  /// cancels it); it stays in effect until the next switch.
  void radius_word(std::string& l, const block& b, bool straight, std::size_t bi) {
    if (!pending_radius_) return;
    const cutter_side side = *pending_radius_;
    if (!straight)
      fail(b, bi, std::string("cutter radius compensation ") + (side == cutter_side::off ? "cancelled" : "switched on") +
                      " for a circular or LN move: a TNC switches it only in a straight-line block L");
    l += side == cutter_side::left ? " RL" : side == cutter_side::right ? " RR" : " R0";
    radius_written_ = side;
    pending_radius_.reset();
  }

  /// Cycle 9, a dwell: `CYCL DEF 9.0 DWELL TIME` (unless `header`: the block just written is a
  /// Heidenhain source's own 9.0, passed through) and `CYCL DEF 9.1 DWELL 1.5`, blocks of their
  /// own (TNC 640 User's Manual for Cycle Programming, Cycle 9 DWELL TIME); refused with other
  /// words, or outside 0 to 3600 s in steps of 0.001 s (`detail::dwell_steps`).
  void dwell(std::string& out, const block& b, std::size_t bi, bool header) {
    if (!b.only_dwell()) fail(b, bi, "a dwell with other words (Cycle 9 takes blocks of its own)");
    if (const std::string why = dwell_refusal(detail::dwell_steps, *b.state.dwell_s); !why.empty()) fail(b, bi, why);
    if (!header) add("CYCL DEF 9.0 DWELL TIME");
    add("CYCL DEF 9.1 DWELL " + format_number(*b.state.dwell_s, detail::dwell_steps.decimals));
    emit(out, b, {}, false);
  }

  /// Another dialect's tool length compensation: a TNC applies the called tool's own length from
  /// TOOL CALL on, always (TNC 620 User's Manual 73498x-01 §5.3 "Tool compensation", p. 164: it
  /// is cancelled only by calling a tool of length 0), so G43 for that tool needs no word. A length of another
  /// register (ISO `G43 H5` with tool 1 called, or before any tool call) is refused at the block
  /// that says it and at each move under it; a move with the length switched off (G49), whose
  /// point is the spindle's gauge point, is refused too.
  void length_check(const block& b, std::size_t bi) {
    if (same_) return;
    source_.apply(b);
    const tool_length t = length_in_effect(source_);
    if (t == tool_length::other && (b.state.length_compensation == true || is_motion(b)))
      fail(b, bi, "tool length compensation " + length_register_text(source_) +
                      " (a TNC applies the called tool's own length, from TOOL CALL)");
    if (t == tool_length::off && is_motion(b))
      fail(b, bi, "a move with tool length compensation off (G49): a TNC applies the called tool's length, so the "
                  "point would be the tool tip instead of the spindle's gauge point");
  }

  /// A preset table row selected by Cycle 247 (TNC 640 User's Manual for Cycle Programming,
  /// Cycle 247 DATUM SETTING), its Q339 on a continued line; any other selection is refused.
  void preset_selection(const block& b, const work_offset& w, std::size_t bi) {
    if (w.family != work_offset_family::preset || w.number < 0 || w.number > 65535)
      fail(b, bi, "work offset " + kin5::program::spelling(w) + " has no Heidenhain form (--work-offset-map names a preset)");
    add("CYCL DEF 247 DATUM SETTING ~\n  Q339=+" + std::to_string(w.number));
  }

  void tool_call(const block& b, bool moves, std::vector<std::string>& kept, std::size_t bi, bool with_tool) {
    std::string l = "TOOL CALL";
    if (b.tool && with_tool) {
      if (*b.tool < 0) fail(b, bi, "tool number " + std::to_string(*b.tool) + " cannot be written");
      l += " " + std::to_string(*b.tool);
    }
    if (b.tool_name && with_tool) l += " " + quoted_tool_name(b, *b.tool_name, bi);
    if (!moves) {
      for (const std::string& w : kept) {
        l += " " + w;
        if (w == "Z") plane_ = arc_plane::xy;
        if (w == "Y") plane_ = arc_plane::zx;
        if (w == "X") plane_ = arc_plane::yz;
      }
      kept.clear();
    }
    if (b.spindle_rpm) l += " S" + format_number(*b.spindle_rpm, rate(*b.spindle_rpm, "spindle speed"));
    if (b.feed && !moves) l += " F" + format_number(*b.feed, rate(*b.feed));
    add(l);
  }

  /// `"MILL_D10"`: a tool name as TOOL CALL takes it (tool_name.hpp); else the block of another
  /// dialect fails (a name read from a TNC program is written back as read).
  std::string quoted_tool_name(const block& b, const std::string& name, std::size_t bi) const {
    if (!same_ && !is_tnc_tool_name(name))
      fail(b, bi, "tool name '" + (std::all_of(name.begin(), name.end(), [](char c) { return c >= 0x20 && c < 0x7f; })
                                       ? name : std::string("…")) +
                      "' cannot be written in TOOL CALL: a TNC tool name is up to 32 of A-Z 0-9 # $ % & , - _ .");
    return '"' + name + '"';
  }

  bool function_tcpm() const { return options_.tcp == tcp_word::function_tcpm; }

  /// ` M3 M8 M91 M128`: the block's M functions, M91 for machine coordinates, M128/M129 for TCP
  /// (with `tcp_word::function_tcpm`, `write` puts the switch on a block of its own instead).
  std::string m_functions(const block& b, std::size_t bi) const {
    std::string m_words;
    std::vector<int> ms;
    // A TNC has no standard M7; M6 only for a TNC program's own M6 line (TOOL CALL is the change).
    const std::string why = m_words_of(b, {.m7_mist = false}, same_ && !b.tool && !b.tool_name, ms);
    if (!why.empty()) fail(b, bi, why);
    for (int m : ms)
      if (!(m == 6 && (b.tool || b.tool_name || !same_))) m_words += " M" + std::to_string(m);  // TOOL CALL is the change: no M6
    if (b.machine_coordinates && b.machine_reference != machine_position::tool_axis_limit &&
        std::find_if(b.m_codes.begin(), b.m_codes.end(), [](int m) { return m == 91 || m == 92; }) == b.m_codes.end())
      m_words += " M91";
    if (b.tcp && !function_tcpm()) m_words += *b.tcp ? " M128" : " M129";
    return m_words;
  }

  std::string cc_line(const arc_words& a) {
    const vec3& c = *a.centre_mm;
    std::string l = "CC";
    if (a.plane != arc_plane::yz) put(l, "X", c.x, options_.linear_decimals);
    if (a.plane != arc_plane::zx) put(l, "Y", c.y, options_.linear_decimals);
    if (a.plane != arc_plane::xy) put(l, "Z", c.z, options_.linear_decimals);
    plane_ = a.plane;
    centre_ = c;
    return l;
  }

  /// The L, LN, C or CR line of a move (with a CC line first when the centre is new).
  void motion_line(const block& b, std::vector<std::string>& kept, const std::string& m_words, std::size_t bi) {
    std::string& l = line_;
    const bool arc = b.motion == motion_kind::arc_cw || b.motion == motion_kind::arc_ccw;
    l = arc ? arc_keyword(b, bi) : b.axes.tool_axis || has_normal(kept) ? "LN" : "L";
    const axis_words& a = b.axes;
    if (a.x_mm) put(l, "X", *a.x_mm, options_.linear_decimals);
    if (a.y_mm) put(l, "Y", *a.y_mm, options_.linear_decimals);
    if (a.z_mm) put(l, "Z", *a.z_mm, options_.linear_decimals);
    if (a.a_deg) put(l, "A", *a.a_deg, options_.angle_decimals);
    if (a.b_deg) put(l, "B", *a.b_deg, options_.angle_decimals);
    if (a.c_deg) put(l, "C", *a.c_deg, options_.angle_decimals);
    for (const std::string& w : kept)
      if (!w.empty() && to_upper(w[0]) == 'N') l += " " + w;
    if (a.tool_axis) {
      put(l, "TX", a.tool_axis->x, options_.vector_decimals);
      put(l, "TY", a.tool_axis->y, options_.vector_decimals);
      put(l, "TZ", a.tool_axis->z, options_.vector_decimals);
    }
    if (arc && b.arc->radius_mm) put(l, "R", *b.arc->radius_mm, options_.linear_decimals);
    if (arc) l += b.motion == motion_kind::arc_cw ? " DR-" : " DR+";
    for (const std::string& w : kept)
      if (w.empty() || to_upper(w[0]) != 'N') l += " " + w;
    kept.clear();
    radius_word(l, b, l.starts_with("L "), bi);
    feed_word(l, b, bi);
    l += m_words;
    add(l);
  }

  static bool has_normal(const std::vector<std::string>& kept) {
    return std::any_of(kept.begin(), kept.end(), [](const std::string& w) { return !w.empty() && to_upper(w[0]) == 'N'; });
  }

  /// `C` (with a CC line first when the centre or plane is new) or `CR`.
  std::string arc_keyword(const block& b, std::size_t bi) {
    if (!b.arc || (!b.arc->centre_mm && !b.arc->radius_mm)) fail(b, bi, "arc has neither a centre nor a radius");
    if (b.axes.tool_axis) fail(b, bi, "an arc cannot carry a tool-axis vector");
    if (b.arc->radius_mm) {
      if (b.arc->plane != plane_) fail(b, bi, "radius arc outside the working plane");
      return "CR";
    }
    if (!centre_ || !(*centre_ == *b.arc->centre_mm) || plane_ != b.arc->plane) add(cc_line(*b.arc));
    return "C";
  }

  /// Decimals of a feed or spindle speed `v` (`rate_decimals`).
  int rate(double v, std::string_view what = "feed") const {
    return rate_decimals(v, options_.feed_decimals, options_.finest_feed_decimals, what);
  }

  /// ` F…`, ` FMAX`, or the F carried from a coordinate-less block.
  void feed_word(std::string& l, const block& b, std::size_t bi) {
    // A move without a motion word of its own is at rapid traverse under a modal G0 of the
    // source: FMAX holds for its block only, so each such block says it again.
    if (b.motion) modal_rapid_ = *b.motion == motion_kind::rapid;
    const bool modal_rapid = !same_ && !b.motion && modal_rapid_;
    if (b.feed && (b.feed_rapid || b.motion == motion_kind::rapid)) fail(b, bi, "block has both a feed and rapid traverse");
    if (modal_rapid && b.feed) {  // `X10 F200` under G0: a rapid; F200 is for the next feed move
      l += " FMAX";
      pending_feed_ = b.feed;
      pending_rapid_ = false;
      return;
    }
    const bool rapid = b.feed_rapid || b.motion == motion_kind::rapid || modal_rapid || (pending_rapid_ && !b.motion && !b.feed);
    if (b.feed) l += " F", append_number(l, *b.feed, rate(*b.feed));
    else if (rapid) l += " FMAX";
    else if (pending_feed_) l += " F", append_number(l, *pending_feed_, rate(*pending_feed_));
    if (!rapid) pending_feed_.reset();
    pending_rapid_ = false;
  }

  /// `5 FN 14: ERROR = 1 ;MESSAGE`: an alarm stop, its number the source's (a Heidenhain
  /// program's) or `default_alarm_number`, the message the line's comment, as the reader takes it
  /// (FN 14 shows the control's text of its number; docs/dialects/heidenhain.md).
  void alarm(std::string& out, const block& b) {
    const alarm_stop& a = *b.alarm;
    std::string line = std::to_string(number_++) + " FN 14: ERROR = " + std::to_string(a.number.value_or(default_alarm_number));
    if (!a.message.empty()) {
      std::string message = a.message;
      std::replace(message.begin(), message.end(), '\n', ' ');
      std::replace(message.begin(), message.end(), '\r', ' ');
      line += " ;" + without_continuation(message);
    }
    out += line + '\n';
  }

  /// The block's lines, numbered, the comment (and kept words) on the last.
  void emit(std::string& out, const block& b, const std::vector<std::string>& kept, bool dropped_move) {
    std::string comment = b.comment.value_or("");
    std::replace(comment.begin(), comment.end(), '\n', ' ');
    std::replace(comment.begin(), comment.end(), '\r', ' ');
    if (!kept.empty()) {
      std::string k;
      for (const std::string& w : kept) k += (k.empty() ? "" : " ") + w;
      comment += (b.comment ? " " : "") + std::string("kept: ") + k;
    }
    bool has_comment = b.comment || !kept.empty();
    // A block that says something (units, a feed mode, a move without coordinates) with nothing
    // Heidenhain can write for it — APT `UNITS/MM`, a lone `RAPID` — becomes its source text as a
    // comment; a translated program's blocks keep their source text, whatever the dialect.
    const bool unsaid = !same_ || dropped_move || b.metric || b.feed_mode;
    if (line_count_ == 0 && !has_comment && unsaid && !b.text.empty() && !b.alarm) {
      std::size_t k = 0;  // without a Heidenhain block number
      if (same_)
        while (k < b.text.size() && (is_digit(b.text[k]) || is_space(b.text[k]))) ++k;
      comment = b.text.substr(k);
      std::replace(comment.begin(), comment.end(), '\n', ' ');
      std::replace(comment.begin(), comment.end(), '\r', ' ');
      has_comment = true;
    }
    if (line_count_ == 0 && !has_comment && (!same_ || b.alarm)) return;  // nothing to say, no source text (APT MULTAX)
    if (line_count_ == 0) add("");
    for (std::size_t k = 0; k < line_count_; ++k) {
      char digits[24];
      out.append(digits, std::to_chars(digits, digits + sizeof digits, number_++).ptr);
      if (!lines_[k].empty()) out += ' ', out += lines_[k];
      if (k + 1 == line_count_ && has_comment) out += " ;", out += without_continuation(comment);
      out += '\n';
    }
  }
};

/// Writes `p` as a Heidenhain conversational program, blocks numbered from 0, in its frame
/// (`BEGIN PGM` first, `END PGM` last).
/// Throws std::invalid_argument naming the block (`file:line`) when a block cannot be written.
inline std::string write(const program& p, const write_options& options = {}) {
  write_options chosen = options;
  if (!chosen.program_metric) {
    program_unit unit;
    for (const block& b : p.blocks) unit.take(b);
    chosen.program_metric = unit.metric;
  }
  if (!chosen.program_name) {
    program_name name;
    for (const block& b : p.blocks) name.take(b);
    chosen.program_name = name.name();
  }
  writer w(p.language, p.file, chosen);
  std::string out;
  for (const block& b : p.blocks) w.write(out, b);
  w.finish(out);
  return out;
}

}  // namespace kin5::program::heidenhain
