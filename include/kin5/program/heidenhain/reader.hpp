/// @file program/heidenhain/reader.hpp
/// The second stage of the Heidenhain reader: a block's words (lexer.hpp) become a `block`, by
/// the block's keyword — `L` `LN` `C` `CC` `CR` (motion.hpp), `TOOL CALL`, M lines, `STOP`,
/// `BEGIN PGM`/`END PGM … MM|INCH` (an INCH program read in millimetres), `;` and `*`
/// comments, `FUNCTION TCPM`/`FUNCTION RESET TCPM`.
/// Blocks that change nothing pass through (a comment in another dialect): `BLK FORM`,
/// `TOOL DEF`, `PLANE RESET`, `TRANS … RESET`, Q assignments (parameters.hpp) and frame cycles
/// whose values are the identity. `CYCL DEF 247 … Q339=n` selects preset n (`state.work_offset`);
/// `CYCL DEF 9.0 DWELL TIME` (passed through) then `CYCL DEF 9.1 DWELL t` is a dwell (`state.dwell_s`).
/// Labels, calls, section repeats, FN 9–FN 12 jumps and the assignments' values are the
/// executor's (`read_blocks`, statements.hpp): the reader sees the blocks it runs, and a word
/// that uses a Q parameter reads its value then (motion.hpp). So are `CALL PGM` calls of
/// programs in other files, which run from the calling program's directory or the include
/// directories (`read_limits::include_dirs`) up to their `END PGM`.
/// `FN 14: ERROR = n ;text` is an alarm stop (`alarm`: number n, the comment its message).
/// Every other block is refused at its keyword, naming it: the
/// cycles kin5 does not read (`CYCL DEF 200`, 32, …), `CYCL CALL`, `M99`/`M89`,
/// `SEL PGM` and `CALL SELECTED PGM`, `FN` functions other than FN 0–FN 13, `M` blocks with other words
/// (`M140 MB MAX`), `TOOL CALL` forms it does not read, `FUNCTION TCPM` options other than
/// `F TCP`, `AXIS POS`, `PATHCTRL AXIS`, unknown keywords; so are Q parameters without a value,
/// and active frame changes (`PLANE SPATIAL`…, `CYCL DEF 7/8/10/11/19/26`, `TRANS`). Incremental
/// `IX` … `IC` are resolved to the positions they reach (motion.hpp). Block numbers are kept as
/// written (repeated or missing is fine).
#pragma once

#include <charconv>
#include <cstddef>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../called_files.hpp"
#include "../interp/executor.hpp"
#include "../machine_functions.hpp"
#include "../lexing.hpp"
#include "../number.hpp"
#include "../read_limits.hpp"
#include "../text.hpp"
#include "../transmission.hpp"
#include "lexer.hpp"
#include "motion.hpp"
#include "parameter_rules.hpp"
#include "statements.hpp"
#include "tcpm_options.hpp"

namespace kin5::program::heidenhain::detail {

/// Whether `text` has a CR that no LF follows (a line ending of CR alone).
inline bool has_lone_cr(std::string_view text) {
  for (std::size_t k = text.find('\r'); k != std::string_view::npos; k = text.find('\r', k + 1))
    if (k + 1 == text.size() || text[k + 1] != '\n') return true;
  return false;
}

/// Whether block `b` ends the program run: M2 or M30 (TNC 640 User's Manual, "Subprograms and
/// program section repeats": the subprograms follow the block with M2 or M30).
inline bool ends_program(const block& b) {
  for (int m : b.m_codes)
    if (m == 2 || m == 30) return true;
  return false;
}

/// Reads one block: the keyword decides which words it takes.
class block_reader : public word_checks {
 public:
  block_reader(const block_text& text, reader_state& state, read_result& out)
      : word_checks(text, out), state_(state) {}

  block read() {
    std::size_t i = scan_.skip_spaces(0);
    b_.text = t_.raw;
    b_.where = t_.where(i);
    control_bytes(i);
    i = block_number(i);
    const std::optional<source_location> dwell_opened = state_.dwell_opened;
    dispatch(i);
    if (dwell_opened && !dwell_closed_) dwell_unfinished(*dwell_opened);
    cycle_call_m();
    // Written anywhere but last, the block would take the next one into it.
    if (t_.continued_past_end && b_.passthrough) error(t_.content.size(), "'~' continues the block past the end of the file");
    for (auto c = t_.inner_comments.rbegin(); c != t_.inner_comments.rend(); ++c)  // comments before `~`
      if (!b_.passthrough) b_.comment = *c + (b_.comment ? " " + *b_.comment : std::string());
    if (b_.comment) b_.comment->resize(end_without_continuation(*b_.comment));  // `*~;x~` is `x`, not `x ~`
    if (!b_.passthrough) {
      for (std::size_t k : stray_) stray_error(k);
      if (b_.axes.x_mm) state_.last[0] = b_.axes.x_mm;
      if (b_.axes.y_mm) state_.last[1] = b_.axes.y_mm;
      if (b_.axes.z_mm) state_.last[2] = b_.axes.z_mm;
      const std::optional<double> given[6] = {b_.axes.x_mm, b_.axes.y_mm, b_.axes.z_mm,
                                              b_.axes.a_deg, b_.axes.b_deg, b_.axes.c_deg};
      for (std::size_t a = 0; a < 6; ++a) {
        if (!given[a]) continue;
        if (b_.machine_coordinates) state_.position[a].reset(), state_.lost_line[a] = b_.where.line;
        else state_.position[a] = axis_position{*given[a], state_.decimals[a]};
      }
    }
    return std::move(b_);
  }

