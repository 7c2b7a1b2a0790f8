// The executor (program/interp/executor.hpp) on a small statement language of this test's own,
// so that control flow is tested apart from any dialect's spelling:
//   P text        ordinary line (recorded)          E            ordinary, ends the program
//   L name        label                             A #n = expr  assignment, then an ordinary line
//   AI #n = expr IF cond   the assignment and its line only when cond holds (FANUC IF … THEN)
//   J name [expr] jump (when expr holds)            JF / JB      forward / backward only
//   C name [n]    call, n passes, until R           S name n     section repeat (to this line)
//   R             return                            SUB name / ENDSUB name   subprogram (keyed)
//   RC            return; nothing without a call
//   I expr / EI expr / EL / EN          IF, ELSEIF, ELSE, ENDIF (nested by depth)
//   W expr / EW   while loop   D / U expr   do … until   RP n / ER   counted   B / K   break / continue
//   F #n a b / EF counting loop (#n from a to b)      JC name      jump, on when the label is missing
//   SE a b n      section repeat from label a to label b, n passes      L name block   two labels
//   PL name       ordinary line that defines a label
//   CF name [n]   call, n passes, of label name or else of the file "name.toy" or "name"
// Expressions are LinuxCNC's spelling; parameters LinuxCNC's rules.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <string_view>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/interp/executor.hpp>
#include <kin5/program/linuxcnc/expression.hpp>
#include <kin5/program/linuxcnc/parameter_rules.hpp>

namespace {

namespace ip = kin5::program::interp;
using kin5::program::text_line;

struct toy_syntax {
  std::size_t statements_read = 0;

  static ip::expression expr(std::string_view text, const text_line& l, std::size_t column) {
    auto p = kin5::program::parse_expression(kin5::program::linuxcnc::spelling, text, l.number, column);
    return std::move(p.tree);
  }

