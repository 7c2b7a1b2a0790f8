/// @file program/lexing.hpp
/// Scanning shared by the dialects' lexers: blanks and runs of text, the extent of an NC number,
/// byte names for diagnostics, and the way back from an offset in a block joined from several
/// physical lines (Heidenhain `~`, APT `$`) to its line and column.
///
/// A dialect's lexer (`program/<dialect>/lexer.hpp`) turns the text of one block into words with
/// these; its reader (`reader.hpp`) turns the words into a `block`.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "text.hpp"

namespace kin5::program::lexing {

/// `s` without blanks at either end.
constexpr std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

/// `s` in ASCII upper case.
inline std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = to_upper(c);
  return out;
}

/// The first position at or after `i` in `s` that is not a blank (`s.size()` if none).
constexpr std::size_t skip_blanks(std::string_view s, std::size_t i) {
  while (i < s.size() && is_space(s[i])) ++i;
  return i;
}

/// Whether `s` is blanks only (or empty).
constexpr bool is_blank(std::string_view s) { return skip_blanks(s, 0) == s.size(); }

/// Whether `v` is a whole number that is not negative (a block, tool or M number).
inline bool is_whole(double v) { return v >= 0 && std::floor(v) == v; }

/// Length of the NC number at the start of `s`, as `read_number` would take it (sign, digits,
/// point, digits), whatever its size and even without a digit.
constexpr std::size_t number_extent(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  while (i < s.size() && is_digit(s[i])) ++i;
  if (i < s.size() && s[i] == '.') ++i;
  while (i < s.size() && is_digit(s[i])) ++i;
  return i;
}

/// A control byte: below 0x20 but not a blank, or DEL.
constexpr bool is_control(char c) {
  const auto u = static_cast<unsigned char>(c);
  return (u < 0x20 && !is_space(c)) || u == 0x7f;
}

/// `0x7f` (lower-case digits) or `0x7F` (upper-case digits): how diagnostics name a byte.
inline std::string hex_byte(char c, bool upper_case) {
  const std::string_view digits = upper_case ? "0123456789ABCDEF" : "0123456789abcdef";
  const auto u = static_cast<unsigned char>(c);
  return std::string("0x") + digits[u >> 4] + digits[u & 15];
}

/// The way back from an offset in a block's joined text to the line and column of that byte:
/// each physical line's piece starts at `offset` in the joined text and at `column` of `line`.
class line_map {
 public:
  /// Records that joined offset `offset` is 1-based `column` of 1-based `line`.
  void add(std::size_t offset, std::size_t line, std::size_t column) { pieces_.push_back({offset, line, column}); }

  /// The line and column of joined offset `offset` (in the last piece that starts at or before it).
  std::pair<std::size_t, std::size_t> locate(std::size_t offset) const {
    const piece* p = &pieces_.front();
    for (const piece& q : pieces_)
      if (q.offset <= offset) p = &q;
    return {p->line, p->column + (offset - p->offset)};
  }

  bool empty() const { return pieces_.empty(); }

 private:
  struct piece {
    std::size_t offset, line, column;
  };
  std::vector<piece> pieces_;
};

}  // namespace kin5::program::lexing
