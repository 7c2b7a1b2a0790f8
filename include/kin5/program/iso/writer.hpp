/// @file program/iso/writer.hpp
/// Blocks written as ISO / Fanuc G code, one block per line, words in the order
/// `N  G90/G91 G17-G19 G40/G41 D/G42 D  kept G  G0-G3  G43.4 H/G43.5 H/G43 H/G49  G93/G94  G21/G20  X Y Z A B C  I J K  R  F S T M
/// kept  (comment)`; a dwell is `N  G4 X1.5  (comment)`, a line of its own.
/// A program read in another dialect is framed as a FANUC program: `%`, `O` and its number, the
/// blocks, an end (`M30` when the source gives none; `finish`), `%`; the other dialect's frame
/// (`%` of LinuxCNC, Siemens `;$PATH=`) is never copied, and a block after its end is refused
/// unless it is only a comment (program_end.hpp). A program read as ISO is written as read.
/// After a block that says inch (`metric == false`, written G20) lengths and per-minute feeds are
/// written in inches with one decimal more. The unit said before the first move is the program's:
/// a later change of unit (Siemens `G700` after motion), which ISO controls and kin5's reader
/// refuse, is not written, and the blocks after it are written in the program's unit. Every coordinate, angle, I J K, R and F has a decimal
/// point (`X10.`, `write_options::decimal_point`). A block ISO cannot express (a tool-axis vector outside
/// G43.5 or with an arc)
/// throws `std::invalid_argument` naming the block's `file:line`. A control built on Fanuc's G code
/// spells TCP, the extended work offsets and the dwell its own way (`write_options::spell`: Haas
/// writes `G234 H…`, `G154 P…`, `G4 P…`; program/haas/writer.hpp).
#pragma once

#include <algorithm>
#include <cmath>
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
#include "../machine_functions.hpp"
#include "../number.hpp"
#include "../program_end.hpp"
#include "../program_name.hpp"
#include "../text.hpp"
#include "../units.hpp"
#include "../work_offsets.hpp"
#include "vocabulary.hpp"

