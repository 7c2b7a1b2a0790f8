/// @file program/program_name.hpp
/// The name a program gives itself, taken block by block: its first opening name (BEGIN PGM,
/// `O…`, `%_N_…_MPF`, PARTNO), else the name its end gives (a Heidenhain END PGM); "M2", "M30"
/// and an empty end name are end words, not names. What a dialect that names its program at the
/// top (Heidenhain's `BEGIN PGM name`) writes there when the source names it later or only at
/// its end.
#pragma once

#include <optional>
#include <string>

#include "block.hpp"

namespace kin5::program {

/// See the file comment: `take` each block in order, then read `name()`.
struct program_name {
  std::optional<std::string> begin;  ///< the first opening name
  std::optional<std::string> end;    ///< the last end that names the program

  void take(const block& b) {
    if (b.passthrough) return;
    if (!begin && b.program_begin) begin = b.program_begin;
    const std::optional<std::string>& e = b.program_end;
    if (e && !e->empty() && *e != "M2" && *e != "M30") end = e;
  }
  std::optional<std::string> name() const { return begin ? begin : end; }
};

/// The name program `p` gives itself (`program_name` over all its blocks), if any.
inline std::optional<std::string> name_of(const program& p) {
  program_name name;
  for (const block& b : p.blocks) name.take(b);
  return name.name();
}

}  // namespace kin5::program
