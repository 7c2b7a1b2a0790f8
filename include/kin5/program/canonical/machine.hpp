/// @file program/canonical/machine.hpp
/// Canonical operations of the machine besides its axes: spindle, coolant, the machine maker's
/// M functions, dwell, stops and the program's end.
#pragma once

#include <optional>
#include <string>

#include "../state_words.hpp"
#include "origin.hpp"

namespace kin5::program::canonical {

/// S: the spindle's speed.
struct set_spindle_speed {
  static constexpr std::string_view kind_name = "set_spindle_speed";
  origin from;
  double rpm = 0;
  friend bool operator==(const set_spindle_speed&, const set_spindle_speed&) = default;
};

/// M3, M4, M5 (Heidenhain M13, M14 with coolant; SPINDL): the spindle turns or stops.
struct set_spindle {
  static constexpr std::string_view kind_name = "set_spindle";
  origin from;
  spindle_rotation rotation = spindle_rotation::stopped;
  friend bool operator==(const set_spindle&, const set_spindle&) = default;
};

/// M7, M8, M9 (COOLNT): flood and mist coolant switched on (true) or off (false); one not
/// given is left as it is. At least one is given.
struct set_coolant {
  static constexpr std::string_view kind_name = "set_coolant";
  origin from;
  std::optional<bool> flood;
  std::optional<bool> mist;
  friend bool operator==(const set_coolant&, const set_coolant&) = default;
};

/// An M function whose meaning is the machine maker's (M428, M126, …), by its number.
struct machine_function {
  static constexpr std::string_view kind_name = "machine_function";
  origin from;
  int number = 0;
  friend bool operator==(const machine_function&, const machine_function&) = default;
};

/// G4, Cycle 9, DELAY/: the axes wait.
struct dwell {
  static constexpr std::string_view kind_name = "dwell";
  origin from;
  double duration_s = 0;
  friend bool operator==(const dwell&, const dwell&) = default;
};

/// M0, M1 (STOP, OPSTOP): the program stops, or stops when the optional-stop switch is on.
struct stop {
  static constexpr std::string_view kind_name = "stop";
  origin from;
  program_stop kind = program_stop::stop;
  friend bool operator==(const stop&, const stop&) = default;
};

/// END PGM, M2, M30, FINI: the program ends. `name` is the program's name where the text gives
/// it, "M2" or "M30" where it gives that word and no name, else empty (block.hpp).
struct end_program {
  static constexpr std::string_view kind_name = "end_program";
  origin from;
  std::string name;
  friend bool operator==(const end_program&, const end_program&) = default;
};

}  // namespace kin5::program::canonical