namespace kin5::program::iso {

/// What a control built on ISO / Fanuc G code spells its own way (Haas: program/haas/writer.hpp).
/// The defaults are Fanuc's.
struct spelling {
  std::string_view name = "ISO";         ///< the control, in messages
  std::string_view tcp_on = "G43.4";     ///< tool-tip tracking on with rotary positions (Haas: G234)
  bool vector_tcp = true;                ///< G43.5 H… I J K, tracking with tool-axis vectors, exists
  std::string_view extended = "G54.1";   ///< the extended work offsets' code; P n follows (Haas: G154)
  int extended_count = 300;              ///< extended offsets P1 … P n (Haas: 99)
  char dwell_letter = 'X';               ///< G4 X seconds (Haas: G4 P seconds, with a decimal point)
};

/// Decimals written for each kind of number. Spindle speeds use `feed_decimals`.
struct write_options {
  int linear_decimals = 3;   ///< X Y Z, arc I J K, R (mm)
  int angle_decimals = 3;    ///< A B C (degrees)
  int feed_decimals = 1;     ///< F (mm/min or 1/min) and S (1/min)
  int finest_feed_decimals = detail::finest_rate_decimals;  ///< more decimals for a small F or S, up to these (rate_decimals)
  int vector_decimals = 7;   ///< tool-axis I J K under G43.5
  /// A decimal point on every coordinate, angle, I J K, R and F (`X10.`): a Fanuc control in
  /// its usual input mode reads `X10` as ten least input increments, 0.010 mm (Fanuc
  /// 30i/31i/32i-B Operator's Manual, "Decimal point programming"). LinuxCNC's writer, whose
  /// controller reads `X10` as 10 mm, turns it off.
  bool decimal_point = true;
  /// S as a whole number of revolutions per minute: S is no decimal-point address on a Fanuc
  /// control (Mitsubishi M700V Programming Manual §5.3: a point there is dropped, on a Fanuc an
  /// alarm); a speed with a fraction is an error. LinuxCNC's writer, whose S is a real, turns it off.
  bool whole_spindle_speed = true;
  /// G28 and G30 go to positions the control keeps in parameters (LinuxCNC), not to the
  /// machine's reference points (Fanuc, Haas): which moves in machine coordinates they write.
  bool stored_homes = false;
  /// Frame a program read in another dialect (`%`, `O…`, …, `%`); LinuxCNC's writer, which
  /// frames its own way, turns it off.
  bool frame = true;
  /// The program number of the `O` line (1 … 9999), when chosen (`--program-number`); else
  /// `program_name` when it is such a number, else 1.
  std::optional<long long> program_number;
  /// The program's name when known ahead (`program_name`: the source's, or the output file's):
  /// its number when it is one, else a comment on the `O` line.
  std::optional<std::string> program_name;
  /// The codes of the control written for (Fanuc's unless a dialect built on ISO says otherwise).
  spelling spell{};
};

namespace detail {

/// Whether tool-tip tracking switched on at block `i` is written G43.5 (rather than G43.4): a
/// block from `i` up to the next switch carries a tool-axis vector.
inline bool vector_tcp_from(const std::vector<block>& blocks, std::size_t i) {
  for (std::size_t k = i; k < blocks.size(); ++k) {
    if (k > i && blocks[k].tcp) break;
    if (blocks[k].axes.tool_axis) return true;
  }
  return false;
}

/// The alarm number written for another dialect's alarm stop: `#3000=1`, FANUC's alarm 3001,
/// the first of the numbers every FANUC and Haas control takes (docs/dialects/iso.md).
inline constexpr long long default_alarm_number = 1;

inline std::string as_comment(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  if (text.find_first_of("()") != std::string::npos) return ";" + text;
  return "(" + text + ")";
}

/// Whether `name` is a FANUC program number: digits only, 1 … 9999 (program number 0 cannot be
/// used: FANUC Series 16i/18i-PB Operator's Manual B-63684EN/01 §13, p. 129).
inline bool is_program_number(std::string_view name) {
  if (name.empty() || name.size() > 9 || name.find_first_not_of("0123456789") != std::string_view::npos) return false;
  long long n = 0;
  for (char c : name) n = n * 10 + (c - '0');
  return n >= 1 && n <= 9999;
}

/// `O` and `n` in four digits (`O0001`), as FANUC programs write it.
inline std::string program_number_word(long long n) {
  std::string digits = std::to_string(n);
  return "O" + std::string(digits.size() < 4 ? 4 - digits.size() : 0, '0') + digits;
}

}  // namespace detail

/// Writes blocks as ISO / Fanuc G code one at a time, remembering the plane, the last point and
/// whether G43.5 is on, so a program of any length is written in constant memory.
/// `write(program)` below is this writer applied to every block.
class writer {
 public:
  /// A writer for blocks read from `source` (another dialect's passthrough text and kept words
  /// go into comments). Blocks name themselves in messages: `file` is not needed.
  explicit writer(dialect_id source, std::string file = {}, const write_options& chosen = {})
      : same_(source == id_named("iso")), options_(chosen) {
    static_cast<void>(file);
  }

