/// @file program/siemens/words.hpp
/// What each word of a Siemens line means (the reader's first step after the lexer): the words of
/// one line (lexer.hpp) recorded in a `line_parse` — block fields, arc and vector words, frame
/// words — with the diagnostic each earns. Checks across the words of a line, and the modal state
/// across lines, are reader.hpp's.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../incremental.hpp"
#include "../machine_functions.hpp"
#include "../lexing.hpp"
#include "../number.hpp"
#include "../text.hpp"
#include "lexer.hpp"
#include "modal.hpp"
#include "vocabulary.hpp"

namespace kin5::program::siemens::detail {

/// Everything one line says, before the modal state is applied.
struct line_parse {
  block b;
  std::array<std::optional<double>, 3> centre_offset_mm;  ///< I J K as written
  std::array<bool, 3> centre_absolute{};                  ///< I J K: `=AC(…)`, a centre coordinate, not an offset
  std::optional<double> radius_mm;                        ///< CR=
  std::array<std::optional<double>, 3> vector;            ///< A3= B3= C3=
  std::optional<arc_plane> plane;
  std::size_t arc_column = 0, vector_column = 0, geometry_column = 0;
  std::string arc_word;
  bool has_geometry = false;   ///< axis, vector, centre or radius words (or failed attempts at them)
  bool has_content = false;    ///< anything besides N, comments and MSG
  bool has_msg = false;
  std::optional<std::size_t> mcall_column;         ///< MCALL seen (a call after it is a modal cycle call)
  std::optional<long long> unit_g;                 ///< G70, G71, G700 or G710 (units.hpp applies it)
  std::size_t unit_column = 0, feed_column = 0;
  bool frame_arguments = false;  ///< RPL= and the like
  bool control = false;          ///< a jump or call refused: the line's other words are its arguments
  std::vector<std::pair<std::string, std::size_t>> frame_words;  ///< TRANS, ROT, G58, … (column)
  std::vector<diagnostic> unknown;  ///< errors if the block has geometry, else it is passthrough
  std::vector<diagnostic> errors, warnings;  ///< the first `max_kept_diagnostics` of each
  std::size_t errors_not_kept = 0, warnings_not_kept = 0, unknown_not_kept = 0;  ///< found after them
  std::optional<std::size_t> dwell_column;          ///< G4 seen: its F is the dwell, in seconds
  std::optional<std::pair<double, std::size_t>> dwell_f;  ///< that F (value, column)
  std::string motion_word, feed_word, tcp_word;     ///< as written, for "conflicting words"
  std::optional<std::pair<std::string, std::size_t>> radius_word;  ///< G40, G41 or G42 (column)
  std::optional<long long> edge;                    ///< D n: the cutting edge selected
  std::optional<std::pair<long long, std::size_t>> turns;  ///< TURN=n (column): extra full turns of a helix
  bool only_assignments = false;  ///< the line assigns numbers (`_X=1 _Y=2`) and does nothing else
  std::optional<std::pair<bool, std::size_t>> g91;  ///< G91 (true) or G90 (false), and its column
  std::array<std::optional<bool>, 6> axis_incremental;  ///< X Y Z A B C: `=IC(…)` (true), `=AC(…)` (false)
  std::array<int, 6> axis_decimals{};                    ///< X Y Z A B C: the decimals written
  std::array<std::size_t, 6> axis_column{};              ///< X Y Z A B C: the word's column
};

/// The index of axis letter `c` in X Y Z A B C.
constexpr std::size_t axis_index(char c) {
  return c == 'X' ? 0 : c == 'Y' ? 1 : c == 'Z' ? 2 : c == 'A' ? 3 : c == 'B' ? 4 : 5;
}

inline const std::string expression_in_axis = "expressions and parameters in axis words are not supported";

/// Records the words of one line in a `line_parse`: the meaning of each word and the diagnostics
/// it earns. Checks across words wait for `finish`.
class word_reader {
 public:
  word_reader(std::size_t line, const file_name& file, line_parse& out) : line_(line), file_(file), out_(out) {}

