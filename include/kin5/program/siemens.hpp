/// @file program/siemens.hpp
/// Siemens 840D programs (G code under TRAORI) read into, and written from, the block model.
///
/// Reading: one block per line; words with or without spaces (`G1X-34.983Y9.1`), `X=10.5` for a
/// plain number, `;` and `( … )` comments, a `%_N_NAME_MPF` header. `TRAORI` / `TRAFOOF` switch
/// tool-tip tracking, `A3= B3= C3=` give a tool-axis vector, `I J K` (incremental from the last
/// programmed point) or `CR=` give arcs, `SUPA` / `G53` / `G153` mean machine coordinates.
/// Expressions, `G91` / `IC()`, inch units and active frame changes (`TRANS`, `ROT`, `CYCLE800`,
/// …) are errors. A block without axis words that is not understood is kept verbatim
/// (`passthrough`). docs/dialects/siemens.md lists every word.
///
/// ```cpp
/// namespace s = kin5::program::siemens;
/// auto r = s::read("N10 G1 Y9.1 Z118.526 B3.536 F1091\n", "part.mpf");
/// if (r.ok()) std::string text = s::write(r.parsed);  // "N10 G1 Y9.1 … F1091\n"
/// ```
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "block.hpp"
#include "number.hpp"
#include "text.hpp"

namespace kin5::program::siemens {

/// Decimals written for each kind of number. Spindle speeds use `feed_decimals`.
struct write_options {
  int linear_decimals = 3;  ///< X Y Z, I J K, CR= (mm)
  int angle_decimals = 3;   ///< A B C (degrees)
  int feed_decimals = 1;    ///< F (mm/min or 1/min) and S (1/min)
  int vector_decimals = 7;  ///< A3= B3= C3= tool-axis components
};

namespace detail {

inline std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = to_upper(c);
  return out;
}

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

/// A byte that may not appear outside comments and strings.
constexpr bool is_bad_byte(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u < 0x20 && !is_space(c)) || u >= 0x7f;
}

inline std::string hex_byte(char c) {
  constexpr std::string_view digits = "0123456789abcdef";
  const auto u = static_cast<unsigned char>(c);
  return std::string("0x") + digits[u >> 4] + digits[u & 15];
}

constexpr bool is_ident_char(char c) { return is_letter(c) || is_digit(c) || c == '_'; }
constexpr bool is_axis_letter(char c) { return c == 'X' || c == 'Y' || c == 'Z' || c == 'A' || c == 'B' || c == 'C'; }
constexpr bool is_centre_letter(char c) { return c == 'I' || c == 'J' || c == 'K'; }

/// Length of the NC number at the start of `s` (as `read_number` would take it, whatever its size).
inline std::size_t number_extent(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  while (i < s.size() && is_digit(s[i])) ++i;
  if (i < s.size() && s[i] == '.') ++i;
  while (i < s.size() && is_digit(s[i])) ++i;
  return i;
}

inline bool is_whole(double v) { return v >= 0 && std::floor(v) == v; }

inline std::string frame_message(std::string_view construct) {
  return std::string(construct) + " changes the working frame; kin5 does not model frame changes";
}

/// Words kept as written (after upper-casing) that do not change geometry.
inline bool is_kept_keyword(std::string_view w) {
  static constexpr std::array<std::string_view, 17> words = {
      "SOFT", "BRISK", "DRIVE", "FFWON", "FFWOF", "CUT2D", "CUT2DF", "ORIWKS", "ORIMKS",
      "ORIAXES", "ORIVECT", "COMPOF", "COMPON", "COMPCAD", "COMPCURV", "TOROTOF", "PAROTOF"};
  return std::find(words.begin(), words.end(), w) != words.end();
}

inline bool is_kept_g(long long g) {
  return g == 9 || g == 40 || (g >= 54 && g <= 57) || g == 60 || g == 64 || (g >= 641 && g <= 645) ||
         (g >= 601 && g <= 603) || g == 90 || g == 500 || (g >= 505 && g <= 599);
}

/// Frame words that are harmless alone (they reset the programmable frame) and errors with axes.
inline bool is_frame_reset_keyword(std::string_view w) {
  return w == "TRANS" || w == "ATRANS" || w == "ROT" || w == "AROT" || w == "SCALE" || w == "ASCALE" ||
         w == "MIRROR" || w == "AMIRROR";
}

/// Frame words that always change the frame.
inline bool is_frame_keyword(std::string_view w) {
  return w == "TRAFRAME" || w == "TOFRAME" || w == "TOROT" || w == "PAROT" || w == "TOFRAMEX" ||
         w == "TOFRAMEY" || w == "TOFRAMEZ";
}

/// Kept words written after T rather than before the motion word: `D1`, `H2`, `T="name"`.
/// The reader stores kept words in that order too (the others first), so writing keeps them.
inline bool is_late_kept(std::string_view w) {
  return (w.size() > 1 && (w[0] == 'D' || w[0] == 'H') && is_digit(w[1])) || w.rfind("T=", 0) == 0;
}

/// Splits a call's arguments at top-level commas.
inline std::vector<std::string_view> split_args(std::string_view args) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  bool in_string = false;
  int depth = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const char c = args[i];
    if (c == '"') in_string = !in_string;
    if (in_string) continue;
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if (c == ',' && depth == 0) {
      out.push_back(trim(args.substr(start, i - start)));
      start = i + 1;
    }
  }
  out.push_back(trim(args.substr(start)));
  return out;
}

/// `CYCLE800()` or a CYCLE800 call whose offsets and angles (arguments 5 to 13) are all zero.
inline bool is_cycle800_reset(std::string_view args) {
  if (trim(args).empty()) return true;
  const auto a = split_args(args);
  if (a.size() < 13) return false;
  for (std::size_t i = 4; i < 13; ++i) {
    if (a[i].empty()) continue;
    const auto n = read_number(a[i]);
    if (n.length != a[i].size() || n.value != 0.0) return false;
  }
  return true;
}