 private:
  reader_state& state_;
  block b_;
  std::vector<std::size_t> stray_;  // bytes that start no word: errors unless the block passes through
  bool dwell_closed_ = false;       // this block is the CYCL DEF 9.1 of the 9.0 before it

  /// M99 / M89 call the last cycle defined: refused (cycles are refused until kin5 reads them).
  void cycle_call_m() {
    for (int m : b_.m_codes) {
      if (m != 99 && m != 89) continue;
      const std::string word = "M" + std::to_string(m);
      std::size_t at = 0;
      for (std::size_t k = t_.upper.find(word); k != std::string::npos; k = t_.upper.find(word, k + 1))
        if (k + word.size() >= t_.upper.size() || !is_digit(t_.upper[k + word.size()])) {
          at = k;
          break;
        }
      error(at, word + ": a cycle call is not supported (fixed cycles are refused until kin5 reads them)");
      return;
    }
  }

  void stray_error(std::size_t k) {
    const char c = s_[k];
    if (lexing::is_control(c)) return;  // reported with the control bytes
    error(k, static_cast<unsigned char>(c) >= 0x80 ? "unexpected byte " + lexing::hex_byte(c, true)
                                                   : std::string("unexpected character '") + c + "'");
  }

  /// Control bytes outside comments (and outside `*` section lines), one diagnostic each.
  void control_bytes(std::size_t i) {
    std::size_t k = i;
    while (k < s_.size() && is_digit(s_[k])) ++k;
    if (scan_.skip_spaces(k) < s_.size() && s_[scan_.skip_spaces(k)] == '*') return;
    for (k = 0; k < s_.size() && s_[k] != ';'; ++k)
      if (lexing::is_control(s_[k])) error(k, "unexpected byte " + lexing::hex_byte(s_[k], true));
  }

  std::size_t block_number(std::size_t i) {
    if (i >= s_.size() || !is_digit(s_[i])) return i;
    std::size_t k = i;
    while (k < s_.size() && is_digit(s_[k])) ++k;
    long long n = 0;
    const auto r = std::from_chars(s_.data() + i, s_.data() + k, n);
    // the bound of every number the readers take (`max_magnitude`), as the ISO and Siemens N
    // words have it: a number past it is one no other dialect's reader reads back
    if (r.ec != std::errc{} || static_cast<double>(n) > max_magnitude) error(i, "block number out of range");
    else b_.number = n;
    return scan_.skip_spaces(k);
  }

  void dispatch(std::size_t i) {
    const std::string head = scan_.letters(i);
    if (i >= s_.size()) return;  // a block number alone
    if (s_[i] == ';' || s_[i] == '*') {
      b_.comment = s_.substr(i + 1);
    } else if (auto begin = scan_.keywords(i, {"BEGIN", "PGM"})) {
      program_line(i, *begin, true);
    } else if (auto end = scan_.keywords(i, {"END", "PGM"})) {
      program_line(i, *end, false);
    } else if (auto call = scan_.keywords(i, {"TOOL", "CALL"})) {
      tool_call(i, *call);
    } else if (head == "L" || head == "LN" || head == "C" || head == "CC" || head == "CR") {
      motion_reader(t_, state_, out_, b_, stray_).read(i, head);
    } else if (head == "M" && i + 1 < s_.size() && (is_digit(s_[i + 1]) || is_space(s_[i + 1]))) {
      m_line(i);
    } else if (auto f = scan_.keywords(i, {"FUNCTION", "TCPM"})) {
      function_tcpm(*f);
    } else if (auto r = scan_.keywords(i, {"FUNCTION", "RESET", "TCPM"})) {
      b_.tcp = false;
      if (!only_comment_after(*r)) {
        b_.passthrough = true, b_.tcp.reset();
        error(scan_.skip_spaces(*r), "FUNCTION RESET TCPM: words after it are not supported");
      }
    } else if (auto cycle = scan_.keywords(i, {"CYCL", "DEF"})) {
      cycle_definition(i, *cycle);
    } else if (is_assignment(std::string_view(s_).substr(i))) {
      b_.passthrough = b_.assignment = true;  // kept as written; the executor has assigned its value
    } else if (const auto fn = fn_head(std::string_view(s_).substr(i)); fn && fn->first != 14) {
      fn_function(i, fn->first);
    } else {
      other(i, head);
    }
  }