  /// Appends the line of block `b` to `out`. A block that switches tool-tip tracking on is
  /// written G43.5 when `vector_tcp_ahead` (a block before the next switch carries a tool-axis
  /// vector), else G43.4; a tool-axis vector outside G43.5 is an error. Throws
  /// `std::invalid_argument` naming the block's `file:line` when it cannot be written.
  void write(std::string& out, const block& b, bool vector_tcp_ahead = false) {
    if (!same_) {
      if (b.framing) return;  // another dialect's frame: `%` and `O` stand for it
      if (end_.after_end(b)) {
        if (b.comment && !b.comment->empty()) out += detail::as_comment(*b.comment) + '\n';
        return;
      }
      if (options_.frame && !opened_) open(out);
    }
    if (b.passthrough) {
      out += (same_ ? b.text : detail::as_comment(b.text)) + '\n';
      return;
    }
    if (b.alarm) {  // a line of its own, before the block's other words (the alarm acts first)
      alarm(out, b);
      if (b.only_alarm()) return;
    }
    if (b.state.dwell_s) return dwell(out, b);
    words_.clear();
    tail_.clear();
    notes_.clear();
    block in_unit = b;
    // The unit is the program's from its first move on: another dialect's later switch (Siemens
    // G700 / G710) is written in it, exactly, since the model holds millimetres.
    if (b.metric && moved_ && *b.metric == inch_) in_unit.metric.reset();
    else if (b.metric) inch_ = !*b.metric;
    moved_ = moved_ || b.moves();
    if (b.feed_mode) inverse_time_ = *b.feed_mode == feed_unit::inverse_time;
    if (inch_) mm_to_inches(in_unit, !inverse_time_);
    const bool loads = changes_tool(b);
    const bool change = !same_ && loads;
    if (b.tool_name)  // ISO's T takes a number: a name is not written as something else
      fail(b, "a tool by name (\"" + *b.tool_name + "\") has no " + std::string(options_.spell.name) +
                  " form (T takes a number; --tool-map NAME=n gives one)");
    if (b.tool) selected_tool_ = *b.tool;
    if (loads) active_tool_ = selected_tool_;
    if (change) {
      if (!selected_tool_) fail(b, "tool change (M6) without a tool number");
      if (tcp_on_ && !(b.tcp && !*b.tcp)) out += "G49\n";  // tool-tip tracking off for the change
    }
    head(in_unit);
    modes(in_unit, vector_tcp_ahead);
    coordinates(in_unit);
    codes(in_unit);
    for (std::string& k : tail_) words_.push_back(std::move(k));
    if (!notes_.empty()) words_.push_back(detail::as_comment(notes_));
    if (b.comment) words_.push_back(detail::as_comment(*b.comment));
    if (words_.empty() && !same_ && !b.text.empty() && !(b.program_begin && opened_) && !b.alarm)
      words_.push_back(detail::as_comment(b.text));
    if (words_.empty() && (!same_ || b.alarm)) return;  // nothing to say and no source text (APT MULTAX): no empty line
    std::string line;
    for (const std::string& w : words_) line += (line.empty() ? "" : " ") + w;
    out += line + '\n';
    if (change && tcp_on_ && !b.tcp)
      out += std::string(tcp_code()) + " H" + std::to_string(*active_tool_) + "\n";
    if (b.tcp) tcp_on_ = *b.tcp;
  }

  /// Closes a program read in another dialect: `M30` when its source gave no end, then `%`.
  /// Call once, after the last `write`.
  void finish(std::string& out) {
    if (!opened_) return;
    if (!end_.ended()) out += "M30\n";
    out += "%\n";
    opened_ = false;
  }

 private:
  bool same_;  // the blocks were read as ISO
  std::vector<int> m_words_;  // the M functions of the block being written (`codes`)
  write_options options_;
  source_end end_;       // where another dialect's program stops running
  bool opened_ = false;  // `%` and `O` written, the closing `%` not yet
  bool vector_tcp_ = false;
  bool tcp_on_ = false;                    // G43.4 / G43.5 in effect after the last block
  std::optional<long long> selected_tool_;  // the last T written
  std::optional<long long> active_tool_;    // the tool of the last change written
  bool inch_ = false;          // G20 written: lengths in inches
  bool moved_ = false;         // a block with axis words written: the unit is the program's
  bool inverse_time_ = false;  // G93 written: F is not a length
  arc_plane plane_ = arc_plane::xy;
  std::optional<double> last_[3];
  bool ended_ = false;              // the last block written had an M2 / M30 M function
  std::vector<std::string> words_;  // the line's words
  std::vector<std::string> tail_;   // non-G kept words
  std::string notes_;               // what another dialect said that ISO cannot: a comment

  /// The code that switches tool-tip tracking on as the writer now writes it: G43.5 with
  /// tool-axis vectors, else the control's own (`spelling::tcp_on`: G43.4, Haas G234).
  std::string_view tcp_code() const { return vector_tcp_ ? "G43.5" : options_.spell.tcp_on; }

  [[noreturn]] void fail(const block& b, const std::string& why) const {
    throw std::invalid_argument(b.where.file + ":" + std::to_string(b.where.line) + ": block cannot be written in " +
                                std::string(options_.spell.name) + ": " + why);
  }

