/// @file program/apt/reader.hpp
/// The second stage of the APT reader: a statement (lexer.hpp) becomes a `block`.
/// `GOTO/x,y,z[,i,j,k]` (tool tip, tool-axis vector), `RAPID` (the next GOTO is rapid),
/// `FEDRAT/[MMPM,|IPM,|INVERS,]f`, `SPINDL/[RPM,]n[,CLW|CCLW]`, `SPINDL/ON|OFF|CLW|CCLW`,
/// `LOADTL/n` and `LOAD/TOOL,n` (a tool change: the tool and M6, as ISO's `T n M6`),
/// `SELECT/TOOL,n` (the tool alone, as ISO's `T n`), `MULTAX[/ON|OFF]` (a kept word),
/// `COOLNT/ON|FLOOD|MIST|OFF`, `STOP`, `OPSTOP`, `DELAY/t` (a dwell of t seconds),
/// `UNITS/MM|INCHES` (also `UNIT/`), `PARTNO name`, `FINI`, `PPRINT/text` and `$$ text` comments,
/// `CIRCLE/xc,yc,zc,i,j,k,r` and the GOTO after it: one arc block (circle.hpp). After `UNITS/INCHES` GOTO points and unit-less
/// feeds are inches, converted to mm (units.hpp); `IPM` feeds always are. Statements that only
/// describe (vocabulary.hpp: `CUTTER`, `TLDATA`, …) and an identity `CSYS`/`MSYS`
/// pass through; every other statement is refused at its major word, with the reason (`CYCLE`,
/// `INSERT`, `TLAXIS`, `CUTCOM`, unknown words, …), as are per-revolution feeds, a CIRCLE that is
/// not one arc in a principal plane, and GOTO with other than 3 or 6 values.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../machine_functions.hpp"
#include "../lexing.hpp"
#include "../number.hpp"
#include "../text.hpp"
#include "../transmission.hpp"
#include "../units.hpp"
#include "circle.hpp"
#include "lexer.hpp"
#include "vocabulary.hpp"

namespace kin5::program::apt::detail {

/// Reads one statement into a block; remembers whether a RAPID is pending, the last GOTO's
/// point and tool axis, and a CIRCLE waiting for the GOTO of its end.
class statement_reader {
 public:
  statement_reader(const file_name& file, bool& rapid_pending, read_result& diagnostics)
      : file_(file), rapid_pending_(rapid_pending), diagnostics_(diagnostics) {}

  /// The block of statement `st`; none for a CIRCLE, whose block is the GOTO after it.
  std::optional<block> read(const statement& st) {
    block b = read_statement(st);
    if (std::exchange(holding_, false)) return std::nullopt;
    return b;
  }

  /// The end of the text: a CIRCLE still waiting has no end point.
  void finish() { circles_.interrupt(diagnostics_); }

 private:
  block read_statement(const statement& st) {
    st_ = &st;
    block b;
    b.where = st.at(file_, 0);
    b.text = st.text;
    if (st.has_comment) b.comment = st.comment;
    c_ = split_code(st.content);
    if (c_.major != "GOTO" && !(c_.major.empty() && st.has_comment)) circles_.interrupt(diagnostics_);
    // Free text after PARTNO / PPRINT / INSERT may hold any byte; elsewhere control bytes are errors.
    const bool free_text = c_.major == "PARTNO" || c_.major == "PPRINT" || c_.major == "INSERT";
    if (control_byte(free_text ? c_.major_at : st.content.size())) return b;
    if (c_.major.empty()) {
      b.passthrough = !st.has_comment;  // a `$$` comment line, or something else kept as written
      return b;
    }
    // In APT a trailing '$' continues the statement and '$$' starts a comment, so a '$' kept in
    // free text could not be written back with the same meaning: reject it rather than guess.
    if (free_text) {
      const std::size_t dollar = st.content.find('$', c_.rest);
      if (dollar != std::string::npos) {
        error(dollar, "'$' in " + c_.major + " text is ambiguous (continuation or comment in APT)");
        return b;
      }
    }
    args_ = arguments(st.content, c_.rest);
    major(b);
    return b;
  }

  const file_name& file_;
  bool& rapid_pending_;
  read_result& diagnostics_;
  const statement* st_ = nullptr;
  bool inch_ = false;  // UNITS/INCHES: GOTO points (and FEDRAT without a unit) in inches
  code c_;
  std::vector<argument> args_;
  std::optional<vec3> at_mm_;  // the last GOTO's point, mm
  vec3 axis_ = unit_z;         // the tool axis in effect (+Z until a GOTO gives one, as post reads it)
  circle_state circles_;
  bool holding_ = false;       // this statement is a CIRCLE held for its GOTO

