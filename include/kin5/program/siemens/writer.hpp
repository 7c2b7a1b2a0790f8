/// @file program/siemens/writer.hpp
/// Blocks written as Siemens 840D text, one line per block, in the order
/// `N  TRAORI/TRAFOOF  G710/G700  G93/G94  G90/G91 G17-G19 G40  kept words  G54…  SUPA  G17-G19  G0-G3  X Y Z A B C  A3= B3= C3=
/// I J K / CR=  F  S  T  D H T="name"  M  ;comment`. Blocks read from another dialect keep their
/// passthrough text and kept words in a comment; such a program opens with the punch-tape header
/// `%_N_NAME_MPF` and `;$PATH=/_N_MPF_DIR` (its name made legal, `legal_program_name`), never
/// with the other dialect's frame (`%`), and a block after its end is refused unless it is only a
/// comment (program_end.hpp); without an end of its own it gets `M30` (`finish`). Their tool
/// length compensation is the active
/// tool's `D1` (off: `D0`), and one that applies another register than the loaded tool's is
/// refused, as is a plane G18/G19 while a length may be in effect (the 840D turns the length with
/// the plane). Units are written `G710` (mm) or `G700` (inch),
/// the forms that also set the unit of F: after `G700` lengths and per-minute feeds are written in
/// inches, with one decimal more. A block Siemens cannot express (a rapid arc, an arc without a
/// known start point) throws `std::invalid_argument` ("file:line: reason"). A dwell is
/// `N  G4 F…  ;comment`, a line of its own.
#pragma once

#include <algorithm>
#include <array>
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
#include "modal.hpp"
#include "vocabulary.hpp"

namespace kin5::program::siemens {

/// Decimals written for each kind of number. Spindle speeds use `feed_decimals`.
struct write_options {
  int linear_decimals = 3;  ///< X Y Z, I J K, CR= (mm)
  int angle_decimals = 3;   ///< A B C (degrees)
  int feed_decimals = 1;    ///< F (mm/min or 1/min) and S (1/min)
  int finest_feed_decimals = detail::finest_rate_decimals;  ///< more decimals for a small F or S, up to these (rate_decimals)
  int vector_decimals = 7;  ///< A3= B3= C3= tool-axis components
  /// The program's name when known ahead (`program_name`: the source's, or the output file's),
  /// for the header of a program read in another dialect; else `PGM`.
  std::optional<std::string> program_name;
};

namespace detail {

inline void append_word(std::string& line, std::string_view word) {
  if (!line.empty()) line += ' ';
  line += word;
}

/// Appends a code word: a letter and a whole number (`N10`, `T5`, `M30`).
inline void append_code(std::string& line, char letter, long long n) {
  if (!line.empty()) line += ' ';
  line += letter;
  line += std::to_string(n);
}

inline std::string checked_line(std::string s, const block& b, const std::string& file) {
  if (s.find_first_of("\r\n") != std::string::npos)
    throw std::invalid_argument(file + ":" + std::to_string(b.where.line) + ": text with a line break cannot be written");
  return s;
}

inline std::string program_file_name(std::string name) {
  for (char& c : name)
    if (!is_ident_char(c)) c = '_';
  if (name.empty()) name = "KIN5";
  if (!(name.size() > 4 && lexing::upper(name.substr(name.size() - 4)) == "_SPF")) name += "_MPF";
  return "%_N_" + name;
}

/// Whether `upper` is a name Windows reserves (CON, PRN, AUX, NUL, COM1…9, LPT1…9), which
/// SINUMERIK does not take as a program name.
inline bool reserved_name(std::string_view upper) {
  if (upper == "CON" || upper == "PRN" || upper == "AUX" || upper == "NUL") return true;
  return upper.size() == 4 && (upper.starts_with("COM") || upper.starts_with("LPT")) && upper[3] >= '1' && upper[3] <= '9';
}

}  // namespace detail

/// `name` as a SINUMERIK program name (SINUMERIK ONE Programming Manual 12/2019 §2.2.1 p. 42):
/// letters, digits and `_` (any other byte becomes `_`); the first two characters two letters or
/// `_` and a letter, else `PGM_` in front (also of a name Windows reserves: CON, COM1, …); at
/// most 24 characters, the rest cut off; `PGM` for an empty name.
inline std::string legal_program_name(std::string name) {
  if (name.empty()) return "PGM";
  for (char& c : name)
    if (!detail::is_ident_char(c)) c = '_';
  const bool starts = name.size() >= 2 && (is_letter(name[0]) || name[0] == '_') && is_letter(name[1]);
  if (!starts || detail::reserved_name(lexing::upper(name))) name = "PGM_" + name;
  if (name.size() > 24) name.resize(24);
  return name;
}

namespace detail {

inline std::optional<arc_plane> plane_of(std::string_view kept_word) {
  if (kept_word.size() < 2 || to_upper(kept_word[0]) != 'G') return std::nullopt;
  const auto n = read_number(kept_word.substr(1));
  if (n.length + 1 != kept_word.size()) return std::nullopt;
  if (n.value == 17) return arc_plane::xy;
  if (n.value == 18) return arc_plane::zx;
  if (n.value == 19) return arc_plane::yz;
  return std::nullopt;
}

constexpr std::string_view motion_word(motion_kind m) {
  switch (m) {
    case motion_kind::rapid: return "G0";
    case motion_kind::linear: return "G1";
    case motion_kind::arc_cw: return "G2";
    case motion_kind::arc_ccw: return "G3";
  }
  return "G1";
}

constexpr std::string_view plane_word(arc_plane p) {
  return p == arc_plane::xy ? "G17" : p == arc_plane::zx ? "G18" : "G19";
}

}  // namespace detail

/// Writes blocks as Siemens 840D text one at a time, remembering what the text written so far
/// leaves modal (motion word, plane, position), so a program of any length is written in
/// constant memory. `write(program)` below is this writer applied to every block.
class writer {
 public:
  /// A writer for blocks read from `source` (another dialect's passthrough text and kept words
  /// go into comments); `file` names the program in messages.
  explicit writer(dialect_id source, std::string file = {}, const write_options& chosen = {})
      : same_(source == id_named("siemens")), program_file_(std::move(file)), options_(chosen) {}