  /// `BEGIN PGM name MM|INCH`, `END PGM name MM|INCH`: an INCH program's lengths are inches and
  /// its F 1/10 inch/min, read in millimetres (motion.hpp, `reader_state`). The name is the
  /// program's (TNC 620 User's Manual §4.2: the first block says it, the last says it again) and
  /// moves nothing: an END PGM name other than BEGIN PGM's is read with a warning, and a
  /// Heidenhain writer writes both with the first (writer.hpp). The unit must agree: it decides
  /// what every length means.
  void program_line(std::size_t i, std::size_t after, bool begin) {
    const std::size_t p = scan_.skip_spaces(after);
    const std::size_t e = scan_.run_end(p);
    const std::string name = s_.substr(p, e - p);
    const std::size_t u = scan_.skip_spaces(e);
    const std::size_t ue = scan_.run_end(u);
    const std::string unit = t_.upper.substr(u, ue - u);
    if (name.empty() || unit.empty()) {
      error(i, std::string(begin ? "BEGIN" : "END") + " PGM needs a name and a unit");
    } else if (unit != "MM" && unit != "INCH") {
      error(u, "unknown unit '" + s_.substr(u, ue - u) + "'");
    } else if (begin) {  // the unit of every block after it
      b_.metric = unit == "MM";
      state_.inch = unit == "INCH";
    } else if (state_.inch && *state_.inch != (unit == "INCH")) {
      error(u, "END PGM unit " + unit + " differs from BEGIN PGM's " + (*state_.inch ? "INCH" : "MM"));
    } else {
      b_.metric = unit == "MM";
    }
    if (!name.empty() && begin) {
      b_.program_begin = name;
      state_.begin_name = name;
    } else if (!name.empty()) {
      b_.program_end = name;
      if (state_.begin_name && *state_.begin_name != name)
        warning(p, "END PGM name " + name + " differs from BEGIN PGM's " + *state_.begin_name +
                       ": a program's name moves nothing; a Heidenhain program is written with " +
                       *state_.begin_name + " in both");
    }
    only_comment_after(ue);
  }

  /// `TOOL CALL 5 Z S6000 F… DL… DR…`, `TOOL CALL "MILL_D10" Z …` (a tool by name: TNC 640
  /// User's Manual 1/2015 §5.2 "Tool number, tool name"); any other form is refused at `i`.
  void tool_call(std::size_t i, std::size_t after) {
    bool understood = true;
    std::optional<std::string> name;
    const std::size_t q = scan_.skip_spaces(after);
    if (q < s_.size() && s_[q] == '"') {
      const std::size_t close = s_.find('"', q + 1);
      if (close == std::string::npos || close == q + 1) understood = false;
      else name = s_.substr(q + 1, close - q - 1);
      after = close == std::string::npos ? s_.size() : close + 1;
    }
    std::vector<word> ws = scan_.words(after, b_.comment, stray_);
    understood = understood && (!ws.empty() || name);
    const word* oversize = nullptr;  // DL, DR, DR2 other than 0
    block t = b_;
    if (name) t.tool_name = std::move(name), t.state.tool_change = true;  // TOOL CALL "NAME" changes the tool
    for (word& w : ws) {
      if (w.key.empty() && w.value && !t.tool && !t.tool_name && !t.spindle_rpm && t.kept_words.empty()) {
        long long n = 0;
        if (!integer_word(w, n)) understood = false;
        t.tool = n;
        t.state.tool_change = true;  // TOOL CALL n changes the tool
      } else if (w.key.size() == 1 && (w.key == "X" || w.key == "Y" || w.key == "Z") && !w.value && !w.sign &&
                 !w.expression && w.error == number_error::none) {
        t.kept_words.push_back(w.key);
      } else if (w.key == "S" && w.value && !t.spindle_rpm) {
        if (rate_ok(w, "spindle speed")) t.spindle_rpm = *w.value;
      } else if (w.key == "F" && w.value && !t.feed) {
        if (rate_ok(w, "feed")) t.feed = *w.value * state_.mm_per_min_per_feed();
      } else if ((w.key == "DL" || w.key == "DR" || w.key == "DR2") && w.value) {
        if (*w.value != 0 && !oversize) oversize = &w;
        t.kept_words.push_back(w.written);
      } else {
        understood = false;
      }
    }
    if (!understood || !(t.tool || t.tool_name || t.spindle_rpm)) {
      b_.comment.reset();
      b_.passthrough = true;
      error(i, "TOOL CALL: only TOOL CALL n or \"name\" with an axis, S, F, DL and DR is read (a tool called "
               "with other words is not supported)");
      return;
    }
    // An oversize moves the tool tip (DL) or the contour (DR with RL/RR, or LN normals): only a
    // zero one changes nothing.
    if (oversize)
      error(oversize->pos, oversize->written + ": a tool oversize in TOOL CALL is not supported yet (the path would move by it)");
    b_ = std::move(t);
    for (const std::string& w : b_.kept_words)  // the tool axis sets the working plane
      if (w == "X" || w == "Y" || w == "Z")
        state_.working = state_.plane = w == "Z" ? arc_plane::xy : w == "Y" ? arc_plane::zx : arc_plane::yz;
  }

