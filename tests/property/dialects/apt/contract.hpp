/// @file apt/contract.hpp
/// The APT dialect's contract with the dialect laws, its fuzz target and the transmission table
/// (contract.hpp): the usual one (`usual_contract`: readings compare to the last bit of a
/// decimal, the writer writes every program the reader accepts, the fuzz target writes the
/// default decimals), with APT's file names and texts.
#pragma once

#include <string_view>

#include <kin5/program/apt/dialect.hpp>

#include "../contract.hpp"

namespace kin5::test {

template <>
struct contract<program::apt::dialect> : usual_contract<program::apt::dialect> {
  static constexpr std::string_view file = "gen.cls", bad_file = "t.cls";
  static drawn_program draw_program();
  static constexpr transmission_texts transmission{
      .ending = "PARTNO T\nGOTO/10,20,30\nFINI\n",
      .open = "PARTNO T\nGOTO/10,20,30\n",
      .etx_in_comment = "PPRINT a\x03~\n"};
};

}  // namespace kin5::test
