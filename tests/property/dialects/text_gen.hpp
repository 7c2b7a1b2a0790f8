/// @file text_gen.hpp
/// Drawing NC numbers and words the way hand-written and post-processed programs spell them:
/// exact decimal values, random case, optional `+`, trailing and leading dots. For use inside
/// RapidCheck properties (each function draws with `*gen`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include <kin5/core/vec.hpp>
#include <kin5/program/number.hpp>

namespace kin5::test {

/// Up to `most` items (none included), each drawn by `draw()` in turn.
template <class Draw>
auto draw_items(std::size_t most, Draw draw) {
  const auto n = *rc::gen::inRange<std::size_t>(0, most + 1);
  std::vector<decltype(draw())> items;
  for (std::size_t i = 0; i < n; ++i) items.push_back(draw());
  return items;
}

/// k / 10^decimals for k uniform in [lo·10^d, hi·10^d]: a value every writer reproduces exactly.
inline double draw_decimal(double lo, double hi, int decimals) {
  double scale = 1;
  for (int i = 0; i < decimals; ++i) scale *= 10;
  const auto k = *rc::gen::inRange<std::int64_t>(static_cast<std::int64_t>(lo * scale),
                                                 static_cast<std::int64_t>(hi * scale) + 1);
  return static_cast<double>(k) / scale;
}

/// A tool-axis vector of exact 7-decimal components in [-1, 1], one of them at least 0.1 in
/// size: a direction that stays one (longer than the readers' 0.001) however coarsely it is written.
inline kin5::vec3 draw_direction() {
  double c[3] = {draw_decimal(-1, 1, 7), draw_decimal(-1, 1, 7), draw_decimal(-1, 1, 7)};
  const auto large = *rc::gen::inRange(0, 3);
  c[large] = (*rc::gen::arbitrary<bool>() ? 1 : -1) * draw_decimal(0.1, 1, 7);
  return {c[0], c[1], c[2]};
}

/// `value` spelled in one of the ways NC programs write it: `+5`, `5.`, `.5`, `-.5`, `5.500`;
/// with `point`, a whole number other than zero always with its point (`5.`, never `5`: ISO's
/// coordinates, where the point decides the unit).
inline std::string draw_spelling(double value, int decimals, bool point = false) {
  std::string s = kin5::program::format_number(value, decimals);
  const bool negative = s.front() == '-';
  std::string digits = negative ? s.substr(1) : s;
  if (digits.find('.') == std::string::npos && ((point && value != 0) || *rc::gen::arbitrary<bool>())) digits += '.';
  if (digits.rfind("0.", 0) == 0 && digits.size() > 2 && *rc::gen::arbitrary<bool>()) digits.erase(0, 1);  // never a bare "."
  if (digits.find('.') != std::string::npos && *rc::gen::arbitrary<bool>()) digits += "00";
  const std::string sign = negative ? "-" : (*rc::gen::arbitrary<bool>() ? "+" : "");
  return sign + digits;
}

/// `word` (upper case) in random letter case.
inline std::string draw_case(std::string word) {
  const int mode = *rc::gen::inRange(0, 3);
  for (char& c : word) {
    const bool lower = mode == 1 || (mode == 2 && *rc::gen::arbitrary<bool>());
    if (lower && c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return word;
}

/// An address word: `letter` in random case, then `value` spelled as `draw_spelling` does (with
/// `point` as there), at random with a blank between (`X 5.`).
inline std::string spell_word(char letter, double value, int decimals, bool point = false) {
  return draw_case(std::string(1, letter)) + (*rc::gen::inRange(0, 6) == 0 ? " " : "") +
         draw_spelling(value, decimals, point);
}

/// Zero to two spaces or tabs.
inline std::string draw_blanks() {
  return *rc::gen::element<std::string>("", "", " ", "  ", "\t");
}

/// One line of `words`: drawn blanks before, after, and (at random) between words instead of a
/// single space, except before a `;` comment. Without its end of line.
inline std::string draw_line(const std::vector<std::string>& words) {
  std::string line = draw_blanks();
  for (std::size_t k = 0; k < words.size(); ++k) {
    if (k) line += *rc::gen::inRange(0, 3) == 0 && words[k].front() != ';' ? draw_blanks() : " ";
    line += words[k];
  }
  return line + draw_blanks();
}

/// Text for a comment or name: letters, digits and inner spaces, no outer blanks.
inline std::string draw_words(std::size_t max_words = 3) {
  const auto n = *rc::gen::inRange<std::size_t>(1, max_words + 1);
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    if (i) s += ' ';
    s += *rc::gen::element<std::string>("ROUGH", "finish", "T1", "op_10", "D10R0.5", "x-y", "Z-5", "ok!", "a=b");
  }
  return s;
}

}  // namespace kin5::test