  void read(const std::vector<word>& words) {
    for (const word& w : words) read(w);
  }

 private:
  std::size_t line_;
  const file_name& file_;
  line_parse& out_;

  source_location at(std::size_t pos) const { return {file_, line_, pos + 1}; }
  void error(std::size_t pos, std::string m) { keep_or_count(out_.errors, out_.errors_not_kept, {at(pos), std::move(m)}); }
  void unknown(std::size_t pos, std::string m) { keep_or_count(out_.unknown, out_.unknown_not_kept, {at(pos), std::move(m)}); }
  void mark_geometry(std::size_t pos) {
    if (!out_.has_geometry) out_.geometry_column = pos;
    out_.has_geometry = true;
  }
  bool duplicate(bool present, std::size_t pos, std::string_view what) {
    if (present) error(pos, "word '" + std::string(what) + "' appears twice");
    return present;
  }

  void read(const word& w) {
    switch (w.kind) {
      case word_kind::comment: return comment(w);
      case word_kind::address: return address(w);
      case word_kind::keyword: return keyword(w);
      case word_kind::system: return system_word(w);
      case word_kind::stray_number:
        return error(w.column, "number '" + std::string(w.text) + "' has no address letter");
      case word_kind::bad_byte: return error(w.column, "unexpected byte " + lexing::hex_byte(w.byte, false));
      case word_kind::block_skip: return unknown(w.column, "block skip '/' is not supported");
      case word_kind::unknown: return unknown(w.column, "unknown word '" + std::string(w.text) + "'");
    }
  }

  void comment(const word& w) {
    if (!w.closed) error(w.column, "comment '(' is not closed");
    const std::string t(lexing::trim(w.text));
    std::optional<std::string>& c = out_.b.comment;
    if (!c) c = t;
    else if (!t.empty()) *c += (c->empty() ? "" : " ") + t;
  }

  void system_word(const word& w) {
    const std::string& name = w.name;
    if (w.assigned && name.rfind("$P_", 0) == 0 &&
        (name.find("FRAME") != std::string::npos || name == "$P_UIFR" || name == "$P_CHBFR" || name == "$P_NCBFR"))
      error(w.column, frame_message(name));
    else
      unknown(w.column, "unknown word '" + name + "'");
  }

  void address(const word& w) {
    const std::size_t start = w.column;
    const bool geometry = is_geometry_letter(w.letter);
    if (!w.extension.empty()) return extended_address(w);
    if (w.assigned) return assigned_address(w);
    switch (w.value) {
      case value_kind::number: return numbered(w.letter, w.number, w.text, start);
      case value_kind::none: return no_value(w.letter, start);
      case value_kind::parameter:
        error(start, expression_in_axis);
        return mark_geometry(start);
      case value_kind::malformed: error(start, "malformed number '" + std::string(w.text) + "'"); break;
      default: error(start, "value out of range"); break;
    }
    if (geometry) mark_geometry(start);
  }

  void no_value(char letter, std::size_t start) {
    static constexpr std::string_view known = "NGXYZABCIJKFSTMDH";
    if (known.find(letter) == std::string_view::npos) return unknown(start, std::string("unknown word '") + letter + "'");
    error(start, std::string("word '") + letter + "' has no value");
    if (is_geometry_letter(letter)) mark_geometry(start);
  }

  /// The plain number after `W=`, or nothing (and reported). `geometry`: an axis, vector, centre
  /// or radius word, for which an expression is always an error.
  std::optional<double> assigned(const word& w, std::string_view name, bool geometry) {
    const std::size_t start = w.column;
    if (geometry) mark_geometry(start);
    switch (w.value) {
      case value_kind::number: return w.number;
      case value_kind::none: error(start, "word '" + std::string(name) + "' has no value"); break;
      case value_kind::malformed: error(start, "malformed number '" + std::string(w.text) + "'"); break;
      case value_kind::out_of_range: error(start, "value out of range"); break;
      default: expression(w, geometry); break;
    }
    return std::nullopt;
  }

