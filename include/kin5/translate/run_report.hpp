/// @file translate/run_report.hpp
/// The account of one run, short enough to read whatever the program's length: the blocks the
/// target cannot reach grouped into runs of consecutive motion blocks (`unreachable_ranges`),
/// each with its worst block, so that 100,000 unreachable blocks in a row are one entry, not
/// 100,000. Two unreachable blocks are in one run when no reachable motion block lies between
/// them (`block_report::ordinal`); comments and other blocks between them do not split a run.
/// @code
///   for (const kin5::unreachable_range& r : kin5::unreachable_ranges(t.result().reports))
///     std::cerr << r.first.line << '-' << r.last.line << ": " << r.blocks << " blocks, worst "
///               << r.worst_gap.value << "° at line " << r.worst.line << '\n';
/// @endcode
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "../core/units.hpp"
#include "../kinematics/matchability.hpp"
#include "../program/block.hpp"
#include "options.hpp"

namespace kin5 {

/// A run of consecutive motion blocks the target cannot reach.
struct unreachable_range {
  program::source_location first, last;  ///< its first and last block
  std::size_t blocks = 0;                ///< how many blocks it holds
  degrees worst_gap{};                   ///< the largest angle from a tool axis to the target's reach
  double worst_excess_mm = 0.0;          ///< the largest distance a slide lies past its travel
  /// The worst block: the largest gap; where no block of the run has a gap, the largest excess.
  program::source_location worst;
  std::string worst_why;  ///< why the worst block cannot be reached (`block_report::why`)
};

/// Whether report `r` is worse than the worst of `range` so far: a larger gap, or no gap on
/// either side and a larger slide excess.
inline bool worse_than(const block_report& r, const unreachable_range& range) {
  const double gap_deg = to_degrees(r.gap).value;
  if (gap_deg != range.worst_gap.value) return gap_deg > range.worst_gap.value;
  return range.worst_gap.value == 0.0 && r.linear_excess_mm > range.worst_excess_mm;
}

/// The unreachable reports of `reports` (in program order, as a translation keeps them)
/// grouped into runs: a report joins the last run when its `ordinal` follows the run's last
/// block's directly.
inline std::vector<unreachable_range> unreachable_ranges(const std::vector<block_report>& reports) {
  std::vector<unreachable_range> ranges;
  std::size_t last_ordinal = 0;
  for (const block_report& r : reports) {
    if (r.match != matchability::unreachable) continue;
    if (ranges.empty() || r.ordinal != last_ordinal + 1) ranges.push_back({r.where, r.where, 0, {}, 0.0, r.where, r.why});
    unreachable_range& range = ranges.back();
    range.last = r.where;
    ++range.blocks;
    if (worse_than(r, range)) range.worst = r.where, range.worst_why = r.why;
    range.worst_gap = degrees{std::max(range.worst_gap.value, to_degrees(r.gap).value)};
    range.worst_excess_mm = std::max(range.worst_excess_mm, r.linear_excess_mm);
    last_ordinal = r.ordinal;
  }
  return ranges;
}

}  // namespace kin5
