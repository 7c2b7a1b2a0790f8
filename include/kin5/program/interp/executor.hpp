/// @file program/interp/executor.hpp
/// Runs the lines of one program as a control does: in order, except where a control statement
/// jumps to a label, takes a branch of an IF, runs a loop, calls a labelled part of the same file
/// (a number of times) or returns from one. Each dialect's syntax says what a line is (a
/// `statement`, statement.hpp); the executor keeps the place, the open calls and loops and the
/// parameters (parameter_store.hpp), and hands each *ordinary* line it executes to the dialect's
/// reader, which reads its words with the parameters' values (`parameters()`).
///
/// The text stays in memory while it runs (the first pass of a translation holds it anyway);
/// only labels are indexed, by one scan when the first jump or call needs one, so memory grows
/// with the labels and the open calls and loops, not with the program's length.
///
/// A call whose target no label of the text defines, and whose statement names the files that
/// may hold it (`statement::files`), runs another file: the `file_opener` given to
/// `open_files_with` finds and loads it (none given: the call is refused, naming the files).
/// The called file runs as a text of its own, with its own labels and the same parameters and
/// bounds, from the label the call names when the file defines it (LinuxCNC's `o<name> sub`),
/// else from its first line, until a return with no call of its own open (M99, M17, RET,
/// `endsub`) or the end of its program (END PGM, M30): then the caller goes on. Its errors name
/// its path (`flow_error::file`); `file()` says which file the line being read is in. A file is
/// loaded once per run and calling file, when first called, and kept for the calls after.
///
/// The calls open at each line are a chain of call sites (the calling statements' first
/// non-blank bytes), interned in a `call_chains` table (call_chain.hpp): `call_chain()` is the
/// chain of the line running now, 0 at the top level; `record_calls_in` gives the table and the
/// main text's file name (the table is the executor's own without it).
///
/// Bounds, each an error at the statement that passes it, after which nothing more runs (the
/// path is unknown): `max_executed_lines` lines executed in all (a loop that never ends);
/// `max_call_depth` calls open (parameter_store.hpp), calls of files included (a file that
/// calls itself stops there); `max_open_loops` loops open.
/// @code
///   kin5::program::interp::executor run{text, kin5::program::linuxcnc::parameter_rules()};
///   run.execute(syntax,                                   // syntax.statement_of(text_line) -> statement
///               [&](const kin5::program::text_line& line, const kin5::program::interp::statement&) { read(line); },
///               [&](const kin5::program::interp::flow_error& e) { report(e.line, e.column, e.message); });
/// @endcode
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "../call_chain.hpp"
#include "../source_location.hpp"
#include "../text.hpp"
#include "evaluate.hpp"
#include "parameter_store.hpp"
#include "statement.hpp"

namespace kin5::program::interp {

/// How much a program may execute.
struct execution_limits {
  /// Lines executed in all, ordinary and control statements alike, counting each time a loop
  /// or call runs a line again. Real programs execute a few million; past this bound the
  /// program is taken to loop for ever (`--max-executed-lines`).
  std::uint64_t max_executed_lines = 100'000'000;
  std::size_t max_open_loops = 64;  ///< loops open at once, over all open calls
};

/// Why execution stopped early, and where (the statement; `column` of its first byte).
struct flow_error {
  std::size_t line = 0;
  std::size_t column = 1;
  std::string message;
  std::string file{};  ///< the called file the statement is in (its path); empty: the main text
};

/// A file a call runs, as a `file_opener` found it.
struct called_file {
  std::string path;    ///< as errors in it name it
  std::string text;    ///< its whole text
  std::string error{};  ///< not empty: the file was found but cannot be run, and why
};

/// Finds the file a call names: `(target, names)` → the first of the file names `names` (the
/// dialect's, for the call's `target`) that exists, loaded; none when no file has one of them.
using file_opener = std::function<std::optional<called_file>(const std::string& target, const std::vector<std::string>& names)>;

/// Runs one program's text (see the file comment).
class executor {
 public:
  executor(std::string_view text, parameter_rules rules, execution_limits limits = {})
      : owned_(std::make_unique<run_state>(std::move(rules))),
        run_(*owned_),
        text_(text),
        parameters_(run_.parameters),
        executed_(run_.executed),
        limits_(limits) {}
  executor(const executor&) = delete;
  executor& operator=(const executor&) = delete;

  parameter_store& parameters() { return parameters_; }
  const parameter_store& parameters() const { return parameters_; }

