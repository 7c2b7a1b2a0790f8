/// @file machine.hpp
/// Machine *types*: a class whose `static constexpr` member `model` is its `machine_model`
/// (machine_model.hpp), checked at compile time with one `static_assert` message per rule. The
/// template API (`tool_axis<M>`, `forward<M>`, `inverse<M>`, …) forwards to the value API with
/// `M::model`, so compile-time machines and machines read at run time run the same code.
///
/// `machine_type<Model>` gives a type its model and the members code written against types reads:
/// `id`, `structure`, `tool_reference`, `rotary` (the rotary axes in chain order, from the
/// workpiece to the tool: `rotary[0]` is p of (G1), `rotary[1]` is q) and `linear`. Example:
/// @code
/// inline constexpr kin5::machine_model sajo_model = kin5::machine_model::from({
///     .id = "sajo-12000p", .structure = "head-table: table B about +Y carrying the part, head A about +X",
///     .linear = kin5::cartesian_axes({-800, 800}, {-500, 500}, {-800, 200}),
///     .rotary = {kin5::rotary_axis{axis_letter::B, mount::table, unit_y, angle_sense::tool_relative,
///                                  rotary_travel::endless(), {0, 0, -600}},
///                kin5::rotary_axis{axis_letter::A, mount::head, unit_x, angle_sense::tool_relative,
///                                  rotary_travel::between({-120.0}, {30.0})}},
///     .tool = {kin5::unit_z, 250.0}});
/// struct sajo_12000p : kin5::machine_type<sajo_model> {};
/// static_assert(kin5::check_machine<sajo_12000p>());
/// @endcode
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <string_view>

#include "machine_model.hpp"

namespace kin5 {

namespace detail {
template <std::size_t N>
constexpr std::array<rotary_axis, N> first_rotary(const std::array<rotary_axis, 2>& all) {
  std::array<rotary_axis, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = all[i];
  return out;
}
}  // namespace detail

/// The members of a machine type with model `Model` (see the file comment).
template <const machine_model& Model>
struct machine_type {
  static constexpr const machine_model& model = Model;
  static constexpr std::string_view id = Model.geometry.id;
  static constexpr std::string_view structure = Model.geometry.structure;
  static constexpr vec3 tool_reference = Model.geometry.tool.reference;
  static constexpr std::array<linear_axis, 3> linear = Model.geometry.linear;
  static constexpr std::array<rotary_axis, Model.rotary_count> rotary = detail::first_rotary<Model.rotary_count>(Model.geometry.rotary);
};

/// The shape of a machine type; `machine` adds the geometric rules.
template <class M>
concept machine_description = requires {
  { M::model } -> std::convertible_to<const machine_model&>;
  { M::id } -> std::convertible_to<std::string_view>;
  { M::rotary.size() } -> std::convertible_to<std::size_t>;
};

/// Number of rotary axes of a machine (1 for a 4-axis machine, 2 for a 5-axis one).
template <machine_description M>
inline constexpr std::size_t rotary_count = M::model.rotary_count;

/// A machine type whose model satisfies every rule of `machine_rules`. Use `check_machine<M>()`
/// for the rule-by-rule diagnostics.
template <class M>
concept machine = machine_description<M> && machine_rules::check(M::model.geometry).ok() &&
                  (M::model.rotary_count == 1 || M::model.rotary_count == 2);

/// Fails to compile, with one message per broken rule, when `M` is not a valid machine.
/// Evaluates to true otherwise, so it can be used as `static_assert(kin5::check_machine<M>())`.
template <machine_description M>
consteval bool check_machine() {
  using machine_rules::holds;
  using machine_rules::rule;
  constexpr const machine_geometry& g = M::model.geometry;
  static_assert(holds(rule::rotary_count, g), "kin5: a machine has one or two rotary axes");
  static_assert(holds(rule::unit_directions, g),
                "kin5: every axis direction and the tool reference must be unit vectors");
  static_assert(holds(rule::rotary_letters, g), "kin5: rotary axes are named A, B or C, each letter at most once");
  static_assert(holds(rule::linear_letters, g), "kin5: the linear axes are X, Y and Z, in that order");
  static_assert(holds(rule::linear_independent, g), "kin5: the linear axis directions must not lie in one plane");
  static_assert(holds(rule::travel_order, g),
                "kin5: a travel needs lower <= upper, and a bounded rotary axis at most 1080 degrees; "
                "declare wider axes continuous");
  static_assert(holds(rule::moves_the_tool, g),
                "kin5: degenerate machine (S1): the carried rotary axis is parallel to the fixed one or to the tool, "
                "so it cannot change the tool direction");
  static_assert(holds(rule::finite, g), "kin5: every number must be finite and the pivot length not negative");
  return true;
}

/// The index of the rotary axis with NC letter `l` in `M::rotary`, or `rotary_count<M>` if none.
template <machine_description M>
constexpr std::size_t rotary_index(axis_letter l) {
  return M::model.rotary_index(l);
}

/// Commanded rotary angles of machine M, in `M::rotary` order, radians.
template <machine_description M>
using rotary_angles = std::array<radians, rotary_count<M>>;

}  // namespace kin5
