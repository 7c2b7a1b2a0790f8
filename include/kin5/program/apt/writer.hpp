/// @file program/apt/writer.hpp
/// Blocks written as APT CL data, one statement per line, no continuations. After a block that
/// says inch (`metric == false`, written `UNITS/INCHES`) GOTO points are written in inches and
/// per-minute feeds as `FEDRAT/IPM`, each with one decimal more. A feed under inverse time (from
/// the block or an earlier one) is `FEDRAT/INVERS`. An M function of a moving block is written
/// before or after its GOTO, where the source's controller runs it (`machine_functions`).
/// An arc is `CIRCLE/xc,yc,zc,i,j,k,r` then the GOTO of its end (circle.hpp). What has no APT
/// form is refused (std::invalid_argument naming the block): rotary axis words, an M function
/// without a statement, a move in machine coordinates, a tool by name, a kept word a comment
/// would lose; only text that moves nothing becomes a `$$` comment (docs/dialects/apt.md,
/// "Writing": comments, passthrough text, tracking switches, plane and mode words). Another
/// dialect's frame (`%`, `;$PATH=`) is not copied, and a block of another dialect after its end
/// is refused unless it is only a comment (program_end.hpp); one that gives no end gets `FINI`
/// last (`finish`). A dwell is `DELAY/t`.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../machine_functions.hpp"
#include "../number.hpp"
#include "../program_end.hpp"
#include "../text.hpp"
#include "../tool_length.hpp"
#include "../units.hpp"
#include "../work_offsets.hpp"
#include "circle.hpp"
#include "vocabulary.hpp"

namespace kin5::program::apt {

struct dialect;  // this folder's entry of `program::dialects` (dialect.hpp)

/// Decimals written for each kind of number.
struct write_options {
  int linear_decimals = 3;   ///< GOTO x, y, z (mm)
  int angle_decimals = 3;    ///< unused: APT has no angle words
  int feed_decimals = 1;     ///< FEDRAT and SPINDL values
  int finest_feed_decimals = detail::finest_rate_decimals;  ///< more decimals for a small F or S, up to these (rate_decimals)
  int vector_decimals = 7;   ///< GOTO i, j, k
};

/// Writes blocks as APT CL data one at a time, remembering whether a RAPID is pending, so a
/// program of any length is written in constant memory. `write(program)` below is this writer
/// applied to every block.
class writer {
 public:
  /// A writer for blocks read from `source` (another dialect's blocks keep their text in `$$`
  /// comments). Blocks name themselves in messages: `file` is not needed.
  explicit writer(dialect_id source, std::string file = {}, const write_options& chosen = {})
      : same_(source == id_named("apt")),
        source_language_(source),
        off_first_(controller_from<dialect>(source).spindle_off_before_motion),
        options_(chosen) {
    static_cast<void>(file);
  }

  /// Ends the CL data of another dialect's program that gave no end (an ISO or LinuxCNC file that
  /// stops at its `%`) with `FINI`, the last statement of CL data (A1). Call once, after the last
  /// `write`.
  void finish(std::string& out) {
    if (!same_ && !finished_ && !end_.ended()) out += "FINI\n";
    finished_ = true;
  }

