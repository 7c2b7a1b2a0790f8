/// @file linuxcnc_machine.hpp
/// The machines of LinuxCNC's own 5-axis kinematics modules, as those modules see them: the
/// joints in their order, their geometry pins, and the world coordinates of their tool-centre
/// type. Needs kin5's core only (no LinuxCNC header), so that it is compiled and checked without
/// LinuxCNC too; `kin5kins.cc` is the HAL glue around it.
///
/// World coordinates are LinuxCNC's: X Y Z in mm, then A B C (degrees) and U V W, in that order,
/// as in its `EmcPose`; under the tool-centre type the rotary and W coordinates are the joints'
/// own values. Where X Y Z are (docs/embedding.md):
/// - table-rotary-tilting (xyzac-trt-kins, xyzbc-trt-kins) and table-dual-rotary
///   (xyzab_tdr_kins): the tool tip in the part frame raised by the tool offset along +Z, so that
///   at every rotary angle zero the world equals the joints;
/// - bridgemill (5axiskins): the tool tip in the part frame, the tool W joints longer than the
///   pivot length; the linear joints place the tip of a tool of length 0 at B = 0, the pivot
///   point being the pivot length above it.
///
/// Every call is `noexcept`, allocates nothing and runs in bounded time.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "kin5/kinematics/forward.hpp"
#include "kin5/kinematics/inverse_pose.hpp"
#include "kin5/machines/catalog.hpp"

namespace kin5::linuxcnc {

/// What a geometry pin of LinuxCNC's module sets.
enum class pin_role {
  none,
  x_rot_point,   ///< the rotation point, mm
  y_rot_point,
  z_rot_point,
  x_offset,      ///< the offset of one rotary axis' line from the rotation point, mm
  y_offset,
  z_offset,
  tool_offset,   ///< the tool length along the tool axis, mm
  pivot_length,  ///< from the heads' pivot point to the spindle nose, mm
};

/// One float HAL input of the module: its name after the module prefix, what it sets, its value
/// at load time.
struct pin_spec {
  std::string_view name{};
  pin_role role = pin_role::none;
  double initial = 0.0;
};

inline constexpr std::size_t max_pins = 6;
/// World coordinates and joints are at most X Y Z A B C U V W.
inline constexpr std::size_t max_coordinates = 9;

/// A machine LinuxCNC ships a kinematics module for.
struct machine_entry {
  std::string_view id;             ///< `machine=` of kin5kins
  std::string_view linuxcnc_kins;  ///< LinuxCNC's module for the same machine
  std::string_view linuxcnc_pins;  ///< the prefix of that module's pins
  const machine_model* model;      ///< the machine at the pins' zero
  /// The joint letters in order (LinuxCNC's `coordinates` default for the module).
  std::string_view joints;
  std::array<pin_spec, max_pins> pins{};
  /// Per rotary axis (chain order): whether its line passes through the rotation point plus the
  /// offset pins (true) or through the rotation point itself.
  std::array<bool, 2> offset_line{};
  /// Whether the tool-centre world is the tip raised by the tool offset along +Z
  /// (table-rotary-tilting, table-dual-rotary) rather than the tip itself (bridgemill).
  bool world_raised_by_tool = true;
  /// Whether the switchable type 0 is identity without `sparm=identityfirst`
  /// (xyzab_tdr_kins has only that order).
  bool identity_first = false;
  /// How many `kinstype.is-N` pins the module has: 3 (switchkins modules) or 2 (xyzab_tdr_kins).
  int type_pins = 3;
};

/// LinuxCNC's table-dual-rotary simulation machine (configs/sim/axis/vismach/5axis/
/// table-dual-rotary, module xyzab_tdr_kins): a rotary table A about +X, carrying the part, on
/// a tilting table B about +Y; both tables turn opposite to a physical right-handed angle
/// (ISO sense). kin5kins' own model: not in the catalog.
inline constexpr machine_model xyzab_tdr_model = machine_model::from({
    .id = "xyzab-tdr",
    .structure = "table-table (LinuxCNC sim): tilting table B about +Y carrying rotary table A about +X (part)",
    .linear = cartesian_axes({}, {}, {}),
    .rotary = {rotary_axis{axis_letter::A, mount::table, unit_x, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, 0.0}},
               rotary_axis{axis_letter::B, mount::table, unit_y, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, 0.0}}}});
static_assert(machine_rules::check(xyzab_tdr_model.geometry).ok());

