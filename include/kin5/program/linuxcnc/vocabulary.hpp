/// @file program/linuxcnc/vocabulary.hpp
/// What the LinuxCNC reader and writer share beyond ISO's vocabulary (iso/vocabulary.hpp): the
/// dwells `G4 P` takes.
/// @code
///   kin5::program::dwell_refusal(kin5::program::linuxcnc::dwell_steps, 0.25);  // "": G4 P0.25
/// @endcode
#pragma once

#include "../dwell.hpp"

namespace kin5::program::linuxcnc {

/// The dwells LinuxCNC takes: P is a real number of seconds (LinuxCNC User Manual, "G-Codes",
/// G4; "G-code Overview", numbers), read and written with any decimals a source gives, to 6.
inline constexpr dwell_input dwell_steps{6, 1e9};

}  // namespace kin5::program::linuxcnc
