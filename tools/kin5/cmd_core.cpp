// The core subcommands of the kin5 tool, each a few calls into the headers on a machine value
// (machine_model), so a machine known only at run time runs the same code:
//
//   kin5 machines [--file ID | --machine-file FILE] the bundled machines, one per line; or the
//                                                   machine file of one; or a file's machine
//   kin5 solve --machine ID --vector I,J,K          every rotary solution within travel (G1)-(G5)
//              [--tip X,Y,Z [--tool-length L] [--work-offset X,Y,Z]]
//                                                   with --tip: every axis solution (G7)
//   kin5 fk --machine ID NAME=DEG ...               the unit tool axis (G1)
//           [X=MM Y=MM Z=MM] [--tool-length L] [--work-offset X,Y,Z]
//                                                   with X, Y, Z: the tip and the axis (G6)
//
// Wherever --machine ID is accepted, --machine-file FILE may be given instead (machine_option.hpp).
// Exit codes are those of commands.hpp: 0 success, 1 bad arguments, 2 a bad machine file,
// 3 no solution.
// Messages go to stderr as one line starting with "kin5 <command>:".
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <kin5/kin5.hpp>
#include <kin5/machines/every_machine.hpp>
#include <kin5/machines/machine_file_writer.hpp>

#include "commands.hpp"
#include "format.hpp"
#include "machine_option.hpp"

namespace kin5::tool {
namespace {

/// The indices of m's rotary axes in NC address order (A, B, C), the order output is written in.
std::vector<std::size_t> letter_order(const machine_model& m) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < m.rotary_count; ++i) order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return m.rotary(a).letter < m.rotary(b).letter; });
  return order;
}

/// "X, Y, Z, C, B": m's axis letters, linear then rotary in chain order (workpiece to tool).
std::string axis_names(const machine_model& m) {
  std::string out = "X, Y, Z";
  for (std::size_t i = 0; i < m.rotary_count; ++i) (out += ", ") += to_char(m.rotary(i).letter);
  return out;
}

/// A limit as a person writes it: "-120", "30", "22.5".
std::string format_limit(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// A length in mm with 6 decimals ("12.500000"); "-0.000000" is written "0.000000".
std::string format_mm(double v) { return format_degrees(v); }

/// "B table continuous tool-relative" or "A head [-120, 30] deg tool-relative".
std::string describe(const rotary_axis& a) {
  std::string out(1, to_char(a.letter));
  out += a.side == mount::head ? " head" : " table";
  out += a.travel.continuous ? std::string(" continuous")
                             : " [" + format_limit(a.travel.lower.value) + ", " + format_limit(a.travel.upper.value) + "] deg";
  out += a.sense == angle_sense::physical ? " physical" : " tool-relative";
  return out;
}

/// "X,Y,Z" as a vector, or an error naming `option`.
std::optional<vec3> parse_triple(std::string_view text, std::string_view option, std::string_view names,
                                 std::string& error) {
  const auto fields = split(text, ',');
  if (fields.size() != 3) {
    error = std::string(option) + " needs three numbers " + std::string(names) + " separated by commas, got '" +
            std::string(text) + "'";
    return std::nullopt;
  }
  std::array<double, 3> c{};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto v = parse_real(fields[i]);
    if (!v) {
      error = std::string(option) + " component '" + std::string(fields[i]) + "' is not a finite number";
      return std::nullopt;
    }
    c[i] = *v;
  }
  return vec3{c[0], c[1], c[2]};
}

/// The unit vector of "I,J,K", or an error message. Scaled before normalising so that large
/// finite components cannot overflow.
std::optional<vec3> parse_direction(std::string_view text, std::string& error) {
  const auto v = parse_triple(text, "--vector", "I,J,K", error);
  if (!v) return std::nullopt;
  const double scale = std::max({std::fabs(v->x), std::fabs(v->y), std::fabs(v->z)});
  if (!(scale > 0)) {
    error = "--vector must not be the zero vector";
    return std::nullopt;
  }
  return normalized((1.0 / scale) * *v);
}

/// The run-time inputs from --tool-length and --work-offset.
std::optional<run_inputs> parse_inputs(const std::string& tool_length, const std::string& work_offset,
                                       std::string& error) {
  run_inputs in{};
  if (!tool_length.empty()) {
    const auto l = parse_length_mm(tool_length);
    if (!l) {
      error = "--tool-length '" + tool_length + "' is not a finite number of mm within ±1e9";
      return std::nullopt;
    }
    in.tool_length_mm = *l;
  }
  if (!work_offset.empty()) {
    const auto w = parse_triple(work_offset, "--work-offset", "X,Y,Z", error);
    if (!w) return std::nullopt;
    if (!parse_point_mm(work_offset)) {
      error = "--work-offset '" + work_offset + "': each number must be within ±1e9 mm";
      return std::nullopt;
    }
    in.work_offset.translation_mm = *w;
  }
  return in;
}

