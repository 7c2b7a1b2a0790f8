/// @file program/heidenhain/control_q.hpp
/// The Q parameters the control sets (Q100–Q199: Q108 the tool radius, Q120–Q122 the axis
/// angles of PLANE … STAY; TNC 640 User's Manual DIN/ISO, "Preassigned Q parameters"), one
/// range for the reader (parameters.hpp) and the interpreter's rules (parameter_rules.hpp).
#pragma once

namespace kin5::program::heidenhain {

inline constexpr long first_control_q = 100, last_control_q = 199;

}  // namespace kin5::program::heidenhain
