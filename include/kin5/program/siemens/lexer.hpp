/// @file program/siemens/lexer.hpp
/// The first stage of the Siemens reader: one line of 840D text split into words — addresses
/// with their values (`X-34.983`, `X = 10`, `A3=0.5`, `T="MILL"`), keywords (`TRAORI`,
/// `CR=5`, `MSG("…")`), system words, comments, and the bytes no word takes — each with its
/// column. The lexer judges only spelling (is the value a number, malformed, missing, an
/// expression?); what a word means, and which diagnostic it earns, is the reader's (reader.hpp).
///
/// Words may touch (`G1X10Y20`), a blank may separate an address from its value (`X 10`), and
/// `;` or `(` start comments anywhere outside strings.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "../lexing.hpp"
#include "../number.hpp"
#include "../text.hpp"
#include "vocabulary.hpp"

namespace kin5::program::siemens {

/// What a word of a line is.
enum class word_kind : unsigned char {
  comment,       ///< `; …` to the end of the line, or `( … )` (`closed` false when `)` is missing)
  address,       ///< one letter and its value: `X-34.983`, `X = 10`, `A3=0.5` (extension `3`), `T="name"`
  keyword,       ///< a name: `TRAORI`, `CR=5` (`assigned`), `MSG("…")` (a call)
  system,        ///< a system variable or name: `$P_UIFR`, `_NAME` (`assigned` when `=` or `[` follows; `_NAME=` takes a value)
  stray_number,  ///< a number with no address letter
  bad_byte,      ///< a byte not allowed outside comments and strings
  block_skip,    ///< `/` at the start of the block
  unknown,       ///< a run of text that starts no other word
};

/// What follows an address letter or a keyword.
enum class value_kind : unsigned char {
  none,          ///< nothing: `X`, `X-`, `X=` at the end of the line or before `;`
  number,        ///< a plain number (`number`, and `text` as written)
  malformed,     ///< `1.2.3`, `1e5`: `text`
  out_of_range,  ///< too large, `XNAN`, `X=INF`
  expression,    ///< after `=`, anything but a plain number: `text` (`R1+2`, `IC(5)`)
  parameter,     ///< `X#1`, `X[1]`, `XR1`: a parameter in place of a number
  string,        ///< `"…"` after `T=`: `text` with its quotes (`closed` false when unterminated)
  call,          ///< `NAME(…)`: `text` is the arguments (`closed` false when `)` is missing)
  run,           ///< after `=` where no number is taken (`M=3`, `RPL=45`): `text`
};

/// One word of a line.
struct word {
  word_kind kind = word_kind::unknown;
  std::size_t column = 0;           ///< 0-based offset of the word's first byte
  char letter = 0;                  ///< address: its letter, upper case
  std::string name;                 ///< keyword or system word: upper case
  std::string_view extension;       ///< address: the digits between letter and `=` (`3` of `A3=`)
  bool assigned = false;            ///< written with `=` (system word: `=` or `[` follows)
  value_kind value = value_kind::none;
  double number = 0;                ///< the value, when `value` is `number`
  std::string_view text;            ///< the value as written; a comment's or a run's text
  bool closed = true;               ///< comment, string or call: its closing character was found
  std::size_t open_column = 0;      ///< 0-based offset of an unclosed string's `"` or call's `(`
  char byte = 0;                    ///< bad_byte: the byte
};

namespace detail {

/// Splits one line into words (see the file comment). Reusable: `run` clears its output first.
class line_lexer {
 public:
  void run(std::string_view line, std::vector<word>& out) {
    s_ = line;
    out_ = &out;
    out.clear();
    first_ = i_ = lexing::skip_blanks(s_, 0);
    for (skip(); i_ < s_.size(); skip()) next();
  }

 private:
  std::string_view s_;
  std::vector<word>* out_ = nullptr;
  std::size_t i_ = 0, first_ = 0;  // the next byte; the line's first non-blank byte

