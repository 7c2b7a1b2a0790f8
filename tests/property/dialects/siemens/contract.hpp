/// @file siemens/contract.hpp
/// The Siemens 840D dialect's contract with the dialect laws and its fuzz target (contract.hpp):
/// the generator knows each block's line, column and text, so the reading of generated text is
/// compared with them; the writer keeps N numbers and must write every program the reader
/// accepts. The fuzz target writes six decimals, so values come back within 1e-6 mm.
#pragma once

#include <string_view>

#include <kin5/program/siemens/dialect.hpp>

#include "../contract.hpp"

namespace kin5::test {

template <>
struct contract<program::siemens::dialect> : usual_contract<program::siemens::dialect> {
  static constexpr std::string_view file = "gen.mpf", bad_file = "bad.mpf";
  static drawn_program draw_program();
  static constexpr transmission_texts transmission{
      .ending = "G0 X10 Y20 Z30\nM30\n",
      .open = "G0 X10 Y20 Z30\n",
      .etx_in_comment = "; a\x03~\n"};
  static constexpr comparison read_exactly{.locations = true};

  static program::siemens::write_options fuzz_options() {
    program::siemens::write_options o;
    o.linear_decimals = o.angle_decimals = o.feed_decimals = o.finest_feed_decimals = 6;
    return o;
  }
  static constexpr comparison fuzz_read_back{.tolerance = 1e-6};
  static constexpr comparison fuzz_fixed_point{.tolerance = 1e-6};
};

}  // namespace kin5::test
