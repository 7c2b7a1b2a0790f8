/// @file translate/work_offset_map.hpp
/// Work offsets across dialects. A selection (`block::state.work_offset`) goes into the target
/// as itself when the target selects the same thing (same family, a number it writes: ISO G54
/// and Siemens G54 both select the control's first settable zero offset); otherwise only the
/// user's mapping says what it is on the target (`work_offset_map`, `--work-offset-map
/// G54=1,G55=2`: ISO G54 is preset 1 on a TNC), and without one the block is refused
/// (`work_offset_into`). `G54=` drops a selection knowingly (APT CL data select none).
/// @code
///   kin5::work_offset_map map;
///   if (!map.add("G54=1,G505=G54.1P3")) usage_error();
///   const auto t = kin5::work_offset_into({program::work_offset_family::g54, 1}, source_language,
///                                         output_language, map);   // t.written: preset 1
/// @endcode
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../program/dialect.hpp"
#include "../program/work_offsets.hpp"

namespace kin5 {

/// The user's mapping of work offsets (`--work-offset-map FROM=TO,…`): FROM and TO as
/// `program::parse_work_offset` reads them (`G54`, `G54.1P7`, `G505`, a preset number); an empty
/// TO drops the selection.
class work_offset_map {
 public:
  /// Adds the comma-separated entries of `entries`; false, nothing changed, when one is bad or
  /// maps a selection twice.
  bool add(std::string_view entries) {
    std::vector<std::pair<program::work_offset, std::optional<program::work_offset>>> added;
    for (;;) {
      const std::size_t comma = entries.find(',');
      const std::string_view entry = entries.substr(0, comma);
      const std::size_t eq = entry.find('=');
      if (eq == std::string_view::npos) return false;
      const auto from = program::parse_work_offset(entry.substr(0, eq));
      std::optional<program::work_offset> to;
      if (eq + 1 < entry.size() && !(to = program::parse_work_offset(entry.substr(eq + 1)))) return false;
      if (!from || target_of(*from)) return false;
      for (const auto& a : added)
        if (a.first == *from) return false;
      added.emplace_back(*from, to);
      if (comma == std::string_view::npos) break;
      entries.remove_prefix(comma + 1);
    }
    map_.insert(map_.end(), added.begin(), added.end());
    return true;
  }

  /// Empty when `w` is not mapped; else the selection written for it (empty: none).
  std::optional<std::optional<program::work_offset>> target_of(const program::work_offset& w) const {
    for (const auto& [from, to] : map_)
      if (from == w) return to;
    return std::nullopt;
  }
  bool empty() const { return map_.empty(); }

 private:
  std::vector<std::pair<program::work_offset, std::optional<program::work_offset>>> map_;
};

/// What a work-offset selection becomes in the target: the selection written (none when the
/// user drops it), or why it cannot be written.
struct work_offset_translation {
  std::optional<program::work_offset> written;
  std::string refusal;  ///< empty when it can be written
};

/// "G54 … G59, G54.1 P1 … G54.1 P300": the selections dialect `d` writes, in its spelling.
inline std::string work_offsets_written(program::dialect d) {
  std::string s;
  const program::capabilities can = program::capabilities_of(d);
  for (const program::work_offset_names& r : can.work_offsets) {
    if (r.first > r.last) continue;
    s += s.empty() ? "" : ", ";
    s += can.spelled({r.family, r.first});
    if (r.last != r.first) s += " … " + can.spelled({r.family, r.last});
  }
  return s;
}

/// `w` as `--work-offset-map` takes it: "G54", "G54.1P7", "7" (a preset); in the spelling of
/// dialect `d` when given ("G154P7" for Haas).
inline std::string map_key(const program::work_offset& w, std::optional<program::dialect> d = std::nullopt) {
  if (w.family == program::work_offset_family::preset) return std::to_string(w.number);
  std::string s;
  for (char c : d ? program::capabilities_of(*d).spelled(w) : program::spelling(w))
    if (c != ' ') s.push_back(c);
  return s;
}

/// Work offset `w` of a program in dialect `from` as written into dialect `to` (see the file
/// comment): the user's mapping when it names `w`, else `w` itself when `to` writes it.
inline work_offset_translation work_offset_into(const program::work_offset& w, program::dialect from,
                                                program::dialect to, const work_offset_map& map) {
  const program::capabilities can = program::capabilities_of(to);
  const std::string name = program::capabilities_of(from).spelled(w);
  if (const auto mapped = map.target_of(w)) {
    if (!*mapped || can.writes(**mapped)) return {*mapped, {}};
    return {std::nullopt, name + ": --work-offset-map gives " + can.spelled(**mapped) + ", which " +
                              std::string(program::name(to)) + " does not select"};
  }
  if (can.writes(w)) return {w, {}};
  const std::string written = work_offsets_written(to);
  return {std::nullopt,
          name + ": a work offset of " + std::string(program::name(from)) + " with no certain equivalent in " +
              std::string(program::name(to)) + (written.empty() ? " (it selects none)" : " (it selects " + written + ")") +
              "; --work-offset-map " + map_key(w, from) + "=... names the target's, or drops it with nothing after ="};
}

}  // namespace kin5