  ip::statement statement_of(const text_line& l) {
    ++statements_read;
    ip::statement s;
    const std::string_view t = l.text;
    const std::size_t sp = t.find(' ');
    const std::string_view op = t.substr(0, sp);
    const std::string_view rest = sp == std::string_view::npos ? std::string_view{} : t.substr(sp + 1);
    const std::size_t rest_column = sp + 2;
    const auto word = [&](std::size_t i) {  // the i-th blank-separated word of rest
      std::size_t b = 0;
      for (std::size_t k = 0; k < i; ++k) b = rest.find(' ', b) + 1;
      return std::string(rest.substr(b, rest.find(' ', b) - b));
    };
    const auto after_word = [&](std::size_t i) {  // rest after the first i words, its column
      std::size_t b = 0;
      for (std::size_t k = 0; k < i; ++k) {
        b = rest.find(' ', b);
        if (b == std::string_view::npos) return std::pair{std::string_view{}, std::size_t{0}};
        ++b;
      }
      return std::pair{rest.substr(b), rest_column + b};
    };
    using K = ip::statement_kind;
    if (op == "P") return s;
    if (op == "PL") return s.label = word(0), s;
    if (op == "E") s.ends_program = true;
    else if (op == "L") s.kind = K::label, s.label = word(0), s.block_label = after_word(1).first;
    else if (op == "JC") s.kind = K::jump, s.target = word(0), s.target_optional = true;
    else if (op == "SE") {
      s.kind = K::call, s.target = word(0), s.end_target = word(1), s.ends = ip::call_end::end_label, s.call_frame = false;
      s.direction = ip::jump_direction::backward_then_forward;
      if (auto [c, col] = after_word(2); !c.empty()) s.count = expr(c, l, col);
    } else if (op == "F") {
      s.kind = K::loop_begin, s.loop = ip::loop_kind::counting;
      auto [first, first_col] = after_word(1);
      auto [last, last_col] = after_word(2);
      s.counter = ip::assignment{expr(word(0), l, rest_column), expr(word(1), l, first_col)};
      s.count = expr(last, l, last_col);
    } else if (op == "EF") s.kind = K::loop_end, s.loop = ip::loop_kind::counting;
    else if (op == "J" || op == "JF" || op == "JB") {
      s.kind = K::jump;
      s.target = word(0);
      s.direction = op == "JF" ? ip::jump_direction::forward : op == "JB" ? ip::jump_direction::backward : ip::jump_direction::either;
      if (auto [c, col] = after_word(1); !c.empty()) s.condition = expr(c, l, col);
    } else if (op == "C" || op == "S" || op == "CF") {
      s.kind = K::call;
      if (op == "CF") s.files = {word(0) + ".toy", word(0)};
      s.target = word(0);
      if (auto [c, col] = after_word(1); !c.empty()) s.count = expr(c, l, col);
      if (op == "S") s.ends = ip::call_end::calling_line, s.call_frame = false;
    } else if (op == "R") s.kind = K::return_from_call;
    else if (op == "RC") s.kind = K::return_from_call, s.only_in_call = true;
    else if (op == "SUB") s.kind = K::subprogram, s.key = word(0), s.label = word(0);
    else if (op == "ENDSUB") s.kind = K::return_from_call, s.key = word(0), s.ends_subprogram = true;
    else if (op == "I") s.kind = K::if_branch, s.condition = expr(rest, l, rest_column);
    else if (op == "EI") s.kind = K::else_if_branch, s.condition = expr(rest, l, rest_column);
    else if (op == "EL") s.kind = K::else_branch;
    else if (op == "EN") s.kind = K::end_if;
    else if (op == "W") s.kind = K::loop_begin, s.condition = expr(rest, l, rest_column);
    else if (op == "EW") s.kind = K::loop_end;
    else if (op == "D") s.kind = K::loop_begin, s.loop = ip::loop_kind::test_last;
    else if (op == "U") s.kind = K::loop_end, s.loop = ip::loop_kind::test_last, s.until = true, s.condition = expr(rest, l, rest_column);
    else if (op == "RP") s.kind = K::loop_begin, s.loop = ip::loop_kind::counted, s.count = expr(rest, l, rest_column);
    else if (op == "ER") s.kind = K::loop_end;
    else if (op == "B") s.kind = K::loop_break;
    else if (op == "K") s.kind = K::loop_continue;
    else if (op == "AI") {
      const std::size_t eq = rest.find('='), cond = rest.find(" IF ");
      s.assignments.push_back({expr(rest.substr(0, eq - 1), l, rest_column),
                               expr(rest.substr(eq + 2, cond - eq - 2), l, rest_column + eq + 2)});
      s.condition = expr(rest.substr(cond + 4), l, rest_column + cond + 4);
    } else if (op == "A") {
      const std::size_t eq = rest.find('=');
      s.assignments.push_back({expr(rest.substr(0, eq - 1), l, rest_column), expr(rest.substr(eq + 2), l, rest_column + eq + 2)});
    } else s.error = ip::expression_error{{l.number, 1, op.size()}, "unknown statement " + std::string(op)};
    return s;
  }
};

struct run_result {
  std::vector<std::string> lines;  // the ordinary lines executed, in order
  std::string error;               // "LINE:COL: message"
  bool ok = true;
};

run_result run(const std::string& text, ip::execution_limits limits = {}) {
  toy_syntax syntax;
  ip::executor x{text, kin5::program::linuxcnc::parameter_rules(), limits};
  run_result r;
  r.ok = x.execute(
      syntax, [&](const text_line& l, const ip::statement&) { r.lines.emplace_back(l.text); },
      [&](const ip::flow_error& e) { r.error = std::to_string(e.line) + ":" + std::to_string(e.column) + ": " + e.message; });
  return r;
}

/// Files by name, for calls of other files: how often each was opened (`opened`), and by which
/// calling file (`opened_from`: the calling file's path, empty for the main text, and the name):
/// each at most once per calling file and run.
struct file_set {
  std::map<std::string, std::string> texts;
  std::map<std::string, int> opened{};
  std::map<std::pair<std::string, std::string>, int> opened_from{};
};

/// Runs `text` with calls of the files in `files`: the ordinary lines executed, those of a
/// called file as "FILE: line"; errors as "FILE:LINE:COL: message" (no FILE: the main text).
run_result run_with_files(const std::string& text, file_set& files, ip::execution_limits limits = {}) {
  toy_syntax syntax;
  ip::executor x{text, kin5::program::linuxcnc::parameter_rules(), limits};
  x.open_files_with([&](const std::string&, const std::vector<std::string>& names) -> std::optional<ip::called_file> {
    for (const std::string& n : names)
      if (auto f = files.texts.find(n); f != files.texts.end()) {
        ++files.opened[n];
        ++files.opened_from[{x.file(), n}];
        if (f->second == "unreadable") return ip::called_file{"dir/" + n, "", "cannot be read"};
        return ip::called_file{"dir/" + n, f->second};
      }
    return std::nullopt;
  });
  run_result r;
  r.ok = x.execute(
      syntax,
      [&](const text_line& l, const ip::statement&) {
        r.lines.push_back(x.file().empty() ? std::string(l.text) : x.file() + ": " + std::string(l.text));
      },
      [&](const ip::flow_error& e) {
        r.error = (e.file.empty() ? "" : e.file + ":") + std::to_string(e.line) + ":" + std::to_string(e.column) + ": " +
                  e.message;
      });
  return r;
}

std::vector<std::string> lines(std::initializer_list<const char*> l) { return {l.begin(), l.end()}; }

}  // namespace

TEST_CASE("executor: a program without control flow runs line by line", "[executor]") {
  const auto r = run("P a\nP b\r\nP c");
  CHECK(r.ok);
  CHECK(r.lines == lines({"P a", "P b", "P c"}));
  // Lines end at LF, CRLF or a lone CR, as for_each_line splits them: line numbers agree.
  CHECK(run("P a\rP b\rJ x\nP skipped\rL x\r\nX\r").error == "6:1: unknown statement X");
  CHECK(run("P a\rP b\rJ x\nP skipped\rL x\r\nP c\r").lines == lines({"P a", "P b", "P c"}));
  CHECK(run("P a\rP b\rJ x\rP c\rL x\r").lines == lines({"P a", "P b"}));  // a lone CR ends a line, as for_each_line has it
}

