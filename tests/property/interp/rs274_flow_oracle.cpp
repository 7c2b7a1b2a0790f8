// LinuxCNC's own interpreter, rs274, as the oracle of kin5's LinuxCNC control flow: a generated
// program with parameters, expressions, o-word branches and loops (if/elseif/else, while,
// do/while, repeat, break and continue of while and do loops) and a subroutine called with arguments is read by kin5's
// LinuxCNC reader, which executes it (program/linuxcnc/statements.hpp), and run by `rs274 -g`:
// kin5's canonical moves (program/canonical/: rapid_move, linear_move, or a modal_move in the mode
// before it) are rs274's STRAIGHT_TRAVERSE and STRAIGHT_FEED, and end where they end, to 1e-9.
// Positions are sums of numbers of 3 decimals, which rs274's 4 printed decimals give exactly.
// Left out, as rs274 (LinuxCNC 2.9) parts from its manual there: once it has passed over a
// `break` it did not take (in an `if` whose condition failed, or in a while loop that did not
// run), the body of a later `do` loop runs once only (docs/dialects/linuxcnc.md); the generator
// draws `break` only in programs without `do` loops.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/canonical/block_operations.hpp>
#include <kin5/program/linuxcnc/dialect.hpp>

#include "rs274_canonical.hpp"

namespace {

using namespace kin5::program;
namespace rs = kin5::test::rs274;
namespace can = kin5::program::canonical;

std::string fixed3(int thousandths) {
  const bool negative = thousandths < 0;
  const int a = std::abs(thousandths);
  std::string s = std::to_string(a / 1000) + "." + std::to_string(1000 + a % 1000).substr(1);
  return negative ? "-" + s : s;
}

/// A structured program in LinuxCNC's spelling, drawn statement by statement.
class program_gen {
 public:
  std::string text;

  void statements(int depth, bool in_loop) {
    const int n = *rc::gen::inRange(1, 4);
    for (int k = 0; k < n; ++k) statement(depth, in_loop);
  }

 private:
  /// `break` is drawn only in a program without `do` loops (file comment).
  const bool breaks_ = *rc::gen::arbitrary<bool>();
  int next_o_ = 100;
  int next_counter_ = 40;

  std::string parameter() { return "#" + std::to_string(*rc::gen::inRange(31, 34)); }
  std::string offset() { return fixed3(*rc::gen::inRange(-20000, 20000)); }

  void line(const std::string& s) { text += s + "\n"; }

  void move() {
    const char* g = *rc::gen::element("G0", "G1");
    line(std::string(g) + " X[" + parameter() + " + " + offset() + "] Y[" + offset() + " - " + parameter() + "] Z" +
         offset());
  }

  void statement(int depth, bool in_loop) {
    const int choice = depth >= 3 ? *rc::gen::inRange(0, 3) : *rc::gen::inRange(0, 10);
    const std::string o = "o" + std::to_string(next_o_++);
    switch (choice) {
      case 0: move(); break;
      case 1: line(parameter() + " = [" + parameter() + " + " + offset() + "]"); break;
      case 2:
        if (in_loop && *rc::gen::inRange(0, 3) == 0) {  // leave or go on, under a condition
          line(o + " if [" + parameter() + " GT " + offset() + "]");
          line(std::string(in_loop_name_) + " " + (breaks_ ? *rc::gen::element("break", "continue") : "continue"));
          line(o + " endif");
        } else {
          line("o<shift> call [" + parameter() + "] [" + offset() + "]");
        }
        break;
      case 3: case 4: {
        line(o + " if [" + parameter() + " LT " + offset() + "]");
        statements(depth + 1, in_loop);
        if (*rc::gen::inRange(0, 2)) {
          line(o + " elseif [" + parameter() + " GE " + offset() + "]");
          statements(depth + 1, in_loop);
        }
        if (*rc::gen::inRange(0, 2)) {
          line(o + " else");
          statements(depth + 1, in_loop);
        }
        line(o + " endif");
        break;
      }
      default: loop(o, depth);
    }
  }

  std::string in_loop_name_ = "o0";