/// What the reader remembers between blocks (and the writer mirrors).
struct modal_state {
  std::optional<motion_kind> motion;
  arc_plane plane = arc_plane::xy;
  std::array<std::optional<double>, 3> position_mm;  ///< last programmed X Y Z (workpiece)
  std::optional<std::string> program_name;

  void move(const block& b) {
    const std::array<std::optional<double>, 3> given = {b.axes.x_mm, b.axes.y_mm, b.axes.z_mm};
    for (std::size_t i = 0; i < 3; ++i)
      if (given[i]) position_mm[i] = b.machine_coordinates ? std::nullopt : given[i];
  }
  std::optional<vec3> position() const {
    if (!position_mm[0] || !position_mm[1] || !position_mm[2]) return std::nullopt;
    return vec3{*position_mm[0], *position_mm[1], *position_mm[2]};
  }
};

constexpr bool is_arc(std::optional<motion_kind> m) {
  return m == motion_kind::arc_cw || m == motion_kind::arc_ccw;
}

/// Everything one line says, before the modal state is applied.
struct line_parse {
  block b;
  std::array<std::optional<double>, 3> centre_offset_mm;  ///< I J K as written
  std::optional<double> radius_mm;                        ///< CR=
  std::array<std::optional<double>, 3> vector;            ///< A3= B3= C3=
  std::optional<arc_plane> plane;
  std::size_t arc_column = 0, vector_column = 0, geometry_column = 0;
  std::string arc_word;
  bool has_geometry = false;   ///< axis, vector, centre or radius words (or failed attempts at them)
  bool has_content = false;    ///< anything besides N, comments and MSG
  bool has_msg = false;
  bool frame_arguments = false;  ///< RPL= and the like
  std::vector<std::pair<std::string, std::size_t>> frame_words;  ///< TRANS, ROT, G58, … (column)
  std::vector<diagnostic> unknown;  ///< errors if the block has geometry, else it is passthrough
  std::vector<diagnostic> errors, warnings;
};

/// Splits one line into words and records them in a `line_parse`.
class line_reader {
 public:
  line_reader(std::string_view s, std::size_t line, const file_name& file, line_parse& out)
      : s_(s), line_(line), file_(file), out_(out) {}

  void run() {
    first_ = 0;
    while (first_ < s_.size() && is_space(s_[first_])) ++first_;
    i_ = first_;
    while (true) {
      skip_spaces();
      if (i_ >= s_.size()) break;
      const char c = s_[i_];
      if (c == ';') {
        add_comment(s_.substr(i_ + 1));
        break;
      }
      if (c == '(') {
        paren_comment();
      } else if (is_letter(c)) {
        word();
      } else if (c == '$' || c == '_') {
        system_word();
      } else if (is_digit(c) || c == '.' || c == '+' || c == '-') {
        stray_number();
      } else if (is_bad_byte(c)) {
        error(i_, "unexpected byte " + hex_byte(c));
        ++i_;
        while (static_cast<unsigned char>(c) >= 0x80 && i_ < s_.size() && static_cast<unsigned char>(s_[i_]) >= 0x80)
          ++i_;  // one diagnostic per multi-byte character
      } else if (c == '/' && i_ == first_) {
        unknown(i_, "block skip '/' is not supported");
        ++i_;
      } else {
        const std::size_t start = i_;
        consume_run();
        unknown(start, "unknown word '" + std::string(s_.substr(start, i_ - start)) + "'");
      }
    }
  }

 private:
  std::string_view s_;
  std::size_t line_;
  const file_name& file_;
  line_parse& out_;
  std::size_t i_ = 0, first_ = 0;  // the next byte; the block's first non-blank byte
  bool named_tool_ = false;         // T="name" seen
  std::string motion_word_, feed_word_, tcp_word_;  // as written, for "conflicting words"

  source_location at(std::size_t pos) const { return {file_, line_, pos + 1}; }
  void error(std::size_t pos, std::string m) { out_.errors.push_back({at(pos), std::move(m)}); }
  void unknown(std::size_t pos, std::string m) { out_.unknown.push_back({at(pos), std::move(m)}); }
  void skip_spaces() {
    while (i_ < s_.size() && is_space(s_[i_])) ++i_;
  }
  char peek(std::size_t pos) const { return pos < s_.size() ? s_[pos] : '\0'; }

