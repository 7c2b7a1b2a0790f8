/// @file apt/contract.hpp
/// The APT dialect's contract with the dialect laws and its fuzz target (contract.hpp):
/// readings compare to the last bit of a decimal; the writer must write every program the reader
/// accepts. The fuzz target writes the default decimals (3 for lengths, 7 for vectors, 1 for
/// feeds), so a first read-back is within 0.05, and once written the text is a fixed point.
#pragma once

#include <string_view>
#include <vector>

#include <kin5/program/apt/dialect.hpp>

#include "../contract.hpp"

namespace kin5::test {

template <>
struct contract<program::apt::dialect> {
  static constexpr std::string_view file = "gen.cls";
  static drawn_program draw_program();
  static std::vector<bad_input> bad_inputs();
  static constexpr std::string_view bad_file = "t.cls";
  static constexpr comparison read_exactly{};
  static constexpr comparison read_back{};
  static constexpr bool numbers_from_zero = false;

  static program::apt::write_options fuzz_options() { return {}; }
  static constexpr comparison fuzz_read_back{.tolerance = 0.05};
  static constexpr comparison fuzz_fixed_point{};
  static constexpr bool writes_all_it_reads = true;
  static bool round_trips(const program::program&) { return true; }
};

}  // namespace kin5::test
