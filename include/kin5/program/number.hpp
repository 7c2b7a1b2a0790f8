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

#include "text.hpp"

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
  const char* const first = s.data() + i;
  const char* const last = s.data() + s.size();
  // A digit or a point followed by a digit starts a number; `from_chars` then reads exactly the
  // grammar above (digits, one optional point, digits) since `fixed` takes no exponent, and
  // neither `inf` nor `nan` can start with a digit or a point.
  const bool starts = first < last && (is_digit(*first) || (*first == '.' && first + 1 < last && is_digit(first[1])));
  if (!starts) {
    out.error = i == 0 && (first == last || *first != '.') ? number_error::empty : number_error::not_a_number;
    return out;
  }
  double v = 0.0;
  const auto r = std::from_chars(first, last, v, std::chars_format::fixed);
  std::size_t end = static_cast<std::size_t>(r.ptr - s.data());
  if (r.ec == std::errc{} && end < s.size() && s[end] == '.') {
    // `5.`: should from_chars stop before a final point, the NC grammar still takes it
    bool seen_point = false;
    for (std::size_t k = i; k < end; ++k) seen_point = seen_point || s[k] == '.';
    if (!seen_point) ++end;
  }
  if (r.ec != std::errc{} || !std::isfinite(v) || v > max_magnitude) {
    out.error = number_error::too_large;
    return out;
  }
  out.value = negative ? -v : v;
  out.length = end;
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
  out.append(begin, static_cast<std::size_t>(end - begin));
}

/// `value` in fixed notation with at most `decimals` decimals, trailing zeros and a trailing
/// point removed, `-0` written as `0`.
inline std::string format_number(double value, int decimals) {
  std::string s;
  append_number(s, value, decimals);
  return s;
}

}  // namespace kin5::program
