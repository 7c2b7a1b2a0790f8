/// @file program/tool_length.hpp
/// The tool length a program has in effect, as a dialect that takes the length with the tool
/// sees it. ISO/Fanuc and LinuxCNC name the length's register (`G43 H n`) and may switch it off
/// (`G49`); Siemens applies the active tool's own edge (`D1`, off with `D0`), Heidenhain and APT
/// the called tool's, always. A writer of such a dialect follows the source's modal state and asks,
/// at each block, which of those the source's length is (`length_in_effect`).
/// @code
///   kin5::program::modal_state source;
///   source.apply(b);
///   if (kin5::program::length_in_effect(source) == kin5::program::tool_length::other)
///     refuse(kin5::program::length_register_text(source));   // "H5 while tool 1 is loaded"
/// @endcode
#pragma once

#include <string>

#include "modal.hpp"

namespace kin5::program {

/// Whose length the source program applies.
enum class tool_length {
  unsaid,  ///< the program has not said (its dialect takes the length with the tool)
  own,     ///< the loaded tool's own: G43 without H, G43 H n with tool n loaded, D1, TOOL CALL
  off,     ///< none: G49, D0; the programmed point is the spindle's gauge point
  other,   ///< a register that is not the loaded tool's (G43 H5 with T1), or no tool loaded yet
};

/// Whose length state `m` applies (H n is tool n's: the convention of Fanuc tool-change macros,
/// and LinuxCNC's own meaning of H).
inline tool_length length_in_effect(const modal_state& m) {
  if (!m.length_compensation) return tool_length::unsaid;
  if (!*m.length_compensation) return tool_length::off;
  if (!m.length_register || (m.active_tool && *m.length_register == *m.active_tool)) return tool_length::own;
  return tool_length::other;
}

/// The register of `m` and the tool loaded, for messages: `H5 while tool 1 is loaded`,
/// `H5 before any tool change`.
inline std::string length_register_text(const modal_state& m) {
  const std::string h = m.length_register ? "H" + std::to_string(*m.length_register) : "H";
  return h + (m.active_tool ? " while tool " + std::to_string(*m.active_tool) + " is loaded" : " before any tool change");
}

}  // namespace kin5::program