  /// Skips to the next space or `;` outside parentheses, brackets and strings.
  void consume_run() {
    int depth = 0;
    bool in_string = false;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '"') in_string = !in_string;
      if (!in_string) {
        if (depth == 0 && (is_space(c) || c == ';' || is_bad_byte(c))) break;
        if (c == '(' || c == '[') ++depth;
        if ((c == ')' || c == ']') && depth > 0) --depth;
      }
      ++i_;
    }
  }

  void add_comment(std::string_view text) {
    const std::string t(trim(text));
    if (!out_.b.comment) out_.b.comment = t;
    else if (!t.empty()) *out_.b.comment += (out_.b.comment->empty() ? "" : " ") + t;
  }

  void paren_comment() {
    const std::size_t close = s_.find(')', i_ + 1);
    if (close == std::string_view::npos) {
      error(i_, "comment '(' is not closed");
      add_comment(s_.substr(i_ + 1));
      i_ = s_.size();
      return;
    }
    add_comment(s_.substr(i_ + 1, close - i_ - 1));
    i_ = close + 1;
  }

  void stray_number() {
    const std::size_t start = i_;
    const std::size_t n = number_extent(s_.substr(i_));
    const bool has_digit =
        std::any_of(s_.begin() + static_cast<std::ptrdiff_t>(start), s_.begin() + static_cast<std::ptrdiff_t>(start + n), is_digit);
    if (!has_digit) {
      consume_run();
      unknown(start, "unknown word '" + std::string(s_.substr(start, i_ - start)) + "'");
      return;
    }
    i_ += n;
    error(start, "number '" + std::string(s_.substr(start, n)) + "' has no address letter");
  }

  void system_word() {
    const std::size_t start = i_;
    ++i_;
    while (i_ < s_.size() && (is_ident_char(s_[i_]) || s_[i_] == '$')) ++i_;
    const std::string name = upper(s_.substr(start, i_ - start));
    std::size_t k = i_;
    while (k < s_.size() && is_space(s_[k])) ++k;
    const bool assigned = peek(k) == '=' || peek(k) == '[';
    consume_run();
    if (assigned && name.rfind("$P_", 0) == 0 &&
        (name.find("FRAME") != std::string::npos || name == "$P_UIFR" || name == "$P_CHBFR" || name == "$P_NCBFR"))
      error(start, frame_message(name));
    else
      unknown(start, "unknown word '" + name + "'");
  }

  /// A word starting with a letter: an address (`X10`, `X=10`, `A3=0.5`) or a keyword.
  void word() {
    std::size_t j = i_;
    while (j < s_.size() && is_letter(s_[j])) ++j;
    if (j - i_ == 1 && peek(j) != '_') address_word();
    else keyword();
  }

  bool duplicate(bool present, std::size_t pos, std::string_view what) {
    if (present) error(pos, "word '" + std::string(what) + "' appears twice");
    return present;
  }

  /// Skips what follows a number that makes it malformed: `.3` of `1.2.3`, `e5` or `EX3` of an exponent.
  void skip_malformed_number() {
    while (i_ < s_.size() && (is_digit(s_[i_]) || s_[i_] == '.' || s_[i_] == '+' || s_[i_] == '-' ||
                              to_upper(s_[i_]) == 'E' || to_upper(s_[i_]) == 'X'))
      ++i_;
  }

  void mark_geometry(std::size_t pos) {
    if (!out_.has_geometry) out_.geometry_column = pos;
    out_.has_geometry = true;
  }

  /// Consumes an expression value (after `=`) and reports it. `geometry`: an axis, vector,
  /// centre or radius word, for which an expression is always an error.
  void expression(bool geometry, std::size_t start, std::size_t value_pos) {
    consume_run();
    const std::string value = upper(s_.substr(value_pos, i_ - value_pos));
    if (value.rfind("IC(", 0) == 0) {
      error(start, "incremental positioning (IC) is not supported");
    } else if (value == "NAN" || value == "INF" || value == "-NAN" || value == "-INF" || value == "INFINITY") {
      error(start, "value out of range");
    } else if (geometry) {
      error(start, "expressions and parameters in axis words are not supported");
    } else {
      unknown(start, "expressions and parameters are not supported");
      return;
    }
    if (geometry) mark_geometry(start);
    else out_.has_content = true;
  }

  /// Reads the plain number after `word=`; nothing (and reported) if it is not one.
  std::optional<double> assigned_number(std::string_view word, bool geometry, std::size_t start) {
    skip_spaces();
    if (geometry) mark_geometry(start);
    const std::size_t value_pos = i_;
    if (i_ >= s_.size() || s_[i_] == ';') {
      error(start, "word '" + std::string(word) + "' has no value");
      return std::nullopt;
    }
    const auto n = read_number(s_.substr(i_));
    const std::size_t extent = number_extent(s_.substr(i_));
    const char next = peek(i_ + extent), after = to_upper(peek(i_ + extent + 1));
    const bool exponent = (next == 'e' || next == 'E') && (is_digit(after) || after == '+' || after == '-' || after == 'X');
    const bool operand_follows = next == '+' || next == '-' || next == '*' || next == '/' || next == '(' ||
                                 next == '[' || next == '<' || next == '>' || next == '=' || next == '.';
    if (n.length > 0 && !operand_follows && !exponent) {
      i_ += n.length;
      return n.value;
    }
    if (n.length > 0 && (exponent || next == '.')) {  // `1e5`, `1.2.3`
      i_ += extent;
      skip_malformed_number();
      error(start, "malformed number '" + std::string(s_.substr(value_pos, i_ - value_pos)) + "'");
      return std::nullopt;
    }
    if (n.error == number_error::too_large && !operand_follows) {
      i_ += extent;
      skip_malformed_number();
      error(start, "value out of range");
      return std::nullopt;
    }
    expression(geometry, start, value_pos);
    return std::nullopt;
  }

  void address_word() {
    const std::size_t start = i_;
    const char letter = to_upper(s_[i_++]);
    const std::size_t after_letter = i_;
    skip_spaces();
    if (peek(i_) == '=') {
      ++i_;
      assignment(letter, start);
      return;
    }
    const std::size_t value_pos = i_;
    {  // The common case, `X-34.983` followed by a blank, `;`, `(`, the end or the next address
      // letter: one scan. Anything else takes the careful path below.
      const parsed_number n = read_number(s_.substr(i_));
      if (n.error == number_error::none) {
        std::size_t k = i_ + n.length;
        const char next = peek(k);
        while (k < s_.size() && is_space(s_[k])) ++k;
        const bool ends = k == s_.size() || next == ';' || next == '(' ||
                          (is_letter(next) && next != 'e' && next != 'E') || (is_space(next) && peek(k) != '=');
        if (ends && peek(k) != '=') {
          i_ += n.length;
          numbered(letter, n.value, s_.substr(value_pos, n.length), start);
          return;
        }
      }
    }
    const std::size_t extent = number_extent(s_.substr(i_));
    const bool has_digit = std::any_of(s_.begin() + static_cast<std::ptrdiff_t>(value_pos),
                                       s_.begin() + static_cast<std::ptrdiff_t>(value_pos + extent), is_digit);
    if (!has_digit) {
      const char next = peek(after_letter);
      if ((is_axis_letter(letter) || is_centre_letter(letter)) && (next == '#' || next == '[')) {
        i_ = after_letter;
        consume_run();
        error(start, "expressions and parameters in axis words are not supported");
        mark_geometry(start);
        return;
      }
      i_ += extent;
      no_value(letter, start);
      return;
    }
    const std::string_view number_text = s_.substr(value_pos, extent);
    i_ = value_pos + extent;
    // `1.2.3`, `1e5`, `1EX3`: a malformed or exponent number.
    const char next = peek(i_), after = to_upper(peek(i_ + 1));
    if (next == '.' || ((next == 'e' || next == 'E') && (is_digit(after) || after == '+' || after == '-' || after == 'X'))) {
      skip_malformed_number();
      error(start, "malformed number '" + std::string(s_.substr(value_pos, i_ - value_pos)) + "'");
      if (is_axis_letter(letter) || is_centre_letter(letter)) mark_geometry(start);
      return;
    }
    // An address with an extension: `A3=` (tool-axis vector), `R1=`, `X1=`, `S1=`, …
    std::size_t k = i_;
    while (k < s_.size() && is_space(s_[k])) ++k;
    if (peek(k) == '=') {
      i_ = k + 1;
      if ((letter == 'A' || letter == 'B' || letter == 'C') && number_text == "3") {
        vector_word(letter, start);
        return;
      }
      skip_spaces();
      consume_run();
      unknown(start, "unknown word '" + std::string(1, letter) + std::string(number_text) + "='");
      return;
    }
    const auto n = read_number(number_text);
    if (n.error != number_error::none) {
      error(start, "value out of range");
      if (is_axis_letter(letter) || is_centre_letter(letter)) mark_geometry(start);
      return;
    }
    numbered(letter, n.value, number_text, start);
  }

  void no_value(char letter, std::size_t start) {
    static constexpr std::string_view known = "NGXYZABCIJKFSTMDH";
    if (known.find(letter) != std::string_view::npos) {
      error(start, std::string("word '") + letter + "' has no value");
      if (is_axis_letter(letter) || is_centre_letter(letter)) mark_geometry(start);
    } else {
      unknown(start, std::string("unknown word '") + letter + "'");
    }
  }

  /// `X=…`: a plain number for X Y Z A B C I J K F S T, a string for T.
  void assignment(char letter, std::size_t start) {
    skip_spaces();
    if (letter == 'T' && peek(i_) == '"') {
      const std::size_t open = i_;
      const std::size_t close = s_.find('"', open + 1);
      if (close == std::string_view::npos) {
        error(open, "string is not closed");
        i_ = s_.size();
        return;
      }
      i_ = close + 1;
      if (duplicate(out_.b.tool.has_value() || named_tool_, start, "T")) return;
      named_tool_ = true;
      out_.b.kept_words.push_back("T=" + std::string(s_.substr(open, close + 1 - open)));
      out_.has_content = true;
      return;
    }
    static constexpr std::string_view assignable = "XYZABCIJKFST";
    if (assignable.find(letter) == std::string_view::npos) {
      const std::size_t value_pos = i_;
      consume_run();
      unknown(start, std::string("unknown word '") + letter + "=" + std::string(s_.substr(value_pos, i_ - value_pos)) + "'");
      return;
    }
    const std::size_t value_pos = i_;
    const auto v = assigned_number(std::string(1, letter), is_axis_letter(letter) || is_centre_letter(letter), start);
    if (!v) return;
    numbered(letter, *v, s_.substr(value_pos, i_ - value_pos), start);
  }

  void vector_word(char letter, std::size_t start) {
    const auto v = assigned_number(std::string(1, letter) + "3", true, start);
    if (!v) return;
    const std::size_t i = static_cast<std::size_t>(letter - 'A');
    if (duplicate(out_.vector[i].has_value(), start, std::string(1, letter) + "3")) return;
    if (!out_.vector[0] && !out_.vector[1] && !out_.vector[2]) out_.vector_column = start;
    out_.vector[i] = *v;
  }

  void set_axis(std::optional<double>& field, char letter, double v, std::size_t start) {
    mark_geometry(start);
    if (duplicate(field.has_value(), start, std::string(1, letter))) return;
    field = v;
  }

  void numbered(char letter, double v, std::string_view number_text, std::size_t start) {
    block& b = out_.b;
    switch (letter) {
      case 'N':
        if (!is_whole(v)) return error(start, "word 'N' needs a whole number");
        if (duplicate(b.number.has_value(), start, "N")) return;
        b.number = static_cast<long long>(v);
        return;
      case 'G': return g_word(v, std::string(1, letter) + std::string(number_text), start);
      case 'X': return set_axis(b.axes.x_mm, letter, v, start);
      case 'Y': return set_axis(b.axes.y_mm, letter, v, start);
      case 'Z': return set_axis(b.axes.z_mm, letter, v, start);
      case 'A': return set_axis(b.axes.a_deg, letter, v, start);
      case 'B': return set_axis(b.axes.b_deg, letter, v, start);
      case 'C': return set_axis(b.axes.c_deg, letter, v, start);
      case 'I':
      case 'J':
      case 'K': {
        auto& field = out_.centre_offset_mm[static_cast<std::size_t>(letter - 'I')];
        mark_geometry(start);
        if (duplicate(field.has_value(), start, std::string(1, letter))) return;
        if (out_.arc_word.empty()) out_.arc_word = std::string(1, letter), out_.arc_column = start;
        field = v;
        return;
      }
      case 'F':
      case 'S': {
        out_.has_content = true;
        if (v < 0) return error(start, "value out of range");
        auto& field = letter == 'F' ? b.feed : b.spindle_rpm;
        if (duplicate(field.has_value(), start, std::string(1, letter))) return;
        field = v;
        return;
      }
      case 'T':
        out_.has_content = true;
        if (!is_whole(v)) return error(start, "word 'T' needs a whole number");
        if (duplicate(b.tool.has_value() || named_tool_, start, "T")) return;
        b.tool = static_cast<long long>(v);
        return;
      case 'M':
        out_.has_content = true;
        if (!is_whole(v)) return error(start, "word 'M' needs a whole number");
        b.m_codes.push_back(static_cast<int>(v));
        return;
      case 'D':
      case 'H':
        out_.has_content = true;
        if (!is_whole(v)) return error(start, std::string("word '") + letter + "' needs a whole number");
        b.kept_words.push_back(letter + std::to_string(static_cast<long long>(v)));
        return;
      default: unknown(start, "unknown word '" + std::string(1, letter) + std::string(number_text) + "'");
    }
  }

  void g_word(double v, const std::string& as_written, std::size_t start) {
    block& b = out_.b;
    if (!is_whole(v) || v > 9999) return unknown(start, "unknown word '" + as_written + "'");
    const auto g = static_cast<long long>(v);
    const std::string canonical = "G" + std::to_string(g);  // G017, G+17, G17. → G17
    out_.has_content = true;
    auto conflict = [&](bool clash, std::string_view earlier) {
      if (clash) error(start, "conflicting words '" + std::string(earlier) + "' and '" + canonical + "'");
      return clash;
    };
    if (g <= 3) {
      const motion_kind m = g == 0 ? motion_kind::rapid : g == 1 ? motion_kind::linear : g == 2 ? motion_kind::arc_cw : motion_kind::arc_ccw;
      if (conflict(b.motion && *b.motion != m, motion_word_)) return;
      b.motion = m;
      motion_word_ = canonical;
    } else if (g >= 17 && g <= 19) {
      out_.plane = g == 17 ? arc_plane::xy : g == 18 ? arc_plane::zx : arc_plane::yz;
      b.kept_words.push_back(canonical);
    } else if (is_kept_g(g)) {
      b.kept_words.push_back(canonical);
    } else if (g == 91) {
      error(start, "incremental positioning (G91) is not supported");
    } else if (g == 93 || g == 94) {
      const feed_unit f = g == 93 ? feed_unit::inverse_time : feed_unit::per_minute;
      if (conflict(b.feed_mode && *b.feed_mode != f, feed_word_)) return;
      b.feed_mode = f;
      feed_word_ = canonical;
    } else if (g == 70 || g == 700) {
      error(start, "inch programs are not supported");
    } else if (g == 71 || g == 710) {
      b.metric = true;
    } else if (g == 53 || g == 153) {
      b.machine_coordinates = true;
    } else if (g == 58 || g == 59) {
      out_.frame_words.emplace_back(canonical, start);
    } else {
      unknown(start, "unknown word '" + canonical + "'");
    }
  }

  void keyword() {
    const std::size_t start = i_;
    while (i_ < s_.size() && is_ident_char(s_[i_])) ++i_;
    const std::string name = upper(s_.substr(start, i_ - start));
    const std::string rest = name.substr(1);
    const char first = name[0];
    if ((is_axis_letter(first) || is_centre_letter(first) || first == 'F' || first == 'S') &&
        (rest == "NAN" || rest == "INF" || rest == "INFINITY")) {
      error(start, "value out of range");
      if (first != 'F' && first != 'S') mark_geometry(start);
      return;
    }
    if ((is_axis_letter(first) || is_centre_letter(first)) && name != "CR" && rest.size() >= 2 &&
        (rest[0] == 'R' || rest[0] == 'Q') && std::all_of(rest.begin() + 1, rest.end(), is_digit)) {
      error(start, "expressions and parameters in axis words are not supported");
      mark_geometry(start);
      return;
    }
    if (peek(i_) == '(') return call(name, start);
    std::size_t k = i_;
    while (k < s_.size() && is_space(s_[k])) ++k;
    if (peek(k) == '=') {
      i_ = k + 1;
      return keyword_assignment(name, start);
    }
    block& b = out_.b;
    if (name == "TRAORI" || name == "TRAFOOF") {
      out_.has_content = true;
      set_tcp(name == "TRAORI", name, start);
    } else if (name == "SUPA") {
      out_.has_content = true;
      b.machine_coordinates = true;
    } else if (is_kept_keyword(name)) {
      out_.has_content = true;
      b.kept_words.push_back(name);
    } else if (is_frame_reset_keyword(name)) {
      out_.has_content = true;
      out_.frame_words.emplace_back(name, start);
    } else if (is_frame_keyword(name)) {
      out_.has_content = true;
      error(start, frame_message(name));
    } else {
      unknown(start, "unknown word '" + name + "'");
    }
  }

  void set_tcp(bool on, const std::string& word, std::size_t start) {
    if (out_.b.tcp && *out_.b.tcp != on) {
      error(start, "conflicting words '" + tcp_word_ + "' and '" + word + "'");
      return;
    }
    out_.b.tcp = on;
    tcp_word_ = word;
  }

  /// `NAME(…)`: TRAORI(…), MSG("…"), CYCLE800(…); anything else is unknown.
  void call(const std::string& name, std::size_t start) {
    const std::size_t open = i_;
    std::size_t close = std::string_view::npos;
    int depth = 0;
    bool in_string = false;
    for (std::size_t k = open; k < s_.size(); ++k) {
      const char c = s_[k];
      if (c == '"') in_string = !in_string;
      if (in_string) continue;
      if (c == '(') ++depth;
      if (c == ')' && --depth == 0) {
        close = k;
        break;
      }
    }
    if (close == std::string_view::npos) {
      error(open, "missing ')'");
      i_ = s_.size();
      return;
    }
    const std::string_view args = s_.substr(open + 1, close - open - 1);
    i_ = close + 1;
    if (name == "TRAORI") {
      out_.has_content = true;
      const std::string_view a = trim(args);
      if (!a.empty() && a != "1")
        out_.warnings.push_back({at(start), "arguments of TRAORI(" + std::string(a) + ") are not kept; written as TRAORI"});
      set_tcp(true, name, start);
    } else if (name == "MSG") {
      out_.has_msg = true;
      out_.b.kept_words.push_back("MSG(" + std::string(args) + ")");
    } else if (name == "CYCLE800") {
      out_.has_content = true;
      if (is_cycle800_reset(args)) out_.b.kept_words.push_back("CYCLE800(" + std::string(args) + ")");
      else error(start, frame_message(name));
    } else if (is_frame_reset_keyword(name) || is_frame_keyword(name)) {
      out_.has_content = true;
      error(start, frame_message(name));
    } else {
      unknown(start, "unknown word '" + name + "'");
    }
  }

  void keyword_assignment(const std::string& name, std::size_t start) {
    if (name == "CR") {
      const auto v = assigned_number("CR", true, start);
      if (!v) return;
      if (duplicate(out_.radius_mm.has_value(), start, "CR")) return;
      if (out_.arc_word.empty()) out_.arc_word = "CR", out_.arc_column = start;
      out_.radius_mm = *v;
      return;
    }
    skip_spaces();
    consume_run();
    if (name == "RPL") out_.frame_arguments = true;
    unknown(start, "unknown word '" + name + "'");
  }
};