TEST_CASE("executor: jumps forward, backward, conditional, and a missing label", "[executor]") {
  CHECK(run("P a\nJ end\nP skipped\nL end\nP b\n").lines == lines({"P a", "P b"}));
  const auto loop = run("A #1 = 0\nL top\nA #1 = [#1+1]\nP x\nJ top [#1 LT 3]\nP done\n");
  CHECK(loop.lines == lines({"A #1 = 0", "A #1 = [#1+1]", "P x", "A #1 = [#1+1]", "P x", "A #1 = [#1+1]", "P x", "P done"}));
  // JF finds only a label after the jump; JB only one before; J the nearest after, else before.
  CHECK(run("L x\nP 1\nJF x\nP 2\n").error == "3:1: jump to x: no such label after this line");
  CHECK(run("A #1 = 1\nJB x [#1 EQ 1]\nL x\n").error == "2:1: jump to x: no such label before this line");
  CHECK(run("L x\nA #1 = [#1+1]\nJ x [#1 LT 2]\nL x\nP end\n").lines == lines({"A #1 = [#1+1]", "P end"}));
  CHECK(run("L x\nA #1 = [#1+1]\nJB x [#1 LT 2]\nL x\nP end\n").lines ==
        lines({"A #1 = [#1+1]", "A #1 = [#1+1]", "P end"}));
}

TEST_CASE("executor: IF, ELSEIF, ELSE nest and take one branch", "[executor]") {
  const std::string text =
      "A #1 = 2\nI [#1 EQ 1]\nP one\nEI [#1 EQ 2]\nI [1]\nP two-inner\nEL\nP never\nEN\nP two\nEI [#1 EQ 2]\nP not-again\n"
      "EL\nP else\nEN\nP after\n";
  CHECK(run(text).lines == lines({"A #1 = 2", "P two-inner", "P two", "P after"}));
  CHECK(run("I [0]\nP a\nEL\nP b\nEN\n").lines == lines({"P b"}));
  CHECK(run("I [0]\nP a\nEI [0]\nP b\nEN\nP c\n").lines == lines({"P c"}));
  CHECK(run("I [0]\nP a\n").error == "1:1: IF without its end");
}

TEST_CASE("executor: an ordinary line with a condition runs only when it holds", "[executor]") {
  const auto r = run("A #1 = 1\nAI #2 = 5 IF [#1 EQ 1]\nAI #3 = 7 IF [#1 EQ 2]\nA #4 = [#2 + #3]\nJ ok [#4 EQ 5]\nP wrong\n"
                     "L ok\nP end\n");
  CHECK(r.ok);
  CHECK(r.lines == lines({"A #1 = 1", "AI #2 = 5 IF [#1 EQ 1]", "A #4 = [#2 + #3]", "P end"}));
  CHECK(run("AI #2 = 1 IF [1/0]\nP end\n").error == "1:16: division by zero");
}

TEST_CASE("executor: while, do-until, counted loops, break and continue", "[executor]") {
  CHECK(run("A #1 = 0\nW [#1 LT 2]\nA #1 = [#1+1]\nEW\nP end\n").lines ==
        lines({"A #1 = 0", "A #1 = [#1+1]", "A #1 = [#1+1]", "P end"}));
  CHECK(run("W [0]\nP never\nEW\nP end\n").lines == lines({"P end"}));
  CHECK(run("A #1 = 5\nD\nA #1 = [#1+1]\nU [#1 GT 2]\nP end\n").lines == lines({"A #1 = 5", "A #1 = [#1+1]", "P end"}));
  CHECK(run("RP [3]\nP x\nER\n").lines == lines({"P x", "P x", "P x"}));
  CHECK(run("RP [0]\nP x\nER\nP end\n").lines == lines({"P end"}));
  CHECK(run("RP [2]\nRP [2]\nP x\nER\nP y\nER\n").lines == lines({"P x", "P x", "P y", "P x", "P x", "P y"}));
  CHECK(run("A #1 = 0\nW [1]\nA #1 = [#1+1]\nI [#1 EQ 3]\nB\nEN\nP x\nEW\nP end\n").lines ==
        lines({"A #1 = 0", "A #1 = [#1+1]", "P x", "A #1 = [#1+1]", "P x", "A #1 = [#1+1]", "P end"}));
  CHECK(run("A #1 = 0\nW [#1 LT 3]\nA #1 = [#1+1]\nI [#1 EQ 2]\nK\nEN\nP x\nEW\n").lines ==
        lines({"A #1 = 0", "A #1 = [#1+1]", "P x", "A #1 = [#1+1]", "A #1 = [#1+1]", "P x"}));
  CHECK(run("B\n").error == "1:1: a loop break outside a loop");
  CHECK(run("EW\n").error == "1:1: the end of a loop that is not open");
  CHECK(run("P a\nW [1]\nP x\n").error == "2:1: a loop without its end");  // the text ends inside it
}

