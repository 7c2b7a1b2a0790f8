/// @file program/apt/vocabulary.hpp
/// Which APT statements the reader may pass on without reading them: a whitelist. A statement
/// passes (`passthrough`: written back in APT, a comment in any other dialect) only when it is
/// known to describe the program without changing the motion; every other statement that the
/// reader does not read into the model is refused at its major word, with the reason
/// (`refusal`), so a post never writes a program that means something else than its CL data.
/// @code
///   if (described("CUTTER", "10,0.5")) b.passthrough = true;
///   else error(major_at, refusal("CYCLE", "DRILL,FEDTO,2"));  // "CYCLE/DRILL: fixed cycles …"
/// @endcode
#pragma once

#include <string>
#include <string_view>

#include "../dwell.hpp"
#include "../lexing.hpp"

namespace kin5::program::apt::detail {

/// The most decimals of a FEDRAT or SPINDL value written (CL data has no controller to limit
/// them; one more for a feed in inches): the writer's finest, and the reader refuses a rate
/// these cannot write back (`unwritable_rate`).
inline constexpr int finest_rate_decimals = 6;

/// The dwells `DELAY/t` writes: seconds, with any decimals a source gives, to 6 (CL data has no
/// controller to limit them).
inline constexpr dwell_input dwell_steps{6, 1e9};

/// Whether statement `major`/`tail` only describes the program (tool, post, display) and
/// changes no motion: `CUTTER` and `TLDATA` (the tool's shape; CL points are already tool-tip
/// points), `TPRINT`, `MACHIN`, `CLPRNT`, `PAINT`, NX's `TOOL PATH/…` header and `END-OF-PATH`.
/// (`MULTAX` and `SELECT/TOOL` are read: reader.hpp.)
inline bool described(std::string_view major, std::string_view tail) {
  const std::string rest = lexing::upper(tail);
  if (major == "TOOL") return rest.rfind("PATH", 0) == 0;
  if (major == "END") return rest == "-OF-PATH";
  return major == "CUTTER" || major == "TLDATA" || major == "TPRINT" || major == "MACHIN" || major == "CLPRNT" ||
         major == "PAINT";
}

/// The first argument of `tail` (up to a comma), upper case: `DRILL` of `DRILL,FEDTO,2`.
inline std::string first_argument(std::string_view tail) {
  return lexing::upper(lexing::trim(tail.substr(0, tail.find(','))));
}

/// Why statement `major`/`tail`, neither read nor `described`, is refused.
inline std::string refusal(std::string_view major, std::string_view tail) {
  const std::string m(major);
  const std::string first = first_argument(tail);
  const std::string named = first.empty() ? m : m + "/" + first;
  if (m == "CYCLE")
    return named + ": fixed cycles are not supported (the points that follow would be holes made by the cycle, "
                   "not positions to feed to)";
  if (m == "INSERT") return "INSERT: text a post copies into the NC program as code; its effect cannot be known";
  if (m == "TLAXIS") return "TLAXIS: a tool-axis statement is not supported (it tilts the tool for the GOTOs that follow)";
  if (m == "CUTCOM") return named + ": cutter radius compensation is not supported in CL data yet";
  if (m == "DELAY") return named + ": only DELAY/t, a dwell of t seconds, is read (a dwell in revolutions depends on the "
                                   "spindle speed)";
  if (m == "DWELL") return "DWELL: not an APT dwell kin5 reads (DELAY/t is)";
  if (m == "CSYS" || m == "MSYS")
    return m + ": a coordinate system other than the identity is not supported (the points that follow are in "
               "another frame)";
  if (m == "ORIGIN" || m == "TRANS" || m == "TRACUT" || m == "COPY" || m == "INDEX" || m == "TRNTYP")
    return named + ": a transformation of the points that follow is not supported";
  if (m == "LOAD") return named + ": only LOAD/TOOL,n (a tool change) is read";
  if (m == "SELECT") return named + ": only SELECT/TOOL,n (a tool made ready) is read";
  return "APT statement " + m +
         " is not supported: only statements known not to change the motion are passed on";
}

}  // namespace kin5::program::apt::detail
