/// @file translate/options.hpp
/// What a translation is asked to do and what it gives back: `translate_options` in (feed
/// policy, setup transform, output dialect, and the `common_options` of every run: angle
/// tolerance, refusals allowed, output decimals); `translation` out (the output program, one `block_report` per motion
/// block, errors, warnings, allowed refusals and counts). `report_detail` says how many block
/// reports a long run keeps. Any error means the output must not be written.
/// @code
///   kin5::translate_options options;
///   options.feed = kin5::feed_policy::tcp;
///   options.output_dialect = kin5::program::parse_dialect("siemens");
///   const kin5::translation t = kin5::translate<From, To>(nc, options);
///   if (!t.ok()) for (const auto& e : t.errors) std::cerr << e.to_string() << '\n';
///   // t.per_class[direct], [other_branch], [unreachable]: motion blocks of each class
/// @endcode
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "../core/rigid.hpp"
#include "../core/units.hpp"
#include "../kinematics/forward.hpp"
#include "../kinematics/matchability.hpp"
#include "../kinematics/tool_table.hpp"
#include "../program/block.hpp"
#include "../program/dialect.hpp"
#include "../program/read_limits.hpp"
#include "allowances.hpp"
#include "diagnostic_list.hpp"
#include "feed.hpp"
#include "machine_output.hpp"
#include "m_codes.hpp"
#include "tool_map.hpp"
#include "work_offset_map.hpp"