  /// A line of M functions; with other words it passes through (axis words are an error).
  void m_line(std::size_t i) {
    std::vector<word> ws = scan_.words(i, b_.comment, stray_);
    block m = b_;
    bool understood = true;
    for (std::size_t k = 0; k < ws.size(); ++k) {
      word& w = ws[k];
      long long n = 0;
      // `M140 MB MAX`: retract along the tool axis to the end of its travel (TNC 640 User's
      // Manual, "Retraction in the tool axis: M140"); a distance (`MB 50`) is not read.
      if (w.key == "M" && w.value == 140.0 && k + 2 < ws.size() && ws[k + 1].key == "MB" && !ws[k + 1].value &&
          !ws[k + 1].expression && ws[k + 2].key == "MAX" && !ws[k + 2].value && !ws[k + 2].expression &&
          !m.machine_coordinates) {
        m.machine_coordinates = true;
        m.machine_reference = machine_position::tool_axis_limit;
        k += 2;
        continue;
      }
      if (w.key == "M" && w.value && *w.value >= 0 && *w.value <= 9999 &&
          *w.value == static_cast<double>(static_cast<long long>(*w.value)) && integer_word(w, n)) {
        set_m(m, n);
      } else {
        understood = false;
      }
    }
    if (understood) {
      b_ = std::move(m);
      return;
    }
    b_.comment.reset();
    b_.passthrough = true;
    for (const word& w : ws) {
      if (!w.key.empty() && w.key.size() <= 2 && is_axis_letter(w.key.back()) && (w.key.size() == 1 || w.key[0] == 'I') &&
          (w.value || w.expression || w.error != number_error::none)) {
        error(w.pos, "axis word '" + w.key + "' without a motion keyword");
        return;
      }
    }
    for (const word& w : ws)
      if (w.key != "M" || !w.value) {
        const std::string text = w.written.empty() ? w.key : w.written;
        error(w.pos, "'" + text + "' in an M block is not supported (M140 MB retracts by a distance, M120 looks "
                     "ahead: the machine would do something else; kin5 reads M140 MB MAX)");
        return;
      }
  }

  /// `FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS`: TCP on, the option pairs kept.
  void function_tcpm(std::size_t k) {
    b_.tcp = true;
    std::vector<std::string> tokens;
    std::vector<std::size_t> at;
    while (!only_comment_after(k)) {
      k = scan_.skip_spaces(k);
      const std::size_t e = scan_.run_end(k);
      tokens.push_back(t_.upper.substr(k, e - k));
      at.push_back(k);
      k = e;
    }
    for (std::size_t t = 0; t < tokens.size(); t += 2) {
      std::string kw = tokens[t] + (t + 1 < tokens.size() ? " " + tokens[t + 1] : "");
      if (kw == "AXIS SPAT") error(at[t], "FUNCTION TCPM AXIS SPAT is not supported");
      else if (!is_tcpm_option(kw))
        error(at[t], "FUNCTION TCPM " + kw + " is not supported (kin5 reads F TCP, AXIS POS, PATHCTRL AXIS)");
      b_.kept_words.push_back(std::move(kw));
    }
  }

  /// `CYCL DEF n.m …`: the frame cycles (7, 8, 10, 11, 19, 26) pass through when every value is
  /// the identity, else are errors; every other cycle is refused at its first line (`n` or `n.0`).
  void cycle_definition(std::size_t i, std::size_t after) {
    const std::size_t k = scan_.skip_spaces(after);
    std::size_t e = k;
    while (e < s_.size() && is_digit(s_[e])) ++e;
    const std::string number = s_.substr(k, e - k);
    std::string part;
    if (e < s_.size() && s_[e] == '.') {
      std::size_t p = e + 1;
      while (p < s_.size() && is_digit(s_[p])) ++p;
      part = s_.substr(e + 1, p - e - 1);
      e = p;
    }
    if (number == "247" && part.empty()) return preset_selection(i, e);
    if (number == "9" && part == "1") return dwell_time(i, e);
    b_.passthrough = true;
    if (number == "9" && part == "0") return void(state_.dwell_opened = t_.where(i));
    const bool frame = number == "7" || number == "8" || number == "10" || number == "11" || number == "19" ||
                       number == "26";
    const double identity = (number == "11" || number == "26") ? 1.0 : 0.0;
    if (frame && !part.empty() && part != "0" && cycle_values_active(e, identity))
      error(i, "CYCL DEF " + number + " changes the working frame; kin5 does not model frame changes");
    else if (!frame && (part.empty() || part == "0")) error(i, cycle_refusal(number));
  }