/// `%_N_NAME_MPF`, `%_N_NAME_SPF`, `%NAME`: the program name, or nothing if `line` is not a header.
inline std::optional<std::string> program_header(std::string_view line) {
  line = trim(line);
  if (line.empty() || line.front() != '%') return std::nullopt;
  line.remove_prefix(1);
  if (starts_with_keyword(line, "_N_")) line.remove_prefix(3);
  std::size_t n = 0;
  while (n < line.size() && is_ident_char(line[n])) ++n;
  if (n == 0 || n != line.size()) return std::nullopt;
  std::string name(line);
  if (name.size() > 4 && upper(name.substr(name.size() - 4)) == "_MPF") name.resize(name.size() - 4);
  return name;
}

/// The line most of a long program is made of: `N… G0|G1 X… Y… Z… A… B… C… F…`, any of those
/// words at most once each, in any order, upper case, blanks between them and nothing else. Such
/// a line is read into `b` in one scan, with the modal state moved on as `finish` would, and the
/// result is true; for any other line (or an arc in effect) nothing changes and the result is
/// false: the full reader then reads it. A law checks that both readers agree on such lines.
inline bool read_plain_motion(std::string_view line, block& b, modal_state& state) {
  std::optional<long long> number;
  std::optional<motion_kind> motion;
  axis_words axes;
  std::optional<double> feed;
  std::size_t i = 0;
  for (;;) {
    while (i < line.size() && is_space(line[i])) ++i;
    if (i == line.size()) break;
    const char letter = line[i++];
    const parsed_number n = read_number(line.substr(i));
    if (n.error != number_error::none) return false;
    i += n.length;
    if (i < line.size() && !is_space(line[i])) return false;
    const double v = n.value;
    auto set = [v](std::optional<double>& field) {
      if (field) return false;
      field = v;
      return true;
    };
    switch (letter) {
      case 'N':
        if (number || !is_whole(v)) return false;
        number = static_cast<long long>(v);
        break;
      case 'G':
        if (motion || !(v == 0.0 || v == 1.0)) return false;
        motion = v == 0.0 ? motion_kind::rapid : motion_kind::linear;
        break;
      case 'X': if (!set(axes.x_mm)) return false; break;
      case 'Y': if (!set(axes.y_mm)) return false; break;
      case 'Z': if (!set(axes.z_mm)) return false; break;
      case 'A': if (!set(axes.a_deg)) return false; break;
      case 'B': if (!set(axes.b_deg)) return false; break;
      case 'C': if (!set(axes.c_deg)) return false; break;
      case 'F':
        if (v < 0 || !set(feed)) return false;
        break;
      default: return false;
    }
  }
  if (is_arc(motion ? motion : state.motion) && axes.has_linear()) return false;  // an arc needs its centre
  b.number = number;
  b.motion = motion;
  b.axes = axes;
  b.feed = feed;
  if (motion) state.motion = motion;
  state.move(b);
  return true;
}