  /// Ends a program read in another dialect whose source gave no end (an ISO or LinuxCNC file
  /// that stops at its `%`) with `M30`: an 840D main program ends with M2, M30 or M17 (SF ch. 14).
  /// Call once, after the last `write`.
  void finish(std::string& out) {
    if (opened_ && !end_.ended()) out += "M30\n";
    opened_ = false;
  }

  /// Appends the text of block `b` to `out` (nothing for a block with nothing to say). Throws
  /// `std::invalid_argument` ("file:line: reason") for a block Siemens cannot express.
  void write(std::string& out, const block& b) {
    const std::string& file = b.where.file.empty() ? program_file_ : b.where.file.str();
    if (!same_) {
      if (b.framing) return;  // another dialect's frame (`%`): the header stands for it
      if (end_.after_end(b)) return after_end(out, b, file);
      if (!opened_) open(out);
    } else if (b.framing) {  // `;$PATH=…` as read: a path statement starts in the first column
      out += detail::checked_line(b.text, b, file) + '\n';
      return;
    }
    if (b.passthrough) {
      out += detail::checked_line(same_ ? b.text : "; " + b.text, b, file) + '\n';
      return;
    }
    if (b.alarm) {  // a line of its own, before the block's other words (the alarm acts first)
      alarm(out, b, file);
      if (b.only_alarm_and_comment()) return;  // its comment on its line
    }
    if (b.state.dwell_s) return dwell(out, b, file);
    if (b.program_begin && same_) {
      out += detail::checked_line(detail::program_file_name(*b.program_begin), b, file) + '\n';
      written_ = detail::modal_state{};
      model_motion_.reset();
    }
    const bool change = !same_ && changes_tool(b);
    source_.apply(b);
    if (b.tool) selected_tool_ = *b.tool, selected_name_.reset();
    if (b.tool_name) selected_name_ = *b.tool_name, selected_tool_.reset();
    if (change && !selected_tool_ && !selected_name_) fail(b, file, "tool change (M6) without a tool number");
    if (change && tcp_on_ && !(b.tcp && !*b.tcp)) out += "TRAFOOF\n";  // the transformation off for the change
    std::string line;
    settings(line, b, file);
    motion(line, b, file);
    axes(line, b, file);
    arc_data(line, b, file);
    tail(line, b, file);
    written_.move(b);
    if (line.empty() && !same_ && !b.program_begin && !b.text.empty() && !b.alarm) {  // nothing Siemens can say: the source text
      line = "; " + b.text;
      std::replace(line.begin(), line.end(), '\n', ' ');
      std::replace(line.begin(), line.end(), '\r', ' ');
    }
    if (line.empty()) return;  // nothing to say (a lone header, an alarm has been written)
    if (b.program_begin && b.number && line == "N" + std::to_string(*b.number)) return;
    out += detail::checked_line(std::move(line), b, file) + '\n';
    if (change) {  // the new tool's first cutting edge: its length and radius (or none, after G49)
      length_on_ = length_in_effect(source_) != tool_length::off;
      out += *length_on_ ? "D1\n" : "D0\n";
    }
    if (change && tcp_on_ && !b.tcp) out += "TRAORI\n";
    if (b.tcp) tcp_on_ = *b.tcp;
  }

