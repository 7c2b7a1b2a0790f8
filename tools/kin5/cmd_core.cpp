// The core subcommands of the kin5 tool, each a few calls into the headers:
//
//   kin5 machines                              the catalog, one machine per line
//   kin5 solve --machine ID --vector I,J,K     every solution within travel (inverse<M>, (G1)-(G5))
//   kin5 fk --machine ID NAME=DEG NAME=DEG     the unit tool axis (tool_axis<M>, (G1))
//
// Exit codes are those of commands.hpp: 0 success, 1 bad arguments, 3 no solution.
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

#include "commands.hpp"
#include "format.hpp"

namespace kin5::tool {
namespace {

/// The indices of M's rotary axes in NC address order (A, B, C), the order output is written in.
template <machine M>
std::array<std::size_t, rotary_count<M>> letter_order() {
  std::array<std::size_t, rotary_count<M>> order{};
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [](std::size_t a, std::size_t b) { return M::rotary[a].letter < M::rotary[b].letter; });
  return order;
}

/// "C, B": M's rotary axis letters in chain order (workpiece to tool).
template <machine M>
std::string axis_names() {
  std::string out;
  for (std::size_t i = 0; i < rotary_count<M>; ++i) {
    if (i) out += ", ";
    out += to_char(M::rotary[i].letter);
  }
  return out;
}

/// A travel limit in degrees as a person writes it: "-120", "30", "22.5".
std::string format_limit(degrees d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", d.value);
  return buf;
}

/// "B table continuous tool-relative" or "A head [-120, 30] deg tool-relative".
std::string describe(const rotary_axis& a) {
  std::string out(1, to_char(a.letter));
  out += a.side == mount::head ? " head" : " table";
  out += a.travel.continuous
             ? std::string(" continuous")
             : " [" + format_limit(a.travel.lower) + ", " + format_limit(a.travel.upper) + "] deg";
  out += a.sense == angle_sense::physical ? " physical" : " tool-relative";
  return out;
}

void report_unknown_machine(std::string_view command, std::string_view id) {
  std::cerr << "kin5 " << command << ": unknown machine '" << id << "'; valid ids: " << join(machine_ids()) << '\n';
}

// ---- machines ---------------------------------------------------------------------------

int run_machines() {
  std::size_t width = 0;
  for (auto id : machine_ids()) width = std::max(width, id.size());
  kin5::machines::for_each_machine([&]<class M>() {
    std::string line(M::id);
    line.resize(width + 2, ' ');
    line += M::structure;
    line += "; axes workpiece to tool: ";
    for (std::size_t i = 0; i < rotary_count<M>; ++i) {
      if (i) line += ", ";
      line += describe(M::rotary[i]);
    }
    std::cout << line << '\n';
  });
  return exit_codes::ok;
}

// ---- solve ------------------------------------------------------------------------------

struct solve_arguments {
  std::string machine_id;
  std::string vector_text;
};

/// The unit vector of "I,J,K", or an error message. Scaled before normalising so that large
/// finite components cannot overflow.
std::optional<vec3> parse_direction(std::string_view text, std::string& error) {
  const auto fields = split(text, ',');
  if (fields.size() != 3) {
    error = "--vector needs three numbers I,J,K separated by commas, got '" + std::string(text) + "'";
    return std::nullopt;
  }
  std::array<double, 3> c{};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto v = parse_real(fields[i]);
    if (!v) {
      error = "--vector component '" + std::string(fields[i]) + "' is not a finite number";
      return std::nullopt;
    }
    c[i] = *v;
  }
  const double scale = std::max({std::fabs(c[0]), std::fabs(c[1]), std::fabs(c[2])});
  if (!(scale > 0)) {
    error = "--vector must not be the zero vector";
    return std::nullopt;
  }
  return normalized(vec3{c[0] / scale, c[1] / scale, c[2] / scale});
}

template <machine M>
int solve_on(const vec3& u) {
  const auto result = inverse<M>(u);
  if (!result.reachable()) {
    std::cerr << "kin5 solve: no solution within travel on " << M::id << ": the tool axis is "
              << format_degrees(to_degrees(result.gap).value) << " deg from what the machine can reach\n";
    return exit_codes::unreachable;
  }
  if (result.status == reach_status::pole)
    std::cerr << "kin5 solve: pole: the tool axis lies along the " << to_char(M::rotary[0].letter)
              << " axis, so " << to_char(M::rotary[0].letter) << " is free and set to 0\n";
  const auto order = letter_order<M>();
  for (const auto& s : result) {
    if (!s.within_travel) continue;
    std::string line;
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k) line += ' ';
      line += to_char(M::rotary[order[k]].letter);
      line += '=';
      line += format_degrees(to_degrees(s.angles[order[k]]).value);
    }
    std::cout << line << '\n';
  }
  return exit_codes::ok;
}

