/// @file program/heidenhain/motion.hpp
/// The Heidenhain motion blocks, read from their words: `L` and `LN` (a straight line, `LN` with a
/// tool-axis vector `TX TY TZ`), `CC` (a circle centre: two coordinates give the plane, a missing
/// one comes from the last position), `C` (an arc around the last `CC`) and `CR` (an arc of
/// radius `R`), with `R0`/`RL`/`RR` (cutter radius compensation, `state.radius_compensation`
/// where it changes), `F`, `FMAX`, `DR±` and M functions. `FAUTO` is refused.
#pragma once

#include <algorithm>
#include <cmath>

#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../machine_functions.hpp"
#include "../number.hpp"
#include "../units.hpp"
#include "../incremental.hpp"
#include "lexer.hpp"
#include "../interp/parameter_store.hpp"
#include "parameters.hpp"

namespace kin5::program::heidenhain::detail {

/// What the reader carries from block to block: the last position (for CC's missing axes), the
/// working plane, the last circle centre, the program's name and unit (for END PGM), and where
/// the Q parameters' values are.
struct reader_state {
  std::optional<double> last[3];
  /// The running program's parameters, which words like `FQ1` and `X+Q2` read (the executor's).
  const interp::parameter_store* parameters = nullptr;
  /// X Y Z (mm) A B C: the last programmed position with its decimals, the base of incremental
  /// words (program/incremental.hpp); a block's own decimals wait in `decimals` until it is done.
  std::optional<axis_position> position[6];
  std::size_t lost_line[6] = {};  ///< the M91/M92 line that made a position unknown (0: none)
  int decimals[6] = {};
  arc_plane plane = arc_plane::xy;
  std::optional<vec3> centre;
  cutter_side radius = cutter_side::off;  ///< RL/RR in effect (modal until R0)
  std::optional<arc_plane> working;       ///< the working plane of the last TOOL CALL's axis
  std::optional<std::string> begin_name;
  std::optional<bool> inch;  ///< the unit of BEGIN PGM (INCH: true)
  /// Where a `CYCL DEF 9.0 DWELL TIME` stands whose `CYCL DEF 9.1 DWELL` line is still to come.
  std::optional<source_location> dwell_opened;

  /// Millimetres per unit of a length as written: 25.4 in an INCH program.
  double mm_per_length() const { return inch.value_or(false) ? mm_per_inch : 1.0; }
  /// mm/min per unit of F as written: an INCH program's F is in 1/10 inch/min, 2.54 mm/min.
  double mm_per_min_per_feed() const { return inch.value_or(false) ? mm_per_inch / 10.0 : 1.0; }
};

/// Diagnostics at offsets of a block's text, and the checks every word goes through.
class word_checks {
 public:
  word_checks(const block_text& text, read_result& out) : t_(text), s_(text.content), scan_(text), out_(out) {}

 protected:
  const block_text& t_;
  const std::string& s_;
  scanner scan_;
  read_result& out_;

  void error(std::size_t pos, std::string message) { out_.add_error({t_.where(pos), std::move(message)}); }
  void warning(std::size_t pos, std::string message) { out_.add_warning({t_.where(pos), std::move(message)}); }

  /// Gives word `w`, whose value is a parameter (`FQ1`, `X-QL2`), that parameter's value in
  /// `parameters`; false, reported, when it has none.
  bool resolve_parameter(word& w, const interp::parameter_store* parameters) {
    const interp::parameter_read v = parameters ? parameters->read(*w.parameter)
                                                : interp::parameter_read{std::nullopt, "parameter " + w.parameter->shown() +
                                                                                           " is read outside a running program"};
    if (!v.value) {
      error(w.pos, v.why);
      w.bad = true;
      return false;
    }
    w.value = w.parameter_negated ? -*v.value : *v.value;
    return true;
  }

  /// Reports a word's number problem; true when the word is usable.
  bool value_ok(word& w) {
    if (w.bad) return false;
    if (w.expression) error(w.pos, "an expression in an axis word is not supported (a TNC reads a number or a Q parameter: X+Q1)");
    else if (w.error == number_error::too_large) error(w.pos, "value out of range");
    else if (!w.malformed.empty()) error(w.pos, "malformed number '" + w.malformed + "'");
    else if (w.error != number_error::none) error(w.pos, "word '" + w.key + "' has a malformed value");
    else if (!w.value) error(w.pos, "word '" + w.key + "' has no value");
    else return true;
    w.bad = true;
    return false;
  }

