/// @file translate/run_report.hpp
/// The account of one run, short enough to read whatever the program's length: the blocks the
/// target cannot reach grouped into runs of consecutive motion blocks (`unreachable_ranges`),
/// each with its worst block, so that 100,000 unreachable blocks in a row are one entry, not
/// 100,000; every input block accounted for (`block_accounting`: read = translated + comment
/// only + refused); and the whole as JSON (`run_account`, `to_json`: `kin5 … --report FILE`).
/// Two unreachable blocks are in one run when no reachable motion block lies between them
/// (`block_report::ordinal`); comments and other blocks between them do not split a run.
/// @code
///   kin5::block_accounting blocks;
///   const auto run = kin5::stream_text(*t, text, from, "part.mpf", to, sink, blocks.watch());
///   kin5::run_account a = kin5::account_of(t->result(), run, blocks, "dmu-80p");
///   a.command = "translate", a.exit_code = 3;
///   const std::string json = kin5::to_json(a);
/// @endcode
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../core/units.hpp"
#include "../kinematics/matchability.hpp"
#include "../program/block.hpp"
#include "options.hpp"
#include "stream.hpp"

namespace kin5 {

/// A run of consecutive motion blocks the target cannot reach.
struct unreachable_range {
  program::source_location first, last;  ///< its first and last block
  std::size_t blocks = 0;                ///< how many blocks it holds
  degrees worst_gap{};                   ///< the largest angle from a tool axis to the target's reach
  double worst_excess_mm = 0.0;          ///< the largest distance a slide lies past its travel
  /// The worst block: the largest gap; where no block of the run has a gap, the largest excess.
  program::source_location worst;
  std::string worst_why;  ///< why the worst block cannot be reached (`block_report::why`)
};

/// Whether report `r` is worse than the worst of `range` so far: a larger gap, or no gap on
/// either side and a larger slide excess.
inline bool worse_than(const block_report& r, const unreachable_range& range) {
  const double gap_deg = to_degrees(r.gap).value;
  if (gap_deg != range.worst_gap.value) return gap_deg > range.worst_gap.value;
  return range.worst_gap.value == 0.0 && r.linear_excess_mm > range.worst_excess_mm;
}

/// The unreachable reports of `reports` (in program order, as a translation keeps them)
/// grouped into runs: a report joins the last run when its `ordinal` follows the run's last
/// block's directly.
inline std::vector<unreachable_range> unreachable_ranges(const std::vector<block_report>& reports) {
  std::vector<unreachable_range> ranges;
  std::size_t last_ordinal = 0;
  for (const block_report& r : reports) {
    if (r.match != matchability::unreachable) continue;
    if (ranges.empty() || r.ordinal != last_ordinal + 1) ranges.push_back({r.where, r.where, 0, {}, 0.0, r.where, r.why});
    unreachable_range& range = ranges.back();
    range.last = r.where;
    ++range.blocks;
    if (worse_than(r, range)) range.worst = r.where, range.worst_why = r.why;
    range.worst_gap = degrees{std::max(range.worst_gap.value, to_degrees(r.gap).value)};
    range.worst_excess_mm = std::max(range.worst_excess_mm, r.linear_excess_mm);
    last_ordinal = r.ordinal;
  }
  return ranges;
}

/// `errors` without the per-block errors of the unreachable blocks in `ranges` of at least
/// `min_blocks` blocks (those a translation to `target_id` made: "<target_id> cannot reach this
/// block (…): …"), which a caller states once per run instead.
inline std::vector<program::diagnostic> errors_outside_runs(const std::vector<program::diagnostic>& errors,
                                                            const std::vector<unreachable_range>& ranges,
                                                            std::string_view target_id, std::size_t min_blocks) {
  std::vector<const unreachable_range*> runs;  // in line order
  for (const auto& r : ranges)
    if (r.blocks >= min_blocks) runs.push_back(&r);
  const std::string unreachable = std::string(target_id) + " cannot reach this block (";
  std::vector<program::diagnostic> out;
  for (const auto& e : errors) {
    const auto after = std::upper_bound(runs.begin(), runs.end(), e.where.line,
                                        [](std::size_t line, const unreachable_range* r) { return line < r->first.line; });
    const bool in_run = after != runs.begin() && e.where.line <= (*(after - 1))->last.line;
    if (!(in_run && e.message.starts_with(unreachable))) out.push_back(e);
  }
  return out;
}

/// How many of the errors `errors` only counted (`not_kept`) `errors_outside_runs` would have
/// kept: all but the per-block errors of the runs of at least `min_blocks` unreachable blocks
/// (one error per unreachable block; those held are the ones `errors_outside_runs` drops).
inline std::size_t not_kept_outside_runs(const diagnostic_list& errors, const std::vector<unreachable_range>& ranges,
                                         std::string_view target_id, std::size_t min_blocks) {
  std::size_t in_runs = 0;
  for (const auto& r : ranges)
    if (r.blocks >= min_blocks) in_runs += r.blocks;
  const std::size_t held_in_runs = errors.size() - errors_outside_runs(errors, ranges, target_id, min_blocks).size();
  const std::size_t counted_in_runs = in_runs > held_in_runs ? in_runs - held_in_runs : 0;
  return errors.not_kept() > counted_in_runs ? errors.not_kept() - counted_in_runs : 0;
}

/// Every block of a run accounted for: `read` = `translated` + `comment_only` + `refused`.
struct block_counts {
  std::size_t read = 0;
  std::size_t translated = 0;    ///< read and translated without an error (written if the run succeeds)
  std::size_t comment_only = 0;  ///< a comment, blanks, or text carried over (not understood, no axis word)
  std::size_t refused = 0;       ///< an error at the block; every block, after an error about the whole file
};

/// Whether block `b` holds nothing but a comment, blanks, a block number, framing or text carried over.
inline bool comment_only(const program::block& b) {
  if (b.moves()) return false;
  program::block content = b;
  content.where = {}, content.call_chain = 0, content.text.clear(), content.number.reset(), content.comment.reset();
  content.passthrough = content.framing = false;  // framing text (`%`, `;$PATH=`) is text too
  return content == program::block{};
}

/// Counts the blocks of a run (`block_counts`): watches the first pass (`watch()`, for
/// `stream_text`), then `counts` adds what the second pass found. A block is refused when the
/// reader or the first pass reported an error while it was read and planned (so a reader's
/// errors count even beyond the ones it keeps), or the second pass one at its line. When the
/// reader found errors nothing is translated, and only the reader's count.
class block_accounting {
 public:
  /// The `block_watch` to give `stream_text` / `stream_blocks`; `*this` must outlive the run.
  block_watch watch() {
    return [this](const program::block& b, const program::read_result& input, const translation& t) { see(b, input, t); };
  }

