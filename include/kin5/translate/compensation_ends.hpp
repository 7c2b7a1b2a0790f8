/// @file translate/compensation_ends.hpp
/// Where cutter radius compensation is switched on and off between two controls that start and
/// end it differently: LinuxCNC ends the entry move with the tool perpendicular to the *entry*
/// line at its end point; ISO/Fanuc (type A), the 840D (`NORM`) and the TNC with the tool
/// perpendicular to the *contour's first element* there. The two points coincide when the entry
/// runs straight on into the first element, and so do the exits when the exit move runs straight
/// on from the last element (docs/dialects/compensation.md, "Entry and exit between LinuxCNC and
/// the others"). `compensation_ends` follows a program block by block and names the first
/// start-up or cancel that does not:
///
///     entry ∥ first element:  t_entry · t_first > 0  and  |t_entry × t_first| ≤ √2·δ·(1/L_entry + 1/L_first)
///
/// t: unit XY directions (a straight move's chord, an arc's tangent at the point), L: the
/// lengths they are measured over (chord, radius), δ: the unit of the last decimal written, so
/// that directions collinear before their points were rounded pass. Points in millimetres, in
/// the source workpiece frame.
/// @code
///   kin5::translate_detail::compensation_ends ends;
///   if (auto why = ends.follow(b, side_before, side_after, moved, says_nothing(b), delta_mm))
///     report(*why);  // a diagnostic at the block that switched compensation, naming the reason
/// @endcode
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "../core/math.hpp"
#include "../core/vec.hpp"
#include "../program/block.hpp"
#include "../program/program_end.hpp"
#include "arc_plane.hpp"

namespace kin5::translate_detail {

/// A direction in the XY plane (unit, z = 0) and the length (mm) it was measured over: how far
/// apart the points that give it are, which bounds what their rounding can turn it by.
struct planar_direction {
  vec3 unit;
  double length_mm = 0.0;
};

/// One move as compensation sees it: from `start_mm` to `end_mm`, straight or along `arc`.
struct planar_move {
  std::optional<vec3> start_mm;  ///< none: not known (the program's first move)
  vec3 end_mm;
  const arc_path* arc = nullptr;  ///< null: a straight move (G0, G1, L)
};

/// The XY direction of move `m` at its start (`at_end` false) or its end: a straight move's
/// chord, an arc's tangent there (about +Z: G3 turns counter-clockwise, G2 clockwise). None when
/// the move does not move in XY (shorter than 1e-9 mm there), or its arc is not in XY or has no
/// centre, or its start is not known.
inline std::optional<planar_direction> xy_direction(const planar_move& m, bool at_end) {
  constexpr double shortest_mm = 1e-9;
  if (!m.start_mm) return std::nullopt;
  const vec3& start_mm = *m.start_mm;
  if (!m.arc) {
    const vec3 chord{m.end_mm.x - start_mm.x, m.end_mm.y - start_mm.y, 0.0};
    const double length_mm = norm(chord);
    if (!(length_mm > shortest_mm)) return std::nullopt;
    return planar_direction{(1.0 / length_mm) * chord, length_mm};
  }
  if (m.arc->plane != program::arc_plane::xy) return std::nullopt;
  const auto centre_mm = arc_centre_mm(*m.arc, start_mm, m.end_mm);
  if (!centre_mm) return std::nullopt;
  const vec3& at_mm = at_end ? m.end_mm : start_mm;
  const vec3 radial{at_mm.x - centre_mm->x, at_mm.y - centre_mm->y, 0.0};
  const double radius_mm = norm(radial);
  if (!(radius_mm > shortest_mm)) return std::nullopt;
  const vec3 counter_clockwise = cross(unit_z, radial);  // +Z × radial: the sense of G3
  return planar_direction{(m.arc->clockwise ? -1.0 : 1.0) / radius_mm * counter_clockwise, radius_mm};
}

/// Whether `after` runs straight on from `before`: the same sense, and the sine of the angle
/// between them at most what rounding each point to `delta_mm` (the unit of the last decimal
/// written: an error of at most δ/2 per coordinate, δ/√2 per point) can turn each direction by,
/// √2·δ/L, the length L over which it was measured.
inline bool runs_straight_on(const planar_direction& before, const planar_direction& after, double delta_mm) {
  const double sine = math::abs(cross(before.unit, after.unit).z);
  const double rounding = std::sqrt(2.0) * delta_mm * (1.0 / before.length_mm + 1.0 / after.length_mm);
  return dot(before.unit, after.unit) > 0.0 && sine <= rounding + 1e-12;
}

/// Follows the start-ups and cancels of cutter radius compensation through a program, for a
/// translation between controls whose entry moves differ: an entry move (the first move at or
/// after the switch-on) must be straight and run straight on into the next move, the contour's
/// first element; an exit move (the first move at or after the switch-off) must be straight
/// and run straight on from the last compensated move. Between a switch and its move, and
/// between the entry and the first element, only blocks that say nothing may stand.
class compensation_ends {
 public:
  /// A refusal: the block that switched compensation, and why (the reason alone, without the
  /// pair of controls).
  struct refusal {
    program::source_location where;
    std::string reason;
  };

