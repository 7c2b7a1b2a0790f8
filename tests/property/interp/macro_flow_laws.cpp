// FANUC macro B control flow as the ISO reader executes it (program/iso/statements.hpp): a
// generated structured program — variables, WHILE … DOm … ENDm, IF … GOTO, IF … THEN, M98 and
// G65 calls of subprograms after M30 — reads to the same moves as its twin unrolled by this test
// (which runs the structure itself, on whole thousandths), and per construct, examples and the
// messages of what is refused; LinuxCNC's and Haas's own statements likewise.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/haas/dialect.hpp>
#include <kin5/program/iso/dialect.hpp>
#include <kin5/program/linuxcnc/dialect.hpp>

namespace {

using namespace kin5::program;

std::string fixed3(long thousandths) {
  const bool negative = thousandths < 0;
  const long a = std::labs(thousandths);
  const std::string s = std::to_string(a / 1000) + "." + std::to_string(1000 + a % 1000).substr(1);
  return negative ? "-" + s : s;
}

/// The end points of the moves of a program read without error ("" and the errors otherwise).
std::string moves_of(const read_result& r) {
  std::string out;
  for (const diagnostic& d : r.errors)
    out += "error " + std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + ": " + d.message + "\n";
  if (!r.errors.empty()) return out;
  double at[3] = {0, 0, 0};
  for (const block& b : r.parsed.blocks) {
    if (!b.moves()) continue;
    if (b.axes.x_mm) at[0] = *b.axes.x_mm;
    if (b.axes.y_mm) at[1] = *b.axes.y_mm;
    if (b.axes.z_mm) at[2] = *b.axes.z_mm;
    out += fixed3(std::lround(at[0] * 1000)) + " " + fixed3(std::lround(at[1] * 1000)) + " " +
           fixed3(std::lround(at[2] * 1000)) + "\n";
  }
  return out;
}

std::string errors_of(const read_result& r) {
  std::string out;
  for (const diagnostic& d : r.errors)
    out += std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + ": " + d.message + "\n";
  return out;
}

/// One statement of a structured FANUC program (see the file comment).
struct statement_node {
  enum class kind { move, assign, if_then, skip, m98, g65, loop } k = kind::move;
  int a = 100, b = 100;   // variables
  long c = 0, d = 0;      // constants, in thousandths
  int count = 0;          // M98's passes, a loop's runs
  int label = 0;          // a skip's N, a loop's counter variable
  std::vector<statement_node> body;  // a skip's or a loop's
};

/// Draws a structured program and writes it (`text`) and its twin, what it does (`twin`).
class macro_gen {
 public:
  std::string text, twin;

  macro_gen() {
    for (int v = 100; v < 103; ++v) {
      v_[v] = *rc::gen::inRange(-5000, 5000);
      text += "#" + std::to_string(v) + " = " + fixed3(v_[v]) + "\n";
    }
    twin = text;
    std::vector<statement_node> program;
    const int n = *rc::gen::inRange(1, 6);
    for (int k = 0; k < n; ++k) program.push_back(draw(0));
    for (const statement_node& s : program) write(s, 0);
    for (const statement_node& s : program) run(s);
    text += "M30\n" + subprograms();
    twin += "M30\n";
  }

 private:
  std::map<int, long> v_;  // the variables, in thousandths
  int label_ = 10;
  int counter_ = 500;

  static std::string subprograms() {
    return "O1000 (M98)\n"
           "G1 X[#100 + 1.] Z#101\n"
           "#102 = #102 + 0.5\n"
           "M99\n"
           "O2000 (G65: A is #1, B is #2)\n"
           "G1 X#1 Y[#2 - #100]\n"
           "IF [#1 GT #2] GOTO 900\n"
           "G0 Z#2\n"
           "N900 M99\n";
  }

  static long constant() { return *rc::gen::inRange(-5000, 5000); }
  static int var() { return *rc::gen::inRange(100, 103); }
  static std::string v(int n) { return "#" + std::to_string(n); }

  statement_node draw(int depth) {
    using K = statement_node::kind;
    statement_node s;
    const int choice = depth >= 2 ? *rc::gen::inRange(0, 3) : *rc::gen::inRange(0, 8);
    s.k = choice <= 5 ? static_cast<K>(choice) : K::loop;
    s.a = var(), s.b = var(), s.c = constant(), s.d = constant();
    if (s.k == K::m98) s.count = *rc::gen::inRange(0, 3);
    if (s.k == K::skip) s.label = label_++, s.body.push_back(draw(depth + 1));
    if (s.k == K::loop) {
      s.count = *rc::gen::inRange(0, 3), s.label = counter_++;
      const int n = *rc::gen::inRange(1, 3);
      for (int k = 0; k < n; ++k) s.body.push_back(draw(depth + 1));
    }
    return s;
  }

