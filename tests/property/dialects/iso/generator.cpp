// Generated ISO / Fanuc programs for the dialect laws (laws.cpp): the ISO-like generator
// (iso_like_generator.hpp) with Fanuc's codes.
#include <kin5/program/iso/dialect.hpp>

#include "contract.hpp"
#include "iso_like_generator.hpp"

/// Text drawn with the block each line must read as (iso_like_generator.hpp).
kin5::test::drawn_program kin5::test::contract<kin5::program::iso::dialect>::draw_program() {
  return iso_like::draw_program<program::iso::dialect>({});
}
