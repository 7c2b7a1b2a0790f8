/// @file program/canonical/modes.hpp
/// Canonical operations that set how the words after them are read: feed mode and feed rate,
/// working plane, length unit, work offset, distance mode.
#pragma once

#include "../block.hpp"
#include "../state_words.hpp"
#include "origin.hpp"

namespace kin5::program::canonical {

/// How F is read from here on: G94 per minute, G93 inverse time.
struct set_feed_mode {
  static constexpr std::string_view kind_name = "set_feed_mode";
  origin from;
  feed_unit mode = feed_unit::per_minute;
  friend bool operator==(const set_feed_mode&, const set_feed_mode&) = default;
};

/// F: millimetres per minute under `feed_unit::per_minute` (an inch program's converted), else
/// the inverse of the move's time in minutes.
struct set_feed_rate {
  static constexpr std::string_view kind_name = "set_feed_rate";
  origin from;
  double per_min = 0;
  friend bool operator==(const set_feed_rate&, const set_feed_rate&) = default;
};

/// FMAX, RAPID: the block's move runs at rapid traverse, not at the feed rate.
struct rapid_feed {
  static constexpr std::string_view kind_name = "rapid_feed";
  origin from;
  friend bool operator==(const rapid_feed&, const rapid_feed&) = default;
};

/// The working plane: G17/G18/G19, the TOOL CALL axis.
struct select_plane {
  static constexpr std::string_view kind_name = "select_plane";
  origin from;
  arc_plane plane = arc_plane::xy;
  friend bool operator==(const select_plane&, const select_plane&) = default;
};

/// The unit of lengths the program writes.
enum class length_unit {
  mm,    ///< G21, G71, G710, MM
  inch,  ///< G20, G70, G700, INCH (the operations hold millimetres all the same)
};

/// The program's text writes lengths in `unit` from here on.
struct use_length_units {
  static constexpr std::string_view kind_name = "use_length_units";
  origin from;
  length_unit unit = length_unit::mm;
  friend bool operator==(const use_length_units&, const use_length_units&) = default;
};

/// The work offset: G54 …, G54.1 P, G505 …, a Heidenhain preset.
struct select_work_offset {
  static constexpr std::string_view kind_name = "select_work_offset";
  origin from;
  work_offset offset;
  friend bool operator==(const select_work_offset&, const select_work_offset&) = default;
};

/// How axis words are read from here on: G90, G91.
struct set_distance_mode {
  static constexpr std::string_view kind_name = "set_distance_mode";
  origin from;
  distance_mode mode = distance_mode::absolute;
  friend bool operator==(const set_distance_mode&, const set_distance_mode&) = default;
};

}  // namespace kin5::program::canonical