  /// Sees block `b`, planned, with the reader's and the translation's diagnostics so far.
  void see(const program::block& b, const program::read_result& input, const translation& t) {
    ++read_;
    unsigned flags = input.error_count() > reader_errors_ ? by_reader : 0u;
    for (std::size_t i = plan_errors_; i < t.errors.count(); ++i)
      t.errors.line(i) == 0 ? void(whole_file_ = true) : void(flags |= by_plan);
    reader_errors_ = input.error_count(), plan_errors_ = t.errors.count();
    if (comment_only(b)) flags |= comment;
    if (flags) marked_.push_back({b.where.line, flags});
  }

  /// The counts once the run `run` of translation `t` is over.
  block_counts counts(const translation& t, const stream_result& run) const {
    const bool translated = run.input.ok();  // else only the reader's errors count
    bool whole_file = translated && whole_file_;
    for (const auto& e : run.input.errors) whole_file = whole_file || e.where.line == 0;
    const unsigned refusing = translated ? by_reader | by_plan : by_reader;
    block_counts c{read_, 0, 0, 0};
    for (const auto& m : marked_)
      if (m.flags & refusing) ++c.refused;
      else if (m.flags & comment) ++c.comment_only;
    for (std::size_t line : translated ? second_pass_lines(t, run) : std::vector<std::size_t>{}) {
      const auto at = std::lower_bound(marked_.begin(), marked_.end(), line,
                                       [](const mark& m, std::size_t l) { return m.line < l; });
      const bool marked = at != marked_.end() && at->line == line;
      if (line == 0) whole_file = true;
      else if (!marked) ++c.refused;
      else if (!(at->flags & refusing)) ++c.refused, --c.comment_only;  // a block marked, not refused, is comment only
    }
    if (whole_file) c.comment_only = 0, c.refused = read_;
    c.translated = read_ - c.comment_only - c.refused;
    return c;
  }

 private:
  static constexpr unsigned by_reader = 1, by_plan = 2, comment = 4;
  struct mark {
    std::size_t line;
    unsigned flags;
  };
  std::size_t read_ = 0, reader_errors_ = 0, plan_errors_ = 0;
  bool whole_file_ = false;     // the first pass found an error about the whole file
  std::vector<mark> marked_;    // blocks refused or comment only, in file order

