/// @file rs274_canonical.hpp
/// LinuxCNC's own interpreter as an oracle for moves: `rs274 -g FILE` (Debian's linuxcnc-uspace)
/// runs a G-code program standalone and prints the canonical calls it makes, one a line. This
/// helper runs it on a program's text and returns the moves among them — `STRAIGHT_TRAVERSE`,
/// `STRAIGHT_FEED`, `ARC_FEED` — with their end positions, and for an arc its centre, turns and
/// plane, each in the length unit then in effect (`USE_LENGTH_UNITS`).
///
/// What rs274 prints: every number with 4 decimals (`%.4f`), so a value is exact only when it has
/// at most 4 decimals (a law compares to 1e-9 only values it makes so: positions of 3 decimals
/// and their sums); positions in the program's unit, inch or mm; angles in degrees. An arc's
/// arguments are in the plane's order (first end, second end, first centre, second centre,
/// rotation, end along the axis, then A B C): XY is X, Y and axis Z; XZ is Z, X and axis Y; YZ
/// is Y, Z and axis X. A build with U V W axes prints three more numbers, which are read and
/// dropped. Two rs274 processes at once can die of a bus error (LinuxCNC 2.9 from Debian): a
/// test that uses this helper runs under CTest's RESOURCE_LOCK rs274.
///
/// Needs `KIN5_RS274`, the path of rs274 (tests/property/interp/CMakeLists.txt finds it).
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

namespace kin5::test::rs274 {

/// The kind of a canonical move.
enum class move_kind { traverse, feed, arc };

/// The plane of an arc (`SELECT_PLANE`): XY, XZ (G18) or YZ (G19).
enum class plane { xy, xz, yz };

/// One canonical move as rs274 printed it.
struct canonical_move {
  move_kind kind = move_kind::feed;
  /// X Y Z in `inches` or mm, A B C in degrees: where the move ends.
  std::array<double, 6> end{};
  /// An arc's centre, X Y Z; the coordinate along the arc's axis is not printed (NaN).
  std::array<double, 3> centre{};
  /// An arc's ARC_FEED rotation: positive counter-clockwise (G3), negative clockwise (G2); its
  /// magnitude is the arc's P, the turns it makes (1 without P).
  int rotation = 0;
  plane arc_plane = plane::xy;
  bool inches = false;  ///< the length unit in effect (USE_LENGTH_UNITS)
  std::string call;     ///< the line as printed, for a failure's log
};

/// What a run of rs274 gave: its whole output, its exit status and the moves in it.
struct run {
  std::string text;
  int status = 0;
  std::vector<canonical_move> moves;
};

/// The index in X Y Z of the plane's first, second and axis coordinates (the order ARC_FEED
/// prints them in).
inline std::array<int, 3> arc_order(plane p) {
  return p == plane::xy ? std::array<int, 3>{0, 1, 2} : p == plane::xz ? std::array<int, 3>{2, 0, 1}
                                                                        : std::array<int, 3>{1, 2, 0};
}

/// The moves in rs274's output `text` (what `run_program` returns in `moves`).
inline std::vector<canonical_move> moves_in(std::string_view text) {
  std::vector<canonical_move> moves;
  bool inches = false;
  plane p = plane::xy;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string line(text.substr(start, end - start));
    start = end + 1;
    if (line.find("USE_LENGTH_UNITS(CANON_UNITS_INCHES)") != std::string::npos) inches = true;
    if (line.find("USE_LENGTH_UNITS(CANON_UNITS_MM)") != std::string::npos) inches = false;
    if (line.find("SELECT_PLANE(CANON_PLANE_XY)") != std::string::npos) p = plane::xy;
    if (line.find("SELECT_PLANE(CANON_PLANE_XZ)") != std::string::npos) p = plane::xz;
    if (line.find("SELECT_PLANE(CANON_PLANE_YZ)") != std::string::npos) p = plane::yz;
    canonical_move m;
    m.inches = inches;
    m.call = line;
    double v[12] = {};
    const auto traverse = line.find("STRAIGHT_TRAVERSE("), feed = line.find("STRAIGHT_FEED("), arc = line.find("ARC_FEED(");
    if (traverse != std::string::npos || feed != std::string::npos) {
      const bool t = traverse != std::string::npos;
      const char* args = line.c_str() + (t ? traverse + 18 : feed + 14);
      if (std::sscanf(args, "%lf, %lf, %lf, %lf, %lf, %lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]) != 6) continue;
      m.kind = t ? move_kind::traverse : move_kind::feed;
      for (int k = 0; k < 6; ++k) m.end[k] = v[k];
      moves.push_back(m);
    } else if (arc != std::string::npos) {
      int rotation = 0;
      if (std::sscanf(line.c_str() + arc + 9, "%lf, %lf, %lf, %lf, %d, %lf, %lf, %lf, %lf", &v[0], &v[1], &v[2], &v[3],
                      &rotation, &v[4], &v[5], &v[6], &v[7]) != 9)
        continue;
      m.kind = move_kind::arc;
      m.arc_plane = p;
      m.rotation = rotation;
      const auto o = arc_order(p);
      m.end[o[0]] = v[0], m.end[o[1]] = v[1], m.end[o[2]] = v[4];
      m.end[3] = v[5], m.end[4] = v[6], m.end[5] = v[7];
      m.centre[o[0]] = v[2], m.centre[o[1]] = v[3], m.centre[o[2]] = std::numeric_limits<double>::quiet_NaN();
      moves.push_back(m);
    }
  }
  return moves;
}

/// Runs `rs274 -g` (at `rs274_path`) on `program` (written to a temporary file, removed after),
/// with `options` before `-g` (`-i FILE.ini`: an ini file whose `[RS274NGC] SUBROUTINE_PATH`
/// says where `o<name> call` finds `name.ngc`).
inline run run_program(const std::string& program, const std::string& options = "",
                       const std::string& rs274_path = KIN5_RS274) {
  static int count = 0;
  const auto dir = std::filesystem::temp_directory_path();
  const std::string file =
      (dir / ("kin5-rs274-moves-" + std::to_string(::getpid()) + "-" + std::to_string(count++) + ".ngc")).string();
  std::ofstream(file) << program;
  run out;
  const std::string command = rs274_path + (options.empty() ? "" : " " + options) + " -g " + file + " 2>&1";
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) out.text += buffer;
    out.status = ::pclose(pipe);
  } else {
    out.status = -1;
  }
  std::filesystem::remove(file);
  out.moves = moves_in(out.text);
  return out;
}

}  // namespace kin5::test::rs274