  void expression(const word& w, bool geometry) {
    const std::size_t start = w.column;
    const std::string value = lexing::upper(w.text);
    if ((value.rfind("IC(", 0) == 0 || value.rfind("AC(", 0) == 0) && w.extension.empty() && geometry) {
      return dimension(w, value[0] == 'I');
    } else if (value == "NAN" || value == "INF" || value == "-NAN" || value == "-INF" || value == "INFINITY") {
      error(start, "value out of range");
    } else if (geometry) {
      error(start, expression_in_axis);
    } else {
      return unknown(start, "expressions and parameters are not supported");
    }
    if (geometry) mark_geometry(start);
    else out_.has_content = true;
  }

  /// `X=IC(5)`, `X=AC(5)`: this axis word incremental or absolute whatever G90/G91 say (SINUMERIK
  /// 840D sl Programming Manual Fundamentals, "Absolute dimensions (G90, AC)", "Incremental
  /// dimensions (G91, IC)"), a plain number inside. I J K are incremental already: `I=IC(…)`
  /// is `I…`; `I=AC(…)` is the centre's coordinate itself, in the workpiece frame, whatever
  /// G90/G91 say (same manual, "Circular interpolation": the centre in absolute dimensions).
  void dimension(const word& w, bool incremental) {
    const std::size_t start = w.column;
    mark_geometry(start);
    const std::string_view inside = w.text.size() >= 4 && w.text.back() == ')' ? w.text.substr(3, w.text.size() - 4)
                                                                               : std::string_view{};
    const std::string_view number = lexing::trim(inside);
    const parsed_number n = read_number(number);
    const std::string name = std::string(1, w.letter) + "=" + (incremental ? "IC" : "AC");
    if (number.empty() || n.error != number_error::none || n.length != number.size())
      return error(start, name + "(…) takes a plain number here: " + expression_in_axis);
    if (is_centre_letter(w.letter)) {
      centre(w.letter, n.value, start);
      out_.centre_absolute[static_cast<std::size_t>(w.letter - 'I')] = !incremental;
      return;
    }
    const std::size_t i = axis_index(w.letter);
    numbered(w.letter, n.value, number, start);
    out_.axis_incremental[i] = incremental;
  }

  /// `X=…`: a plain number for X Y Z A B C I J K F S T, a string for T.
  void assigned_address(const word& w) {
    const std::size_t start = w.column;
    if (w.value == value_kind::string) {
      if (!w.closed) return error(w.open_column, "string is not closed");
      if (duplicate(out_.b.tool.has_value() || out_.b.tool_name.has_value(), start, "T")) return;
      const std::string_view name = w.text.substr(1, w.text.size() >= 2 ? w.text.size() - 2 : 0);  // inside the quotes
      if (name.empty()) return error(start, "T=\"\": a tool name is empty");
      // What the writer can write back in T="…" (1 to 32 characters, no control character).
      for (std::size_t k = 0; k < name.size(); ++k)
        if (static_cast<unsigned char>(name[k]) < 0x20)
          return error(w.open_column + 1 + k, "control character " + lexing::hex_byte(name[k], false) +
                                                  " in a tool name (T=\"…\" takes printable characters)");
      if (name.size() > 32)
        return error(start, "a tool name of " + std::to_string(name.size()) +
                                " characters: T=\"…\" takes at most 32 (840D sl tool management)");
      out_.b.tool_name = std::string(name);
      out_.has_content = true;
      return;
    }
    if (w.value == value_kind::run)
      return unknown(start, std::string("unknown word '") + w.letter + "=" + std::string(w.text) + "'");
    const auto v = assigned(w, std::string(1, w.letter), is_geometry_letter(w.letter));
    if (v) numbered(w.letter, *v, w.text, start);
  }