namespace kin5 {

/// What every run takes, `translate`, `reverse` and `post` alike.
struct common_options {
  /// A rotary value this close to its axis' travel, or a tool axis this close (times the
  /// source's rotary axes) to the target's travel or reach, counts as on the edge. Empty: half a
  /// unit of the program's angular resolution (translate/angle_tolerance.hpp).
  std::optional<degrees> angle_tolerance;
  /// Named refusals turned into warnings (allowances.hpp).
  allowances allow;
  /// Decimals of every position word (linear and angle) in the output, overriding the source's
  /// resolution and the output dialect's limits (precision.hpp): rounding chosen knowingly.
  std::optional<int> digits;
  /// M functions renamed or dropped on the way into another dialect (m_codes.hpp).
  m_map m_codes;
  /// Where the part sits on the target and the tool length (`run_inputs`: the work offset,
  /// machine_T_work, and the tool length, mm). Given, every output block's slides X, Y, Z (G7)
  /// are checked against the target's linear travel, and a block past it is reported like an
  /// unreachable one, with the excess in mm. Not given: the linear axes are not checked.
  std::optional<run_inputs> placement;
  /// Work offsets mapped into another dialect's (work_offset_map.hpp).
  work_offset_map work_offsets;
  /// Tool numbers for tools the source calls by name (tool_map.hpp, `--tool-map`).
  tool_map tool_numbers;
  /// Where the part sat on the source and its tool length: given, motion without tool-tip
  /// tracking is read as machine coordinates and written as TCP (translate/untracked.hpp);
  /// not given, it is refused.
  std::optional<run_inputs> source_placement;
  /// How far (mm) the written tool-tip path may stray from the source's, where a block read as
  /// machine coordinates is cut into pieces because its rotary axes move.
  double tolerance_mm = 0.005;
  /// What the output's motion blocks say: the tool tip under TCP, or the target's axis values
  /// (machine_output.hpp; needs `placement`). Empty: what the output dialect does
  /// (`default_output_mode`). `tolerance_mm` also bounds the tip's path between such blocks.
  std::optional<output_mode> coordinates;
  /// Each tool's length by tool-table entry (`--tool-table`): where motion is read or written in
  /// machine coordinates, a block takes the length of the entry in effect, its length register
  /// else its tool (translate/tool_lengths.hpp). `placement`'s and `source_placement`'s
  /// `tool_length_mm` serve one tool without an entry, when the flags below say they were given.
  std::optional<tool_table> tools;
  /// Whether `placement` / `source_placement` give a tool length, not only a work offset.
  bool placement_has_length = true, source_placement_has_length = true;
  /// What the streaming driver reads of a program's text (`stream_text`): the file, line and
  /// words-per-line sizes, and no NUL byte (program/read_limits.hpp).
  program::read_limits limits;
};

/// How to translate.
struct translate_options {
  feed_policy feed = feed_policy::tcp;
  /// target_T_source; default: `default_setup<From, To>()`.
  std::optional<rigid_transform> setup;
  /// Empty: the dialect of the target machine's controller (`program::default_dialect`).
  std::optional<program::dialect> output_dialect;
  common_options common{};
};

/// The dialect a translation with `options` to machine `to_id` writes: the options', else the
/// one `to_id`'s controller reads, else the first of `program::dialects`.
constexpr program::dialect output_dialect_of(const translate_options& options, std::string_view to_id) {
  return options.output_dialect ? *options.output_dialect : program::default_dialect(to_id).value_or(program::dialect{});
}

/// What happened to one motion block.
struct block_report {
  program::source_location where;
  matchability match = matchability::direct;
  radians gap{};              ///< angle from the tool axis to the target's reach, when unreachable
  std::string source_angles;  ///< the source pose as written/modal, e.g. "A=-77.954 B=3.536" (degrees)
  std::string why;            ///< the reason, when not direct
  double linear_excess_mm = 0.0;  ///< how far a slide lies past its travel, when that is why
  /// The block's place among the motion blocks reported (from 0): consecutive unreachable blocks
  /// are grouped by it (run_report.hpp).
  std::size_t ordinal = 0;
  /// The calls open when the block ran (`block::call_chain`, an id into the reader's
  /// `read_result::calls`); 0: none.
  std::uint32_t call_chain = 0;
};

/// The result of `translate`, `reverse` or `post`.
struct translation {
  program::program output;                   ///< in the output dialect
  std::vector<block_report> reports;         ///< one per motion block, in program order
  diagnostic_list errors;    ///< any error: the output must not be written (the first 1,000 in source order held; `count()`)
  diagnostic_list warnings;  ///< e.g. a branch switch, a passed-through block (bounded as `errors`)
  /// Refusals the user allowed (`common_options::allow`): accepted knowingly, listed as warnings.
  std::vector<program::diagnostic> allowed;
  std::size_t blocks_read = 0, blocks_written = 0, passed_through = 0;
  /// Blocks written in addition to the program's: pieces of blocks read as machine coordinates
  /// whose rotary axes move (`blocks_written` counts them too).
  std::size_t blocks_added = 0;
  /// Motion blocks per matchability class, indexed by `matchability` (direct, other branch,
  /// unreachable): complete even when `reports` keeps only the exceptions.
  std::array<std::size_t, 3> per_class{};
  /// The angle tolerance the run used (`common_options::angle_tolerance` or the program's default).
  degrees angle_tolerance{};
  /// The decimals the output is to be written with (precision.hpp; `write_settings_for`).
  program::word_decimals output_decimals{};
  bool ok() const { return errors.empty(); }

  /// Refusal `d` (`d.construct` names it): an error, or an allowed construct when `allow` has
  /// its name.
  void refuse(program::diagnostic d, const allowances& allow) {
    // Not one `?:` over both: `allowed` is a vector and `errors` a diagnostic_list, so the
    // conditional would be a copy of the vector, and the error would be added to the copy.
    if (!d.construct.empty() && allow.allows(d.construct)) allowed.push_back(called(std::move(d)));
    else errors.push_back(std::move(d));
  }
};

/// Which block reports a translation keeps (`translation::per_class` counts them all anyway).
enum class report_detail {
  every_block,      ///< one report per motion block
  exceptions_only,  ///< only blocks that are not `matchability::direct`: constant memory
};

}  // namespace kin5
