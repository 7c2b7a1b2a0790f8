/// @file haas/contract.hpp
/// The Haas dialect's contract with the dialect laws, its fuzz target and the transmission
/// table (contract.hpp): the usual one (`usual_contract`: readings compare to the last bit of a
/// decimal, N numbers included; the writer writes every program the reader accepts; the fuzz
/// target writes the default decimals), with Haas's file names and texts.
#pragma once

#include <string_view>

#include <kin5/program/haas/dialect.hpp>

#include "../contract.hpp"

namespace kin5::test {

template <>
struct contract<program::haas::dialect> : usual_contract<program::haas::dialect> {
  static constexpr std::string_view file = "gen.nc", bad_file = "t.nc";
  static drawn_program draw_program();
  static constexpr transmission_texts transmission{
      .ending = "%\nO01000\nG0 X10. Y20. Z30.\nM30\n%\n",
      .open = "%\nO01000\nG0 X10. Y20. Z30.\n",
      .etx_in_comment = "(a\x03~)\n"};
};

}  // namespace kin5::test
