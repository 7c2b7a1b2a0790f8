/// @file program/apt/circle.hpp
/// APT circles as the reader takes them (docs/dialects/apt.md, "Circles"): `CIRCLE/xc,yc,zc,
/// i,j,k,r` comes after the GOTO of the arc's start and the next GOTO is its end (PTC Creo, "CL
/// Output for Circular Interpolation"). The plane vector is ±X, ±Y or ±Z and gives the plane and,
/// by the right-hand rule, the direction (+Z: XY, counter-clockwise seen from +Z). Start and end
/// lie on the circle within `circle_tolerance_mm`, measured in its plane (a rise along the vector
/// is a helix), and the tool axis stays. The end GOTO's block becomes the arc: `motion` arc_cw or
/// arc_ccw, `arc` {plane, centre}, its place and text from the CIRCLE on. A GOTO right after it
/// that ends elsewhere on the same circle is refused: a further point of the arc (Creo may write
/// several) or a straight move, the record cannot say; one along the vector only (a retract) is a
/// straight move. The writer takes `plane_vector` and
/// `radius_in_plane_mm` for the CIRCLE it writes.
/// @code
///   kin5::program::apt::detail::circle_state circles;
///   const auto c = circle_state::from(centre_mm, vector, radius_mm, start_mm, rapid_pending);
///   circles.hold(std::get<circle_state::circle>(c), statement, file);
///   if (const auto why = circles.end_at(goto_block, end_mm, axis_in_effect)) report(*why);
/// @endcode
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "../../core/vec.hpp"
#include "../block.hpp"
#include "../number.hpp"
#include "lexer.hpp"

namespace kin5::program::apt::detail {

/// How far (mm, in the circle's plane) a start or end point may lie off a CIRCLE's radius: ten
/// times what rounding to 3 decimals can move a point.
inline constexpr double circle_tolerance_mm = 0.005;

/// How far point `p_mm` lies from `centre_mm` in `plane` (its component along the normal dropped).
inline double radius_in_plane_mm(arc_plane plane, const vec3& centre_mm, const vec3& p_mm) {
  vec3 d = p_mm - centre_mm;
  (plane == arc_plane::xy ? d.z : plane == arc_plane::zx ? d.y : d.x) = 0.0;
  return norm(d);
}

/// The CIRCLE plane vector of an arc in `plane`: its normal (XY +Z, ZX +Y, YZ +X), the arc
/// counter-clockwise about it by the right-hand rule; the opposite vector when `clockwise`.
inline vec3 plane_vector(arc_plane plane, bool clockwise) {
  const vec3 n = plane == arc_plane::xy ? unit_z : plane == arc_plane::zx ? unit_y : unit_x;
  return clockwise ? -1.0 * n : n;
}

/// The CIRCLE waiting for the GOTO of its end, and the circle the last GOTO ended on.
class circle_state {
 public:
  struct circle {
    arc_plane plane = arc_plane::xy;
    bool clockwise = false;  ///< the plane vector is −X, −Y or −Z
    vec3 centre_mm{};
    double radius_mm = 0;
  };
  /// Where an error in the end GOTO lies: its major word or its i, j, k.
  enum where { at_goto, at_vector };
  /// An error: the argument it lies at (0: the statement) and why.
  using refusal = std::pair<std::size_t, std::string>;

  /// The circle of CIRCLE's values (mm), whose arc starts at `start_mm` (the last GOTO's point).
  static std::variant<circle, refusal> from(const vec3& centre_mm, const vec3& n, double radius_mm,
                                            const std::optional<vec3>& start_mm, bool rapid_pending) {
    circle c{arc_plane::xy, false, centre_mm, radius_mm};
    const double big = std::fmax(std::fabs(n.x), std::fmax(std::fabs(n.y), std::fabs(n.z)));
    const double along = big == std::fabs(n.z) ? n.z : big == std::fabs(n.y) ? n.y : n.x;
    if (std::fabs(big - 1.0) > 1e-6 || std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z) - big > 1e-6)
      return refusal{3, "CIRCLE plane vector is not along X, Y or Z (an arc outside a principal plane is not supported)"};
    c.plane = along == n.z ? arc_plane::xy : along == n.y ? arc_plane::zx : arc_plane::yz;
    c.clockwise = along < 0;
    if (!(radius_mm > 0)) return refusal{6, "CIRCLE radius must be greater than 0"};
    if (!start_mm) return refusal{0, "CIRCLE without a start point: no GOTO before it"};
    if (rapid_pending) return refusal{0, "CIRCLE after RAPID: an arc is a feed move"};
    if (const double off = off_circle_mm(c, *start_mm); off > circle_tolerance_mm)
      return refusal{0, "the GOTO before CIRCLE is " + format_number(off, 4) + " mm off its circle"};
    // the centre at the start's height along the normal, as Creo writes it
    (c.plane == arc_plane::xy ? c.centre_mm.z : c.plane == arc_plane::zx ? c.centre_mm.y : c.centre_mm.x) =
        c.plane == arc_plane::xy ? start_mm->z : c.plane == arc_plane::zx ? start_mm->y : start_mm->x;
    return c;
  }