  /// Interns the call chains in `table`, the call sites of the main text named `main_file`.
  /// Call it before `execute`.
  void record_calls_in(call_chains& table, file_name main_file) {
    run_.calls = &table;
    run_.main_file = std::move(main_file);
  }

  /// The calls open now, as an id into the table of `calls()`: 0 in the main program, none open.
  std::uint32_t call_chain() const { return run_.chain; }
  /// The table the call chains are interned in.
  const call_chains& calls() const { return *run_.calls; }

  /// Lines executed so far.
  std::uint64_t executed_lines() const { return executed_; }

  /// Lets calls run other files, found by `open` (see the file comment).
  void open_files_with(file_opener open) { run_.open = std::move(open); }

  /// The path of the called file whose line runs now; empty in the main text.
  const std::string& file() const {
    static const std::string main_text;
    return run_.running.empty() ? main_text : run_.running.back()->path;
  }

  /// Files loaded by calls so far (each once).
  std::size_t files_loaded() const { return run_.files.size(); }

  /// Runs the program from its first line. `syntax.statement_of(const text_line&)` says what
  /// each line is; `on_line(const text_line&, const statement&)` reads each ordinary line
  /// executed (after the statement's assignments); `on_error(flow_error)` is called once, for
  /// the error that stops the run. Returns false when an error stopped it.
  template <class Syntax, class OnLine, class OnError>
  bool execute(Syntax& syntax, OnLine&& on_line, OnError&& on_error) {
    return execute_from(position{0, 1}, syntax, on_line, on_error);
  }

 private:
  struct position {
    std::size_t offset = 0;  ///< of the line's first byte; the text's size: its end
    std::size_t number = 1;  ///< 1-based line number
  };

  template <class Syntax, class OnLine, class OnError>
  bool execute_from(position start, Syntax& syntax, OnLine& on_line, OnError& on_error) {
    for (position at = start; at.offset < text_.size();) {
      const line_at here = line_of(at);
      if (++executed_ > limits_.max_executed_lines) return fail(on_error, here.line, limit_message());
      const statement s = syntax.statement_of(here.line);
      if (s.error) return fail(on_error, here.line, s.error->message, s.error->where.column);
      std::optional<position> next = here.next;  // empty: stop after an error
      // An ordinary line with a condition (FANUC `IF [c] THEN #1 = 5`) runs only when it holds.
      const auto runs = s.kind == statement_kind::ordinary ? holds(s.condition, here.line, on_error) : std::optional<bool>(true);
      if (!runs) return false;
      if (*runs && !assign_all(s, here.line, on_error)) return false;
      switch (*runs ? s.kind : statement_kind::label) {
        case statement_kind::ordinary:
          on_line(here.line, s);
          if (s.ends_program) return end_of_file_call();
          break;
        case statement_kind::label:
        case statement_kind::end_if: break;
        case statement_kind::jump: next = jump(syntax, s, at, here.line, on_error); break;
        case statement_kind::call:
          if constexpr (runs_files<Syntax>) {
            if (!s.files.empty() && !find_label(syntax, s.target, s.direction, at)) {
              if (!call_file(syntax, s, here, on_line, on_error)) return false;
              next = here.next;
              break;
            }
          }
          next = call(syntax, s, at, here, on_error);
          break;
        case statement_kind::subprogram: {  // reached in the program's flow: its body is skipped
          const auto end = find_end_of_subprogram(syntax, here.next, s.key);
          if (!end) return fail(on_error, here.line, "subprogram " + s.key + " has no end");
          next = after(*end);
          break;
        }
        case statement_kind::return_from_call:
          if (!in_subprogram()) {
            if (caller_) {  // the called file's end
              while (!calls_.empty()) drop_call();
              return true;
            }
            if (s.ends_program) return true;
            if (s.only_in_call) break;
            return fail(on_error, here.line, "returns from a call, but no call is open");
          }
          while (calls_.back().ends != call_end::return_statement) drop_call();  // the section repeats inside end too
          next = finish_pass();
          break;
        case statement_kind::if_branch: next = branch(syntax, s, here, on_error); break;
        case statement_kind::else_if_branch:
          if (entering_else_if_) next = branch(syntax, s, here, on_error);
          else next = skip_to_end_if(syntax, here, s.key, on_error);  // the branch before it ran
          break;
        case statement_kind::else_branch: next = skip_to_end_if(syntax, here, s.key, on_error); break;
        case statement_kind::loop_begin: next = loop_top(syntax, s, at, here, on_error); break;
        case statement_kind::loop_end: next = loop_bottom(s, at, here, on_error); break;
        case statement_kind::loop_break:
          if (!in_loop()) return fail(on_error, here.line, "a loop break outside a loop");
          next = leave_loop(syntax, here.line, on_error);
          break;
        case statement_kind::loop_continue:
          if (!in_loop()) return fail(on_error, here.line, "a loop continue outside a loop");
          next = loop_end_of(syntax, loops_.back());
          if (!next) return fail(on_error, here.line, "a loop without its end");
          break;
      }
      if (!next) return false;
      if (!calls_.empty() && calls_.back().ends == call_end::end_label && at.offset == calls_.back().end.offset)
        next = finish_pass();  // the repeat's end label has run
      while (!calls_.empty() && calls_.back().ends == call_end::calling_line && next->offset == calls_.back().from.offset)
        next = finish_pass();  // back at the repeat's own line (which may end the repeat around it too)
      if (next->offset >= text_.size() && !calls_.empty())
        return fail(on_error, here.line,
                    "the text ends inside the call from line " + std::to_string(calls_.back().from.number));
      if (next->offset >= text_.size() && caller_)
        return fail(on_error, here.line, "the called file ends without returning to the call from line " +
                                             std::to_string(run_.calls->site(run_.chain).line));
      at = *next;
    }
    if (!loops_.empty()) return fail(on_error, line_of(loops_.back().begin).line, "a loop without its end");
    return true;
  }