 private:
  bool same_;                                // the blocks were read as Siemens
  std::vector<int> m_words_;                 // the M functions of the block being written (`tail`)
  bool opened_ = false;                      // the header written (another dialect's program)
  source_end end_;                           // where another dialect's program stops running
  std::string program_file_;
  write_options options_;
  detail::modal_state written_;              // what the written text leaves the controller in
  std::optional<motion_kind> model_motion_;  // the program's own modal motion
  bool ended_ = false;                       // the last block written had an M2 / M30 M function
  bool tcp_on_ = false;                      // TRAORI in effect after the last block
  std::optional<long long> selected_tool_;   // the last T written
  std::optional<std::string> selected_name_;  // the last T="…" written
  bool inch_ = false;                        // G700 written: lengths and per-minute F in inches
  bool inverse_time_ = false;                // G93 written: F is not a length
  modal_state source_;                       // the source program's state after the block (another dialect's)
  std::optional<bool> length_on_;            // D1 (true) or D0 (false) written last; empty: not known

  /// The punch-tape header of a program read in another dialect, its first two lines: the name
  /// (`%_N_NAME_MPF`, a main program) and the directory it is loaded into (SINUMERIK 840D/840Di/
  /// 810D Operator's Guide HMI Advanced 03.04 §7.3 p. 7-369: `%` in the first column of the first
  /// line, `;$PATH=` the next block; docs/dialects/siemens.md).
  void open(std::string& out) {
    opened_ = true;
    out += "%_N_" + legal_program_name(options_.program_name.value_or("")) + "_MPF\n;$PATH=/_N_MPF_DIR\n";
  }

  /// A block after the source's end with no effect (`source_end`): its comment, if any.
  static void after_end(std::string& out, const block& b, const std::string& file) {
    if (!b.comment || b.comment->empty()) return;
    std::string c = "; " + *b.comment;
    std::replace(c.begin(), c.end(), '\n', ' ');
    std::replace(c.begin(), c.end(), '\r', ' ');
    out += detail::checked_line(std::move(c), b, file) + '\n';
  }

  [[noreturn]] static void fail(const block& b, const std::string& file, const std::string& why) {
    throw std::invalid_argument(file + ":" + std::to_string(b.where.line) + ": " + why);
  }

