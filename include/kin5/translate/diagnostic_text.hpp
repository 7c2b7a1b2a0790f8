/// @file translate/diagnostic_text.hpp
/// The pieces a translation's diagnostics are made of: `fixed(v, n)`, a number with n decimals
/// (never "-0.000"); `at(b, message)`, a diagnostic at block b; `feed_word_at(b)`, where block
/// b's F word starts, for an error about its feed.
/// @code
///   out.errors.push_back(at(b, "slide X=" + fixed(x_mm, 3) + " mm past its travel"));
/// @endcode
#pragma once

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

#include "../program/block.hpp"

namespace kin5::translate_detail {

/// `v` with `decimals` decimals, never "-0.000".
inline std::string fixed(double v, int decimals) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  std::string s(buf, r.ptr);
  if (s.find_first_not_of("-0.") == std::string::npos && s.front() == '-') s.erase(0, 1);  // no "-0.000"
  return s;
}

/// A diagnostic at block `b`.
inline program::diagnostic at(const program::block& b, std::string message) { return {b.where, std::move(message)}; }

/// Where the F word of block `b` starts: the first `F` (`f`) outside comments and strings that
/// begins a word and is not the start of a longer one (FMAX, FEDRAT); the block's start when
/// there is none (APT: the F is a FEDRAT statement of its own).
inline program::source_location feed_word_at(const program::block& b) {
  const std::string_view t = b.text;
  auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  std::size_t lead = 0;  // the text of a Heidenhain block starts at column 1, before `where`
  while (lead < t.size() && (t[lead] == ' ' || t[lead] == '\t')) ++lead;
  std::size_t line = b.where.line, column = b.where.column - std::min(lead, b.where.column - 1);
  char closing = 0;  // inside a comment or string until this byte
  for (std::size_t i = 0; i < t.size(); ++i, ++column) {
    const char c = t[i];
    if (c == '\n') {
      ++line, column = 0, closing = closing == '\n' ? 0 : closing;
      continue;
    }
    if (closing) {
      if (c == closing) closing = 0;
    } else if (c == '(' || c == '"') {
      closing = c == '(' ? ')' : '"';
    } else if (c == ';') {
      closing = '\n';
    } else if ((c == 'F' || c == 'f') && (i == 0 || !letter(t[i - 1])) && (i + 1 == t.size() || !letter(t[i + 1]))) {
      return {b.where.file, line, column};
    }
  }
  return b.where;
}

}  // namespace kin5::translate_detail