  /// A feed or spindle speed the writer could write back (`unwritable_rate`: `S.0101` needs a
  /// fourth decimal); false, reported, if not.
  bool rate_ok(word& w, std::string_view what) {
    if (!value_ok(w)) return false;
    const auto why = unwritable_rate(*w.value, finest_rate_decimals, what);
    if (!why) return true;
    error(w.pos, *why);
    w.bad = true;
    return false;
  }

  /// A whole number that is not negative (a tool or M number) into `n`; false, reported, if not.
  bool integer_word(word& w, long long& n) {
    if (!value_ok(w)) return false;
    if (*w.value != static_cast<double>(static_cast<long long>(*w.value)) || *w.value < 0) {
      error(w.pos, "word '" + w.key + "' needs a whole number");
      return false;
    }
    n = static_cast<long long>(*w.value);
    return true;
  }

  /// M128 / M129 switch TCP; M91 / M92 mean machine coordinates; M0 M1 M3 M4 M5 M6 M8 M9 M13 M14 are
  /// state words (machine_functions.hpp); all others are kept as M codes.
  static void set_m(block& t, long long m) {
    if (m == 128) t.tcp = true;
    else if (m == 129) t.tcp = false;
    else {
      if (m == 91 || m == 92) t.machine_coordinates = true;
      if (m == 92) t.machine_reference = machine_position::builder_position;
      read_machine_function(t, m, {.m7_mist = false, .m13_m14 = true});
    }
  }
};

/// Reads one L, LN, C, CC or CR block into `b`.
class motion_reader : public word_checks {
 public:
  motion_reader(const block_text& text, reader_state& state, read_result& out, block& b, std::vector<std::size_t>& stray)
      : word_checks(text, out), state_(state), b_(b), stray_(stray) {}

  void read(std::size_t i, const std::string& head) {
    head_ = head;
    arc_ = head == "C" || head == "CR";
    std::vector<word> ws = scan_.words(i + head.size(), b_.comment, stray_);
    if (head != "CC") b_.motion = motion_kind::linear;
    for (word& w : ws) take(w);
    if (head == "CC") centre(i);
    else end_point(i);
    if (b_.feed && b_.feed_rapid) error(i, "F and FMAX in one block");
  }

 private:
  reader_state& state_;
  block& b_;
  std::vector<std::size_t>& stray_;
  std::string head_;
  bool arc_ = false;
  std::optional<double> radius_;
  char direction_ = 0;
  std::optional<double> axis_[6], tool_axis_[3];
  bool incremental_[6] = {};        // IX … IC
  std::optional<int> parameter_decimals_;  // the decimals of the Q parameter the word being taken uses
  std::size_t word_pos_[6] = {};    // where each axis word stands

  /// A word whose value is a Q parameter (`FQ1`, `X-Q2`) takes the parameter's value now.
  bool resolve(word& w) {
    if (!resolve_parameter(w, state_.parameters)) return false;
    w.parameter.reset();
    parameter_decimals_ = decimals_of(*w.value);
    return true;
  }

  /// The decimals of a parameter's value, which has no written text: those of its shortest
  /// form, at most 6 (a millionth of a millimetre or degree).
  static int decimals_of(double v) {
    double scale = 1;
    for (int d = 0; d < 6; ++d, scale *= 10)
      if (std::abs(std::round(v * scale) / scale - v) <= 1e-9 * std::max(1.0, std::abs(v))) return d;
    return 6;
  }

  void take(word& w) {
    const std::string& key = w.key;
    parameter_decimals_.reset();
    if (w.parameter && !resolve(w)) return;
    if (w.expression) {
      value_ok(w);
    } else if (key.empty()) {
      error(w.pos, w.error == number_error::too_large ? "value out of range" : "number without an address letter");
    } else if (key.size() == 1 && is_axis_letter(key[0])) {
      axis_word(w);
    } else if (key.size() == 2 && key[0] == 'I' && is_axis_letter(key[1])) {
      axis_word(w, 1);
    } else if (head_ == "LN" && key.size() == 2 && key[0] == 'T' && (key[1] == 'X' || key[1] == 'Y' || key[1] == 'Z')) {
      if (!value_ok(w)) return;
      const std::size_t a = static_cast<std::size_t>(key[1] - 'X');
      if (tool_axis_[a]) error(w.pos, "word '" + key + "' given twice");
      else tool_axis_[a] = *w.value;
    } else if (head_ == "LN" && key.size() == 2 && key[0] == 'N' && (key[1] == 'X' || key[1] == 'Y' || key[1] == 'Z')) {
      if (value_ok(w)) b_.kept_words.push_back(w.written);
    } else if (head_ == "CC") {
      error(w.pos, "unknown word '" + w.written + "'");
    } else {
      other_word(w);
    }
  }

