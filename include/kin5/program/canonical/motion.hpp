/// @file program/canonical/motion.hpp
/// Canonical operations that move the axes, or say how: a block's circle data, rapid, linear
/// and circular moves, a move in the motion mode in effect, and a move in machine coordinates
/// or to a reference point.
///
/// A move holds the axis words its block writes (`axis_words`: X Y Z in mm, A B C in degrees,
/// absolute, an incremental word already resolved by the reader); an axis not written stays
/// where it is. A motion word without axis words (`G1` alone) is a move whose `to` is empty: it
/// sets the motion mode and moves nothing.
#pragma once

#include <optional>

#include "../block.hpp"
#include "origin.hpp"

namespace kin5::program::canonical {

/// Circle data in a block whose move is no arc: Heidenhain's CC (a centre that holds for the arcs
/// after it), or I J K / R beside a move in the arc mode in effect.
struct arc_data {
  static constexpr std::string_view kind_name = "arc_data";
  origin from;
  arc_words circle;
  friend bool operator==(const arc_data&, const arc_data&) = default;
};

/// G0, Heidenhain's `L … FMAX` (after its `rapid_feed`), APT's `GOTO` after `RAPID`: a straight
/// move at rapid traverse.
struct rapid_move {
  static constexpr std::string_view kind_name = "rapid_move";
  origin from;
  axis_words to;
  friend bool operator==(const rapid_move&, const rapid_move&) = default;
};

/// G1, L, GOTO: a straight move at the feed rate.
struct linear_move {
  static constexpr std::string_view kind_name = "linear_move";
  origin from;
  axis_words to;
  friend bool operator==(const linear_move&, const linear_move&) = default;
};

/// G2/G3, C DR-/DR+: a circular (or helical) move at the feed rate, in `circle`'s plane when the
/// block gives circle data, else in the plane and about the centre in effect.
struct arc_move {
  static constexpr std::string_view kind_name = "arc_move";
  origin from;
  bool clockwise = false;
  axis_words to;
  std::optional<arc_words> circle;
  friend bool operator==(const arc_move&, const arc_move&) = default;
};

/// Axis words without a motion word: a move in the motion mode in effect. `to` is never empty.
struct modal_move {
  static constexpr std::string_view kind_name = "modal_move";
  origin from;
  axis_words to;
  friend bool operator==(const modal_move&, const modal_move&) = default;
};

/// A move whose axis words are in machine coordinates, not the workpiece's (G53, SUPA, M91,
/// M92), or name a reference point's intermediate point (G28, G30), or none (M140 MB MAX):
/// `reference` says what they name (block.hpp), `motion` the block's motion word if it has one.
struct machine_move {
  static constexpr std::string_view kind_name = "machine_move";
  origin from;
  machine_position reference = machine_position::machine_zero;
  std::optional<motion_kind> motion;
  axis_words to;
  friend bool operator==(const machine_move&, const machine_move&) = default;
};

}  // namespace kin5::program::canonical