  struct line_at {
    text_line line;
    position next;  ///< the next line's start (the end of the text after the last line)
  };
  struct open_call {
    position from;                  ///< the calling statement
    position back;                  ///< where the program goes on after the call
    position start;                 ///< the first line of each pass
    std::uint64_t passes_left = 1;  ///< this pass included
    call_end ends{};
    position end{};                 ///< `call_end::end_label`: each pass's last line
    bool frame = true;              ///< the call opened a frame of local parameters
    std::size_t loops_open = 0;     ///< loops open when the call began
  };
  struct open_loop {
    position begin;                 ///< the loop's first statement
    position body;                  ///< the line after it
    std::optional<position> end{};  ///< its end statement, once found
    std::string key;
    loop_kind kind{};
    std::uint64_t runs_left = 0;    ///< counted loops
    double last = 0;                ///< counting loops: the counter's last value
    std::optional<parameter_key> counter{};  ///< counting loops
    std::size_t call_depth = 0;     ///< calls open when it began
  };
  struct label_entry {
    std::string name;
    position at;
  };

  /// What the main text's executor and those of the files it calls share.
  struct run_state {
    explicit run_state(parameter_rules rules) : parameters(std::move(rules)) {}
    parameter_store parameters;
    std::uint64_t executed = 0;
    call_chains own_calls{};
    call_chains* calls = &own_calls;  // where the chains are interned (`record_calls_in`)
    file_name main_file{};            // of the main text's call sites
    std::uint32_t chain = 0;          // the calls open now: an id in `calls`
    file_opener open{};
    std::map<std::string, std::shared_ptr<const called_file>, std::less<>> files{};  // by calling file and target
    std::vector<const called_file*> running{};  // the called files open, outermost first
  };

  /// A called file's executor: the caller's run, `file`'s text.
  executor(executor& caller, const called_file& file)
      : run_(caller.run_),
        text_(file.text),
        parameters_(run_.parameters),
        executed_(run_.executed),
        limits_(caller.limits_),
        caller_(&caller),
        text_file_(file.path),
        outer_calls_(caller.outer_calls_ + caller.calls_.size() + 1),
        outer_loops_(caller.outer_loops_ + caller.loops_.size()) {}

  std::unique_ptr<run_state> owned_;  // the main text's executor's
  run_state& run_;
  std::string_view text_;
  parameter_store& parameters_;
  std::uint64_t& executed_;
  execution_limits limits_;
  executor* caller_ = nullptr;    // a called file's executor: the one that called it
  file_name text_file_{};         // of this text's call sites: a called file's path
  std::size_t outer_calls_ = 0;   // calls open in the callers, the file calls included
  std::size_t outer_loops_ = 0;   // loops open in the callers
  std::vector<open_call> calls_;
  std::vector<open_loop> loops_;
  std::optional<std::vector<label_entry>> labels_;  // in file order, once scanned
  bool entering_else_if_ = false;                   // a false branch passed control to this ELSEIF
  mutable std::size_t lf_from_ = std::string_view::npos;  // line_of's cache: the first LF at or after
  mutable std::size_t lf_ = std::string_view::npos;       // lf_from_ (npos: none)

