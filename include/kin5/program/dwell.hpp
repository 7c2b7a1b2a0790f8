/// @file program/dwell.hpp
/// How finely and how long a controller dwells (`state_words::dwell_s`: the axes hold still for
/// a time in seconds while spindle and coolant run on). Each dialect's `controller` has a
/// `dwell_input`: the decimals of a second it takes and its longest dwell; a dwell outside them
/// has no spelling there (`dwell_refusal`). The spellings, each in a block of its own: ISO
/// `G4 X1.5` or `G4 P1500`, LinuxCNC `G4 P1.5`, Siemens `G4 F1.5`, Heidenhain `CYCL DEF 9.0
/// DWELL TIME` then `CYCL DEF 9.1 DWELL 1.5`, APT `DELAY/1.5` (docs/dialects/*.md, with the
/// manuals). A dwell in spindle revolutions (Siemens `G4 S…`, Fanuc `G4` under G95) is refused
/// by the readers: its time depends on the spindle speed.
/// @code
///   constexpr kin5::program::dwell_input tnc{3, 3600.0};
///   kin5::program::dwell_refusal(tnc, 1.5);     // "": written as it is
///   kin5::program::dwell_refusal(tnc, 0.0005);  // "a dwell of 0.0005 s is not one … (… steps of 0.001 s)"
/// @endcode
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

namespace kin5::program {

/// The dwells a controller takes: whole steps of 10^-decimals s, from 0 to `longest_s`.
struct dwell_input {
  int decimals = 6;        ///< decimals of a second it reads
  double longest_s = 1e9;  ///< its longest dwell, seconds
};

/// `s` seconds as the messages write it: 12 significant digits, no trailing zeros ("1.5",
/// "3600.001", "1e-07").
inline std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", s);
  return buf;
}

/// Why a controller taking `in` (named `who` in the message) cannot dwell `s` seconds exactly
/// (negative, too long, or finer than its step); empty when it can.
inline std::string dwell_refusal(const dwell_input& in, double s, const std::string& who = "the controller") {
  const double steps = s * std::pow(10.0, in.decimals);
  const bool whole = std::abs(steps - std::round(steps)) <= 1e-6 * std::max(1.0, std::abs(steps));
  if (std::isfinite(s) && s >= 0 && s <= in.longest_s && whole) return "";
  const std::string step =
      in.decimals <= 0 ? "1" : "0." + std::string(static_cast<std::size_t>(in.decimals - 1), '0') + "1";
  return "a dwell of " + seconds_text(s) + " s is not one " + who + " takes (0 to " + seconds_text(in.longest_s) +
         " s in steps of " + step + " s)";
}

}  // namespace kin5::program
