/// @file program/iso/reader.hpp
/// The second stage of the ISO / Fanuc reader: the words of a line (lexer.hpp) become a `block`.
/// G0–G3 with `I J K` (incremental centre) or `R`, G17/G18/G19, `G43.4` / `G43.5` (tool-tip
/// tracking; under G43.5 `I J K` in G0/G1 blocks are the tool-axis vector), `G49`, G93/G94, G21,
/// `G53` / `G28` / `G30` (machine coordinates), M30/M2, G20/G21 (an inch program's lengths and
/// per-minute feeds are converted to mm: units.hpp). Tool length compensation: `G43 H n`,
/// `G43.4 H n`, `G43.5 H n` switch it on with offset n (without H: the last H of the program),
/// `G43` after `G43.4` / `G43.5` ends tracking (one modal group, 08), `G49` off (`state.length_compensation`, `length_register`). Cutter radius compensation:
/// `G41 D n` / `G42 D n` (without D: the last D), `G40` (`state.radius_compensation`,
/// `radius_register`; start-up and cancel in an arc refused). G91 axis words are resolved to the
/// positions they reach (`absolute_positions`; refused where the position they add to is not
/// known). Errors: G95, a unit change after motion, active frames (G68, G68.2, G51, G52 with
/// offsets, G92), canned cycles, G10, macro and subprogram calls (G65, G66, M98, M97,
/// M99), G44, `H` without G43/G43.4/G43.5, G43 without H before
/// any H, and any word not understood, moving or not: each at its word, naming it. G17/G18/G19, G90/G91 and G40 are read into `state`
/// (working plane, distance mode, radius compensation off), `G4 X2.` / `G4 P2000` into
/// `state.dwell_s` (seconds; a block of its own). Harmless modal words (G05.1 Q1,
/// D1, …) are kept as written; `%` lines pass through. Work offsets
/// G54 … G59 and G54.1 P n are read into `state.work_offset` (work_offsets.hpp). The lines run
/// through the interpreter (../interp/executor.hpp) with the dialect's statements (`Own::syntax`:
/// statements.hpp): a parameter assignment (`#1 = 5000`, `#2 = [#1 * 2]`, a line of its own) is
/// an `assignment` block, its text as written when it assigns a number, else the number it
/// assigned (`#2 = 10000`); a word whose value is a parameter or an expression (`F#1`, `X-#1`,
/// `Z[#2 / 4]`) takes the value the interpreter's parameters give it, written as the number
/// assigned when it is one parameter assigned a number (`#1 = 5000.` makes `F#1` `F5000.`). A
/// parameter without a value, or one the control owns (`#5221`, a work offset), is refused
/// where it is written, naming it (the parameter rules: parameter_rules.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../called_files.hpp"
#include "../interp/evaluate.hpp"
#include "../interp/executor.hpp"
#include "../lexing.hpp"
#include "../machine_functions.hpp"
#include "../modal.hpp"
#include "../number.hpp"
#include "../parameters.hpp"
#include "../read_limits.hpp"
#include "../text.hpp"
#include "../transmission.hpp"
#include "../units.hpp"
#include "lexer.hpp"
#include "reader_state.hpp"
#include "vocabulary.hpp"

namespace kin5::program::iso::detail {

/// Reads the lines of one program into blocks; `Own` reads the words of a dialect built on ISO.
template <class Own = no_own_words>
class basic_reader {
 public:
  basic_reader(const std::string& file, read_result& result, const block_sink& on_block)
      : file_(file), result_(result), on_block_(on_block) {}

  /// Runs the program `text` (see the file comment), its lines executed at most as `limits` says.
  /// After the line that ends the program (M30, M2) the control stops; the lines after it are
  /// read as written (a writer of another dialect refuses one with an effect), up to the first
  /// that starts a part of the file the program calls (`O1000`, the `N1000` of an M97) or is a
  /// statement.
  void run(std::string_view text, interp::execution_limits limits = {current_read_limits().max_executed_lines}) {
    interp::executor x{text, Own::parameter_rules(), limits};
    x.open_files_with(called_file_opener(current_read_limits()));
    store_ = &x.parameters();
    run_ = &x;
    x.record_calls_in(result_.calls, file_);
    typename Own::syntax syntax{text};
    std::optional<text_line> ended;
    const file_name main_file = file_;
    std::string running;  // the called file being read; empty: the main text
    const auto in_file = [&](const std::string& path) {
      if (path == running) return;
      running = path;
      file_ = path.empty() ? main_file : file_name(path);
      in_called_file_ = !path.empty();
    };
    const bool ran = x.execute(
        syntax,
        [&](const text_line& line, const interp::statement& s) {
          in_file(x.file());
          result_.reading_call = x.call_chain();
          read_line(line, s);
          if (s.ends_program && !running.empty()) {
            line_ = line.number;
            error(1, "the end of the program (M30, M2) in a called program: end it with M99, which returns to the "
                     "caller");
          }
          if (s.ends_program && running.empty()) ended = line;
        },
        [&](const interp::flow_error& e) {
          in_file(e.file);
          result_.reading_call = x.call_chain();
          line_ = e.line;
          error(e.column, syntax.explain(e.message));
        });
    in_file({});
    const bool ended_in_call = x.call_chain() != 0;
    result_.reading_call = 0;
    if (ran && ended && !ended_in_call) {
      // The lines after the end, split as the executor splits them (LF, CRLF or a lone CR).
      std::size_t offset = static_cast<std::size_t>(ended->text.data() - text.data()) + ended->text.size();
      std::size_t number = ended->number;
      while (offset < text.size()) {
        offset += text[offset] == '\r' && offset + 1 < text.size() && text[offset + 1] == '\n' ? 2 : 1;
        if (offset >= text.size()) break;
        const std::size_t end = std::min(text.find_first_of("\r\n", offset), text.size());
        const text_line line{text.substr(offset, end - offset), ++number};
        const interp::statement st = syntax.statement_of(line);
        if (st.kind != interp::statement_kind::ordinary || st.error || st.condition || !st.assignments.empty() ||
            syntax.starts_called_part(st))
          break;
        read_line(line, st);
        offset = end;
      }
    }
    store_ = nullptr;
    run_ = nullptr;
  }