/// Applies the modal state to a parsed line and decides passthrough.
inline void finish(line_parse& p, modal_state& state, read_result& result) {
  block& b = p.b;
  const auto error = [&](std::size_t column, std::string m) {
    p.errors.push_back({{b.where.file, b.where.line, column + 1}, std::move(m)});
  };
  for (const auto& [word, column] : p.frame_words) {
    if (p.has_geometry || p.frame_arguments) error(column, frame_message(word));
    else b.kept_words.push_back(word);
  }
  const bool only_msg = p.has_msg && !p.has_content && !p.has_geometry && p.unknown.empty() && !b.moves();
  if ((!p.unknown.empty() && !p.has_geometry) || only_msg) {
    block kept;
    kept.where = b.where;
    kept.text = b.text;
    kept.number = b.number;
    kept.passthrough = true;
    b = std::move(kept);
  } else {
    for (auto& d : p.unknown) p.errors.push_back(std::move(d));
    std::stable_partition(b.kept_words.begin(), b.kept_words.end(), [](const std::string& w) { return !is_late_kept(w); });
    if (b.motion) state.motion = b.motion;
    if (p.plane) state.plane = *p.plane;
    // Checks across words only on a line whose words read cleanly: one diagnostic per problem.
    const bool clean = p.errors.empty();
    if (clean && (p.vector[0] || p.vector[1] || p.vector[2])) {
      if (!p.vector[0] || !p.vector[1] || !p.vector[2]) error(p.vector_column, "tool-axis vector needs A3, B3 and C3");
      else if (b.axes.has_rotary()) error(p.vector_column, "rotary axes and a tool-axis vector in one block");
      else b.axes.tool_axis = vec3{*p.vector[0], *p.vector[1], *p.vector[2]};
    }
    const bool has_centre = p.centre_offset_mm[0] || p.centre_offset_mm[1] || p.centre_offset_mm[2];
    if (!clean) {
      // an arc word may be the one in error: leave the arc out
    } else if (has_centre || p.radius_mm) {
      if (!is_arc(state.motion)) {
        error(p.arc_column, "word '" + p.arc_word + "' needs G2 or G3");
      } else if (has_centre && p.radius_mm) {
        error(p.arc_column, "arc has both a centre and a radius");
      } else if (p.radius_mm) {
        b.arc = arc_words{state.plane, std::nullopt, p.radius_mm};
      } else if (const auto start = state.position()) {
        const vec3 offset{p.centre_offset_mm[0].value_or(0.0), p.centre_offset_mm[1].value_or(0.0),
                          p.centre_offset_mm[2].value_or(0.0)};
        b.arc = arc_words{state.plane, *start + offset, std::nullopt};
      } else {
        error(p.arc_column, "arc start point is not known");
      }
    } else if (is_arc(state.motion) && b.axes.has_linear()) {
      error(p.geometry_column, "arc needs a centre (I J K) or a radius (CR=)");
    }
    state.move(b);
    // M2 / M30 end the program: carried by `program_end` only, not also in `m_codes`.
    const bool m30 = std::find(b.m_codes.begin(), b.m_codes.end(), 30) != b.m_codes.end();
    const bool m2 = std::find(b.m_codes.begin(), b.m_codes.end(), 2) != b.m_codes.end();
    if (m30 || m2) {
      b.program_end = m30 ? state.program_name.value_or("") : std::string("M2");
      b.m_codes.erase(std::remove_if(b.m_codes.begin(), b.m_codes.end(), [](int m) { return m == 2 || m == 30; }),
                      b.m_codes.end());
    }
  }
  std::stable_sort(p.errors.begin(), p.errors.end(),
                   [](const diagnostic& a, const diagnostic& c) { return a.where.column < c.where.column; });
  for (auto& d : p.errors) result.errors.push_back(std::move(d));
  for (auto& d : p.warnings) result.warnings.push_back(std::move(d));
}

}  // namespace detail

