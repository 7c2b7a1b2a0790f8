/// @file translate/tool_map.hpp
/// Tools called by name (Siemens `T="MILL_D10"`, Heidenhain `TOOL CALL "MILL_D10"`) across
/// dialects. Siemens and Heidenhain call tools by name (`capabilities::tool_names`), so a name
/// goes into them as itself. ISO, LinuxCNC and APT take a number: only the user's mapping says
/// which (`tool_map`, `--tool-map MILL_D10=7`), and without one the block is refused
/// (`tool_name_refusal`). A mapped name is a number from the source on (`numbered_tools`), for
/// every dialect and for the tool table (`--tool-table`) alike.
/// @code
///   kin5::tool_map tools;
///   if (!tools.add("MILL_D10=7")) usage_error();
///   std::optional<program::block> storage;
///   const program::block& b = kin5::numbered_tools(source_block, tools, storage);  // T7 for "MILL_D10"
/// @endcode
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "../program/block.hpp"
#include "../program/dialect.hpp"

namespace kin5 {

/// The user's tool numbers for tool names (`--tool-map NAME=N`, one entry per option).
class tool_map {
 public:
  /// Adds `NAME=N` (the name as the program writes it, N a whole number 0 … 99999999); false,
  /// nothing changed, when the entry is malformed or names a tool twice.
  bool add(std::string_view entry) {
    const std::size_t eq = entry.rfind('=');
    if (eq == std::string_view::npos || eq == 0 || eq + 1 == entry.size()) return false;
    const std::string_view digits = entry.substr(eq + 1);
    if (digits.size() > 8 || digits.find_first_not_of("0123456789") != std::string_view::npos) return false;
    long long n = 0;
    for (char c : digits) n = n * 10 + (c - '0');
    return numbers_.emplace(std::string(entry.substr(0, eq)), n).second;
  }

  /// The number given for tool `name`, if any.
  std::optional<long long> number_of(const std::string& name) const {
    const auto it = numbers_.find(name);
    return it == numbers_.end() ? std::nullopt : std::optional<long long>(it->second);
  }

  bool empty() const { return numbers_.empty(); }

 private:
  std::map<std::string, long long> numbers_;
};

/// Block `b` with a tool name the map numbers called by its number instead (kept in
/// `storage`); `b` itself when it names no mapped tool.
inline const program::block& numbered_tools(const program::block& b, const tool_map& map,
                                            std::optional<program::block>& storage) {
  if (!b.tool_name || map.empty()) return b;
  const std::optional<long long> n = map.number_of(*b.tool_name);
  if (!n) return b;
  storage = b;
  storage->tool = *n;
  storage->tool_name.reset();
  return *storage;
}

/// Why tool name `name`, read in dialect `from`, cannot be written into dialect `to` (empty:
/// it can).
inline std::string tool_name_refusal(const std::string& name, program::dialect from, program::dialect to) {
  if (program::capabilities_of(to).tool_names) return "";
  return "a tool called by name (\"" + name + "\") in " + std::string(program::name(from)) + " has no number in " +
         std::string(program::name(to)) + "; --tool-map " + name + "=N gives its number there";
}

}  // namespace kin5