 private:
  file_name file_;  // one string for every location in the file
  read_result& result_;
  const block_sink& on_block_;
  reader_state state_;
  std::size_t line_ = 0;
  bool failed_ = false;
  std::vector<word> words_;  // reused from line to line
  Own own_;
  interp::parameter_store* store_ = nullptr;               // the running program's parameters
  const interp::executor* run_ = nullptr;                  // the running program's executor
  bool in_called_file_ = false;                           // the line read is in a file a call runs
  std::map<interp::parameter_key, parameter_literal> literals_;  // parameters last assigned a number, as written
  std::vector<interp::expression> values_;                // the computed values of this line's words
  std::deque<std::string> substituted_;                   // the text of this line's computed words
  int decimals_[6] = {};                                  // the decimals of this line's X Y Z A B C positions

  void error(std::size_t column, std::string message) {
    result_.add_error({{file_, line_, column}, std::move(message)});
    failed_ = true;
  }

  void read_line(const text_line& line, const interp::statement& statement) {
    const std::string_view s = line.text;
    const std::size_t first = lexing::skip_blanks(s, 0);
    if (first == s.size()) return;
    std::size_t end = s.size();
    while (end > first && is_space(s[end - 1])) --end;
    line_ = line.number;
    failed_ = false;
    block b;
    b.where = {file_, line.number, first + 1};
    b.call_chain = result_.reading_call;
    b.text = std::string(s.substr(first, end - first));
    if (!statement.label.empty() && statement.label[0] == 'O' && run_ && run_->call_chain() != 0) return;  // a called program's number
    if (!statement.assignments.empty()) {
      if (auto problem = own_.line(s, first, end)) error(problem->column, problem->message);  // LinuxCNC's (ABORT, …)
      else assigned(statement, s, b);
      on_block_(std::move(b));
      return;
    }
    if constexpr (Own::alarm_parameter != 0)
      if (alarm(s, first, end, b)) {
        on_block_(std::move(b));
        return;
      }
    if (s[first] == '%' && in_called_file_) return;  // a called file's tape marks: the program's are the main text's
    if (s[first] == '%') {  // a tape mark (FANUC B-64014EN/03 §2.5; LinuxCNC file delimiters)
      b.passthrough = true;
      b.framing = true;
      on_block_(std::move(b));
      return;
    }
    words_.clear();
    values_.clear();
    substituted_.clear();
    auto problem = own_.line(s, first, end);
    if (!problem)
      problem = lex_line(s, first, end, words_, b.comment, computed_values{&Own::read_value, line.number, &values_},
                         Own::comments);
    if (!problem) problem = substitute();
    if (problem) error(problem->column, problem->message);
    const auto report = [this](std::size_t column, std::string message) { error(column, std::move(message)); };
    if (!failed_) own_.take(words_, b, report);
    if (!failed_) interpret(b);
    if (!failed_) own_.check(b, report);
    on_block_(std::move(b));
  }

  /// `#3000 = n (MESSAGE)` (after a block number): the program stops with alarm n and the
  /// message of the line's comments (FANUC Custom Macro B, system variable #3000; Haas the same;
  /// docs/dialects/iso.md). The syntax leaves it to this reader, not the executor (statements.hpp).
  /// A number that is not whole, or outside 0 … 9999, is refused: which alarm a control then
  /// gives is its own. False when the line is no such assignment.
  bool alarm(std::string_view s, std::size_t first, std::size_t end, block& b) {
    std::optional<long> number;
    const std::size_t i = detail::after_block_number(s, first, end, &number);
    static_assert(Own::alarm_parameter == 3000, "the alarm variable is #3000");
    constexpr std::string_view name = "#3000";
    if (s.substr(i, name.size()) != name || (i + name.size() < end && is_digit(s[i + name.size()])))
      return false;
    interp::statement st;
    const auto after = detail::read_assignment(macro_spelling, true, s, i, detail::code_end(s, end), line_, st);
    if (!after) {
      error(st.error->where.column, st.error->message);
      return true;
    }
    const interp::expression& value = st.assignments.back().value;
    const interp::evaluation v = interp::evaluate(value, *store_);
    if (!v.ok()) {
      error(v.error->where.column, v.error->message);
      return true;
    }
    if (!(v.value >= 0 && v.value <= 9999 && v.value == std::floor(v.value))) {
      error(value.at(value.root).where.column, std::string(name) + " = " + written(v.value) +
                                                   ": an alarm number is a whole number from 0 to 9999");
      return true;
    }
    std::vector<word> others;
    std::optional<std::string> comment;
    if (auto p = lex_line(s, *after, end, others, comment)) error(p->column, p->message);
    else if (!others.empty()) error(others.front().column, "a word after the alarm " + std::string(name) +
                                                               ": the alarm takes its block alone");
    b.alarm = alarm_stop{comment.value_or(""), static_cast<long long>(v.value)};
    if (number) b.number = *number;
    return true;
  }

