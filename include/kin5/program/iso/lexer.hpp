/// @file program/iso/lexer.hpp
/// The first stage of the ISO / Fanuc reader: one line split into address words (`X-450.`,
/// `G43.4`, `x 10`: a letter, optional blanks, a number, or a parameter `X#1`, `X-#1` whose value
/// the reader supplies) and comments (`( … )` and `;` to the end of the line); a parameter
/// assignment `#1 = 5000` (`lex_assignment`). Where the dialect has named parameters (LinuxCNC:
/// `named` true), `#<feed>` stands where `#1` may. The first problem stops the line: an
/// expression (`[`, `#1+2`, `##1`), a number without a letter, a malformed number, a stray byte.
/// What a word means is the reader's.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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
  std::optional<long> parameter;   ///< `X#1`: the parameter standing for the number (the reader's to resolve)
  std::string_view parameter_name; ///< `X#<feed>`: the named one, as written between `<` and `>`
  bool parameter_negated = false;  ///< `X-#1`
  bool substituted = false;        ///< the number is a parameter's value (`X#1`), not written here
};

/// A line that assigns a parameter, `#1 = 5000` (after an optional block number).
struct parameter_assignment {
  long number = 0;
  std::string name;                          ///< a named parameter's name as read (`#<feed>`); empty for `#n`
  std::size_t column = 0;                    ///< of the `#`, 1-based
  std::optional<parameter_literal> literal;  ///< the number assigned; none when a problem stops the line
  std::optional<std::string> comment;        ///< the line's comments (`#3000 = 1 (MESSAGE)`)
  std::optional<long long> block_number;     ///< `N10 #1 = 5`: 10
};

/// A problem that stops the line: where (1-based column) and what.
struct lex_problem {
  std::size_t column = 0;
  std::string message;
};

namespace detail {

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

/// The parameter number `#n` at `k` (at most six digits) and the position after it; 0 if none.
inline std::size_t parameter_number(std::string_view s, std::size_t k, std::size_t end, long& n) {
  if (k >= end || s[k] != '#') return 0;
  std::size_t e = k + 1;
  n = 0;
  while (e < end && is_digit(s[e]) && e - k <= 6) n = n * 10 + (s[e++] - '0');
  return e > k + 1 ? e : 0;
}

/// The named parameter `#<name>` at `k` (`name` as written between `<` and `>`, holding
/// something besides blanks) and the position after it; 0 if none.
inline std::size_t parameter_name(std::string_view s, std::size_t k, std::size_t end, std::string_view& name) {
  if (k + 1 >= end || s[k] != '#' || s[k + 1] != '<') return 0;
  const std::size_t close = s.find('>', k + 2);
  if (close == std::string_view::npos || close >= end) return 0;
  name = s.substr(k + 2, close - k - 2);
  return lexing::trim(name).empty() ? 0 : close + 1;
}

/// `#n` or, where `named`, `#<name>` at `k` into `n` or `name`; the position after it, 0 if none.
inline std::size_t parameter_at(std::string_view s, std::size_t k, std::size_t end, bool named, long& n,
                                std::string_view& name) {
  if (named)
    if (const std::size_t e = parameter_name(s, k, end, name)) return e;
  return parameter_number(s, k, end, n);
}

/// `X#1`, `X-#1`: a parameter standing for the word's number, from `k`; its end, or 0 if the
/// value is not a lone parameter (an expression).
inline std::size_t parameter_value(std::string_view s, std::size_t i, std::size_t k, std::size_t end, bool named,
                                   word& w) {
  const bool negated = k < end && s[k] == '-';
  const std::size_t p = k < end && (s[k] == '-' || s[k] == '+') ? k + 1 : k;
  long n = 0;
  std::string_view name;
  const std::size_t e = parameter_at(s, p, end, named, n, name);
  if (e == 0 || !word_ends(s, e, end)) return 0;
  if (name.empty()) w.parameter = n;
  w.parameter_name = name;
  w.parameter_negated = negated;
  w.text = s.substr(i, e - i);
  return e;
}

/// An address word at `i` (a letter); its end, or the problem that stops the line.
inline std::size_t address_word(std::string_view s, std::size_t i, std::size_t end, bool named, word& w,
                                std::optional<lex_problem>& problem) {
  w.letter = to_upper(s[i]);
  w.column = i + 1;
  const std::size_t k = lexing::skip_blanks(s.substr(0, end), i + 1);
  const bool signed_parameter = k + 1 < end && (s[k] == '-' || s[k] == '+') && s[k + 1] == '#';
  if (k < end && (s[k] == '#' || s[k] == '[' || signed_parameter)) {
    if (const std::size_t e = parameter_value(s, i, k, end, named, w)) return e;
    const bool axis = std::string_view("XYZABCIJKR").find(w.letter) != std::string_view::npos;
    problem = {w.column, axis ? "expressions and parameters in axis words are not supported"
                              : "expressions and parameters are not supported"};
    return end;
  }
  const parsed_number n = read_number(s.substr(k, end - k));
  if (n.error == number_error::too_large) problem = {w.column, "value out of range"};
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
  if (c == '#' || c == '[') return {i + 1, "expressions and parameters are not supported"};
  if (is_digit(c) || c == '.' || c == '+' || c == '-') return {i + 1, "number with no address letter"};
  if (c == '/' && first_word) return {i + 1, "block delete (/) is not supported"};
  if (u < 0x20 || u >= 0x7f) return {i + 1, std::string("unexpected byte ") + lexing::hex_byte(c, true)};
  return {i + 1, std::string("unexpected character '") + c + "'"};
}

}  // namespace detail

