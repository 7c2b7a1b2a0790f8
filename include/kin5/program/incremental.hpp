/// @file program/incremental.hpp
/// The position an incremental axis word reaches (G91, Heidenhain `IX`, Siemens `X=IC(…)`): the
/// last programmed position of its axis plus the distance, added as a control adds, in the
/// decimals written. A control counts positions in whole input increments, so `X0.1` then
/// `G91 X0.2` reaches 0.3, where a plain double sum gives 0.30000000000000004 (a value no writer
/// writes back exactly). The readers keep each axis's last position with the decimals it was
/// written with (`axis_position`) and resolve every incremental word with `reached`.
/// @code
///   kin5::program::axis_position x{0.1, 1};
///   kin5::program::reached(x, 0.2, 1);  // {0.3, 1}: exactly the double read from "0.3"
/// @endcode
#pragma once

#include <algorithm>
#include <cmath>
#include <string_view>

namespace kin5::program {

/// A programmed position of one axis, in the program's unit, and the decimals it has as written.
struct axis_position {
  double value = 0;
  int decimals = 0;
};

/// How many decimals the number `digits` is written with (`12.50`: 2; `7`: 0).
constexpr int decimals_written(std::string_view digits) {
  const auto point = digits.find('.');
  if (point == std::string_view::npos) return 0;
  int n = 0;
  for (auto k = point + 1; k < digits.size() && digits[k] >= '0' && digits[k] <= '9'; ++k) ++n;
  return n;
}

/// How many decimals `value` has in its shortest spelling (`-37.5`: 1; 12 at most).
inline int shortest_decimals(double value) {
  for (int d = 0; d < 12; ++d) {
    double scale = 1;
    for (int k = 0; k < d; ++k) scale *= 10;
    if (std::abs(value) * scale < 4503599627370496.0 && std::round(value * scale) / scale == value) return d;
  }
  return 12;
}

/// `from` moved by `distance`, written with `decimals`: the sum rounded to the finer of the two
/// decimals (at most 12), so that it is the double nearest the decimal sum; a sum too large for
/// that many decimals in a double's 53 bits is the plain sum.
inline axis_position reached(const axis_position& from, double distance, int decimals) {
  const int d = std::clamp(std::max(from.decimals, decimals), 0, 12);
  const double sum = from.value + distance;
  double scale = 1;
  for (int k = 0; k < d; ++k) scale *= 10;  // exact up to 10^22
  if (!(std::abs(sum) * scale < 4503599627370496.0)) return {sum, d};  // 2^52
  return {std::round(sum * scale) / scale, d};
}

}  // namespace kin5::program
