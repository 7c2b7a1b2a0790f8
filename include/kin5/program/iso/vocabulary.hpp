/// @file program/iso/vocabulary.hpp
/// ISO / Fanuc G codes as the reader and the writer name them: a G code as ten times its value
/// (G43.4 → 434), the codes kin5 keeps as written because they change no geometry, and what a
/// Fanuc-style controller reads (`fanuc_reads`, which Haas's builds on).
#pragma once

#include <cmath>

#include "../dialect_id.hpp"
#include "../dwell.hpp"

namespace kin5::program::iso::detail {

/// The most decimals of a feed or spindle speed (F, S) the controller reads (input setting unit
/// IS-C, Mitsubishi M700V Programming Manual §2.1; one more for an inch feed per minute): the
/// writer's finest, and the reader refuses a rate these cannot write back (`unwritable_rate`).
inline constexpr int finest_rate_decimals = 3;

/// The dwells an ISO / Fanuc control takes with `G4 X`: seconds with 3 decimals, up to
/// 9999.999 s, within the range of both increment systems (IS-B 0.001 to 99999.999 s, IS-C
/// 0.0001 to 9999.9999 s: SINUMERIK ISO Milling 04/2007 §3.3.1, Table 3-7).
inline constexpr dwell_input dwell_steps{3, 9999.999};

/// What a Fanuc-style controller reads: increment system IS-C (Mitsubishi M700V §2.1; IS-B
/// rounds the 4th); `( … )` are comments; S is no decimal-point address (M700V §5.3): a whole
/// number; G4 X dwells (`dwell_steps`).
inline constexpr controller fanuc_reads{.usual = {3, 3, 1, 7}, .finest = {4, 4, 3, 7}, .paren_comments = true,
                                        .whole_spindle_speed = true, .dwell = dwell_steps};

/// G code as ten times its value (G43.4 → 434), or -1 if not a multiple of 0.1.
inline int g_code(double v) {
  const double t = std::round(v * 10);
  return (std::abs(v * 10 - t) < 1e-6 && t >= 0 && t < 100000) ? static_cast<int>(t) : -1;
}

/// G codes kept as written: they change no geometry (times ten). G17–G19, G40, G90 and the
/// dwell G4 are read into the block's state instead.
inline bool kept_g(int g) {
  switch (g) {
    case 50: case 51: case 80: case 131: case 150:
    case 500: case 501:
    case 610: case 611: case 640: case 690: case 800: case 980: case 990:
      return true;
    default:
      return false;
  }
}

}  // namespace kin5::program::iso::detail
