/// @file program/canonical/tool.hpp
/// Canonical operations of the tool: selection by number or name, change, the spindle axis and
/// oversizes of a Heidenhain tool call, length and radius compensation, Siemens cutting edge,
/// tool-tip tracking.
#pragma once

#include <optional>
#include <string>

#include "../state_words.hpp"
#include "origin.hpp"

namespace kin5::program::canonical {

/// T n, TOOL CALL n: tool `number` is the next one changed to.
struct select_tool {
  static constexpr std::string_view kind_name = "select_tool";
  origin from;
  long long number = 0;
  friend bool operator==(const select_tool&, const select_tool&) = default;
};

/// T="NAME", TOOL CALL "NAME": the tool by the name its tool table gives it.
struct select_tool_by_name {
  static constexpr std::string_view kind_name = "select_tool_by_name";
  origin from;
  std::string name;
  friend bool operator==(const select_tool_by_name&, const select_tool_by_name&) = default;
};

/// M6, TOOL CALL, LOADTL: the selected tool goes into the spindle.
struct change_tool {
  static constexpr std::string_view kind_name = "change_tool";
  origin from;
  friend bool operator==(const change_tool&, const change_tool&) = default;
};

/// The machine axis the tool points along (Heidenhain `TOOL CALL n Z`).
struct select_tool_axis {
  static constexpr std::string_view kind_name = "select_tool_axis";
  origin from;
  spindle_axis axis = spindle_axis::z;
  friend bool operator==(const select_tool_axis&, const select_tool_axis&) = default;
};

/// Heidenhain DL, DR in TOOL CALL: oversizes of the tool's length and radius. At least one is
/// given.
struct set_tool_oversize {
  static constexpr std::string_view kind_name = "set_tool_oversize";
  origin from;
  std::optional<double> length_delta_mm;
  std::optional<double> radius_delta_mm;
  friend bool operator==(const set_tool_oversize&, const set_tool_oversize&) = default;
};

/// G40/G41/G42 (R0/RL/RR, CUTCOM) and D n: the side of cutter radius compensation, the
/// register it takes the radius from (none: the active tool's own). At least one is given.
struct set_radius_compensation {
  static constexpr std::string_view kind_name = "set_radius_compensation";
  origin from;
  std::optional<cutter_side> side;
  std::optional<long long> register_number;
  friend bool operator==(const set_radius_compensation&, const set_radius_compensation&) = default;
};

/// G43/G49 (TOOL CALL, Siemens D) and H n: tool length compensation on or off, the register it
/// takes the length from (none: the active tool's own). At least one is given.
struct set_length_compensation {
  static constexpr std::string_view kind_name = "set_length_compensation";
  origin from;
  std::optional<bool> on;
  std::optional<long long> register_number;
  friend bool operator==(const set_length_compensation&, const set_length_compensation&) = default;
};

/// Siemens D n: cutting edge `number` of the active tool.
struct select_cutting_edge {
  static constexpr std::string_view kind_name = "select_cutting_edge";
  origin from;
  long long number = 0;
  friend bool operator==(const select_cutting_edge&, const select_cutting_edge&) = default;
};

/// Tool-tip tracking on (TRAORI, M128, G43.4) or off (TRAFOOF, M129, G49).
struct set_tool_tip_tracking {
  static constexpr std::string_view kind_name = "set_tool_tip_tracking";
  origin from;
  bool on = false;
  friend bool operator==(const set_tool_tip_tracking&, const set_tool_tip_tracking&) = default;
};

}  // namespace kin5::program::canonical
