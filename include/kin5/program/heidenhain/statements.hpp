/// @file program/heidenhain/statements.hpp
/// What each line of a Heidenhain conversational program is to the interpreter
/// (../interp/statement.hpp), for the executor (../interp/executor.hpp) that runs the reader:
/// | line | statement |
/// |---|---|
/// | `LBL 1`, `LBL "NAME"` | a label, `LBL 1` / `LBL "NAME"` |
/// | `LBL 0` | the end of a subprogram: returns from the innermost call; reached without one, it does nothing |
/// | `CALL LBL 1` | a call of the subprogram at `LBL 1`, up to its `LBL 0`; no frame of its own (QL are the program's) |
/// | `CALL LBL 1 REP 2` | a section repeat: back to `LBL 1` and on to this line, 2 times more |
/// | `FN 9: IF +Q1 EQU +Q2 GOTO LBL 1` | a jump when Q1 = Q2 (`FN 10` NE, `FN 11` GT, `FN 12` LT) |
/// | `FN 0`–`FN 8`, `FN 13`, `Q1 = …`, `QL1 = …`, `QR1 = …` | an assignment, then the line for the reader |
/// | `CALL PGM SUB`, `CALL PGM SUB.H`, `CALL PGM ..\DIR\SUB.H` | a call of the program in another file, run to its `END PGM`; its own QL (`program_file_names`) |
/// | `END PGM` in a called program's file | ordinary, ending the call: the caller goes on |
/// | a line after one ending in `~` | nothing (the reader joins it to the block it continues) |
/// | any other line | an ordinary line for the reader |
/// A label number or name from a parameter (`CALL LBL Q5`, `LBL QS1`) is refused: the label the
/// program goes to would depend on the run; so is a program called by a string parameter
/// (`CALL PGM QS1`), a call of an ISO program (`.I`), and any word after the called file (`REP`:
/// a program call runs once).
///
/// For an ordinary line `statement_of` looks at the first byte after the block number only
/// (and at the end of the line before, for a continuation); it is called for every line run.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../expression_parser.hpp"
#include "../interp/statement.hpp"
#include "../lexing.hpp"
#include "../text.hpp"
#include "expression.hpp"

namespace kin5::program::heidenhain {

/// The file names a `CALL PGM` of `written` may mean, for the opener of called files
/// (../called_files.hpp): the path with `/` between its parts, relative to the calling
/// program's directory, `.h` added when the name has no type (the TNC's default). A path from
/// a drive or the root (`TNC:\PARTS\SUB.H`, `\SUB.H`) names the control's own directories,
/// which a PC does not have: only its file name is tried.
inline std::vector<std::string> program_file_names(std::string_view written) {
  std::string path(written);
  for (char& c : path)
    if (c == '\\') c = '/';
  const std::size_t colon = path.find(':');
  const bool absolute = colon != std::string::npos || (!path.empty() && path[0] == '/');
  if (colon != std::string::npos) path.erase(0, colon + 1);
  const std::size_t slash = path.rfind('/');
  std::string file = slash == std::string::npos ? path : path.substr(slash + 1);
  if (file.find('.') == std::string::npos) path += ".h", file += ".h";
  return {absolute ? file : path};
}

/// The statements of one program's lines (see the file comment). `lines` are the program's
/// lines as the executor numbers them (line n is `lines[n - 1]`).
class statements {
 public:
  explicit statements(const std::vector<text_line>& lines) : lines_(&lines) {}

  /// The statements of a program another one calls (`CALL PGM`), whose text is `text`: its own
  /// lines, and its `END PGM` ends the call.
  statements for_text(std::string_view text) const {
    auto lines = std::make_shared<const std::vector<text_line>>(split_lines(text));
    statements called(*lines);
    called.owned_ = std::move(lines);
    called.called_ = true;
    return called;
  }

  /// After the program's end has been read (M2, M30, END PGM): the next line the executor asks
  /// for ends the run.
  void end_program() { ended_ = true; }
  void resume() { ended_ = false; }