int run_solve(const solve_arguments& args) {
  std::string error;
  const auto u = parse_direction(args.vector_text, error);
  if (!u) {
    std::cerr << "kin5 solve: " << error << '\n';
    return exit_codes::usage;
  }
  int code = exit_codes::ok;
  if (!with_machine(args.machine_id, [&]<class M>() { code = solve_on<M>(*u); })) {
    report_unknown_machine("solve", args.machine_id);
    return exit_codes::usage;
  }
  return code;
}

// ---- fk ---------------------------------------------------------------------------------

struct fk_arguments {
  std::string machine_id;
  std::vector<std::string> values;  // "NAME=DEG"
};

/// M's commanded angles from "NAME=DEG" arguments, each rotary axis exactly once.
template <machine M>
std::optional<rotary_angles<M>> parse_axis_values(const std::vector<std::string>& values, std::string& error) {
  rotary_angles<M> angles{};
  std::array<bool, rotary_count<M>> seen{};
  for (const std::string& arg : values) {
    const auto eq = arg.find('=');
    if (eq == std::string::npos) {
      error = "'" + arg + "' is not NAME=DEG (axes of " + std::string(M::id) + ": " + axis_names<M>() + ")";
      return std::nullopt;
    }
    const std::string_view name = std::string_view(arg).substr(0, eq);
    const std::string_view number = std::string_view(arg).substr(eq + 1);
    std::size_t index = rotary_count<M>;
    if (name.size() == 1) {
      const char letter = (name[0] >= 'a' && name[0] <= 'z') ? static_cast<char>(name[0] - 'a' + 'A') : name[0];
      for (std::size_t i = 0; i < rotary_count<M>; ++i)
        if (to_char(M::rotary[i].letter) == letter) index = i;
    }
    if (index == rotary_count<M>) {
      error = std::string(M::id) + " has no rotary axis '" + std::string(name) + "'; its axes are " + axis_names<M>();
      return std::nullopt;
    }
    if (seen[index]) {
      error = "axis " + std::string(name) + " is given more than once";
      return std::nullopt;
    }
    const auto deg = parse_real(number);
    if (!deg) {
      error = "'" + arg + "': '" + std::string(number) + "' is not a finite number of degrees";
      return std::nullopt;
    }
    seen[index] = true;
    angles[index] = to_radians(degrees{*deg});
  }
  for (std::size_t i = 0; i < rotary_count<M>; ++i) {
    if (!seen[i]) {
      error = std::string("missing a value for axis ") + to_char(M::rotary[i].letter) + " (axes of " +
              std::string(M::id) + ": " + axis_names<M>() + ")";
      return std::nullopt;
    }
  }
  return angles;
}

template <machine M>
int fk_on(const std::vector<std::string>& values) {
  std::string error;
  const auto angles = parse_axis_values<M>(values, error);
  if (!angles) {
    std::cerr << "kin5 fk: " << error << '\n';
    return exit_codes::usage;
  }
  for (std::size_t i = 0; i < rotary_count<M>; ++i)
    if (!M::rotary[i].travel.contains((*angles)[i]))
      std::cerr << "kin5 fk: note: " << describe(M::rotary[i]) << ": "
                << format_degrees(to_degrees((*angles)[i]).value) << " is outside its travel\n";
  const vec3 u = tool_axis<M>(*angles);
  std::cout << format_component(u.x) << ' ' << format_component(u.y) << ' ' << format_component(u.z) << '\n';
  return exit_codes::ok;
}

int run_fk(const fk_arguments& args) {
  int code = exit_codes::ok;
  if (!with_machine(args.machine_id, [&]<class M>() { code = fk_on<M>(args.values); })) {
    report_unknown_machine("fk", args.machine_id);
    return exit_codes::usage;
  }
  return code;
}

}  // namespace

void add_machines_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("machines", "List the catalog machines: id, structure, rotary axes and travel");
  sub->callback([&exit_code] { exit_code = run_machines(); });
}

void add_solve_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<solve_arguments>();
  auto* sub = app.add_subcommand("solve", "Every set of rotary angles within travel that gives a tool axis");
  sub->add_option("--machine,-m", args->machine_id, "Catalog machine id (see `kin5 machines`)")->required();
  sub->add_option("--vector,-v", args->vector_text,
                  "Tool axis I,J,K in the workpiece frame, tip towards spindle; need not be unit")
      ->required();
  sub->footer("Prints one solution per line as NAME=DEG pairs. Exit 3 when no solution is within travel.\n");
  sub->callback([args, &exit_code] { exit_code = run_solve(*args); });
}

void add_fk_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<fk_arguments>();
  auto* sub = app.add_subcommand("fk", "The unit tool axis I J K for commanded rotary angles");
  sub->add_option("--machine,-m", args->machine_id, "Catalog machine id (see `kin5 machines`)")->required();
  sub->add_option("values", args->values, "One NAME=DEG per rotary axis, e.g. B=90 C=0");
  sub->callback([args, &exit_code] { exit_code = run_fk(*args); });
}

}  // namespace kin5::tool
