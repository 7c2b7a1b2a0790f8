/// @file translate/machine_moves.hpp
/// A move in machine coordinates by what it means (docs/translation.md, "Machine-coordinate and
/// home moves"). Machine coordinates of two machines share no origin, so a translation carries
/// each linear axis as its distance from the axis' home, and each rotary axis as its commanded
/// angle:
///
///     from_home_mm[i] = value − home_mm(from, i)      G53, SUPA, M91: the value is machine coordinates
///                     = 0                              G28: the axis goes to its reference point
///     target value    = home_mm(to, i) + from_home_mm[i]
///
/// The tool-axis slide (Z) at its home is at the top of its travel: a retract, every control's
/// first and last move. A move of the rotary axes alone, after a retract and without tool-tip
/// tracking, is a positioning: the tool is clear of the part, so what it means is the tool axis
/// it ends at, and the target takes its own angles for it (the CAM safe-start idiom).
/// @code
///   kin5::translate_detail::machine_move m;
///   if (auto why = kin5::translate_detail::read_machine_move(b, from, incremental, m)) refuse(*why);
/// @endcode
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "../kinematics/machine_model.hpp"
#include "../program/block.hpp"
#include "../program/machine_position_text.hpp"

namespace kin5::translate_detail {

/// What a block in machine coordinates does, machine-neutrally.
struct machine_move {
  /// X, Y, Z: where each axis ends, mm from its home (+ away from the home along the axis);
  /// empty: the axis does not move.
  std::array<std::optional<double>, 3> from_home_mm{};
  /// A, B, C: the commanded angle each rotary axis ends at, degrees; empty: it does not move.
  std::array<std::optional<double>, 3> rotary_deg{};

  bool has_linear() const { return from_home_mm[0] || from_home_mm[1] || from_home_mm[2]; }
  bool has_rotary() const { return rotary_deg[0] || rotary_deg[1] || rotary_deg[2]; }
  /// Whether the tool-axis slide ends at its home or above it: the tool is retracted.
  bool retracts() const { return from_home_mm[2] && *from_home_mm[2] >= 0.0; }
};

/// The rotary axis of `m` with letter `l`, or null.
inline const rotary_axis* rotary_with(const machine_model& m, axis_letter l) {
  const std::size_t i = m.rotary_index(l);
  return i < m.rotary_count ? &m.rotary(i) : nullptr;
}

/// Reads block `b` (in machine coordinates) of a program for machine `from` into `out`;
/// `incremental`: G91 is in effect with the block. Returns why it is refused, if it is.
inline std::optional<std::string> read_machine_move(const program::block& b, const machine_model& from,
                                                    bool incremental, machine_move& out) {
  using program::machine_position;
  const machine_position p = b.machine_reference;
  const std::string what = program::machine_position_name(p);
  switch (p) {
    case machine_position::second_reference:
      return what + " is not translated: the second reference point is a position the control keeps (a "
                    "parameter of the control), not in the machine file; write G53 with the machine position meant";
    case machine_position::stored_position:
    case machine_position::second_stored_position:
      return what + " is not translated: LinuxCNC keeps it in parameters #5161-#5166 (G28) or #5181-#5186 (G30), "
                    "which the program does not set; write G53 G0 with the machine position meant";
    case machine_position::builder_position:
      return what + " is not translated: the machine builder's point is not in the machine file; write M91 with "
                    "the position from the machine datum";
    case machine_position::machine_zero:
    case machine_position::reference_point:
    case machine_position::tool_axis_limit:  // no axis words: the source walk reads it
      break;
  }
  if (b.axes.tool_axis) return what + " with a tool-axis vector is not translated";
  const bool reference = p == machine_position::reference_point;
  const std::optional<double>* linear[3] = {&b.axes.x_mm, &b.axes.y_mm, &b.axes.z_mm};
  const std::optional<double>* rotary[3] = {&b.axes.a_deg, &b.axes.b_deg, &b.axes.c_deg};
  if (incremental && !reference)
    return what + " in incremental mode (G91) is not translated: write it under G90";
  if (reference) {
    // G28's words are an intermediate point: under G91 a zero names an axis without moving it
    // there first; any other point is a move of its own (in part coordinates) before the home.
    for (const auto* w : linear)
      if (*w && (!incremental || **w != 0.0))
        return what + " through an intermediate point is not translated (the axes move there first, in the "
                      "part's coordinates): write G91 G28 with zeros, which goes straight to the reference point";
    for (const auto* w : rotary)
      if (*w && (!incremental || **w != 0.0))
        return what + " through an intermediate point is not translated (the axes turn there first): write G91 "
                      "G28 with zeros";
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (!*linear[i]) continue;
    if (reference) {
      out.from_home_mm[i] = 0.0;
      continue;
    }
    const auto home = from.linear(i).home_mm;
    const char letter = "XYZ"[i];
    if (!home)
      return what + " of " + letter + " needs the source machine's home of " + letter +
             ": give home_mm in [linear." + letter + "] of its machine file (--from-file; docs/machine-files.md)";
    out.from_home_mm[i] = **linear[i] - *home;
  }
  for (std::size_t i = 0; i < 3; ++i) {
    if (!*rotary[i]) continue;
    const auto letter = static_cast<axis_letter>("ABC"[i]);
    const rotary_axis* axis = rotary_with(from, letter);
    if (!axis) return what + " names " + std::string(1, "ABC"[i]) + ", an axis the source machine does not have";
    if (!reference) {
      out.rotary_deg[i] = **rotary[i];  // a rotary axis' machine position is its commanded angle
      continue;
    }
    if (!axis->home_deg)
      return what + " of " + std::string(1, "ABC"[i]) + " needs the source machine's reference angle: give home_deg in its "
                    "[[rotary]] table of the machine file (--from-file; docs/machine-files.md)";
    out.rotary_deg[i] = axis->home_deg->value;
  }
  return std::nullopt;
}

}  // namespace kin5::translate_detail