/// Splits `s` from `i` to `end` into `words`, comments into `comment`; the first problem stops it.
/// `named`: the dialect has named parameters (`#<feed>`).
inline std::optional<lex_problem> lex_line(std::string_view s, std::size_t i, std::size_t end, std::vector<word>& words,
                                           std::optional<std::string>& comment, bool named = false) {
  std::optional<lex_problem> problem;
  while (i < end && !problem) {
    const char c = s[i];
    if (is_space(c)) {
      ++i;
    } else if (c == '(') {
      const std::size_t close = s.find(')', i);
      if (close == std::string_view::npos || close >= end) return lex_problem{i + 1, "comment is not closed"};
      detail::add_comment(comment, s.substr(i + 1, close - i - 1));
      i = close + 1;
    } else if (c == ';') {
      detail::add_comment(comment, s.substr(i + 1, end - i - 1));
      i = end;
    } else if (is_letter(c)) {
      word w;
      i = detail::address_word(s, i, end, named, w, problem);
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

/// The parameter assignment the line from `i` to `end` is (`#1 = 5000`, `N10 #1=-2.5 (Z SAFE)`,
/// where `named` `#<feed> = 1250` too), or nothing when it starts otherwise. Only a number may be
/// assigned, and nothing but a comment may follow it: an expression (`#2 = #1*2`, `#1 = [5]`) or
/// another word is the problem that stops the line.
inline std::optional<parameter_assignment> lex_assignment(std::string_view s, std::size_t i, std::size_t end,
                                                          std::optional<lex_problem>& problem, bool named = false) {
  i = lexing::skip_blanks(s.substr(0, end), i);
  std::optional<long long> block_number;
  if (i < end && to_upper(s[i]) == 'N') {  // the block number
    std::size_t k = i + 1;
    long long n = 0;
    while (k < end && is_digit(s[k]) && n < 100000000000000000) n = n * 10 + (s[k++] - '0');
    if (k > i + 1 && (k >= end || !is_digit(s[k]))) block_number = n;
    while (k < end && is_digit(s[k])) ++k;
    if (k > i + 1) i = lexing::skip_blanks(s.substr(0, end), k);
  }
  parameter_assignment a;
  a.block_number = block_number;
  std::string_view named_as;
  std::size_t k = detail::parameter_at(s, i, end, named, a.number, named_as);
  if (k == 0) return std::nullopt;
  k = lexing::skip_blanks(s.substr(0, end), k);
  if (k >= end || s[k] != '=') return std::nullopt;
  a.column = i + 1;
  if (!named_as.empty()) a.name = named_parameter(named_as);
  const std::string name = a.name.empty() ? "#" + std::to_string(a.number) : a.name;
  const std::size_t v = lexing::skip_blanks(s.substr(0, end), k + 1);
  const parsed_number n = read_number(s.substr(v, end - v));
  const std::size_t after = v + n.length;
  if (n.error == number_error::too_large) {
    problem = lex_problem{v + 1, "value out of range"};
    return a;
  }
  if (n.error != number_error::none || n.length == 0 || !detail::word_ends(s, after, end)) {
    problem = lex_problem{v + 1, "parameter " + name + " is assigned an expression: only a number is read "
                                 "(arithmetic is not supported)"};
    return a;
  }
  std::optional<std::string> comment;
  std::vector<word> others;
  if (auto p = lex_line(s, after, end, others, comment, named)) problem = p;
  else if (!others.empty()) problem = lex_problem{others.front().column, "a word after the parameter assignment "
                                                                           "on one line is not supported"};
  if (!problem) a.literal = parameter_literal{n.value, std::string(s.substr(v, n.length))};
  a.comment = std::move(comment);
  return a;
}

}  // namespace kin5::program::iso