  /// `A3=…` (a tool-axis vector component); any other `L<digits>=` is unknown.
  void extended_address(const word& w) {
    const std::size_t start = w.column;
    const std::string name = w.letter + std::string(w.extension);
    if (w.value == value_kind::run) return unknown(start, "unknown word '" + name + "='");
    const auto v = assigned(w, name, true);
    if (!v) return;
    const std::size_t i = static_cast<std::size_t>(w.letter - 'A');
    if (duplicate(out_.vector[i].has_value(), start, name)) return;
    if (!out_.vector[0] && !out_.vector[1] && !out_.vector[2]) out_.vector_column = start;
    out_.vector[i] = *v;
  }

  void set_axis(std::optional<double>& field, char letter, double v, std::size_t start) {
    mark_geometry(start);
    if (duplicate(field.has_value(), start, std::string(1, letter))) return;
    field = v;
  }

  void centre(char letter, double v, std::size_t start) {
    auto& field = out_.centre_offset_mm[static_cast<std::size_t>(letter - 'I')];
    mark_geometry(start);
    if (duplicate(field.has_value(), start, std::string(1, letter))) return;
    if (out_.arc_word.empty()) out_.arc_word = std::string(1, letter), out_.arc_column = start;
    field = v;
  }

  /// A whole-number word (N T M D H): false, and reported, when `v` is not one.
  bool whole(char letter, double v, std::size_t start) {
    if (lexing::is_whole(v)) return true;
    error(start, std::string("word '") + letter + "' needs a whole number");
    return false;
  }

  void numbered(char letter, double v, std::string_view number_text, std::size_t start) {
    block& b = out_.b;
    if (is_axis_letter(letter)) {
      out_.axis_decimals[axis_index(letter)] = decimals_written(number_text);
      out_.axis_column[axis_index(letter)] = start;
    }
    switch (letter) {
      case 'N':
        if (whole(letter, v, start) && !duplicate(b.number.has_value(), start, "N")) b.number = static_cast<long long>(v);
        return;
      case 'G': return g_word(v, std::string(1, letter) + std::string(number_text), start);
      case 'X': return set_axis(b.axes.x_mm, letter, v, start);
      case 'Y': return set_axis(b.axes.y_mm, letter, v, start);
      case 'Z': return set_axis(b.axes.z_mm, letter, v, start);
      case 'A': return set_axis(b.axes.a_deg, letter, v, start);
      case 'B': return set_axis(b.axes.b_deg, letter, v, start);
      case 'C': return set_axis(b.axes.c_deg, letter, v, start);
      case 'I': case 'J': case 'K': return centre(letter, v, start);
      case 'F': case 'S':
        if (out_.dwell_column) return dwell_word(letter, v, start);
        return feed_or_speed(letter, v, start);
      case 'T':
        out_.has_content = true;
        if (whole(letter, v, start) && !duplicate(b.tool.has_value() || b.tool_name.has_value(), start, "T"))
          b.tool = static_cast<long long>(v);
        return;
      case 'M':
        out_.has_content = true;
        if (whole(letter, v, start)) read_machine_function(b, static_cast<long long>(v));
        return;
      case 'D': case 'H':
        out_.has_content = true;
        if (whole(letter, v, start)) b.kept_words.push_back(letter + std::to_string(static_cast<long long>(v)));
        if (letter == 'D' && lexing::is_whole(v)) out_.edge = static_cast<long long>(v);
        return;
      case 'L':
        return unknown(start, "L" + std::string(number_text) +
                                  ": a subprogram call is not supported (the motion it makes would be lost)");
      default: unknown(start, "unknown word '" + std::string(1, letter) + std::string(number_text) + "'");
    }
  }

  void feed_or_speed(char letter, double v, std::size_t start) {
    out_.has_content = true;
    if (v < 0) return error(start, "value out of range");
    auto& field = letter == 'F' ? out_.b.feed : out_.b.spindle_rpm;
    if (letter == 'F') out_.feed_column = start;
    if (duplicate(field.has_value(), start, std::string(1, letter))) return;
    // what the writer could not write back (`S.0101` needs a fourth decimal) is refused here
    if (auto why = unwritable_rate(v, finest_rate_decimals, letter == 'F' ? "feed" : "spindle speed"))
      return error(start, *why);
    field = v;
  }

