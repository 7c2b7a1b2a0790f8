/// @file linuxcnc/contract.hpp
/// The LinuxCNC dialect's contract with the dialect laws, its fuzz target and the transmission
/// table (contract.hpp): the usual one (`usual_contract`: readings compare to the last bit of a
/// decimal, N numbers included; the writer writes every program the reader accepts; the fuzz
/// target writes the default decimals), with LinuxCNC's file names and texts.
#pragma once

#include <string_view>

#include <kin5/program/linuxcnc/dialect.hpp>

#include "../contract.hpp"

namespace kin5::test {

template <>
struct contract<program::linuxcnc::dialect> : usual_contract<program::linuxcnc::dialect> {
  static constexpr std::string_view file = "gen.ngc", bad_file = "t.ngc";
  static drawn_program draw_program();
  static constexpr transmission_texts transmission{
      .ending = "%\nG0 X10 Y20 Z30\nM2\n%\n", .open = "%\nG0 X10 Y20 Z30\n", .etx_in_comment = "(a\x03~)\n"};
};

}  // namespace kin5::test
