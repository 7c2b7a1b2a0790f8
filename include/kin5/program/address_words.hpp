/// @file program/address_words.hpp
/// A light scan of NC text for address words with a plain number — `X+10.5`, `A=30`, `B-.5`,
/// `F1200` — outside comments, with their place and their decimals. It does not read a program
/// (the readers do, and refuse what they do not understand): the translation uses it to point
/// at a word the reader turned into a value (an axis word the machine lacks), and the streaming
/// driver to see how finely a program writes its numbers before reading it (`scan_resolution`).
///
/// A word is a letter not preceded by a letter, digit-free identifier or `#`/`_`, then an
/// optional `=`, an optional sign and a decimal number not followed by `=` (so `A3=0.5`, a
/// Siemens vector component, and `R1=5`, a parameter, are not words). Comments: `;` to the end
/// of the line, `( … )` where the dialect's controller reads them as comments
/// (`controller::paren_comments`), strings `"…"` skipped. CL data (`capabilities::cl_data`) is
/// scanned by its records (`GOTO/x,y,z,i,j,k`, `FEDRAT/f`, `SPINDL/s`). `for_each_address_word_in_text`
/// finds the same words in a whole text in one pass over its bytes (the scan of a long program).
/// @code
///   namespace kp = kin5::program;
///   kp::for_each_address_word("N10 G1 X10.25 A-30", *kp::parse_dialect("iso"),
///                             [](const kp::address_word& w) { /* X 2, A 0 */ });
///   const auto r = kp::scan_resolution(text, *kp::parse_dialect("siemens"));
/// @endcode
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <utility>
#include <string_view>

#include "block.hpp"
#include "dialect.hpp"
#include "lexing.hpp"
#include "parameters.hpp"
#include "resolution.hpp"
#include "text.hpp"

namespace kin5::program {

/// One address word found by `for_each_address_word`.
struct address_word {
  char letter = 0;             ///< upper case
  std::size_t offset = 0;      ///< of the letter in the scanned text
  std::string_view text;       ///< the word as written, letter to the number's last digit
  int decimals = 0;            ///< digits after the decimal point
};

namespace detail {

/// The end of the number starting at `i` in `s` (sign, digits, point), and its decimals; `i`
/// itself when there is no digit.
constexpr std::size_t scan_number(std::string_view s, std::size_t i, int& decimals) {
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t digits = 0;
  decimals = 0;
  while (i < s.size() && is_digit(s[i])) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i])) ++i, ++digits, ++decimals;
  }
  return digits > 0 ? i : 0;
}

/// Whether `c` may stand just before an address letter.
constexpr bool word_boundary(char c) { return !is_letter(c) && c != '_' && c != '#' && c != '$'; }

}  // namespace detail

/// Calls `f(address_word)` for each address word of one line of letter-address text (Siemens,
/// Heidenhain, ISO), in order; comments and strings are skipped (see the file comment).
template <class F>
constexpr void for_each_address_word(std::string_view line, dialect d, F&& f) {
  const bool paren_comments = controller_of(d).paren_comments;
  int depth = 0;  // ISO comment nesting
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (depth > 0) {
      depth += c == '(' ? 1 : (c == ')' ? -1 : 0);
      continue;
    }
    if (c == ';') return;
    if (c == '(' && paren_comments) {
      depth = 1;
      continue;
    }
    if (c == '"') {
      const std::size_t close = line.find('"', i + 1);
      if (close == std::string_view::npos) return;
      i = close;
      continue;
    }
    if (!is_letter(c) || (i > 0 && !detail::word_boundary(line[i - 1]))) continue;
    std::size_t j = i + 1;
    if (j < line.size() && line[j] == '=') ++j;
    int decimals = 0;
    const std::size_t end = detail::scan_number(line, j, decimals);
    if (end == 0 || (end < line.size() && line[end] == '=')) continue;
    f(address_word{to_upper(c), i, std::string_view(line.data() + i, end - i), decimals});
    i = end - 1;
  }
}