TEST_CASE("executor: a jump out of a loop closes it", "[executor]") {
  // Without closing, the second W would be taken for the first one's test again.
  CHECK(run("A #2 = 0\nL top\nA #2 = [#2+1]\nW [1]\nJ out\nEW\nL out\nJ top [#2 LT 3]\nP end\n").lines ==
        lines({"A #2 = 0", "A #2 = [#2+1]", "A #2 = [#2+1]", "A #2 = [#2+1]", "P end"}));
}

TEST_CASE("executor: calls with passes, locals, returns, subprograms and section repeats", "[executor]") {
  // A subprogram after the program's end, called twice with 2 passes.
  CHECK(run("P a\nC sub [2]\nP b\nE\nL sub\nP in\nR\n").lines == lines({"P a", "P in", "P in", "P b", "E"}));
  // Locals (#1–#30 in LinuxCNC) belong to the call; globals (#31 on) do not.
  CHECK(run("A #1 = 7\nA #31 = 0\nC s\nP after\nE\nL s\nA #1 = 1\nA #31 = [#1+#31]\nR\n").ok);
  {
    toy_syntax syntax;
    const std::string text = "A #1 = 7\nC s\nE\nL s\nA #1 = 1\nA #31 = 5\nR\n";
    ip::executor x{text, kin5::program::linuxcnc::parameter_rules()};
    CHECK(x.execute(syntax, [](const text_line&, const ip::statement&) {}, [](const ip::flow_error&) {}));
    CHECK(x.parameters().read({"#", 1}).value == 7.0);
    CHECK(x.parameters().read({"#", 31}).value == 5.0);
  }
  // A keyed subprogram in the flow is skipped; a call starts after its first line.
  CHECK(run("SUB s\nP in\nENDSUB s\nP a\nC s\nP b\n").lines == lines({"P a", "P in", "P b"}));
  // Section repeat: back to the label 2 more times, then on after the calling line.
  CHECK(run("P a\nL rep\nP x\nS rep [2]\nP b\n").lines == lines({"P a", "P x", "P x", "P x", "P b"}));
  CHECK(run("L rep\nS rep [2]\nP b\n").lines == lines({"P b"}));  // an empty section
  CHECK(run("L a\nL b\nP x\nS b [1]\nS a [1]\nP end\n").lines == lines({"P x", "P x", "P x", "P x", "P end"}));  // nested
  // A return inside a section repeat inside a subprogram leaves both.
  CHECK(run("C s\nE\nL s\nL r\nP x\nA #31 = [#31+1]\nI [#31 EQ 2]\nR\nEN\nS r [3]\nP never\nR\n").lines ==
        lines({"P x", "A #31 = [#31+1]", "P x", "A #31 = [#31+1]", "E"}));
  CHECK(run("C nowhere\n").error == "1:1: call of nowhere: no such label in this file");
  CHECK(run("R\n").error == "1:1: returns from a call, but no call is open");
  CHECK(run("L a\nP x\nR\nS a [1]\n").error == "3:1: returns from a call, but no call is open");  // a repeat is no call
  CHECK(run("C s\nL s\nP x\n").error == "3:1: the text ends inside the call from line 1");
  CHECK(run("L s\nC s\n").error == "2:1: calls nested more than 64 deep");
}