  /// Appends the statements of block `b` to `out`. Throws `std::invalid_argument` naming the
  /// block's `file:line` when it cannot be written in APT.
  void write(std::string& out, const block& b) {
    if (!same_) {
      if (b.framing) return;  // another dialect's frame: CL data have none
      if (end_.after_end(b)) {
        if (b.comment && !b.comment->empty()) out += "$$ " + flat(*b.comment) + '\n';
        return;
      }
    }
    if (b.passthrough) {
      if (same_) out += b.text + '\n', ended_.reset();  // a statement: it ends an arc's record
      else out += "$$ " + flat(b.text) + '\n';
      if (b.comment && !same_) out += "$$ " + one_line(b, *b.comment) + '\n';
      return;
    }
    // An alarm stop is a control's, not the part's: ISO 4343 and the APT vocabulary have no
    // statement that stops the program with an alarm (`STOP` waits for the operator to go on).
    if (b.alarm)
      fail(b, "an alarm stop (\"" + one_line(b, b.alarm->message) +
                  "\") has no APT form (CL data have no alarm: end the program before it, or translate to an NC "
                  "dialect)");
    if (b.state.dwell_s) return ended_.reset(), dwell(out, b);
    if (b.tool_name)
      fail(b, "a tool by name (\"" + one_line(b, *b.tool_name) +
                  "\") has no APT form (LOADTL takes a number; --tool-map NAME=n gives one)");
    // CL data are in the part's frame: APT has no statement that selects a work offset.
    if (b.state.work_offset) fail(b, "work offset " + spelling(*b.state.work_offset) + " has no APT form");
    // GOTO points are absolute tip positions and arcs are not written, so absolute mode, the
    // working plane and a radius compensation cancel change nothing in CL data; incremental
    // positioning would. Compensation on is refused: a GOTO point is the tool's position (ISO
    // 3592), while a compensated program's points are the contour (docs/dialects/compensation.md).
    if (b.state.distance == distance_mode::incremental) fail(b, "incremental positioning (G91) has no APT form");
    if (b.state.radius_compensation && *b.state.radius_compensation != cutter_side::off)
      fail(b, "cutter radius compensation (G41/G42): a GOTO point is the tool's position, and the program's points "
              "are the contour it offsets");
    length_check(b);
    lines_.clear();
    after_.clear();
    foreign_note_ = ends_ = false;
    if (b.metric) inch_ = !*b.metric;
    if (b.feed_mode) inverse_time_ = *b.feed_mode == feed_unit::inverse_time;
    block in_unit = b;
    if (inch_) mm_to_inches(in_unit, !inverse_time_);
    setup(in_unit);
    machine_functions(in_unit);
    feed(in_unit);
    kept_words(in_unit);
    motion(in_unit);
    lines_.insert(lines_.end(), after_.begin(), after_.end());  // what acts at the block's end
    if (b.program_end || ends_) lines_.push_back("FINI");
    if (foreign_note_) lines_.insert(lines_.begin(), "$$ " + flat(b.text));
    if (b.comment) {
      if (lines_.empty() || (foreign_note_ && lines_.size() == 1)) lines_.push_back("$$ " + one_line(b, *b.comment));
      else lines_.back() += " $$ " + one_line(b, *b.comment);
    }
    if (lines_.empty() && !b.text.empty() && !same_) lines_.push_back("$$ " + flat(b.text));
    for (const std::string& l : lines_) {
      out += l + '\n';
      if (l.rfind("GOTO/", 0) != 0 && l.rfind("$$", 0) != 0) ended_.reset();  // a statement ends the arc's record
      else if (l.rfind("GOTO/", 0) == 0) ended_ = goto_ended_;
    }
  }

 private:
  bool same_;       // the blocks were read as APT
  dialect_id source_language_;  // the dialect they were read in
  bool off_first_;  // the source's controller runs M5, M9 and M6 before a block's move (LinuxCNC)
  write_options options_;
  source_end end_;  // where another dialect's program stops running
  bool finished_ = false;  // `finish` has run
  bool rapid_pending_ = false;
  std::optional<long long> selected_tool_;  // the last tool number written
  modal_state source_;                      // the source program's state after the block (another dialect's)
  bool inch_ = false;          // UNITS/INCHES written: lengths in inches
  bool inverse_time_ = false;  // inverse-time feed in effect (this block's or an earlier one's)
  std::optional<bool> fedrat_inverse_;  // whether the last FEDRAT written was INVERS
  std::string fedrat_;                  // the last FEDRAT written
  std::optional<detail::circle_state::circle> ended_;  // the circle the last GOTO ended an arc on
  std::optional<detail::circle_state::circle> goto_ended_;  // that of this block's GOTO, if an arc's
  std::vector<std::string> lines_;  // the block's statements up to its GOTO
  std::vector<std::string> after_;  // those after it: the M functions that act at the block's end
  bool foreign_note_ = false;       // something without an APT form: carry the block's text
  bool ends_ = false;               // an M2 / M30 M function: the end of the program run
  std::optional<vec3> at_;          // the last GOTO's point, in the unit written
  vec3 axis_ = unit_z;              // the tool axis in effect (+Z until a GOTO gives one)

  [[noreturn]] static void fail(const block& b, const std::string& why) {
    throw std::invalid_argument(b.where.file + ":" + std::to_string(b.where.line) + ": block cannot be written in APT: " + why);
  }

  /// Another dialect's source text as one comment line: a block continued over lines
  /// (Heidenhain `~`) has its line breaks as blanks.
  static std::string flat(std::string s) {
    for (char& c : s)
      if (c == '\n' || c == '\r') c = ' ';
    return s;
  }

  static const std::string& one_line(const block& b, const std::string& s) {
    if (s.find_first_of("\r\n") != std::string::npos) fail(b, "line break in text");
    return s;
  }