  /// Opens a program read in another dialect: `%`, then `O` and its number (FANUC Fast Data
  /// Server Operator's Manual B-64014EN/03 §2.5: `%`, the `O` number at the beginning of the
  /// program section, the blocks, an M code, `%`), with a name that is no number as the comment
  /// its example puts there (`O0001(COMMENT)`).
  void open(std::string& out) {
    const std::string name = options_.program_name.value_or("");
    const bool numbered = detail::is_program_number(name);
    const long long n = options_.program_number ? *options_.program_number : numbered ? std::stoll(name) : 1;
    if (n < 1 || n > 9999) throw std::invalid_argument("program number " + std::to_string(n) + " is outside 1 … 9999");
    out += "%\n" + detail::program_number_word(n);
    if (!numbered && !name.empty() && name.find_first_of("()\r\n") == std::string::npos) out += " (" + name + ")";
    out += '\n';
    opened_ = true;
  }

  /// A coordinate, angle, I J K, R or F word: with a decimal point (`decimal_point`).
  void put(char letter, double v, int decimals) {
    std::string w = letter + format_number(v, decimals);
    if (options_.decimal_point && w.find('.') == std::string::npos) w += '.';
    words_.push_back(std::move(w));
  }
  void note(std::string_view text) {
    if (!notes_.empty()) notes_ += ' ';
    notes_ += text;
  }
  /// `M30`, `N10`, `T5`: a letter and a whole number.
  static std::string code(char letter, long long n) {
    std::string w(1, letter);
    w += std::to_string(n);
    return w;
  }

  /// `N10 #3000=1 (MESSAGE)`: an alarm stop, its number the source's (an ISO or Haas program's)
  /// or `detail::default_alarm_number`, its message in the parentheses after it (FANUC custom macro,
  /// system variable #3000; docs/dialects/iso.md). A message the parentheses cannot hold is refused.
  void alarm(std::string& out, const block& b) const {
    const alarm_stop& a = *b.alarm;
    if (a.message.find_first_of("()\n\r") != std::string::npos)
      fail(b, "an alarm message with parentheses or a line break has no " + std::string(options_.spell.name) +
                  " form (#3000 takes its message in one pair of parentheses): remove them from the message");
    std::string line = b.number ? "N" + std::to_string(*b.number) + " " : std::string();
    line += "#3000=" + std::to_string(a.number.value_or(detail::default_alarm_number));
    if (!a.message.empty()) line += " (" + a.message + ")";
    out += line + '\n';
  }

  /// `N10 G4 X1.5 (comment)`: a dwell, seconds with a decimal point (always seconds, whatever
  /// the decimal-point input setting), in a block of its own (SINUMERIK ISO Milling 04/2007
  /// §3.3.1, the Fanuc G04: "must not include commands other than G04"); refused when the block
  /// says more or the control cannot dwell that long or that finely (`detail::dwell_steps`).
  void dwell(std::string& out, const block& b) {
    if (!b.only_dwell()) fail(b, "a dwell with other words (G4 takes a block of its own)");
    if (const std::string why = dwell_refusal(detail::dwell_steps, *b.state.dwell_s); !why.empty()) fail(b, why);
    std::string line = b.number ? code('N', *b.number) + " G4 " : std::string("G4 ");
    line += options_.spell.dwell_letter;
    line += format_number(*b.state.dwell_s, detail::dwell_steps.decimals);
    if (line.find('.') == std::string::npos) line += '.';
    if (b.comment) line += " " + detail::as_comment(*b.comment);
    out += line + '\n';
  }

  /// N, O, kept G words (same dialect; the others into a note), G53, the plane of an arc.
  void head(const block& b) {
    if (b.number) words_.push_back(code('N', *b.number));
    if (b.program_begin && !opened_) {  // a framed program's `O` line is written
      const std::string& name = *b.program_begin;
      if (!name.empty() && name.find_first_not_of("0123456789") == std::string::npos) words_.push_back("O" + name);
      else note("program " + name);
    }
    state_words(b);
    bool machine_word = false;
    for (const std::string& k : b.kept_words) {
      if (!same_) note(k);
      else if (k.empty() || to_upper(k.front()) != 'G') tail_.push_back(k);
      else machine_word = kept_g_word(k) || machine_word;
    }
    if (b.machine_coordinates && !machine_word) words_.push_back(machine_code(b));
    if (b.state.work_offset) work_offset_words(b, *b.state.work_offset);
    if (b.arc && b.arc->plane != plane_) {
      plane_ = b.arc->plane;
      words_.push_back(plane_ == arc_plane::xy ? "G17" : plane_ == arc_plane::zx ? "G18" : "G19");
    }
  }

