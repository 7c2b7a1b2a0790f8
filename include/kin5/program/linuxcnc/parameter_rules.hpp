/// @file program/linuxcnc/parameter_rules.hpp
/// LinuxCNC's parameters for the interpreter (../interp/parameter_store.hpp; LinuxCNC User
/// Manual, "G-code Overview", "Parameters", "Subroutine Parameters", "Named Parameters"):
/// #1–#30 are local to an `o… call` (its arguments, the rest 0), #31–#5000 the program's own,
/// and both read 0 before they are assigned; #5001 and up are the control's (probe results,
/// G28/G30 homes, work offsets, the tool): reading or setting one is refused, as the reader
/// refuses setting them (reader.hpp, `unassignable`). A named parameter `#<name>` is local to
/// the call it is assigned in, `#<_name>` global; reading one never assigned is an error, as in
/// LinuxCNC ("Named parameter … not defined"); the predefined read-only ones (`#<_x>`, …) are
/// the machine's and refused.
#pragma once

#include <string>
#include <string_view>

#include "../interp/parameter_store.hpp"
#include "predefined_parameters.hpp"

namespace kin5::program::linuxcnc {

inline interp::parameter_rules parameter_rules() {
  using interp::parameter_scope;
  interp::parameter_rules r;
  r.numbered = {
      {"#", 1, 30, parameter_scope::local, true},
      {"#", 31, last_program_parameter, parameter_scope::global, true},
      {"#", last_program_parameter + 1, 999999999, parameter_scope::reserved, false,
       "set by the control (#5001 and up: probe results, homes, offsets), not a value of this program"},
  };
  r.named_scope = [](const std::string& name) {
    // name is "#<…>"
    if (name.size() > 3 && name[2] == '_')
      return is_predefined_parameter(std::string_view(name).substr(2, name.size() - 3)) ? parameter_scope::reserved
                                                                                         : parameter_scope::global;
    return parameter_scope::local;
  };
  return r;
}

}  // namespace kin5::program::linuxcnc
