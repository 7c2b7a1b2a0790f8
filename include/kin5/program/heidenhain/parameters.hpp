/// @file program/heidenhain/parameters.hpp
/// The Q-parameter lines as the reader sees them: `FN k:` heads, and assignments (`FN 0: Q1=+1131`,
/// `Q1 = 5 * Q2`, `QL1 = …`, `QR1 = …`, `QS1 = …`), which pass through as written. Their values
/// are the interpreter's: the executor runs each assignment (statements.hpp) before the line is
/// read, and a word that uses a parameter (`FQ1`, `X+Q1`, `X-QL2`) reads its value from the
/// running program's parameters (motion.hpp), or is refused naming why it has none (never
/// assigned: its value is the machine's; Q100–Q199: set by the control).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "../lexing.hpp"
#include "../text.hpp"

namespace kin5::program::heidenhain::detail {

/// `s` (one statement, block number removed) after the keywords `FN <n>:` — the FN number and
/// the position after the colon — if it starts with them.
inline std::optional<std::pair<int, std::size_t>> fn_head(std::string_view s) {
  std::size_t k = 0;
  if (!starts_with_keyword(s, "FN")) return std::nullopt;
  k = lexing::skip_blanks(s, 2);
  const std::size_t d = k;
  int n = 0;
  while (k < s.size() && is_digit(s[k]) && k - d < 3) n = n * 10 + (s[k++] - '0');
  if (k == d) return std::nullopt;
  k = lexing::skip_blanks(s, k);
  if (k >= s.size() || s[k] != ':') return std::nullopt;
  return std::pair{n, k + 1};
}

/// `s` without blanks and a block number at its start.
inline std::string_view statement_of(std::string_view s) {
  std::size_t k = lexing::skip_blanks(s, 0);
  while (k < s.size() && is_digit(s[k])) ++k;
  return s.substr(lexing::skip_blanks(s, k));
}

/// Whether statement `s` (block number removed) assigns a parameter: `FN k: Qn=…` (k from 0 to 8
/// or 13), `Qn = …`, `QLn = …`, `QRn = …`, or a string `QSn = …` (read by no word: a word that uses
/// one is refused).
inline bool is_assignment(std::string_view s) {
  std::size_t k = 0;
  if (const auto head = fn_head(s)) {
    if (head->first > 13 || (head->first >= 9 && head->first <= 12)) return false;
    k = lexing::skip_blanks(s, head->second);
  }
  if (k >= s.size() || to_upper(s[k]) != 'Q') return false;
  ++k;
  if (k < s.size() && (to_upper(s[k]) == 'L' || to_upper(s[k]) == 'R' || to_upper(s[k]) == 'S')) ++k;
  const std::size_t d = k;
  while (k < s.size() && is_digit(s[k])) ++k;
  if (k == d) return false;
  k = lexing::skip_blanks(s, k);
  return k < s.size() && s[k] == '=';
}

}  // namespace kin5::program::heidenhain::detail
