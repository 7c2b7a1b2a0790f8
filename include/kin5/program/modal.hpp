/// @file program/modal.hpp
/// Modal state of an NC program: what stays in effect from one block to the next. A block
/// holds only its own words (block.hpp); a motion block's full pose is its words plus the modal
/// values of every axis it does not name.
///
/// Tracked: the last value of every axis (X Y Z in mm, A B C in degrees, the last tool-axis
/// vector), the motion mode (G0–G3, L, C), tool-tip tracking (TRAORI / M128 / G43.4) on or off,
/// the feed mode (G93/G94) and F, the arc plane and the last arc centre (Heidenhain CC).
/// Machine-coordinate moves (G53, M91/M92) leave the workpiece position unknown: the axes they
/// name are forgotten.
/// @code
///   kin5::program::modal_state state;
///   for (const auto& b : nc.blocks) {
///     const auto before = state;
///     state.apply(b);
///     if (kin5::program::is_motion(b)) use(before, state);   // from `before` to `state`
///   }
/// @endcode
#pragma once

#include <optional>

#include "block.hpp"

namespace kin5::program {

/// Whether `b` moves the tool in the workpiece frame: it has axis words, not in machine
/// coordinates.
inline bool is_motion(const block& b) { return b.moves() && !b.machine_coordinates; }

/// Whether motion kind `k` is a circular move (G2/G3, C DR±).
inline bool is_arc(motion_kind k) { return k == motion_kind::arc_cw || k == motion_kind::arc_ccw; }

/// The state in effect after the blocks applied so far.
struct modal_state {
  std::optional<double> x_mm, y_mm, z_mm;     ///< last linear positions, workpiece frame
  std::optional<double> a_deg, b_deg, c_deg;  ///< last rotary positions, as commanded
  /// Last tool-axis vector written (unit), while no rotary word has come after it.
  std::optional<vec3> tool_axis;
  std::optional<motion_kind> motion;          ///< G0/G1/G2/G3 (L, C) in effect
  bool tcp = false;                           ///< tool-tip tracking on
  feed_unit feed_mode = feed_unit::per_minute;
  std::optional<double> feed;                 ///< F in effect, in `feed_mode`'s unit
  std::optional<arc_plane> plane;             ///< plane of the last arc or centre
  std::optional<vec3> arc_centre_mm;          ///< last centre (Heidenhain CC is modal)
  bool rotary_moved = false;                  ///< some rotary axis has been programmed

  /// The last value of axis `letter` (X Y Z A B C, upper case), if known.
  std::optional<double> value(char letter) const {
    switch (letter) {
      case 'X': return x_mm;
      case 'Y': return y_mm;
      case 'Z': return z_mm;
      case 'A': return a_deg;
      case 'B': return b_deg;
      case 'C': return c_deg;
      default: return std::nullopt;
    }
  }

  /// The motion mode block `b` runs in: its own, else the modal one.
  std::optional<motion_kind> motion_of(const block& b) const { return b.motion ? b.motion : motion; }

  /// Updates the state with block `b`'s words.
  void apply(const block& b) {
    if (b.tcp) tcp = *b.tcp;
    if (b.feed_mode) feed_mode = *b.feed_mode;
    if (b.feed) feed = *b.feed;
    if (b.motion) motion = *b.motion;
    if (b.arc) {
      plane = b.arc->plane;
      if (b.arc->centre_mm) arc_centre_mm = *b.arc->centre_mm;
    }
    const axis_words& w = b.axes;
    if (b.machine_coordinates) {  // positions in another frame: the workpiece values are lost
      auto forget = [](const std::optional<double>& word, std::optional<double>& slot) {
        if (word) slot.reset();
      };
      forget(w.x_mm, x_mm), forget(w.y_mm, y_mm), forget(w.z_mm, z_mm);
      forget(w.a_deg, a_deg), forget(w.b_deg, b_deg), forget(w.c_deg, c_deg);
      if (w.has_rotary()) tool_axis.reset(), rotary_moved = true;
      return;
    }
    auto take = [](const std::optional<double>& word, std::optional<double>& slot) {
      if (word) slot = *word;
    };
    take(w.x_mm, x_mm), take(w.y_mm, y_mm), take(w.z_mm, z_mm);
    take(w.a_deg, a_deg), take(w.b_deg, b_deg), take(w.c_deg, c_deg);
    if (w.has_rotary()) tool_axis.reset(), rotary_moved = true;
    if (w.tool_axis) tool_axis = normalized(*w.tool_axis);
  }
};

}  // namespace kin5::program