  void skip() { i_ = lexing::skip_blanks(s_, i_); }
  char peek(std::size_t pos) const { return pos < s_.size() ? s_[pos] : '\0'; }
  word& add(word_kind kind, std::size_t column) {
    out_->push_back(word{});
    out_->back().kind = kind;
    out_->back().column = column;
    return out_->back();
  }

  void next() {
    const char c = s_[i_];
    if (c == ';') {
      add(word_kind::comment, i_).text = s_.substr(i_ + 1);
      i_ = s_.size();
    } else if (c == '(') {
      paren_comment();
    } else if (is_letter(c)) {
      std::size_t j = i_;
      while (j < s_.size() && is_letter(s_[j])) ++j;
      if (j - i_ == 1 && peek(j) != '_') address();
      else keyword();
    } else if (c == '$' || c == '_') {
      system_word();
    } else if (is_digit(c) || c == '.' || c == '+' || c == '-') {
      stray_number();
    } else if (detail::is_bad_byte(c)) {
      add(word_kind::bad_byte, i_).byte = c;
      ++i_;
      while (static_cast<unsigned char>(c) >= 0x80 && i_ < s_.size() && static_cast<unsigned char>(s_[i_]) >= 0x80)
        ++i_;  // one word per multi-byte character
    } else if (c == '/' && i_ == first_) {
      add(word_kind::block_skip, i_++);
    } else {
      const std::size_t start = i_;
      consume_run();
      add(word_kind::unknown, start).text = s_.substr(start, i_ - start);
    }
  }

  /// Skips to the next blank or `;` outside parentheses, brackets and strings.
  void consume_run() {
    int depth = 0;
    bool in_string = false;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '"') in_string = !in_string;
      if (!in_string) {
        if (depth == 0 && (is_space(c) || c == ';' || detail::is_bad_byte(c))) break;
        if (c == '(' || c == '[') ++depth;
        if ((c == ')' || c == ']') && depth > 0) --depth;
      }
      ++i_;
    }
  }

  /// Skips what follows a number that makes it malformed: `.3` of `1.2.3`, `e5` or `EX3` of an exponent.
  void skip_malformed_number() {
    while (i_ < s_.size() && (is_digit(s_[i_]) || s_[i_] == '.' || s_[i_] == '+' || s_[i_] == '-' ||
                              to_upper(s_[i_]) == 'E' || to_upper(s_[i_]) == 'X'))
      ++i_;
  }

  void paren_comment() {
    word& w = add(word_kind::comment, i_);
    const std::size_t close = s_.find(')', i_ + 1);
    w.closed = close != std::string_view::npos;
    w.text = w.closed ? s_.substr(i_ + 1, close - i_ - 1) : s_.substr(i_ + 1);
    i_ = w.closed ? close + 1 : s_.size();
  }

  void stray_number() {
    const std::size_t start = i_;
    const std::size_t n = lexing::number_extent(s_.substr(i_));
    bool has_digit = false;
    for (std::size_t k = start; k < start + n; ++k) has_digit = has_digit || is_digit(s_[k]);
    if (!has_digit) {
      consume_run();
      add(word_kind::unknown, start).text = s_.substr(start, i_ - start);
      return;
    }
    i_ += n;
    add(word_kind::stray_number, start).text = s_.substr(start, n);
  }

  /// `$P_UIFR[1]=…`, `_NAME`: a user variable `_NAME=…` takes its value as an address does
  /// (`assigned_value`); the rest is skipped to the run's end.
  void system_word() {
    word& w = add(word_kind::system, i_);
    const std::size_t start = i_++;
    while (i_ < s_.size() && (detail::is_ident_char(s_[i_]) || s_[i_] == '$')) ++i_;
    w.name = lexing::upper(s_.substr(start, i_ - start));
    const std::size_t k = lexing::skip_blanks(s_, i_);
    w.assigned = peek(k) == '=' || peek(k) == '[';
    if (s_[start] == '_' && peek(k) == '=') {
      i_ = k + 1;
      return assigned_value(w);
    }
    consume_run();
  }

