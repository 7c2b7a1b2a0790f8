// The M functions a block says, as ISO numbers, for laws that follow what a program switches:
// written from the table of docs/dialects/iso.md, independently of program/machine_functions.hpp.
#pragma once

#include <vector>

#include <kin5/program/block.hpp>

namespace kin5::test {

/// Block `b`'s state words as M functions (tool change M6; spindle M3, M4, M5; coolant M9 for
/// both off, M7 mist on, M8 flood on; stop M0, optional stop M1), then its other M functions as
/// read, in that order: a reader keeps a number only after the state word of its group.
inline std::vector<int> m_numbers_of(const program::block& b) {
  using namespace kin5::program;
  std::vector<int> out;
  const state_words& s = b.state;
  if (s.tool_change) out.push_back(6);
  if (s.spindle == spindle_rotation::clockwise) out.push_back(3);
  if (s.spindle == spindle_rotation::counter_clockwise) out.push_back(4);
  if (s.spindle == spindle_rotation::stopped) out.push_back(5);
  if (s.coolant_flood == false || s.coolant_mist == false) out.push_back(9);
  if (s.coolant_mist == true) out.push_back(7);
  if (s.coolant_flood == true) out.push_back(8);
  if (s.stop == program_stop::stop) out.push_back(0);
  if (s.stop == program_stop::optional_stop) out.push_back(1);
  out.insert(out.end(), b.m_codes.begin(), b.m_codes.end());
  return out;
}

}  // namespace kin5::test
