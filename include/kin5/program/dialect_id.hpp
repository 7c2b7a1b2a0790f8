/// @file program/dialect_id.hpp
/// What every dialect declares of itself, as data: what its writer can express
/// (`capabilities`) and the text that gives a file away as written in it (`marker`).
///
/// Each entry of `program::dialects` (program/dialect.hpp) carries one `capabilities` value and
/// an array of `marker`s; the translation asks the capabilities (can the target write G93? does it
/// need a separate circle-centre block?), and `guess_dialect` looks for the markers.
#pragma once

#include <array>
#include <string_view>

#include "work_offsets.hpp"

namespace kin5::program {

/// What a dialect's writer can express. Each flag is checked against the writer by the dialect
/// law suite: a capability that is false makes the writer refuse (or, for TCP switches, note) the
/// construct; one that is true writes it so that the dialect's reader reads it back.
struct capabilities {
  bool cl_data = false;            ///< cutter-location data: tool tip and tool axis, no machine axes (APT)
  bool inverse_time_feed = false;  ///< feed as 1 / block time (G93, FEDRAT/INVERS)
  bool tcp_switch = false;         ///< words that switch tool-tip tracking on and off (TRAORI, M128, G43.4)
  bool rotary_axis_words = false;  ///< A B C axis words
  bool tool_axis_vectors = false;  ///< a tool-axis vector in a motion block (A3=, TX, G43.5 I J K, GOTO/…,i,j,k)
  bool arcs = false;               ///< circular moves
  bool arc_centre_block = false;   ///< an arc's centre is a modal block of its own (Heidenhain CC)
  /// The work offsets its writer selects, each range in the dialect's own form (G54, G54.1 P n,
  /// G505, CYCL DEF 247 Q339=n); a selection in none of them is refused (docs/dialects/*.md).
  std::array<work_offset_names, 3> work_offsets{};

  /// Whether the writer selects work offset `w`.
  constexpr bool writes(const work_offset& w) const {
    for (const work_offset_names& r : work_offsets)
      if (r.holds(w)) return true;
    return false;
  }
};

/// Text only one dialect writes, as `guess_dialect` looks for it: an upper-case keyword matched
/// case-insensitively, either at the start of a block (after an optional block number) or as a
/// word anywhere in a line (not glued to a letter or digit before it, nor to a digit after it).
struct marker {
  enum class place { block_start, anywhere };
  std::string_view keyword;
  place where = place::anywhere;
};

}  // namespace kin5::program