/// LinuxCNC's bridgemill simulation machine (configs/sim/axis/vismach/5axis/bridgemill, module
/// 5axiskins): a head C about +Z carrying a head B about −Y (B tilts the tool towards −X at
/// C = 0), both through the pivot point; W moves the tool along its axis. kin5kins' own model:
/// not in the catalog.
inline constexpr machine_model bridgemill_model = machine_model::from({
    .id = "bridgemill",
    .structure = "head-head (LinuxCNC sim): head C about +Z carrying head B about -Y, W along the tool",
    .linear = cartesian_axes({}, {}, {}),
    .rotary = {rotary_axis{axis_letter::C, mount::head, unit_z, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, 0.0}},
               rotary_axis{axis_letter::B, mount::head, -unit_y, angle_sense::tool_relative, rotary_travel::endless(),
                           {0.0, 0.0, 0.0}}}});
static_assert(machine_rules::check(bridgemill_model.geometry).ok());

/// The machines kin5kins serves, each with LinuxCNC's module for it. A pin LinuxCNC's module
/// creates but never reads (xyzac-trt-kins' x-offset, xyzbc-trt-kins' y-offset) is not one.
inline constexpr std::array<machine_entry, 4> machine_entries{{
    {"xyzac-trt", "xyzac-trt-kins", "xyzac-trt-kins", &machines::xyzac_trt::model, "XYZAC",
     {{{"x-rot-point", pin_role::x_rot_point}, {"y-rot-point", pin_role::y_rot_point},
       {"z-rot-point", pin_role::z_rot_point}, {"y-offset", pin_role::y_offset}, {"z-offset", pin_role::z_offset},
       {"tool-offset", pin_role::tool_offset}}},
     {false, true}},
    {"xyzbc-trt", "xyzbc-trt-kins", "xyzbc-trt-kins", &machines::xyzbc_trt::model, "XYZBC",
     {{{"x-rot-point", pin_role::x_rot_point}, {"y-rot-point", pin_role::y_rot_point},
       {"z-rot-point", pin_role::z_rot_point}, {"x-offset", pin_role::x_offset}, {"z-offset", pin_role::z_offset},
       {"tool-offset", pin_role::tool_offset}}},
     {false, true}},
    {"xyzab-tdr", "xyzab_tdr_kins", "xyzab_tdr_kins", &xyzab_tdr_model, "XYZAB",
     {{{"x-rot-point", pin_role::x_rot_point}, {"y-rot-point", pin_role::y_rot_point},
       {"z-rot-point", pin_role::z_rot_point}, {"x-offset", pin_role::x_offset}, {"z-offset", pin_role::z_offset},
       {"tool-offset-z", pin_role::tool_offset}}},
     {true, false},
     true,
     true,
     2},
    {"bridgemill", "5axiskins", "5axiskins", &bridgemill_model, "XYZBCW",
     {{{"pivot-length", pin_role::pivot_length, 250.0}}},
     {false, false},
     false},
}};

/// The entry with id `id`, or null.
constexpr const machine_entry* find_entry(std::string_view id) noexcept {
  for (const auto& e : machine_entries)
    if (e.id == id) return &e;
  return nullptr;
}

/// The values of an entry's pins, in the order of `machine_entry::pins`.
using pin_values = std::array<double, max_pins>;
/// World coordinates X Y Z A B C U V W (mm, degrees).
using world_values = std::array<double, max_coordinates>;
/// Joint values in the entry's order (`machine_entry::joints`), mm and degrees.
using joint_values = std::array<double, max_coordinates>;

/// The pins' initial values.
constexpr pin_values initial_pins(const machine_entry& e) noexcept {
  pin_values v{};
  for (std::size_t i = 0; i < max_pins; ++i) v[i] = e.pins[i].initial;
  return v;
}

/// The value of the pin with role `r`, 0 when the entry has none.
constexpr double pin_value(const machine_entry& e, const pin_values& v, pin_role r) noexcept {
  for (std::size_t i = 0; i < max_pins; ++i)
    if (e.pins[i].role == r && r != pin_role::none) return v[i];
  return 0.0;
}