  /// F or S after G4: the dwell in seconds (F) or spindle revolutions (S, refused: its time
  /// depends on the spindle speed), SINUMERIK 840D sl Fundamentals 05/2017, "Dwell time (G4)".
  void dwell_word(char letter, double v, std::size_t start) {
    if (letter == 'S')
      return error(start, "G4 S: a dwell in spindle revolutions is not supported (its time depends on the spindle speed)");
    if (duplicate(out_.dwell_f.has_value(), start, "F")) return;
    if (v < 0) return error(start, "G4 F: a dwell time cannot be negative");
    if (const std::string why = dwell_refusal(dwell_steps, v); !why.empty()) return error(start, "G4 F: " + why);
    out_.dwell_f = std::pair{v, start};
  }

  bool conflict(bool clash, std::string_view earlier, std::string_view later, std::size_t start) {
    if (clash) error(start, "conflicting words '" + std::string(earlier) + "' and '" + std::string(later) + "'");
    return clash;
  }

  void g_word(double v, const std::string& as_written, std::size_t start) {
    block& b = out_.b;
    if (!lexing::is_whole(v) || v > 9999) return unknown(start, "unknown word '" + as_written + "'");
    const auto g = static_cast<long long>(v);
    const std::string canonical = "G" + std::to_string(g);  // G017, G+17, G17. → G17
    out_.has_content = true;
    if (g <= 3) {
      const motion_kind m = g == 0 ? motion_kind::rapid : g == 1 ? motion_kind::linear : g == 2 ? motion_kind::arc_cw : motion_kind::arc_ccw;
      if (conflict(b.motion && *b.motion != m, out_.motion_word, canonical, start)) return;
      b.motion = m;
      out_.motion_word = canonical;
    } else if (g >= 17 && g <= 19) {
      out_.plane = g == 17 ? arc_plane::xy : g == 18 ? arc_plane::zx : arc_plane::yz;
      b.state.working_plane = out_.plane;
    } else if (g == 90 || g == 91) {
      if (out_.g91 && out_.g91->first != (g == 91))
        return error(start, "G90 and G91 in one block: two distance modes; write the one meant");
      out_.g91 = {g == 91, start};
    } else if (g == 40 || g == 41 || g == 42) {
      if (out_.radius_word && out_.radius_word->first != canonical)
        return error(start, "two cutter radius compensation words in one block");
      out_.radius_word = {canonical, start};
      b.state.radius_compensation = g == 40 ? cutter_side::off : g == 41 ? cutter_side::left : cutter_side::right;
    } else if ((g >= 54 && g <= 57) || g == 500 || (g >= 505 && g <= 599)) {
      // Settable zero offsets: G54 … G57 are the first four, G505 … G599 the others, G500 none
      const work_offset w = g <= 57 ? work_offset{work_offset_family::g54, static_cast<int>(g) - 53}
                                    : work_offset{work_offset_family::siemens, g == 500 ? 0 : static_cast<int>(g)};
      if (b.state.work_offset) return error(start, "two work offsets in one block");
      b.state.work_offset = w;
    } else if (is_kept_g(g)) {
      b.kept_words.push_back(canonical);
    } else if (g == 93 || g == 94) {
      const feed_unit f = g == 93 ? feed_unit::inverse_time : feed_unit::per_minute;
      if (conflict(b.feed_mode && *b.feed_mode != f, out_.feed_word, canonical, start)) return;
      b.feed_mode = f;
      out_.feed_word = canonical;
    } else {
      other_g(g, canonical, start);
    }
  }

  void other_g(long long g, const std::string& canonical, std::size_t start) {
    if (g == 70 || g == 71 || g == 700 || g == 710) unit_word(g, canonical, start);
    else if (g == 53 || g == 153) out_.b.machine_coordinates = true;
    else if (g == 58 || g == 59) out_.frame_words.emplace_back(canonical, start);
    else if (g == 4) out_.dwell_column = start;
    else unknown(start, "unknown word '" + canonical + "'");
  }

