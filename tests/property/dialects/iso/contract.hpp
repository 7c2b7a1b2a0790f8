/// @file iso/contract.hpp
/// The ISO / Fanuc dialect's contract with the dialect laws and its fuzz target (contract.hpp):
/// readings compare to the last bit of a decimal, N numbers included; the writer must write
/// every program the reader accepts. The fuzz target writes the default decimals (3 for lengths
/// and angles, 7 for vectors, 1 for feeds), so a first read-back is within 0.05, and once written
/// the text is a fixed point.
#pragma once

#include <string_view>

#include <kin5/program/iso/dialect.hpp>

#include "../contract.hpp"

namespace kin5::test {

template <>
struct contract<program::iso::dialect> : usual_contract<program::iso::dialect> {
  static constexpr std::string_view file = "gen.nc";
  static drawn_program draw_program();
  static constexpr std::string_view bad_file = "t.nc";
};

}  // namespace kin5::test