  /// The number `value` as a word or an assignment writes it: 12 decimals at most.
  static std::string written(double value) {
    std::string out;
    append_number(out, value, 12);
    return out;
  }

  /// The text of number `root` of `e` (signed: `-2.5`) in line `s`, when the node is one.
  static std::optional<std::string> literal_text(const interp::expression& e, interp::node_id root, std::string_view s) {
    const interp::node* n = &e.at(root);
    const std::size_t from = n->where.column;
    if (n->kind == interp::node_kind::unary && (n->unary == interp::unary_op::negate || n->unary == interp::unary_op::plus))
      n = &e.at(n->a);
    if (n->kind != interp::node_kind::number || from == 0 || n->where.column + n->where.length - 1 > s.size()) return {};
    return std::string(s.substr(from - 1, n->where.column + n->where.length - from));
  }

  /// A line of parameter assignments, run by the executor: an `assignment` block, its text as
  /// written when each assigns a number to a parameter named by a number, else the numbers
  /// assigned (`#3 = 10`), so that the program written reads back to the same values.
  void assigned(const interp::statement& statement, std::string_view s, block& b) {
    b.passthrough = b.assignment = true;
    bool as_written = !statement.condition;  // `IF [c] THEN #1 = 5`: the assignment made
    std::string text;
    for (const interp::assignment& a : statement.assignments) {
      const interp::parameter_target t = interp::parameter_of(a.target, *store_);
      if (!t.key) continue;  // the executor set it: not reached
      const interp::parameter_read v = store_->read(*t.key);
      if (!v.value) continue;
      const interp::node& target = a.target.at(a.target.root);
      if (target.kind == interp::node_kind::numbered_parameter && a.target.at(target.a).kind != interp::node_kind::number)
        as_written = false;
      const auto literal = literal_text(a.value, a.value.root, s);
      if (literal) literals_[*t.key] = parameter_literal{*v.value, *literal};
      else literals_.erase(*t.key), as_written = false;
      if (!writable(*v.value))
        return error(a.value.at(a.value.root).where.column,
                     "parameter " + t.key->shown() + " is assigned a number no NC program can hold (magnitude above 1e9)");
      text += (text.empty() ? "" : " ") + t.key->shown() + " = " + (literal ? *literal : written(*v.value));
    }
    if (!as_written) b.text = text;
  }

  /// The number a computed value `e` (= `value`) stands for as written: the number assigned to
  /// the one parameter it is (negated: `X-#1`), or `value` written.
  std::string written_as(const interp::expression& e, double value) const {
    const interp::node& root = e.at(e.root);
    const bool negated = root.kind == interp::node_kind::unary && root.unary == interp::unary_op::negate;
    const interp::node_id p = negated ? root.a : e.root;
    const interp::node_kind k = e.at(p).kind;
    if (k == interp::node_kind::numbered_parameter || k == interp::node_kind::named_parameter) {
      const interp::parameter_target t = interp::parameter_of(detail::rooted(e, p), *store_);
      if (t.key)
        if (const auto it = literals_.find(*t.key); it != literals_.end()) {
          const parameter_literal n = negated ? it->second.negated() : it->second;
          if (n.value == value) return n.written;
        }
    }
    return written(value);
  }

  /// Each word whose value is computed (`X#1`, `Z[#2 / 4]`) takes it, as if written there; the
  /// first that has none (an unassigned parameter, a division by zero) is the problem that
  /// stops the line.
  std::optional<lex_problem> substitute() {
    for (word& w : words_) {
      if (!w.computed) continue;
      const interp::expression& e = values_[*w.computed];
      const interp::evaluation v = interp::evaluate(e, *store_);
      if (!v.ok()) return lex_problem{v.error->where.column, v.error->message};
      double value = v.value;
      if (!writable(value)) return lex_problem{w.column, "value out of range"};
      std::string n = written_as(e, value);
      if (Own::whole_address(w.letter) && std::floor(value) != value) {  // the control rounds it
        value = std::round(value);
        n = format_number(value, 0);
      }
      substituted_.push_back(std::string(1, w.letter) + n);
      w.value = value;
      w.text = substituted_.back();
      w.digits = w.text.substr(1);
      w.substituted = true;
      w.computed.reset();
    }
    return std::nullopt;
  }

  /// First pass over the G words: what kind of block this is; false after "two motion words".
  bool classify(line_words& l) {
    bool g52 = false;
    const word* length_word = nullptr;  // G43, G43.4, G43.5 or G49
    for (const word& w : words_) {
      if (w.letter != 'G') continue;
      const int g = g_code(w.value);
      if (g == 280 || g == 300) l.homing = true;
      if (g == 435) l.g43_5 = true;
      if (g == 430 || g == 434 || g == 435) l.g43 = &w;
      if (g == 430 || g == 434 || g == 435 || g == 490) {  // modal group 08: one per block
        if (length_word && g_code(length_word->value) != g)
          return error(w.column, std::string(length_word->text) + " and " + std::string(w.text) +
                                     " in one block: two tool length codes of one modal group (08), which "
                                     "cannot both apply; write the one meant"),
                 false;
        length_word = &w;
      }
      if (g == 400 || g == 410 || g == 420) {  // the same word twice says it once
        const word* said = l.g41 ? l.g41 : l.g40;
        if (said && g_code(said->value) != g)
          return error(w.column, "two cutter radius compensation words in one block"), false;
        (g == 400 ? l.g40 : l.g41) = &w;
      }
      if (g == 50 || g == 51 || g == 80) l.uses_pq = true;
      if (g == 40) l.dwell = &w;
      if (g == 541 && !l.extended) l.extended = &w;  // its P may come first
      if (g == 520) g52 = true;
      if (g >= 0 && g <= 30 && g % 10 == 0) {
        if (l.motion) {
          error(w.column, "two motion words in one block");
          return false;
        }
        l.motion = &w;
      }
    }
    l.g52_reset = g52;  // G52 with all offsets zero resets the local frame: harmless
    if (g52)
      for (const word& w : words_)
        if (std::string_view("XYZABC").find(w.letter) != std::string_view::npos && w.value != 0) l.g52_reset = false;
    return true;
  }