  interp::statement statement_of(const text_line& l) {
    interp::statement s;
    if (ended_) {
      s.ends_program = true;
      return s;
    }
    if (continues_block(l.number)) {
      s.kind = interp::statement_kind::label;  // joined to the block before it: nothing of its own
      return s;
    }
    const std::string_view t = l.text;
    std::size_t k = lexing::skip_blanks(t, 0);
    while (k < t.size() && is_digit(t[k])) ++k;
    k = lexing::skip_blanks(t, k);
    if (k >= t.size()) return s;
    switch (to_upper(t[k])) {
      case 'L':
        if (keyword_at(t, k, "LBL")) label(t, k, l.number, s);
        break;
      case 'C':
        if (keyword_at(t, k, "CALL") && keyword_at(t, lexing::skip_blanks(t, k + 4), "LBL")) call(t, k, l.number, s);
        else if (keyword_at(t, k, "CALL") && keyword_at(t, lexing::skip_blanks(t, k + 4), "PGM"))
          program_call(t, lexing::skip_blanks(t, k + 4) + 3, l.number, s);
        break;
      case 'E':
        if (called_ && keyword_at(t, k, "END") && keyword_at(t, lexing::skip_blanks(t, k + 3), "PGM")) s.ends_program = true;
        break;
      case 'F':
        if (keyword_at(t, k, "FN")) function(t, k, l.number, s);
        break;
      case 'Q':
        if (k + 1 < t.size() && (is_digit(t[k + 1]) || ((to_upper(t[k + 1]) == 'L' || to_upper(t[k + 1]) == 'R') &&
                                                        k + 2 < t.size() && is_digit(t[k + 2]))))
          assign(t, k, l.number, s);
        break;
      default: break;
    }
    return s;
  }

 private:
  const std::vector<text_line>* lines_;
  std::shared_ptr<const std::vector<text_line>> owned_{};  // a called program's lines (for_text)
  bool called_ = false;  // the text of a program a CALL PGM runs
  bool ended_ = false;

  /// Whether line `number` continues the block of the line before it (that line ends in `~`).
  bool continues_block(std::size_t number) const {
    if (number < 2 || number - 2 >= lines_->size()) return false;
    const std::string_view p = (*lines_)[number - 2].text;
    std::size_t e = p.size();
    while (e > 0 && is_space(p[e - 1])) --e;
    return e > 0 && p[e - 1] == '~';
  }

  /// Whether the upper-case `word` stands at `k` and does not run on into a letter.
  static bool keyword_at(std::string_view t, std::size_t k, std::string_view word) {
    return starts_with_keyword(t.substr(std::min(k, t.size())), word) &&
           (k + word.size() >= t.size() || !is_letter(t[k + word.size()]));
  }

  static void refuse(interp::statement& s, std::size_t line, std::size_t at, std::size_t length, std::string message) {
    s.error = interp::expression_error{{line, at + 1, length == 0 ? 1 : length}, std::move(message)};
  }

  /// The label at `k` (`1`, `"NAME"`) as its key (`LBL 1`, `LBL "NAME"`), and where it ends;
  /// empty, refused in `s`, when there is none.
  static std::optional<std::pair<std::string, std::size_t>> label_name(std::string_view t, std::size_t k, std::size_t line,
                                                                       std::string_view what, interp::statement& s) {
    k = lexing::skip_blanks(t, k);
    if (k < t.size() && t[k] == '"') {
      const std::size_t close = t.find('"', k + 1);
      if (close == std::string_view::npos || close == k + 1) {
        refuse(s, line, k, 1, std::string(what) + ": a label name needs its closing '\"' (LBL \"NAME\")");
        return std::nullopt;
      }
      return std::pair{"LBL " + std::string(t.substr(k, close + 1 - k)), close + 1};
    }
    std::size_t e = k;
    while (e < t.size() && is_digit(t[e])) ++e;
    if (e == k || e - k > 9 || (e < t.size() && !is_space(t[e]) && t[e] != ';')) {
      std::size_t end = k;
      while (end < t.size() && !is_space(t[end]) && t[end] != ';') ++end;
      if (k < t.size() && to_upper(t[k]) == 'Q')
        refuse(s, line, k, end - k, std::string(what) + " " + std::string(t.substr(k, end - k)) +
                                        ": a label from a parameter is not supported (where the program goes would depend "
                                        "on the run); write the label's number or name");
      else
        refuse(s, line, k, end - k, std::string(what) + ": expected a label number or a name in quotes (LBL 1, LBL \"NAME\")");
      return std::nullopt;
    }
    return std::pair{"LBL " + std::to_string(std::stol(std::string(t.substr(k, e - k)))), e};
  }

