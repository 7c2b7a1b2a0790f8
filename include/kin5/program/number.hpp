/// @file program/number.hpp
/// Numbers as NC programs write them: an optional sign (`+` or `-`), digits, an optional
/// decimal point with optional digits on either side (`-450.`, `.5`, `+34.983`). No exponents,
/// no `inf`/`nan`, and magnitudes up to `max_magnitude`. Writing uses the shortest fixed form
/// with a given number of decimals and no trailing zeros beyond them.
#pragma once

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

/// `value` in fixed notation with at most `decimals` decimals, trailing zeros and a trailing
/// point removed, `-0` written as `0`.
inline std::string format_number(double value, int decimals) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  std::string s(buf, r.ptr);
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

}  // namespace kin5::program