  void interpret(block& b) {
    // A block that turns out to be passthrough must leave the reader's record as it was.
    const reader_state saved = state_;
    line_words l;
    if (!classify(l)) return;
    if (l.motion) {
      const int g = g_code(l.motion->value) / 10;
      b.motion = g == 0 ? motion_kind::rapid : g == 1 ? motion_kind::linear : g == 2 ? motion_kind::arc_cw : motion_kind::arc_ccw;
    }
    for (const word& w : words_) take(b, w, l);
    if (l.dwell && !l.suppress && !failed_) dwell(b, l);  // after an error in a word: that one only
    length_offset(b, l);
    radius_offset(b, l);
    if (l.extended && !b.state.work_offset && !l.suppress)
      error(l.extended->column, "G54.1 needs P n, the number of the extended work offset");
    if (b.motion) state_.motion = b.motion;
    inverse_time_feed(b, l);
    centre_or_vector(b, l);
    if (!l.suppress) absolute_positions(b, l);  // after the G43.5 vector: a block that moves
    if (!b.machine_coordinates)
      for (int i = 0; i < 6; ++i)
        if (const auto& p = axis_slot(b, i)) state_.last[i] = axis_position{*p, decimals_[i]};
    rates();
    if (state_.inch) inches_to_mm(b, !state_.inverse_time);
    state_.moved = state_.moved || b.moves();
    // The order the writer uses: G codes first, then the others (H, D, P, Q), each as written.
    std::stable_partition(b.kept_words.begin(), b.kept_words.end(),
                          [](const std::string& k) { return to_upper(k.front()) == 'G'; });
    if (!l.unknown || l.suppress) return;
    // Not understood: refused, moving or not (a word kin5 does not read may change the motion).
    error(l.unknown->column, "unknown word '" + std::string(l.unknown->text) + "'");
    state_ = saved;
  }

  /// F and S words the writer could not write back, refused at the word (`unwritable_rate`):
  /// `S.0101` needs a fourth decimal. An inch feed per minute is written with one more.
  void rates() {
    const int inch = state_.inch && !state_.inverse_time ? 1 : 0;
    for (const word& w : words_)
      if (w.letter == 'F' || (w.letter == 'S' && !Own::whole_address('S')))  // a whole S: refused in `take`
        if (auto why = unwritable_rate(w.value, detail::finest_rate_decimals + (w.letter == 'F' ? inch : 0),
                                       w.letter == 'F' ? "feed" : "spindle speed"))
          error(w.column, *why);
  }

  /// The meaning of one word.
  void take(block& b, const word& w, line_words& l) {
    const auto keep = [&] { b.kept_words.emplace_back(w.text); };
    const auto unknown = [&] {
      if (!l.unknown) l.unknown = &w;
    };
    if (Own::point_decides_unit(w.letter) && !l.dwell && !w.substituted && w.value != 0 &&
        w.digits.find('.') == std::string_view::npos)
      return error(w.column, std::string(w.text) + " without a decimal point: least input increments or whole units as "
                             "the control is set (on a control in decimal point input I, X10 is 0.010 mm); write " +
                             std::string(w.text) + ".");
    switch (w.letter) {
      case 'G': return g_word(b, w, l);
      case 'X': case 'Y': case 'Z': case 'A': case 'B': case 'C': return axis_word(b, w, l);
      case 'I': case 'J': case 'K': {
        const int axis = w.letter - 'I';
        if (l.ijk[axis]) return error(w.column, std::string("word '") + w.letter + "' appears twice");
        l.ijk[axis] = w.value;
        l.ijk_word[axis] = &w;
        return;
      }
      case 'R':
        if (l.radius) error(w.column, "word 'R' appears twice");
        l.radius = w.value;
        return;
      case 'F': b.feed = w.value; return;
      case 'S':
        if (Own::whole_address('S') && !lexing::is_whole(w.value))
          return error(w.column, "spindle speed " + std::string(w.text) +
                                     " is not a whole number: an ISO/Fanuc control reads S as whole revolutions "
                                     "per minute (S takes no decimal point)");
        b.spindle_rpm = w.value;
        return;
      case 'T': if (whole(w, "tool number")) b.tool = static_cast<long long>(w.value); return;
      case 'N': if (whole(w, "block number")) b.number = static_cast<long long>(w.value); return;
      case 'O':
        if (w.digits.empty() || w.digits.find_first_not_of("0123456789") != std::string_view::npos)
          error(w.column, "program number must be a whole number");
        else
          b.program_begin = std::string(w.digits);
        return;
      case 'M': return m_word(b, w, l);
      case 'H':
        if (l.h) return error(w.column, "word 'H' appears twice");
        l.h = &w;
        return;
      case 'D':
        if (l.d) return error(w.column, "word 'D' appears twice");
        l.d = &w;
        return;
      case 'P':
        if (l.extended && !b.state.work_offset) return extended_offset(b, w, l);
        if (l.dwell) return dwell_time(w, l);
        return l.uses_pq ? keep() : unknown();
      case 'Q': case 'L': return l.uses_pq ? keep() : unknown();
      default: return unknown();
    }
  }

