/// @file program/text.hpp
/// Splitting NC text into lines with their locations, the shared first step of every reader.
///
/// Accepts LF, CRLF and lone CR line endings, any bytes (comments in other encodings are kept as
/// they are), and a missing final newline. Lines and columns are 1-based; columns count bytes.
#pragma once

#include <cstddef>
#include <cstring>
#include <string_view>
#include <vector>

namespace kin5::program {

/// One physical line of the input, without its line ending.
struct text_line {
  std::string_view text;
  std::size_t number = 0;  ///< 1-based
};

/// Calls `f(text_line)` for each line of `text`, in order, without storing them. A final line
/// ending does not start an empty last line. Line ends are found with `memchr`: the next LF,
/// searched for once, then a CR before it; so a text whose lines end in CR alone is split in
/// one pass too.
template <class F>
void for_each_line(std::string_view text, F&& f) {
  const char* const first = text.data();
  const char* const last = first + text.size();
  const char* lf = first;  // the next LF at or after `start` (`last`: none), found once
  std::size_t number = 1;
  for (const char* start = first; start < last;) {
    if (lf < start) lf = start;
    if (lf < last && *lf != '\n') {
      const void* found = std::memchr(lf, '\n', static_cast<std::size_t>(last - lf));
      lf = found ? static_cast<const char*>(found) : last;
    }
    const void* cr = std::memchr(start, '\r', static_cast<std::size_t>(lf - start));
    const char* end = cr ? static_cast<const char*>(cr) : lf;
    if (end == last) {
      f(text_line{std::string_view(start, static_cast<std::size_t>(last - start)), number});
      return;
    }
    f(text_line{std::string_view(start, static_cast<std::size_t>(end - start)), number++});
    start = end + 1;
    if (*end == '\r' && start < last && *start == '\n') ++start;
  }
}

/// The lines of `text`. A final line ending does not start an empty last line.
inline std::vector<text_line> split_lines(std::string_view text) {
  std::vector<text_line> lines;
  for_each_line(text, [&](const text_line& line) { lines.push_back(line); });
  return lines;
}

/// ASCII upper case; other bytes unchanged.
constexpr char to_upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

constexpr bool is_space(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }
constexpr bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// Case-insensitive comparison of `s` with an upper-case `keyword` at the start of `s`.
constexpr bool starts_with_keyword(std::string_view s, std::string_view keyword) {
  if (s.size() < keyword.size()) return false;
  for (std::size_t i = 0; i < keyword.size(); ++i)
    if (to_upper(s[i]) != keyword[i]) return false;
  return true;
}

}  // namespace kin5::program