  void write(const statement_node& s, int depth) {
    using K = statement_node::kind;
    switch (s.k) {
      case K::move: text += "G1 X[" + v(s.a) + " + " + fixed3(s.c) + "] Y" + v(s.b) + " Z-" + v(s.a) + "\n"; break;
      case K::assign: text += v(s.a) + " = " + v(s.b) + " - " + fixed3(s.c) + "\n"; break;
      case K::if_then: text += "IF [" + v(s.a) + " LT " + fixed3(s.c) + "] THEN " + v(s.b) + " = " + fixed3(s.d) + "\n"; break;
      case K::skip:
        text += "IF [" + v(s.a) + " GE " + fixed3(s.c) + "] GOTO " + std::to_string(s.label) + "\n";
        for (const statement_node& b : s.body) write(b, depth + 1);
        text += "N" + std::to_string(s.label) + "\n";
        break;
      case K::m98: text += "M98 P1000 L" + std::to_string(s.count) + "\n"; break;
      case K::g65: text += "G65 P2000 A" + fixed3(s.c) + " B" + fixed3(s.d) + "\n"; break;
      case K::loop: {
        const std::string m = std::to_string(depth + 1);
        text += v(s.label) + " = 0\nWHILE [" + v(s.label) + " LT " + std::to_string(s.count) + "] DO" + m + "\n";
        for (const statement_node& b : s.body) write(b, depth + 1);
        text += v(s.label) + " = " + v(s.label) + " + 1\nEND" + m + "\n";
      }
    }
  }

  void set(int var, long value) {
    v_[var] = value;
    twin += v(var) + " = " + fixed3(value) + "\n";
  }

  void run(const statement_node& s) {
    using K = statement_node::kind;
    switch (s.k) {
      case K::move: twin += "G1 X" + fixed3(v_[s.a] + s.c) + " Y" + fixed3(v_[s.b]) + " Z" + fixed3(-v_[s.a]) + "\n"; break;
      case K::assign: set(s.a, v_[s.b] - s.c); break;
      case K::if_then:
        if (v_[s.a] < s.c) set(s.b, s.d);
        break;
      case K::skip:
        if (!(v_[s.a] >= s.c))
          for (const statement_node& b : s.body) run(b);
        twin += "N" + std::to_string(s.label) + "\n";
        break;
      case K::m98:
        for (int k = 0; k < s.count; ++k) {
          twin += "G1 X" + fixed3(v_[100] + 1000) + " Z" + fixed3(v_[101]) + "\n";
          set(102, v_[102] + 500);
        }
        break;
      case K::g65:
        twin += "G1 X" + fixed3(s.c) + " Y" + fixed3(s.d - v_[100]) + "\n";
        if (!(s.c > s.d)) twin += "G0 Z" + fixed3(s.d) + "\n";
        break;
      case K::loop:
        set(s.label, 0);
        for (int k = 0; k < s.count; ++k) {
          for (const statement_node& b : s.body) run(b);
          set(s.label, v_[s.label] + 1000);
        }
    }
  }
};

const std::string preamble = "G21 G90 G94\nG0 X0. Y0. Z0.\n";

}  // namespace

TEST_CASE("FANUC macro B: a structured program reads to the moves of its unrolled twin", "[flow]") {
  rc::prop("the ISO reader executes WHILE, IF GOTO, IF THEN, M98 and G65 as the twin does", [] {
    const macro_gen g;
    RC_LOG() << g.text << "--- twin:\n" << g.twin;
    const std::string ours = moves_of(iso::read(preamble + g.text, "t.nc"));
    RC_ASSERT(ours == moves_of(iso::read(preamble + g.twin, "t.nc")));
    RC_ASSERT(ours.find("error") == std::string::npos);
    RC_ASSERT(moves_of(haas::read(preamble + g.text, "t.nc")) == ours);  // Haas reads FANUC's macros
  });
}

