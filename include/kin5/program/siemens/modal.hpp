/// @file program/siemens/modal.hpp
/// What a Siemens program leaves in effect from one block to the next, as far as reading and
/// writing 840D text need it: the motion word (G0–G3), the arc plane (G17–G19), the last
/// programmed X Y Z (arc centres are written relative to it), the program's name (M30 ends it),
/// the unit (G70/G700 inch) and the feed mode (G93 inverse time).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "../block.hpp"
#include "../incremental.hpp"

namespace kin5::program::siemens::detail {

/// The modal state of the reader, mirrored by the writer for the text it has written.
struct modal_state {
  std::optional<motion_kind> motion;
  arc_plane plane = arc_plane::xy;
  std::array<std::optional<double>, 3> position_mm;  ///< last programmed X Y Z (workpiece)
  std::optional<std::string> program_name;
  bool inch = false;          ///< G70 or G700 in effect: lengths in inches
  bool g70 = false;           ///< G70 in effect: lengths in inches, F in the control's basic system
  bool inverse_time = false;  ///< G93 in effect: F is 1/min, not a length
  std::optional<double> inverse_feed;  ///< the F given since G93 (the reader's): later feed moves take it
  std::optional<long long> edge;  ///< the active cutting edge: D n, or the one a tool change activates (the reader's)
  bool tool_loaded = false;       ///< a tool change has been read (the reader's)
  bool radius_on = false;         ///< G41/G42 in effect (the reader's)
  bool startup_pending = false;   ///< G41/G42 said without motion: the next move starts it up
  bool incremental = false;       ///< G91 in effect (the reader's)
  std::size_t incremental_line = 0;  ///< the line of that G91 (the reader's)
  bool written_incremental = false;  ///< the model's G91 in effect: a block kept G91 (the reader's)
  /// X Y Z (mm) A B C: the last programmed position with its decimals, for incremental words
  /// (the reader's; program/incremental.hpp), and the machine-coordinate line that made one
  /// unknown.
  std::array<std::optional<axis_position>, 6> last;
  std::array<std::size_t, 6> lost_line{};

  /// Takes block `b`'s axis words with the decimals each has (`reached`'s, for an inch word one
  /// more than written: a millimetre value).
  void reach(const block& b, const std::array<int, 6>& decimals) {
    const std::array<std::optional<double>, 6> given = {b.axes.x_mm, b.axes.y_mm, b.axes.z_mm,
                                                        b.axes.a_deg, b.axes.b_deg, b.axes.c_deg};
    for (std::size_t i = 0; i < 6; ++i) {
      if (!given[i]) continue;
      if (b.machine_coordinates) last[i].reset(), lost_line[i] = b.where.line;
      else last[i] = axis_position{*given[i], decimals[i]};
    }
  }

  /// Takes block `b`'s linear axis words (machine coordinates make them unknown).
  void move(const block& b) {
    const std::array<std::optional<double>, 3> given = {b.axes.x_mm, b.axes.y_mm, b.axes.z_mm};
    for (std::size_t i = 0; i < 3; ++i)
      if (given[i]) position_mm[i] = b.machine_coordinates ? std::nullopt : given[i];
  }
  /// The last programmed point, when all three coordinates are known.
  std::optional<vec3> position() const {
    if (!position_mm[0] || !position_mm[1] || !position_mm[2]) return std::nullopt;
    return vec3{*position_mm[0], *position_mm[1], *position_mm[2]};
  }
};

constexpr bool is_arc(std::optional<motion_kind> m) {
  return m == motion_kind::arc_cw || m == motion_kind::arc_ccw;
}

}  // namespace kin5::program::siemens::detail