  /// The lines of the errors found after the first pass, once each, in order.
  std::vector<std::size_t> second_pass_lines(const translation& t, const stream_result& run) const {
    std::vector<std::size_t> lines;
    for (std::size_t i = plan_errors_; i < t.errors.count(); ++i) lines.push_back(t.errors.line(i));
    if (run.writer_error) lines.push_back(run.writer_error->where.line);
    std::sort(lines.begin(), lines.end());
    lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
    return lines;
  }
};

/// What a run did, for `to_json`: what was asked (the caller's part), and what happened.
struct run_account {
  std::string command, input, output;     ///< "translate", "reverse" or "post"; IN and OUT as given
  std::string input_dialect, output_dialect;
  std::optional<std::string> from, to;    ///< the machines' ids (`reverse` has no `to`, `post` no `from`)
  int exit_code = 0;
  bool written = false;                   ///< OUT holds the translated program
  block_counts blocks;
  std::size_t blocks_written = 0, blocks_added = 0;
  std::array<std::size_t, 3> motion{};    ///< motion blocks by `matchability`
  /// Errors, warnings and refusals allowed by the user, each listed once (`account_of`: the
  /// first 1,000 errors and warnings); the per-block errors of unreachable blocks are listed as
  /// `unreachable` runs instead.
  std::vector<program::diagnostic> errors, warnings, allowed;
  std::size_t errors_not_listed = 0, warnings_not_listed = 0;  ///< found but not listed (beyond the first 1,000)
  std::vector<unreachable_range> unreachable;
  /// Every error found: `errors`, those not listed, and one per unreachable block.
  std::size_t error_count() const {
    std::size_t n = errors.size() + errors_not_listed;
    for (const auto& r : unreachable) n += r.blocks;
    return n;
  }
};

/// Diagnostics in source order (line, then column; ties as given).
inline std::vector<program::diagnostic> in_source_order(std::vector<program::diagnostic> ds) {
  std::stable_sort(ds.begin(), ds.end(), [](const program::diagnostic& a, const program::diagnostic& b) {
    return a.where.line != b.where.line ? a.where.line < b.where.line : a.where.column < b.where.column;
  });
  return ds;
}

/// The first `max_kept_diagnostics` of `ds` in source order; the others counted in `more`.
inline std::vector<program::diagnostic> first_in_source_order(std::vector<program::diagnostic> ds, std::size_t& more) {
  ds = in_source_order(std::move(ds));
  if (ds.size() > program::max_kept_diagnostics) {
    more += ds.size() - program::max_kept_diagnostics;
    ds.resize(program::max_kept_diagnostics);
  }
  return ds;
}

/// The account of translation `t` to `target_id` streamed as `run`, its blocks counted by
/// `blocks`, completing `asked` (what the job asked: command, files, dialects, machines); the
/// caller fills in the exit code and whether OUT was written.
/// When the reader found errors nothing was translated, and only the reader's errors count.
/// Errors and warnings are listed up to `max_kept_diagnostics` each, the first in source order
/// (500,000 refused blocks would list 100 MB), and the rest counted.
inline run_account account_of(const translation& t, const stream_result& run, const block_accounting& blocks,
                              std::string_view target_id, run_account asked = {}) {
  run_account a = std::move(asked);
  a.blocks = blocks.counts(t, run);
  a.blocks_written = t.blocks_written, a.blocks_added = t.blocks_added, a.motion = t.per_class;
  a.errors = run.input.errors, a.warnings = run.input.warnings;
  a.errors_not_listed = run.input.errors_not_kept, a.warnings_not_listed = run.input.warnings_not_kept;
  if (!run.input.ok()) return a;  // nothing translated: the reader's account only (its first 1,000)
  a.unreachable = unreachable_ranges(t.reports);
  for (auto& e : errors_outside_runs(t.errors, a.unreachable, target_id, 1)) a.errors.push_back(std::move(e));
  a.errors_not_listed += not_kept_outside_runs(t.errors, a.unreachable, target_id, 1);
  if (run.writer_error) a.errors.push_back(*run.writer_error);
  a.warnings.insert(a.warnings.end(), t.warnings.begin(), t.warnings.end());
  a.warnings_not_listed += t.warnings.not_kept();
  a.allowed = t.allowed;
  a.errors = first_in_source_order(std::move(a.errors), a.errors_not_listed);
  a.warnings = first_in_source_order(std::move(a.warnings), a.warnings_not_listed);
  return a;
}

namespace json_detail {

using program::utf8_length;

/// `s` as a JSON string: quotes, backslashes and control characters escaped; a byte that is
/// not part of well-formed UTF-8 becomes U+FFFD, so that the report is valid JSON whatever the input.
inline std::string json_string(std::string_view s) {
  std::string out = "\"";
  while (!s.empty()) {
    const std::size_t n = utf8_length(s);
    const char c = s[0];
    if (n == 0) out += "\\ufffd";
    else if (c == '"' || c == '\\') out += '\\', out += c;
    else if (c == '\n') out += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else out.append(s.data(), n);
    s.remove_prefix(n == 0 ? 1 : n);
  }
  return out + "\"";
}

/// `s` quoted, or `null` when empty.
inline std::string string_or_null(std::string_view s) { return s.empty() ? "null" : json_string(s); }

/// `v` as a JSON number with at most 6 decimals (`null` when not finite).
inline std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", v);
  std::string s(buf);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

/// `"name": value` members joined into one object.
inline std::string object(std::initializer_list<std::pair<std::string_view, std::string>> members) {
  std::string out = "{";
  for (const auto& [name, value] : members) out += (out.size() > 1 ? ", " : "") + json_string(name) + ": " + value;
  return out + "}";
}

/// `items`, each made JSON by `to_json`, one per line.
template <class T, class F>
std::string array(const std::vector<T>& items, F&& to_json) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ",\n    " : "\n    ") + to_json(items[i]);
  return out + (items.empty() ? "]" : "\n  ]");
}