  /// `CYCL DEF 247 DATUM SETTING ~ Q339=+n`: selects row n of the preset table (TNC 640 User's
  /// Manual for Cycle Programming, Cycle 247 DATUM SETTING), `state.work_offset` {preset, n}.
  /// Anything else in the block is refused at it.
  void preset_selection(std::size_t i, std::size_t p) {
    std::optional<int> row;
    while (!only_comment_after(p)) {
      p = scan_.skip_spaces(p);
      const std::string key = scan_.letters(p);
      if ((key == "DATUM" || key == "SETTING") && !row) {
        p += key.size();
        continue;
      }
      if (!row && t_.upper.compare(p, 5, "Q339=") == 0) {
        const parsed_number n = read_number(std::string_view(s_).substr(p + 5));
        if (n.error == number_error::none && n.length > 0 && n.value >= 0 && n.value <= 65535 &&
            n.value == static_cast<double>(static_cast<int>(n.value))) {
          row = static_cast<int>(n.value);
          p += 5 + n.length;
          continue;
        }
      }
      b_.passthrough = true;
      return error(p, "CYCL DEF 247 (datum setting): only Q339=n, a preset number from 0 to 65535, is read");
    }
    if (!row) {
      b_.passthrough = true;
      return error(i, "CYCL DEF 247 (datum setting) without Q339 in its block: the preset it selects is not known");
    }
    b_.state.work_offset = work_offset{work_offset_family::preset, *row};
  }

  /// A `CYCL DEF 9.0` at `at` whose next block is not its `CYCL DEF 9.1`: refused at the 9.0,
  /// whose dwell would be lost.
  void dwell_unfinished(const source_location& at) {
    out_.add_error({at, "CYCL DEF 9.0 (dwell time) without its CYCL DEF 9.1 DWELL block after it"});
    if (state_.dwell_opened == at) state_.dwell_opened.reset();
  }

  /// `CYCL DEF 9.1 DWELL 1.5` after `CYCL DEF 9.0 DWELL TIME`: Cycle 9, a dwell of 1.5 s, in effect
  /// where it is defined (TNC 640 User's Manual for Cycle Programming, Cycle 9 DWELL TIME;
  /// 0 to 3600 s, TNC 640 User's Manual DIN/ISO 1/2015 p. 631). The 9.0 block before it passes
  /// through, as the cycle's header.
  void dwell_time(std::size_t i, std::size_t p) {
    const bool opened = state_.dwell_opened.has_value();
    state_.dwell_opened.reset();
    dwell_closed_ = opened;
    if (!opened) return error(i, "CYCL DEF 9.1 without CYCL DEF 9.0 DWELL TIME in the block before it");
    const auto dwell = scan_.keywords(p, {"DWELL"});
    const std::size_t v = dwell ? scan_.skip_spaces(*dwell) : p;
    const parsed_number n = read_number(std::string_view(s_).substr(v));
    if (!dwell || n.error != number_error::none || n.length == 0 || !only_comment_after(v + n.length))
      return error(i, "CYCL DEF 9.1: only DWELL and a time in seconds are read (CYCL DEF 9.1 DWELL 1.5)");
    if (n.value < 0) return error(v, "CYCL DEF 9.1 DWELL: a dwell time cannot be negative");
    if (const std::string why = dwell_refusal(dwell_steps, n.value); !why.empty())
      return error(v, "CYCL DEF 9.1 DWELL: " + why);
    b_.state.dwell_s = n.value;
  }

  /// Why cycle `number` (not a frame cycle) is refused.
  static std::string cycle_refusal(const std::string& number) {
    const std::string head = "CYCL DEF " + (number.empty() ? std::string("without a number") : number);
    if (number == "32") return head + " (tolerance) is not supported yet: the contour tolerance would be lost";
    return head + " is not supported: fixed cycles are refused until kin5 reads them (their holes and pockets "
                  "would be lost)";
  }

  /// Whether any value of a frame cycle from `p` on differs from `identity` (0, or scale 1).
  bool cycle_values_active(std::size_t p, double identity) const {
    bool active = false;
    while (p < s_.size() && s_[p] != ';') {
      if (is_letter(s_[p]) && (p == 0 || !is_letter(s_[p - 1]))) {
        const std::string key = scan_.letters(p);
        const std::size_t v = p + key.size();
        if (key == "F" || key == "ABST" || key == "DATUM" || key == "SHIFT" || key == "WORKING" || key == "PLANE" ||
            key == "ROTATION" || key == "SCALING" || key == "IROT") {
          p = v;
        } else if (starts_number(s_, v)) {
          const parsed_number n = read_number(std::string_view(s_).substr(v));
          if (n.error != number_error::none || n.value != identity) active = true;
          p = v + std::max<std::size_t>(n.length, 1);
        } else {
          active = true;  // a mirrored axis, or a parameter
          p = v;
        }
        continue;
      }
      if (s_[p] == '#' || s_[p] == 'Q') active = true;
      ++p;
    }
    return active;
  }

