/// @file program/modal.hpp
/// Modal state of an NC program: what stays in effect from one block to the next. A block
/// holds only its own words (block.hpp); a motion block's full pose is its words plus the modal
/// values of every axis it does not name.
///
/// Tracked: the last value of every axis (X Y Z in mm, A B C in degrees, the last tool-axis
/// vector), the motion mode (G0–G3, L, C), tool-tip tracking (TRAORI / M128 / G43.4) on or off,
/// the feed mode (G93/G94) and F, the arc plane and the last arc centre (Heidenhain CC), and the
/// machine state of `block::state` (tools, compensation, spindle, coolant, work offset, plane,
/// distance mode, units) with the rules in `apply_state`. Machine-coordinate moves (G53,
/// M91/M92) leave the workpiece position unknown: the axes they name are forgotten.
/// @code
///   kin5::program::modal_state state;
///   for (const auto& b : nc.blocks) {
///     const auto before = state;
///     state.apply(b);
///     if (kin5::program::is_motion(b)) use(before, state);   // from `before` to `state`
///   }
/// @endcode
#pragma once

#include <algorithm>
#include <optional>
#include <string>

#include "block.hpp"
#include "machine_functions.hpp"

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

  std::optional<long long> selected_tool;     ///< last T / TOOL CALL number (ISO: the next tool)
  std::optional<long long> active_tool;       ///< tool in the spindle after the last change
  std::optional<std::string> selected_tool_name;  ///< last tool selected by name (then no `selected_tool`)
  std::optional<std::string> active_tool_name;    ///< tool in the spindle, when called by name
  std::optional<spindle_axis> tool_spindle_axis;
  std::optional<bool> length_compensation;    ///< G43 … on, G49 off
  std::optional<long long> length_register;   ///< H in effect; empty: the active tool's own
  std::optional<cutter_side> radius_compensation;
  std::optional<long long> radius_register;   ///< D in effect; empty: the active tool's own
  std::optional<long long> cutting_edge;      ///< Siemens D
  std::optional<spindle_rotation> spindle;
  std::optional<double> spindle_rpm;          ///< S in effect (kept while the spindle is stopped)
  std::optional<bool> coolant_flood, coolant_mist;  ///< independent: M7 and M8 may both be on
  std::optional<kin5::program::work_offset> work_offset;
  std::optional<arc_plane> working_plane;
  std::optional<distance_mode> distance;
  std::optional<bool> metric;                 ///< the unit the program text uses
  bool ended = false;                         ///< a block has ended the program (M2, M30, END PGM, FINI)
  /// Inverse time: the F in effect has been used by a feed move; the next feed move needs its own.
  bool inverse_time_feed_used = false;

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
    apply_feed(b);
    if (b.motion) motion = *b.motion;
    if (feed_mode == feed_unit::inverse_time && moves_at_feed(b)) inverse_time_feed_used = true;
    apply_state(b);
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

  /// Whether block `b` moves the tool at the programmed feed (not rapid): a move that needs F.
  bool moves_at_feed(const block& b) const {
    const auto kind = motion_of(b);
    return b.moves() && !b.feed_rapid && kind && *kind != motion_kind::rapid;
  }

 private:
  /// F is modal per minute. Switching the feed mode drops it (a G94 after G93 needs a new F, as
  /// LinuxCNC's interpreter insists), and in inverse time each feed move uses its own F: once a
  /// feed move has run, no F is in effect until the next one is given.
  void apply_feed(const block& b) {
    if (inverse_time_feed_used) feed.reset(), inverse_time_feed_used = false;
    if (b.feed_mode && *b.feed_mode != feed_mode) feed.reset();
    if (b.feed_mode) feed_mode = *b.feed_mode;
    if (b.feed) feed = *b.feed;
  }

  /// Tools: T selects, a change loads the selected tool (the block's own T first). Turning a
  /// compensation on without a register means the active tool's own entry. Coolant flood and
  /// mist are independent (M9 writes both off). Everything else: the last value given.
  void apply_state(const block& b) {
    const state_words& s = b.state;
    if (b.tool) selected_tool = *b.tool, selected_tool_name.reset();
    if (b.tool_name) selected_tool_name = *b.tool_name, selected_tool.reset();
    if (changes_tool(b)) active_tool = selected_tool, active_tool_name = selected_tool_name;
    take_word(s.tool_spindle_axis, tool_spindle_axis);
    if (s.length_compensation == true && !s.length_register) length_register.reset();
    take_word(s.length_compensation, length_compensation);
    take_word(s.length_register, length_register);
    const bool radius_on = s.radius_compensation && *s.radius_compensation != cutter_side::off;
    if (radius_on && !s.radius_register) radius_register.reset();
    take_word(s.radius_compensation, radius_compensation);
    take_word(s.radius_register, radius_register);
    take_word(s.cutting_edge, cutting_edge);
    take_word(s.spindle, spindle);
    take_word(b.spindle_rpm, spindle_rpm);
    take_word(s.coolant_flood, coolant_flood);
    take_word(s.coolant_mist, coolant_mist);
    take_word(s.work_offset, work_offset);
    take_word(s.working_plane, working_plane);
    take_word(s.distance, distance);
    take_word(b.metric, metric);
    if (b.program_end) ended = true;
  }

  template <class T>
  static void take_word(const std::optional<T>& word, std::optional<T>& slot) {
    if (word) slot = *word;
  }
};

}  // namespace kin5::program