  /// G90 / G91, G17 / G18 / G19, G40: the distance mode, working plane and radius compensation
  /// cancel the block says (Fanuc 30i/31i/32i-B Operator's Manual, "Absolute and incremental
  /// programming (G90, G91)", "Plane selection", "Cutter compensation"). G41 / G42 take D: the
  /// register the block names (ISO's, LinuxCNC's tool), else, as another dialect compensates
  /// with the active tool's own radius, that tool's register (D n = tool n, as for H); with no
  /// tool changed before, refused (FANUC B-63324EN/03 ch. 14; docs/dialects/compensation.md).
  /// G91 only where it is not a block's positions: alone, or on a machine-coordinate or home
  /// block (whose intermediate point it makes incremental).
  void state_words(const block& b) {
    const auto& s = b.state;
    if (s.distance == distance_mode::incremental && b.moves() && !b.machine_coordinates)
      fail(b, "G91 on a block that moves: a block holds the positions its axes reach (readers resolve incremental "
              "words), so its words cannot be written as distances");
    if (s.distance) words_.push_back(*s.distance == distance_mode::absolute ? "G90" : "G91");
    if (s.working_plane) {
      plane_ = *s.working_plane;
      words_.push_back(plane_ == arc_plane::xy ? "G17" : plane_ == arc_plane::zx ? "G18" : "G19");
    }
    if (!s.radius_compensation) return;
    words_.push_back(cutter_side_code(*s.radius_compensation));
    if (*s.radius_compensation == cutter_side::off) return;
    const auto d = s.radius_register ? s.radius_register : active_tool_;
    if (!d) fail(b, std::string(cutter_side_code(*s.radius_compensation)) + ": cutter radius compensation switched on "
                    "before any tool change: no tool gives its radius offset D");
    words_.push_back(code('D', *d));
  }

  /// G54 … G59 (work offsets 1 … 6), G54.1 P n (extended offset n): ISO's only forms (Fanuc
  /// 30i/31i/32i-B Operator's Manual, "Workpiece coordinate system" and "Adding workpiece
  /// coordinate systems (G54.1 or G54)"); any other selection is refused.
  void work_offset_words(const block& b, const work_offset& w) {
    if (w.family == work_offset_family::g54 && w.number >= 1 && w.number <= 6) {
      words_.push_back("G" + std::to_string(53 + w.number));
    } else if (w.family == work_offset_family::extended && w.number >= 1 && w.number <= options_.spell.extended_count) {
      words_.push_back(std::string(options_.spell.extended));
      words_.push_back(code('P', w.number));
    } else {
      fail(b, "work offset " + kin5::program::spelling(w) + " has no " + std::string(options_.spell.name) +
                  " form (--work-offset-map names one)");
    }
  }

  /// Writes kept G word `k`, following the plane it selects; true for a machine-coordinate word.
  /// The G code of block `b` in machine coordinates: G53 (machine zero), G28 and G30 (the
  /// reference points; with `write_options::stored_homes`, the positions the control keeps).
  std::string machine_code(const block& b) const {
    const bool stored = options_.stored_homes;
    switch (b.machine_reference) {
      case machine_position::machine_zero: return "G53";
      case machine_position::reference_point: if (!stored) return "G28"; break;
      case machine_position::second_reference: if (!stored) return "G30"; break;
      case machine_position::stored_position: if (stored) return "G28"; break;
      case machine_position::second_stored_position: if (stored) return "G30"; break;
      case machine_position::builder_position: case machine_position::tool_axis_limit: break;
    }
    fail(b, unwritable_machine_position(b));
  }