  /// The line at `p` and where the next starts: lines end at LF, CRLF or a lone CR, as
  /// `for_each_line` (text.hpp) splits them, so both count the same line numbers. The next LF
  /// is searched once for all the lines before it (a text of lone CRs is not searched again per line).
  line_at line_of(position p) const {
    if (!(lf_from_ <= p.offset && (lf_ == std::string_view::npos || p.offset <= lf_))) {
      lf_from_ = p.offset;
      lf_ = text_.find('\n', p.offset);
    }
    const std::size_t lf = lf_ == std::string_view::npos ? text_.size() : lf_;
    const std::size_t cr = text_.substr(0, lf).find('\r', p.offset);
    const std::size_t end = cr == std::string_view::npos ? lf : cr;
    if (end == text_.size()) return {{text_.substr(p.offset), p.number}, {text_.size(), p.number + 1}};
    std::size_t next = end + 1;
    if (text_[end] == '\r' && next < text_.size() && text_[next] == '\n') ++next;
    return {{text_.substr(p.offset, end - p.offset), p.number}, {next, p.number + 1}};
  }

  position after(position p) const { return line_of(p).next; }

  template <class OnError>
  bool fail(OnError& on_error, const text_line& line, std::string message, std::size_t column = 0) {
    if (column == 0) {
      column = 1;
      while (column <= line.text.size() && (line.text[column - 1] == ' ' || line.text[column - 1] == '\t')) ++column;
    }
    on_error(flow_error{line.number, column, std::move(message), run_.running.empty() ? std::string() : run_.running.back()->path});
    return false;
  }

  /// The program ends at this line: in a called file, the call ends instead (see the file comment).
  bool end_of_file_call() {
    if (caller_) while (!calls_.empty()) drop_call();
    return true;
  }

  std::size_t calls_open() const { return outer_calls_ + calls_.size(); }

  template <class OnError>
  std::optional<position> failed(OnError& on_error, const text_line& line, std::string message, std::size_t column = 0) {
    fail(on_error, line, std::move(message), column);
    return std::nullopt;
  }

  bool in_loop() const { return !loops_.empty() && loops_.back().call_depth == calls_.size(); }

  /// Whether a subprogram call is open (not only section repeats).
  bool in_subprogram() const {
    return std::any_of(calls_.begin(), calls_.end(), [](const open_call& c) { return c.ends == call_end::return_statement; });
  }

  std::string limit_message() const {
    std::string m = "more than " + std::to_string(limits_.max_executed_lines) + " lines executed";
    if (!loops_.empty()) m += ": the loop at line " + std::to_string(loops_.back().begin.number) + " may never end";
    else if (!calls_.empty()) m += ": the call at line " + std::to_string(calls_.back().from.number) + " may never end";
    else m += ": a jump may repeat for ever";
    return m + " (--max-executed-lines raises the bound)";
  }

  template <class OnError>
  bool assign_all(const statement& s, const text_line& line, OnError& on_error) {
    for (const assignment& a : s.assignments) {
      const evaluation v = evaluate(a.value, parameters_);
      if (!v.ok()) return fail(on_error, line, v.error->message, v.error->where.column);
      const parameter_target t = parameter_of(a.target, parameters_);
      if (!t.key) return fail(on_error, line, t.error->message, t.error->where.column);
      if (auto why = parameters_.assign(*t.key, v.value))
        return fail(on_error, line, *why, a.target.at(a.target.root).where.column);
    }
    return true;
  }

  /// Whether `condition` holds (none: always); empty after reporting an error.
  template <class OnError>
  std::optional<bool> holds(const std::optional<expression>& condition, const text_line& line, OnError& on_error) {
    if (!condition) return true;
    const evaluation v = evaluate(*condition, parameters_);
    if (!v.ok()) {
      fail(on_error, line, v.error->message, v.error->where.column);
      return std::nullopt;
    }
    return v.value != 0.0;
  }

  /// A repeat count: a whole number, not negative (none: 1); empty after reporting an error.
  template <class OnError>
  std::optional<std::uint64_t> count_of(const statement& s, const text_line& line, OnError& on_error) {
    if (!s.count) return 1;
    const evaluation v = evaluate(*s.count, parameters_);
    if (!v.ok()) {
      fail(on_error, line, v.error->message, v.error->where.column);
      return std::nullopt;
    }
    const double whole = std::round(v.value);
    if (std::abs(v.value - whole) > 1e-9 || whole < 0 || whole > 1e12) {
      fail(on_error, line, "repeat count " + std::to_string(v.value) + " is not a whole number of 0 or more",
           s.count->at(s.count->root).where.column);
      return std::nullopt;
    }
    return static_cast<std::uint64_t>(whole);
  }

