/// @file machine.hpp
/// What a machine type is: a class whose geometry is `static constexpr` data, checked at compile
/// time with one `static_assert` message per rule.
///
/// A machine lists its rotary axes in chain order *from the workpiece to the tool*:
/// `rotary[0]` is the axis that does not move in the workpiece frame (p of (G1): the table
/// axis that carries the part, or the outer head axis on a head-head machine), `rotary[1]` the
/// one it carries (q). The tool axis is then (G1)
///
///     u = R(p, ψp) · R(q, ψq) · t
///
/// with `t = tool_reference`, the tool axis at the zero pose. Linear axes X, Y, Z are aligned
/// with the workpiece frame; under tool-tip tracking (TRAORI, M128, G43.4) the programmed XYZ is
/// the tool tip in the workpiece frame. Example, (K1):
/// @code
/// struct sajo_12000p {
///   static constexpr std::string_view id = "sajo-12000p";
///   static constexpr std::string_view structure = "table B about +Y carrying the part, head A about +X";
///   static constexpr kin5::vec3 tool_reference = kin5::unit_z;
///   static constexpr std::array rotary{
///     kin5::rotary_axis{axis_letter::B, mount::table, unit_y, angle_sense::tool_relative, rotary_travel::endless()},
///     kin5::rotary_axis{axis_letter::A, mount::head,  unit_x, angle_sense::tool_relative,
///                       rotary_travel::between(-120_deg, 30_deg)}};
/// };
/// @endcode
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <string_view>

#include "axis.hpp"

namespace kin5 {

/// The shape of a machine description; `machine` adds the geometric rules.
template <class M>
concept machine_description = requires {
  { M::id } -> std::convertible_to<std::string_view>;
  { M::structure } -> std::convertible_to<std::string_view>;
  { M::tool_reference } -> std::convertible_to<vec3>;
  { M::rotary.size() } -> std::convertible_to<std::size_t>;
  { M::rotary[0] } -> std::convertible_to<rotary_axis>;
};

/// Number of rotary axes of a machine (1 for a 4-axis machine, 2 for a 5-axis one).
template <machine_description M>
inline constexpr std::size_t rotary_count = M::rotary.size();

namespace rules {

inline constexpr double unit_tolerance = 1e-12;
/// A machine whose ρ (G2) is below this is degenerate (S1).
inline constexpr double degenerate_rho = 1e-9;
/// Widest travel of a bounded axis, so that one pose has at most four 360° shifts.
inline constexpr double widest_bounded_travel_deg = 1080.0;

constexpr bool is_unit(const vec3& v) {
  const double d = squared_norm(v) - 1.0;
  return d < unit_tolerance && d > -unit_tolerance;
}

template <machine_description M>
constexpr bool directions_are_unit() {
  if (!is_unit(M::tool_reference)) return false;
  for (const auto& a : M::rotary)
    if (!is_unit(a.direction)) return false;
  return true;
}

template <machine_description M>
constexpr bool letters_are_rotary_and_distinct() {
  for (std::size_t i = 0; i < M::rotary.size(); ++i) {
    const auto l = M::rotary[i].letter;
    if (l != axis_letter::A && l != axis_letter::B && l != axis_letter::C) return false;
    for (std::size_t j = 0; j < i; ++j)
      if (M::rotary[j].letter == l) return false;
  }
  return true;
}

template <machine_description M>
constexpr bool travels_are_ordered_and_bounded() {
  for (const auto& a : M::rotary) {
    if (a.travel.continuous) continue;
    if (!(a.travel.lower.value <= a.travel.upper.value)) return false;
    if (a.travel.upper.value - a.travel.lower.value > widest_bounded_travel_deg) return false;
  }
  return true;
}

/// (S1): on a two-rotary machine, q must be neither parallel to p nor to t, else one axis
/// cannot change the tool direction. ρ = |p×q|·|q×t| (G2).
template <machine_description M>
constexpr bool second_axis_moves_the_tool() {
  if constexpr (rotary_count<M> == 2) {
    const vec3 p = M::rotary[0].direction, q = M::rotary[1].direction, t = M::tool_reference;
    return norm(cross(p, q)) * norm(cross(q, t)) > degenerate_rho;
  } else {
    const vec3 p = M::rotary[0].direction, t = M::tool_reference;
    return norm(cross(p, t)) > degenerate_rho;
  }
}

}  // namespace rules

/// A machine description that satisfies every geometric rule. Use `check_machine<M>()` for the
/// rule-by-rule diagnostics.
template <class M>
concept machine = machine_description<M> &&
                  (rotary_count<M> == 1 || rotary_count<M> == 2) &&
                  rules::directions_are_unit<M>() && rules::letters_are_rotary_and_distinct<M>() &&
                  rules::travels_are_ordered_and_bounded<M>() && rules::second_axis_moves_the_tool<M>();

/// Fails to compile, with one message per broken rule, when `M` is not a valid machine.
/// Evaluates to true otherwise, so it can be used as `static_assert(kin5::check_machine<M>())`.
template <machine_description M>
consteval bool check_machine() {
  static_assert(rotary_count<M> == 1 || rotary_count<M> == 2,
                "kin5: a machine has one or two rotary axes");
  static_assert(rules::directions_are_unit<M>(),
                "kin5: every axis direction and the tool reference must be unit vectors");
  static_assert(rules::letters_are_rotary_and_distinct<M>(),
                "kin5: rotary axes are named A, B or C, each letter at most once");
  static_assert(rules::travels_are_ordered_and_bounded<M>(),
                "kin5: a bounded axis needs lower <= upper and at most 1080 degrees of travel; "
                "declare wider axes continuous");
  static_assert(rules::second_axis_moves_the_tool<M>(),
                "kin5: degenerate machine (S1): the carried rotary axis is parallel to the "
                "fixed one or to the tool, so it cannot change the tool direction");
  return true;
}

/// The index of the rotary axis with NC letter `l` in `M::rotary`, or `rotary_count<M>` if none.
template <machine_description M>
constexpr std::size_t rotary_index(axis_letter l) {
  for (std::size_t i = 0; i < rotary_count<M>; ++i)
    if (M::rotary[i].letter == l) return i;
  return rotary_count<M>;
}

/// Commanded rotary angles of machine M, in `M::rotary` order, radians.
template <machine_description M>
using rotary_angles = std::array<radians, rotary_count<M>>;

}  // namespace kin5
