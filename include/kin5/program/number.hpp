/// @file program/number.hpp
/// Numbers as NC programs write them: an optional sign (`+` or `-`), digits, an optional
/// decimal point with optional digits on either side (`-450.`, `.5`, `+34.983`). No exponents,
/// no `inf`/`nan`, and magnitudes up to `max_magnitude`. Writing uses the shortest fixed form
/// with a given number of decimals and no trailing zeros beyond them, and refuses (throws
/// `number_out_of_range`, before writing anything) what reading would refuse: so every number
/// written reads back. Feeds and speeds keep three significant digits (`rate_decimals`).
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

#include "text.hpp"

namespace kin5::program {

/// Largest magnitude accepted in an NC number (1e9 mm is a kilometre of travel and then some).
inline constexpr double max_magnitude = 1e9;

/// Shortest tool-axis vector (I J K, TX TY TZ, GOTO's i,j,k) taken as a direction. Components
/// are written to about 7 decimals; below this length their rounding turns the direction by
/// more than 1e-4 rad, and a vector such as (1e-28, 0, 0) is no direction at all.
inline constexpr double min_direction_length = 1e-3;

/// Whether the components `i, j, k` of a written tool-axis vector make a direction.
inline bool is_direction(double i, double j, double k) {
  const double m = std::max({std::abs(i), std::abs(j), std::abs(k)});  // scaled: no underflow
  if (!(m > 0.0) || !std::isfinite(m)) return false;
  const double x = i / m, y = j / m, z = k / m;
  return m * std::sqrt(x * x + y * y + z * z) >= min_direction_length;
}

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

/// A number that no NC program can hold: not finite, or larger in magnitude than
/// `max_magnitude`. A `std::invalid_argument`, as the writers' other refusals.
struct number_out_of_range : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Whether `value` can be written as an NC number: finite, and |value| ≤ `max_magnitude` (its
/// rounding to any number of decimals is then within the bound too, 1e9 being exact).
constexpr bool writable(double value) { return value == value && value >= -max_magnitude && value <= max_magnitude; }

namespace detail {

/// `value` (finite, |value| at most `max_magnitude`) in fixed notation with `decimals` (0 to 12)
/// decimals into `[first, last)` (32 bytes or more), byte for byte as
/// `std::to_chars(first, last, value, std::chars_format::fixed, decimals)` writes it: the sign
/// of a negative value or -0, the digits of |value| correctly rounded, the point when
/// `decimals` > 0. Returns the end.
///
/// The digits are those of the integer nearest s = |value|·10^decimals. Below 2^31 the product
/// is within 2^-23 of the exact one (10^decimals is exact), so unless it lies within 1e-6 of a
/// half, its nearest integer is the exact product's; otherwise (larger values, near-ties)
/// `to_chars` decides. No string, no division of doubles.
inline char* fixed_chars(char* first, char* last, double value, int decimals) {
  static constexpr double scale[13]{1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12};
  const double scaled = std::abs(value) * scale[decimals];
  const double whole = std::floor(scaled), part = scaled - whole;
  if (!(scaled < 0x1p31) || std::abs(part - 0.5) <= 1e-6) {
    const auto r = std::to_chars(first, last, value, std::chars_format::fixed, decimals);
    if (r.ec != std::errc{}) throw number_out_of_range("a number too long to write");  // not reached
    return r.ptr;
  }
  auto n = static_cast<std::uint64_t>(whole) + (part > 0.5 ? 1u : 0u);
  char digits[24];  // least significant first; at least decimals + 1 of them
  int k = 0;
  do {
    digits[k++] = static_cast<char>('0' + n % 10);
    n /= 10;
  } while (n != 0 || k <= decimals);
  char* out = first;
  if (std::signbit(value)) *out++ = '-';
  for (int i = k - 1; i >= decimals; --i) *out++ = digits[i];
  if (decimals > 0) *out++ = '.';
  for (int i = decimals - 1; i >= 0; --i) *out++ = digits[i];
  return out;
}

}  // namespace detail

/// Appends `value` to `out` in fixed notation with at most `decimals` decimals (clamped to 0 to
/// 12), trailing zeros and a trailing point removed, `-0` written as `0`; with `plus`, a `+`
/// before a value that is not negative (Heidenhain's `X+34.983`). Throws `number_out_of_range`,
/// `out` unchanged, for a value that is not `writable`. No allocation beyond `out`'s growth.
inline void append_number(std::string& out, double value, int decimals, bool plus = false) {
  if (!writable(value)) {
    char text[32];
    const auto shown = std::to_chars(text, text + sizeof text, value);  // shortest form: fits 32
    throw number_out_of_range("the number " + std::string(text, shown.ptr) +
                              " cannot be written in an NC program (finite, magnitude at most 1e9)");
  }
  decimals = std::clamp(decimals, 0, 12);
  // Sign, 10 digits up to 1e9, point, 12 decimals, and the '+' in front: 25 of the 32 bytes.
  char buf[32];
  char* const first = buf + 1;  // room for a leading '+'
  char* end = detail::fixed_chars(first, buf + sizeof buf, value, decimals);
  if (decimals > 0) {  // a point was written: trailing zeros go
    while (end > first && end[-1] == '0') --end;
    if (end > first && end[-1] == '.') --end;
  }
  char* begin = first;
  if (end - begin == 2 && begin[0] == '-' && begin[1] == '0') ++begin;  // "-0" → "0"
  if (plus && *begin != '-') *--begin = '+';
  out.append(begin, static_cast<std::size_t>(end - begin));
}

namespace detail {

/// `rate_decimals`' choice for `value`, and whether those decimals write it within 0.5 %.
struct rate_choice {
  int decimals = 0;
  bool within = true;
};

inline rate_choice choose_rate_decimals(double value, int decimals, int finest) {
  decimals = std::clamp(decimals, 0, 12);
  const double m = std::abs(value);
  if (!(m > 0.0) || !writable(value)) return {decimals, true};
  if (m >= 100.0) return {decimals, true};  // three digits before the point already (no logarithm)
  const int three_digits = 2 - static_cast<int>(std::floor(std::log10(m)));
  if (three_digits <= decimals) return {decimals, true};
  const int d = std::max(decimals, std::min(three_digits, std::clamp(finest, 0, 12)));
  const double scale = std::pow(10.0, d);
  return {d, std::abs(std::round(m * scale) / scale - m) <= 0.005 * m};
}

/// `value` as short as it reads back: fixed from 1e-4 to 1e9 (`0.0004`), else with an exponent.
inline std::string shortest(double value) {
  char text[48];
  const double m = std::abs(value);
  const bool fixed = m == 0.0 || (m >= 1e-4 && m <= max_magnitude);  // at most 4 + 17 digits: fits 48
  const auto shown = fixed ? std::to_chars(text, text + sizeof text, value, std::chars_format::fixed)
                           : std::to_chars(text, text + sizeof text, value);  // shortest form: fits 48
  return std::string(text, shown.ptr);
}

inline std::string rate_refusal(double value, int d, std::string_view what) {
  const double scale = std::pow(10.0, d);
  return "the " + std::string(what) + " " + shortest(value) + " cannot be written with " + std::to_string(d) +
         " decimals, the most the controller reads (it would read as " +
         (std::round(std::abs(value) * scale) == 0.0 ? std::string("0") : std::string("another value")) + ")";
}

}  // namespace detail

/// Decimals to write a feed or spindle speed `value` (F, S) with: at least `decimals`, and as
/// many more as keep three significant digits, up to `finest` (the controller's input
/// resolution), so that a rate is written within 0.5 % — an inverse-time F of 0.02 (1000 mm at
/// F20) is `F0.02`, not `F0`. Throws `number_out_of_range` for a rate other than 0 that `finest`
/// decimals cannot write within 0.5 % (it would read as 0, or as another rate); what is not
/// `writable` is left to `append_number` to refuse.
inline int rate_decimals(double value, int decimals, int finest, std::string_view what = "feed") {
  const detail::rate_choice c = detail::choose_rate_decimals(value, decimals, finest);
  if (!c.within) throw number_out_of_range(detail::rate_refusal(value, c.decimals, what));
  return c.decimals;
}

/// Why a writer with at most `finest` decimals would refuse the feed or spindle speed `value`
/// (in the unit it writes it in): not `writable`, or not within 0.5 % (`rate_decimals`); nothing
/// when it writes it. Readers refuse such a rate at its word, so that what a dialect's reader
/// accepts its writer writes back: `S.0101` is not read where the controller reads 3 decimals.
inline std::optional<std::string> unwritable_rate(double value, int finest, std::string_view what = "feed") {
  if (!writable(value))
    return "the " + std::string(what) + " " + detail::shortest(value) +
           " cannot be written in an NC program (finite, magnitude at most 1e9)";
  const detail::rate_choice c = detail::choose_rate_decimals(value, 0, finest);
  if (c.within) return std::nullopt;
  return detail::rate_refusal(value, c.decimals, what);
}

/// `value` in fixed notation with at most `decimals` decimals, trailing zeros and a trailing
/// point removed, `-0` written as `0`; throws `number_out_of_range` as `append_number`.
inline std::string format_number(double value, int decimals) {
  std::string s;
  append_number(s, value, decimals);
  return s;
}

}  // namespace kin5::program