  /// G54 … G59 select work offsets 1 … 6; G54.1 P n extended offset n (ISO/Fanuc).
  void select_offset(block& b, const word& w, work_offset selected, line_words& l) {
    if (l.offset || l.extended) return error(w.column, "two work offsets in one block");
    l.offset = &w;
    b.state.work_offset = selected;
  }

  /// The P of G54.1: 1 … 300, the most a Fanuc control has (the writers' range).
  void extended_offset(block& b, const word& w, line_words& l) {
    if (!lexing::is_whole(w.value) || w.value < 1 || w.value > 300)
      return error(w.column, "G54.1 P: the extended work offset's number must be a whole number from 1 to 300");
    b.state.work_offset = work_offset{work_offset_family::extended, static_cast<int>(w.value)};
    l.offset = &w;
  }

  bool whole(const word& w, const char* what) {
    if (lexing::is_whole(w.value)) return true;
    error(w.column, std::string(what) + " must be a whole number");
    return false;
  }

  /// G43 / G43.4 / G43.5 with H n: tool length compensation on with offset n (FANUC B-63942EN/02
  /// App. B; without H the offset of the last H, which before any H the program does not say);
  /// H anywhere else is refused: under G43 a lone H changes the offset. In a refused construct's
  /// block (G44, M98, a cycle) H is kept with it.
  void length_offset(block& b, line_words& l) {
    if (l.suppress) {
      if (l.h) b.kept_words.emplace_back(l.h->text);
      return;
    }
    if (l.h && !l.g43)
      return error(l.h->column, "word 'H' without G43, G43.4 or G43.5 (H is the length offset they apply; alone "
                                "it would change the offset in effect)");
    if (!l.g43) return;
    if (l.h && !whole(*l.h, "length offset number H")) return;
    if (l.h && l.h->value < 0) return error(l.h->column, "length offset number H must not be negative");
    if (l.h) state_.length_register = static_cast<long long>(l.h->value);
    if (!state_.length_register)
      return error(l.g43->column, std::string(l.g43->text) + " without H: the length offset in effect before the "
                                  "program is not known (G43 H n names it)");
    b.state.length_compensation = true;
    b.state.length_register = state_.length_register;
  }

  /// G41 / G42 with D n: cutter radius compensation left / right with offset n (FANUC
  /// B-63324EN/03 ch. 14; without D the offset of the last D, which before any D the program does
  /// not say), G40 off. Start-up and cancel are refused in a circular move (ch. 14: only in G0/G1),
  /// as is a D that would change the offset under compensation; a D with compensation off is kept
  /// (it names the offset of a later G41 without D). In a refused construct's block D is kept.
  void radius_offset(block& b, line_words& l) {
    if (l.suppress) {
      if (l.d) b.kept_words.emplace_back(l.d->text);
      return;
    }
    if (l.d && !whole(*l.d, "radius offset number D")) return;
    if (l.d && l.d->value < 1) return error(l.d->column, "radius offset number D must be 1 or more (D0 compensates no radius)");
    if (l.d && !l.g41 && state_.radius_on)
      return error(l.d->column, "word 'D' without G41 or G42 while cutter radius compensation is on (it would change "
                                "the offset in effect)");
    if (l.d) state_.radius_register = static_cast<long long>(l.d->value);
    if (l.d && !l.g41) b.kept_words.emplace_back(l.d->text);
    const word* sw = l.g41 ? l.g41 : l.g40;
    const auto kind = b.motion ? b.motion : state_.motion;
    const bool arc = kind && is_arc(*kind) && (b.motion || b.moves());
    if (!sw) {
      if (state_.startup_pending && arc)
        error(l.motion ? l.motion->column : 1, "a circular move starts cutter radius compensation up (G41/G42 before "
                                               "it): start-up is allowed only in G0/G1");
      if (b.moves()) state_.startup_pending = false;
      return;
    }
    if (arc && (l.g41 || state_.radius_on))  // G40 with compensation off cancels nothing
      return error(sw->column, std::string(sw->text) + ": cutter radius compensation " +
                                   (l.g41 ? "start-up" : "cancel") + " in a circular move (allowed only in G0/G1)");
    if (l.g41 && !l.d && b.state.radius_register) state_.radius_register = b.state.radius_register;  // `Own`'s
    if (l.g41 && !state_.radius_register && !failed_)
      return error(sw->column, std::string(sw->text) + " without D: the radius offset in effect before the program "
                                                       "is not known (G41 D n names it)");
    if (failed_) return;
    const bool left = l.g41 && g_code(l.g41->value) == 410;
    b.state.radius_compensation = !l.g41 ? cutter_side::off : left ? cutter_side::left : cutter_side::right;
    if (l.g41) b.state.radius_register = state_.radius_register;
    state_.radius_on = l.g41 != nullptr;
    state_.startup_pending = l.g41 && !b.moves();
  }

  void m_word(block& b, const word& w, line_words& l) {
    if (!lexing::is_whole(w.value) || w.value > 99999) {
      if (!l.unknown) l.unknown = &w;
      return;
    }
    const int m = static_cast<int>(w.value);
    if (m == 98 || m == 97 || m == 198) {
      error(w.column, "M" + std::to_string(m) + ": a subprogram call is not supported (the motion it makes would be lost)");
      l.suppress = true;  // its P, L, H words are the call's
    } else if (m == 99) {
      error(w.column, "M99: a subprogram return or loop is not supported (the path would depend on it)");
      l.suppress = true;
    } else if (m == 30 || m == 2) b.program_end = "M" + std::to_string(m);
    else read_machine_function(b, m);
  }