  /// `N10 SETAL(65000,"MESSAGE")`: an alarm stop, its number the source's (a Siemens program's)
  /// or `detail::default_alarm_number`, the message its text parameter (docs/dialects/siemens.md).
  /// A message with a double quote, which would end the string, is refused.
  static void alarm(std::string& out, const block& b, const std::string& file) {
    const alarm_stop& a = *b.alarm;
    if (a.message.find_first_of("\"\n\r") != std::string::npos)
      fail(b, file, "an alarm message with a double quote or a line break has no Siemens form (SETAL takes it as a "
                    "string): remove them from the message");
    std::string line;
    if (b.number) detail::append_code(line, 'N', *b.number);
    std::string call = "SETAL(" + std::to_string(a.number.value_or(detail::default_alarm_number));
    if (!a.message.empty()) call += ",\"" + a.message + "\"";
    detail::append_word(line, call + ")");
    if (b.comment && b.only_alarm_and_comment()) {
      std::string c = *b.comment;
      std::replace(c.begin(), c.end(), '\n', ' ');
      std::replace(c.begin(), c.end(), '\r', ' ');
      line += " ;" + (c.empty() ? std::string() : " " + c);
    }
    out += detail::checked_line(std::move(line), b, file) + '\n';
  }

  /// `N10 G4 F1.5 ;comment`: a dwell, F in seconds, in a block of its own (SINUMERIK 840D sl
  /// Fundamentals 05/2017, "Dwell time (G4)": "G4 must be programmed in a separate block"; the F
  /// there is the time and leaves the feed alone). Refused with other words, or outside the
  /// dwells the control takes (`detail::dwell_steps`).
  void dwell(std::string& out, const block& b, const std::string& file) const {
    if (!b.only_dwell()) fail(b, file, "a dwell with other words (G4 takes a block of its own)");
    if (const std::string why = dwell_refusal(detail::dwell_steps, *b.state.dwell_s); !why.empty()) fail(b, file, why);
    std::string line;
    if (b.number) detail::append_code(line, 'N', *b.number);
    detail::append_word(line, "G4 F" + format_number(*b.state.dwell_s, detail::dwell_steps.decimals));
    if (b.comment) line += " ;" + (b.comment->empty() ? std::string() : " " + *b.comment);
    out += detail::checked_line(std::move(line), b, file) + '\n';
  }

  void number(std::string& line, std::string_view address, double v, int decimals) {
    detail::append_word(line, std::string(address) + format_number(v, decimals));
  }
  /// A length in mm, written in the program's unit (inches after G700, one decimal more).
  void length(std::string& line, std::string_view address, double v_mm) {
    number(line, address, inch_ ? v_mm / mm_per_inch : v_mm, linear_decimals());
  }
  int linear_decimals() const { return options_.linear_decimals + (inch_ ? 1 : 0); }

  /// `N`, TRAORI / TRAFOOF, G71, G93 / G94, kept words (same dialect), SUPA.
  void settings(std::string& line, const block& b, const std::string& file) {
    if (b.number) detail::append_code(line, 'N', *b.number);
    if (b.tcp) detail::append_word(line, *b.tcp ? "TRAORI" : "TRAFOOF");
    if (b.metric) {
      inch_ = !*b.metric;
      detail::append_word(line, inch_ ? "G700" : "G710");
    }
    if (b.feed_mode) inverse_time_ = *b.feed_mode == feed_unit::inverse_time;
    if (b.feed_mode) detail::append_word(line, inverse_time_ ? "G93" : "G94");
    state_words(line, b, file);
    if (same_) {
      for (const auto& w : b.kept_words) {
        if (detail::is_late_kept(w)) continue;
        detail::append_word(line, w);
        if (const auto plane = detail::plane_of(w)) written_.plane = *plane;
      }
    }
    if (b.state.work_offset) work_offset_word(line, b, file, *b.state.work_offset);
    if (b.machine_coordinates && b.machine_reference != machine_position::machine_zero)
      fail(b, file, unwritable_machine_position(b));
    if (b.machine_coordinates) detail::append_word(line, "SUPA");
  }