  static std::string where_searched(jump_direction d) {
    switch (d) {
      case jump_direction::forward: return "after this line";
      case jump_direction::backward: return "before this line";
      case jump_direction::either:
      case jump_direction::backward_then_forward: break;
    }
    return "in this file";
  }

  template <class Syntax>
  void index_labels(Syntax& syntax) {
    labels_.emplace();
    for (position p{0, 1}; p.offset < text_.size();) {
      const line_at l = line_of(p);
      statement s = syntax.statement_of(l.line);
      if (!s.label.empty()) labels_->push_back({std::move(s.label), p});
      if (!s.block_label.empty()) labels_->push_back({std::move(s.block_label), p});
      p = l.next;
    }
  }

  /// The label `name` searched in `direction` from the line at `from`: the nearest after it
  /// (forward; `either` then searches before it), or the nearest before it (backward).
  template <class Syntax>
  std::optional<position> find_label(Syntax& syntax, const std::string& name, jump_direction direction, position from) {
    if (!labels_) index_labels(syntax);
    if (direction == jump_direction::backward_then_forward) {
      if (auto before = find_label(syntax, name, jump_direction::backward, from)) return before;
      return find_label(syntax, name, jump_direction::forward, from);
    }
    if (direction != jump_direction::backward)
      for (const label_entry& e : *labels_)
        if (e.at.offset > from.offset && e.name == name) return e.at;
    if (direction == jump_direction::forward) return std::nullopt;
    std::optional<position> nearest;
    for (const label_entry& e : *labels_)
      if (e.at.offset <= from.offset && e.name == name) nearest = e.at;
    return nearest;
  }

  /// The first line at or after `from` that defines label `name`.
  template <class Syntax>
  std::optional<position> find_label_at_or_after(Syntax& syntax, const std::string& name, position from) {
    if (!labels_) index_labels(syntax);
    for (const label_entry& e : *labels_)
      if (e.at.offset >= from.offset && e.name == name) return e.at;
    return std::nullopt;
  }

  template <class Syntax, class OnError>
  std::optional<position> jump(Syntax& syntax, const statement& s, position at, const text_line& line, OnError& on_error) {
    const auto taken = holds(s.condition, line, on_error);
    if (!taken) return std::nullopt;
    if (!*taken) return after(at);
    const auto target = find_label(syntax, s.target, s.direction, at);
    if (!target && s.target_optional) return after(at);
    if (!target) return failed(on_error, line, "jump to " + s.target + ": no such label " + where_searched(s.direction));
    leave_loops_for(syntax, *target);
    return target;
  }

  template <class Syntax, class OnError>
  std::optional<position> call(Syntax& syntax, const statement& s, position at, const line_at& here, OnError& on_error) {
    const auto count = count_of(s, here.line, on_error);
    if (!count) return std::nullopt;
    if (*count == 0) return here.next;
    const auto target = find_label(syntax, s.target, s.direction, at);
    if (!target) return failed(on_error, here.line, "call of " + s.target + ": no such label " + where_searched(s.direction));
    const statement first = syntax.statement_of(line_of(*target).line);
    const position start =
        first.kind == statement_kind::label || first.kind == statement_kind::subprogram ? after(*target) : *target;
    if (s.ends == call_end::calling_line && start.offset == at.offset) return here.next;  // an empty section
    position end{};
    if (s.ends == call_end::end_label) {
      const auto last = find_label_at_or_after(syntax, s.end_target, *target);
      if (!last)
        return failed(on_error, here.line, "repeat of " + s.target + " to " + s.end_target + ": no label " + s.end_target +
                                               " after " + s.target);
      end = *last;
    }
    if (s.call_frame) {
      if (!enter_frame(s, here.line, on_error)) return std::nullopt;
    } else if (calls_open() >= parameter_store::max_call_depth) {
      return failed(on_error, here.line, "calls nested more than " + std::to_string(parameter_store::max_call_depth) + " deep");
    }
    calls_.push_back({at, here.next, start, *count, s.ends, end, s.call_frame, loops_.size()});
    open_call_at(here.line);
    return start;
  }

  /// Names `names` as a list: "A", "A or B", "A, B or C".
  static std::string one_of(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i)
      out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return out;
  }