TEST_CASE("executor: calls of other files", "[executor][files]") {
  file_set f{{{"sub.toy", "P in\nA #1 = 9\nA #31 = [#31+1]\nR\n"},
              {"deep", "P deep\nCF sub [1]\nE\n"},
              {"keyed.toy", "P before\nSUB keyed\nP k\nENDSUB keyed\n"},
              {"self.toy", "CF self\nR\n"},
              {"open.toy", "P x\n"},
              {"bad.toy", "P x\nJ nowhere\nR\n"},
              {"gone.toy", "unreadable"}}};
  // Run and back, twice with 2 passes; the file loaded once; its locals its own.
  const auto r = run_with_files("A #1 = 2\nA #31 = 0\nCF sub [2]\nP b\nCF sub\nI [#31 NE 3 OR #1 NE 2]\nP wrong\nEN\nE\n", f);
  CHECK(r.error.empty());
  CHECK(r.lines == lines({"A #1 = 2", "A #31 = 0", "dir/sub.toy: P in", "dir/sub.toy: A #1 = 9", "dir/sub.toy: A #31 = [#31+1]", "dir/sub.toy: P in",
                          "dir/sub.toy: A #1 = 9", "dir/sub.toy: A #31 = [#31+1]", "P b", "dir/sub.toy: P in", "dir/sub.toy: A #1 = 9", "dir/sub.toy: A #31 = [#31+1]", "E"}));
  CHECK(f.opened["sub.toy"] == 1);
  // A label of the text is called before a file of that name.
  CHECK(run_with_files("CF sub\nE\nL sub\nP here\nR\n", f).lines == lines({"P here", "E"}));
  // A file that calls a file; its end of program (E) ends its call.
  CHECK(run_with_files("CF deep\nP b\n", f).lines ==
        lines({"dir/deep: P deep", "dir/sub.toy: P in", "dir/sub.toy: A #1 = 9", "dir/sub.toy: A #31 = [#31+1]", "dir/deep: E", "P b"}));
  // A file that defines the label runs from it, to its end (a keyed subprogram).
  CHECK(run_with_files("CF keyed\nP b\n", f).lines == lines({"dir/keyed.toy: P k", "P b"}));
  // Refused: no opener, no file, a file that cannot be read, an error inside a file (named by
  // the file's path and line), a file that never returns, a file that calls itself for ever.
  CHECK(run("P a\nCF sub\n").error == "2:1: call of sub: no label sub in this file, and no directory to look for its "
                                       "file sub.toy or sub in (--include-dir DIR names the directory that holds it)");
  CHECK(run_with_files("CF none\n", f).error ==
        "1:1: call of none: no label none in this file, nor a file none.toy or none in the include directories (--include-dir)");
  CHECK(run_with_files("CF gone\n", f).error == "1:1: call of gone: dir/gone.toy: cannot be read");
  CHECK(run_with_files("P a\nCF bad\n", f).error == "dir/bad.toy:2:1: jump to nowhere: no such label in this file");
  CHECK(run_with_files("CF open\n", f).error == "dir/open.toy:1:1: the called file ends without returning to the call from line 1");
  CHECK(run_with_files("CF self\n", f).error.ends_with("calls nested more than 64 deep (a file that calls itself without end?)"));
  CHECK(f.opened["self.toy"] == 2);  // once for the main text's call, once for its own: a name may be
                                     // relative to the calling file (Heidenhain CALL PGM)
  // The bounds count over all files.
  ip::execution_limits small;
  small.max_executed_lines = 5;
  CHECK(run_with_files("CF sub [3]\n", f, small).error.starts_with("dir/sub.toy:"));
}

namespace {

/// Each ordinary line run, with the calls open at it as `[FILE:LINE:COL <- …]`, outermost first
/// (the main text is "main"); the run's table of call chains afterwards (`calls`).
struct chain_run {
  std::vector<std::string> lines;
  kin5::program::call_chains calls;
  std::string error;
};

chain_run run_chains(const std::string& text, file_set& files) {
  toy_syntax syntax;
  chain_run r;
  ip::executor x{text, kin5::program::linuxcnc::parameter_rules()};
  x.record_calls_in(r.calls, "main");
  x.open_files_with([&](const std::string&, const std::vector<std::string>& names) -> std::optional<ip::called_file> {
    for (const std::string& n : names)
      if (auto f = files.texts.find(n); f != files.texts.end()) return ip::called_file{"dir/" + n, f->second};
    return std::nullopt;
  });
  x.execute(
      syntax,
      [&](const text_line& l, const ip::statement&) {
        std::string line(l.text);
        if (x.call_chain() != 0) {
          line += " [";
          const auto sites = r.calls.sites(x.call_chain());
          for (std::size_t i = 0; i < sites.size(); ++i)
            line += (i ? " <- " : "") + sites[i].file.str() + ":" + std::to_string(sites[i].line) + ":" +
                    std::to_string(sites[i].column);
          line += "]";
        }
        r.lines.push_back(line);
      },
      [&](const ip::flow_error& e) { r.error = std::to_string(e.line) + ": " + e.message; });
  return r;
}

}  // namespace

TEST_CASE("executor: every line runs in the chain of the calls open, interned once", "[executor][calls]") {
  file_set none;
  // A loop calls s 1,000 times; s calls t: two chains in all, whatever the count.
  const auto r = run_chains("A #31 = 0\nW [#31 LT 1000]\nA #31 = [#31+1]\nC s\nEW\nP top\nE\nL s\nP in-s\nC t\nR\nL t\nP in-t\nR\n", none);
  CHECK(r.error.empty());
  REQUIRE(r.lines.size() == 2 + 3 * 1000 + 1);
  CHECK(r.lines[2] == "P in-s [main:4:1]");
  CHECK(r.lines[3] == "P in-t [main:4:1 <- main:10:1]");
  CHECK(r.lines[r.lines.size() - 3] == "P in-t [main:4:1 <- main:10:1]");
  CHECK(r.lines[r.lines.size() - 2] == "P top");  // back at the top level
  CHECK(r.calls.size() == 2);
  // Repeats and calls of other files are calls too; a file's own call sites name its path.
  file_set f{{{"sub.toy", "P in\nC t\nR\nL t\nP deep\nR\n"}}};
  CHECK(run_chains("P a\nCF sub [2]\nP b\nL r\nP x\nS r [1]\n", f).lines ==
        lines({"P a", "P in [main:2:1]", "P deep [main:2:1 <- dir/sub.toy:2:1]", "P in [main:2:1]",
               "P deep [main:2:1 <- dir/sub.toy:2:1]", "P b", "P x", "P x [main:6:1]"}));
}