namespace detail {

/// Adds the decimals of word `w` to its class in `r`.
constexpr void count_word(number_resolution& r, char letter, int decimals) {
  auto take = [decimals](std::optional<int>& d) {
    if (!d || decimals > *d) d = decimals;
  };
  switch (letter) {
    case 'X': case 'Y': case 'Z': case 'I': case 'J': case 'K': case 'R': take(r.linear_decimals); break;
    case 'A': case 'B': case 'C': take(r.angle_decimals); break;
    case 'F': take(r.feed_decimals); break;
    case 'S': take(r.speed_decimals); break;
    default: break;
  }
}

/// The resolution of one CL-data (APT) statement: GOTO/x,y,z[,i,j,k], FEDRAT/[MMPM,]f, SPINDL/[RPM,]s.
constexpr void count_cl_statement(number_resolution& r, std::string_view s) {
  std::size_t k = 0;
  while (k < s.size() && is_space(s[k])) ++k;
  s.remove_prefix(k);
  const int kind = starts_with_keyword(s, "GOTO/") ? 0 : starts_with_keyword(s, "FEDRAT/") ? 1
                   : starts_with_keyword(s, "SPINDL/")                                      ? 2
                                                                                            : -1;
  if (kind < 0) return;
  std::size_t i = s.find('/') + 1;
  bool counted = false;  // FEDRAT, SPINDL: the first number, wherever its unit word stands
  for (int field = 0; i <= s.size(); ++field) {
    while (i < s.size() && is_space(s[i])) ++i;
    int decimals = 0;
    const std::size_t end = scan_number(s, i, decimals);
    if (end != 0) {
      if (kind == 0 && field < 3) count_word(r, 'X', decimals);
      if (kind == 0 && field >= 3 && field < 6 && (!r.vector_decimals || decimals > *r.vector_decimals))
        r.vector_decimals = decimals;
      if (kind != 0 && !counted) count_word(r, kind == 1 ? 'F' : 'S', decimals);
      counted = counted || kind != 0;
    }
    const std::size_t comma = s.find(',', i);
    if (comma == std::string_view::npos) break;
    i = comma + 1;
  }
}

/// The bytes `for_each_address_word_in_text` stops at: letters, `;`, `(` and `"`; every other byte (digits,
/// blanks, line ends) is passed over.
inline constexpr auto scan_stops = [] {
  std::array<bool, 256> stop{};
  for (int c = 0; c < 256; ++c) stop[c] = is_letter(static_cast<char>(c)) || c == ';' || c == '(' || c == '"';
  return stop;
}();

constexpr bool is_line_end(char c) { return c == '\n' || c == '\r'; }

/// The line end at or after `i` in `text` (its size if none).
constexpr std::size_t line_end(std::string_view text, std::size_t i) {
  while (i < text.size() && !is_line_end(text[i])) ++i;
  return i;
}

}  // namespace detail

/// Calls `f(letter, offset, decimals)` for each word `for_each_address_word` finds on the lines
/// of `text` (a letter-address dialect), in order, `offset` counted from the start of `text`;
/// one pass over the bytes that stops only at letters, `;`, `(` and `"`, without splitting the
/// text into lines: a line end only ends a comment or a string, and it is a word boundary as
/// the start of a line is.
template <class F>
constexpr void for_each_address_word_in_text(std::string_view text, dialect d, F&& f) {
  const std::size_t n = text.size();
  const bool paren_comments = controller_of(d).paren_comments;
  std::size_t i = 0;
  while (i < n) {
    const char c = text[i];
    if (!detail::scan_stops[static_cast<unsigned char>(c)]) {
      ++i;
    } else if (c == ';') {
      i = detail::line_end(text, i);
    } else if (c == '(') {
      if (!paren_comments) {
        ++i;
        continue;
      }
      int depth = 1;  // nested ( … ) comments, to the line end at most
      for (++i; i < n && depth > 0 && !detail::is_line_end(text[i]); ++i)
        depth += text[i] == '(' ? 1 : (text[i] == ')' ? -1 : 0);
    } else if (c == '"') {
      std::size_t close = i + 1;
      while (close < n && text[close] != '"' && !detail::is_line_end(text[close])) ++close;
      i = close < n && text[close] == '"' ? close + 1 : close;  // unclosed: the rest of the line
    } else if (i > 0 && !detail::word_boundary(text[i - 1])) {
      ++i;
    } else {
      std::size_t j = i + 1;
      if (j < n && text[j] == '=') ++j;
      int decimals = 0;
      const std::size_t end = detail::scan_number(text, j, decimals);
      if (end == 0 || (end < n && text[end] == '=')) {
        ++i;
        continue;
      }
      f(to_upper(c), i, decimals);
      i = end;
    }
  }
}

namespace detail {

/// Whether `c` names a parameter: `#1` (ISO, LinuxCNC), `R1` (Siemens), `Q1` (Heidenhain).
constexpr bool parameter_prefix(char c) { return c == '#' || c == 'R' || c == 'r' || c == 'Q' || c == 'q'; }

/// The parameter at `i` in `line` (a prefix, then up to six digits): its prefix, upper case, and
/// number in `name`, and the position after it; 0 if there is none.
constexpr std::size_t parameter_at(std::string_view line, std::size_t i, std::pair<char, long>& name) {
  if (i >= line.size() || !parameter_prefix(line[i])) return 0;
  std::size_t j = i + 1;
  long n = 0;
  while (j < line.size() && is_digit(line[j]) && j - i <= 6) n = n * 10 + (line[j++] - '0');
  name = {to_upper(line[i]), n};
  return j > i + 1 ? j : 0;
}

}  // namespace detail