  /// `DELAY/1.5 $$ comment`: a dwell, seconds (PTC Creo Parametric Help, "Supported CL Data
  /// Commands": DELAY), a statement of its own; refused with other words.
  static void dwell(std::string& out, const block& b) {
    if (!b.only_dwell()) fail(b, "a dwell with other words (DELAY is a statement of its own)");
    if (const std::string why = dwell_refusal(detail::dwell_steps, *b.state.dwell_s); !why.empty()) fail(b, why);
    out += "DELAY/" + format_number(*b.state.dwell_s, detail::dwell_steps.decimals);
    if (b.comment) out += " $$ " + one_line(b, *b.comment);
    out += '\n';
  }

  /// Another dialect's tool length compensation: a GOTO point is the tip of the tool loaded
  /// (LOADTL; ISO 4343:2000, ISO 3592: CL data are tool positions), so G43
  /// for that tool needs no statement. A length of another register (ISO `G43 H5` with tool 1
  /// loaded, or before any tool change) is refused at the block that says it and at each move
  /// under it; a move with the length switched off (G49), whose point is the spindle's gauge
  /// point, is refused too.
  void length_check(const block& b) {
    if (same_) return;
    source_.apply(b);
    const tool_length t = length_in_effect(source_);
    if (t == tool_length::other && (b.state.length_compensation == true || is_motion(b)))
      fail(b, "tool length compensation " + length_register_text(source_) + " (a GOTO point is the loaded tool's tip)");
    if (t == tool_length::off && is_motion(b))
      fail(b, "a move with tool length compensation off (G49): its point is the spindle's gauge point, and a GOTO "
              "point is the tool tip");
  }

  /// PARTNO, APT's own kept statements (MULTAX), UNITS/MM, LOADTL.
  void setup(const block& b) {
    if (same_) lines_.insert(lines_.end(), b.kept_words.begin(), b.kept_words.end());
    if (b.program_begin) {
      const std::string& name = one_line(b, *b.program_begin);
      lines_.push_back(name.empty() ? "PARTNO" : name.front() == '/' ? "PARTNO/" + name : "PARTNO " + name);
    }
    if (b.metric) lines_.push_back(*b.metric ? "UNITS/MM" : "UNITS/INCHES");
    // LOADTL is the change (M6, TOOL CALL n); a T alone only selects: SELECT/TOOL.
    const bool change = changes_tool(b);
    if (b.tool) selected_tool_ = *b.tool;
    if (change && !selected_tool_) fail(b, "tool change (M6) without a tool number");
    if (change) lines_.push_back("LOADTL/" + std::to_string(*selected_tool_));
    else if (b.tool) lines_.push_back("SELECT/TOOL," + std::to_string(*b.tool));
  }

  /// SPINDL, COOLNT, STOP, OPSTOP from S and the M codes APT has a statement for, each on the
  /// side of a moving block's GOTO where the source's controller runs it (docs/dialects/apt.md,
  /// "M functions on a moving block"): what switches on before it; STOP and OPSTOP after it;
  /// SPINDL/OFF and COOLNT/OFF after it too, but before it from LinuxCNC. A tool change beside a
  /// move is refused unless the controller runs it first: elsewhere the machine maker chooses.
  /// M2 / M30 (a Heidenhain line's end of the program run) is FINI.
  void machine_functions(const block& b) {
    const std::string rpm =
        b.spindle_rpm ? format_number(*b.spindle_rpm, rate_decimals(*b.spindle_rpm, options_.feed_decimals,
                                                                    options_.finest_feed_decimals, "spindle speed"))
                      : "";
    bool rpm_written = !b.spindle_rpm;
    std::vector<int> ms;
    if (const std::string why = m_words_of(b, {}, true, ms); !why.empty()) fail(b, why);
    for (int m : ms) {
      if (m == 3 || m == 4) {
        lines_.push_back("SPINDL/" + (rpm_written ? "" : rpm + ",") + (m == 3 ? "CLW" : "CCLW"));
        rpm_written = true;
      } else if (m == 5) (off_first_ ? lines_ : after_).push_back("SPINDL/OFF");
      else if (m == 8) lines_.push_back("COOLNT/ON");
      else if (m == 7) lines_.push_back("COOLNT/MIST");
      else if (m == 9) (off_first_ ? lines_ : after_).push_back("COOLNT/OFF");
      else if (m == 0) after_.push_back("STOP");
      else if (m == 1) after_.push_back("OPSTOP");
      else if (m == 6 && b.moves() && !off_first_) fail(b, "tool change (M6) in a block that moves (before or after the move?)");
      else if (m == 6) continue;  // LOADTL is the tool change: no M6 beside it
      else if (m == 2 || m == 30) ends_ = true;  // a Heidenhain line's end of the program run: FINI
      else fail(b, "M function M" + std::to_string(m) + " has no APT statement");
    }
    if (!rpm_written) lines_.push_back("SPINDL/" + rpm);
  }

