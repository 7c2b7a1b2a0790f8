// The program subcommands of the kin5 tool: a whole NC program in, a whole program out.
//
//   kin5 translate --from ID --to ID [--feed P] [--from-dialect D] [--to-dialect D] [-o OUT] IN
//   kin5 reverse   --machine ID [--dialect D] [-o OUT] IN       NC program -> APT CL data
//   kin5 post      --machine ID [--dialect D] [-o OUT] IN       APT CL data -> NC program
//   kin5 canon     [--dialect D] IN                             the program's canonical operations
// (each machine also as a machine file: --from-file, --to-file, --machine-file; machine_option.hpp)
//
// Each one reads IN (a path, or '-' for stdin) as bytes and runs a `block_translator`
// (translate/pipeline.hpp: make_translator / make_reverse / make_post, on machine values) over them with the library's
// streaming driver (translate/stream.hpp: two passes, the second over compact block records),
// which writes each output block as it is made to OUT (a path, or '-' / nothing for stdout).
// Everything else goes to stderr:
//   * every diagnostic as `FILE:LINE:COL: error: ...` or `... warning: ...`;
//   * every block the target cannot reach, as an error at the block, with its source angles
//     and the angular gap; a run of consecutive ones as one error, with its worst block;
//   * of each severity the first 100 (errors beyond them counted, in one line);
//   * one summary line: blocks read, written, passed through, and per matchability class.
// With --report FILE.json, the account of the run as JSON (translate/run_report.hpp), written
// whatever the exit code, as OUT is (a temporary file linked into place).
//
// Exit codes (commands.hpp): 0 written; 1 bad arguments; 2 the input cannot be read or
// translated, or the output cannot be written; 3 blocks unreachable on the target. On any
// non-zero exit OUT is neither created nor changed (output_file.hpp: a temporary file linked or
// renamed into place when complete; FIFOs, devices and stdout get the text only then).
#include <algorithm>
#include <array>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <kin5/machines/tool_table_file.hpp>
#include <kin5/program/canonical/block_operations.hpp>
#include <kin5/program/canonical/print.hpp>
#include <kin5/program/io.hpp>
#include <kin5/program/number.hpp>
#include <kin5/program/printable.hpp>
#include <kin5/translate/run_report.hpp>
#include <kin5/translate/translate.hpp>
#include <kin5/translate/stream.hpp>

#include "commands.hpp"
#include "format.hpp"
#include "input_text.hpp"
#include "machine_option.hpp"
#include "output_file.hpp"
#include "same_file.hpp"

namespace kin5::tool {
namespace {

namespace prog = kin5::program;

/// The NC dialects of `program::dialects`: every one but CL data, which `translate` neither reads
/// nor writes.
std::vector<std::string_view> nc_dialect_names() {
  return dialect_names([](const prog::capabilities& can) { return !can.cl_data; });
}

// ---- files --------------------------------------------------------------------------------

/// The name diagnostics use for IN: the path as given, or `<stdin>` for '-'.
std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : prog::printable(path); }

// ---- reporting ----------------------------------------------------------------------------

/// A diagnostic with its severity ("error", "warning", "note").
struct message {
  const char* severity;
  prog::diagnostic diagnostic;
};

/// Adds every diagnostic of `from` to `to` with severity `severity`.
void collect(std::vector<message>& to, const std::vector<prog::diagnostic>& from, const char* severity) {
  for (const auto& d : from) to.push_back({severity, d});
}

/// Messages of one severity printed by one `print_in_source_order`; the rest are counted.
constexpr std::size_t max_shown = 100;

/// Prints `messages` in source order (line, then column; ties in the order collected), each
/// as `FILE:LINE:COL: severity: text`, the format compilers use (`FILE: severity: text` for a
/// message about the whole file): the first `max_shown` of each severity, then one line with
/// the count of those not shown.
/// `not_kept`: errors and warnings the reader only counted (`read_result`), among those not shown.
void print_in_source_order(std::vector<message> messages, const std::string& prefix,
                           std::array<std::size_t, 2> not_kept = {}) {
  std::stable_sort(messages.begin(), messages.end(), [](const message& a, const message& b) {
    const auto& l = a.diagnostic.where;
    const auto& r = b.diagnostic.where;
    return l.line != r.line ? l.line < r.line : l.column < r.column;
  });
  constexpr std::string_view severities[] = {"error", "warning", "note"};
  std::size_t shown[3] = {}, hidden[3] = {not_kept[0], not_kept[1], 0};
  for (const auto& m : messages) {
    const auto k = static_cast<std::size_t>(std::find(severities, severities + 2, m.severity) - severities);
    if (shown[k] == max_shown) {
      ++hidden[k];
      continue;
    }
    ++shown[k];
    const auto& where = m.diagnostic.where;
    if (where.line == 0)  // about the whole file
      std::cerr << prog::printable(where.file.str()) << ": " << m.severity << ": " << prog::printable(m.diagnostic.message)
                << '\n';
    else
      std::cerr << m.diagnostic.to_string(m.severity) << '\n';
  }
  for (std::size_t k = 0; k < 3; ++k)
    if (hidden[k])
      std::cerr << prefix << hidden[k] << " more " << severities[k] << (hidden[k] == 1 ? "" : "s")
                << " not shown (the first " << max_shown << " are)\n";
}

/// A note for a block translated on the other solution branch (listed with --verbose), with the
/// calls it ran in (`calls`: the reader's).
prog::diagnostic other_branch_note(const block_report& r, const prog::call_chains& calls) {
  std::string text = "translated on the other solution branch";
  if (!r.source_angles.empty()) text += ": " + r.source_angles;
  if (!r.why.empty()) text += " (" + r.why + ")";
  prog::diagnostic note{r.where, text};
  if (r.call_chain != 0 && r.call_chain <= calls.size()) note.called_from = calls.sites(r.call_chain);
  return note;
}

/// One error for a run of more than one unreachable block, at its first block.
prog::diagnostic range_error(const unreachable_range& r, const std::string& target) {
  return {r.first, target + " cannot reach the " + std::to_string(r.blocks) + " blocks of lines " +
                       std::to_string(r.first.line) + "-" + std::to_string(r.last.line) + "; the worst, at line " +
                       std::to_string(r.worst.line) + ": " + r.worst_why};
}

/// The errors of `t`, but each run of more than one unreachable block (`ranges`) as one error
/// (`range_error`) in place of one per block.
std::vector<prog::diagnostic> errors_by_run(const translation& t, const std::vector<unreachable_range>& ranges,
                                            const std::string& target) {
  std::vector<prog::diagnostic> out;
  for (const auto& r : ranges)
    if (r.blocks > 1) out.push_back(range_error(r, target));
  for (auto& e : errors_outside_runs(t.errors, ranges, target, 2)) out.push_back(std::move(e));
  return out;
}

/// How many errors of `t` beyond those it holds `errors_by_run` would list.
std::size_t errors_by_run_not_kept(const translation& t, const std::vector<unreachable_range>& ranges,
                                   const std::string& target) {
  return not_kept_outside_runs(t.errors, ranges, target, 2);
}

/// Says on stderr that a file cannot be read or written, and records it in `a` as an error about
/// the whole `file` (line 0; `file` as the report names it).
void file_failure(run_account& a, const std::string& prefix, const std::string& file, std::string message) {
  std::cerr << prefix << prog::printable(message) << '\n';
  a.errors.push_back({prog::source_location{file, 0, 0}, std::move(message)});
}

// ---- the common run -----------------------------------------------------------------------

/// What one program subcommand does, once its arguments are checked.
struct job {
  std::string command;      ///< "translate", "reverse", "post": the prefix of its messages
  std::string input_path;   ///< '-' for stdin
  std::string output_path;  ///< '-' for stdout
  std::string report_path;  ///< --report: the JSON account of the run; empty: none
  prog::dialect input_dialect{};
  bool input_dialect_given = false;  ///< false: a dialect recognised by guess_dialect wins
  prog::dialect output_dialect{};
  std::string target;       ///< what the output is for, named when blocks are unreachable
  std::optional<std::string> from_id, to_id;  ///< the machines, for the report
  bool verbose = false;
  /// The translator for a program read in this dialect from this file.
  std::function<std::unique_ptr<block_translator>(prog::dialect, const std::string&)> make;
  /// The writer settings the user chose (--tcp-word); the decimals come from the translation.
  prog::write_settings writer_choices;
  prog::read_limits limits;  ///< what IN may hold (the translator checks the same)
};

/// The report file (--report) of a run, written when the run ends, whatever its exit code, as
/// OUT is: a temporary file linked into place, never half-written.
class report_file {
 public:
  report_file(const job& j, const std::string& prefix) : prefix_(prefix) {
    if (j.report_path.empty()) return;
    std::error_code ec;
    if (j.report_path == "-" && j.output_path == "-") usage_ = "--report - and OUT - would both be stdout";
    else if (j.report_path == j.output_path || std::filesystem::equivalent(j.report_path, j.output_path, ec))
      usage_ = "--report names OUT";
    if (!usage_.empty()) return;
    file_ = std::make_unique<output_file>(j.report_path);
    if (!file_->ok()) refusal_ = "cannot write '" + j.report_path + "': " + file_->error();
    path_ = j.report_path;
  }
  /// Why --report cannot be written (its path), or cannot be asked for (`usage`: with this OUT).
  const std::string& refusal() const { return refusal_; }
  const std::string& usage() const { return usage_; }
  explicit operator bool() const { return file_ != nullptr; }

