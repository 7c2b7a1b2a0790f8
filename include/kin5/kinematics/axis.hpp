/// @file axis.hpp
/// One machine axis as data. A linear axis: its NC letter, the side it moves, its direction and
/// travel in mm. A rotary axis: its NC letter, where it is mounted, its line (a point and a
/// direction), how a commanded angle relates to the rotation of the tool relative to the
/// workpiece, and its travel.
///
/// Sign convention (docs/theory.md, "Commanded angles"): ψ is the right-handed rotation *of the tool relative to the
/// workpiece* about `direction`. For a head axis ψ is the physical rotation. For a table axis
/// ψ = −φ, φ being the physical right-handed rotation of the table. A controller that programs
/// ISO tool-relative angles writes ψ itself (`angle_sense::tool_relative`); one that programs
/// physical table angles writes φ (`angle_sense::physical`).
#pragma once

#include <optional>
#include <string_view>

#include "../core/units.hpp"
#include "../core/vec.hpp"

namespace kin5 {

/// The NC address letter of an axis; `none` marks an unused rotary slot of a 4-axis machine.
enum class axis_letter : char { none = '\0', X = 'X', Y = 'Y', Z = 'Z', A = 'A', B = 'B', C = 'C' };

constexpr char to_char(axis_letter l) { return static_cast<char>(l); }

/// Which side of the kinematic chain carries the axis.
enum class mount { head, table };

/// How the value written in the NC program relates to ψ (see the file comment).
enum class angle_sense { tool_relative, physical };

/// Travel of a rotary axis, in degrees as a machine's manual gives it.
struct rotary_travel {
  degrees lower{-180.0};
  degrees upper{180.0};
  bool continuous = false;  ///< endless rotation; lower/upper are ignored

  static constexpr rotary_travel endless() { return {{-180.0}, {180.0}, true}; }
  static constexpr rotary_travel between(degrees lo, degrees hi) { return {lo, hi, false}; }

  /// Whether the commanded angle lies within the travel, with `slack` for rounding.
  constexpr bool contains(radians commanded, radians slack = {1e-12}) const {
    if (continuous) return true;
    return commanded.value >= to_radians(lower).value - slack.value &&
           commanded.value <= to_radians(upper).value + slack.value;
  }
};

/// Travel of a linear axis, in millimetres.
struct linear_travel {
  double lower_mm = -1e9;
  double upper_mm = 1e9;

  static constexpr linear_travel between(double lo_mm, double hi_mm) { return {lo_mm, hi_mm}; }

  /// Whether the value lies within the travel, with `slack_mm` for rounding.
  constexpr bool contains(double value_mm, double slack_mm = 1e-9) const {
    return value_mm >= lower_mm - slack_mm && value_mm <= upper_mm + slack_mm;
  }
  /// How far the value lies outside the travel, mm; 0 inside.
  constexpr double excess_mm(double value_mm) const {
    return value_mm < lower_mm ? lower_mm - value_mm : (value_mm > upper_mm ? value_mm - upper_mm : 0.0);
  }
};

/// A linear axis. Its value x moves the tool by +x·direction relative to the part (ISO 841),
/// whether the slide carries the spindle (`mount::head`, which moves by +x·direction) or the
/// table (`mount::table`, which moves by −x·direction).
struct linear_axis {
  axis_letter letter{};
  mount side{};
  vec3 direction{};        ///< unit vector, machine frame
  linear_travel travel{};  ///< limits of the value, mm
  /// The value, in the control's machine coordinates (G53, SUPA, M91), at the axis' home: its
  /// reference point, where `G28` sends it, and for the tool axis the top of its travel, where a
  /// retract ends (docs/machine-files.md, `home_mm`). Empty: not known, and a move in machine
  /// coordinates of this axis is refused rather than guessed.
  std::optional<double> home_mm{};
};

/// A rotary axis.
struct rotary_axis {
  axis_letter letter{};
  mount side{};
  vec3 direction{};         ///< unit vector, machine frame, at the zero pose of the machine
  angle_sense sense{};      ///< how the commanded value relates to ψ
  rotary_travel travel{};   ///< limits of the commanded value
  vec3 point_mm{};          ///< a point on the axis line, machine frame, at the zero pose
  /// The commanded angle at the axis' home, its reference point, where `G28` sends it
  /// (docs/machine-files.md, `home_deg`). Empty: not known, and a move to the reference point
  /// of this axis is refused rather than guessed.
  std::optional<degrees> home_deg{};

  /// φ, the physical right-handed rotation about `direction`, from the commanded angle: the
  /// commanded angle itself, negated for a table programmed tool-relative.
  constexpr radians physical(radians commanded_value) const {
    return (side == mount::table && sense == angle_sense::tool_relative) ? -commanded_value : commanded_value;
  }

  /// dψ / d(commanded): −1 for a physical table angle, +1 otherwise.
  constexpr double psi_per_commanded() const {
    return (sense == angle_sense::physical && side == mount::table) ? -1.0 : 1.0;
  }
  /// ψ, the tool-relative angle, from the commanded angle.
  constexpr radians psi(radians commanded) const { return psi_per_commanded() * commanded; }
  /// The commanded angle from ψ.
  constexpr radians commanded(radians psi_value) const { return psi_per_commanded() * psi_value; }
};

}  // namespace kin5