  void axis_word(block& b, const word& w, line_words& l) {
    std::optional<double>* slot = w.letter == 'X' ? &b.axes.x_mm : w.letter == 'Y' ? &b.axes.y_mm
                                : w.letter == 'Z' ? &b.axes.z_mm : w.letter == 'A' ? &b.axes.a_deg
                                : w.letter == 'B' ? &b.axes.b_deg : &b.axes.c_deg;
    if (*slot) return error(w.column, std::string("word '") + w.letter + "' appears twice");
    if (l.dwell && w.letter != 'X') return error(w.column, std::string("word '") + w.letter + "' in a dwell block (G4)");
    if (l.dwell) return dwell_time(w, l);  // G4 X1.5: 1.5 s, not a position
    if (l.g52_reset) b.kept_words.emplace_back(w.text);
    else *slot = w.value;
  }

  void g_word(block& b, const word& w, line_words& l) {
    const int g = g_code(w.value);
    const auto keep = [&] { b.kept_words.emplace_back(w.text); };
    if ((g >= 0 && g <= 30 && g % 10 == 0) || g == 40) return;  // motion, dwell: done in `classify`
    if (g == 170 || g == 180 || g == 190) {
      state_.plane = g == 170 ? arc_plane::xy : g == 180 ? arc_plane::zx : arc_plane::yz;
      b.state.working_plane = state_.plane;
    } else if (g == 900 || g == 910) {
      if (l.distance && g_code(l.distance->value) != g)
        return error(w.column, std::string(l.distance->text) + " and " + std::string(w.text) +
                                   " in one block: two distance modes (modal group 03); write the one meant");
      l.distance = &w;
      if (g == 910 && !state_.incremental) state_.incremental_line = line_;
      state_.incremental = g == 910;
    } else if (g == 400 || g == 410 || g == 420) {
      return;  // cutter radius compensation, with its D: `radius_offset`
    } else if (g >= 540 && g <= 590 && g % 10 == 0) {
      select_offset(b, w, {work_offset_family::g54, g / 10 - 53}, l);
    } else if (g == 541) {
      if (l.extended != &w) return error(w.column, "two work offsets in one block");
    } else if (kept_g(g) || (g == 520 && l.g52_reset)) {
      keep();
    } else if (g == 930 || g == 940) {
      state_.inverse_time = g == 930;
      b.feed_mode = g == 930 ? feed_unit::inverse_time : feed_unit::per_minute;
    } else if (g == 430) {
      // G43 replaces G43.4 / G43.5 in modal group 08: tracking ends, the length stays (its H:
      // `length_offset`).
      if (state_.tcp) b.tcp = false;
      state_.tcp = state_.vector_tcp = false;
    } else if (g == 434 || g == 435 || g == 490) {
      b.tcp = g != 490;
      state_.tcp = g != 490;
      state_.vector_tcp = g == 435;
      if (g == 490) b.state.length_compensation = false;
    } else if (g == 530 || g == 280 || g == 300) {
      b.machine_coordinates = true;
      // The word is the field: the writer spells it back (G53, G28, G30), so it is not kept.
      if (g != 530)
        b.machine_reference = g == 280 ? (Own::stored_homes ? machine_position::stored_position : machine_position::reference_point)
                                       : (Own::stored_homes ? machine_position::second_stored_position
                                                            : machine_position::second_reference);
    } else {
      refused_g(b, w, g, l);
    }
  }

  /// G20, G95, cycles and frames are refused (G21 is read); other G codes are not understood.
  void refused_g(block& b, const word& w, int g, line_words& l) {
    if (g == 200 || g == 210) {
      if (state_.moved && state_.inch != (g == 200))
        return error(w.column, "G" + std::to_string(g / 10) + " after motion: a unit change inside a program is not supported");
      b.metric = g == 210;
      state_.inch = g == 200;
    } else if (g == 950) {
      error(w.column, "feed per revolution (G95) is not supported");
    } else if (g == 730 || g == 740 || g == 760 || (g >= 810 && g <= 890 && g % 10 == 0)) {
      error(w.column, "canned cycle G" + std::to_string(g / 10) + " is not supported");
      l.suppress = true;  // its R, P, Q words are the cycle's: no further diagnostics
    } else if (g == 680 || g == 682 || g == 683 || g == 684 || g == 510 || g == 511 || g == 520) {
      const std::string name = "G" + std::to_string(g / 10) + (g % 10 ? "." + std::to_string(g % 10) : "");
      error(w.column, name + " changes the working frame; kin5 does not model frame changes");
      l.suppress = true;  // its I J K R P words are the frame's
    } else if (const std::string why = refusal_of_g(g); !why.empty()) {
      error(w.column, "G" + std::to_string(g / 10) + (g % 10 ? "." + std::to_string(g % 10) : "") + why);
      l.suppress = true;  // its D, P, L, R words are the construct's
    } else if (!l.unknown) {
      l.unknown = &w;
    }
  }

  /// Why G code `g` (times ten) is refused, after its name; empty for a code not understood.
  static std::string refusal_of_g(int g) {
    if (g == 440) return ": negative tool length compensation is not supported (no other dialect subtracts the length)";
    if (g == 100) return ": setting offsets from the program is not supported (later moves would use other offsets)";
    if (g == 650 || g == 660 || g == 661) return ": a macro call is not supported (the motion it makes would be lost)";
    if (g == 920 || g == 921) return ": a coordinate system shift is not supported (the points that follow are in another frame)";
    return "";
  }

