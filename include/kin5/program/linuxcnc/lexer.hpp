/// @file program/linuxcnc/lexer.hpp
/// The first stage of the LinuxCNC reader: ISO's lexer (iso/lexer.hpp: address words, `( … )`
/// and `;` comments, `#` parameters and `[ … ]` expressions refused) after one check of
/// LinuxCNC's own. A line that starts with an o-word (`o100 sub`, `o<probe> call`, `o101 while
/// [#1 LT 3]`) is control flow, refused at the `o`, naming it (LinuxCNC User Manual, "O Codes");
/// an `O` word elsewhere is the reader's to refuse.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "../iso/lexer.hpp"
#include "../lexing.hpp"
#include "../text.hpp"

namespace kin5::program::linuxcnc {

using iso::lex_problem;
using iso::word;

namespace detail {

/// The o-word starting at `i` as written up to its keyword: "o100 while", "o<probe> call".
inline std::string o_word_text(std::string_view s, std::size_t i, std::size_t end) {
  std::size_t k = i + 1;
  if (k < end && s[k] == '<') {
    const std::size_t close = s.find('>', k);
    k = close == std::string_view::npos || close >= end ? end : close + 1;
  }
  while (k < end && (is_digit(s[k]) || is_space(s[k]))) ++k;
  while (k < end && is_letter(s[k])) ++k;
  return std::string(lexing::trim(s.substr(i, k - i)));
}

}  // namespace detail

/// The o-word that starts the line from `i` to `end` (after an optional block number), as the
/// problem that stops the line; nothing when the line starts otherwise.
inline std::optional<lex_problem> o_word(std::string_view s, std::size_t i, std::size_t end) {
  i = lexing::skip_blanks(s.substr(0, end), i);
  if (i < end && (s[i] == 'n' || s[i] == 'N')) {
    std::size_t k = i + 1;
    while (k < end && is_digit(s[k])) ++k;
    if (k > i + 1) i = lexing::skip_blanks(s.substr(0, end), k);
  }
  if (i < end && (s[i] == 'o' || s[i] == 'O'))
    return lex_problem{i + 1, "o-word control flow (" + detail::o_word_text(s, i, end) + ") is not supported"};
  return std::nullopt;
}

}  // namespace kin5::program::linuxcnc