// ---- machines ---------------------------------------------------------------------------

struct machines_arguments {
  std::string file_of;       // --file ID
  std::string machine_file;  // --machine-file FILE
};

/// "id  structure; axes workpiece to tool: ..." for one machine, the id padded to `width`.
std::string machine_line(const machine_model& m, std::size_t width) {
  std::string line(m.geometry.id);
  line.resize(std::max(width, line.size()) + 2, ' ');
  line += m.geometry.structure;
  line += "; axes workpiece to tool: ";
  for (std::size_t i = 0; i < m.rotary_count; ++i) {
    if (i) line += ", ";
    line += describe(m.rotary(i));
  }
  return line;
}

int run_machines(const machines_arguments& args) {
  if (!args.file_of.empty() && !args.machine_file.empty()) {
    std::cerr << "kin5 machines: give at most one of --file and --machine-file\n";
    return exit_codes::usage;
  }
  int exit_code = exit_codes::ok;
  if (!args.file_of.empty() || !args.machine_file.empty()) {
    const auto m = resolve_machine({args.file_of, args.machine_file, "--file"}, "machines", exit_code);
    if (!m) return exit_code;
    if (!args.file_of.empty()) std::cout << to_machine_file(m->model().geometry);
    else std::cout << machine_line(m->model(), 0) << '\n';
    return exit_codes::ok;
  }
  std::size_t width = 0;
  kin5::machines::for_each_machine_in<kin5::machines::every_machine>(
      [&]<class M>() { width = std::max(width, M::id.size()); });
  kin5::machines::for_each_machine_in<kin5::machines::every_machine>(
      [&]<class M>() { std::cout << machine_line(M::model, width) << '\n'; });
  return exit_codes::ok;
}

// ---- solve ------------------------------------------------------------------------------

struct solve_arguments {
  machine_choice machine;
  std::string vector_text;
  std::string tip_text;
  std::string tool_length;
  std::string work_offset;
};

/// "A=… B=…" for rotary angles of m, in letter order.
std::string rotary_words(const machine_model& m, const rotary_values& angles) {
  std::string line;
  for (std::size_t k : letter_order(m)) {
    if (!line.empty()) line += ' ';
    line += to_char(m.rotary(k).letter);
    line += '=';
    line += format_degrees(to_degrees(angles[k]).value);
  }
  return line;
}

void note_pole(const machine_model& m) {
  const char p = to_char(m.rotary(0).letter);
  std::cerr << "kin5 solve: pole: the tool axis lies along the " << p << " axis, so " << p << " is free and set to 0\n";
}

int solve_axis(const machine_model& m, const vec3& u) {
  const auto result = inverse(m, u);
  if (!result.reachable()) {
    std::cerr << "kin5 solve: no solution within travel on " << m.geometry.id << ": the tool axis is "
              << format_degrees(to_degrees(result.gap).value) << " deg from what the machine can reach\n";
    return exit_codes::unreachable;
  }
  if (result.status == reach_status::pole) note_pole(m);
  for (const auto& s : result)
    if (s.within_travel) std::cout << rotary_words(m, s.angles) << '\n';
  return exit_codes::ok;
}

int solve_pose(const machine_model& m, const tool_pose& target, const run_inputs& in) {
  const auto result = inverse(m, target, in);
  if (!result.reachable()) {
    std::cerr << "kin5 solve: no solution within travel on " << m.geometry.id << ": ";
    if (result.gap.value > 0.0)
      std::cerr << "the tool axis is " << format_degrees(to_degrees(result.gap).value)
                << " deg from what the machine can reach\n";
    else
      std::cerr << "the linear axes would leave their travel by " << format_mm(result.linear_excess_mm) << " mm\n";
    return exit_codes::unreachable;
  }
  if (result.status == reach_status::pole) note_pole(m);
  for (const auto& s : result) {
    if (!s.within_travel) continue;
    std::cout << "X=" << format_mm(s.joints.xyz_mm.x) << " Y=" << format_mm(s.joints.xyz_mm.y)
              << " Z=" << format_mm(s.joints.xyz_mm.z) << ' ' << rotary_words(m, s.joints.rotary) << '\n';
  }
  return exit_codes::ok;
}