  /// PLANE, TRANS, BLK, TOOL DEF, STOP; calls, labels and functions, the contour functions kin5
  /// does not read, stray axis words: refused; anything else refused as an unknown keyword.
  void other(std::size_t i, const std::string& head) {
    if (refused_keyword(i, head)) return;
    if (head == "PLANE" || head == "TRANS") {
      const std::size_t k = scan_.skip_spaces(i + head.size());
      const std::string kind = scan_.letters(k);
      const bool reset = head == "PLANE" ? kind == "RESET" : scan_.letters(scan_.skip_spaces(k + kind.size())) == "RESET";
      if (!reset) error(i, head + " " + kind + " changes the working frame; kin5 does not model frame changes");
      b_.passthrough = true;
    } else if (head == "BLK" || scan_.keywords(i, {"TOOL", "DEF"})) {
      b_.passthrough = true;  // the blank's shape, a tool made ready: no motion
    } else if (head == "STOP" && only_comment_after(i + head.size())) {
      b_.state.stop = program_stop::stop;
    } else if (head == "CT" || head == "CP" || head == "LP" || head == "CTP" || head == "RND" || head == "CHF" ||
               head == "APPR" || head == "DEP" || head == "FL" || head == "FLT" || head == "FC" || head == "FCT" ||
               head == "FPOL" || head == "CCA") {
      error(i, "'" + head + "' is not supported");
    } else if ((head.size() == 1 || (head.size() == 2 && head[0] == 'I')) && is_axis_letter(head.back()) &&
               scan_.has_axis_word(i)) {
      error(i, "axis word '" + head + "' without a motion keyword");  // IX too: an L, C or CC reads it
    } else if (scan_.has_axis_word(i)) {
      error(i, "unknown keyword '" + t_.upper.substr(i, scan_.run_end(i) - i) + "' in a block with axis words");
      b_.passthrough = true;
    } else {
      error(i, "unknown keyword '" + t_.upper.substr(i, scan_.run_end(i) - i) +
                   "' is not supported: only blocks known not to change the motion are passed on");
      b_.passthrough = true;
    }
  }

  /// `PGM CALL file`, `SEL PGM file`, `CALL SELECTED PGM` (`CALL PGM` is the executor's): the
  /// keywords and the file as written, when the block at `i` is one.
  std::optional<std::string> called_program(std::size_t i) const {
    for (const auto& ws : {std::initializer_list<std::string_view>{"PGM", "CALL"}, {"SEL", "PGM"},
                           {"CALL", "SELECTED", "PGM"}}) {
      const auto after = scan_.keywords(i, ws);
      if (!after || (*after < s_.size() && !is_space(s_[*after]))) continue;
      std::string head;
      for (std::string_view w : ws) {
        if (!head.empty()) head += ' ';
        head += w;
      }
      const std::size_t f = scan_.skip_spaces(*after);
      const std::size_t e = scan_.run_end(f);
      return e > f ? head + " " + s_.substr(f, e - f) : head;
    }
    return std::nullopt;
  }

  /// Whether only blanks and a `;` comment follow `k` (the comment is kept).
  bool only_comment_after(std::size_t k) {
    k = scan_.skip_spaces(k);
    if (k < s_.size() && s_[k] == ';') b_.comment = s_.substr(k + 1);
    return k >= s_.size() || s_[k] == ';';
  }

  /// `FN 14: ERROR = n ;text` at `i`: the program stops with the control's error n (0 … 1199),
  /// the line's comment its message (docs/dialects/heidenhain.md); true when the block is FN 14.
  /// A number that is not a whole one in that range, or a parameter, is refused.
  bool error_stop(std::size_t i) {
    const auto fn = fn_head(std::string_view(t_.upper).substr(i));
    if (!fn || fn->first != 14) return false;
    const std::string_view u(t_.upper);
    std::size_t k = scan_.skip_spaces(i + fn->second);
    bool ok = scan_.letters(k) == "ERROR";
    if (ok) k = scan_.skip_spaces(k + 5), ok = k < u.size() && u[k] == '=';
    parsed_number n{};
    if (ok) {
      k = scan_.skip_spaces(k + 1);
      n = read_number(u.substr(k));
      ok = n.error == number_error::none && n.length > 0 && n.value >= 0 && n.value <= 1199 &&
           n.value == static_cast<double>(static_cast<long long>(n.value));
      k += n.length;
    }
    if (ok) ok = only_comment_after(k);
    if (!ok) {
      error(i, "FN 14: kin5 reads FN 14: ERROR = n with n a whole number from 0 to 1199, then at most a comment");
      b_.passthrough = true;
      return true;
    }
    b_.alarm = alarm_stop{b_.comment.value_or(""), static_cast<long long>(n.value)};
    b_.comment.reset();
    return true;
  }