TEST_CASE("executor: bounds and errors stop the run at the statement", "[executor]") {
  ip::execution_limits small;
  small.max_executed_lines = 100;
  CHECK(run("W [1]\nP x\nEW\n", small).error == "2:1: more than 100 lines executed: the loop at line 1 may never end "
                                                "(--max-executed-lines raises the bound)");
  CHECK(run("L a\nJ a\n", small).error.ends_with("a jump may repeat for ever (--max-executed-lines raises the bound)"));
  CHECK(run("P a\nA #1 = [1/0]\nP never\n").error.starts_with("2:"));
  CHECK(run("P a\nX\n").error == "2:1: unknown statement X");
  CHECK(run("RP [1.5]\nER\n").error.find("is not a whole number") != std::string::npos);
  CHECK(run("P a\nW [1]\nP x\n").error == "2:1: a loop without its end");  // its body runs into the end
}

TEST_CASE("executor: labels are indexed once, and only when needed", "[executor]") {
  toy_syntax plain;
  ip::executor a{std::string_view("P a\nP b\nP c\n"), kin5::program::linuxcnc::parameter_rules()};
  a.execute(plain, [](const text_line&, const ip::statement&) {}, [](const ip::flow_error&) {});
  CHECK(plain.statements_read == 3);
}

// The law: a random structured program (nested IFs, while, do-until and counted loops with
// breaks, calls of subprograms with passes, section repeats) runs to the same ordinary lines as
// a direct recursive run of the tree it was printed from.
namespace {

struct node;
using body = std::vector<node>;

struct node {
  enum class kind { print, assign, if_else, while_loop, do_until, counted, call, section, early_return } what = kind::print;
  int a = 0, b = 0;     // print: id; assign: variable, value; if: variable, bound; loops: runs; call: sub, passes
  bool has_break = false;
  int counter = 0;      // a loop's counter: parameter #(40 + counter)
  body then_body, else_body;
};

struct tree {
  body main;
  std::vector<body> subs;  // sub k calls only subs after it
};

rc::Gen<body> gen_body(int depth, int sub, int subs);

// A whole number in [first, last), every one as likely at any size (`inRange` keeps to the low
// end while RapidCheck's size is small, which left every condition false).
rc::Gen<int> uniform(int first, int last) {
  std::vector<int> v;
  for (int i = first; i < last; ++i) v.push_back(i);
  return rc::gen::elementOf(v);
}

rc::Gen<node> gen_node(int depth, int sub, int subs) {
  using K = node::kind;
  std::vector<rc::Gen<node>> choices{
      rc::gen::map(uniform(0, 100), [](int id) { return node{K::print, id}; }),
      rc::gen::map(rc::gen::pair(uniform(0, 3), uniform(0, 4)),
                   [](std::pair<int, int> p) { return node{K::assign, p.first, p.second}; })};
  if (depth < 3) {
    choices.push_back(rc::gen::map(rc::gen::tuple(uniform(0, 3), uniform(0, 4), gen_body(depth + 1, sub, subs),
                                                  gen_body(depth + 1, sub, subs)),
                                   [](std::tuple<int, int, body, body> t) {
                                     node n{K::if_else, std::get<0>(t), std::get<1>(t)};
                                     n.then_body = std::get<2>(t);
                                     n.else_body = std::get<3>(t);
                                     return n;
                                   }));
    for (K k : {K::while_loop, K::do_until, K::counted, K::section})
      choices.push_back(rc::gen::map(rc::gen::tuple(uniform(0, 3), rc::gen::arbitrary<bool>(), gen_body(depth + 1, sub, subs)),
                                     [k](std::tuple<int, bool, body> t) {
                                       node n{k, std::get<0>(t)};
                                       n.has_break = k != K::section && std::get<1>(t);
                                       n.then_body = std::get<2>(t);
                                       return n;
                                     }));
  }
  if (sub >= 0)  // in a subprogram: return when a parameter is below a bound (twice as likely as the others)
    for (int twice = 0; twice < 2; ++twice)
      choices.push_back(rc::gen::map(rc::gen::pair(uniform(0, 3), uniform(0, 4)),
                                     [](std::pair<int, int> p) { return node{K::early_return, p.first, p.second}; }));
  if (sub + 1 < subs)
    choices.push_back(rc::gen::map(rc::gen::pair(uniform(sub + 1, subs), uniform(0, 3)),
                                   [](std::pair<int, int> p) { return node{K::call, p.first, p.second}; }));
  return rc::gen::join(rc::gen::elementOf(choices));
}

rc::Gen<body> gen_body(int depth, int sub, int subs) {
  return rc::gen::lazy([=] { return rc::gen::container<body>(rc::gen::resize(3, rc::gen::lazy([=] { return gen_node(depth, sub, subs); }))); });
}

// Gives each loop a counter of its own.
void number_loops(body& b, int& next) {
  for (node& n : b) {
    if (n.what == node::kind::while_loop || n.what == node::kind::do_until || n.what == node::kind::counted) n.counter = next++;
    number_loops(n.then_body, next);
    number_loops(n.else_body, next);
  }
}

/// A random program tree (inside a property): a main body and 1 to 4 subprograms, its loops numbered.
tree gen_tree() {
  const int subs = *uniform(1, 4);
  tree t;
  t.main = *gen_body(0, -1, subs);
  for (int s = 0; s < subs; ++s) t.subs.push_back(*gen_body(1, s, subs));
  int counters = 0;
  number_loops(t.main, counters);
  for (body& b : t.subs) number_loops(b, counters);
  return t;
}

// The printed program.
struct printer {
  std::string out;
  int labels = 0;
  void line(const std::string& s) { out += s + "\n"; }
  void print(const body& b) {
    for (const node& n : b) print(n);
  }
  void print(const node& n) {
    using K = node::kind;
    const std::string c = "#" + std::to_string(40 + n.counter);
    switch (n.what) {
      case K::print: line("P " + std::to_string(n.a)); break;
      case K::assign: line("A #" + std::to_string(31 + n.a) + " = [" + std::to_string(n.b) + "]"); break;
      case K::if_else:
        line("I [#" + std::to_string(31 + n.a) + " LT " + std::to_string(n.b) + "]");
        print(n.then_body);
        line("EL");
        print(n.else_body);
        line("EN");
        break;
      case K::while_loop:
      case K::do_until:
      case K::counted: {
        line("A " + c + " = 0");
        line(n.what == K::while_loop ? "W [" + c + " LT " + std::to_string(n.a) + "]"
                                     : n.what == K::do_until ? "D" : "RP [" + std::to_string(n.a) + "]");
        line("A " + c + " = [" + c + "+1]");
        if (n.has_break) line("I [" + c + " EQ 2]"), line("B"), line("EN");
        print(n.then_body);
        line(n.what == K::while_loop ? "EW" : n.what == K::do_until ? "U [" + c + " GE " + std::to_string(n.a) + "]" : "ER");
        break;
      }
      case K::section: {
        const std::string l = "s" + std::to_string(labels++);
        line("L " + l);
        print(n.then_body);
        line("S " + l + " [" + std::to_string(n.a) + "]");
        break;
      }
      case K::call: line("C sub" + std::to_string(n.a) + " [" + std::to_string(n.b) + "]"); break;
      case K::early_return:
        line("I [#" + std::to_string(31 + n.a) + " LT " + std::to_string(n.b) + "]");
        line("R");
        line("EN");
        break;
    }
  }
};

// The direct run of the tree.
struct model {
  const tree& t;
  std::map<int, double> p{};  // parameters by number
  std::vector<std::string> out{};
  bool returning = false;  // an early return is leaving the running subprogram

