// The matchability subcommand of the kin5 tool:
//
//   kin5 match --from ID|--from-file FILE --to ID|--to-file FILE [--program FILE] [--from-dialect D]
//              [--format md|csv|svg|json] [--tool-length MM] [--work-offset X,Y,Z]
//
// Without a program: the pair's table (the same text as docs/tables/, computed afresh, Ipopt
// checks included) or its sphere map. With one: the program's report — motion blocks per class,
// the unreachable ones as runs of lines with their worst gap, the rotary travel the target
// needs, the tool-tip range and the slides each block needs against the target's linear travel
// (with the tool length and work offset given) — and, when blocks are unreachable or a slide
// leaves its travel, a setup search whose result is printed as the `--setup-rotation` (and,
// with the work offset given, `--setup-offset`) options of `kin5 translate`. docs/matchability.md explains all of it.
//
// Exit codes (commands.hpp): 0 done and every block reachable; 1 bad arguments; 2 the program
// cannot be read; 3 blocks unreachable under the pair's default setup, or, with --work-offset, a
// slide past its travel (the report is printed).
#include <cstdio>
#include <string>

#include "commands.hpp"

#if KIN5_HAS_REACH

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <kin5/program/io.hpp>
#include <kin5/program/printable.hpp>
#include <kin5/reach.hpp>
#include <kin5/reach/report_text.hpp>
#include <kin5/translate/setup.hpp>

#include "format.hpp"
#include "input_text.hpp"
#include "machine_option.hpp"

