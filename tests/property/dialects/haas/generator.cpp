// Generated Haas programs for the dialect laws (laws.cpp): the ISO-like generator
// (../iso/iso_like_generator.hpp) with Haas's codes: TCPC `G234 H n` (no G43.5), additional work
// offsets `G154 P1` … `P99` and `G110` … `G129`, a dwell `G04 P` in seconds with a decimal point or
// in milliseconds without.
#include <kin5/program/haas/dialect.hpp>

#include "../iso/iso_like_generator.hpp"
#include "contract.hpp"

/// Text drawn with the block each line must read as (iso_like_generator.hpp).
kin5::test::drawn_program kin5::test::contract<kin5::program::haas::dialect>::draw_program() {
  return iso_like::draw_program<program::haas::dialect>(
      {.tcp_on = "G234", .vector_tcp = false, .extended = "G154", .extended_count = 99, .g110 = true,
       .dwell_seconds = 'P'});
}