  void run(const body& b) {
    for (const node& n : b) {
      run(n);
      if (returning) return;
    }
  }
  void run(const node& n) {
    using K = node::kind;
    const int c = 40 + n.counter;
    const std::string cs = "#" + std::to_string(c);
    switch (n.what) {
      case K::print: out.push_back("P " + std::to_string(n.a)); break;
      case K::assign:
        p[31 + n.a] = n.b;
        out.push_back("A #" + std::to_string(31 + n.a) + " = [" + std::to_string(n.b) + "]");
        break;
      case K::if_else: run(p[31 + n.a] < n.b ? n.then_body : n.else_body); break;
      case K::while_loop:
      case K::do_until:
      case K::counted:
        p[c] = 0;
        out.push_back("A " + cs + " = 0");
        for (int run_no = 0;; ++run_no) {
          if (n.what == K::while_loop && !(p[c] < n.a)) break;
          if (n.what == K::counted && run_no >= n.a) break;
          p[c] += 1;
          out.push_back("A " + cs + " = [" + cs + "+1]");
          if (n.has_break && p[c] == 2) break;
          run(n.then_body);
          if (returning) return;
          if (n.what == K::do_until && p[c] >= n.a) break;
        }
        break;
      case K::section:
        for (int pass = 0; pass <= n.a && !returning; ++pass) run(n.then_body);
        break;
      case K::call:
        for (int pass = 0; pass < n.b; ++pass) {
          run(t.subs[static_cast<std::size_t>(n.a)]);
          returning = false;
        }
        break;
      case K::early_return: returning = p[31 + n.a] < n.b; break;
    }
  }
};

}  // namespace