  /// The X or P of a G4 block (one of them, once).
  void dwell_time(const word& w, line_words& l) {
    if (l.dwell_time) return error(w.column, std::string("word '") + w.letter + "' after '" + l.dwell_time->letter +
                                                 "' in a dwell block (G4 takes X or P, once)");
    l.dwell_time = &w;
  }

  /// A dwell (F4: SINUMERIK ISO Milling 04/2007 §3.3.1, the Fanuc G04): `G4 X2.` seconds, with a
  /// decimal point (without one X counts least input increments or seconds as a parameter of the
  /// control says: refused unless 0), or `G4 P2000`, whole milliseconds; in a block of its own
  /// ("the block used to specify dwell must not include commands other than G04").
  void dwell(block& b, const line_words& l) {
    const word* t = l.dwell_time;
    if (!t) return error(l.dwell->column, "G4 needs X (seconds, with a decimal point) or P (milliseconds)");
    const std::string written(t->text);
    if (t->value < 0) return error(t->column, "G4 " + written + ": a dwell time cannot be negative");
    if (t->letter == 'P' && !lexing::is_whole(t->value))
      return error(t->column, "G4 " + written + ": P is whole milliseconds (it takes no decimal point)");
    if (t->letter == 'X' && t->value != 0 && t->digits.find('.') == std::string_view::npos)
      return error(t->column, "G4 " + written + ": without a decimal point X is seconds or least input increments "
                                                "as the control is set (write X with a point, or P in milliseconds)");
    const double s = t->letter == 'X' ? t->value : t->value / 1000.0;
    if (const std::string why = dwell_refusal(detail::dwell_steps, s); !why.empty())
      return error(t->column, "G4 " + written + ": " + why);
    b.state.dwell_s = s;
    if (!b.only_dwell())
      error(l.dwell->column, "G4: a dwell takes a block of its own (N, X or P, and a comment)");
  }

  /// In inverse time (G93) F is not modal: every G1, G2, G3 block gives its own, the block's time
  /// (Mitsubishi M700V §7.5, precaution 2: program error P62 without it; LinuxCNC User Manual,
  /// G93: "an F word must appear on every line which has a G1, G2, or G3 motion"). A feed move
  /// without one is refused at the block. Homing and machine-coordinate blocks are not judged.
  void inverse_time_feed(const block& b, const line_words& l) {
    if (!state_.inverse_time || b.feed || !b.moves() || b.machine_coordinates || l.homing || l.suppress) return;
    if (!state_.motion || *state_.motion == motion_kind::rapid) return;
    error(b.where.column, "feed move in inverse time (G93) without its own F: in G93 each G1, G2 and G3 block gives "
                          "its time as F (write F in this block)");
  }

  /// The block's axis word for axis `i` (X Y Z A B C).
  static std::optional<double>& axis_slot(block& b, int i) {
    std::optional<double>* slots[6] = {&b.axes.x_mm, &b.axes.y_mm, &b.axes.z_mm,
                                       &b.axes.a_deg, &b.axes.b_deg, &b.axes.c_deg};
    return *slots[i];
  }

  /// G90 / G91 (Fanuc 30i/31i/32i-B Operator's Manual, "Absolute and incremental programming";
  /// LinuxCNC G-code reference, G90, G91): under G91 an axis word is a distance from the last
  /// programmed position of its axis, linear and rotary alike. The block gets the position the
  /// control reaches, so the model holds absolute positions and a writer writes them: an
  /// incremental word whose base is not known — no absolute position of its axis yet, or a
  /// machine-coordinate or home move since (G53, G28, G30: the workpiece position they leave is
  /// the machine's) — is refused at the word. Machine-coordinate and home blocks keep their
  /// words as written (G28's intermediate point is incremental under G91) and the distance mode
  /// the control reads them in: `state.distance` says G91 there, and G90 on the next block that
  /// moves; elsewhere it says what a block without motion writes (G90, G91) or G90 where needed.
  /// A distance of 0 from an unknown position (`G91 G0 B0.` after `G28 B0.`) moves nothing: the
  /// word is left out, and the position stays unknown. A rotary axis sent to its reference point
  /// (G28; not LinuxCNC's, whose G28 goes to stored positions) is at the source machine's
  /// reference angle when the reading knows it (`read_limits::rotary_home_deg`, the machine
  /// file's `home_deg`): a rotary axis' commanded angle is its machine position, so the next
  /// incremental word counts from there.
  void absolute_positions(block& b, const line_words& l) {
    const auto said = state_.incremental ? distance_mode::incremental : distance_mode::absolute;
    if (b.machine_coordinates) {
      if (l.distance || state_.written_incremental != state_.incremental) b.state.distance = said;
      state_.written_incremental = state_.incremental;
      bool any = false;
      for (int i = 0; i < 6; ++i)
        if (axis_slot(b, i)) any = true;
      const bool reference = b.machine_reference == machine_position::reference_point;
      for (int i = 0; i < 6; ++i) {  // G28 / G30 without axis words send every axis home
        if (!axis_slot(b, i) && !(l.homing && !any)) continue;
        state_.last[i].reset(), state_.lost_line[i] = line_, state_.lost_at_reference[i] = reference;
        if (i < 3 || !reference) continue;
        if (const auto home = current_read_limits().rotary_home_deg[static_cast<std::size_t>(i - 3)])
          state_.last[i] = axis_position{*home, shortest_decimals(*home)}, state_.lost_line[i] = 0;
      }
      return;
    }
    static constexpr char letters[] = "XYZABC";
    for (int i = 0; i < 6; ++i) {
      const word* w = nullptr;
      for (const word& x : words_)
        if (x.letter == letters[i]) w = &x;
      decimals_[i] = w ? decimals_written(w->digits) : 0;
    }
    if (state_.incremental) {
      for (int i = 0; i < 6; ++i) {
        auto& p = axis_slot(b, i);
        if (!p) continue;
        if (state_.last[i]) {
          const axis_position to = reached(*state_.last[i], *p, decimals_[i]);
          p = to.value, decimals_[i] = to.decimals;
          continue;
        }
        if (*p == 0) {  // no distance: the axis stays wherever it is, which a block without the word says
          p.reset();
          continue;
        }
        const word* w = nullptr;
        for (const word& x : words_)
          if (x.letter == letters[i]) w = &x;
        const std::string since = state_.lost_line[i] ? "since the machine-coordinate or home move of line " +
                                                            std::to_string(state_.lost_line[i])
                                                      : "since the start of the program";
        const std::string home = i >= 3 && state_.lost_line[i] && state_.lost_at_reference[i]
                                     ? std::string(", or give home_deg in ") + letters[i] +
                                           "'s [[rotary]] table of the source machine file, the angle G28 leaves it at "
                                           "(--from-file; docs/machine-files.md)"
                                     : "";
        error(w ? w->column : b.where.column,
              "incremental " + std::string(1, letters[i]) + " (G91 of line " + std::to_string(state_.incremental_line) +
                  ") from a position the program does not say: no absolute " + letters[i] + " " + since +
                  ", so the move would start from wherever the machine stands; program an absolute " + letters[i] +
                  " (G90) before it" + home);
      }
    }
    if (b.moves() || (b.motion && is_arc(*b.motion))) {
      if (l.distance || state_.written_incremental) b.state.distance = distance_mode::absolute;
      state_.written_incremental = false;
    } else if (l.distance) {
      b.state.distance = said;
      state_.written_incremental = state_.incremental;
    }
  }

