/// @file apt/contract.hpp
/// The APT dialect's contract with the dialect laws, its fuzz target and the transmission table
/// (contract.hpp): the usual one (`usual_contract`: readings compare to the last bit of a
/// decimal, the writer writes every program the reader accepts), with APT's file names and
/// texts, and lengths written with nine decimals by the fuzz target.
#pragma once

#include <string_view>

#include <kin5/program/apt/dialect.hpp>

#include "../contract.hpp"

namespace kin5::test {

template <>
struct contract<program::apt::dialect> : usual_contract<program::apt::dialect> {
  static constexpr std::string_view file = "gen.cls", bad_file = "t.cls";
  static drawn_program draw_program();
  /// Nine decimals for lengths: a CIRCLE read back keeps its start and end within the reader's
  /// 0.005 mm of the radius only if the text loses nothing (the reader accepts every point of
  /// a CIRCLE up to that tolerance, so rounding to the usual 3 decimals could push one past it).
  static program::apt::write_options fuzz_options() {
    program::apt::write_options o;
    o.linear_decimals = 9;
    return o;
  }
  static constexpr transmission_texts transmission{
      .ending = "PARTNO T\nGOTO/10,20,30\nFINI\n",
      .open = "PARTNO T\nGOTO/10,20,30\n",
      .etx_in_comment = "PPRINT a\x03~\n"};
};

}  // namespace kin5::test