TEST_CASE("executor law: structured programs run as their trees", "[executor][law]") {
  rc::prop("the executed ordinary lines equal a direct run of the program's tree", [] {
    const tree t = gen_tree();
    const int subs = static_cast<int>(t.subs.size());
    printer pr;
    pr.print(t.main);
    pr.line("E");
    for (int s = 0; s < subs; ++s) {
      pr.line("L sub" + std::to_string(s));
      pr.print(t.subs[static_cast<std::size_t>(s)]);
      pr.line("R");
    }
    model m{t};
    m.run(t.main);
    m.out.push_back("E");
    const run_result r = run(pr.out);
    RC_LOG() << pr.out << "error: " << r.error << "\n";
    RC_ASSERT(r.error.empty());
    RC_ASSERT(r.lines == m.out);
  });
  rc::prop("with each subprogram in a file of its own, the same lines run", [] {
    const tree t = gen_tree();
    const int subs = static_cast<int>(t.subs.size());
    const auto as_file_calls = [](std::string text) {  // "C subN" → "CF subN"
      for (std::size_t at = text.find("C sub"); at != std::string::npos; at = text.find("C sub", at))
        if (at == 0 || text[at - 1] == '\n') text.replace(at, 1, "CF");
        else ++at;
      return text;
    };
    printer pr;
    pr.print(t.main);
    pr.line("E");
    file_set f;
    for (int s = 0; s < subs; ++s) {
      printer sub;
      sub.print(t.subs[static_cast<std::size_t>(s)]);
      sub.line("R");
      f.texts["sub" + std::to_string(s) + ".toy"] = as_file_calls(sub.out);
    }
    model m{t};
    m.run(t.main);
    m.out.push_back("E");
    run_result r = run_with_files(as_file_calls(pr.out), f);
    for (std::string& l : r.lines)  // the lines without their files
      if (l.starts_with("dir/")) l = l.substr(l.find(": ") + 2);
    for (std::string& l : m.out) l = as_file_calls(l);
    RC_LOG() << pr.out << "error: " << r.error << "\n";
    RC_ASSERT(r.error.empty());
    RC_ASSERT(r.lines == m.out);
    for (const auto& [from, times] : f.opened_from) RC_ASSERT(times == 1);
  });
}

TEST_CASE("executor: a return that is only for calls does nothing in the program's flow", "[executor]") {
  // Heidenhain: a subprogram before M30, run into without a call, runs once; its LBL 0 is passed.
  const auto r = run("L s\nP a\nRC\nC s\nE\n");
  CHECK(r.ok);
  CHECK(r.lines == lines({"P a", "P a", "E"}));
  const auto plain = run("L s\nP a\nR\nC s\nE\n");
  CHECK_FALSE(plain.ok);
  CHECK(plain.error == "3:1: returns from a call, but no call is open");
}

TEST_CASE("executor: counting loops, optional jumps, sections between two labels, block labels", "[executor]") {
  // FOR: the counter from its first value up by 1 to the last, evaluated once; none when past it.
  CHECK(run("F #1 1 3\nA #2 = #1\nEF\nP end\n").lines == lines({"A #2 = #1", "A #2 = #1", "A #2 = #1", "P end"}));
  CHECK(run("F #1 4 3\nP never\nEF\nP end\n").lines == lines({"P end"}));
  CHECK(run("F #1 1 2\nF #2 1 2\nP x\nEF\nP y\nEF\n").lines == lines({"P x", "P x", "P y", "P x", "P x", "P y"}));
  {
    toy_syntax syntax;
    const std::string text = "A #3 = 2\nF #1 1 #3\nA #3 = 10\nEF\n";  // the last value is read once
    ip::executor x{text, kin5::program::linuxcnc::parameter_rules()};
    CHECK(x.execute(syntax, [](const text_line&, const ip::statement&) {}, [](const ip::flow_error&) {}));
    CHECK(x.parameters().read({"#", 1}).value == 3.0);
  }
  CHECK(run("F #1 1 2\nA #9 = #1\nB\nEF\nP end\n").lines == lines({"A #9 = #1", "P end"}));
  // GOTOC: a missing label is no error, the run goes on.
  CHECK(run("JC nowhere\nP a\n").lines == lines({"P a"}));
  CHECK(run("JC x\nP skipped\nL x\nP a\n").lines == lines({"P a"}));
  // A section between two labels, run n times from the calling line, then on after it.
  CHECK(run("P a\nSE s e 2\nP b\nE\nL s\nP in\nL e\nP never\n").lines == lines({"P a", "P in", "P in", "P b", "E"}));
  CHECK(run("PL s\nP x\nSE s s 2\nP end\n").lines == lines({"PL s", "P x", "PL s", "PL s", "P end"}));  // one line
  CHECK(run("L s\nSE s e 1\n").error == "2:1: repeat of s to e: no label e after s");
  // The start searched before the call first, then after it.
  CHECK(run("PL s\nPL e\nSE s e 1\nE\nPL s\nP after\nPL e\n").lines == lines({"PL s", "PL e", "PL s", "PL e", "E"}));
  CHECK(run("SE s e 1\nE\nPL s\nP after\nPL e\n").lines == lines({"PL s", "P after", "PL e", "E"}));
  // A line's second label (its block number) is a jump target too.
  CHECK(run("J N30\nP skipped\nL x N30\nP a\n").lines == lines({"P a"}));
}
