/// @file machines/machine_file_writer.hpp
/// Writing a machine as a machine file (TOML, schema in docs/machine-files.md): the text that
/// `read_machine_file` turns back into the same geometry, every number written with 17
/// significant digits so that it reads back bit for bit. Standard library only.
/// @code
///   std::cout << kin5::to_machine_file(kin5::machines::ac_trunnion::model.geometry);
/// @endcode
#pragma once

#include <cstdio>
#include <string>

#include "../kinematics/machine_model.hpp"

namespace kin5 {

namespace machine_file_detail {

/// `v` with 17 significant digits, shortest form ("-120", "0.70710678118654757").
inline std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

inline std::string vector_text(const vec3& v) {
  return "[" + number_text(v.x) + ", " + number_text(v.y) + ", " + number_text(v.z) + "]";
}

/// A TOML basic string: quotes and backslashes escaped, control characters as \uXXXX.
inline std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') (out += '\\') += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else out += c;
  }
  return out + '"';
}

inline std::string side_text(mount m) { return m == mount::head ? "\"head\"" : "\"table\""; }

}  // namespace machine_file_detail

/// The machine file of `g` (every rotary axis in chain order, workpiece to tool).
inline std::string to_machine_file(const machine_geometry& g) {
  using namespace machine_file_detail;
  std::string out = "# kin5 machine file (docs/machine-files.md). Lengths in mm, angles in degrees, directions\n"
                    "# unit vectors in the machine frame at the zero pose.\n";
  out += "kin5_machine = 1\n";
  out += "id = " + quoted(g.id) + "\n";
  out += "structure = " + quoted(g.structure) + "\n\n";
  out += "[tool]\nreference = " + vector_text(g.tool.reference) + "\n";
  out += "pivot_length_mm = " + number_text(g.tool.pivot_length_mm) + "\n";
  for (const linear_axis& a : g.linear) {
    out += std::string("\n[linear.") + to_char(a.letter) + "]\n";
    out += "direction = " + vector_text(a.direction) + "\nside = " + side_text(a.side) + "\n";
    out += "travel_mm = [" + number_text(a.travel.lower_mm) + ", " + number_text(a.travel.upper_mm) + "]\n";
    if (a.home_mm) out += "home_mm = " + number_text(*a.home_mm) + "\n";
  }
  for (const rotary_axis& a : g.rotary) {
    if (a.letter == axis_letter::none) break;
    out += std::string("\n[[rotary]]\nletter = \"") + to_char(a.letter) + "\"\n";
    out += "side = " + side_text(a.side) + "\ndirection = " + vector_text(a.direction) + "\n";
    out += "point_mm = " + vector_text(a.point_mm) + "\n";
    out += std::string("sense = ") + (a.sense == angle_sense::physical ? "\"physical\"" : "\"tool-relative\"") + "\n";
    if (a.travel.continuous) out += "continuous = true\n";
    else out += "travel_deg = [" + number_text(a.travel.lower.value) + ", " + number_text(a.travel.upper.value) + "]\n";
    if (a.home_deg) out += "home_deg = " + number_text(a.home_deg->value) + "\n";
  }
  return out;
}

}  // namespace kin5