  void error(std::size_t offset, std::string message, std::string construct = {}) {
    diagnostics_.add_error({st_->at(file_, offset), std::move(message), std::move(construct)});
  }

  /// Reports the first control byte before `end`; true if there is one.
  bool control_byte(std::size_t end) {
    for (std::size_t k = 0; k < end; ++k) {
      const char ch = st_->content[k];
      const auto u = static_cast<unsigned char>(ch);
      if ((u < 0x20 && ch != '\t') || u == 0x7f) {
        error(k, "unexpected byte " + lexing::hex_byte(ch, true));
        return true;
      }
    }
    return false;
  }

  /// Nothing after the major word; else reported.
  bool no_values() {
    if (c_.tail.empty()) return true;
    error(c_.rest, "unexpected '" + std::string(c_.tail) + "' after " + c_.major);
    return false;
  }

  /// Argument `a` as a plain number into `v`; false, reported, if it is not one.
  bool number(const argument& a, double& v) {
    const parsed_number n = read_number(a.text);
    if (n.error == number_error::too_large) {
      error(a.offset, "value out of range");
      return false;
    }
    if (n.error != number_error::none || n.length != a.text.size()) {
      const bool malformed =
          n.length > 0 && a.text.substr(n.length).find_first_not_of("0123456789.eE+-") == std::string_view::npos;
      if (a.text.empty()) error(a.offset, c_.major + " value is missing");
      else if (malformed) error(a.offset, "malformed number '" + std::string(a.text) + "'");  // `1.2.3`, `1E5`
      else error(a.offset, "'" + std::string(a.text) + "' is not a number");
      return false;
    }
    v = n.value;
    return true;
  }

  void major(block& b) {
    const std::string& m = c_.major;
    const std::string word = lexing::upper(c_.tail);
    if (m == "GOTO") return go_to(b);
    if (m == "RAPID") {
      if (!no_values()) return;
      b.motion = motion_kind::rapid;
      b.feed_rapid = true;
      rapid_pending_ = true;
    } else if (m == "FEDRAT") {
      feed_rate(b);
    } else if (m == "SPINDL") {
      spindle(b);
    } else if (m == "LOADTL") {
      load_tool(b, 0);
    } else if (m == "LOAD" && !args_.empty() && lexing::upper(args_[0].text) == "TOOL") {
      load_tool(b, 1);
    } else if (m == "SELECT" && !args_.empty() && lexing::upper(args_[0].text) == "TOOL") {
      load_tool(b, 1, false);
    } else if (m == "MULTAX") {
      multax(b, word);
    } else if (m == "COOLNT") {
      if (word == "ON" || word == "FLOOD") take_machine_function(b.state, 8);
      else if (word == "MIST") take_machine_function(b.state, 7);
      else if (word == "OFF") take_machine_function(b.state, 9);
      else error(c_.major_at, "COOLNT/" + word + " is not supported (only ON, FLOOD, MIST and OFF are read)", "COOLNT");
    } else if (m == "STOP" || m == "OPSTOP") {
      if (no_values()) b.state.stop = m == "STOP" ? program_stop::stop : program_stop::optional_stop;
    } else if (m == "DELAY" && args_.size() == 1 && !args_[0].text.empty() && !is_letter(args_[0].text.front())) {
      delay(b);
    } else {
      other(b, word);
    }
  }

  /// UNITS, PARTNO, FINI, PPRINT, CIRCLE; what only describes passes through; the rest is refused.
  void other(block& b, const std::string& word) {
    const std::string& m = c_.major;
    if (m == "UNITS" || m == "UNIT") {
      if (word == "MM" || word == "INCHES" || word == "INCH") b.metric = word == "MM", inch_ = word != "MM";
      else error(c_.major_at, m + "/" + word + " is not supported (only MM and INCHES are read)", m);
    } else if (m == "PARTNO") {
      b.program_begin = std::string(c_.tail);
    } else if (m == "FINI") {
      if (no_values()) b.program_end = std::string();
    } else if (m == "PPRINT") {
      std::string text(c_.tail);
      if (b.comment) text += (text.empty() ? "$$ " : " $$ ") + *b.comment;
      b.comment = std::string(lexing::trim(text));
    } else if (m == "CIRCLE") {
      circle();
    } else if (detail::described(m, c_.tail) || ((m == "CSYS" || m == "MSYS") && identity_frame())) {
      b.passthrough = true;  // written back in APT, a comment elsewhere: it changes no motion
    } else {
      error(c_.major_at, detail::refusal(m, c_.tail), m);
    }
  }

