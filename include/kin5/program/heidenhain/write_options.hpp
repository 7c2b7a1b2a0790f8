/// @file program/heidenhain/write_options.hpp
/// What the Heidenhain writer (writer.hpp) is told: `write_options`, the decimals of each kind
/// of number, the program's unit and name when known ahead, and `tcp_word`, the form of the TCP
/// switch it writes (`--tcp-word`: `M128` / `M129` or `FUNCTION TCPM` / `FUNCTION RESET TCPM`).
#pragma once

#include <optional>
#include <string>

#include "lexer.hpp"

namespace kin5::program::heidenhain {

/// How the writer switches tool-tip tracking (TCP) on and off (`--tcp-word`). Both forms
/// mean the same on a TNC 640 for what kin5 writes: the tool tip follows the programmed path,
/// rotary words are axis positions and the axes interpolate linearly (TNC 640 User's Manual,
/// M128 and FUNCTION TCPM, whose options F TCP, AXIS POS, PATHCTRL AXIS say exactly that).
enum class tcp_word {
  m128,           ///< `M128` on the block, `M129` off
  function_tcpm,  ///< `FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS` / `FUNCTION RESET TCPM`, blocks of their own
};

/// Decimals written for each kind of number, and the TCP switch.
struct write_options {
  int linear_decimals = 3;  ///< X Y Z, CC, CR radius (mm)
  int angle_decimals = 3;   ///< A B C (degrees)
  int feed_decimals = 1;    ///< F (mm/min) and S (1/min)
  int finest_feed_decimals = detail::finest_rate_decimals;  ///< more decimals for a small F or S, up to these (rate_decimals)
  int vector_decimals = 7;  ///< TX TY TZ
  /// The program's unit when known ahead (`program_unit`): BEGIN PGM says it even when the
  /// source states it only after its header (Siemens `%_N_P_MPF`, then `G700`).
  std::optional<bool> program_metric;
  /// The TCP switch written. Empty: `M128` / `M129`, except that a program read as Heidenhain
  /// keeps its own `FUNCTION TCPM` blocks.
  std::optional<tcp_word> tcp;
  /// The program's name when known ahead (`program_name`: the source's, or the output file's),
  /// for a program whose first block names none; else `PGM`.
  std::optional<std::string> program_name;
};

}  // namespace kin5::program::heidenhain