int run_solve(const solve_arguments& args) {
  std::string error;
  const auto u = parse_direction(args.vector_text, error);
  std::optional<vec3> tip;
  if (u && !args.tip_text.empty()) tip = parse_triple(args.tip_text, "--tip", "X,Y,Z", error);
  const auto in = error.empty() ? parse_inputs(args.tool_length, args.work_offset, error) : std::nullopt;
  if (error.empty() && args.tip_text.empty() && (!args.tool_length.empty() || !args.work_offset.empty()))
    error = "--tool-length and --work-offset need --tip";
  if (!error.empty()) {
    std::cerr << "kin5 solve: " << error << '\n';
    return exit_codes::usage;
  }
  int exit_code = exit_codes::ok;
  const auto m = resolve_machine(args.machine, "solve", exit_code);
  if (!m) return exit_code;
  return tip ? solve_pose(m->model(), {*tip, *u}, *in) : solve_axis(m->model(), *u);
}

// ---- fk ---------------------------------------------------------------------------------

struct fk_arguments {
  machine_choice machine;
  std::vector<std::string> values;  // "NAME=VALUE"
  std::string tool_length;
  std::string work_offset;
};

/// m's axis values from "NAME=VALUE" arguments: each rotary axis exactly once (degrees), and X,
/// Y, Z (mm) all or none. `linear` says whether they were given.
std::optional<axis_values> parse_axis_values(const machine_model& m, const std::vector<std::string>& values,
                                             bool& linear, std::string& error) {
  axis_values q{};
  std::array<bool, 5> seen{};  // X, Y, Z, rotary[0], rotary[1]
  for (const std::string& arg : values) {
    const auto eq = arg.find('=');
    if (eq == std::string::npos) {
      error = "'" + arg + "' is not NAME=DEG or X=MM, Y=MM, Z=MM (axes of " + std::string(m.geometry.id) + ": " + axis_names(m) + ")";
      return std::nullopt;
    }
    const std::string_view name = std::string_view(arg).substr(0, eq);
    const std::string_view number = std::string_view(arg).substr(eq + 1);
    std::size_t index = seen.size();
    if (name.size() == 1) {
      const char letter = (name[0] >= 'a' && name[0] <= 'z') ? static_cast<char>(name[0] - 'a' + 'A') : name[0];
      if (letter >= 'X' && letter <= 'Z') index = static_cast<std::size_t>(letter - 'X');
      for (std::size_t i = 0; i < m.rotary_count; ++i)
        if (to_char(m.rotary(i).letter) == letter) index = 3 + i;
    }
    if (index == seen.size()) {
      const bool rotary_name = name.size() == 1 && std::string_view("ABCabc").find(name[0]) != std::string_view::npos;
      error = std::string(m.geometry.id) + " has no " + (rotary_name ? "rotary " : "") + "axis '" + std::string(name) +
              "'; its axes are " + axis_names(m);
      return std::nullopt;
    }
    if (seen[index]) {
      error = "axis " + std::string(name) + " is given more than once";
      return std::nullopt;
    }
    const auto v = parse_real(number);
    if (!v) {
      error = "'" + arg + "': '" + std::string(number) + "' is not a finite number";
      return std::nullopt;
    }
    seen[index] = true;
    if (index < 3) (index == 0 ? q.xyz_mm.x : index == 1 ? q.xyz_mm.y : q.xyz_mm.z) = *v;
    else q.rotary[index - 3] = to_radians(degrees{*v});
  }
  for (std::size_t i = 0; i < m.rotary_count; ++i) {
    if (!seen[3 + i]) {
      error = std::string("missing a value for axis ") + to_char(m.rotary(i).letter) + " (axes of " +
              std::string(m.geometry.id) + ": " + axis_names(m) + ")";
      return std::nullopt;
    }
  }
  linear = seen[0] || seen[1] || seen[2];
  if (linear && !(seen[0] && seen[1] && seen[2])) {
    error = "give all of X, Y and Z, or none (the tool axis alone)";
    return std::nullopt;
  }
  return q;
}