  /// Whether only blanks and a `;` comment follow `k`; else refused in `s` at the first byte.
  static bool nothing_after(std::string_view t, std::size_t k, std::size_t line, std::string_view what, interp::statement& s) {
    k = lexing::skip_blanks(t, k);
    if (k >= t.size() || t[k] == ';') return true;
    refuse(s, line, k, 1, "unexpected '" + std::string(t.substr(k, 1)) + "' after " + std::string(what));
    return false;
  }

  /// `LBL n`, `LBL "NAME"`, `LBL 0`.
  static void label(std::string_view t, std::size_t k, std::size_t line, interp::statement& s) {
    const auto name = label_name(t, k + 3, line, "LBL", s);
    if (!name || !nothing_after(t, name->second, line, name->first, s)) return;
    if (name->first == "LBL 0") {
      s.kind = interp::statement_kind::return_from_call;
      s.only_in_call = true;  // reached in the program's flow (a subprogram not called), it does nothing
      return;
    }
    s.kind = interp::statement_kind::label;
    s.label = name->first;
  }

  /// `CALL LBL n`, `CALL LBL n REP m`, `CALL LBL "NAME" …`.
  static void call(std::string_view t, std::size_t k, std::size_t line, interp::statement& s) {
    const std::size_t lbl = lexing::skip_blanks(t, k + 4);
    const auto name = label_name(t, lbl + 3, line, "CALL LBL", s);
    if (!name) return;
    if (name->first == "LBL 0") return refuse(s, line, lbl, 3, "CALL LBL 0: LBL 0 ends a subprogram; it cannot be called");
    s.kind = interp::statement_kind::call;
    s.target = name->first;
    s.call_frame = false;  // QL parameters are local to the program, not to a subprogram
    std::size_t p = lexing::skip_blanks(t, name->second);
    if (keyword_at(t, p, "REP") || (starts_with_keyword(t.substr(p), "REP") && p + 3 < t.size() && is_digit(t[p + 3]))) {
      const std::size_t v = lexing::skip_blanks(t, p + 3);
      std::size_t e = v;
      while (e < t.size() && is_digit(t[e])) ++e;
      if (e == v || e - v > 5 || (e < t.size() && !is_space(t[e]) && t[e] != ';'))
        return refuse(s, line, p, e > p ? e - p : 3, "CALL LBL … REP: expected the number of repeats, 1 to 65534 (REP 2)");
      const long n = std::stol(std::string(t.substr(v, e - v)));
      if (n < 1 || n > 65534) return refuse(s, line, v, e - v, "CALL LBL … REP " + std::to_string(n) + ": repeats are 1 to 65534");
      interp::expression count;
      count.root = count.number(static_cast<double>(n), {line, v + 1, e - v});
      s.count = std::move(count);
      s.ends = interp::call_end::calling_line;  // runs from the label to this line again, n times more
      p = e;
    }
    nothing_after(t, p, line, "CALL " + name->first, s);
  }

  /// `CALL PGM file` (the file from `k`, after `PGM`): a call of another file, as written or in
  /// quotes; a string parameter, an ISO program and words after the file are refused.
  static void program_call(std::string_view t, std::size_t k, std::size_t line, interp::statement& s) {
    std::size_t f = lexing::skip_blanks(t, k);
    std::size_t e = f;
    std::string name;
    if (f < t.size() && t[f] == '"') {
      e = t.find('"', f + 1);
      if (e == std::string_view::npos || e == f + 1)
        return refuse(s, line, f, 1, "CALL PGM: a file name in quotes needs its closing '\"'");
      name = std::string(t.substr(f + 1, e - f - 1));
      ++e;
    } else {
      while (e < t.size() && !is_space(t[e]) && t[e] != ';') ++e;
      name = std::string(t.substr(f, e - f));
    }
    if (name.empty()) return refuse(s, line, f, 1, "CALL PGM needs the file of the program to call (CALL PGM SUB.H)");
    const std::string upper = lexing::upper(name);
    if (upper.size() > 2 && upper[0] == 'Q' && upper[1] == 'S' && is_digit(upper[2]))
      return refuse(s, line, f, e - f, "CALL PGM " + name + ": a program named by a string parameter is not supported "
                                        "(the file would depend on the run); write the file's name");
    if (upper.size() > 2 && upper.ends_with(".I"))
      return refuse(s, line, f, e - f, "CALL PGM " + name + ": a call of an ISO program (.I) is not supported (kin5 "
                                        "reads a Heidenhain program's called files as Heidenhain)");
    const std::size_t after = lexing::skip_blanks(t, e);
    if (after < t.size() && t[after] != ';') {
      std::size_t end = after;
      while (end < t.size() && !is_space(t[end]) && t[end] != ';') ++end;
      return refuse(s, line, after, end - after, "CALL PGM " + name + ": '" + std::string(t.substr(after, end - after)) +
                                                     "' after the file is not supported (a program call runs its "
                                                     "program once, with no words after the file)");
    }
    s.kind = interp::statement_kind::call;
    s.target = "PGM " + name;
    s.files = program_file_names(name);
    s.call_frame = true;  // QL parameters are each program's own; Q and QR are shared
  }

