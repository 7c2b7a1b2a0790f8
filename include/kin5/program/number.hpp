/// @file program/number.hpp
/// Numbers as NC programs write them: an optional sign (`+` or `-`), digits, an optional
/// decimal point with optional digits on either side (`-450.`, `.5`, `+34.983`). No exponents,
/// no `inf`/`nan`, and magnitudes up to `max_magnitude`. Writing uses the shortest fixed form
/// with a given number of decimals and no trailing zeros beyond them.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace kin5::program {

/// Largest magnitude accepted in an NC number (1e9 mm is a kilometre of travel and then some).
inline constexpr double max_magnitude = 1e9;

/// Why a number could not be read.
enum class number_error { none, empty, not_a_number, too_large };

struct parsed_number {
  double value = 0.0;
  std::size_t length = 0;  ///< characters consumed
  number_error error = number_error::none;
};

/// Reads the longest NC number at the start of `s`. `length` is 0 and `error` set on failure.
inline parsed_number read_number(std::string_view s) {
  parsed_number out{};
  std::size_t i = 0;
  bool negative = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
  const std::size_t digits_start = i;
  std::size_t digits = 0;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i, ++digits;
  }
  if (digits == 0) {
    out.error = i == 0 ? number_error::empty : number_error::not_a_number;  // "", or only "+", "-", "."
    return out;
  }
  // Only digits and one point lie in [digits_start, i): `5.` and `.5` read as strtod reads them.
  double v = 0.0;
  const auto r = std::from_chars(s.data() + digits_start, s.data() + i, v, std::chars_format::fixed);
  if (r.ec != std::errc{} || !std::isfinite(v) || v > max_magnitude) {
    out.error = number_error::too_large;
    return out;
  }
  out.value = negative ? -v : v;
  out.length = i;
  return out;
}

/// Appends `value` to `out` in fixed notation with at most `decimals` decimals (0 to 12),
/// trailing zeros and a trailing point removed, `-0` written as `0`; with `plus`, a `+` before
/// a value that is not negative (Heidenhain's `X+34.983`). No allocation beyond `out`'s growth.
inline void append_number(std::string& out, double value, int decimals, bool plus = false) {
  char buf[64];
  char* const first = buf + 1;  // room for a leading '+'
  const auto r = std::to_chars(first, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  char* end = r.ptr;
  if (std::find(first, end, '.') != end) {
    while (end > first && end[-1] == '0') --end;
    if (end > first && end[-1] == '.') --end;
  }
  char* begin = first;
  if (end - begin == 2 && begin[0] == '-' && begin[1] == '0') ++begin;  // "-0" → "0"
  if (plus && *begin != '-') *--begin = '+';
  out.append(begin, end);
}

/// `value` in fixed notation with at most `decimals` decimals, trailing zeros and a trailing
/// point removed, `-0` written as `0`.
inline std::string format_number(double value, int decimals) {
  std::string s;
  append_number(s, value, decimals);
  return s;
}

}  // namespace kin5::program