int fk_on(const machine_model& m, const fk_arguments& args) {
  std::string error;
  bool linear = false;
  const auto q = parse_axis_values(m, args.values, linear, error);
  const auto in = q ? parse_inputs(args.tool_length, args.work_offset, error) : std::nullopt;
  if (q && in && !linear && (!args.tool_length.empty() || !args.work_offset.empty()))
    error = "--tool-length and --work-offset need X, Y and Z";
  if (!error.empty()) {
    std::cerr << "kin5 fk: " << error << '\n';
    return exit_codes::usage;
  }
  for (std::size_t i = 0; i < m.rotary_count; ++i)
    if (!m.rotary(i).travel.contains(q->rotary[i]))
      std::cerr << "kin5 fk: note: " << describe(m.rotary(i)) << ": "
                << format_degrees(to_degrees(q->rotary[i]).value) << " is outside its travel\n";
  if (!linear) {
    const vec3 u = tool_axis(m, q->rotary);
    std::cout << format_component(u.x) << ' ' << format_component(u.y) << ' ' << format_component(u.z) << '\n';
    return exit_codes::ok;
  }
  const double x[3] = {q->xyz_mm.x, q->xyz_mm.y, q->xyz_mm.z};
  for (std::size_t i = 0; i < 3; ++i)
    if (!m.linear(i).travel.contains(x[i]))
      std::cerr << "kin5 fk: note: " << to_char(m.linear(i).letter) << ": " << format_mm(x[i])
                << " mm is outside its travel [" << format_limit(m.linear(i).travel.lower_mm) << ", "
                << format_limit(m.linear(i).travel.upper_mm) << "] mm\n";
  const tool_pose pose = forward(m, *q, *in);
  std::cout << "tip " << format_mm(pose.tip_mm.x) << ' ' << format_mm(pose.tip_mm.y) << ' ' << format_mm(pose.tip_mm.z)
            << '\n';
  std::cout << "axis " << format_component(pose.axis.x) << ' ' << format_component(pose.axis.y) << ' '
            << format_component(pose.axis.z) << '\n';
  return exit_codes::ok;
}

int run_fk(const fk_arguments& args) {
  int exit_code = exit_codes::ok;
  const auto m = resolve_machine(args.machine, "fk", exit_code);
  if (!m) return exit_code;
  return fk_on(m->model(), args);
}

}  // namespace

void add_machines_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<machines_arguments>();
  auto* sub = app.add_subcommand("machines", "List the bundled machines: id, structure, rotary axes and travel");
  sub->add_option("--file", args->file_of, "Print the machine file (TOML) of the bundled machine ID");
  sub->add_option("--machine-file", args->machine_file, "Check a machine file and describe its machine");
  sub->callback([args, &exit_code] { exit_code = run_machines(*args); });
}

void add_solve_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<solve_arguments>();
  auto* sub = app.add_subcommand("solve", "Every set of axis values within travel that gives a tool axis (and tip)");
  add_machine_options(*sub, args->machine);
  sub->add_option("--vector,-v", args->vector_text,
                  "Tool axis I,J,K in the workpiece frame, tip towards spindle; need not be unit")
      ->required();
  sub->add_option("--tip", args->tip_text, "Tool tip X,Y,Z in the workpiece frame, mm: solve every axis");
  sub->add_option("--tool-length", args->tool_length, "Tool length, gauge point to tip, mm (with --tip; default 0)");
  sub->add_option("--work-offset", args->work_offset,
                  "Workpiece origin X,Y,Z in machine coordinates at the zero pose, mm (with --tip; default 0,0,0)");
  sub->footer(
      "Prints one solution per line as NAME=VALUE pairs (degrees, and mm for X Y Z with --tip). Exit 3 when no "
      "solution is within travel.\n");
  sub->callback([args, &exit_code] { exit_code = run_solve(*args); });
}

void add_fk_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<fk_arguments>();
  auto* sub = app.add_subcommand("fk", "The unit tool axis for rotary angles; with X Y Z, the tool tip too");
  add_machine_options(*sub, args->machine);
  sub->add_option("--tool-length", args->tool_length, "Tool length, gauge point to tip, mm (with X Y Z; default 0)");
  sub->add_option("--work-offset", args->work_offset,
                  "Workpiece origin X,Y,Z in machine coordinates at the zero pose, mm (with X Y Z; default 0,0,0)");
  sub->add_option("values", args->values,
                  "One NAME=DEG per rotary axis, e.g. B=90 C=0; and X=MM Y=MM Z=MM in machine coordinates");
  sub->footer("Without X Y Z prints I J K. With them prints 'tip X Y Z' (mm, workpiece frame) and 'axis I J K'.\n");
  sub->callback([args, &exit_code] { exit_code = run_fk(*args); });
}

}  // namespace kin5::tool