  /// G70 / G71 / G700 / G710: in effect from this block on (finish applies it to the block).
  void unit_word(long long g, const std::string& canonical, std::size_t start) {
    if (conflict(out_.unit_g && *out_.unit_g != g, "G" + std::to_string(out_.unit_g.value_or(0)), canonical, start)) return;
    out_.unit_g = g;
    out_.unit_column = start;
    out_.b.metric = g == 71 || g == 710;
  }

  void keyword(const word& w) {
    if (w.value == value_kind::call) return call(w);
    if (w.assigned) return keyword_assignment(w);
    const std::string& name = w.name;
    const std::size_t start = w.column;
    block& b = out_.b;
    if (name == "MCALL") {  // alone it cancels a modal call: harmless; with a call it is refused there
      out_.has_content = true;
      out_.mcall_column = start;
      b.kept_words.push_back(name);
      return;
    }
    const bool known = name == "TRAORI" || name == "TRAFOOF" || name == "SUPA" || is_kept_keyword(name) ||
                       is_frame_reset_keyword(name) || is_frame_keyword(name);
    if (!known) {
      std::string why = unread_keyword(name);
      if (why.rfind("unknown word", 0) == 0) return unknown(start, std::move(why));
      out_.control = true;  // `GOTOF END`, `IF R1>5 …`: refused once, at the keyword
      return error(start, std::move(why));
    }
    out_.has_content = true;
    if (name == "TRAORI" || name == "TRAFOOF") set_tcp(name == "TRAORI", name, start);
    else if (name == "SUPA") b.machine_coordinates = true;
    else if (is_kept_keyword(name)) b.kept_words.push_back(name);
    else if (is_frame_reset_keyword(name)) out_.frame_words.emplace_back(name, start);
    else error(start, frame_message(name));
  }

  void set_tcp(bool on, const std::string& word, std::size_t start) {
    if (conflict(out_.b.tcp && *out_.b.tcp != on, out_.tcp_word, word, start)) return;
    out_.b.tcp = on;
    out_.tcp_word = word;
  }

  /// `SETAL(n)`, `SETAL(n, "text")`: the program stops with cycle alarm n and the text as its
  /// parameter (docs/dialects/siemens.md). A number outside the cycle alarms 60000 … 69999, or
  /// arguments of another form (an expression, a variable), are refused.
  void setal(const std::string& args, std::size_t start) {
    out_.has_content = true;
    const std::string_view a = lexing::trim(args);
    const std::size_t comma = a.find(',');
    const std::string_view digits = lexing::trim(a.substr(0, comma));
    const parsed_number n = read_number(digits);
    bool ok = n.error == number_error::none && n.length > 0 && n.length == digits.size() &&
              n.value >= static_cast<double>(detail::first_alarm_number) &&
              n.value <= static_cast<double>(detail::last_alarm_number) && n.value == static_cast<double>(static_cast<long long>(n.value));
    std::string message;
    if (comma != std::string_view::npos) {
      const std::string_view text = lexing::trim(a.substr(comma + 1));
      ok = ok && text.size() >= 2 && text.front() == '"' && text.back() == '"' &&
           text.substr(1, text.size() - 2).find('"') == std::string_view::npos;
      if (ok) message = std::string(text.substr(1, text.size() - 2));
    }
    if (!ok)
      return error(start, "SETAL(" + std::string(a) + "): kin5 reads SETAL(n) and SETAL(n, \"text\") with n a cycle "
                          "alarm number from 60000 to 69999");
    if (out_.b.alarm) return error(start, "two alarms (SETAL) in one block");
    out_.b.alarm = alarm_stop{std::move(message), static_cast<long long>(n.value)};
  }