  bool kept_g_word(const std::string& k) {
    words_.push_back(k);
    std::string_view digits = std::string_view(k).substr(1);
    while (!digits.empty() && is_space(digits.front())) digits.remove_prefix(1);
    const parsed_number n = read_number(digits);
    const int g = n.error == number_error::none ? detail::g_code(n.value) : -1;
    if (g == 170) plane_ = arc_plane::xy;
    if (g == 180) plane_ = arc_plane::zx;
    if (g == 190) plane_ = arc_plane::yz;
    return g == 530 || g == 280 || g == 300;
  }

  /// G0–G3, G43.4 / G43.5 / G49, G43 [H] (length compensation without tracking), G93 / G94, G21.
  void modes(const block& b, bool vector_tcp_ahead) {
    if (b.motion || b.feed_rapid) {
      const motion_kind m = b.feed_rapid ? motion_kind::rapid : *b.motion;
      words_.push_back(m == motion_kind::rapid ? "G0" : m == motion_kind::linear ? "G1" : m == motion_kind::arc_cw ? "G2" : "G3");
    }
    // Tracking off with the length kept on is `G43 H n`, which replaces G43.4 / G43.5 (G234) in
    // modal group 08; G49 would drop the length too.
    const bool length_ends_tcp = b.tcp && !*b.tcp && b.state.length_compensation == true;
    if (b.tcp && !length_ends_tcp) {
      vector_tcp_ = *b.tcp && vector_tcp_ahead && options_.spell.vector_tcp;
      words_.push_back(std::string(*b.tcp ? tcp_code() : "G49"));
      // H: the register the block names (ISO's own G43.4 H n, LinuxCNC's G43 H n), else, as
      // another dialect's TCP uses the active tool's own length, that tool's register (the
      // offset number equal to the tool number, as tool-change macros set it). With no tool
      // changed before, no register is known: another dialect's is refused (G43.4 without H
      // takes whatever H is in effect on the control); a block of ISO's own without one is
      // written as it was given.
      const auto h = b.state.length_register ? b.state.length_register : active_tool_;
      if (*b.tcp && !same_ && !h)
        fail(b, std::string(tcp_code()) +
                    ": tool-tip tracking switched on before any tool change: no tool gives its length offset H");
      if (*b.tcp && h) words_.push_back(code('H', *h));
    }
    // Without tool-tip tracking: G43 [H n] / G49. Another dialect's length switched on under
    // tracking (Siemens D1 under TRAORI) is the tracking's own, G43.4 H n's: nothing to write.
    const bool tracked_length = !b.tcp && !same_ && tcp_on_ && b.state.length_compensation == true &&
                                (!b.state.length_register || b.state.length_register == active_tool_);
    if (b.state.length_compensation && (!b.tcp || length_ends_tcp) && !tracked_length) {
      if (length_ends_tcp) vector_tcp_ = false;
      words_.push_back(*b.state.length_compensation ? "G43" : "G49");
      const auto h = b.state.length_register ? b.state.length_register : active_tool_;
      if (*b.state.length_compensation && !same_ && !h)
        fail(b, "G43: tool length compensation switched on before any tool change: no tool gives its length offset H");
      if (*b.state.length_compensation && h) words_.push_back(code('H', *h));
    }
    if (b.feed_mode) words_.push_back(*b.feed_mode == feed_unit::inverse_time ? "G93" : "G94");
    if (b.metric) words_.push_back(*b.metric ? "G21" : "G20");
  }

