/// @file translate/rotary_move.hpp
/// Rotary moves from one motion block to the next. `source_rotary_delta(from, to)`: the change
/// of the source's commanded angles (degrees), as the block length (K16) counts it.
/// `rotary_move_warning(m, from, to, change)`: what a target move from angles `from` to `to`
/// deserves a warning for — a change of solution branch, else a sudden turn: a rotary axis
/// turning by `sudden_turn` or more while the tool axis turns by less than half of that (a swing
/// past a pole: the table whips round inside a short block).
/// @code
///   const auto delta = source_rotary_delta(previous_step, step);   // → block_length(…, delta.span())
///   if (auto w = rotary_move_warning(to, before, after, std::nullopt)) out.warnings.push_back(at(b, *w));
/// @endcode
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "../core/units.hpp"
#include "../kinematics/forward.hpp"
#include "source_walk.hpp"

namespace kin5::translate_detail {

/// The change of the source's commanded angles from step `from` to step `to` (degrees, machine
/// order), as (K16) counts it; `count` of them.
struct rotary_delta_deg {
  std::array<double, 2> value{};
  std::size_t count = 0;
  std::span<const double> span() const { return {value.data(), count}; }
};
inline rotary_delta_deg source_rotary_delta(const source_step& from, const source_step& to) {
  rotary_delta_deg d;
  d.count = to.rotary_count;
  for (std::size_t i = 0; i < to.rotary_count && i < from.rotary_count; ++i)
    d.value[i] = to.rotary_source_deg[i] - from.rotary_source_deg[i];
  return d;
}

/// A rotary move of this much or more in one block, for less than half of it of tool-axis turn,
/// is a warning (`rotary_move_warning`).
inline constexpr radians sudden_turn{pi / 2};

/// A change of the planner's solution branch between two motions off a pole; `avoidable` when
/// both motions could have been on one branch (the plan chose least total rotary travel).
struct branch_change {
  int from = 0, to = 0;
  bool avoidable = false;
};

/// The warning the move of machine `m` from commanded angles `from` to `to` deserves, with its
/// largest rotary move: the branch `change`, when there is one, else a sudden turn; none else.
inline std::optional<std::string> rotary_move_warning(const machine_model& m, const kin5::rotary_values& from,
                                                      const kin5::rotary_values& to, std::optional<branch_change> change) {
  std::size_t axis = 0;
  for (std::size_t i = 1; i < m.rotary_count; ++i)
    if (math::abs(to[i].value - from[i].value) > math::abs(to[axis].value - from[axis].value)) axis = i;
  const radians turn{math::abs(to[axis].value - from[axis].value)};
  // The text only when a warning is written: most moves have none.
  const auto turned = [&] {
    return " on " + std::string(m.geometry.id) + ": " + std::string(1, to_char(m.rotary(axis).letter)) + " turns by " +
           fixed(to_degrees(turn).value, 3) + "°";
  };
  if (change)
    return std::string(change->avoidable ? "solution branch switch (least total rotary travel)"
                                         : "unavoidable solution branch switch") +
           " from branch " + std::to_string(change->from) + " to " + std::to_string(change->to) + turned();
  if (turn.value < sudden_turn.value) return std::nullopt;
  const radians axis_turn = angle_between(tool_axis(m, from), tool_axis(m, to));
  if (!(turn.value > 2.0 * axis_turn.value)) return std::nullopt;
  return "sudden rotary move" + turned() + " while the tool axis turns by " + fixed(to_degrees(axis_turn).value, 3) +
         "° (past a pole)";
}

}  // namespace kin5::translate_detail
