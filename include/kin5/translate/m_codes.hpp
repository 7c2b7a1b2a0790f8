/// @file translate/m_codes.hpp
/// M functions across dialects. Outside a few numbers that DIN 66025 / ISO 6983 fix and every
/// kin5 dialect reads the same way, an M function means what the machine maker made it mean:
/// Heidenhain `M126` (shortest rotary path) or `M99` (cycle call) is a subprogram return on a
/// Fanuc control, `M13` is spindle and coolant on a TNC and a rotary lock on a Haas. So an M
/// code is written into a program of another dialect only when its meaning is shared
/// (`shared_m_code`) or the user maps it (`m_map`, `--m-map N=M` renames, `--m-map N=` drops it
/// knowingly); any other is refused at its word.
///
/// | M | meaning | carried between |
/// |---|---|---|
/// | 0, 1 | program stop, optional stop | every dialect |
/// | 2, 30 | program end | every dialect (the writers write one end) |
/// | 3, 4, 5 | spindle clockwise, counter-clockwise, stop | every dialect |
/// | 6 | tool change | every dialect (the Heidenhain writer makes it part of TOOL CALL) |
/// | 8, 9 | coolant on, off | every dialect |
/// | 7 | mist coolant | dialects whose controller reads M7 so (`controller::m7_mist_coolant`; a TNC has no standard M7) |
/// | 91, 92 | machine coordinates (`controller::m91_m92_machine_coordinates`: Heidenhain) | written as the target's machine-coordinate word |
/// @code
///   kin5::m_map map;
///   if (!map.add("126=")) usage_error();       // drop M126
///   const auto m = map.target_of(126);          // std::optional<std::optional<int>>: {nullopt}
///   if (!kin5::shared_m_code(13, source_dialect, output_dialect, false)) refuse();
/// @endcode
#pragma once

#include <charconv>
#include <vector>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "../program/block.hpp"
#include "../program/dialect.hpp"

namespace kin5 {

/// Whether M function `m` of a block in dialect `from` means the same in dialect `to` (see the
/// file comment); `machine_coordinates`: the block moves in machine coordinates.
constexpr bool shared_m_code(int m, program::dialect from, program::dialect to, bool machine_coordinates) {
  if (from == to) return true;
  switch (m) {
    case 0: case 1: case 2: case 3: case 4: case 5: case 6: case 8: case 9: case 30: return true;
    case 7: return program::controller_of(from).m7_mist_coolant && program::controller_of(to).m7_mist_coolant;
    case 91: case 92: return program::controller_of(from).m91_m92_machine_coordinates && machine_coordinates;
    default: return false;
  }
}

/// The user's mapping of M functions into another dialect (`--m-map N=M`, `--m-map N=`).
class m_map {
 public:
  /// Adds "N=M" (rename) or "N=" (drop); false, nothing changed, when `entry` is neither.
  bool add(std::string_view entry) {
    const auto eq = entry.find('=');
    if (eq == std::string_view::npos) return false;
    const auto from = number(entry.substr(0, eq));
    if (!from) return false;
    if (eq + 1 == entry.size()) {
      map_[*from] = std::nullopt;
      return true;
    }
    const auto to = number(entry.substr(eq + 1));
    if (!to) return false;
    map_[*from] = *to;
    return true;
  }
  /// Empty when `m` is not mapped; else the M function written for it (empty: none).
  std::optional<std::optional<int>> target_of(int m) const {
    const auto it = map_.find(m);
    if (it == map_.end()) return std::nullopt;
    return it->second;
  }
  bool empty() const { return map_.empty(); }

 private:
  std::map<int, std::optional<int>> map_;

  static std::optional<int> number(std::string_view s) {
    int v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || end != s.data() + s.size() || v < 0 || s.empty()) return std::nullopt;
    return v;
  }
};

/// Applies the user's mapping `map` to the M functions of block `b`, as it is written into a
/// program of another dialect: each number mapped is renamed or dropped, the unmapped ones stay.
/// A state word counts as its M function (tool change M6, spindle M3/M4/M5, coolant M7/M8/M9,
/// stop M0/M1; machine_functions.hpp): when the map names that number, the word becomes the
/// number the map gives, or nothing.
inline void map_m_codes(program::block& b, const m_map& map) {
  std::vector<int> out;
  const auto take = [&](bool says, int m, auto&& unsay) {
    if (!says) return;
    const auto t = map.target_of(m);
    if (!t) return;
    unsay();
    if (*t) out.push_back(**t);
  };
  program::state_words& s = b.state;
  take(s.tool_change, 6, [&] { s.tool_change = false; });
  if (s.spindle) {
    const int m = *s.spindle == program::spindle_rotation::clockwise ? 3
                : *s.spindle == program::spindle_rotation::counter_clockwise ? 4 : 5;
    take(true, m, [&] { s.spindle.reset(); });
  }
  take(s.coolant_flood == false && s.coolant_mist == false, 9, [&] { s.coolant_flood.reset(), s.coolant_mist.reset(); });
  take(s.coolant_mist == true, 7, [&] { s.coolant_mist.reset(); });
  take(s.coolant_flood == true, 8, [&] { s.coolant_flood.reset(); });
  if (s.stop) take(true, *s.stop == program::program_stop::stop ? 0 : 1, [&] { s.stop.reset(); });
  for (int m : b.m_codes) {
    const auto t = map.target_of(m);
    if (!t) out.push_back(m);
    else if (*t) out.push_back(**t);
  }
  b.m_codes = std::move(out);
}

}  // namespace kin5