  /// The loaded file that holds `s`'s target (loaded now when first called); none after
  /// reporting why there is none.
  template <class OnError>
  std::shared_ptr<const called_file> file_of(const statement& s, const text_line& line, OnError& on_error) {
    const std::string what = "call of " + s.target + ": ";
    if (!run_.open) {
      fail(on_error, line, what + "no label " + s.target + " in this file, and no directory to look for its file " +
                               one_of(s.files) + " in (--include-dir DIR names the directory that holds it)");
      return nullptr;
    }
    // By the calling file too: a name may be relative to the calling file's directory
    // (Heidenhain's CALL PGM), so the same name called from two files may be two files.
    const std::string key = (run_.running.empty() ? std::string() : run_.running.back()->path) + '\n' + s.target;
    auto found = run_.files.find(key);
    if (found == run_.files.end()) {
      std::optional<called_file> f = run_.open(s.target, s.files);
      if (!f) {
        fail(on_error, line, what + "no label " + s.target + " in this file, nor a file " + one_of(s.files) +
                                 " in the include directories (--include-dir)");
        return nullptr;
      }
      if (!f->error.empty()) {
        fail(on_error, line, what + f->path + ": " + f->error);
        return nullptr;
      }
      found = run_.files.emplace(key, std::make_shared<const called_file>(std::move(*f))).first;
    }
    return found->second;
  }

  /// A call of another file (see the file comment): its passes run, each to its file's return
  /// or end; false after reporting an error (in the caller or in the file).
  template <class Syntax, class OnLine, class OnError>
  bool call_file(Syntax& syntax, const statement& s, const line_at& here, OnLine& on_line, OnError& on_error) {
    const auto count = count_of(s, here.line, on_error);
    if (!count) return false;
    if (*count == 0) return true;
    const std::shared_ptr<const called_file> file = file_of(s, here.line, on_error);
    if (!file) return false;
    if (calls_open() >= parameter_store::max_call_depth)
      return fail(on_error, here.line, "calls nested more than " + std::to_string(parameter_store::max_call_depth) +
                                           " deep (a file that calls itself without end?)");
    for (std::uint64_t pass = 0; pass < *count; ++pass) {
      if (s.call_frame && !enter_frame(s, here.line, on_error)) return false;
      open_call_at(here.line);
      run_.running.push_back(file.get());
      executor called{*this, *file};
      Syntax called_syntax = syntax_for(syntax, std::string_view(file->text));
      const bool ok = called.run_file(called_syntax, s.target, on_line, on_error);
      run_.running.pop_back();
      run_.chain = run_.calls->outer(run_.chain);
      if (!ok) return false;
      if (s.call_frame) parameters_.leave_call();
    }
    return true;
  }

  /// Whether a syntax can be had for another text (`syntax_for`): only then are calls of files run.
  template <class Syntax>
  static constexpr bool runs_files = requires(Syntax& s, std::string_view t) { s.for_text(t); } ||
                                     std::is_constructible_v<Syntax, std::string_view> ||
                                     std::is_default_constructible_v<Syntax>;

  /// The syntax of another text: `syntax.for_text(text)` when the dialect's syntax has one, else
  /// one made from the text, or a fresh one (a syntax that keeps nothing of its text).
  template <class Syntax>
  static Syntax syntax_for(Syntax& syntax, std::string_view text) {
    if constexpr (requires { syntax.for_text(text); }) return syntax.for_text(text);
    else if constexpr (std::is_constructible_v<Syntax, std::string_view>) return Syntax(text);
    else return Syntax();
  }

  /// Runs this called file: from the line after its label `target` when it defines one (a
  /// subprogram's first line), else from its first line.
  template <class Syntax, class OnLine, class OnError>
  bool run_file(Syntax& syntax, const std::string& target, OnLine& on_line, OnError& on_error) {
    position start{0, 1};
    if (const auto l = find_label_at_or_after(syntax, target, start)) {
      const statement first = syntax.statement_of(line_of(*l).line);
      start = first.kind == statement_kind::label || first.kind == statement_kind::subprogram ? after(*l) : *l;
    }
    return execute_from(start, syntax, on_line, on_error);
  }

