/// @file bench/translate/spiral.hpp
/// The input of the translation benchmarks: a long 5-axis Siemens 840D program for the SAJO
/// 12000P, as text. The path is a spiral of 0.1-0.25 mm steps over a wavy surface, under TRAORI,
/// one `N… G1 X Y Z A B F` block per step, with A in [-80°, -10°] and B in [-60°, 60°], both
/// smooth, so that every block lies in the SAJO's reachable region and maps directly onto the
/// DMU 80P (docs/matchability.md: A in [-90°, 0°]). A header (tool call, spindle, TRAORI,
/// approach) and a footer (retract, TRAFOOF, M30) frame the motion blocks.
/// @code
///   const std::string text = kin5_bench::spiral_program(20000);  // 20,000 motion blocks
/// @endcode
#pragma once

#include <charconv>
#include <cmath>
#include <string>

namespace kin5_bench {

/// Appends `letter` and `value` with `decimals` decimals to `out`.
inline void append_word(std::string& out, char letter, double value, int decimals) {
  char buf[48];
  buf[0] = letter;
  const auto r = std::to_chars(buf + 1, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  out.append(buf, r.ptr);
}

/// The spiral program with `blocks` motion blocks (see the file comment).
inline std::string spiral_program(long blocks) {
  std::string out =
      "%_N_BENCH_SPIRAL_MPF\n"
      "; kin5 translation benchmark: a spiral finishing pass, SAJO 12000P, TRAORI\n"
      "N10 G17 G40 G71 G90 G94\n"
      "N20 G54\n"
      "N30 T1 D1\n"
      "N40 M6\n"
      "N50 S8000 M3\n"
      "N60 TRAORI\n"
      "N70 G0 X20. Y0. Z80. A-45. B0.\n";
  long n = 70;
  out.reserve(static_cast<std::size_t>(blocks) * 64 + 256);
  for (long i = 0; i < blocks; ++i) {
    const double theta = 0.005 * static_cast<double>(i);  // rad along the spiral
    const double r = 20.0 + 30.0 * static_cast<double>(i) / static_cast<double>(blocks);
    const double x = r * std::cos(theta), y = r * std::sin(theta);
    const double z = 10.0 + 2.0 * std::sin(0.05 * x) * std::cos(0.05 * y);
    const double a = -45.0 + 35.0 * std::sin(theta / 7.0);
    const double b = 60.0 * std::sin(theta / 11.0);
    const double feed = 1000.0 + 100.0 * std::sin(theta / 13.0);
    n += 10;
    out += 'N';
    out += std::to_string(n);
    out += " G1 ";
    append_word(out, 'X', x, 3), out += ' ';
    append_word(out, 'Y', y, 3), out += ' ';
    append_word(out, 'Z', z, 3), out += ' ';
    append_word(out, 'A', a, 3), out += ' ';
    append_word(out, 'B', b, 3), out += ' ';
    append_word(out, 'F', std::round(feed), 0), out += '\n';
  }
  // Appended, not `"N" + …`: GCC 12 warns falsely (-Wrestrict) on that.
  for (const char* end : {" G0 Z100.\n", " TRAFOOF\n", " M5\n", " M30\n"}) {
    n += 10;
    out += 'N';
    out += std::to_string(n);
    out += end;
  }
  return out;
}

}  // namespace kin5_bench
