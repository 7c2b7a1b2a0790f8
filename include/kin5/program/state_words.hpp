/// @file program/state_words.hpp
/// The words of a block that set the machine's state without moving it: tool change, length and
/// radius compensation, spindle, coolant, work offset, working plane, distance mode, dwell, stop.
/// Each is a dialect-neutral meaning; `docs/dialects/*.md` give the table from every dialect's
/// spelling to it and back, with the controller manual for each.
///
/// A block holds only what its own text says (`block::state`); what is in effect after a block is
/// `modal_state` (modal.hpp). Lengths are millimetres whatever the program's unit (readers of an
/// inch program convert, writers of one convert back), times seconds.
/// @code
///   kin5::program::block b;                       // ISO `T5 M6`, Heidenhain `TOOL CALL 5 Z`
///   b.tool = 5;
///   b.state.tool_change = true;
///   b.state.tool_spindle_axis = kin5::program::spindle_axis::z;   // Heidenhain only
/// @endcode
/// All members are trivially copyable, so a store may keep the struct as bytes.
#pragma once

#include <optional>
#include <type_traits>

namespace kin5::program {

/// Plane of a circular move (G17/G18/G19, or the Heidenhain CC axes), and the working plane.
enum class arc_plane { xy, zx, yz };

/// The machine axis the tool points along (Heidenhain `TOOL CALL n Z`).
enum class spindle_axis { x, y, z };

/// Spindle command: M3, M4, M5 (Heidenhain also M13/M14 with coolant; APT `SPINDL/CLW|CCLW|OFF`).
enum class spindle_rotation {
  clockwise,          ///< M3, SPINDL/CLW
  counter_clockwise,  ///< M4, SPINDL/CCLW
  stopped,            ///< M5, SPINDL/OFF
};

/// Cutter radius compensation: G40/G41/G42, Heidenhain R0/RL/RR, APT CUTCOM/OFF|LEFT|RIGHT.
enum class cutter_side {
  off,    ///< G40, R0
  left,   ///< G41, RL: tool left of the path, seen along the motion
  right,  ///< G42, RR
};

/// How axis words are read: G90/G91 (Heidenhain `I` prefix, Siemens `=IC()` per word).
enum class distance_mode { absolute, incremental };

/// Program stop: M0, M1 (Heidenhain `STOP`/M0, M1; APT `STOP`, `OPSTOP`).
enum class program_stop {
  stop,           ///< M0: always stops
  optional_stop,  ///< M1: stops when the operator's optional-stop switch is on
};

/// Which family of work offset a number belongs to. Numbers mean nothing across families: a
/// translation maps between them only by a documented identity or a mapping the user gives.
enum class work_offset_family {
  /// G54 … G59 and LinuxCNC's G59.1 … G59.3, numbered 1 … 9 (G54 = 1, G59 = 6, G59.3 = 9).
  /// Siemens G54 … G57 are 1 … 4 (its G58/G59 are programmable shifts, not work offsets).
  g54,
  extended,  ///< Fanuc/ISO `G54.1 P n` (also written `G54 P n`): number n
  siemens,   ///< Siemens settable zero offsets `G505` … `G599` (number 505 … 599), `G500` (0: none)
  preset,    ///< Heidenhain preset table row: `CYCL DEF 247` `Q339=n`, `PRESET SELECT #n`
};

/// The work offset a block selects.
struct work_offset {
  work_offset_family family = work_offset_family::g54;
  int number = 1;
  friend bool operator==(const work_offset&, const work_offset&) = default;
};

/// The state words of one block, each as its text gave it (empty: the block does not say).
///
/// Registers: an absent `length_register` / `radius_register` with compensation switched on
/// means "the active tool's own entry" (Heidenhain TOOL CALL, LinuxCNC `G43` without H, Siemens
/// D with its edge); a number is the register the text names (ISO/Fanuc H, D; LinuxCNC H, D are
/// tool-table entries; APT `CUTCOM/LEFT,n`).
struct state_words {
  /// The tool is changed in this block (M6, `TOOL CALL n`, `LOADTL`): to `block::tool` when the
  /// block gives one, else to the tool selected before (ISO `T5` … `M6`).
  bool tool_change = false;
  std::optional<spindle_axis> tool_spindle_axis;  ///< Heidenhain `TOOL CALL n Z`
  std::optional<double> tool_length_delta_mm;     ///< Heidenhain `DL` in TOOL CALL (oversize)
  std::optional<double> tool_radius_delta_mm;     ///< Heidenhain `DR` in TOOL CALL (oversize)
  /// Tool length compensation on (G43, G43.4/G43.5/G234 with H, Heidenhain TOOL CALL, Siemens
  /// D ≥ 1) or off (G49, Siemens D0).
  std::optional<bool> length_compensation;
  std::optional<long long> length_register;       ///< H n (ISO/Fanuc offset, LinuxCNC tool entry)
  std::optional<cutter_side> radius_compensation;  ///< G40/G41/G42, R0/RL/RR
  std::optional<long long> radius_register;       ///< D n with G41/G42 (ISO, LinuxCNC), CUTCOM n
  std::optional<long long> cutting_edge;          ///< Siemens D n: edge n of the active tool
  std::optional<spindle_rotation> spindle;        ///< M3/M4/M5
  std::optional<bool> coolant_flood;              ///< M8 (true), M9 (false)
  std::optional<bool> coolant_mist;               ///< M7 (true), M9 (false)
  std::optional<kin5::program::work_offset> work_offset;  ///< G54 …, G54.1 P, G505 …, preset
  std::optional<arc_plane> working_plane;         ///< G17/G18/G19, TOOL CALL axis
  std::optional<distance_mode> distance;          ///< G90/G91
  std::optional<double> dwell_s;                  ///< G4, Cycle 9, DELAY/: seconds
  std::optional<program_stop> stop;               ///< M0/M1

  friend bool operator==(const state_words&, const state_words&) = default;

  /// Whether the block says none of these.
  bool empty() const { return *this == state_words{}; }
};

static_assert(std::is_trivially_copyable_v<state_words>, "a store keeps state_words as bytes");

}  // namespace kin5::program
