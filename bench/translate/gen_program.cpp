// Writes a long 5-axis Siemens 840D program for the SAJO 12000P, the input of the translation
// benchmark (bench/translate/run.sh).
//
//   kin5_bench_gen_program BLOCKS OUT.mpf
//
// The path: a spiral of 0.1-0.25 mm steps over a wavy surface, under TRAORI, one
// `N… G1 X Y Z A B F` block per step, with A in [-80°, -10°] and B in [-60°, 60°], both
// smooth, so that every block lies in the SAJO's reachable region and maps directly onto the
// DMU 80P (docs/matchability.md: A in [-90°, 0°]). A header (tool call, spindle, TRAORI, approach) and a
// footer (retract, TRAFOOF, M30) frame the motion blocks.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {


void append(std::string& out, char letter, double value, int decimals) {
  char buf[48];
  buf[0] = letter;
  const auto r = std::to_chars(buf + 1, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  out.append(buf, r.ptr);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s BLOCKS OUT.mpf\n", argv[0]);
    return 1;
  }
  const long blocks = std::strtol(argv[1], nullptr, 10);
  if (blocks <= 0) {
    std::fprintf(stderr, "%s: BLOCKS must be a positive number\n", argv[0]);
    return 1;
  }
  std::FILE* f = std::fopen(argv[2], "wb");
  if (!f) {
    std::perror(argv[2]);
    return 2;
  }
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
  out.reserve(1 << 22);
  for (long i = 0; i < blocks; ++i) {
    const double theta = 0.005 * static_cast<double>(i);             // rad along the spiral
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
    append(out, 'X', x, 3), out += ' ';
    append(out, 'Y', y, 3), out += ' ';
    append(out, 'Z', z, 3), out += ' ';
    append(out, 'A', a, 3), out += ' ';
    append(out, 'B', b, 3), out += ' ';
    append(out, 'F', std::round(feed), 0), out += '\n';
    if (out.size() > (1 << 22) - 256) {
      std::fwrite(out.data(), 1, out.size(), f);
      out.clear();
    }
  }
  out += "N" + std::to_string(n + 10) + " G0 Z100.\n";
  out += "N" + std::to_string(n + 20) + " TRAFOOF\n";
  out += "N" + std::to_string(n + 30) + " M5\n";
  out += "N" + std::to_string(n + 40) + " M30\n";
  std::fwrite(out.data(), 1, out.size(), f);
  if (std::fclose(f) != 0) {
    std::perror(argv[2]);
    return 2;
  }
  return 0;
}
