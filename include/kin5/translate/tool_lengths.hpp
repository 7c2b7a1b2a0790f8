/// @file translate/tool_lengths.hpp
/// The tool length (mm) in effect at a block, for motion read or written in machine coordinates
/// (where the chain (G6) needs it): the tool-table entry of the length register in effect
/// (`G43 H n`, kept across tool changes as a controller keeps it), else of the tool in the
/// spindle (`T n M6`, `TOOL CALL n`). An entry the table lacks takes the one length given
/// (`--tool-length`), but for one entry only: a second tool with it would be a guess. No length
/// known is an error that names the tool and the option that gives it.
/// @code
///   kin5::translate_detail::tool_length_tracker lengths({table, 100.0}, "--source-tool-length");
///   std::string why;
///   const auto l = lengths.length_mm(kin5::translate_detail::length_entry(modal), why);  // empty: `why` says
/// @endcode
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "../kinematics/tool_table.hpp"
#include "../program/modal.hpp"

namespace kin5::translate_detail {

/// What a run knows of its tool lengths: a table by entry number, and one length for an entry
/// it lacks (one entry only).
struct tool_lengths {
  std::optional<tool_table> table;
  std::optional<double> single_mm;
};

/// The entry `length_entry` gives for a tool called by name: the table is by number, so it has
/// none (tool_map.hpp: `--tool-map` gives the name a number first).
inline constexpr long long named_tool_entry = -1;

/// The entry whose length is in effect in state `m`: the length register, else the active
/// tool (`named_tool_entry` for one called by name); empty before either is known (the tool
/// loaded before the program).
inline std::optional<long long> length_entry(const program::modal_state& m) {
  if (m.length_register) return m.length_register;
  return m.active_tool_name ? std::optional<long long>(named_tool_entry) : m.active_tool;
}

/// Answers, block after block, the tool length of the entry in effect.
class tool_length_tracker {
 public:
  tool_length_tracker() = default;
  /// `single_option`: the option that gives `lengths.single_mm` ("--tool-length", …).
  tool_length_tracker(tool_lengths lengths, std::string_view single_option)
      : lengths_(std::move(lengths)), single_option_(single_option) {}

  /// The length (mm) of entry `entry`; empty, with the reason in `why`, when it is not known.
  std::optional<double> length_mm(std::optional<long long> entry, std::string& why) {
    if (entry == named_tool_entry) {
      why = "the tool in effect is called by name, and tool lengths are by number; --tool-map NAME=N gives it one";
      return std::nullopt;
    }
    if (entry && lengths_.table)
      if (const tool_entry* t = lengths_.table->find(*entry)) return t->length_mm;
    if (lengths_.single_mm && (!single_for_ || *single_for_ == entry)) {
      single_for_ = entry;
      return lengths_.single_mm;
    }
    const std::string table = "--tool-table FILE";
    if (!lengths_.single_mm)
      why = entry ? "tool " + std::to_string(*entry) + " has no entry in the tool table: its length is not known; give "
                        "it in " + table
                  : "no tool change or length register before this motion: the tool length is not known; give " +
                        std::string(single_option_);
    else
      why = "tool " + (entry ? std::to_string(*entry) : std::string("loaded before the program")) + ": its length is not known (" +
            std::string(single_option_) + " gives one tool's, " +
            (*single_for_ ? "tool " + std::to_string(**single_for_) + "'s" : std::string("the tool loaded before the program's")) +
            "); give each tool's length in " + table;
    return std::nullopt;
  }

 private:
  tool_lengths lengths_;
  std::string_view single_option_;
  std::optional<std::optional<long long>> single_for_;  // the entry that took the single length
};

}  // namespace kin5::translate_detail