  /// G90 / G91, G17 / G18 / G19, G40: the distance mode, working plane and radius compensation
  /// cancel the block says (SINUMERIK 840D sl Programming Manual Fundamentals, "Absolute
  /// dimensions (G90, AC)", "Incremental dimensions (G91, IC)", "Selection of the working plane
  /// (G17/G18/G19)", "Tool radius compensation (G40, G41, G42, OFFN)"). G41/G42 are not written:
  /// no reader gives them yet.
  void state_words(std::string& line, const block& b, const std::string& file) {
    const auto& s = b.state;
    if (s.distance == distance_mode::incremental && b.moves() && !b.machine_coordinates)
      fail(b, file, "G91 on a block that moves: a block holds the positions its axes reach (readers resolve "
                    "incremental words), so its words cannot be written as distances");
    if (s.distance) detail::append_word(line, *s.distance == distance_mode::absolute ? "G90" : "G91");
    if (s.working_plane) {
      written_.plane = *s.working_plane;
      plane_word(line, b, file, *s.working_plane);
    }
    radius_check(b, file);
    if (s.radius_compensation) detail::append_word(line, cutter_side_code(*s.radius_compensation));
  }

  /// Another dialect's cutter radius compensation: G41 / G42 take the radius of the active
  /// cutting edge (SINUMERIK 840D sl Fundamentals 05/2017, ch. 11 "Tool radius compensation"),
  /// which is the loaded tool's own once the writer has written `D1` after its change. A radius
  /// of another register (ISO `G41 D5` with tool 1 loaded) is refused at the block that says it
  /// and at each move under it; so is G41/G42 while `D0` or no D is in effect.
  void radius_check(const block& b, const std::string& file) const {
    if (same_) return;
    const bool says_on = b.state.radius_compensation && *b.state.radius_compensation != cutter_side::off;
    if (radius_in_effect(source_) == tool_radius::other && (says_on || is_motion(b)))
      fail(b, file, "cutter radius compensation " + radius_register_text(source_) +
                        ": an 840D compensates with the active tool's own edge (D1), not another tool's register");
    if (says_on && length_on_ != true)
      fail(b, file, std::string(cutter_side_code(*b.state.radius_compensation)) +
                        (length_on_ ? " while D0 is in effect" : " before any tool change") +
                        ": an 840D compensates with the active edge's radius, and only D1 after a change is written");
  }

  /// Another dialect's tool length compensation: the active tool's first edge, `D1`, or `D0`
  /// (SINUMERIK 840D sl Fundamentals, ch. 6 "Tool offsets": D selects the edge whose length and
  /// radius apply, D0 none); nothing when that is in effect already. A length that is not the
  /// loaded tool's own (ISO `G43 H5` with T1 loaded, or before any tool change) has no D form:
  /// refused at the block that says it and at each move under it. After a tool change the writer
  /// writes the D itself (`write`).
  void length_word(std::string& line, const block& b, const std::string& file) {
    if (same_) return;
    if (length_in_effect(source_) == tool_length::other && (b.state.length_compensation == true || is_motion(b)))
      fail(b, file, "tool length compensation " + length_register_text(source_) +
                        ": an 840D applies the active tool's own length (D1), not another tool's register");
    const auto& on = b.state.length_compensation;
    if (!on || changes_tool(b) || length_on_ == *on) return;
    detail::append_word(line, *on ? "D1" : "D0");
    length_on_ = *on;
  }

  /// A plane word G18 / G19 of another dialect's program, refused while a tool length may be in
  /// effect: an 840D applies a milling tool's length along the axis normal to the working plane
  /// (Y under G18, X under G19) and under TRAORI turns the tool's basic orientation with the plane
  /// (SINUMERIK ONE Programming Manual 12/2019 §3.13.3.4 "Tool length and plane change"; Function
  /// Manual W1 11/2006 §2.7 "Basic tool orientation", p. 130), where the source dialects keep it
  /// along the tool axis. After `D0` (no length) it is written.
  void plane_word(std::string& line, const block& b, const std::string& file, arc_plane p) {
    if (!same_ && p != arc_plane::xy && length_on_ != false)
      fail(b, file, std::string(detail::plane_word(p)) + " while tool length compensation may be on: an 840D would "
                        "apply the tool length along " + (p == arc_plane::zx ? "Y" : "X") +
                        " (and turn the tool orientation under TRAORI), not along the tool axis");
    detail::append_word(line, detail::plane_word(p));
  }

