/// @file program/heidenhain/tcpm_options.hpp
/// The `FUNCTION TCPM` options kin5 reads and writes, one list for the reader and the writer:
/// `F TCP` (the feed is the tool tip's), `AXIS POS` (rotary words are axis positions) and
/// `PATHCTRL AXIS` (the rotary axes move linearly between blocks). Together they mean what M128
/// means, so kin5 writes either form for tool-tip tracking (HEIDENHAIN TNC7 User's Manual,
/// FUNCTION TCPM: docs/dialects/heidenhain.md, H3). `AXIS SPAT` and the other options change the
/// meaning of the rotary words or the feed, and the reader refuses them.
/// @code
///   if (!heidenhain::is_tcpm_option("F TCP")) …;
///   "FUNCTION TCPM " + heidenhain::tcpm_options_text   // "FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS"
/// @endcode
#pragma once

#include <algorithm>
#include <array>
#include <string_view>

namespace kin5::program::heidenhain {

/// Each option as a keyword and its value, in the order kin5 writes them.
inline constexpr std::array<std::string_view, 3> tcpm_options{"F TCP", "AXIS POS", "PATHCTRL AXIS"};

/// The options as one text, as the writer writes them after `FUNCTION TCPM `.
inline constexpr std::string_view tcpm_options_text = "F TCP AXIS POS PATHCTRL AXIS";

/// Whether `w` (a keyword and its value, one blank between) is one of `tcpm_options`.
constexpr bool is_tcpm_option(std::string_view w) {
  return std::find(tcpm_options.begin(), tcpm_options.end(), w) != tcpm_options.end();
}

static_assert(is_tcpm_option("AXIS POS") && !is_tcpm_option("AXIS SPAT"));
static_assert(tcpm_options_text == "F TCP AXIS POS PATHCTRL AXIS", "the options in the order of tcpm_options");

/// The whole switches as the writer spells them (`--tcp-word function-tcpm`).
inline constexpr const char* tcpm = "FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS";
inline constexpr const char* reset_tcpm = "FUNCTION RESET TCPM";
static_assert(std::string_view(tcpm).substr(14) == tcpm_options_text, "FUNCTION TCPM and its options");

}  // namespace kin5::program::heidenhain