  /// Opens the frame of local parameters of call `s` and sets its arguments, evaluated with the
  /// caller's parameters (`o2 call [#1]` passes the caller's #1); false after reporting an error.
  template <class OnError>
  bool enter_frame(const statement& s, const text_line& line, OnError& on_error) {
    std::vector<double> values;
    values.reserve(s.arguments.size());
    for (const argument& a : s.arguments) {
      const evaluation v = evaluate(a.value, parameters_);
      if (!v.ok()) return fail(on_error, line, v.error->message, v.error->where.column);
      values.push_back(v.value);
    }
    if (!parameters_.enter_call())
      return fail(on_error, line, "calls nested more than " + std::to_string(parameter_store::max_call_depth) + " deep");
    for (std::size_t i = 0; i < values.size(); ++i)
      if (auto why = parameters_.assign(s.arguments[i].key, values[i])) return fail(on_error, line, *why);
    return true;
  }

  /// The running pass of the innermost call is over: run it again or go back to the caller.
  position finish_pass() {
    open_call& c = calls_.back();
    loops_.resize(c.loops_open);
    if (--c.passes_left > 0) return c.start;
    const position back = c.back;
    drop_call();
    return back;
  }

  /// Closes the innermost call, its loops and its local parameters.
  void drop_call() {
    loops_.resize(calls_.back().loops_open);
    if (calls_.back().frame) parameters_.leave_call();
    calls_.pop_back();
    run_.chain = run_.calls->outer(run_.chain);
  }

  /// A call from `line` of this text opens: the chain of the calls open gains its site.
  void open_call_at(const text_line& line) {
    std::size_t column = 1;
    while (column <= line.text.size() && (line.text[column - 1] == ' ' || line.text[column - 1] == '\t')) ++column;
    if (!caller_) text_file_ = run_.main_file;  // `record_calls_in` may name it after construction
    run_.chain = run_.calls->enter(run_.chain, {text_file_, line.number, column});
  }

  /// The first statement from `from` on of one of `kinds` that pairs with an opening statement
  /// of key `key`: the same key when it has one; else at the same nesting, where statements of
  /// kind `opens` and `closes` without a key nest.
  template <class Syntax>
  std::optional<position> find_pair(Syntax& syntax, position from, const std::string& key,
                                    std::initializer_list<statement_kind> kinds, statement_kind opens,
                                    statement_kind closes) {
    int depth = 0;
    for (position p = from; p.offset < text_.size();) {
      const line_at l = line_of(p);
      const statement s = syntax.statement_of(l.line);
      const bool wanted = std::find(kinds.begin(), kinds.end(), s.kind) != kinds.end();
      if (!key.empty()) {
        if (wanted && s.key == key) return p;
      } else if (s.key.empty()) {
        if (s.kind == opens) ++depth;
        else if (wanted && depth == 0) return p;
        else if (s.kind == closes) --depth;
      }
      p = l.next;
    }
    return std::nullopt;
  }

  template <class Syntax>
  std::optional<position> find_end_of_subprogram(Syntax& syntax, position from, const std::string& key) {
    for (position p = from; p.offset < text_.size();) {
      const line_at l = line_of(p);
      const statement s = syntax.statement_of(l.line);
      if (s.kind == statement_kind::return_from_call && s.ends_subprogram && s.key == key) return p;
      p = l.next;
    }
    return std::nullopt;
  }

  /// IF or ELSEIF: on into its lines when its condition holds; else to the next branch.
  template <class Syntax, class OnError>
  std::optional<position> branch(Syntax& syntax, const statement& s, const line_at& here, OnError& on_error) {
    entering_else_if_ = false;
    const auto taken = holds(s.condition, here.line, on_error);
    if (!taken) return std::nullopt;
    if (*taken) return here.next;
    const auto next_branch = find_pair(syntax, here.next, s.key,
                                       {statement_kind::else_if_branch, statement_kind::else_branch, statement_kind::end_if},
                                       statement_kind::if_branch, statement_kind::end_if);
    if (!next_branch) return failed(on_error, here.line, "IF without its end");
    if (syntax.statement_of(line_of(*next_branch).line).kind == statement_kind::else_if_branch) {
      entering_else_if_ = true;
      return next_branch;
    }
    return after(*next_branch);
  }

  template <class Syntax, class OnError>
  std::optional<position> skip_to_end_if(Syntax& syntax, const line_at& here, const std::string& key, OnError& on_error) {
    const auto end = find_pair(syntax, here.next, key, {statement_kind::end_if}, statement_kind::if_branch,
                               statement_kind::end_if);
    if (!end) return failed(on_error, here.line, "ELSE without the end of its IF");
    return after(*end);
  }

  template <class Syntax>
  std::optional<position> loop_end_of(Syntax& syntax, open_loop& l) {
    if (!l.end) l.end = find_pair(syntax, l.body, l.key, {statement_kind::loop_end}, statement_kind::loop_begin, statement_kind::loop_end);
    return l.end;
  }

