/// @file program/linuxcnc/predefined_parameters.hpp
/// The parameters LinuxCNC sets and a program may only read, one list for the reader (which
/// refuses setting them) and the interpreter's rules (which refuse their machine values):
/// #5001 and up (probe results, G28/G30 homes, work offsets: User Manual, "Numbered
/// Parameters"), and the predefined named parameters `#<_x>`, …, `#<_ini[…]…>`, `#<_hal[…]>`
/// ("Predefined Named Parameters", "HAL pins and INI values").
#pragma once

#include <string_view>

namespace kin5::program::linuxcnc {

/// The last numbered parameter the program owns; above it they are the control's.
inline constexpr long last_program_parameter = 5000;

/// Whether `inner` (a named parameter's name between `#<` and `>`, lower case) is one LinuxCNC sets.
constexpr bool is_predefined_parameter(std::string_view inner) {
  constexpr std::string_view predefined[] = {
      "_vmajor", "_vminor", "_line", "_motion_mode", "_plane", "_ccomp", "_metric", "_imperial", "_absolute",
      "_incremental", "_inverse_time", "_units_per_minute", "_units_per_rev", "_coord_system", "_tool_offset",
      "_retract_r_plane", "_retract_old_z", "_spindle_rpm_mode", "_spindle_css_mode", "_ijk_absolute_mode",
      "_lathe_diameter_mode", "_lathe_radius_mode", "_spindle_on", "_spindle_cw", "_mist", "_flood",
      "_speed_override", "_feed_override", "_adaptive_feed", "_feed_hold", "_feed", "_rpm", "_x", "_y", "_z",
      "_a", "_b", "_c", "_u", "_v", "_w", "_abs_x", "_abs_y", "_abs_z", "_abs_a", "_abs_b", "_abs_c", "_abs_u",
      "_abs_v", "_abs_w", "_current_tool", "_current_pocket", "_selected_tool", "_selected_pocket", "_value",
      "_value_returned", "_task", "_call_level", "_remap_level"};
  if (inner.find('[') != std::string_view::npos) return true;
  for (std::string_view p : predefined)
    if (inner == p) return true;
  return false;
}

}  // namespace kin5::program::linuxcnc