  /// `CIRCLE/xc,yc,zc,i,j,k,r` of arc block `b` ending at `end` (PTC Creo, "CL Output for
  /// Circular Interpolation"): the centre, the plane's normal (− for clockwise: the right-hand
  /// rule), the radius the mean of the start's and the end's, so that each lies within the
  /// reader's tolerance of it whenever it lay so of the radius read; the centre at the start's
  /// height along the normal, as Creo writes it (a rise to the end is a helix). Refused without
  /// a centre or a start, with start and end more than twice the tolerance apart in radius, or
  /// with a tool axis other than the one in effect.
  std::string circle(const block& b, const vec3& end, int decimals) const {
    if (!b.arc || !b.arc->centre_mm || !(b.motion == motion_kind::arc_cw || b.motion == motion_kind::arc_ccw))
      fail(b, "an arc without its centre or direction (CIRCLE needs both)");
    if (!at_) fail(b, "an arc whose start point is not known (CIRCLE follows the GOTO of its start)");
    if (b.axes.tool_axis && norm(normalized(*b.axes.tool_axis) - normalized(axis_)) > 1e-6)
      fail(b, "the tool axis changes during the arc (CIRCLE keeps the tool axis)");
    const arc_plane plane = b.arc->plane;
    vec3 c = *b.arc->centre_mm;
    (plane == arc_plane::xy ? c.z : plane == arc_plane::zx ? c.y : c.x) =
        plane == arc_plane::xy ? at_->z : plane == arc_plane::zx ? at_->y : at_->x;
    const double tolerance = detail::circle_tolerance_mm / (inch_ ? mm_per_inch : 1.0);
    const double r_end = detail::radius_in_plane_mm(plane, c, end), r_start = detail::radius_in_plane_mm(plane, c, *at_);
    const double r = (r_start + r_end) / 2.0;
    if (r <= tolerance || std::fabs(r_end - r_start) > 2.0 * tolerance)
      fail(b, "the arc's start and end are not on one circle about its centre (radii " + format_number(r_start, decimals) +
                  " and " + format_number(r_end, decimals) + ")");
    const vec3 n = detail::plane_vector(plane, b.motion == motion_kind::arc_cw);
    return "CIRCLE/" + format_number(c.x, decimals) + "," + format_number(c.y, decimals) + "," +
           format_number(c.z, decimals) + "," + format_number(n.x, 0) + "," + format_number(n.y, 0) + "," +
           format_number(n.z, 0) + "," + format_number(r, decimals);
  }

  /// Before the GOTO of a straight feed move to `end` right after an arc: when it ends elsewhere
  /// on that arc's circle, a reader takes it for a further point of the arc (circle.hpp), so the
  /// FEDRAT in effect is said again, which ends the arc's record and changes no feed.
  void separate_from_arc(const vec3& end) {
    if (!ended_ || !at_) return;
    const double tolerance = detail::circle_tolerance_mm / (inch_ ? mm_per_inch : 1.0);
    const bool on_circle =
        std::fabs(detail::radius_in_plane_mm(ended_->plane, ended_->centre_mm, end) - ended_->radius_mm) <= tolerance;
    if (!on_circle || detail::radius_in_plane_mm(ended_->plane, *at_, end) <= tolerance) return;
    for (const std::string& l : lines_)
      if (l.rfind("$$", 0) != 0) return;  // a statement of the block's own before it ends the record
    if (!fedrat_.empty()) lines_.push_back(fedrat_);
  }

  /// FEDRAT/MMPM,f or FEDRAT/INVERS,f.
  void feed(const block& b) {
    if (b.feed) {
      const char* mode = inverse_time_ ? "INVERS," : inch_ ? "IPM," : "MMPM,";
      const int inch = inch_ ? 1 : 0;
      const int decimals = rate_decimals(*b.feed, options_.feed_decimals + inch, options_.finest_feed_decimals + inch);
      lines_.push_back(std::string("FEDRAT/") + mode + format_number(*b.feed, decimals));
      fedrat_ = lines_.back();
      fedrat_inverse_ = inverse_time_;
    } else if (b.feed_mode) {
      foreign_note_ = true;  // the unit goes with the next FEDRAT (`motion` refuses a feed move without one)
    }
    if (b.tcp) foreign_note_ = true;  // CL data are tool-tip data: a tracking switch has no statement
  }