  /// Writes `a` as JSON; false, with the reason printed, if it cannot. A report is written once;
  /// a second call replaces it (a new temporary file linked over the first).
  bool write(const run_account& a) {
    if (!file_) return true;
    if (failed_) return false;  // said once
    if (committed_) file_ = std::make_unique<output_file>(path_);
    file_->buffer() = to_json(a);
    committed_ = file_->ok() && file_->commit();
    failed_ = !committed_;
    if (failed_) std::cerr << prefix_ << "cannot write the report '" << prog::printable(path_) << "': " << file_->error() << '\n';
    return committed_;
  }

 private:
  std::string prefix_, path_, refusal_, usage_;
  std::unique_ptr<output_file> file_;
  bool committed_ = false, failed_ = false;
};

/// The part of a run's account the job gives: what was asked.
run_account asked(const job& j, prog::dialect input_dialect) {
  run_account a;
  a.command = j.command;
  a.input = display_name(j.input_path);
  a.output = j.output_path == "-" ? "<stdout>" : j.output_path;
  a.input_dialect = prog::name(input_dialect);
  a.output_dialect = prog::name(j.output_dialect);
  a.from = j.from_id, a.to = j.to_id;
  return a;
}

/// Prints the summary line and, on failure, the line that says why nothing was written.
void print_summary(const job& j, const translation& result, bool committed, int code) {
  const std::string prefix = "kin5 " + j.command + ": ";
  const auto count = [&](matchability m) { return result.per_class[static_cast<std::size_t>(m)]; };
  std::cerr << prefix << result.blocks_read << " blocks read, " << (committed ? result.blocks_written : 0) << " written"
            << (committed && result.blocks_added ? " (" + std::to_string(result.blocks_added) + " added: rotary moves "
                                                   "without tool-tip tracking cut into pieces)"
                                                 : std::string())
            << ", " << result.passed_through << " passed through; ";
  for (matchability m : {matchability::direct, matchability::other_branch, matchability::unreachable})
    std::cerr << count(m) << ' ' << name(m) << (m == matchability::unreachable ? "\n" : ", ");
  const std::size_t unreachable = count(matchability::unreachable);
  if (code == exit_codes::input_error && !result.errors.empty()) {
    const std::size_t n = result.errors.count();
    std::cerr << prefix << n << (n == 1 ? " error" : " errors") << "; nothing written\n";
  } else if (code == exit_codes::unreachable) {
    std::cerr << prefix << unreachable << (unreachable == 1 ? " block" : " blocks") << " cannot be reached on "
              << j.target << "; nothing written\n";
  }
}

/// The run of `execute` once OUT, the report and IN are open: translates `bytes` read in
/// `dialect`, prints every diagnostic and the summary, commits OUT on success; fills `a`.
int translate_and_write(const job& j, std::string bytes, prog::dialect dialect, output_file& out,
                        report_file& report, run_account& a) {
  const std::string prefix = "kin5 " + j.command + ": ";
  const std::string file = display_name(j.input_path);
  const std::unique_ptr<block_translator> translator = j.make(dialect, file);
  block_accounting blocks;

  // Both passes (translate/stream.hpp): the output reaches OUT's temporary file while the run is
  // clean; the rest is still translated after an error, so that one run lists every error.
  // A program named by its output file when the source names none (Heidenhain BEGIN PGM).
  prog::write_settings choices = j.writer_choices;
  if (j.output_path != "-") choices.program_name = std::filesystem::path(j.output_path).stem().string();
  const stream_result run = stream_text(*translator, std::move(bytes), dialect, file, j.output_dialect, out,
                                        report ? blocks.watch() : block_watch{}, choices);
  const translation& result = translator->result();
  a = account_of(result, run, blocks, j.target, std::move(a));
  {
    std::vector<message> messages;
    collect(messages, run.input.errors, "error");
    collect(messages, run.input.warnings, "warning");
    print_in_source_order(std::move(messages), prefix, {run.input.errors_not_kept, run.input.warnings_not_kept});
  }
  if (!run.input.ok()) {
    const std::size_t n = run.input.error_count();
    std::cerr << prefix << n << (n == 1 ? " error" : " errors") << " in "
              << file << " (read as " << prog::name(dialect) << "); nothing written\n";
    return exit_codes::input_error;
  }
  const std::optional<prog::diagnostic>& writer_error = run.writer_error;  // a block the output dialect cannot say
  const bool file_failed = run.sink_failed;                            // the output file: `out.error()` says why

  // Unreachable blocks come as errors too (with their source angles and gap): one per block
  // that stands alone, one per run of consecutive unreachable blocks (with its worst block).
  {
    std::vector<message> messages;
    collect(messages, errors_by_run(result, a.unreachable, j.target), "error");
    collect(messages, result.warnings, "warning");
    for (auto d : result.allowed) {  // refusals the user accepted (--allow)
      d.message += " [allowed by " + d.option + "]";
      messages.push_back({"warning", std::move(d)});
    }
    if (j.verbose)
      for (const auto& r : result.reports)
        if (r.match == matchability::other_branch) messages.push_back({"note", other_branch_note(r, run.input.calls)});
    print_in_source_order(std::move(messages), prefix,
                          {errors_by_run_not_kept(result, a.unreachable, j.target), result.warnings.not_kept()});
  }
  const std::size_t unreachable = result.per_class[static_cast<std::size_t>(matchability::unreachable)];

  int code = exit_codes::ok;
  if (result.errors.count() > unreachable) {
    code = exit_codes::input_error;
  } else if (unreachable > 0) {
    code = exit_codes::unreachable;
  } else if (writer_error) {
    prog::diagnostic d = *writer_error;
    d.message = "cannot write the program as " + std::string(prog::name(j.output_dialect)) + ": " + d.message;
    std::cerr << d.to_string("error") << '\n';
    code = exit_codes::input_error;
  }
  // The report is written first, as for a program written: one that cannot be leaves OUT as it
  // was. The output is committed before the summary, which then says what OUT holds.
  bool committed = false;
  if (code == exit_codes::ok && !file_failed) {
    a.exit_code = code, a.written = true;
    if (report.write(a)) committed = out.commit();
    else code = exit_codes::input_error;  // OUT left as it was
  }
  if (code == exit_codes::ok && !committed) {
    file_failure(a, prefix, a.output, "cannot write '" + j.output_path + "': " + out.error());
    code = exit_codes::input_error;
  }
  a.written = committed;
  print_summary(j, result, committed, code);
  return code;
}

/// Reads IN, translates it in two passes (`block_translator`): the first over the text, the
/// second over the blocks kept as compact records (`block_store`); writes OUT block by block,
/// and the report (--report) whatever the outcome.
int execute(const job& j) {
  const std::string prefix = "kin5 " + j.command + ": ";
  if (const auto why = overwrite_refusal(j.input_path, j.output_path, j.report_path)) {  // nothing touched
    std::cerr << prefix << *why << '\n';
    return exit_codes::usage;
  }
  report_file report(j, prefix);  // checked, as OUT is, before the input is read
  if (!report.usage().empty()) {
    std::cerr << prefix << report.usage() << '\n';
    return exit_codes::usage;
  }
  if (!report.refusal().empty()) {
    std::cerr << prefix << report.refusal() << '\n';
    return exit_codes::input_error;
  }
  run_account a = asked(j, j.input_dialect);
  const auto finish = [&](int code) {
    a.exit_code = code;
    if (code == exit_codes::ok && a.written) return code;  // reported before OUT was committed
    return report.write(a) || code != exit_codes::ok ? code : exit_codes::input_error;
  };
  output_file out(j.output_path);  // what OUT is, checked before the input is read
  if (!out.ok()) {
    file_failure(a, prefix, a.output, "cannot write '" + j.output_path + "': " + out.error());
    return finish(exit_codes::input_error);
  }
  std::string error;
  auto bytes = read_input(j.input_path, j.limits, error);
  if (!bytes) {
    file_failure(a, prefix, a.input, "cannot read '" + j.input_path + "': " + error);
    return finish(exit_codes::input_error);
  }

  prog::dialect dialect = j.input_dialect;
  if (!j.input_dialect_given) {
    if (const auto guessed = prog::guess_dialect(*bytes); guessed && *guessed != dialect) {
      std::cerr << prefix << "note: reading " << display_name(j.input_path) << " as " << prog::name(*guessed)
                << " (recognised by its markers), not as " << prog::name(dialect)
                << "; choose with --" << (j.command == "translate" ? "from-dialect" : "dialect") << '\n';
      dialect = *guessed;
      a.input_dialect = prog::name(dialect);
    }
  }
  return finish(translate_and_write(j, std::move(*bytes), dialect, out, report, a));
}

// ---- argument checks ----------------------------------------------------------------------

/// The dialect named `given`, or else the machine's default.
prog::dialect dialect_or_default(const std::string& given, std::string_view machine_id) {
  if (!given.empty()) return *prog::parse_dialect(given);
  return prog::default_dialect(machine_id).value_or(prog::dialect{});
}

/// The names of `feed_policies`, in its order.
std::vector<std::string_view> feed_policy_names() {
  std::vector<std::string_view> names;
  for (const auto& p : feed_policies) names.push_back(p.name);
  return names;
}

/// "tcp: …; block-time: …; inverse-time: …" from `feed_policies`.
std::string feed_policy_help() {
  std::string help;
  for (const auto& p : feed_policies)
    help += (help.empty() ? "" : "; ") + std::string(p.name) + ": " + std::string(p.help);
  return help;
}

/// The options every program command takes (`common_options`), as given.
struct common_arguments {
  std::optional<double> angle_tolerance_deg;
  std::vector<std::string> allow;
  std::optional<int> digits;
  std::vector<std::string> m_map;
  std::string tool_length, work_offset;  ///< translate and post: the target's placement
  std::string source_tool_length, source_work_offset;  ///< translate and reverse: the source's
  std::optional<double> tolerance_mm;
  std::vector<std::string> work_offset_map;
  std::vector<std::string> tool_map;  ///< --tool-map NAME=N, one per option
  std::string report;  ///< --report FILE.json
  std::string output_mode;  ///< tcp | machine; empty: the output dialect's
  std::string tool_table;   ///< --tool-table FILE
  std::string tcp_word;     ///< --tcp-word: translate and post into Heidenhain; empty: M128
  std::optional<long long> program_number;  ///< --program-number: translate and post into ISO
  prog::read_limits limits;  ///< --max-file-bytes, --max-line-bytes, --max-block-words
};

std::optional<std::vector<double>> parse_list(std::string_view text, std::size_t count);

/// A tool length (mm, 0 or more; none: 0) and a work offset X,Y,Z (mm) from the options
/// --PREFIXtool-length and --PREFIXwork-offset; nothing, with the reason printed, on bad input.
std::optional<run_inputs> parse_run_inputs(std::string_view command, std::string_view prefix,
                                           const std::string& tool_length, const std::string& work_offset) {
  run_inputs in;
  if (!tool_length.empty()) {
    const auto l = parse_length_mm(tool_length, true);
    if (!l) {
      std::cerr << "kin5 " << command << ": --" << prefix << "tool-length: give a length in mm, 0 or more\n";
      return std::nullopt;
    }
    in.tool_length_mm = *l;
  }
  const auto w = parse_point_mm(work_offset);
  if (!w) {
    std::cerr << "kin5 " << command << ": --" << prefix << "work-offset needs 3 numbers X,Y,Z (mm, within ±1e9)\n";
    return std::nullopt;
  }
  in.work_offset.translation_mm = {(*w)[0], (*w)[1], (*w)[2]};
  return in;
}

/// `c.placement` from --tool-length and --work-offset (the check of the target's linear travel
/// runs when the part's place is given); false, with the reason printed, on bad input.
bool parse_placement(std::string_view command, const common_arguments& a, common_options& c) {
  if (a.work_offset.empty()) {
    if (a.tool_length.empty()) return true;
    std::cerr << "kin5 " << command << ": --tool-length needs --work-offset: the target's linear travel is checked "
                                       "only where the part's place on it is given\n";
    return false;
  }
  c.placement = parse_run_inputs(command, "", a.tool_length, a.work_offset);
  c.placement_has_length = !a.tool_length.empty() || a.tool_table.empty();  // without a table: 0 for one tool
  return c.placement.has_value();
}

/// `c.source_placement` from --source-tool-length and --source-work-offset (both or neither)
/// and `c.tolerance_mm` from --tolerance; false, with the reason printed, on bad input.
bool parse_source_placement(std::string_view command, const common_arguments& a, common_options& c) {
  if (a.tolerance_mm) {
    if (!(*a.tolerance_mm >= 1e-6 && *a.tolerance_mm <= 10.0)) {
      std::cerr << "kin5 " << command << ": --tolerance: give mm in [0.000001, 10]\n";
      return false;
    }
    c.tolerance_mm = *a.tolerance_mm;
  }
  if (a.source_work_offset.empty() && a.source_tool_length.empty()) return true;
  if (a.source_work_offset.empty() || (a.source_tool_length.empty() && a.tool_table.empty())) {
    std::cerr << "kin5 " << command << ": --source-work-offset and --source-tool-length (or --tool-table) go together: "
                                       "motion without tool-tip tracking is read as machine coordinates only where the "
                                       "part's place and the tool lengths are known\n";
    return false;
  }
  c.source_placement = parse_run_inputs(command, "source-", a.source_tool_length, a.source_work_offset);
  c.source_placement_has_length = !a.source_tool_length.empty();
  return c.source_placement.has_value();
}

/// `c.tools` from --tool-table FILE; false, with the reasons printed (FILE:LINE:COL for a
/// mistake in the file, `exit_code` then an input error), on bad input.
bool parse_tool_table(std::string_view command, const common_arguments& a, common_options& c, int& exit_code) {
  if (a.tool_table.empty()) return true;
  if (a.work_offset.empty() && a.source_work_offset.empty()) {
    std::cerr << "kin5 " << command << ": --tool-table gives tool lengths for motion in machine coordinates: give "
                                       "--source-work-offset or --work-offset with it\n";
    return false;
  }
  tool_table_result r = read_tool_table_file(a.tool_table);
  if (!r.ok()) {
    for (const auto& e : r.errors) std::cerr << e.to_string() << '\n';
    exit_code = exit_codes::input_error;
    return false;
  }
  c.tools = std::move(*r.table);
  return true;
}

/// `common_options` from `a`; prints the reason and returns nothing on bad input, with the exit
/// code in `exit_code` (a usage error unless said otherwise).
std::optional<common_options> parse_common(std::string_view command, const common_arguments& a, int& exit_code) {
  exit_code = exit_codes::usage;
  common_options c;
  if (a.angle_tolerance_deg) {
    if (!(*a.angle_tolerance_deg >= 0.0 && *a.angle_tolerance_deg <= 1.0)) {
      std::cerr << "kin5 " << command << ": --angle-tolerance: give degrees in [0, 1]\n";
      return std::nullopt;
    }
    c.angle_tolerance = degrees{*a.angle_tolerance_deg};
  }
  for (const auto& name : a.allow)
    if (!c.allow.add(name)) {
      std::cerr << "kin5 " << command << ": --allow: no refusal is named '" << name << "'; valid: " << allowable_names()
                << '\n';
      return std::nullopt;
    }
  if (a.digits && (*a.digits < 0 || *a.digits > 9)) {
    std::cerr << "kin5 " << command << ": --digits: give 0 to 9 decimals\n";
    return std::nullopt;
  }
  c.digits = a.digits;
  c.limits = a.limits;
  for (const auto& entry : a.tool_map)
    if (!c.tool_numbers.add(entry)) {
      std::cerr << "kin5 " << command << ": --tool-map: '" << entry
                << "' is not NAME=N (N a whole number of at most 8 digits), or maps a tool twice\n";
      return std::nullopt;
    }
  for (const auto& entry : a.m_map)
    if (!c.m_codes.add(entry)) {
      std::cerr << "kin5 " << command << ": --m-map: '" << entry << "' is neither N=M (rename) nor N= (drop)\n";
      return std::nullopt;
    }
  if (!parse_placement(command, a, c) || !parse_source_placement(command, a, c) ||
      !parse_tool_table(command, a, c, exit_code))
    return std::nullopt;
  if (!a.output_mode.empty()) {
    c.coordinates = parse_output_mode(a.output_mode);
    if (!c.coordinates) {
      std::cerr << "kin5 " << command << ": --output-mode: give tcp or machine\n";
      return std::nullopt;
    }
  }
  for (const auto& entries : a.work_offset_map)
    if (!c.work_offsets.add(entries)) {
      std::cerr << "kin5 " << command << ": --work-offset-map: '" << entries
                << "' is not FROM=TO[,FROM=TO…] (FROM, TO: G54 … G59, G54.1P n, G500, G505 … G599, or a "
                   "Heidenhain preset number; TO empty drops it), or maps a work offset twice\n";
      return std::nullopt;
    }
  return c;
}

/// The TCP switch of --tcp-word into `j.writer_choices`; false, with the reason printed, when
/// the word is not one of the output dialect's (only Heidenhain has a choice).
bool parse_tcp_word(std::string_view command, const std::string& word, job& j) {
  if (word.empty()) return true;
  if (j.output_dialect != prog::id_of<prog::heidenhain::dialect>()) {
    std::cerr << "kin5 " << command << ": --tcp-word chooses Heidenhain's TCP switch; the output dialect is "
              << prog::name(j.output_dialect) << '\n';
    return false;
  }
  j.writer_choices.of<prog::heidenhain::dialect>().tcp =
      word == "function-tcpm" ? prog::heidenhain::tcp_word::function_tcpm : prog::heidenhain::tcp_word::m128;
  return true;
}

/// The `O` number of --program-number into `j.writer_choices`; false, with the reason printed,
/// when the output dialect is not ISO or Haas (the ones numbering their programs).
bool parse_program_number(std::string_view command, std::optional<long long> number, job& j) {
  if (!number) return true;
  if (j.output_dialect == prog::id_of<prog::haas::dialect>()) {
    j.writer_choices.of<prog::haas::dialect>().program_number = *number;
    return true;
  }
  if (j.output_dialect != prog::id_of<prog::iso::dialect>()) {
    std::cerr << "kin5 " << command << ": --program-number numbers an ISO or Haas program (its O line); the output "
              << "dialect is " << prog::name(j.output_dialect) << '\n';
    return false;
  }
  j.writer_choices.of<prog::iso::dialect>().program_number = *number;
  return true;
}

/// Adds --program-number (the ISO output's O number) to `sub`.
void add_program_number_option(CLI::App* sub, common_arguments& a) {
  sub->add_option("--program-number", a.program_number,
                  "ISO output of a program read in another dialect: the number N of its O line, 1 to 9999 "
                  "(default: the source's name when it is such a number, else 1)")
      ->check(CLI::Range(1LL, 9999LL));
}

/// Adds --tcp-word (the output's TCP switch) to `sub`.
void add_tcp_word_option(CLI::App* sub, common_arguments& a) {
  sub->add_option("--tcp-word", a.tcp_word,
                  "Heidenhain output: switch tool-tip tracking with m128 (M128/M129, the default) or function-tcpm "
                  "(FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS / FUNCTION RESET TCPM)")
      ->check(CLI::IsMember({"m128", "function-tcpm"}));
}

/// Adds the options of `common_arguments` to `sub`.
void add_common_options(CLI::App* sub, common_arguments& a) {
  add_limit_options(sub, a.limits);
  sub->add_option("--angle-tolerance", a.angle_tolerance_deg,
                  "Degrees a rotary value may lie past a travel or reach edge and count as on it (default: half a "
                  "unit of the program's last angle decimal, at most 0.0005)");
  sub->add_option("--allow", a.allow, "Accept a named refusal knowingly, as a warning: " + allowable_names());
  sub->add_option("--digits", a.digits,
                  "Decimals of positions and angles in OUT (default: the source's, within what the output "
                  "controller reads)");
  sub->add_option("--m-map", a.m_map,
                  "Into another dialect, write M function N as M (N=M) or drop it (N=); other M functions "
                  "whose meaning is the machine maker's are refused")
      ->allow_extra_args(false);  // one entry per option: the input file after it stays the input
  sub->add_option("--report", a.report,
                  "Also write the account of the run to this file as JSON (exact counts, the first 1,000 errors and "
                  "warnings, unreachable blocks as runs of lines), whatever the exit code; '-' for stdout");
  sub->add_option("--work-offset-map", a.work_offset_map,
                  "Write work offset FROM as TO (G54=1: G54 selects Heidenhain preset 1; G505=G54.1P5; G54= "
                  "drops it); a work offset with no certain equivalent in the output dialect is refused")
      ->allow_extra_args(false);
  sub->add_option("--tool-map", a.tool_map,
                  "Call tool NAME (T=\"NAME\", TOOL CALL \"NAME\") as tool number N (NAME=N), in every dialect and "
                  "the tool table; a tool called by name is refused where the output dialect takes only numbers")
      ->allow_extra_args(false);  // one entry per option: a name may hold a comma
  sub->add_option("--output-mode", a.output_mode,
                  "tcp: motion as the tool tip under tool-tip tracking; machine: as the target's axis values, without "
                  "it (needs --work-offset; pieces within --tolerance). Default: tcp where the output dialect switches "
                  "tool-tip tracking")
      ->check(CLI::IsMember({"tcp", "machine"}));
  sub->add_option("--tool-table", a.tool_table,
                  "Tool lengths by tool number, a TOML file (docs/machine-files.md): motion read or written in machine "
                  "coordinates takes the length of the tool in effect (its length register H, else its tool change)");
}

/// Adds --tool-length and --work-offset (the target's placement) to `sub`.
void add_placement_options(CLI::App* sub, common_arguments& a) {
  sub->add_option("--work-offset", a.work_offset,
                  "Where the workpiece zero sits on the target, X,Y,Z in mm (machine coordinates at the zero pose); "
                  "given, every output block's slides are checked against the target's linear travel");
  sub->add_option("--tool-length", a.tool_length, "Tool length on the target, gauge point to tip, mm, for one tool (with --work-offset; default 0, "
                  "none with --tool-table; other tools' lengths come from --tool-table)");
}

/// Adds --tolerance to `sub`.
void add_tolerance_option(CLI::App* sub, common_arguments& a) {
  sub->add_option("--tolerance", a.tolerance_mm,
                  "How far (mm) the written tool-tip path may stray from the source's where a rotary move read or "
                  "written in machine coordinates is cut into pieces (default 0.005)");
}

/// Adds --source-work-offset, --source-tool-length and --tolerance (motion without tool-tip
/// tracking read as machine coordinates) to `sub`.
void add_source_options(CLI::App* sub, common_arguments& a) {
  sub->add_option("--source-work-offset", a.source_work_offset,
                  "Where the workpiece zero sat on the source, X,Y,Z in mm (machine coordinates at the zero pose); "
                  "with --source-tool-length, motion without tool-tip tracking is read as machine coordinates");
  sub->add_option("--source-tool-length", a.source_tool_length,
                  "Tool length on the source, gauge point to tip, mm, for one tool (with --source-work-offset; other "
                  "tools' lengths come from --tool-table)");
  add_tolerance_option(sub, a);
}

struct translate_arguments {
  machine_choice from, to;
  std::string feed{feed_policies[0].name}, from_dialect, to_dialect, output = "-", input;
  std::string setup_rotation, setup_axis, setup_offset;
  std::optional<double> setup_angle_deg;
  common_arguments common;
  bool verbose = false;
};

/// Numbers separated by commas, exactly `count` of them, or nothing.
std::optional<std::vector<double>> parse_list(std::string_view text, std::size_t count) {
  const auto fields = split(text, ',');
  if (fields.size() != count) return std::nullopt;
  std::vector<double> out;
  for (auto f : fields) {
    const auto v = parse_real(f);
    if (!v) return std::nullopt;
    out.push_back(*v);
  }
  return out;
}

/// target_T_source from --setup-rotation | --setup-axis with --setup-angle, and --setup-offset;
/// what is not given comes from the pair's default setup. Prints the reason and returns nothing
/// on bad input.
std::optional<rigid_transform> parse_setup(const translate_arguments& a, const machine_model& from,
                                           const machine_model& to) {
  const bool any = !a.setup_rotation.empty() || !a.setup_axis.empty() || a.setup_angle_deg || !a.setup_offset.empty();
  rigid_transform setup = default_setup(from.geometry.id, to.geometry.id);
  if (!any) return setup;
  auto fail = [](const std::string& why) -> std::optional<rigid_transform> {
    std::cerr << "kin5 translate: " << why << "\n";
    return std::nullopt;
  };
  if (!a.setup_rotation.empty() && (!a.setup_axis.empty() || a.setup_angle_deg))
    return fail("give the setup rotation either as --setup-rotation or as --setup-axis with --setup-angle, not both");
  if (!a.setup_rotation.empty()) {
    const auto rows = parse_list(a.setup_rotation, 9);
    if (!rows) return fail("--setup-rotation needs 9 numbers, row by row, separated by commas");
    const auto& r = *rows;
    const mat3 target_R_source{{vec3{r[0], r[1], r[2]}, vec3{r[3], r[4], r[5]}, vec3{r[6], r[7], r[8]}}};
    if (!is_proper_rotation(target_R_source))
      return fail("--setup-rotation is not a proper rotation (R Rᵀ = I and det R = +1 to 1e-9)");
    setup.rotation = target_R_source;
  } else if (!a.setup_axis.empty() || a.setup_angle_deg) {
    const auto axis = parse_list(a.setup_axis, 3);
    if (!axis || !a.setup_angle_deg) return fail("--setup-axis X,Y,Z and --setup-angle DEG go together");
    if (!std::isfinite(*a.setup_angle_deg)) return fail("--setup-angle must be a finite number of degrees");
    const vec3 axis_source{(*axis)[0], (*axis)[1], (*axis)[2]};
    if (!(norm(axis_source) > 1e-12)) return fail("--setup-axis must not be the zero vector");
    if (!std::isfinite(norm(axis_source))) return fail("--setup-axis is too long to normalise; scale it down");
    setup.rotation = rotation(normalized(axis_source), to_radians(degrees{*a.setup_angle_deg}));
  }
  if (!a.setup_offset.empty()) {
    const auto offset_mm = parse_list(a.setup_offset, 3);
    if (!offset_mm) return fail("--setup-offset needs 3 numbers (millimetres) separated by commas");
    for (double v : *offset_mm)  // what an NC program can hold; no controller takes more
      if (!prog::writable(v)) return fail("--setup-offset: each number must be within ±1e9 mm");
    setup.translation_mm = {(*offset_mm)[0], (*offset_mm)[1], (*offset_mm)[2]};
  }
  return setup;
}

struct machine_arguments {
  machine_choice machine;
  std::string dialect, output = "-", input;
  common_arguments common;
  bool verbose = false;
};

int run_translate(const translate_arguments& a) {
  int code = exit_codes::ok;
  const std::optional<chosen_machine> from = resolve_machine(a.from, "translate", code);
  if (!from) return code;
  const std::optional<chosen_machine> to = resolve_machine(a.to, "translate", code);
  if (!to) return code;
  const machine_model& from_model = from->model();
  const machine_model& to_model = to->model();
  job j;
  j.command = "translate";
  j.input_path = a.input;
  j.output_path = a.output;
  j.input_dialect = dialect_or_default(a.from_dialect, from_model.geometry.id);
  j.input_dialect_given = !a.from_dialect.empty();
  j.output_dialect = dialect_or_default(a.to_dialect, to_model.geometry.id);
  j.target = std::string(to_model.geometry.id);
  j.from_id = std::string(from_model.geometry.id), j.to_id = j.target;
  j.report_path = a.common.report;
  j.limits = a.common.limits;
  j.verbose = a.verbose;
  translate_options options;
  options.setup = parse_setup(a, from_model, to_model);
  if (!options.setup) return exit_codes::usage;
  const auto feed = parse_feed_policy(a.feed);
  if (!feed) {
    std::cerr << "kin5 translate: --feed: unknown feed policy '" << a.feed << "'; valid: " << join(feed_policy_names())
              << '\n';
    return exit_codes::usage;
  }
  options.feed = *feed;
  if (const auto refusal = feed_refusal(options.feed, j.output_dialect)) {  // found before reading
    const auto with_inverse_time =
        dialect_names([](const prog::capabilities& can) { return can.inverse_time_feed && !can.cl_data; });
    std::cerr << "kin5 translate: --feed " << a.feed << ": " << *refusal << "; choose --to-dialect "
              << one_of(with_inverse_time) << ", or another --feed\n";
    return exit_codes::usage;
  }
  options.output_dialect = j.output_dialect;
  int common_error = exit_codes::usage;
  const auto common = parse_common("translate", a.common, common_error);
  if (!common) return common_error;
  options.common = *common;
  if (!parse_tcp_word("translate", a.common.tcp_word, j)) return exit_codes::usage;
  if (!parse_program_number("translate", a.common.program_number, j)) return exit_codes::usage;
  if (const auto why = translate_detail::output_mode_refusal(options.common, j.output_dialect)) {
    std::cerr << "kin5 translate: " << *why << '\n';
    return exit_codes::usage;
  }
  j.make = [&from_model, &to_model, options](prog::dialect d, const std::string& file) {
    return kin5::make_translator(from_model, to_model, d, file, options, report_detail::exceptions_only);
  };
  return execute(j);
}

int run_reverse(const machine_arguments& a) {
  int code = exit_codes::ok;
  const std::optional<chosen_machine> m = resolve_machine(a.machine, "reverse", code);
  if (!m) return code;
  const machine_model& model = m->model();
  job j;
  j.command = "reverse";
  j.input_path = a.input;
  j.output_path = a.output;
  j.input_dialect = dialect_or_default(a.dialect, model.geometry.id);
  j.input_dialect_given = !a.dialect.empty();
  j.output_dialect = prog::cl_data_dialect();
  j.target = "APT CL data";
  j.from_id = std::string(model.geometry.id);
  j.report_path = a.common.report;
  j.limits = a.common.limits;
  j.verbose = a.verbose;
  int common_error = exit_codes::usage;
  const auto common = parse_common("reverse", a.common, common_error);
  if (!common) return common_error;
  if (common->coordinates == output_mode::machine) {
    std::cerr << "kin5 reverse: --output-mode machine: APT CL data holds the tool tip and axis, not machine "
                 "coordinates\n";
    return exit_codes::usage;
  }
  j.make = [&model, common](prog::dialect d, const std::string& file) {
    return kin5::make_reverse(model, d, file, report_detail::exceptions_only, *common);
  };
  return execute(j);
}

int run_post(const machine_arguments& a) {
  int code = exit_codes::ok;
  const std::optional<chosen_machine> m = resolve_machine(a.machine, "post", code);
  if (!m) return code;
  const machine_model& model = m->model();
  job j;
  j.command = "post";
  j.input_path = a.input;
  j.output_path = a.output;
  j.input_dialect = prog::cl_data_dialect();
  j.input_dialect_given = true;
  j.output_dialect = dialect_or_default(a.dialect, model.geometry.id);
  j.target = std::string(model.geometry.id);
  j.to_id = j.target;
  j.report_path = a.common.report;
  j.limits = a.common.limits;
  j.verbose = a.verbose;
  const prog::dialect out = j.output_dialect;
  int common_error = exit_codes::usage;
  const auto common = parse_common("post", a.common, common_error);
  if (!common) return common_error;
  if (!parse_tcp_word("post", a.common.tcp_word, j)) return exit_codes::usage;
  if (!parse_program_number("post", a.common.program_number, j)) return exit_codes::usage;
  if (const auto why = translate_detail::output_mode_refusal(*common, out)) {
    std::cerr << "kin5 post: " << *why << '\n';
    return exit_codes::usage;
  }
  j.make = [&model, out, common](prog::dialect d, const std::string& file) {
    return kin5::make_post(model, d, out, file, report_detail::exceptions_only, *common);
  };
  return execute(j);
}

struct canon_arguments {
  std::string dialect, input;
  prog::read_limits limits;
};

/// `kin5 canon`: reads IN as the control runs it (its loops, calls and parameters) and prints
/// each executed block's canonical operations, one a line, `FILE:LINE: name values` (the block's
/// own `block_start` is left out: its line is named on each). Nothing is printed when the
/// program has errors: they go to stderr, exit 2.
int run_canon(const canon_arguments& a) {
  const std::string prefix = "kin5 canon: ";
  const std::string file = display_name(a.input);
  std::string error;
  auto bytes = read_input(a.input, a.limits, error);
  if (!bytes) {
    std::cerr << prefix << "cannot read '" << file << "': " << error << '\n';
    return exit_codes::input_error;
  }
  std::optional<prog::dialect> dialect = a.dialect.empty() ? prog::guess_dialect(*bytes) : prog::parse_dialect(a.dialect);
  if (!dialect) {
    std::cerr << prefix << "no marker of one dialect in " << file << "; choose it with --dialect\n";
    return exit_codes::usage;
  }
  prog::read_result diagnostics;
  std::string out;
  std::vector<prog::canonical::operation> operations;
  prog::canonical::operation_printer printer;
  prog::read_blocks(
      *dialect, *bytes, file, diagnostics,
      [&](prog::block&& b) {
        if (!diagnostics.ok()) return;  // nothing partial: the output is dropped anyway
        operations.clear();
        prog::canonical::append_operations(b, operations);
        const std::string where = prog::printable(b.where.file.str()) + ":" + std::to_string(b.where.line) + ": ";
        for (const auto& op : operations) {
          const std::string text = printer.text(op);  // a block's start too: the printer keeps its text
          if (!std::holds_alternative<prog::canonical::block_start>(op)) out += where + text + '\n';
        }
      },
      a.limits);
  std::vector<message> messages;
  collect(messages, diagnostics.errors, "error");
  collect(messages, diagnostics.warnings, "warning");
  print_in_source_order(std::move(messages), prefix, {diagnostics.errors_not_kept, diagnostics.warnings_not_kept});
  if (!diagnostics.ok()) {
    const std::size_t n = diagnostics.error_count();
    std::cerr << prefix << n << (n == 1 ? " error" : " errors") << " in " << file << " (read as "
              << prog::name(*dialect) << "); nothing written\n";
    return exit_codes::input_error;
  }
  std::cout << out;
  return exit_codes::ok;
}

/// The help footer's table of default dialects, one machine per line.
std::string default_dialect_table() {
  std::size_t width = 0;
  for (auto id : machine_ids()) width = std::max(width, id.size());
  std::string out =
      "Dialects: the option's, else (input only) the one recognised from markers such as BEGIN PGM\n"
      "or TRAORI, else the machine's default:";
  for (auto id : machine_ids()) {
    const auto d = prog::default_dialect(id);
    std::string line(id);
    line.resize(width + 2, ' ');
    out += "\n  " + line + std::string(prog::name(d.value_or(prog::dialect{})));
  }
  return out;
}

const char* exit_code_footer =
    "\n\nExit codes: 0 written; 1 bad arguments; 2 the input cannot be read or has errors (all listed as\n"
    "FILE:LINE:COL: error: ...), or the output cannot be written; 3 blocks unreachable on the target\n"
    "(each listed with its source angles and gap). On a non-zero exit OUT is not created or changed.\n";

}  // namespace