  /// `NAME(…)`: TRAORI(…), MSG("…"), SETAL(…), CYCLE800(…); anything else is unknown.
  void call(const word& w) {
    const std::string& name = w.name;
    const std::size_t start = w.column;
    if (!w.closed) return error(w.open_column, "missing ')'");
    if (out_.mcall_column)
      return error(*out_.mcall_column, "MCALL " + name + ": a modal cycle call is not supported (the cycle would run at every later position)");
    const std::string args(w.text);
    if (name == "TRAORI") {
      out_.has_content = true;
      const std::string_view a = lexing::trim(args);
      if (!a.empty() && a != "1")
        keep_or_count(out_.warnings, out_.warnings_not_kept, {at(start), "arguments of TRAORI(" + std::string(a) + ") are not kept; written as TRAORI"});
      set_tcp(true, name, start);
    } else if (name == "MSG") {
      out_.has_msg = true;
      out_.b.kept_words.push_back("MSG(" + args + ")");
    } else if (name == "SETAL") {
      setal(args, start);
    } else if (name == "CYCLE800") {
      out_.has_content = true;
      if (is_cycle800_reset(args)) out_.b.kept_words.push_back("CYCLE800(" + args + ")");
      else error(start, frame_message(name));
    } else if (is_frame_reset_keyword(name) || is_frame_keyword(name)) {
      out_.has_content = true;
      error(start, frame_message(name));
    } else {
      unknown(start, name + "(…): a call kin5 does not read is not supported (a cycle or subprogram: the motion "
                            "it makes would be lost)");
    }
  }

  /// The refusal of keyword `name`: control flow and calls named as such, others as unknown.
  static std::string unread_keyword(const std::string& name) {
    for (std::string_view flow : {"GOTOF", "GOTOB", "GOTO", "GOTOC", "IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR",
                                  "ENDFOR", "REPEAT", "REPEATB", "UNTIL", "LOOP", "ENDLOOP", "CASE", "RET"})
      if (name == flow) return name + ": a control statement takes a block of its own (after its number and label)";
    for (std::string_view call : {"CALL", "PCALL", "EXTCALL", "MCALL"})
      if (name == call) return name + ": a subprogram call is not supported (the motion it makes would be lost)";
    return "unknown word '" + name + "'";
  }

  /// `TURN=n`: a helix that makes n full turns more than its G2/G3 says (SINUMERIK 840D sl
  /// Fundamentals, "Helical interpolation (G2/G3, TURN)"). `TURN=0` is the arc alone; a block's
  /// arc turns once at most in kin5's model (block.hpp, `arc_words`), and not every dialect has
  /// a helix of several turns (ISO/FANUC has none), so a positive n is refused by name.
  void turn(const word& w) {
    const auto v = assigned(w, "TURN", true);
    if (!v || duplicate(out_.turns.has_value(), w.column, "TURN")) return;
    if (*v < 0 || !lexing::is_whole(*v) || *v > 999)
      return error(w.column, "TURN=" + std::string(w.text) + ": the number of extra turns is a whole number 0 … 999");
    out_.turns = std::pair{static_cast<long long>(*v), w.column};
    if (*v > 0)
      error(w.column, "TURN=" + std::string(w.text) + ": extra full turns of a helix are not supported (an arc turns "
                          "once at most in kin5, and ISO/FANUC writes no such helix); split the helix into G2/G3 "
                          "blocks of at most one turn each");
  }

  void keyword_assignment(const word& w) {
    if (w.name == "TURN") return turn(w);
    if (w.name != "CR") {
      if (w.name == "RPL") {  // ROT's angle: the frame word is the refusal
        out_.frame_arguments = true;
        return;
      }
      return unknown(w.column, "unknown word '" + w.name + "'");
    }
    const auto v = assigned(w, "CR", true);
    if (!v || duplicate(out_.radius_mm.has_value(), w.column, "CR")) return;
    if (out_.arc_word.empty()) out_.arc_word = "CR", out_.arc_column = w.column;
    out_.radius_mm = *v;
  }
};

}  // namespace kin5::program::siemens::detail
