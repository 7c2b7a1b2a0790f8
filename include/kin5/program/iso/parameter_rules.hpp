/// @file program/iso/parameter_rules.hpp
/// FANUC Custom Macro B variables for the interpreter (../interp/parameter_store.hpp; FANUC
/// Operator's Manuals, "Custom Macro", "Types of variables"): #1–#33 local to a `G65` call (its
/// arguments) and to the main program, #100–#199 and #500–#999 common (global); #0 (always) and a
/// variable never assigned are "vacant", whose arithmetic kin5 does not model, so reading #0, or
/// a variable the program has not assigned, is refused, naming it. #1000 and up are system variables (offsets,
/// positions, the clock): the machine's, refused; other numbers do not exist. The same ranges
/// the reader lets a program set (reader_state.hpp, `unassignable`).
#pragma once

#include "../interp/parameter_store.hpp"
#include "macro_variables.hpp"

namespace kin5::program::iso {

inline interp::parameter_rules macro_parameter_rules() {
  using interp::parameter_scope;
  interp::parameter_rules r;
  r.numbered = {{"#", 0, 0, parameter_scope::reserved, false,
                  "the null variable, always vacant, whose arithmetic kin5 does not model"}};
  for (const macro_variable_range& v : program_variables)
    r.numbered.push_back({"#", v.first, v.last, v.local ? parameter_scope::local : parameter_scope::global});
  r.numbered.push_back({"#", first_system_variable, 999999999, parameter_scope::reserved, false,
                        "a system variable (#1000 and up: the control's offsets, positions and signals), not a value "
                        "of this program"});
  return r;
}

}  // namespace kin5::program::iso