namespace detail {

constexpr bool name_char(char c) { return is_letter(c) || is_digit(c) || c == '_'; }

/// The named parameter or variable at `i` in `line`, as its reader names it: `#<Feed Rate>` is
/// `#<feedrate>` (LinuxCNC: lower case, blanks removed), `_F_CUT` or `Depth` is `_F_CUT` or
/// `DEPTH` (Siemens: upper case; a name of two characters or more); into `name`, with the
/// position after it; 0 if there is none.
inline std::size_t named_at(std::string_view line, std::size_t i, std::string& name) {
  name.clear();
  if (i + 1 < line.size() && line[i] == '#' && line[i + 1] == '<') {
    const std::size_t close = line.find('>', i + 2);
    if (close == std::string_view::npos) return 0;
    name = named_parameter(line.substr(i + 2, close - i - 2));
    return close + 1;
  }
  if (i >= line.size() || !(is_letter(line[i]) || line[i] == '_')) return 0;
  std::size_t j = i;
  while (j < line.size() && name_char(line[j])) name += to_upper(line[j++]);
  return name.size() >= 2 ? j : 0;
}

/// Where the text of a line `s` stops being read for parameters: its first `;` or `(`.
constexpr std::size_t code_end(std::string_view s) {
  std::size_t k = 0;
  while (k < s.size() && s[k] != ';' && s[k] != '(') ++k;
  return k;
}

}  // namespace detail

/// Adds to `r` the decimals of the parameters that words use: an assignment of a number,
/// `#1 = 10.1234`, `R1=10.1234`, `Q1 = +10.1234`, `#<z> = 10.1234`, `_Z=10.1234` or a Siemens
/// declaration `DEF REAL Z=10.1234`, records 4 decimals for that parameter, and a later word
/// that uses it, `X#1`, `X-#1`, `X=R1`, `F=-R1`, `X+Q1`, `FQ1`, `F Q1`, `X#<z>` or `X=_Z`, counts
/// them for its letter as the literal `X10.1234` would: a number written only in a parameter
/// keeps its decimals in the output. An assignment of anything else forgets the parameter. Which
/// of these spellings a dialect has is its reader's to say (a word it does not read is refused
/// there); text after `;` or `(` is not read.
inline void count_parameter_words(std::string_view text, number_resolution& r) {
  std::map<std::pair<char, long>, int> decimals;  // per numbered parameter assigned a number
  std::map<std::string, int, std::less<>> named;  // per named one, by its reader's name
  std::string word_name;
  for_each_line(text, [&](const text_line& line) {
    const std::string_view s = line.text.substr(0, detail::code_end(line.text));
    if (decimals.empty() && named.empty() && s.find('=') == std::string_view::npos) return;  // nothing assigned, nothing to use
    std::pair<char, long> name;
    for (std::size_t k = 0; k < s.size(); ++k) {
      const bool boundary = k == 0 || detail::word_boundary(s[k - 1]) || s[k] == '#';
      if (!boundary) continue;
      // An assignment, `#1 = 5.25`, `#<z> = 5.25`, `_Z=5.25`: the number's decimals, or forgotten.
      std::size_t end = detail::parameter_at(s, k, name);
      const bool numbered = end != 0;
      if (!numbered) end = detail::named_at(s, k, word_name);
      if (end != 0) {
        const std::size_t eq = lexing::skip_blanks(s, end);
        if (eq < s.size() && s[eq] == '=' && (eq + 1 == s.size() || s[eq + 1] != '=')) {
          int d = 0;
          const std::size_t v = lexing::skip_blanks(s, eq + 1);
          const std::size_t after = detail::scan_number(s, v, d);
          const bool number = after != 0 && (after == s.size() || !detail::parameter_prefix(s[after]));
          if (numbered) {
            if (number) decimals[name] = d;
            else decimals.erase(name);
          } else if (number) {
            named[word_name] = d;
          } else if (const auto it = named.find(word_name); it != named.end()) {
            named.erase(it);
          }
          k = eq;
          continue;
        }
        if (!numbered && !is_letter(s[k])) continue;
      }
      if (!is_letter(s[k])) continue;
      std::size_t j = lexing::skip_blanks(s, k + 1);  // `X#1`, `X-#1`, `X=R1`, `F=-R1`, `X+Q1`, `FQ1`, `F Q1`, `X=_Z`
      if (j < s.size() && s[j] == '=') ++j;
      if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
      if (const std::size_t e = detail::parameter_at(s, j, name); e != 0) {
        if (e < s.size() && s[e] == '=') continue;
        if (const auto it = decimals.find(name); it != decimals.end()) detail::count_word(r, to_upper(s[k]), it->second);
        k = e - 1;
      } else if (const std::size_t e2 = named.empty() ? 0 : detail::named_at(s, j, word_name); e2 != 0) {
        if (const auto it = named.find(word_name); it != named.end()) detail::count_word(r, to_upper(s[k]), it->second);
        k = e2 - 1;
      }
    }
  });
}

/// How finely `text`, a program in dialect `d`, writes its numbers (see the file comment): one
/// pass over the bytes, no reading; the parameters words use count as their numbers
/// (`count_parameter_words`).
inline number_resolution scan_resolution(std::string_view text, dialect d) {
  number_resolution r;
  if (!capabilities_of(d).cl_data) {
    for_each_address_word_in_text(text, d, [&r](char letter, std::size_t, int decimals) {
      detail::count_word(r, letter, decimals);
    });
    count_parameter_words(text, r);
    return r;
  }
  for_each_line(text, [&](const text_line& line) { detail::count_cl_statement(r, line.text); });
  return r;
}

}  // namespace kin5::program