  /// X, or IX when `at` is 1 (incremental: TNC 640 User's Manual, "Absolute/incremental
  /// coordinates"), and the other axes likewise.
  void axis_word(word& w, std::size_t at = 0) {
    if (!value_ok(w)) return;
    const std::size_t a = std::string_view("XYZABC").find(w.key[at]);
    if (a >= std::size(axis_)) return error(w.pos, "unknown axis '" + w.key + "'");  // not reached: callers pass axes
    if (axis_[a]) return error(w.pos, "axis '" + std::string(1, w.key[at]) + "' given twice");
    const bool inch = a < 3 && state_.mm_per_length() != 1.0;
    axis_[a] = a < 3 ? *w.value * state_.mm_per_length() : *w.value;
    state_.decimals[a] = parameter_decimals_.value_or(decimals_written(w.written)) + (inch ? 1 : 0);  // ×25.4: one more
    incremental_[a] = at == 1;
    word_pos_[a] = w.pos;
  }

  /// IX … IC: the position reached from the last programmed one of the axis (a CC's centre
  /// likewise). A base the program does not say (no absolute position yet, or M91/M92 since)
  /// is refused at the word, unless the distance is 0 (the axis stays: the word is left out);
  /// incremental words in an M91/M92 block, whose words are kept as written, are refused.
  void absolute_positions() {
    static constexpr char letters[] = "XYZABC";
    for (std::size_t a = 0; a < 6; ++a) {
      if (!axis_[a] || !incremental_[a]) continue;
      const std::string letter(1, letters[a]);
      if (b_.machine_coordinates) {
        error(word_pos_[a], "I" + letter + " in a machine-coordinate block (M91/M92) is not supported (its words are "
                                           "kept as written)");
        continue;
      }
      if (state_.position[a]) {
        const axis_position to = reached(*state_.position[a], *axis_[a], state_.decimals[a]);
        axis_[a] = to.value, state_.decimals[a] = to.decimals;
        continue;
      }
      if (*axis_[a] == 0) {
        axis_[a].reset();
        continue;
      }
      const std::string since = state_.lost_line[a] ? "since the machine-coordinate move (M91/M92) of line " +
                                                          std::to_string(state_.lost_line[a])
                                                    : "since the start of the program";
      error(word_pos_[a], "incremental " + letter + " (I" + letter + ") from a position the program does not say: no "
                          "absolute " + letter + " " + since + ", so the move would start from wherever the machine "
                          "stands; program an absolute " + letter + " before it");
      axis_[a].reset();
    }
  }

  /// R, R0, RL/RR, DR±, F, FMAX, FAUTO, M.
  void other_word(word& w) {
    const std::string& key = w.key;
    const bool bare = !w.value && !w.sign;
    if (key == "R" && head_ == "CR" && !radius_ && !w.sign) {
      if (value_ok(w)) radius_ = *w.value * state_.mm_per_length();
    } else if (key == "R" && w.value && *w.value == 0 && w.error == number_error::none) {
      if (state_.radius == cutter_side::off) b_.kept_words.push_back("R0");
      else compensation(w, cutter_side::off);
    } else if ((key == "RL" || key == "RR") && bare && w.error == number_error::none) {
      compensation(w, key == "RL" ? cutter_side::left : cutter_side::right);
    } else if (key == "DR" && arc_ && w.sign && !direction_) {
      direction_ = w.sign;
    } else if (key == "F") {
      if (b_.feed) error(w.pos, "word 'F' given twice");
      else if (rate_ok(w, "feed")) b_.feed = *w.value * state_.mm_per_min_per_feed();
    } else if (key == "FMAX" && bare) {
      b_.feed_rapid = true;
      b_.motion = arc_ ? b_.motion : motion_kind::rapid;
    } else if (key == "FAUTO" && bare) {
      error(w.pos, "FAUTO: the feed of the TOOL CALL is not supported yet (give F)");
    } else if (key == "M") {
      long long m = 0;
      if (integer_word(w, m)) set_m(b_, m);
    } else {
      error(w.pos, "unknown word '" + (w.written.empty() ? key : w.written) + "'");
    }
  }