namespace kin5::tool {
namespace {

namespace prog = kin5::program;

struct match_arguments {
  machine_choice from, to;
  std::string program, from_dialect, format = "md";
  std::string tool_length, work_offset;  ///< as given; checked as every command checks them (format.hpp)
  double tool_length_mm = 0.0;
  std::vector<double> work_offset_mm;  ///< X, Y, Z of the workpiece frame on the target, or empty
  std::vector<std::string> work_offset_map;  ///< --work-offset-map entries, as `translate` takes them
  std::vector<std::string> tool_map;         ///< --tool-map entries, as `translate` takes them
  prog::read_limits limits;                  ///< what the program may hold, as `translate` takes them
};

run_inputs target_inputs(const match_arguments& a) {
  run_inputs in{.tool_length_mm = a.tool_length_mm};
  if (a.work_offset_mm.size() == 3) in.work_offset.translation_mm = {a.work_offset_mm[0], a.work_offset_mm[1], a.work_offset_mm[2]};
  return in;
}

/// Whether --work-offset says where the part sits: then the slides' ends are checked.
bool placed(const match_arguments& a) { return a.work_offset_mm.size() == 3; }

void print(const std::string& text) { std::fwrite(text.data(), 1, text.size(), stdout); }

int pair_only(const machine_model& from, const machine_model& to, const match_arguments& a) {
  const auto t = reach::make_pair_table(from, to, default_setup(from.geometry.id, to.geometry.id), true);
  if (a.format == "svg") {
    reach::map_text text{t.from + " \u2192 " + t.to, "tool axes in the " + t.from + " workpiece frame", {}};
    print(reach::sphere_svg(t.raster, t.curves, t.markers, text));
  } else {
    print(a.format == "csv" ? reach::csv(t) : a.format == "json" ? reach::json(t) : reach::markdown(t));
  }
  return exit_codes::ok;
}

int with_program(const machine_model& from, const machine_model& to, const match_arguments& a) {
  const std::string name = a.program == "-" ? "<stdin>" : kin5::program::printable(a.program);
  std::string error;
  const auto bytes = read_input(a.program, a.limits, error);
  if (!bytes) {
    std::fprintf(stderr, "kin5 match: cannot read %s: %s\n", name.c_str(), error.c_str());
    return exit_codes::input_error;
  }
  const prog::dialect d = a.from_dialect.empty() ? prog::default_dialect(from.geometry.id).value_or(prog::dialect{})
                                                 : *prog::parse_dialect(a.from_dialect);
  const prog::read_result in = prog::read(d, *bytes, name, a.limits);
  if (!in.ok()) {
    for (const auto& e : in.errors) std::fprintf(stderr, "%s\n", e.to_string().c_str());
    std::fprintf(stderr, "kin5 match: %zu errors in %s; no report\n", in.error_count(), name.c_str());
    return exit_codes::input_error;
  }
  work_offset_map work_offsets;
  std::string map_text;
  for (const auto& entries : a.work_offset_map) {
    if (!work_offsets.add(entries)) {
      std::fprintf(stderr, "kin5 match: --work-offset-map: '%s' is not FROM=TO[,FROM=TO…], or maps a work offset twice\n",
                   entries.c_str());
      return exit_codes::usage;
    }
    map_text += (map_text.empty() ? "" : ",") + entries;
  }
  tool_map tool_numbers;
  for (const auto& entry : a.tool_map)
    if (!tool_numbers.add(entry)) {
      std::fprintf(stderr, "kin5 match: --tool-map: '%s' is not NAME=N (N a whole number of at most 8 digits), or maps a "
                           "tool twice\n", entry.c_str());
      return exit_codes::usage;
    }
  const rigid_transform setup = default_setup(from.geometry.id, to.geometry.id);
  auto report = reach::make_program_report(from, to, in.parsed, setup, true, target_inputs(a), placed(a), work_offsets,
                                           tool_numbers);
  report.work_offset_map_option = map_text;
  report.tool_map_options = a.tool_map;
  std::optional<reach::setup_search_result> search;
  std::optional<reach::chosen_setup> chosen;
  const bool runs = report.unreachable.empty() && !(placed(a) && report.linear_exceeded());
  if (!runs) {
    search = reach::search_setup(from, to, report.source_axes, setup.rotation);
    chosen = reach::choose_setup(from, to, in.parsed, *search, setup.translation_mm, target_inputs(a), placed(a),
                                 work_offsets, tool_numbers);
    if (chosen) chosen->report.work_offset_map_option = map_text, chosen->report.tool_map_options = a.tool_map;
  }
  if (a.format == "svg") {
    const auto t = reach::make_pair_table(from, to, setup, true, false);
    reach::map_text text{t.from + " \u2192 " + t.to + ": " + name, "tool axes of the program's blocks (dots)", {}};
    print(reach::sphere_svg(t.raster, t.curves, t.markers, text, report.source_axes));
  } else if (a.format == "csv") {
    print(reach::report_csv(report));
  } else if (a.format == "json") {
    print(reach::report_json(report, chosen));
  } else {
    print(reach::report_markdown(report, search, chosen));
  }
  return runs ? exit_codes::ok : exit_codes::unreachable;
}

/// --tool-length and --work-offset into `a`'s numbers; false, with the reason printed, when one
/// is not a length the other commands take (`nan`, `inf`, `1e400` were read as such).
bool parse_placement(match_arguments& a) {
  if (!a.tool_length.empty()) {
    const auto l = parse_length_mm(a.tool_length, true);
    if (!l) {
      std::fprintf(stderr, "kin5 match: --tool-length: give a length in mm, 0 or more (within 1e9)\n");
      return false;
    }
    a.tool_length_mm = *l;
  }
  if (!a.work_offset.empty()) {
    const auto w = parse_point_mm(a.work_offset);
    if (!w) {
      std::fprintf(stderr, "kin5 match: --work-offset needs 3 numbers X,Y,Z (mm, within ±1e9)\n");
      return false;
    }
    a.work_offset_mm.assign(w->begin(), w->end());
  }
  return true;
}

int run_match(match_arguments a) {
  if (!parse_placement(a)) return exit_codes::usage;
  int code = exit_codes::ok;
  const std::optional<chosen_machine> from = resolve_machine(a.from, "match", code);
  if (!from) return code;
  const std::optional<chosen_machine> to = resolve_machine(a.to, "match", code);
  if (!to) return code;
  return a.program.empty() ? pair_only(from->model(), to->model(), a) : with_program(from->model(), to->model(), a);
}

}  // namespace

/// The dialects a source program may be in: every one of `program::dialects` but CL data.
std::vector<std::string> source_dialect_names() {
  const auto names = dialect_names([](const prog::capabilities& can) { return !can.cl_data; });
  return {names.begin(), names.end()};
}

void add_match_command(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<match_arguments>();
  auto* sub = app.add_subcommand("match", "Which blocks of a machine another can run: the pair's table, or a program's report");
  add_machine_options(*sub, a->from, "--from", "Source machine");
  add_machine_options(*sub, a->to, "--to", "Target machine");
  sub->add_option("--program", a->program, "NC program of the source machine ('-' for stdin): report on it");
  sub->add_option("--from-dialect", a->from_dialect, "Dialect of the program (default: the --from machine's)")
      ->check(CLI::IsMember(source_dialect_names()));
  sub->add_option("--format", a->format, "md, csv, svg or json")
      ->check(CLI::IsMember({"md", "csv", "svg", "json"}))
      ->capture_default_str();
  sub->add_option("--tool-length", a->tool_length, "Tool length on the target, mm (places the slides)");
  sub->add_option("--work-offset", a->work_offset, "Origin of the workpiece frame on the target X,Y,Z, mm");
  sub->add_option("--work-offset-map", a->work_offset_map,
                  "Work offset selections of the program mapped to the target's, as translate takes them "
                  "(FROM=TO[,FROM=TO…])")
      ->allow_extra_args(false);
  sub->add_option("--tool-map", a->tool_map,
                  "A tool the program calls by name as tool number N (NAME=N, once per tool), as translate takes it")
      ->allow_extra_args(false);
  add_limit_options(sub, a->limits);
  sub->footer("Exit codes: 0 every block reachable (or no program), 1 bad arguments, 2 the program cannot be read,\n"
              "3 blocks unreachable under the pair's default setup, or with --work-offset a slide past its travel\n"
              "(the report says which, and a setup that helps).");
  sub->callback([a, &exit_code] { exit_code = run_match(*a); });
}

}  // namespace kin5::tool

#else  // built without Ipopt

namespace kin5::tool {

void add_match_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("match", "Matchability tables and program reports (needs kin5::reach, Ipopt)");
  sub->allow_extras();
  sub->callback([&exit_code] {
    std::fprintf(stderr, "kin5 match: this kin5 was built without Ipopt (kin5::reach)\n");
    exit_code = exit_codes::usage;
  });
}

}  // namespace kin5::tool

#endif
