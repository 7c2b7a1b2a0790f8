/// @file program/heidenhain/parameters.hpp
/// Q parameters used as constants: `FN 0: Q1=+1131` (or `Q1 = 1131`) assigns a literal, and a
/// later word whose value is that parameter (`FQ1`, `F Q1`, `X+Q1`, `X-Q1`) reads as the literal.
/// Refused at the word, naming why: a parameter assigned an expression or by another FN function
/// (the line is named), one not assigned earlier in the file (its value is the machine's),
/// Q100–Q199 (set by the control, e.g. Q120–Q122 by PLANE … STAY), and any parameter in a
/// program with control flow (`LBL`, `CALL LBL`, `CALL PGM`, `FN 9`–`FN 12` jumps): its value
/// would depend on the path taken. The table is the one every reader shares (../parameters.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "../lexing.hpp"
#include "../number.hpp"
#include "../parameters.hpp"
#include "../text.hpp"
#include "control_q.hpp"

namespace kin5::program::heidenhain::detail {

/// The Q parameters of a file: Q100-Q199 are the control's (e.g. Q120-Q122 set by PLANE … STAY).
inline parameter_table q_parameters() {
  return parameter_table(
      "Q", {{first_control_q, last_control_q, "set by the control (Q100-Q199), not a constant of this file"}});
}

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

/// The control-flow statement `line` starts with ("LBL", "CALL LBL", "FN 9", …), or "".
inline std::string control_flow_of(std::string_view line) {
  const std::string_view s = statement_of(line);
  for (std::string_view kw : {"LBL", "CALL LBL", "CALL PGM", "PGM CALL", "CALL SELECTED", "SEL PGM"})
    if (starts_with_keyword(s, kw) && (s.size() == kw.size() || !is_letter(s[kw.size()]))) return std::string(kw);
  if (const auto fn = fn_head(s); fn && fn->first >= 9 && fn->first <= 12) return "FN " + std::to_string(fn->first);
  return "";
}

/// Records an assignment to a Q parameter in statement `s` (block number removed) at `line`:
/// `FN 0: Qn=number`, `Qn = number` (a literal), or any other `FN k: Qn=…` / `Qn = …` (computed).
/// Returns whether `s` was an assignment.
inline bool record_assignment(std::string_view s, std::size_t line, parameter_table& q) {
  std::size_t k = 0;
  int fn = 0;
  if (const auto head = fn_head(s)) fn = head->first, k = lexing::skip_blanks(s, head->second);
  else if (!(starts_with_keyword(s, "Q") && s.size() > 1 && is_digit(s[1]))) return false;
  if (k >= s.size() || to_upper(s[k]) != 'Q') return false;
  const std::size_t d = ++k;
  int n = 0;
  while (k < s.size() && is_digit(s[k]) && k - d < 5) n = n * 10 + (s[k++] - '0');
  if (k == d) return false;
  k = lexing::skip_blanks(s, k);
  if (k >= s.size() || s[k] != '=') return false;
  k = lexing::skip_blanks(s, k + 1);
  const parsed_number v = read_number(s.substr(k));
  const std::size_t after = lexing::skip_blanks(s, k + v.length);
  const bool literal = fn == 0 && v.error == number_error::none && v.length > 0 && (after == s.size() || s[after] == ';');
  std::optional<parameter_literal> value;
  if (literal) value = parameter_literal{v.value, std::string(s.substr(k, v.length))};
  q.assign(n, std::move(value), line);
  return true;
}

}  // namespace kin5::program::heidenhain::detail