void add_program_commands(CLI::App& app, int& exit_code) {
  const auto nc_names = nc_dialect_names();
  const auto dialects = CLI::IsMember(std::vector<std::string>(nc_names.begin(), nc_names.end()));
  const auto feed_names = feed_policy_names();

  {
    auto a = std::make_shared<translate_arguments>();
    auto* sub = app.add_subcommand("translate", "Translate an NC program from one machine to another");
    add_machine_options(*sub, a->from, "--from", "Machine the program was written for");
    add_machine_options(*sub, a->to, "--to", "Machine to write the program for");
    sub->add_option("--feed", a->feed, feed_policy_help())
        ->check(CLI::IsMember(std::vector<std::string>(feed_names.begin(), feed_names.end())))
        ->capture_default_str();
    sub->add_option("--from-dialect", a->from_dialect, "Dialect of IN (default: the --from machine's)")
        ->check(dialects);
    sub->add_option("--to-dialect", a->to_dialect, "Dialect of OUT (default: the --to machine's)")->check(dialects);
    sub->add_option("-o,--output", a->output, "Output file; '-' for stdout")->capture_default_str();
    sub->add_option("--setup-rotation", a->setup_rotation,
                    "Setup rotation target_R_source, 9 numbers row by row (default: the pair's; see docs)");
    sub->add_option("--setup-axis", a->setup_axis, "Setup rotation as an axis X,Y,Z (with --setup-angle)");
    sub->add_option("--setup-angle", a->setup_angle_deg, "Setup rotation angle about --setup-axis, degrees, right-handed");
    sub->add_option("--setup-offset", a->setup_offset,
                    "Setup translation X,Y,Z in mm: target point = R * source point + offset (default: the pair's)");
    add_common_options(sub, a->common);
    add_placement_options(sub, a->common);
    add_source_options(sub, a->common);
    add_tcp_word_option(sub, a->common);
    add_program_number_option(sub, a->common);
    sub->add_flag("-v,--verbose", a->verbose, "Also list the blocks translated on the other solution branch");
    sub->add_option("input", a->input, "Input NC program; '-' for stdin")->required();
    sub->footer(default_dialect_table() + exit_code_footer);
    sub->callback([a, &exit_code] { exit_code = run_translate(*a); });
  }
  {
    auto a = std::make_shared<machine_arguments>();
    auto* sub = app.add_subcommand("reverse", "Turn a machine's NC program into APT CL data (tool tip and axis)");
    add_machine_options(*sub, a->machine, "--machine", "Machine the program was written for");
    sub->add_option("--dialect", a->dialect, "Dialect of IN (default: the machine's)")->check(dialects);
    sub->add_option("-o,--output", a->output, "Output file; '-' for stdout")->capture_default_str();
    add_common_options(sub, a->common);
    add_source_options(sub, a->common);
    sub->add_flag("-v,--verbose", a->verbose, "Also list the blocks read on the other solution branch");
    sub->add_option("input", a->input, "Input NC program; '-' for stdin")->required();
    sub->footer(default_dialect_table() + exit_code_footer);
    sub->callback([a, &exit_code] { exit_code = run_reverse(*a); });
  }
  {
    auto a = std::make_shared<machine_arguments>();
    auto* sub = app.add_subcommand("post", "Post-process APT CL data into an NC program for a machine");
    add_machine_options(*sub, a->machine, "--machine", "Machine to write the program for");
    sub->add_option("--dialect", a->dialect, "Dialect of OUT (default: the machine's)")->check(dialects);
    sub->add_option("-o,--output", a->output, "Output file; '-' for stdout")->capture_default_str();
    add_common_options(sub, a->common);
    add_placement_options(sub, a->common);
    add_tolerance_option(sub, a->common);
    add_tcp_word_option(sub, a->common);
    add_program_number_option(sub, a->common);
    sub->add_flag("-v,--verbose", a->verbose, "Also list the blocks posted on the other solution branch");
    sub->add_option("input", a->input, "Input APT CL file; '-' for stdin")->required();
    sub->footer(default_dialect_table() + exit_code_footer);
    sub->callback([a, &exit_code] { exit_code = run_post(*a); });
  }
  {
    auto a = std::make_shared<canon_arguments>();
    auto* sub = app.add_subcommand("canon", "Print an NC program's canonical operations as the control runs it, one a line");
    const auto every_name = dialect_names([](const prog::capabilities&) { return true; });
    sub->add_option("--dialect", a->dialect, "Dialect of IN (default: the one recognised from its markers)")
        ->check(CLI::IsMember(std::vector<std::string>(every_name.begin(), every_name.end())));
    add_limit_options(sub, a->limits);
    sub->add_option("input", a->input, "Input NC program; '-' for stdin")->required();
    sub->footer(
        "\n\nEach line: FILE:LINE: name values, lengths in mm, angles in deg (docs/user-guide.md, \"Canonical "
        "operations\").\nExit codes: 0 printed; 1 bad arguments; 2 the input cannot be read or has errors (all "
        "listed as\nFILE:LINE:COL: error: ...); nothing is printed then.\n");
    sub->callback([a, &exit_code] { exit_code = run_canon(*a); });
  }
}

}  // namespace kin5::tool
