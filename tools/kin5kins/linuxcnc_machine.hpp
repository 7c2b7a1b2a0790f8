/// @file linuxcnc_machine.hpp
/// A catalog machine as LinuxCNC's own kinematics module for it sees it: its joints in
/// LinuxCNC's order, its geometry pins, and the world coordinates of LinuxCNC's tool-centre
/// type. Needs kin5's core only (no LinuxCNC header), so that it is compiled and checked without
/// LinuxCNC too; `kin5kins.cc` is the HAL glue around it.
///
/// LinuxCNC's world position under its TCP type (xyzac-trt-kins, xyzbc-trt-kins) is the tool tip
/// in the part frame raised by the tool offset along the tool reference (+Z): at every rotary
/// angle zero, world X Y Z equal the joints. The world rotary coordinates are the joints' own
/// angles, in degrees. Every call here is `noexcept`, allocates nothing and runs in bounded time.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "kin5/kinematics/forward.hpp"
#include "kin5/kinematics/inverse_pose.hpp"
#include "kin5/machines/catalog.hpp"

namespace kin5::linuxcnc {

/// The geometry pins of LinuxCNC's table-rotary-tilting modules, each a float HAL input, mm.
enum class pin { x_rot_point, y_rot_point, z_rot_point, x_offset, y_offset, z_offset, tool_offset };

inline constexpr std::size_t pin_count = 7;

/// The pin's name after the module prefix, as LinuxCNC's module names it.
constexpr const char* pin_name(pin p) noexcept {
  switch (p) {
    case pin::x_rot_point: return "x-rot-point";
    case pin::y_rot_point: return "y-rot-point";
    case pin::z_rot_point: return "z-rot-point";
    case pin::x_offset: return "x-offset";
    case pin::y_offset: return "y-offset";
    case pin::z_offset: return "z-offset";
    case pin::tool_offset: return "tool-offset";
  }
  return "";
}

/// A catalog machine that LinuxCNC ships a kinematics module for.
struct machine_entry {
  std::string_view id;             ///< the kin5 catalog id, `machine=` of kin5kins
  std::string_view linuxcnc_kins;  ///< LinuxCNC's module for the same machine
  /// The joint letters in LinuxCNC's order (its `coordinates` default): X Y Z, then the tilting
  /// axis, then C.
  std::string_view joints;
  /// The pins that module reads; a pin it creates but never reads (xyzac-trt-kins' x-offset,
  /// xyzbc-trt-kins' y-offset) is not one.
  std::array<bool, pin_count> reads{};
};

/// The machines kin5kins serves, each with LinuxCNC's module for it.
inline constexpr std::array<machine_entry, 2> machine_entries{{
    {"xyzac-trt", "xyzac-trt-kins", "XYZAC", {true, true, true, false, true, true, true}},
    {"xyzbc-trt", "xyzbc-trt-kins", "XYZBC", {true, true, true, true, false, true, true}},
}};

/// The entry with catalog id `id`, or null.
constexpr const machine_entry* find_entry(std::string_view id) noexcept {
  for (const auto& e : machine_entries)
    if (e.id == id) return &e;
  return nullptr;
}

/// The values of the pins, mm, indexed by `pin`.
using pin_values = std::array<double, pin_count>;

/// The machine `base` (a catalog model of a table-rotary-tilting machine: C through the rotation
/// point, the tilting axis carrying it) with the geometry of `pins`: C through the rotation
/// point, the tilting axis through the rotation point plus the offsets its module reads.
constexpr machine_model with_pins(const machine_model& base, const machine_entry& e, const pin_values& pins) noexcept {
  machine_geometry g = base.geometry;
  auto value = [&](pin p) { return e.reads[static_cast<std::size_t>(p)] ? pins[static_cast<std::size_t>(p)] : 0.0; };
  const vec3 rotation_point{value(pin::x_rot_point), value(pin::y_rot_point), value(pin::z_rot_point)};
  g.rotary[0].point_mm = rotation_point;
  g.rotary[1].point_mm = rotation_point + vec3{value(pin::x_offset), value(pin::y_offset), value(pin::z_offset)};
  return machine_model::from(g);
}

/// World coordinates of LinuxCNC's TCP type: X Y Z in mm, A B C in degrees (0 for a letter the
/// machine lacks).
struct world_position {
  vec3 xyz_mm{};
  std::array<double, 3> abc_deg{};
};

/// Joint values in LinuxCNC's order (`machine_entry::joints`): mm and degrees.
using joint_values = std::array<double, 5>;

namespace detail {

constexpr std::size_t abc_index(axis_letter l) noexcept {
  return l == axis_letter::A ? 0 : (l == axis_letter::B ? 1 : 2);
}
// The joint holding rotary axis i (chain order) of m: joint 4 holds C, joint 3 the tilting axis.
constexpr std::size_t joint_of_rotary(const machine_model& m, std::size_t i) noexcept {
  return m.rotary(i).letter == axis_letter::C ? 4 : 3;
}

}  // namespace detail

/// Forward kinematics of the TCP type: joints → world. False when a result is not finite (a pin
/// or joint is NaN or infinite).
constexpr bool tcp_forward(const machine_model& m, const joint_values& j, double tool_offset_mm,
                           world_position& out) noexcept {
  axis_values q{{j[0], j[1], j[2]}, {}};
  for (std::size_t i = 0; i < 2; ++i) q.rotary[i] = to_radians(degrees{j[detail::joint_of_rotary(m, i)]});
  const tool_pose pose = forward(m, q, run_inputs{.tool_length_mm = tool_offset_mm});
  out.xyz_mm = pose.tip_mm + tool_offset_mm * m.tool_reference();
  out.abc_deg = {};
  for (std::size_t i = 0; i < 2; ++i)
    out.abc_deg[detail::abc_index(m.rotary(i).letter)] = j[detail::joint_of_rotary(m, i)];
  return machine_rules::is_finite(out.xyz_mm);
}

/// Inverse kinematics of the TCP type: world → joints, the rotary joints at the world's angles.
/// False when a result is not finite.
constexpr bool tcp_inverse(const machine_model& m, const world_position& w, double tool_offset_mm,
                           joint_values& out) noexcept {
  std::array<radians, 2> rotary{};
  for (std::size_t i = 0; i < 2; ++i) {
    const double deg = w.abc_deg[detail::abc_index(m.rotary(i).letter)];
    rotary[i] = to_radians(degrees{deg});
    out[detail::joint_of_rotary(m, i)] = deg;
  }
  const run_inputs in{.tool_length_mm = tool_offset_mm};
  const vec3 x = linear_axes_for(m, rotary, w.xyz_mm - tool_offset_mm * m.tool_reference(), in);
  out[0] = x.x;
  out[1] = x.y;
  out[2] = x.z;
  return machine_rules::is_finite(x);
}

/// Forward kinematics of the identity type: each joint is the world coordinate of its letter.
constexpr void identity_forward(const machine_model& m, const joint_values& j, world_position& out) noexcept {
  out.xyz_mm = {j[0], j[1], j[2]};
  out.abc_deg = {};
  for (std::size_t i = 0; i < 2; ++i)
    out.abc_deg[detail::abc_index(m.rotary(i).letter)] = j[detail::joint_of_rotary(m, i)];
}

/// Inverse kinematics of the identity type.
constexpr void identity_inverse(const machine_model& m, const world_position& w, joint_values& out) noexcept {
  out[0] = w.xyz_mm.x;
  out[1] = w.xyz_mm.y;
  out[2] = w.xyz_mm.z;
  for (std::size_t i = 0; i < 2; ++i)
    out[detail::joint_of_rotary(m, i)] = w.abc_deg[detail::abc_index(m.rotary(i).letter)];
}

}  // namespace kin5::linuxcnc