  void loop(const std::string& o, int depth) {
    const std::string counter = "#" + std::to_string(next_counter_++);
    const int runs = *rc::gen::inRange(0, 4);
    const std::string saved = in_loop_name_;
    in_loop_name_ = o;
    int kind = *rc::gen::inRange(0, 3);
    if (breaks_ && kind == 1) kind = 0;  // no do loop where a break may be drawn
    switch (kind) {
      case 0:
        line(counter + " = 0");
        line(o + " while [" + counter + " LT " + std::to_string(runs) + "]");
        line(counter + " = [" + counter + " + 1]");
        statements(depth + 1, true);
        line(o + " endwhile");
        break;
      case 1:
        line(counter + " = 0");
        line(o + " do");
        line(counter + " = [" + counter + " + 1]");
        statements(depth + 1, true);
        line(o + " while [" + counter + " LT " + std::to_string(runs) + "]");
        break;
      default:  // break and continue leave only while and do loops (rs274: "no matching while/do label")
        line(o + " repeat [" + std::to_string(runs) + "]");
        statements(depth + 1, false);
        line(o + " endrepeat");
    }
    in_loop_name_ = saved;
  }
};

std::string program_text() {
  program_gen g;
  g.text = "G21 G90 G94 G17\nF100\nG0 X0 Y0 Z0\n";
  for (int p = 31; p <= 33; ++p) g.text += "#" + std::to_string(p) + " = " + fixed3(*rc::gen::inRange(-9000, 9000)) + "\n";
  g.text +=
      "o<shift> sub\n"
      "G1 X[#1 + #31] Y[#2 - #32]\n"
      "o<shift_side> if [#1 GT #2]\n"
      "G1 Z#1\n"
      "o<shift_side> return\n"
      "o<shift_side> endif\n"
      "G0 Z[#2 * 2]\n"
      "o<shift> endsub\n";
  g.statements(0, false);
  g.text += "M2\n";
  return g.text;
}

struct kin5_move {
  bool rapid = false;
  double end[3] = {0, 0, 0};
};

}  // namespace

TEST_CASE("LinuxCNC control flow: kin5 executes what rs274 executes") {
  rc::prop("a generated program's moves end where rs274's do", [] {
    const std::string text = program_text();
    RC_LOG() << text;
    const read_result r = linuxcnc::read(text, "t.ngc");
    for (const diagnostic& d : r.errors) RC_LOG() << "kin5: " << d.where.line << ":" << d.where.column << ": " << d.message << "\n";
    RC_ASSERT(r.errors.empty());
    std::vector<kin5_move> ours;
    double at[3] = {0, 0, 0};
    bool rapid_mode = false;
    for (const block& b : r.parsed.blocks)
      for (const can::operation& op : can::operations_of(b)) {
        const axis_words* to = nullptr;
        if (const auto* m = std::get_if<can::rapid_move>(&op)) rapid_mode = true, to = &m->to;
        else if (const auto* m = std::get_if<can::linear_move>(&op)) rapid_mode = false, to = &m->to;
        else if (const auto* m = std::get_if<can::modal_move>(&op)) to = &m->to;
        RC_ASSERT(!std::holds_alternative<can::arc_move>(op) && !std::holds_alternative<can::machine_move>(op));
        if (!to || to->empty()) continue;
        if (to->x_mm) at[0] = *to->x_mm;
        if (to->y_mm) at[1] = *to->y_mm;
        if (to->z_mm) at[2] = *to->z_mm;
        kin5_move m;
        m.rapid = rapid_mode;
        for (int k = 0; k < 3; ++k) m.end[k] = at[k];
        ours.push_back(m);
      }
    const rs::run theirs = rs::run_program(text);
    RC_LOG() << "--- rs274:\n" << theirs.text << "\n";
    RC_ASSERT(theirs.status == 0);
    RC_ASSERT(theirs.moves.size() == ours.size());
    for (std::size_t k = 0; k < ours.size(); ++k) {
      RC_ASSERT((theirs.moves[k].kind == rs::move_kind::traverse) == ours[k].rapid);
      for (int a = 0; a < 3; ++a) RC_ASSERT(std::abs(theirs.moves[k].end[a] - ours[k].end[a]) <= 1e-9);
    }
  });
}