  /// Another dialect's kept words: the block's text as a `$$` comment when they are harmless
  /// there (plane, absolute mode, cancels, path smoothing); refused when its dialect lists one
  /// as a word whose effect a comment would lose (`lost_as_comment`: Siemens `T="NAME"`, `D0`).
  void kept_words(const block& b) {
    if (same_) return;
    for (const std::string& w : b.kept_words) {
      std::string word;
      for (char c : w)
        if (!is_space(c)) word.push_back(to_upper(c));
      if (const std::string_view lost = lost_from<dialect>(source_language_, word); !lost.empty())
        fail(b, w + " (" + std::string(lost) + ") has no APT form, and a $$ comment would lose it");
      foreign_note_ = true;
    }
  }

  /// RAPID and GOTO/x,y,z[,i,j,k].
  void motion(const block& b) {
    const bool rapid = b.motion == motion_kind::rapid || b.feed_rapid;
    if (b.machine_coordinates && b.moves()) {
      fail(b, "a move in machine coordinates (G53, G28, G30, SUPA, M91, M92) has no APT form (GOTO points are in the "
              "part's frame)");
    } else if (b.moves()) {
      if (b.axes.has_rotary()) fail(b, "rotary axis words (A, B, C) have no APT form");
      if (!b.axes.x_mm || !b.axes.y_mm || !b.axes.z_mm) fail(b, "GOTO needs x, y and z");
      const vec3 end{*b.axes.x_mm, *b.axes.y_mm, *b.axes.z_mm};
      const bool arc = b.arc || b.motion == motion_kind::arc_cw || b.motion == motion_kind::arc_ccw;
      if (arc && rapid) fail(b, "a rapid arc (CIRCLE is a feed move)");
      if (rapid && !rapid_pending_) lines_.push_back("RAPID");
      if (!rapid && rapid_pending_) fail(b, "a linear move cannot follow RAPID");
      if (!rapid && fedrat_inverse_ && *fedrat_inverse_ != inverse_time_)
        fail(b, std::string("a feed move ") + (inverse_time_ ? "in inverse time (G93)" : "per minute (G94)") +
                    " without its own F: the FEDRAT in effect is in the other unit, and APT changes the unit only with "
                    "a value");
      const int linear = options_.linear_decimals + (inch_ ? 1 : 0);
      if (arc) lines_.push_back(circle(b, end, linear));
      else if (!rapid) separate_from_arc(end);
      std::string go = "GOTO/" + format_number(*b.axes.x_mm, linear) + "," + format_number(*b.axes.y_mm, linear) +
                       "," + format_number(*b.axes.z_mm, linear);
      if (b.axes.tool_axis) {
        const vec3& v = *b.axes.tool_axis;
        go += "," + format_number(v.x, options_.vector_decimals) + "," + format_number(v.y, options_.vector_decimals) +
              "," + format_number(v.z, options_.vector_decimals);
      }
      lines_.push_back(std::move(go));
      rapid_pending_ = false;
      goto_ended_.reset();
      if (arc) {
        const arc_plane plane = b.arc->plane;
        goto_ended_ = detail::circle_state::circle{plane, false, *b.arc->centre_mm,
                                                   detail::radius_in_plane_mm(plane, *b.arc->centre_mm, end)};
      }
      at_ = end;
      if (b.axes.tool_axis) axis_ = *b.axes.tool_axis;
    } else if (rapid) {
      lines_.push_back("RAPID");
      rapid_pending_ = true;
    } else if (b.motion || b.arc) {
      foreign_note_ = true;
    }
  }
};

/// Writes `p` as APT CL data, one statement per line. Throws std::invalid_argument naming the
/// block's `file:line` when a block has rotary axis words, an arc CIRCLE cannot say, a move missing
/// one of x, y, z, a linear move right after a rapid-only block, or a line break in a text field.
inline std::string write(const program& p, const write_options& options = {}) {
  writer w(p.language, p.file, options);
  std::string out;
  for (const block& b : p.blocks) w.write(out, b);
  w.finish(out);
  return out;
}

}  // namespace kin5::program::apt