  /// X Y Z A B C, the tool-axis I J K, the arc's R or I J K; the last point moves on.
  void coordinates(const block& b) {
    const axis_words& a = b.axes;
    const int linear = options_.linear_decimals + (inch_ ? 1 : 0);
    if (a.x_mm) put('X', *a.x_mm, linear);
    if (a.y_mm) put('Y', *a.y_mm, linear);
    if (a.z_mm) put('Z', *a.z_mm, linear);
    if (a.a_deg) put('A', *a.a_deg, options_.angle_decimals);
    if (a.b_deg) put('B', *a.b_deg, options_.angle_decimals);
    if (a.c_deg) put('C', *a.c_deg, options_.angle_decimals);
    if (a.tool_axis) {
      if (!vector_tcp_)
        fail(b, options_.spell.vector_tcp ? "a tool-axis vector needs G43.5"
                                          : "a tool-axis vector (no G43.5 here: tracking takes rotary axis words)");
      if (b.arc) fail(b, "a tool-axis vector and an arc in one block");
      put('I', a.tool_axis->x, options_.vector_decimals);
      put('J', a.tool_axis->y, options_.vector_decimals);
      put('K', a.tool_axis->z, options_.vector_decimals);
    }
    if (b.arc && b.arc->radius_mm) {
      put('R', *b.arc->radius_mm, linear);
    } else if (b.arc && b.arc->centre_mm) {
      if (!last_[0] || !last_[1] || !last_[2]) fail(b, "arc centre with no known start point");
      const double centre[3] = {b.arc->centre_mm->x, b.arc->centre_mm->y, b.arc->centre_mm->z};
      const int first = plane_ == arc_plane::xy ? 0 : plane_ == arc_plane::zx ? 2 : 1;
      const int second = plane_ == arc_plane::xy ? 1 : plane_ == arc_plane::zx ? 0 : 2;
      for (int k : {std::min(first, second), std::max(first, second)})
        put(static_cast<char>('I' + k), centre[k] - *last_[k], linear);
    }
    const std::optional<double>* given[3] = {&a.x_mm, &a.y_mm, &a.z_mm};
    for (int k = 0; k < 3; ++k)
      if (*given[k]) last_[k] = b.machine_coordinates ? std::nullopt : *given[k];
  }

  /// F S T, M codes, and the program end (never a second M2 / M30).
  void codes(const block& b) {
    const int inch = inch_ && !inverse_time_ ? 1 : 0;
    if (b.feed) put('F', *b.feed, rate_decimals(*b.feed, options_.feed_decimals + inch, options_.finest_feed_decimals + inch));
    if (b.spindle_rpm && options_.whole_spindle_speed) {  // S takes no decimal point on a Fanuc control
      if (std::floor(*b.spindle_rpm) != *b.spindle_rpm)
        fail(b, "spindle speed S" + format_number(*b.spindle_rpm, options_.finest_feed_decimals) +
                    " is not a whole number; S takes no decimal point");
      words_.push_back('S' + format_number(*b.spindle_rpm, 0));
    } else if (b.spindle_rpm) {  // as short as it reads
      const int d = rate_decimals(*b.spindle_rpm, options_.feed_decimals, options_.finest_feed_decimals, "spindle speed");
      words_.push_back('S' + format_number(*b.spindle_rpm, d));
    }
    if (b.tool) words_.push_back(code('T', *b.tool));
    bool ends = false;  // an M2 / M30 written in this block
    m_words_.clear();
    if (const std::string why = m_words_of(b, {}, true, m_words_); !why.empty()) fail(b, why);
    for (int m : m_words_) {
      // M91 / M92 of another dialect are machine coordinates, already written as G53
      if (!same_ && b.machine_coordinates && (m == 91 || m == 92)) continue;
      words_.push_back(code('M', m));
      ends = ends || m == 2 || m == 30;
    }
    // A program end right after an M2 / M30 M function (Heidenhain `M30`, then `END PGM`) says it again.
    const bool end_written = ended_ && !same_;
    ended_ = ends;
    if (b.program_end && !ends && !end_written) words_.push_back(*b.program_end == "M2" ? "M2" : "M30");
  }
};

/// Writes `p` as ISO / Fanuc G code, one block per line (see the file comment); tool-tip tracking
/// is switched on with G43.5 where tool-axis vectors follow, else G43.4.
inline std::string write(const program& p, const write_options& options = {}) {
  write_options chosen = options;
  if (!chosen.program_name) chosen.program_name = name_of(p);
  writer w(p.language, p.file, chosen);
  std::string out;
  for (std::size_t k = 0; k < p.blocks.size(); ++k) {
    const block& b = p.blocks[k];
    w.write(out, b, b.tcp && *b.tcp && detail::vector_tcp_from(p.blocks, k));
  }
  w.finish(out);
  return out;
}

}  // namespace kin5::program::iso
