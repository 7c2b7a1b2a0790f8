/// @file program/cutter_radius.hpp
/// The cutter radius a program compensates with, as a dialect that takes the radius with the
/// tool sees it (docs/dialects/compensation.md). ISO/Fanuc and LinuxCNC name the radius's
/// register (`G41 D n`, D n holding tool n's radius); Siemens applies the active tool's first
/// edge (`D1`), Heidenhain the called tool's. A writer of such a dialect follows the source's
/// modal state and asks, at each block, which of those the source's radius is (`radius_in_effect`).
/// @code
///   kin5::program::modal_state source;
///   source.apply(b);
///   if (kin5::program::radius_in_effect(source) == kin5::program::tool_radius::other)
///     refuse(kin5::program::radius_register_text(source));   // "D5 while tool 1 is loaded"
/// @endcode
#pragma once

#include <string>

#include "modal.hpp"

namespace kin5::program {

/// Whose radius the source program compensates with.
enum class tool_radius {
  off,    ///< no compensation: G40, R0, or never switched on
  own,    ///< the loaded tool's own: Siemens D1, Heidenhain, G41 D n with tool n loaded
  other,  ///< a register that is not the loaded tool's (G41 D5 with T1), or no tool loaded yet
};

/// Whose radius state `m` compensates with (D n is tool n's: the convention of Fanuc
/// tool-change macros, and LinuxCNC's own meaning of D).
inline tool_radius radius_in_effect(const modal_state& m) {
  if (!m.radius_compensation || *m.radius_compensation == cutter_side::off) return tool_radius::off;
  if (!m.radius_register || (m.active_tool && *m.radius_register == *m.active_tool)) return tool_radius::own;
  return tool_radius::other;
}

/// The register of `m` and the tool loaded, for messages: `D5 while tool 1 is loaded`,
/// `D5 before any tool change`.
inline std::string radius_register_text(const modal_state& m) {
  const std::string d = m.radius_register ? "D" + std::to_string(*m.radius_register) : "D";
  return d + (m.active_tool ? " while tool " + std::to_string(*m.active_tool) + " is loaded" : " before any tool change");
}

/// `G41` or `G42` for a side on; `G40` for off.
inline const char* cutter_side_code(cutter_side s) {
  return s == cutter_side::left ? "G41" : s == cutter_side::right ? "G42" : "G40";
}

}  // namespace kin5::program