TEST_CASE("FANUC macro B: each construct, and what is refused", "[flow]") {
  const auto moves = [](const std::string& t) { return moves_of(iso::read(preamble + t, "t.nc")); };
  const auto errors = [](const std::string& t) { return errors_of(iso::read(t, "t.nc")); };
  CHECK(moves("#1 = 2.\nG1 X[#1 * 3 + 1] Y#[1] Z-[#1]\n") == "0.000 0.000 0.000\n7.000 2.000 -2.000\n");
  CHECK(moves("N5 #1 = 0\nN10 #1 = #1 + 1\nG1 X#1\nIF [#1 LT 3] GOTO 10\n") ==
        "0.000 0.000 0.000\n1.000 0.000 0.000\n2.000 0.000 0.000\n3.000 0.000 0.000\n");
  CHECK(moves("#1 = 0\nDO1\n#1 = #1 + 1\nIF [#1 GT 2] GOTO 20\nG1 Y#1\nEND1\nN20 G1 Z1.\n") ==
        "0.000 0.000 0.000\n0.000 1.000 0.000\n0.000 2.000 0.000\n0.000 2.000 1.000\n");
  // a GOTO searches its own program: N10 of O5 is not the main program's
  CHECK(moves("O1\n#1 = 0\nN10 #1 = #1 + 1\nG1 X#1\nIF [#1 LT 2] GOTO 10\nM98 P5\nM30\nO5\nN10 G1 Y1.\nM99\n") ==
        "0.000 0.000 0.000\n1.000 0.000 0.000\n2.000 0.000 0.000\n2.000 1.000 0.000\n");
  CHECK(moves("M98 P21000\nM30\nO1000\n#100 = 1\nG1 X#100\nM99\n") ==  // P: 2 passes of O1000
        "0.000 0.000 0.000\n1.000 0.000 0.000\n1.000 0.000 0.000\n");
  CHECK(moves("G65 P9 L2 X3. Y4. Z-1.\nM30\nO9\nG1 X#24 Y#25 Z#26\nM99\n") ==
        "0.000 0.000 0.000\n3.000 4.000 -1.000\n3.000 4.000 -1.000\n");
  // the executed program reads back: an assignment of an expression is written as the number
  const read_result r = iso::read("#1 = 2.\n#2 = #1 * 3\nG1 X#2\n", "t.nc");
  REQUIRE(r.ok());
  CHECK(r.parsed.blocks[1].text == "#2 = 6");
  CHECK(errors("M98 P1000\n") == "1:1: call of O1000: no label O1000 in this file, and no directory to look for its file "
                                  "O1000, O1000.nc or 1000.nc in (--include-dir DIR names the directory that holds it)\n");
  CHECK(errors("G1 X1.\nM99\n") ==
        "2:1: M99 in the main program: the control runs the program again from its start, without end (kin5 "
        "translates a program that ends: M30 or M2)\n");
  CHECK(errors("GOTO #1\n") == "1:6: GOTO to a computed block number is not supported (write GOTO n)\n");
  CHECK(errors("M98 P1000 X1.\nM30\nO1000\nM99\n") ==
        "1:11: word 'X1.' in the block of M98: a subprogram call or return is read in a block of its own (write the "
        "word in a block before it)\n");
  CHECK(errors("M30\nO1\nM99 P10\n").empty());  // never reached
  CHECK(errors("G65 P9 A1\nM30\nO9\nM99\n") ==
        "1:8: G65 argument A1 without a decimal point: the control reads it in the least input increment of address "
        "A (write A1.)\n");
  {  // the bound, lowered from its default of 10^8 so that the loop stops in a moment
    const read_limits few_lines{.max_executed_lines = 100'000};
    const read_limits_scope scope(few_lines);
    CHECK(errors("#1 = 1\nWHILE [#1 GT 0] DO1\nEND1\n") ==
          "3:1: more than 100000 lines executed: the loop at line 2 may never end (--max-executed-lines raises the "
          "bound)\n");
  }
  CHECK(errors("#5221 = 1.\n") ==
        "1:1: parameter #5221 is a system variable (#1000 and up: the control's offsets, positions and signals), not "
        "a value of this program\n");
  CHECK(errors("G1 X#1\n") == "1:5: parameter #1 is read before it is assigned in the main program\n");
  CHECK(errors("O ENTER OP AND LAST 3 DIGITS\n") ==
        "1:1: program number O without its digits (O1 … O9999): write the number, or put the text in a comment ( … )\n");
}

TEST_CASE("Haas: M97 calls the blocks from N n of this program", "[flow]") {
  const read_result r = haas::read(preamble + "M97 P100 L2\nG0 Z5.\nM30\nN100 G1 X1.\nG1 X2.\nM99\n", "t.nc");
  CHECK(errors_of(r).empty());
  CHECK(moves_of(r) == "0.000 0.000 0.000\n1.000 0.000 0.000\n2.000 0.000 0.000\n1.000 0.000 0.000\n"
                       "2.000 0.000 0.000\n2.000 0.000 5.000\n");
  CHECK(errors_of(iso::read("M97 P100\n", "t.nc")) ==
        "1:1: M97: a subprogram call is not supported (the motion it makes would be lost)\n");
}

TEST_CASE("LinuxCNC o-words: each construct, and what is refused", "[flow]") {
  const auto moves = [](const std::string& t) { return moves_of(linuxcnc::read("G21 G90\nG0 X0 Y0 Z0\n" + t, "t.ngc")); };
  const auto errors = [](const std::string& t) { return errors_of(linuxcnc::read(t, "t.ngc")); };
  CHECK(moves("o<p> sub\nG1 X#1 Y#2 F100\no<p> endsub\no<p> call [1] [2*3]\no<p> call [4]\n") ==
        "0.000 0.000 0.000\n1.000 6.000 0.000\n4.000 0.000 0.000\n");
  CHECK(moves("#<i> = 0\no1 do\n#<i> = [#<i> + 1]\nG1 X#<i> F100\no1 while [#<i> LT 2]\no2 repeat [2]\nG1 Y1\n"
              "o2 endrepeat\n") == "0.000 0.000 0.000\n1.000 0.000 0.000\n2.000 0.000 0.000\n2.000 1.000 0.000\n"
                                   "2.000 1.000 0.000\n");
  CHECK(errors("o<probe> call [1]\n") == "1:1: call of o<probe>: no label o<probe> in this file, and no directory to look "
                                          "for its file probe.ngc in (--include-dir DIR names the directory that holds it)\n");
  CHECK(errors("o1 repeat [2]\no1 break\no1 endrepeat\n") ==
        "2:1: o1 break: break and continue name a while or do loop of their o-word, and o1 is none (LinuxCNC stops: "
        "\"no matching while/do label\")\n");
  CHECK(errors("o1 if [1] G1 X1\n") == "1:11: a word after 'o1 if': an o-word takes its line alone\n");
  CHECK(errors("o1 frobnicate\n").find("unknown o-word 'o1 frobnicate'") != std::string::npos);
  CHECK(errors("#1 = 2 #2 = #1\n").find("a second parameter setting on a line that reads a parameter") != std::string::npos);
  CHECK(errors("o1 endsub\n") == "1:1: returns from a call, but no call is open\n");
}

namespace {

/// The calls open at `b` as "FILE:LINE:COL <- …", outermost first; "" at the top level.
std::string calls_of(const read_result& r, const block& b) {
  std::string out;
  for (const source_location& s : r.calls.sites(b.call_chain))
    out += (out.empty() ? "" : " <- ") + s.file.str() + ":" + std::to_string(s.line) + ":" + std::to_string(s.column);
  return out;
}

}  // namespace

TEST_CASE("ISO and LinuxCNC: blocks and errors in a call say where it was called from", "[flow][calls]") {
  // A loop calls O1000 100 times from one line, O1000 calls O2000: two chains in all.
  const read_result r = iso::read(
      "#1 = 0\nWHILE [#1 LT 100] DO1\n  M98 P1000\n#1 = #1 + 1\nEND1\nG1 Z1.\nM30\nO1000\nG1 X1.\nM98 P2000\nM99\n"
      "O2000\nG1 Y1.\nM99\n",
      "t.nc");
  REQUIRE(errors_of(r).empty());
  CHECK(r.calls.size() == 2);
  std::map<std::string, std::map<std::string, int>> seen;  // block text → its calls → how often
  for (const block& b : r.parsed.blocks) ++seen[b.text][calls_of(r, b)];
  CHECK(seen["G1 X1."] == std::map<std::string, int>{{"t.nc:3:3", 100}});
  CHECK(seen["G1 Y1."] == std::map<std::string, int>{{"t.nc:3:3 <- t.nc:10:1", 100}});
  CHECK(seen["G1 Z1."] == std::map<std::string, int>{{"", 1}});
  // An error in a subprogram called from two places: once per call, each noting its call.
  const read_result e = iso::read("M98 P1000\nM98 P1000\nM30\nO1000\nG1 X#7\nM99\n", "t.nc");
  REQUIRE(e.errors.size() == 2);
  CHECK(e.errors[0].to_string() ==
        "t.nc:5:5: error: parameter #7 is read before it is assigned in the main program\n"
        "t.nc:1:1: note: called from here");
  CHECK(e.errors[1].called_from == std::vector<source_location>{{"t.nc", 2, 1}});
  // An error of the executor itself inside a call: the same.
  const read_result j = iso::read("M98 P1000\nM30\nO1000\nGOTO 99\nM99\n", "t.nc");
  REQUIRE(j.errors.size() == 1);
  CHECK(j.errors[0].called_from == std::vector<source_location>{{"t.nc", 1, 1}});
  // LinuxCNC: a sub called with an argument; nested in another.
  const read_result l = linuxcnc::read(
      "o100 sub\nG1 X#1\no100 endsub\no200 sub\no100 call [3]\no200 endsub\nG21 G90\no200 call\nG1 Z1\nM2\n", "t.ngc");
  REQUIRE(errors_of(l).empty());
  std::vector<std::string> moves;
  for (const block& b : l.parsed.blocks)
    if (b.moves()) moves.push_back(calls_of(l, b));
  CHECK(moves == std::vector<std::string>{"t.ngc:8:1 <- t.ngc:5:1", ""});
}