  /// `FN k: …`: FN 9 to 12 are jumps, FN 0 to 8 and 13 assignments; any other is the reader's.
  static void function(std::string_view t, std::size_t k, std::size_t line, interp::statement& s) {
    std::size_t d = lexing::skip_blanks(t, k + 2);
    int fn = 0;
    const std::size_t first = d;
    while (d < t.size() && is_digit(t[d]) && d - first < 3) fn = fn * 10 + (t[d++] - '0');
    if (d == first) return;
    if (fn >= 9 && fn <= 12) return jump(t, k, fn, lexing::skip_blanks(t, d), line, s);
    if (fn <= 8 || fn == 13) assign(t, k, line, s);
  }

  /// `FN 9: IF a EQU b GOTO LBL n` (10: NE, 11: GT, 12: LT).
  static void jump(std::string_view t, std::size_t k, int fn, std::size_t colon, std::size_t line, interp::statement& s) {
    std::size_t end = t.find(';', k);
    if (end == std::string_view::npos) end = t.size();
    const std::string_view text = t.substr(k, end - k);
    expression_parser p(spelling, text, line, k + 1);
    const std::string head = "FN " + std::to_string(fn);
    static constexpr std::string_view compare[] = {"EQU", "NE", "GT", "LT"};
    static constexpr interp::binary_op op[] = {interp::binary_op::equal, interp::binary_op::not_equal,
                                               interp::binary_op::greater, interp::binary_op::less};
    const std::string_view word = compare[fn - 9];
    p.seek(colon - k);
    if (!p.take(':')) p.fail(colon - k, colon - k + 1, "expected ':' after " + head);
    if (!p.failed() && !p.take_word("IF")) p.fail(p.position(), p.position() + 1, "expected IF after " + head + ":");
    const interp::node_id a = p.failed() ? interp::no_node : p.operand();
    const std::size_t at = p.position();
    if (!p.failed() && !p.take_word(word))
      p.fail(at, at + 1, "expected " + std::string(word) + " in " + head + " (FN 9 EQU, FN 10 NE, FN 11 GT, FN 12 LT)");
    const interp::node_id b = p.failed() ? interp::no_node : p.operand();
    std::size_t go = p.failed() ? 0 : p.position();
    if (!p.failed() && !(p.take_word("GOTO") && p.take_word("LBL")))
      p.fail(go, go + 1, "expected GOTO LBL and a label after the condition of " + head);
    if (p.failed()) {
      s.error = p.error();
      return;
    }
    const auto name = label_name(t, k + p.position(), line, head + " … GOTO LBL", s);
    if (!name || !nothing_after(t, name->second, line, "GOTO " + name->first, s)) return;
    interp::expression condition = std::move(p.tree());
    condition.root = condition.binary(op[fn - 9], a, b, p.span_of(at, at + word.size()));
    s.kind = interp::statement_kind::jump;
    s.target = name->first;
    s.condition = std::move(condition);
  }

  /// `FN 0: Q1 = …` … `FN 13`, `Q1 = …`, `QL1 = …`, `QR1 = …`: an assignment before the line is read.
  static void assign(std::string_view t, std::size_t k, std::size_t line, interp::statement& s) {
    q_assignment a = read_assignment(t.substr(k), line, k + 1);
    if (!a.value.ok()) {
      s.error = a.value.error;
      return;
    }
    const std::size_t q = t.find_first_of("Qq", k);  // the parameter assigned: `FN` has no Q
    const std::size_t length = a.target.shown().size();
    interp::expression target;
    target.root = target.numbered_parameter(
        a.target.prefix, target.number(static_cast<double>(a.target.number), {line, q + 1, length}), {line, q + 1, length});
    s.assignments.push_back({std::move(target), std::move(a.value.tree)});
  }
};

}  // namespace kin5::program::heidenhain