/// Reads a Siemens 840D program block by block: `on_block` receives each block in file order as
/// soon as it is read; errors and warnings go to `diagnostics` (its `parsed` is not touched).
/// Nothing but the current line is held, so a program of any length reads in constant memory.
inline void read_blocks(std::string_view text, const std::string& file_path, read_result& diagnostics,
                        const block_sink& on_block) {
  const file_name file(file_path);  // one string for every location in the file
  detail::modal_state state;
  for_each_line(text, [&](const text_line& line) {
    if (line.text.empty()) return;
    block b;
    std::size_t first = 0;
    while (first < line.text.size() && is_space(line.text[first])) ++first;
    b.where = {file, line.number, (first < line.text.size() ? first : 0) + 1};
    b.text = std::string(line.text);
    if (first == line.text.size()) {  // spaces only
      b.passthrough = true;
      on_block(std::move(b));
      return;
    }
    if (auto name = detail::program_header(line.text)) {
      b.program_begin = *name;
      state = detail::modal_state{};
      state.program_name = *name;
      on_block(std::move(b));
      return;
    }
    if (detail::read_plain_motion(line.text, b, state)) {
      on_block(std::move(b));
      return;
    }
    detail::line_parse p;
    p.b = std::move(b);
    detail::line_reader(line.text, line.number, file, p).run();
    detail::finish(p, state, diagnostics);
    on_block(std::move(p.b));
  });
}