  template <class Syntax, class OnError>
  std::optional<position> loop_top(Syntax& syntax, const statement& s, position at, const line_at& here, OnError& on_error) {
    const bool again = in_loop() && loops_.back().begin.offset == at.offset;  // back at the top: test again
    if (!again) {
      if (outer_loops_ + loops_.size() >= limits_.max_open_loops)
        return failed(on_error, here.line, "loops nested more than " + std::to_string(limits_.max_open_loops) + " deep");
      std::uint64_t runs = 0;
      if (s.loop == loop_kind::counted) {
        const auto c = count_of(s, here.line, on_error);
        if (!c) return std::nullopt;
        runs = *c;
      }
      loops_.push_back({at, here.next, std::nullopt, s.key, s.loop, runs, 0, std::nullopt, calls_.size()});
      if (s.loop == loop_kind::counted && runs == 0) return leave_loop(syntax, here.line, on_error);
      if (s.loop == loop_kind::counting) return count_from(syntax, s, here, on_error);
    }
    if (s.loop != loop_kind::test_first) return here.next;
    const auto go_on = holds(s.condition, here.line, on_error);
    if (!go_on) return std::nullopt;
    return *go_on ? std::optional<position>(here.next) : leave_loop(syntax, here.line, on_error);
  }

  /// A counting loop begins: its counter takes its first value and its last is evaluated; no
  /// run when the first is past the last.
  template <class Syntax, class OnError>
  std::optional<position> count_from(Syntax& syntax, const statement& s, const line_at& here, OnError& on_error) {
    open_loop& l = loops_.back();
    if (!s.counter || !s.count) return failed(on_error, here.line, "a counting loop without its counter or last value");
    const evaluation first = evaluate(s.counter->value, parameters_);
    if (!first.ok()) return failed(on_error, here.line, first.error->message, first.error->where.column);
    const evaluation last = evaluate(*s.count, parameters_);
    if (!last.ok()) return failed(on_error, here.line, last.error->message, last.error->where.column);
    const parameter_target t = parameter_of(s.counter->target, parameters_);
    if (!t.key) return failed(on_error, here.line, t.error->message, t.error->where.column);
    if (auto why = parameters_.assign(*t.key, first.value))
      return failed(on_error, here.line, *why, s.counter->target.at(s.counter->target.root).where.column);
    l.counter = *t.key;
    l.last = last.value;
    if (first.value <= last.value) return here.next;
    return leave_loop(syntax, here.line, on_error);
  }

  template <class OnError>
  std::optional<position> loop_bottom(const statement& s, position at, const line_at& here, OnError& on_error) {
    if (!in_loop()) return failed(on_error, here.line, "the end of a loop that is not open");
    open_loop& l = loops_.back();
    l.end = at;
    bool again = true;
    switch (l.kind) {
      case loop_kind::test_first: return l.begin;  // the test is at the top
      case loop_kind::counted: again = --l.runs_left > 0; break;
      case loop_kind::endless: break;
      case loop_kind::counting: {
        const parameter_read c = parameters_.read(*l.counter);
        if (!c.value) return failed(on_error, here.line, c.why);
        if (auto why = parameters_.assign(*l.counter, *c.value + 1)) return failed(on_error, here.line, *why);
        again = *c.value + 1 <= l.last;
        break;
      }
      case loop_kind::test_last: {
        const auto h = holds(s.condition, here.line, on_error);
        if (!h) return std::nullopt;
        again = *h != s.until;
        break;
      }
    }
    if (again) return l.body;
    loops_.pop_back();
    return here.next;
  }

  /// Closes the innermost loop and goes on after its end statement.
  template <class Syntax, class OnError>
  std::optional<position> leave_loop(Syntax& syntax, const text_line& line, OnError& on_error) {
    const auto end = loop_end_of(syntax, loops_.back());
    loops_.pop_back();
    if (!end) return failed(on_error, line, "a loop without its end");
    return after(*end);
  }

  /// A jump to `target` closes every loop of the running call that does not hold it.
  template <class Syntax>
  void leave_loops_for(Syntax& syntax, position target) {
    while (in_loop()) {
      open_loop& l = loops_.back();
      const auto end = loop_end_of(syntax, l);
      if (target.offset > l.begin.offset && end && target.offset <= end->offset) break;
      loops_.pop_back();
    }
  }
};

}  // namespace kin5::program::interp