/// The machine of `e` with the geometry of its pins.
constexpr machine_model with_pins(const machine_entry& e, const pin_values& v) noexcept {
  machine_geometry g = e.model->geometry;
  const vec3 rotation_point{pin_value(e, v, pin_role::x_rot_point), pin_value(e, v, pin_role::y_rot_point),
                            pin_value(e, v, pin_role::z_rot_point)};
  const vec3 offset{pin_value(e, v, pin_role::x_offset), pin_value(e, v, pin_role::y_offset),
                    pin_value(e, v, pin_role::z_offset)};
  for (std::size_t i = 0; i < 2; ++i) g.rotary[i].point_mm = rotation_point + (e.offset_line[i] ? offset : vec3{});
  g.tool.pivot_length_mm = pin_value(e, v, pin_role::pivot_length);
  return machine_model::from(g);
}

namespace detail {

// X Y Z A B C U V W → 0 … 8; anything else → max_coordinates.
constexpr std::size_t coordinate_index(char letter) noexcept {
  constexpr std::string_view letters = "XYZABCUVW";
  const std::size_t i = letters.find(letter);
  return i == std::string_view::npos ? max_coordinates : i;
}

}  // namespace detail

/// The tool length, mm: the tool offset pin, and the W coordinate on a machine with a W joint
/// (bridgemill: W moves the tool along its axis). A machine without one ignores W, as its
/// LinuxCNC module does.
constexpr double tool_length_mm(const machine_entry& e, const pin_values& pins, const world_values& world) noexcept {
  const bool has_w = e.joints.find('W') != std::string_view::npos;
  return pin_value(e, pins, pin_role::tool_offset) + (has_w ? world[8] : 0.0);
}

/// Forward kinematics of the tool-centre type: joints → world. False when a result is not
/// finite (a pin or joint is NaN or infinite).
constexpr bool tcp_forward(const machine_entry& e, const machine_model& m, const pin_values& pins,
                           const joint_values& joints, world_values& world) noexcept {
  world = {};
  for (std::size_t k = 0; k < e.joints.size(); ++k) world[detail::coordinate_index(e.joints[k])] = joints[k];
  const double tool_mm = tool_length_mm(e, pins, world);
  const vec3 t = m.tool_reference();
  axis_values q{vec3{world[0], world[1], world[2]} + m.geometry.tool.pivot_length_mm * t, {}};
  for (std::size_t i = 0; i < m.rotary_count; ++i)
    q.rotary[i] = to_radians(degrees{world[detail::coordinate_index(to_char(m.rotary(i).letter))]});
  const tool_pose pose = forward(m, q, run_inputs{.tool_length_mm = tool_mm});
  const vec3 xyz = pose.tip_mm + (e.world_raised_by_tool ? tool_mm : 0.0) * t;
  world[0] = xyz.x;
  world[1] = xyz.y;
  world[2] = xyz.z;
  return machine_rules::is_finite(xyz);
}

/// Inverse kinematics of the tool-centre type: world → joints, the rotary and W joints at the
/// world's values. False when a result is not finite.
constexpr bool tcp_inverse(const machine_entry& e, const machine_model& m, const pin_values& pins,
                           const world_values& world, joint_values& joints) noexcept {
  const double tool_mm = tool_length_mm(e, pins, world);
  const vec3 t = m.tool_reference();
  std::array<radians, 2> rotary{};
  for (std::size_t i = 0; i < m.rotary_count; ++i)
    rotary[i] = to_radians(degrees{world[detail::coordinate_index(to_char(m.rotary(i).letter))]});
  const vec3 tip = vec3{world[0], world[1], world[2]} - (e.world_raised_by_tool ? tool_mm : 0.0) * t;
  const vec3 x = linear_axes_for(m, rotary, tip, run_inputs{.tool_length_mm = tool_mm}) -
                 m.geometry.tool.pivot_length_mm * t;
  world_values values = world;
  values[0] = x.x;
  values[1] = x.y;
  values[2] = x.z;
  joints = {};
  for (std::size_t k = 0; k < e.joints.size(); ++k) joints[k] = values[detail::coordinate_index(e.joints[k])];
  return machine_rules::is_finite(x);
}

/// Forward kinematics of the identity type: each joint is the world coordinate of its letter.
constexpr void identity_forward(const machine_entry& e, const joint_values& joints, world_values& world) noexcept {
  world = {};
  for (std::size_t k = 0; k < e.joints.size(); ++k) world[detail::coordinate_index(e.joints[k])] = joints[k];
}

/// Inverse kinematics of the identity type.
constexpr void identity_inverse(const machine_entry& e, const world_values& world, joint_values& joints) noexcept {
  joints = {};
  for (std::size_t k = 0; k < e.joints.size(); ++k) joints[k] = world[detail::coordinate_index(e.joints[k])];
}

}  // namespace kin5::linuxcnc