  /// Reads the value after `word=` (blanks skipped) into `w` the way a plain-number address
  /// takes it: a number, or nothing, malformed, too large, or an expression up to the run's end.
  void assigned_value(word& w) {
    skip();
    const std::size_t value_pos = i_;
    if (i_ >= s_.size() || s_[i_] == ';') return;  // value_kind::none
    const auto n = read_number(s_.substr(i_));
    const std::size_t extent = lexing::number_extent(s_.substr(i_));
    const char next = peek(i_ + extent), after = to_upper(peek(i_ + extent + 1));
    const bool exponent = (next == 'e' || next == 'E') && (is_digit(after) || after == '+' || after == '-' || after == 'X');
    const bool operand_follows = next == '+' || next == '-' || next == '*' || next == '/' || next == '(' ||
                                 next == '[' || next == '<' || next == '>' || next == '=' || next == '.';
    if (n.length > 0 && !operand_follows && !exponent) {
      i_ += n.length;
      w.value = value_kind::number, w.number = n.value;
    } else if (n.length > 0 && (exponent || next == '.')) {  // `1e5`, `1.2.3`
      i_ += extent;
      skip_malformed_number();
      w.value = value_kind::malformed;
    } else if (n.error == number_error::too_large && !operand_follows) {
      i_ += extent;
      skip_malformed_number();
      w.value = value_kind::out_of_range;
    } else {
      consume_run();
      w.value = value_kind::expression;
    }
    w.text = s_.substr(value_pos, i_ - value_pos);
  }

  /// What follows `=` where no number is read: the run up to the next blank.
  void assigned_run(word& w) {
    skip();
    const std::size_t value_pos = i_;
    consume_run();
    w.value = value_kind::run;
    w.text = s_.substr(value_pos, i_ - value_pos);
  }

  void address() {
    word& w = add(word_kind::address, i_);
    w.letter = to_upper(s_[i_++]);
    const std::size_t after_letter = i_;
    skip();
    if (peek(i_) == '=') {
      ++i_;
      w.assigned = true;
      return assignment(w);
    }
    if (plain_number(w)) return;
    const std::size_t value_pos = i_;
    const std::size_t extent = lexing::number_extent(s_.substr(i_));
    bool has_digit = false;
    for (std::size_t k = value_pos; k < value_pos + extent; ++k) has_digit = has_digit || is_digit(s_[k]);
    if (!has_digit) return no_number(w, after_letter, extent);
    i_ = value_pos + extent;
    w.text = s_.substr(value_pos, extent);
    const char next = peek(i_), after = to_upper(peek(i_ + 1));
    if (next == '.' || ((next == 'e' || next == 'E') && (is_digit(after) || after == '+' || after == '-' || after == 'X'))) {
      skip_malformed_number();
      w.value = value_kind::malformed;
      w.text = s_.substr(value_pos, i_ - value_pos);
      return;
    }
    const std::size_t k = lexing::skip_blanks(s_, i_);
    if (peek(k) == '=') return extension(w, k);
    const auto n = read_number(w.text);
    if (n.error != number_error::none) w.value = value_kind::out_of_range;
    else w.value = value_kind::number, w.number = n.value;
  }

  /// The common case, `X-34.983` followed by a blank, `;`, `(`, the end or the next address
  /// letter: one scan. Anything else is left to the careful path of `address`.
  bool plain_number(word& w) {
    const parsed_number n = read_number(s_.substr(i_));
    if (n.error != number_error::none) return false;
    std::size_t k = i_ + n.length;
    const char next = peek(k);
    k = lexing::skip_blanks(s_, k);
    const bool ends = k == s_.size() || next == ';' || next == '(' || (is_letter(next) && next != 'e' && next != 'E') ||
                      (is_space(next) && peek(k) != '=');
    if (!ends || peek(k) == '=') return false;
    w.value = value_kind::number, w.number = n.value;
    w.text = s_.substr(i_, n.length);
    i_ += n.length;
    return true;
  }