  /// `FN n:` other than the assignments (FN 0 to FN 8, FN 13), whose values the executor has
  /// given, and the jumps (FN 9 to FN 12), which it has taken: refused at `i`, naming it.
  void fn_function(std::size_t i, int fn) {
    b_.passthrough = true;
    if (fn == 18)
      return error(i, "FN 18: SYSREAD reads the machine's state, which the program does not fix; kin5 cannot know "
                      "the value");
    error(i, "FN " + std::to_string(fn) + ": this Q-parameter function is not supported (kin5 runs FN 0 to FN 13)");
  }

  /// Cycle calls, labels, program calls and FN functions: refused at `i`, naming them.
  bool refused_keyword(std::size_t i, const std::string& head) {
    std::string why;
    if (head == "CYCL") why = "CYCL CALL: a cycle call is not supported (fixed cycles are refused until kin5 reads them)";
    else if (head == "LBL") why = "LBL: labels are not supported (the path would depend on the calls and repeats)";
    else if (auto file = called_program(i))
      why = *file + ": not supported (its motion would be lost); kin5 runs a program in another file called with CALL "
                    "PGM file";
    else if (head == "CALL" || head == "SEL" || head == "PGM")
      why = t_.upper.substr(i, scan_.run_end(scan_.skip_spaces(scan_.run_end(i))) - i) +
            ": program and label calls are not supported (the motion they make would be lost)";
    else if (head == "FN" && error_stop(i)) return true;
    else if (head == "FN") why = "FN: functions other than FN 0 (a constant) and FN 14 (an error) are not supported";
    if (why.empty()) return false;
    error(i, why);
    b_.passthrough = true;
    return true;
  }
};

}  // namespace kin5::program::heidenhain::detail

