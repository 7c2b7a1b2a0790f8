/// @file heidenhain/contract.hpp
/// The Heidenhain dialect's contract with the dialect laws and its fuzz target (contract.hpp):
/// readings compare exactly; the writer numbers blocks 0, 1, 2, … itself, so a written program
/// reads back with other numbers (and a passthrough line's content is its text after the number).
/// The writer may refuse a block it names (an L without coordinates is never written as an L:
/// its F and FMAX move to the next move), so only programs without one must round-trip. It
/// frames every program (BEGIN PGM first, END PGM last): a read-back may have both in addition.
#pragma once

#include <string_view>

#include <kin5/program/heidenhain/dialect.hpp>

#include "../contract.hpp"

namespace kin5::test {

template <>
struct contract<program::heidenhain::dialect> : usual_contract<program::heidenhain::dialect> {
  static constexpr std::string_view file = "g.h", bad_file = "t.h";
  static drawn_program draw_program();
  static constexpr transmission_texts transmission{
      .ending = "BEGIN PGM T MM\nL X+10 Y+20 Z+30 FMAX\nEND PGM T MM\n",
      .open = "BEGIN PGM T MM\nL X+10 Y+20 Z+30 FMAX\n",
      .etx_in_comment = "* - a\x03~\n"};
  static constexpr comparison read_exactly{.relative = 0};
  static constexpr comparison read_back{.relative = 0, .block_numbers = false, .framed = true};
  static constexpr bool numbers_from_zero = true;

  /// Nine decimals: more than any value read has, so the written text loses nothing.
  static program::heidenhain::write_options fuzz_options() {
    program::heidenhain::write_options o;
    o.linear_decimals = o.angle_decimals = o.feed_decimals = o.finest_feed_decimals = 9;
    return o;
  }
  static constexpr comparison fuzz_read_back{.tolerance = 1e-9, .relative = 1e-15, .block_numbers = false, .framed = true};
  static constexpr comparison fuzz_fixed_point = fuzz_read_back;
  static constexpr bool writes_all_it_reads = false;
  /// Also outside: a BEGIN PGM after the first block (the frame opens before it).
  static bool round_trips(const program::program& p) {
    for (std::size_t i = 0; i < p.blocks.size(); ++i) {
      const program::block& b = p.blocks[i];
      if (b.axes.empty() && !b.arc && (b.motion || b.feed_rapid)) return false;
      if (b.program_begin && i > 0) return false;
    }
    return true;
  }
};

}  // namespace kin5::test
