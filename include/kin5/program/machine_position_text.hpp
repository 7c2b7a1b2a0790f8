/// @file program/machine_position_text.hpp
/// What a writer says when it cannot write a block in machine coordinates whose axis words name
/// another place than the machine's zero (`machine_position`): a reference point, a position the
/// control keeps or one from the machine builder's point is written only in the dialect it was
/// read in, by its kept word; another writer would write machine coordinates, a different place.
#pragma once

#include <string>

#include "block.hpp"

namespace kin5::program {

/// The construct of `p` as the controls spell it, for messages.
inline const char* machine_position_name(machine_position p) {
  switch (p) {
    case machine_position::machine_zero: return "a move in machine coordinates (G53, SUPA, M91)";
    case machine_position::reference_point: return "a move to the reference point (G28)";
    case machine_position::second_reference: return "a move to the second reference point (G30)";
    case machine_position::stored_position: return "a move to the position the control keeps for G28 (LinuxCNC)";
    case machine_position::second_stored_position: return "a move to the position the control keeps for G30 (LinuxCNC)";
    case machine_position::builder_position: return "a move from the machine builder's point (M92)";
    case machine_position::tool_axis_limit: return "a retract along the tool axis to the end of travel (M140 MB MAX)";
  }
  return "a move in machine coordinates";
}

/// Why block `b`, in machine coordinates to another place than the machine's zero, cannot be
/// written by a writer of another dialect.
inline std::string unwritable_machine_position(const block& b) {
  if (b.machine_reference == machine_position::tool_axis_limit)
    return std::string(machine_position_name(b.machine_reference)) +
           " has no form here while a head may tilt the tool: program the head's angles before it, so that the "
           "retract is a move of Z";
  return std::string(machine_position_name(b.machine_reference)) +
         " is written only in the dialect it was read in (a machine-coordinate word here would name another "
         "place); kin5 translate writes the target's own retract or home move";
}

}  // namespace kin5::program