/// Reads a Siemens 840D program. Never throws on bad input: problems are in `errors`.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(dialect::siemens, text, std::move(file_name), &read_blocks);
}

namespace detail {

inline void append_word(std::string& line, std::string_view word) {
  if (!line.empty()) line += ' ';
  line += word;
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
  if (!(name.size() > 4 && detail::upper(name.substr(name.size() - 4)) == "_SPF")) name += "_MPF";
  return "%_N_" + name;
}

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
  explicit writer(dialect source, std::string file = {}, const write_options& chosen = {})
      : same(source == dialect::siemens), program_file(std::move(file)), options(chosen) {}

  /// Appends the text of block `b` to `out` (nothing for a block with nothing to say). Throws
  /// `std::invalid_argument` ("file:line: reason") for a block Siemens cannot express.
  void write(std::string& out, const block& b) {
    const std::string& file = b.where.file.empty() ? program_file : b.where.file.str();
    const auto fail = [&](const std::string& why) {
      throw std::invalid_argument(file + ":" + std::to_string(b.where.line) + ": " + why);
    };
    if (b.passthrough) {
      out += detail::checked_line(same ? b.text : "; " + b.text, b, file) + '\n';
      return;
    }
    if (b.program_begin) {
      out += detail::checked_line(detail::program_file_name(*b.program_begin), b, file) + '\n';
      written = detail::modal_state{};
      model_motion.reset();
    }
    std::string line;
    if (b.number) detail::append_word(line, "N" + std::to_string(*b.number));
    if (b.tcp) detail::append_word(line, *b.tcp ? "TRAORI" : "TRAFOOF");
    if (b.metric) {
      if (!*b.metric) fail("inch units cannot be written; kin5 writes millimetres");
      detail::append_word(line, "G71");
    }
    if (b.feed_mode) detail::append_word(line, *b.feed_mode == feed_unit::inverse_time ? "G93" : "G94");
    if (same) {
      for (const auto& w : b.kept_words) {
        if (detail::is_late_kept(w)) continue;
        detail::append_word(line, w);
        if (const auto plane = detail::plane_of(w)) written.plane = *plane;
      }
    }
    if (b.machine_coordinates) detail::append_word(line, "SUPA");

    std::optional<motion_kind> word = b.motion;
    if (b.motion) model_motion = b.motion;
    if (b.feed_rapid) {
      if (b.arc) fail("an arc at rapid traverse cannot be written");
      word = motion_kind::rapid;
    } else if (!word && model_motion && written.motion != model_motion && (b.moves() || b.arc)) {
      word = model_motion;
    }
    if (word) written.motion = word;
    if (b.arc) {
      if (!detail::is_arc(written.motion)) fail("arc data without G2 or G3 cannot be written");
      if (b.arc->plane != written.plane) {
        detail::append_word(line, detail::plane_word(b.arc->plane));
        written.plane = b.arc->plane;
      }
    }
    if (word) detail::append_word(line, detail::motion_word(*word));

    const auto number = [&](std::string_view address, double v, int decimals) {
      detail::append_word(line, std::string(address) + format_number(v, decimals));
    };
    const axis_words& a = b.axes;
    if (a.x_mm) number("X", *a.x_mm, options.linear_decimals);
    if (a.y_mm) number("Y", *a.y_mm, options.linear_decimals);
    if (a.z_mm) number("Z", *a.z_mm, options.linear_decimals);
    if (a.a_deg) number("A", *a.a_deg, options.angle_decimals);
    if (a.b_deg) number("B", *a.b_deg, options.angle_decimals);
    if (a.c_deg) number("C", *a.c_deg, options.angle_decimals);
    if (a.tool_axis) {
      if (a.has_rotary()) fail("rotary axes and a tool-axis vector in one block cannot be written");
      number("A3=", a.tool_axis->x, options.vector_decimals);
      number("B3=", a.tool_axis->y, options.vector_decimals);
      number("C3=", a.tool_axis->z, options.vector_decimals);
    }
    if (b.arc && b.arc->centre_mm) {
      const auto start = written.position();
      if (!start) fail("arc centre needs a known start point (X Y Z)");
      const vec3 offset = *b.arc->centre_mm - *start;
      const std::array<double, 3> o = {offset.x, offset.y, offset.z};
      const std::array<bool, 3> in_plane = {b.arc->plane != arc_plane::yz, b.arc->plane != arc_plane::zx,
                                            b.arc->plane != arc_plane::xy};
      for (std::size_t i = 0; i < 3; ++i) {
        const std::string v = format_number(o[i], options.linear_decimals);
        if (in_plane[i] || v != "0") detail::append_word(line, std::string(1, static_cast<char>('I' + i)) + v);
      }
    } else if (b.arc && b.arc->radius_mm) {
      number("CR=", *b.arc->radius_mm, options.linear_decimals);
    }
    if (b.feed) number("F", *b.feed, options.feed_decimals);
    if (b.spindle_rpm) number("S", *b.spindle_rpm, options.feed_decimals);
    if (b.tool) detail::append_word(line, "T" + std::to_string(*b.tool));
    if (same) {
      for (const auto& w : b.kept_words)
        if (detail::is_late_kept(w)) detail::append_word(line, w);
    }
    bool ends = false;  // an M2 / M30 written in this block: never a second one
    for (int m : b.m_codes) {
      // M91 / M92 of another dialect are machine coordinates, already written as SUPA
      if (!same && b.machine_coordinates && (m == 91 || m == 92)) continue;
      detail::append_word(line, "M" + std::to_string(m));
      ends = ends || m == 2 || m == 30;
    }
    // A program end right after an M2 / M30 M function (Heidenhain `M30`, then `END PGM`) says it again.
    const bool end_written = ended && !same;
    ended = ends;
    if (b.program_end && !ends && !end_written) detail::append_word(line, *b.program_end == "M2" ? "M2" : "M30");
    std::string comment;
    if (!same) {
      for (const auto& w : b.kept_words) comment += (comment.empty() ? "" : " ") + w;
    }
    if (b.comment && !b.comment->empty()) comment += (comment.empty() ? "" : " ") + *b.comment;
    if (b.comment || !comment.empty()) line += line.empty() ? ";" : " ;";
    if (!comment.empty()) line += " " + comment;
    written.move(b);
    if (line.empty() && !same && !b.program_begin && !b.text.empty()) {  // nothing Siemens can say: the source text
      line = "; " + b.text;
      std::replace(line.begin(), line.end(), '\n', ' ');
      std::replace(line.begin(), line.end(), '\r', ' ');
    }
    if (line.empty()) return;  // nothing to say (a lone header has been written)
    if (b.program_begin && b.number && line == "N" + std::to_string(*b.number)) return;
    out += detail::checked_line(std::move(line), b, file) + '\n';
  }

 private:
  bool same;                                // the blocks were read as Siemens
  std::string program_file;
  write_options options;
  detail::modal_state written;              // what the written text leaves the controller in
  std::optional<motion_kind> model_motion;  // the program's own modal motion
  bool ended = false;                       // the last block written had an M2 / M30 M function
};

/// Writes `p` as a Siemens 840D program, one line per block, in the order
/// `N  TRAORI/TRAFOOF  G71  G93/G94  kept words  SUPA  G17-G19  G0-G3  X Y Z A B C  A3= B3= C3=
/// I J K / CR=  F  S  T  D H T="name"  M  ;comment`. Blocks read from another dialect keep their passthrough
/// text and kept words in a comment. Throws `std::invalid_argument` ("file:line: reason") for a
/// block Siemens cannot express (inch units, a rapid arc, an arc without a known start point).
inline std::string write(const program& p, const write_options& options = {}) {
  writer w(p.language, p.file, options);
  std::string out;
  for (const block& b : p.blocks) w.write(out, b);
  return out;
}

}  // namespace kin5::program::siemens
