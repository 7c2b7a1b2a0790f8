/// @file program/iso/macro_variables.hpp
/// The FANUC Custom Macro B variables a program owns, one list for the reader (which lets a
/// program set only these: reader_state.hpp, `unassignable`) and the interpreter's rules
/// (parameter_rules.hpp): local #1–#33, common #100–#199 and #500–#999 (FANUC Operator's
/// Manuals, "Custom Macro", "Types of variables"). #1000 and up are system variables.
#pragma once

namespace kin5::program::iso {

/// Variables `first` … `last`, and whether they are local to a call (`G65`).
struct macro_variable_range {
  long first, last;
  bool local;
};

inline constexpr macro_variable_range program_variables[] = {{1, 33, true}, {100, 199, false}, {500, 999, false}};

/// The first system variable: from here on they are the control's.
inline constexpr long first_system_variable = 1000;

/// Whether `#n` is one of the program's own variables.
constexpr bool is_program_variable(long n) {
  for (const macro_variable_range& r : program_variables)
    if (n >= r.first && n <= r.last) return true;
  return false;
}

}  // namespace kin5::program::iso