  /// An address letter with no digits after it: `X`, `X-`, or a parameter `X#1`, `X[1]`.
  void no_number(word& w, std::size_t after_letter, std::size_t extent) {
    const char next = peek(after_letter);
    if (detail::is_geometry_letter(w.letter) && (next == '#' || next == '[')) {
      i_ = after_letter;
      consume_run();
      w.value = value_kind::parameter;
      return;
    }
    i_ += extent;
  }

  /// `A3=…`, `R1=…`, `X1=…`: an address with digits before `=`.
  void extension(word& w, std::size_t equals) {
    i_ = equals + 1;
    w.extension = w.text;
    w.assigned = true;
    w.text = {};
    if ((w.letter == 'A' || w.letter == 'B' || w.letter == 'C') && w.extension == "3") return assigned_value(w);
    assigned_run(w);
  }

  /// `X=…`: a plain number for X Y Z A B C I J K F S T, a string for T; a run for any other letter.
  void assignment(word& w) {
    skip();
    if (w.letter == 'T' && peek(i_) == '"') {
      const std::size_t open = i_;
      const std::size_t close = s_.find('"', open + 1);
      w.value = value_kind::string;
      w.closed = close != std::string_view::npos;
      w.open_column = open;
      i_ = w.closed ? close + 1 : s_.size();
      w.text = s_.substr(open, i_ - open);
      return;
    }
    static constexpr std::string_view assignable = "XYZABCIJKFST";
    if (assignable.find(w.letter) == std::string_view::npos) return assigned_run(w);
    assigned_value(w);
  }

  void keyword() {
    const std::size_t start = i_;
    while (i_ < s_.size() && detail::is_ident_char(s_[i_])) ++i_;
    std::string name = lexing::upper(s_.substr(start, i_ - start));
    if (number_like(name, start)) return;
    word& w = add(word_kind::keyword, start);
    w.name = std::move(name);
    if (peek(i_) == '(') return call(w);
    const std::size_t k = lexing::skip_blanks(s_, i_);
    if (peek(k) != '=') return;
    i_ = k + 1;
    w.assigned = true;
    if (w.name == "CR" || w.name == "TURN") assigned_value(w);  // a number's keywords
    else assigned_run(w);
  }

  /// `XNAN`, `FINF` (a value out of range) and `XR1`, `YQ2` (a parameter): an address, not a
  /// keyword. True when `name` is one, added as such.
  bool number_like(const std::string& name, std::size_t start) {
    const std::string_view rest = std::string_view(name).substr(1);
    const char first = name[0];
    const bool geometry = detail::is_geometry_letter(first);
    value_kind v;
    if ((geometry || first == 'F' || first == 'S') && (rest == "NAN" || rest == "INF" || rest == "INFINITY")) {
      v = value_kind::out_of_range;
    } else if (geometry && name != "CR" && rest.size() >= 2 && (rest[0] == 'R' || rest[0] == 'Q') &&
               all_digits(rest.substr(1))) {
      v = value_kind::parameter;
    } else {
      return false;
    }
    word& w = add(word_kind::address, start);
    w.letter = first;
    w.value = v;
    return true;
  }

  static bool all_digits(std::string_view s) {
    for (char c : s)
      if (!is_digit(c)) return false;
    return true;
  }

  /// `NAME(…)`, to the matching `)` outside strings.
  void call(word& w) {
    const std::size_t open = i_;
    int depth = 0;
    bool in_string = false;
    w.value = value_kind::call;
    w.open_column = open;
    for (std::size_t k = open; k < s_.size(); ++k) {
      const char c = s_[k];
      if (c == '"') in_string = !in_string;
      if (in_string) continue;
      if (c == '(') ++depth;
      if (c == ')' && --depth == 0) {
        w.text = s_.substr(open + 1, k - open - 1);
        i_ = k + 1;
        return;
      }
    }
    w.closed = false;
    i_ = s_.size();
  }
};

}  // namespace detail

/// The words of one line of 840D text, in order (see `word`).
inline std::vector<word> lex_line(std::string_view line) {
  std::vector<word> words;
  detail::line_lexer().run(line, words);
  return words;
}

}  // namespace kin5::program::siemens