  /// Follows block `b`: the side in effect before it (`was`) and after it (`now`), its move if
  /// it is a motion (`moved`), whether it says nothing that acts (`quiet`), and the unit of the
  /// last decimal of its points (`delta_mm`). A refusal for the first start-up or cancel it
  /// shows to differ, once.
  std::optional<refusal> follow(const program::block& b, program::cutter_side was, program::cutter_side now,
                                const std::optional<planar_move>& moved, bool quiet, double delta_mm) {
    const auto refuse = [&](std::string reason) {
      std::optional<refusal> r = refusal{switch_at_, std::move(reason)};
      awaiting_ = awaiting::nothing, last_end_.reset();
      return r;
    };
    const auto line = [&] { return "line " + std::to_string(b.where.line); };
    const bool off = now == program::cutter_side::off;
    const bool switched_on = b.state.radius_compensation && !off;
    const bool switched_off = off && was != program::cutter_side::off;
    if (switched_on && (was != program::cutter_side::off || awaiting_ == awaiting::exit)) {
      if (was != program::cutter_side::off) switch_at_ = b.where;
      return refuse(was != program::cutter_side::off
                        ? "switched on again while on (LinuxCNC refuses G41/G42 under compensation: G40 first)"
                        : "switched on again (" + line() + ") before the exit move");
    }
    if (awaiting_ == awaiting::first_element && switched_off)
      return refuse("switched off (" + line() + ") before the contour's first element");
    if (awaiting_ != awaiting::nothing && !moved && !quiet && !(awaiting_ == awaiting::entry && switched_off))
      return refuse(line() + " stands between the switch and its move; only blocks that say nothing may stand there");
    if (awaiting_ == awaiting::first_element && moved) {
      const auto first = xy_direction(*moved, false);
      if (!first)
        return refuse("the contour's first element (" + line() +
                      ") does not move in the XY plane, so the controls would end the entry move differently");
      if (!runs_straight_on(entry_, *first, delta_mm))
        return refuse("the entry move is not collinear with the contour's first element (" + line() +
                      "): one control ends it tangent to the entry line, the other at the contour's start, so the "
                      "approach would cut differently");
      awaiting_ = awaiting::nothing;
    }
    if (switched_on || (awaiting_ == awaiting::entry && moved && !switched_off)) {
      if (switched_on) switch_at_ = b.where;
      awaiting_ = awaiting::entry;
      if (moved) {
        if (moved->arc)
          return refuse("the entry move is an arc; only a straight entry collinear with the contour's first element "
                        "starts compensation alike on both");
        const auto entry = xy_direction(*moved, false);
        if (!entry) return refuse("the entry move's direction is not known (no motion in XY, or no start point)");
        entry_ = *entry, awaiting_ = awaiting::first_element;
      }
    } else if (switched_off) {
      switch_at_ = b.where;
      // Switched on and off again with no move between: nothing was cut compensated.
      awaiting_ = awaiting_ == awaiting::entry ? awaiting::nothing : awaiting::exit;
    }
    if (awaiting_ == awaiting::exit && moved) {
      if (moved->arc)
        return refuse("the exit move is an arc; only a straight exit collinear with the contour's last element ends "
                      "compensation alike on both");
      const auto exit = xy_direction(*moved, false);
      if (!last_end_ || !exit)
        return refuse("the direction of the exit move (" + line() +
                      ") or of the contour's last element is not known (no motion in XY)");
      if (!runs_straight_on(*last_end_, *exit, delta_mm))
        return refuse("the exit move (" + line() +
                      ") is not collinear with the contour's last element: the controls leave the contour from "
                      "different points, so the departure would cut differently");
      awaiting_ = awaiting::nothing;
    }
    if (moved) {
      if (off) last_end_.reset();
      else last_end_ = xy_direction(*moved, true);
    }
    return std::nullopt;
  }

  /// Forgets what it follows: after a block that failed, whose move is not known.
  void reset() { awaiting_ = awaiting::nothing, last_end_.reset(); }

 private:
  enum class awaiting { nothing, entry, first_element, exit };
  awaiting awaiting_ = awaiting::nothing;
  program::source_location switch_at_{};     // the block that switched compensation on or off
  planar_direction entry_{};                 // the entry move's direction, awaiting the first element
  std::optional<planar_direction> last_end_;  // the last compensated move's direction at its end
};

/// Whether block `b` says nothing that acts: only its number, comment, a parameter's assignment
/// or the program's tape frame. As `program::without_effect`, with an assignment, but not a
/// program end or text not understood (which may act on the source control).
inline bool says_nothing(const program::block& b) {
  if (b.program_end || b.passthrough) return false;
  program::block rest = b;
  rest.assignment = false;
  return program::without_effect(rest);
}

}  // namespace kin5::translate_detail