  /// Whether the arguments are the identity frame: `CSYS/` 3×4 matrix [R | t] row by row, or
  /// `MSYS/` origin, x axis, y axis; nothing reported.
  bool identity_frame() const {
    static constexpr double csys[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    static constexpr double msys[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const bool is_csys = c_.major == "CSYS";
    const double* want = is_csys ? csys : msys;
    if (args_.size() != (is_csys ? 12u : 9u)) return false;
    for (std::size_t k = 0; k < args_.size(); ++k) {
      const parsed_number n = read_number(args_[k].text);
      if (n.error != number_error::none || n.length != args_[k].text.size() || n.value != want[k]) return false;
    }
    return true;
  }

  /// `GOTO/x,y,z[,i,j,k]`: rapid when a RAPID came before it; the arc of a CIRCLE before it.
  void go_to(block& b) {
    b.motion = rapid_pending_ ? motion_kind::rapid : motion_kind::linear;
    rapid_pending_ = false;
    if (!c_.slash || (args_.size() != 3 && args_.size() != 6)) {
      circles_.discard();
      return error(c_.major_at, "GOTO needs 3 or 6 values");
    }
    double v[6] = {};
    bool good = true;
    for (std::size_t a = 0; a < args_.size(); ++a) good = number(args_[a], v[a]) && good;
    if (!good) return circles_.discard();
    const double unit_mm = inch_ ? mm_per_inch : 1.0;
    b.axes.x_mm = v[0] * unit_mm, b.axes.y_mm = v[1] * unit_mm, b.axes.z_mm = v[2] * unit_mm;
    at_mm_ = vec3{*b.axes.x_mm, *b.axes.y_mm, *b.axes.z_mm};
    if (args_.size() == 6 && !is_direction(v[3], v[4], v[5])) {
      circles_.discard();
      return error(args_[3].offset, "tool-axis vector shorter than 0.001 is not a direction");
    }
    if (args_.size() == 6) b.axes.tool_axis = vec3{v[3], v[4], v[5]};
    if (const auto why = circles_.end_at(b, *at_mm_, axis_))
      error(why->first == circle_state::at_vector ? args_[3].offset : c_.major_at, why->second, "CIRCLE");
    if (args_.size() == 6) axis_ = vec3{v[3], v[4], v[5]};
  }

  /// `CIRCLE/xc,yc,zc,i,j,k,r` (circle.hpp): held for the GOTO of its end, or refused.
  void circle() {
    if (!c_.slash || args_.size() != 7)
      return error(c_.major_at, "CIRCLE needs 7 values (x, y, z, i, j, k, r); other forms are not read", "CIRCLE");
    double v[7] = {};
    bool good = true;
    for (std::size_t a = 0; a < args_.size(); ++a) good = number(args_[a], v[a]) && good;
    if (!good) return;
    const double unit_mm = inch_ ? mm_per_inch : 1.0;
    const auto c = circle_state::from(unit_mm * vec3{v[0], v[1], v[2]}, vec3{v[3], v[4], v[5]}, v[6] * unit_mm, at_mm_,
                                      rapid_pending_);
    if (const auto* why = std::get_if<circle_state::refusal>(&c))
      return error(why->first == 0 ? c_.major_at : args_[why->first].offset, why->second, "CIRCLE");
    circles_.hold(std::get<circle_state::circle>(c), *st_, file_);
    holding_ = true;
  }

  /// `FEDRAT/[MMPM,|IPM,|INVERS,]f` (f alone: per minute in the program's unit).
  void feed_rate(block& b) {
    if (!c_.slash || c_.tail.empty()) return error(c_.major_at, "FEDRAT needs a feed value");
    std::optional<feed_unit> mode = feed_unit::per_minute;
    double unit_mm = inch_ ? mm_per_inch : 1.0;
    const argument* value = nullptr;
    for (const argument& a : args_) {
      const std::string word = lexing::upper(a.text);
      if (word == "MMPM") mode = feed_unit::per_minute, unit_mm = 1.0;
      else if (word == "INVERS") mode = feed_unit::inverse_time, unit_mm = 1.0;
      else if (word == "IPM") mode = feed_unit::per_minute, unit_mm = mm_per_inch;
      else if (word == "MMPR" || word == "IPR") return error(a.offset, "feed per revolution is not supported");
      else if (!value) value = &a;
      else return error(a.offset, "unexpected '" + std::string(a.text) + "' after FEDRAT");
    }
    double f = 0;
    if (!value) return error(c_.major_at, "FEDRAT needs a feed value");
    if (!number(*value, f)) return;
    // refused if the writer could not write it back, in the unit it writes (the program's)
    const double written = mode == feed_unit::inverse_time ? f : f * unit_mm / (inch_ ? mm_per_inch : 1.0);
    if (auto why = unwritable_rate(written, finest_rate_decimals + (inch_ ? 1 : 0)))
      return error(value->offset, *why);
    b.feed = f * unit_mm;
    b.feed_mode = mode;
  }

  /// `SPINDL/[RPM,]n[,CLW|CCLW]`, `SPINDL/ON|OFF|CLW|CCLW`.
  void spindle(block& b) {
    const std::string message = "SPINDL needs a speed, ON, OFF, CLW or CCLW";
    if (!c_.slash || c_.tail.empty()) return error(c_.major_at, message);
    const argument* value = nullptr;
    int direction = 0;
    for (const argument& a : args_) {
      const std::string word = lexing::upper(a.text);
      if (word == "OFF" && args_.size() == 1) b.state.spindle = spindle_rotation::stopped;
      else if (word == "ON" || word == "CLW") direction = 3;
      else if (word == "CCLW") direction = 4;
      else if (word == "RPM") continue;
      else if (word == "SFM" || word == "SMM") return error(a.offset, "constant surface speed is not supported");
      else if (!value && !a.text.empty() && !is_letter(a.text.front())) value = &a;
      else return error(a.offset, "unexpected '" + std::string(a.text) + "' after SPINDL");
    }
    if (!value && !direction && !b.state.spindle) return error(c_.major_at, message);
    if (value) {
      double s = 0;
      if (!number(*value, s)) return;
      if (auto why = unwritable_rate(s, finest_rate_decimals, "spindle speed")) return error(value->offset, *why);
      b.spindle_rpm = s;
    }
    if (direction) take_machine_function(b.state, direction);
  }

  /// `DELAY/t`: a dwell of t seconds (PTC Creo Parametric Help, "Supported CL Data Commands":
  /// DELAY); `DELAY/REV,n` and other forms are refused (vocabulary.hpp).
  void delay(block& b) {
    double t = 0;
    if (!c_.slash) return error(c_.major_at, "DELAY: a dwell is DELAY/t (a '/' and the seconds)", "DELAY");
    if (!number(args_[0], t)) return;
    if (t < 0) return error(args_[0].offset, "DELAY: a dwell time cannot be negative", "DELAY");
    if (const std::string why = dwell_refusal(dwell_steps, t); !why.empty())
      return error(args_[0].offset, "DELAY: " + why, "DELAY");
    b.state.dwell_s = t;
  }

  /// `MULTAX`, `MULTAX/ON`, `MULTAX/OFF`: whether GOTOs carry a tool axis, which their value
  /// count already says; kept (`kept_words`) so that APT is written back with it.
  void multax(block& b, const std::string& word) {
    if (!word.empty() && word != "ON" && word != "OFF")
      return error(c_.major_at, "MULTAX/" + word + " is not supported (only MULTAX, MULTAX/ON and MULTAX/OFF are read)",
                   "MULTAX");
    b.kept_words.push_back(word.empty() ? "MULTAX" : "MULTAX/" + word);
  }

  /// `LOADTL/n` (`at` = 0) or `LOAD/TOOL,n` (`at` = 1): a tool change, the tool and `tool_change`;
  /// `SELECT/TOOL,n` (`change` false): the tool made ready, as ISO's `T n` alone.
  void load_tool(block& b, std::size_t at, bool change = true) {
    double t = 0;
    const std::string name = !change ? "SELECT/TOOL" : at == 0 ? "LOADTL" : "LOAD/TOOL";
    if (!c_.slash || args_.size() != at + 1) return error(c_.major_at, name + " needs one tool number", c_.major);
    if (!number(args_[at], t)) return;
    if (t < 0 || t != static_cast<double>(static_cast<long long>(t)))
      return error(args_[at].offset, "tool number must be a whole number");
    b.tool = static_cast<long long>(t);
    if (change) b.state.tool_change = true;
  }
};

}  // namespace kin5::program::apt::detail

namespace kin5::program::apt {

/// Reads APT CL data statement by statement: `on_block` receives each block in file order as soon
/// as it is read; errors go to `diagnostics` (its `parsed` is not touched).
inline void read_blocks(std::string_view text, const std::string& file_path, read_result& diagnostics,
                        const block_sink& on_block) {
  const file_name file(file_path);  // one string for every location in the file
  bool rapid_pending = false;
  detail::statement_reader reader(file, rapid_pending, diagnostics);
  read_transmitted(text, file_path, diagnostics, on_block, [&](std::string_view body, const block_sink& sink) {
    for_each_statement(body, [&](statement&& st) {
      if (auto b = reader.read(st)) sink(std::move(*b));
    });
    reader.finish();
  });
}

}  // namespace kin5::program::apt
