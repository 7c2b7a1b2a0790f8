/// @file paper/case_table.hpp
/// `case_table_result`: what a printed case table (a "piecewise by quadrant" formula) gives for
/// one input: every case whose condition holds, with its value.
///
/// A correct table matches exactly one case for every input it covers. A printed table with an
/// erratum shows it here: `count == 0` is a gap (e.g. [000:7] on b ∈ (270°, 360°), erratum E1),
/// `count == 2` an overlap. `value()` is the single value when `count == 1`.
#pragma once

#include <array>
#include <cstddef>
#include <optional>

namespace kin5::paper {

struct case_table_result {
  static constexpr std::size_t capacity = 8;

  std::size_t count = 0;                  ///< number of cases whose condition holds
  std::array<int, capacity> case_no{};    ///< 1-based case numbers, in printed order
  std::array<double, capacity> value_deg{};  ///< the value each matching case gives, degrees

  /// Records that printed case `number` holds and gives `value`.
  constexpr void add(int number, double value) {
    if (count < capacity) {
      case_no[count] = number;
      value_deg[count] = value;
      ++count;
    }
  }
  /// The value when exactly one case holds; empty for a gap or an overlap.
  constexpr std::optional<double> value() const {
    if (count != 1) return std::nullopt;
    return value_deg[0];
  }
};

}  // namespace kin5::paper
