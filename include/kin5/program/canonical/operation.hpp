/// @file program/canonical/operation.hpp
/// The canonical operations: a closed set of typed operations, each with its `origin` (the
/// block that caused it), lengths in millimetres, angles in degrees, times in seconds, speeds in
/// revolutions per minute, each unit in its member's name or type.
///
/// The alternatives of `operation` are listed in the order a control executes the words of one
/// block, and `operations_of` (block_operations.hpp) gives a block's operations in that order.
/// The order is LinuxCNC's (LinuxCNC User Manual, "G-code Overview", "G-code Order of
/// Execution"), with kin5's own operations put where they act:
///
/// | step | operations |
/// |---|---|
/// | the block itself | `block_start` (its number and text) |
/// | O words, the program's name | `begin_program` |
/// | comment, message | `comment`, `raise_alarm` (LinuxCNC's ABORT acts before the line's other words) |
/// | the block's text without motion | `framing`, `pass_through`, `parameter_assignment` |
/// | feed mode, feed rate | `set_feed_mode`, `set_feed_rate`, `rapid_feed` |
/// | spindle speed | `set_spindle_speed` |
/// | select tool, change tool | `select_tool`, `select_tool_by_name`, `change_tool`, `select_tool_axis`, `set_tool_oversize` (a Heidenhain TOOL CALL's axis and oversizes come with the tool) |
/// | spindle, coolant | `set_spindle`, `set_coolant` |
/// | user-defined M functions | `machine_function` |
/// | dwell | `dwell` |
/// | plane, length units | `select_plane`, `use_length_units` |
/// | radius and length compensation | `set_radius_compensation`, `set_length_compensation`, `select_cutting_edge`, `set_tool_tip_tracking` (G43.4 is a length compensation) |
/// | coordinate system | `select_work_offset` |
/// | path control and other modes | `kept_word` |
/// | distance mode | `set_distance_mode` |
/// | motion, as modified by G53 | `arc_data`, then one of `rapid_move`, `linear_move`, `arc_move`, `modal_move`, `machine_move` |
/// | stop, end | `stop`, `end_program` |
#pragma once

#include <cstddef>
#include <string_view>
#include <variant>

#include "machine.hpp"
#include "modes.hpp"
#include "motion.hpp"
#include "origin.hpp"
#include "text.hpp"
#include "tool.hpp"

namespace kin5::program::canonical {

/// One canonical operation; the alternatives in the order of execution (see the file comment).
using operation =
    std::variant<block_start, begin_program, comment, raise_alarm, framing, pass_through, parameter_assignment,
                 set_feed_mode, set_feed_rate, rapid_feed, set_spindle_speed, select_tool, select_tool_by_name,
                 change_tool, select_tool_axis, set_tool_oversize, set_spindle, set_coolant, machine_function, dwell,
                 select_plane, use_length_units, set_radius_compensation, set_length_compensation,
                 select_cutting_edge, set_tool_tip_tracking, select_work_offset, kept_word, set_distance_mode,
                 arc_data, rapid_move, linear_move, arc_move, modal_move, machine_move, stop, end_program>;

/// The number of kinds of operation.
inline constexpr std::size_t operation_kinds = std::variant_size_v<operation>;

/// The origin of `op`.
inline const origin& origin_of(const operation& op) {
  return std::visit([](const auto& o) -> const origin& { return o.from; }, op);
}

/// The name of `op`'s kind ("linear_move"): its type's name.
inline std::string_view name_of(const operation& op) {
  return std::visit([](const auto& o) { return o.kind_name; }, op);
}

/// Whether `op` moves the axes, or would with axis words: one of the moves of motion.hpp.
inline bool is_move(const operation& op) {
  return std::holds_alternative<rapid_move>(op) || std::holds_alternative<linear_move>(op) ||
         std::holds_alternative<arc_move>(op) || std::holds_alternative<modal_move>(op) ||
         std::holds_alternative<machine_move>(op);
}

}  // namespace kin5::program::canonical