namespace kin5::program::heidenhain {

/// Reads a Heidenhain conversational program as a TNC runs it, block by block: the executor
/// (../interp/executor.hpp) runs the lines (statements.hpp: labels, subprogram calls, section
/// repeats, FN 9–FN 12 jumps, assignments) and `on_block` receives each block it runs, in the order
/// run, as soon as it is read; errors and warnings go to `out` (its `parsed` is not touched). The
/// run ends at M2, M30 or END PGM; the blocks after that end which lie outside the subprograms
/// (`LBL n` … `LBL 0`), `END PGM` for one, are read after it, in file order, with their
/// assignments (a control never runs them; kin5 reads them as it did before it ran programs).
/// `limits` bounds the lines run (`--max-executed-lines`).
inline void read_blocks(std::string_view text, const std::string& file_path, read_result& out,
                        const block_sink& on_block, const interp::execution_limits& limits) {
  const file_name file(file_path);  // one string for every location in the file
  detail::reader_state state;
  read_transmitted(text, file_path, out, on_block, [&](std::string_view body, const block_sink& sink) {
    std::string lf_ends;  // the executor ends lines at LF: a lone CR becomes one (same offsets, same lines)
    if (detail::has_lone_cr(body)) {
      lf_ends.assign(body);
      for (std::size_t k = 0; k < lf_ends.size(); ++k)
        if (lf_ends[k] == '\r' && (k + 1 == lf_ends.size() || lf_ends[k + 1] != '\n')) lf_ends[k] = '\n';
      body = lf_ends;
    }
    const std::vector<text_line> lines = split_lines(body);
    statements syntax(lines);
    interp::executor run(body, parameter_rules(), limits);
    run.record_calls_in(out.calls, file);
    state.parameters = &run.parameters();
    // The programs CALL PGM runs, by path: a copy of each text (the executor runs its own) and its
    // lines, for the blocks continued with `~`; the name and unit of its BEGIN PGM.
    struct called_program {
      std::string text;
      std::vector<text_line> lines;
      std::optional<std::string> begin_name;
    };
    std::map<std::string, called_program> called;
    const read_limits reading = current_read_limits();
    run.open_files_with([&](const std::string&, const std::vector<std::string>& names) -> std::optional<interp::called_file> {
      const beside_caller_result found =
          find_beside_caller(run.file().empty() ? file_path : run.file(), names, reading.include_dirs);
      if (!found.path)
        return interp::called_file{names.front(), {},
                                   found.not_found + " (--include-dir DIR names the directory that holds it)"};
      interp::called_file f = load_called_file(*found.path, reading);
      if (f.error.empty() && called.find(f.path) == called.end()) {  // loaded again for another caller: the same text
        called_program& c = called[f.path];
        c.text = f.text;
        c.lines = split_lines(c.text);
      }
      return f;
    });
    std::optional<std::size_t> tail;  // the first line after the block that ended the run
    bool tail_in_subprogram = false;   // the run ended inside a called subprogram
    // Reads the block that starts at line `li`; returns its last line's index.
    const auto read_block = [&](std::size_t li, bool ends_run) {
      block_text source;
      source.file = file;
      const std::size_t last = detail::join_block(lines, li, source);
      block b = detail::block_reader(source, state, out).read();
      b.call_chain = out.reading_call;
      if (ends_run && !b.passthrough && (b.program_end || detail::ends_program(b))) {
        tail = last + 1;
        tail_in_subprogram = run.call_chain() != 0;
        syntax.end_program();
      }
      sink(std::move(b));
      return last;
    };
    // Reads the block at line `line` of the called program at `path`: its BEGIN PGM and END PGM
    // make no block (the main program's frame the executed program), and must say the caller's
    // unit.
    const auto read_called_block = [&](const std::string& path, const text_line& line) {
      if (lexing::is_blank(line.text)) return;
      called_program& c = called[path];
      block_text source;
      source.file = file_name(path);
      detail::join_block(c.lines, line.number - 1, source);
      const std::optional<bool> caller_inch = state.inch;
      std::optional<std::string> caller_name = std::move(state.begin_name);
      state.begin_name = c.begin_name;
      block b = detail::block_reader(source, state, out).read();
      c.begin_name = std::move(state.begin_name);
      state.begin_name = std::move(caller_name);
      const bool unit_differs = state.inch.value_or(false) != caller_inch.value_or(false);
      state.inch = caller_inch;
      if (b.program_begin || b.program_end) {
        if (unit_differs)
          out.add_error({b.where, std::string(b.program_begin ? "BEGIN" : "END") + " PGM " + c.begin_name.value_or("") +
                                      ": a called program in " + (caller_inch.value_or(false) ? "MM" : "INCH") +
                                      " from a program in " + (caller_inch.value_or(false) ? "INCH" : "MM") +
                                      " is not supported (give both programs one unit)"});
        return;
      }
      if (!b.passthrough && detail::ends_program(b))
        out.add_error({b.where, "M2 or M30 in a program that CALL PGM runs: the TNC does not allow them there (the "
                                "called program ends at its END PGM)"});
      sink(std::move(b));
    };
    const bool ran = run.execute(
        syntax,
        [&](const text_line& line, const interp::statement& s) {
          if (!run.file().empty()) return read_called_block(run.file(), line);
          if (s.ends_program || lexing::is_blank(line.text)) return;  // the line after the end; a blank line
          out.reading_call = run.call_chain();
          read_block(line.number - 1, true);
        },
        [&](const interp::flow_error& e) {  // at the statement, after its block number
          out.reading_call = run.call_chain();
          std::size_t column = e.column;
          const std::vector<text_line>& in = e.file.empty() ? lines : called[e.file].lines;
          if (e.line >= 1 && e.line <= in.size()) {
            const std::string_view t = in[e.line - 1].text;
            if (column == lexing::skip_blanks(t, 0) + 1 && column <= t.size() && is_digit(t[column - 1])) {
              while (column <= t.size() && is_digit(t[column - 1])) ++column;
              column = lexing::skip_blanks(t, column - 1) + 1;
            }
          }
          out.add_error({{e.file.empty() ? file : file_name(e.file), e.line, column}, e.message});
        });
    out.reading_call = 0;
    if (ran && tail) {  // after the end: what lies outside the subprograms, as written
      syntax.resume();
      bool in_subprogram = tail_in_subprogram;
      for (std::size_t li = *tail; li < lines.size(); ++li) {
        if (lexing::is_blank(lines[li].text)) continue;
        const interp::statement s = syntax.statement_of(lines[li]);
        if (s.kind == interp::statement_kind::label && !s.label.empty()) in_subprogram = true;
        else if (s.kind == interp::statement_kind::return_from_call) in_subprogram = false;
        else if (s.kind == interp::statement_kind::ordinary && !in_subprogram) {
          for (const interp::assignment& a : s.assignments) {  // in file order, as the blocks are read
            const interp::evaluation v = interp::evaluate(a.value, run.parameters());
            const interp::parameter_target t = interp::parameter_of(a.target, run.parameters());
            std::optional<std::string> why = !v.ok() ? v.error->message : !t.key ? t.error->message : std::optional<std::string>{};
            if (!why) why = run.parameters().assign(*t.key, v.value);
            if (why) out.add_error({{file, li + 1, (!v.ok() ? v.error->where : a.target.at(a.target.root).where).column}, *why});
          }
          li = read_block(li, false);
        }
      }
    }
    if (state.dwell_opened)
      out.add_error({*state.dwell_opened, "CYCL DEF 9.0 (dwell time) without its CYCL DEF 9.1 DWELL block after it"});
  });
}

/// The same, with the bound on the lines run of the reading under way (`current_read_limits`).
inline void read_blocks(std::string_view text, const std::string& file_path, read_result& out,
                        const block_sink& on_block) {
  read_blocks(text, file_path, out, on_block, interp::execution_limits{current_read_limits().max_executed_lines});
}

}  // namespace kin5::program::heidenhain