  /// G54 … G57 (settable zero offsets 1 … 4), G505 … G599, G500 (none): the 840D's only forms
  /// (SINUMERIK 840D sl Programming Manual Fundamentals, "Settable zero offset (G54 to G57, G505
  /// to G599, G53, G500, SUPA, G153)"); any other selection is refused.
  void work_offset_word(std::string& line, const block& b, const std::string& file, const work_offset& w) {
    const bool settable = w.family == work_offset_family::g54 && w.number >= 1 && w.number <= 4;
    const bool more = w.family == work_offset_family::siemens && (w.number == 0 || (w.number >= 505 && w.number <= 599));
    if (!settable && !more) fail(b, file, "work offset " + kin5::program::spelling(w) + " has no Siemens form (--work-offset-map names one)");
    detail::append_word(line, kin5::program::spelling(w));
  }

  /// G17–G19 for an arc in another plane, and G0–G3 where the written text needs it.
  void motion(std::string& line, const block& b, const std::string& file) {
    std::optional<motion_kind> word = b.motion;
    if (b.motion) model_motion_ = b.motion;
    if (b.feed_rapid) {
      if (b.arc) fail(b, file, "an arc at rapid traverse cannot be written");
      word = motion_kind::rapid;
    } else if (!word && model_motion_ && written_.motion != model_motion_ && (b.moves() || b.arc)) {
      word = model_motion_;
    }
    if (word) written_.motion = word;
    if (b.arc) {
      if (!detail::is_arc(written_.motion)) fail(b, file, "arc data without G2 or G3 cannot be written");
      if (b.arc->plane != written_.plane) {
        plane_word(line, b, file, b.arc->plane);
        written_.plane = b.arc->plane;
      }
    }
    if (word) detail::append_word(line, detail::motion_word(*word));
  }

  /// X Y Z A B C, and A3= B3= C3= for a tool-axis vector.
  void axes(std::string& line, const block& b, const std::string& file) {
    const axis_words& a = b.axes;
    if (a.x_mm) length(line, "X", *a.x_mm);
    if (a.y_mm) length(line, "Y", *a.y_mm);
    if (a.z_mm) length(line, "Z", *a.z_mm);
    if (a.a_deg) number(line, "A", *a.a_deg, options_.angle_decimals);
    if (a.b_deg) number(line, "B", *a.b_deg, options_.angle_decimals);
    if (a.c_deg) number(line, "C", *a.c_deg, options_.angle_decimals);
    if (a.tool_axis) {
      if (a.has_rotary()) fail(b, file, "rotary axes and a tool-axis vector in one block cannot be written");
      number(line, "A3=", a.tool_axis->x, options_.vector_decimals);
      number(line, "B3=", a.tool_axis->y, options_.vector_decimals);
      number(line, "C3=", a.tool_axis->z, options_.vector_decimals);
    }
  }

  /// I J K relative to the last written point (zero off-plane offsets left out), or CR=.
  void arc_data(std::string& line, const block& b, const std::string& file) {
    if (b.arc && b.arc->centre_mm) {
      const auto start = written_.position();
      if (!start) fail(b, file, "arc centre needs a known start point (X Y Z)");
      const vec3 offset = (*b.arc->centre_mm - *start) * (inch_ ? 1.0 / mm_per_inch : 1.0);
      const std::array<double, 3> o = {offset.x, offset.y, offset.z};
      const std::array<bool, 3> in_plane = {b.arc->plane != arc_plane::yz, b.arc->plane != arc_plane::zx,
                                            b.arc->plane != arc_plane::xy};
      for (std::size_t i = 0; i < 3; ++i) {
        const std::string v = format_number(o[i], linear_decimals());
        if (in_plane[i] || v != "0") detail::append_word(line, std::string(1, static_cast<char>('I' + i)) + v);
      }
    } else if (b.arc && b.arc->radius_mm) {
      length(line, "CR=", *b.arc->radius_mm);
    }
  }