  /// I J K and R: arc data, or the G43.5 tool-axis vector.
  void centre_or_vector(block& b, line_words& l) {
    const bool arc_motion = !b.machine_coordinates &&
                            (state_.motion == motion_kind::arc_cw || state_.motion == motion_kind::arc_ccw);
    const bool arc = !l.g43_5 && arc_motion;
    if (l.suppress) return;
    if (arc_motion && l.g43_5 && b.moves() && !l.radius) {  // I J K are G43.5's: no centre
      error(b.where.column, "arc needs I, J, K or R (in a G43.5 block I, J, K are the tool axis)");
    } else if (l.any_ijk() && !arc && !(state_.vector_tcp || l.g43_5)) {
      const word* w = l.first_ijk();
      error(w->column, std::string("word '") + w->letter + "' needs G2, G3 or G43.5");
    } else if (l.any_ijk() && !arc) {
      if (!l.ijk[0] || !l.ijk[1] || !l.ijk[2]) error(l.first_ijk()->column, "tool-axis vector needs I, J and K");
      else if (!is_direction(*l.ijk[0], *l.ijk[1], *l.ijk[2]))
        error(l.first_ijk()->column, "tool-axis vector shorter than 0.001 is not a direction");
      else b.axes.tool_axis = vec3{*l.ijk[0], *l.ijk[1], *l.ijk[2]};
    } else if (arc && (l.any_ijk() || l.radius || b.moves())) {
      b.arc = arc_data(b, l);
    } else if (l.radius && !l.unknown) {
      for (const word& w : words_)
        if (w.letter == 'R') {
          l.unknown = &w;
          break;
        }
    }
  }

  /// The arc of an arc block: its radius, or its centre from the last point and I J K.
  arc_words arc_data(const block& b, const line_words& l) {
    arc_words a;
    const arc_plane plane = state_.plane;
    a.plane = plane;
    const int first = plane == arc_plane::xy ? 0 : plane == arc_plane::zx ? 2 : 1;
    const int second = plane == arc_plane::xy ? 1 : plane == arc_plane::zx ? 0 : 2;
    const int normal = 3 - first - second;
    const auto& last = state_.last;
    if (l.radius && l.any_ijk()) {
      error(l.first_ijk()->column, "arc has both I J K and R");
    } else if (l.radius) {
      a.radius_mm = l.radius;
    } else if (!l.any_ijk()) {
      error(b.where.column, "arc needs I, J, K or R");
    } else if (l.ijk[normal]) {
      error(l.ijk_word[normal]->column, std::string("word '") + l.ijk_word[normal]->letter + "' is not in the arc plane");
    } else if (!last[0] || !last[1] || !last[2]) {
      const word* w = l.ijk_word[first] ? l.ijk_word[first] : l.ijk_word[second];
      error(w->column, "arc centre needs a known start point");
    } else {
      double c[3] = {last[0]->value, last[1]->value, last[2]->value};
      if (l.ijk[first]) c[first] += *l.ijk[first];
      if (l.ijk[second]) c[second] += *l.ijk[second];
      a.centre_mm = vec3{c[0], c[1], c[2]};
    }
    return a;
  }
};

/// The ISO reader.
using reader = basic_reader<>;

}  // namespace kin5::program::iso::detail

namespace kin5::program::iso {

/// Reads ISO / Fanuc G code block by block: `on_block` receives each block in file order as soon
/// as it is read; errors and warnings go to `diagnostics` (its `parsed` is not touched).
inline void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                        const block_sink& on_block) {
  read_transmitted(text, file_name, diagnostics, on_block, [&](std::string_view body, const block_sink& sink) {
    detail::reader(file_name, diagnostics, sink).run(body);
  });
}

}  // namespace kin5::program::iso
