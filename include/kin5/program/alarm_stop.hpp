/// @file program/alarm_stop.hpp
/// An alarm stop: the program stops at this block with an alarm, and the operator sees its
/// message; it does not continue from there (the operator resets the control). LinuxCNC
/// `(ABORT, text)`, FANUC and Haas `#3000 = n (text)`, Siemens `SETAL(n, "text")`, Heidenhain
/// `FN 14: ERROR = n`. The number only picks the alarm a control shows and means nothing in
/// another dialect: a translation drops it (translate/carry_over.hpp) and the target's writer
/// writes its own default (`docs/dialects/*.md`).
/// @code
///   kin5::program::block b;                         // LinuxCNC `(ABORT, probe failed)`
///   b.alarm = kin5::program::alarm_stop{"probe failed", std::nullopt};
/// @endcode
#pragma once

#include <optional>
#include <string>

namespace kin5::program {

/// The program stops here with an alarm (see the file comment).
struct alarm_stop {
  std::string message;              ///< the text the operator sees; empty when the source gives none
  std::optional<long long> number;  ///< the alarm number as the source dialect writes it
  friend bool operator==(const alarm_stop&, const alarm_stop&) = default;
};

}  // namespace kin5::program