  /// The name of the tool block `b` selects by name, as `T="…"` holds it: 1 to 32 characters,
  /// none a quote or a control character (840D sl tool management: a tool name of up to 32
  /// characters); else the block fails.
  static std::string tool_name(const block& b, const std::string& file) {
    const std::string& n = *b.tool_name;
    const bool bad = std::any_of(n.begin(), n.end(), [](char c) { return c == '"' || static_cast<unsigned char>(c) < 0x20; });
    if (n.empty() || n.size() > 32 || bad)
      fail(b, file, (bad ? std::string("a tool name with a quote or a control character") : "tool name '" + n + "'") +
                        " cannot be written in T=\"…\" (1 to 32 characters, no quote)");
    return n;
  }

  /// F S T or T="name", D H (same dialect), M codes, the program end, the comment.
  void tail(std::string& line, const block& b, const std::string& file) {
    if (b.feed) {
      const int inch = inch_ && !inverse_time_ ? 1 : 0;  // in/min: one decimal more
      const double f = *b.feed / (inch ? mm_per_inch : 1.0);
      number(line, "F", f, rate_decimals(f, options_.feed_decimals + inch, options_.finest_feed_decimals + inch));
    }
    if (b.spindle_rpm)
      number(line, "S", *b.spindle_rpm,
             rate_decimals(*b.spindle_rpm, options_.feed_decimals, options_.finest_feed_decimals, "spindle speed"));
    if (b.tool) detail::append_code(line, 'T', *b.tool);
    if (b.tool_name) detail::append_word(line, "T=\"" + tool_name(b, file) + "\"");
    length_word(line, b, file);
    if (same_) {
      for (const auto& w : b.kept_words)
        if (detail::is_late_kept(w)) detail::append_word(line, w);
    }
    bool ends = false;  // an M2 / M30 written in this block: never a second one
    m_words_.clear();
    if (const std::string why = m_words_of(b, {}, true, m_words_); !why.empty()) fail(b, file, why);
    for (int m : m_words_) {
      // M91 / M92 of another dialect are machine coordinates, already written as SUPA
      if (!same_ && b.machine_coordinates && (m == 91 || m == 92)) continue;
      detail::append_code(line, 'M', m);
      ends = ends || m == 2 || m == 30;
    }
    // A program end right after an M2 / M30 M function (Heidenhain `M30`, then `END PGM`) says it again.
    const bool end_written = ended_ && !same_;
    ended_ = ends;
    if (b.program_end && !ends && !end_written) detail::append_word(line, *b.program_end == "M2" ? "M2" : "M30");
    std::string comment;
    if (!same_) {
      for (const auto& w : b.kept_words) comment += (comment.empty() ? "" : " ") + w;
    }
    if (b.comment && !b.comment->empty()) comment += (comment.empty() ? "" : " ") + *b.comment;
    if (b.comment || !comment.empty()) line += line.empty() ? ";" : " ;";
    if (!comment.empty()) line += " " + comment;
  }
};

/// Writes `p` as a Siemens 840D program, one line per block (see the file comment). Throws
/// `std::invalid_argument` ("file:line: reason") for a block Siemens cannot express.
inline std::string write(const program& p, const write_options& options = {}) {
  write_options chosen = options;
  if (!chosen.program_name) chosen.program_name = name_of(p);
  writer w(p.language, p.file, chosen);
  std::string out;
  for (const block& b : p.blocks) w.write(out, b);
  w.finish(out);
  return out;
}

}  // namespace kin5::program::siemens
