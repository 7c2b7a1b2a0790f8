/// @file program/iso/lexer.hpp
/// The first stage of the ISO / Fanuc reader: one line split into address words (`X-450.`,
/// `G43.4`, `x 10`: a letter, optional blanks, a number, or a value the interpreter computes:
/// a parameter `X#1`, `X-#1`, `X#<feed>` or a bracketed expression `X[#1*2]`, `Z-[#3]`, read
/// by the dialect's `value_reader`, whose value the reader supplies) and comments (`( … )`, with
/// comments nested in it where the dialect has them, and `;` to the end of the line). The first problem stops the line: an expression that cannot be
/// read, a number without a letter, a malformed number, a stray byte. What a word means is the
/// reader's; a parameter assignment (`#1 = 5000`) is a statement (statements.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "../expression_parser.hpp"
#include "../lexing.hpp"
#include "../number.hpp"
#include "../parameters.hpp"
#include "../text.hpp"

namespace kin5::program::iso {

/// One address word as written: `X-450.` is letter 'X', value -450, text "X-450.".
struct word {
  char letter = 0;  ///< upper case
  double value = 0;
  std::string_view text;     ///< as written, letter to last digit
  std::string_view digits;   ///< the number as written
  std::size_t column = 0;    ///< 1-based
  /// `X#1`, `X[#1*2]`: the index of the value's expression in the line's list (`lex_line`'s
  /// `values`), for the reader to evaluate; none for a number written here.
  std::optional<std::size_t> computed;
  bool substituted = false;  ///< the number is a computed value (`X#1`), not written here
};

/// How a dialect reads a computed word value (`#1`, `[#1*2]`, `-#<feed>`) from `text`, which
/// starts at 1-based `column` of line `line`: its `read_value` (expression.hpp).
using value_reader = parsed_expression (*)(std::string_view text, std::size_t line, std::size_t column);

/// Where `lex_line` puts the computed values of a line's words.
struct computed_values {
  value_reader read = nullptr;  ///< null: a computed value is refused
  std::size_t line = 1;
  std::vector<interp::expression>* values = nullptr;
};

/// A problem that stops the line: where (1-based column) and what.
struct lex_problem {
  std::size_t column = 0;
  std::string message;
};

/// What a `(` inside a `( … )` comment is. FANUC's and Haas's controls skip everything from the
/// control-out `(` to the control-in `)` that closes it, and CAM posts write comments inside
/// comments (NX's tool lists, `(T1 (D10 MILL))`): `nested`, the comment ends at the `)` that
/// closes the first `(`. LinuxCNC ends a comment at its first `)`: `flat` (its interpreter
/// refuses a `(` inside a comment; docs/dialects/linuxcnc.md).
enum class comment_nesting { nested, flat };

namespace detail {

/// The `)` that closes the comment opening at `s[open]`, or `end` when none does before `end`.
inline std::size_t comment_close(std::string_view s, std::size_t open, std::size_t end, comment_nesting nesting) {
  std::size_t depth = 1;
  for (std::size_t k = open + 1; k < end; ++k) {
    if (s[k] == '(' && nesting == comment_nesting::nested) ++depth;
    else if (s[k] == ')' && --depth == 0) return k;
  }
  return end;
}

/// Where the comment from `s[open]` to its `)` at `close` (nested) reads otherwise on a control
/// that ends it at its first `)`: the first byte after that `)` that such a control would read
/// as code (neither a blank, nor a parenthesis, nor inside a comment opened after it); `close`
/// when both readings agree (`(T1 (D10 MILL)  )`: only blanks and a `)` left over).
inline std::size_t flat_reading_differs(std::string_view s, std::size_t open, std::size_t close) {
  std::size_t k = open + 1;
  while (k < close && s[k] != ')') ++k;
  bool inside = false;  // in a comment the flat reading opened after the first `)`
  for (++k; k < close; ++k) {
    if (s[k] == '(') inside = true;
    else if (s[k] == ')') inside = false;
    else if (!inside && !is_space(s[k])) return k;
  }
  return close;
}

/// Adds comment text `c` (trimmed) to `comment`, a blank between two non-empty pieces.
inline void add_comment(std::optional<std::string>& comment, std::string_view c) {
  c = lexing::trim(c);
  if (comment && !comment->empty() && !c.empty()) *comment += ' ';
  comment = comment.value_or("") + std::string(c);
}

/// Whether a word may end before `s[k]`: the line's end, a blank, a comment, the next letter.
inline bool word_ends(std::string_view s, std::size_t k, std::size_t end) {
  return k >= end || is_space(s[k]) || is_letter(s[k]) || s[k] == '(' || s[k] == ';';
}

/// An address word at `i` (a letter); its end, or the problem that stops the line.
inline std::size_t address_word(std::string_view s, std::size_t i, std::size_t end, const computed_values& computed,
                                word& w, std::optional<lex_problem>& problem) {
  w.letter = to_upper(s[i]);
  w.column = i + 1;
  const std::size_t k = lexing::skip_blanks(s.substr(0, end), i + 1);
  const bool signed_value = k + 1 < end && (s[k] == '-' || s[k] == '+') && (s[k + 1] == '#' || s[k + 1] == '[');
  if (k < end && (s[k] == '#' || s[k] == '[' || signed_value)) {
    if (!computed.read) {
      problem = {w.column, "expressions and parameters are not supported"};
      return end;
    }
    parsed_expression e = computed.read(s.substr(k, end - k), computed.line, k + 1);
    if (!e.ok()) {
      problem = {e.error->where.column, e.error->message};
      return end;
    }
    const std::size_t after = k + e.end;
    if (!word_ends(s, after, end)) {
      problem = {after + 1, std::string("the value of word '") + w.letter + "' goes on after its end (an expression "
                            "in a word is bracketed: " + w.letter + "[…])"};
      return end;
    }
    w.computed = computed.values->size();
    computed.values->push_back(std::move(e.tree));
    w.text = s.substr(i, after - i);
    return after;
  }
  const parsed_number n = read_number(s.substr(k, end - k));
  if (n.error == number_error::too_large) problem = {w.column, "value out of range"};
  else if (n.error != number_error::none && w.letter == 'O' && i == lexing::skip_blanks(s, 0))
    problem = {w.column, "program number O without its digits (O1 … O9999): write the number, or put the text in a "
                         "comment ( … )"};
  else if (n.error != number_error::none) problem = {w.column, std::string("word '") + w.letter + "' has no value"};
  if (problem) return end;
  if (k + n.length < end && s[k + n.length] == '.') {  // `1.2.3`
    std::size_t e = k + n.length;
    while (e < end && (is_digit(s[e]) || s[e] == '.')) ++e;
    problem = {w.column, "malformed number '" + std::string(s.substr(k, e - k)) + "'"};
    return end;
  }
  w.value = n.value;
  w.digits = s.substr(k, n.length);
  w.text = s.substr(i, k + n.length - i);
  return k + n.length;
}

/// A byte that starts no word at `i`: the problem it is.
inline lex_problem stray(std::string_view s, std::size_t i, bool first_word) {
  const char c = s[i];
  const auto u = static_cast<unsigned char>(c);
  if (c == '#' || c == '[') return {i + 1, "a parameter or expression with no address letter (a parameter is set by `#n = …` at the start of a block)"};
  if (is_digit(c) || c == '.' || c == '+' || c == '-') return {i + 1, "number with no address letter"};
  if (c == '/' && first_word) return {i + 1, "block delete (/) is not supported"};
  if (u < 0x20 || u >= 0x7f) return {i + 1, std::string("unexpected byte ") + lexing::hex_byte(c, true)};
  return {i + 1, std::string("unexpected character '") + c + "'"};
}

}  // namespace detail

/// Splits `s` from `i` to `end` into `words`, comments into `comment`; the first problem stops it.
/// Computed word values are read with `computed` (none: refused); a `(` inside a comment opens a
/// nested one when `nesting` says so.
inline std::optional<lex_problem> lex_line(std::string_view s, std::size_t i, std::size_t end, std::vector<word>& words,
                                           std::optional<std::string>& comment, const computed_values& computed = {},
                                           comment_nesting nesting = comment_nesting::nested) {
  std::optional<lex_problem> problem;
  while (i < end && !problem) {
    const char c = s[i];
    if (is_space(c)) {
      ++i;
    } else if (c == '(') {
      const std::size_t close = detail::comment_close(s, i, end, nesting);
      if (close >= end) return lex_problem{i + 1, "comment is not closed"};
      if (const std::size_t k = detail::flat_reading_differs(s, i, close); k < close)
        return lex_problem{k + 1, "text after a comment inside a comment: a control that nests comments skips it, one "
                                  "that ends a comment at its first ')' reads it as code; remove the inner parentheses "
                                  "or end the comment before the text"};
      detail::add_comment(comment, s.substr(i + 1, close - i - 1));
      i = close + 1;
    } else if (c == ';') {
      detail::add_comment(comment, s.substr(i + 1, end - i - 1));
      i = end;
    } else if (is_letter(c)) {
      word w;
      i = detail::address_word(s, i, end, computed, w, problem);
      if (problem) break;
      words.push_back(w);
      if (w.letter == 'O' && words.size() == 1) {  // LinuxCNC `o100 sub`: control flow
        const std::size_t j = lexing::skip_blanks(s.substr(0, end), i);
        if (j + 1 < end && is_letter(s[j]) && is_letter(s[j + 1]))
          problem = lex_problem{w.column, "o-word control flow is not supported"};
      }
    } else {
      problem = detail::stray(s, i, words.empty());
    }
  }
  return problem;
}

}  // namespace kin5::program::iso
