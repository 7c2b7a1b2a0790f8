// Compares a regenerated text with the committed one: the words must be equal and the numbers
// equal to within a tolerance, so that a last-digit difference of Ipopt on another machine does
// not fail the comparison but any other change does.
#pragma once

#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>

namespace kin5::gen_tables {

/// Where two texts first differ, or nothing.
struct difference {
  bool found = false;
  std::size_t line = 0;  ///< 1-based, in the committed text
  std::string expected, actual;
};

namespace detail {

inline bool starts_number(std::string_view s, std::size_t i) {
  const auto digit = [&](std::size_t k) { return k < s.size() && s[k] >= '0' && s[k] <= '9'; };
  return digit(i) || (s[i] == '-' && digit(i + 1));
}

/// The number starting at s[i] (advances i), as strtod reads it.
inline double read_number(std::string_view s, std::size_t& i) {
  const std::string tail(s.substr(i, 40));
  char* end = nullptr;
  const double v = std::strtod(tail.c_str(), &end);
  i += static_cast<std::size_t>(end - tail.c_str());
  return v;
}

inline std::string around(std::string_view s, std::size_t i) {
  const std::size_t b = s.rfind('\n', i), e = s.find('\n', i);
  return std::string(s.substr(b == std::string_view::npos ? 0 : b + 1, (e == std::string_view::npos ? s.size() : e) - (b == std::string_view::npos ? 0 : b + 1)));
}

}  // namespace detail

/// Compares `expected` (committed) with `actual` (regenerated); numbers may differ by `tolerance`.
inline difference compare(std::string_view expected, std::string_view actual, double tolerance) {
  std::size_t i = 0, j = 0, line = 1;
  auto fail = [&] { return difference{true, line, detail::around(expected, i), detail::around(actual, j)}; };
  while (i < expected.size() && j < actual.size()) {
    const bool ni = detail::starts_number(expected, i), nj = detail::starts_number(actual, j);
    if (ni && nj) {
      const double a = detail::read_number(expected, i), b = detail::read_number(actual, j);
      if (!(std::abs(a - b) <= tolerance)) return fail();
      continue;
    }
    if (ni != nj || expected[i] != actual[j]) return fail();
    if (expected[i] == '\n') ++line;
    ++i, ++j;
  }
  if (i != expected.size() || j != actual.size()) return fail();
  return {};
}

}  // namespace kin5::gen_tables