  /// Holds circle `c`, read from statement `st`, for the next GOTO.
  void hold(const circle& c, const statement& st, const file_name& file) {
    held_ = c;
    held_at_ = st.at(file, 0);
    held_text_ = st.text;
    held_comment_ = st.has_comment ? std::optional<std::string>(st.comment) : std::nullopt;
  }

  /// GOTO block `b`, ending at `end_mm` with tool axis `axis` in effect before it: the arc of a
  /// held CIRCLE, or a move; why it is refused, if it is.
  std::optional<std::pair<where, std::string>> end_at(block& b, const vec3& end_mm, const vec3& axis) {
    const std::optional<circle> before = std::exchange(ended_, std::nullopt);
    if (!held_) {
      if (before && off_circle_mm(*before, end_mm) <= circle_tolerance_mm &&
          radius_in_plane_mm(before->plane, ended_at_mm_, end_mm) > circle_tolerance_mm)
        return std::pair{at_goto, std::string("GOTO ends on the circle of the CIRCLE before it: a further point of the "
                                              "arc or a straight move? (one CIRCLE for each GOTO of an arc)")};
      return std::nullopt;
    }
    const circle c = *std::exchange(held_, std::nullopt);
    b.where = held_at_;
    b.text = held_text_ + '\n' + b.text;
    if (held_comment_) b.comment = b.comment ? *held_comment_ + ' ' + *b.comment : *held_comment_;
    if (b.axes.tool_axis && norm(normalized(*b.axes.tool_axis) - normalized(axis)) > 1e-6)
      return std::pair{at_vector, std::string("the tool axis changes during the arc of CIRCLE (not supported)")};
    if (const double off = off_circle_mm(c, end_mm); off > circle_tolerance_mm)
      return std::pair{at_goto, "the GOTO after CIRCLE is " + format_number(off, 4) + " mm off its circle"};
    b.axes.tool_axis.reset();  // the axis in effect, unchanged
    b.motion = c.clockwise ? motion_kind::arc_cw : motion_kind::arc_ccw;
    b.arc = arc_words{c.plane, c.centre_mm, std::nullopt};
    ended_ = c;  // the circle through its end, whatever radius the CIRCLE said
    ended_->radius_mm = radius_in_plane_mm(c.plane, c.centre_mm, end_mm);
    ended_at_mm_ = end_mm;
    return std::nullopt;
  }

  /// A GOTO that could not be read: a held CIRCLE's error is the GOTO's own; nothing is held.
  void discard() { held_.reset(), ended_.reset(); }

  /// A statement other than GOTO, or the end of the text: a held CIRCLE has no end point.
  void interrupt(read_result& diagnostics) {
    ended_.reset();
    if (!held_) return;
    held_.reset();
    diagnostics.add_error({held_at_, "CIRCLE is not followed by the GOTO of its end point", "CIRCLE"});
  }

 private:
  std::optional<circle> held_;
  source_location held_at_;
  std::string held_text_;
  std::optional<std::string> held_comment_;
  std::optional<circle> ended_;
  vec3 ended_at_mm_{};  // where that arc ended

  /// How far point `p_mm` lies off circle `c`, in the circle's plane.
  static double off_circle_mm(const circle& c, const vec3& p_mm) {
    return std::fabs(radius_in_plane_mm(c.plane, c.centre_mm, p_mm) - c.radius_mm);
  }
};

}  // namespace kin5::program::apt::detail
