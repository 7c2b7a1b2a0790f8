/// @file kinematics/tool_table.hpp
/// The lengths of a program's tools, as a controller's tool table or length-offset table holds
/// them: entry number → tool length (gauge point to tool tip, mm) and, optionally, radius (mm).
/// A program selects an entry with its tool change (`T5 M6`, `TOOL CALL 5`) or, where it names
/// one, its length register (`G43 H5`): the entry of that number. A tool table is read from a
/// file by `machines/tool_table_file.hpp`; the translation takes each block's length from it.
/// @code
///   kin5::tool_table tools;
///   tools.entries[1] = {.length_mm = 92.5};
///   tools.entries[7] = {.length_mm = 141.0, .radius_mm = 4.0};
///   if (const kin5::tool_entry* t = tools.find(7)) use(t->length_mm);  // 141.0
/// @endcode
#pragma once

#include <map>
#include <optional>

namespace kin5 {

/// One entry of a tool table.
struct tool_entry {
  double length_mm = 0.0;            ///< gauge point to tool tip, along the tool axis
  std::optional<double> radius_mm;   ///< the cutter's radius, when given (not used for motion)
};

/// Tool (or length-register) number → entry.
struct tool_table {
  std::map<long long, tool_entry> entries;

  /// The entry of number `n`, or null.
  const tool_entry* find(long long n) const {
    const auto it = entries.find(n);
    return it == entries.end() ? nullptr : &it->second;
  }
  bool empty() const { return entries.empty(); }
};

}  // namespace kin5