/// A place in the source: file, line, column.
inline std::string location(const program::source_location& at) {
  return object({{"file", json_string(at.file.str())}, {"line", std::to_string(at.line)},
                 {"column", std::to_string(at.column)}});
}

/// A diagnostic: where (line 0: about the whole file), the construct and option if named, why,
/// and the calls open there, outermost first (none at the top level).
inline std::string diagnostic(const program::diagnostic& d) {
  std::string calls = "[";
  for (const auto& c : d.called_from) calls += (calls.size() > 1 ? ", " : "") + location(c);
  return object({{"file", json_string(d.where.file.str())}, {"line", std::to_string(d.where.line)},
                 {"column", std::to_string(d.where.column)}, {"construct", string_or_null(d.construct)},
                 {"reason", json_string(d.message)}, {"option", string_or_null(d.option)},
                 {"called_from", calls + "]"}});
}

/// A run of unreachable blocks.
inline std::string range(const unreachable_range& r) {
  return object({{"first_line", std::to_string(r.first.line)}, {"first_column", std::to_string(r.first.column)},
                 {"last_line", std::to_string(r.last.line)}, {"blocks", std::to_string(r.blocks)},
                 {"worst_line", std::to_string(r.worst.line)}, {"worst_gap_deg", number(r.worst_gap.value)},
                 {"worst_excess_mm", number(r.worst_excess_mm)}, {"worst_reason", json_string(r.worst_why)}});
}

}  // namespace json_detail

/// `a` as one JSON object (docs/user-guide.md, "The report"); lists in source order.
inline std::string to_json(const run_account& a) {
  using namespace json_detail;
  const auto count = [](std::size_t n) { return std::to_string(n); };
  const auto machine = [](const std::optional<std::string>& id) { return id ? json_string(*id) : std::string("null"); };
  std::string out = "{\n  \"kin5_report\": 1,\n";
  out += "  \"command\": " + json_string(a.command) + ", \"exit_code\": " + std::to_string(a.exit_code) +
         ", \"written\": " + (a.written ? "true" : "false") + ",\n";
  out += "  \"input\": " + object({{"file", json_string(a.input)}, {"dialect", json_string(a.input_dialect)}, {"machine", machine(a.from)}}) + ",\n";
  out += "  \"output\": " + object({{"file", json_string(a.output)}, {"dialect", json_string(a.output_dialect)}, {"machine", machine(a.to)}}) + ",\n";
  out += "  \"blocks\": " + object({{"read", count(a.blocks.read)}, {"translated", count(a.blocks.translated)},
                                    {"comment_only", count(a.blocks.comment_only)}, {"refused", count(a.blocks.refused)},
                                    {"written", count(a.written ? a.blocks_written : 0)},
                                    {"added", count(a.written ? a.blocks_added : 0)}}) + ",\n";
  out += "  \"motion_blocks\": " + object({{"direct", count(a.motion[0])}, {"other_branch", count(a.motion[1])},
                                           {"unreachable", count(a.motion[2])}}) + ",\n";
  out += "  \"error_count\": " + count(a.error_count()) + ", \"errors_not_listed\": " + count(a.errors_not_listed) +
         ", \"warning_count\": " + count(a.warnings.size() + a.warnings_not_listed) +
         ", \"warnings_not_listed\": " + count(a.warnings_not_listed) + ",\n";
  out += "  \"errors\": " + array(in_source_order(a.errors), diagnostic) + ",\n";
  out += "  \"warnings\": " + array(in_source_order(a.warnings), diagnostic) + ",\n";
  out += "  \"allowed\": " + array(in_source_order(a.allowed), diagnostic) + ",\n";
  out += "  \"unreachable\": " + array(a.unreachable, range) + "\n}\n";
  return out;
}

}  // namespace kin5