  /// RL / RR / R0: cutter radius compensation left, right, off; modal until changed. It is
  /// switched on and off only in a straight-line block L (TNC 620 ISO Programming User's Manual
  /// 340 56x-02, "Radius compensation", p. 154: not in a circle block; iTNC 530 DIN/ISO 6/2010
  /// §5.3 p. 183: R0 in a straight-line block cancels it); a circle block may repeat the side in
  /// effect. An `LN` block's RL/RR is 3-D compensation: refused.
  void compensation(const word& w, cutter_side side) {
    const std::string key = side == cutter_side::off ? "R0" : w.key;
    if (head_ == "LN" && side != cutter_side::off)
      return error(w.pos, key + " in an LN block: 3-D tool compensation along the surface normal is not supported");
    if (side == state_.radius) return;
    if (arc_)
      return error(w.pos, key + ": cutter radius compensation " + (side == cutter_side::off ? "cancelled" : "switched on") +
                              " in a circle block (allowed only in a straight-line block L)");
    if (side != cutter_side::off && state_.working != arc_plane::xy)
      return error(w.pos, key + ": cutter radius compensation is translated only with the tool axis Z (TOOL CALL n Z "
                                "before it: the working plane XY)");
    if (side != cutter_side::off) b_.state.working_plane = arc_plane::xy;  // the plane it offsets in, said
    b_.state.radius_compensation = side;
    state_.radius = side;
  }

  /// CC: two coordinates give the plane; missing ones come from the last position.
  void centre(std::size_t i) {
    absolute_positions();
    const int given = (axis_[0] ? 1 : 0) + (axis_[1] ? 1 : 0) + (axis_[2] ? 1 : 0);
    if (axis_[3] || axis_[4] || axis_[5]) error(i, "CC takes linear axes only");
    if (given == 3) error(i, "CC takes at most two coordinates");
    if (given == 2) state_.plane = !axis_[2] ? arc_plane::xy : !axis_[1] ? arc_plane::zx : arc_plane::yz;
    vec3 c{};
    double* cs[3] = {&c.x, &c.y, &c.z};
    for (std::size_t a = 0; a < 3; ++a) {
      if (axis_[a]) *cs[a] = *axis_[a];
      else if (state_.last[a]) *cs[a] = *state_.last[a];
      else if (given < 3) warning(i, std::string("CC: last ") + "XYZ"[a] + " position unknown, 0 assumed");
    }
    b_.arc = arc_words{state_.plane, c, std::nullopt};
    state_.centre = c;
  }

  /// L, LN, C, CR: the end point, the tool-axis vector, and the arc.
  void end_point(std::size_t i) {
    absolute_positions();
    axis_words& ax = b_.axes;
    ax.x_mm = axis_[0], ax.y_mm = axis_[1], ax.z_mm = axis_[2];
    ax.a_deg = axis_[3], ax.b_deg = axis_[4], ax.c_deg = axis_[5];
    if (tool_axis_[0] || tool_axis_[1] || tool_axis_[2]) {
      const vec3 t{tool_axis_[0].value_or(0.0), tool_axis_[1].value_or(0.0), tool_axis_[2].value_or(0.0)};
      if (is_direction(t.x, t.y, t.z)) ax.tool_axis = t;
      else error(i, "tool-axis vector shorter than 0.001 is not a direction");
    }
    if (!arc_) return;
    b_.motion = direction_ == '-' ? motion_kind::arc_cw : motion_kind::arc_ccw;
    if (!direction_) error(i, "arc needs a direction (DR+ or DR-)");
    if (head_ == "CR") {
      if (!radius_) error(i, "CR needs a radius (R)");
      b_.arc = arc_words{state_.plane, std::nullopt, radius_};
    } else {
      if (!state_.centre) error(i, "arc C needs a circle centre (CC) before it");
      b_.arc = arc_words{state_.plane, state_.centre, std::nullopt};
    }
  }
};

}  // namespace kin5::program::heidenhain::detail
