// Siemens control flow under the interpreter (statements.hpp, reader.hpp): a structured program
// drawn at random, in 840D spelling, reads to the same blocks as its twin unrolled by this test
// (not by kin5): loops, branches, jumps and section repeats written out, every parameter's value
// put in by hand. Then examples of each construct and its refusals.
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <kin5/kin5.hpp>
#include <kin5/program/io.hpp>
#include <kin5/program/siemens/dialect.hpp>

namespace {

using namespace kin5::program;

/// A statement of the drawn program.
struct node {
  enum kind_t { move, for_loop, while_loop, repeat_until, endless, branch, skip, section } kind = move;
  int k = 0;   // move: its offset; loops: runs; branch: taken when odd; section: repeats
  int id = 0;  // its label's number
  std::vector<node> body{}, other{};  // other: the ELSE branch
};

rc::Gen<std::vector<node>> draw_body(int depth);

rc::Gen<node> draw_node(int depth) {
  const auto move = rc::gen::map(rc::gen::inRange(0, 50), [](int k) { return node{node::move, k}; });
  if (depth >= 3) return move;
  return rc::gen::oneOf(
      move, rc::gen::apply(
                [](int kind, int runs, std::vector<node> body, std::vector<node> other) {
                  return node{static_cast<node::kind_t>(kind), runs, 0, std::move(body), std::move(other)};
                },
                rc::gen::inRange(1, 8), rc::gen::inRange(1, 4), draw_body(depth + 1), draw_body(depth + 1)));
}

rc::Gen<std::vector<node>> draw_body(int depth) {
  return rc::gen::mapcat(rc::gen::inRange(1, 4),
                         [depth](int n) { return rc::gen::container<std::vector<node>>(n, draw_node(depth)); });
}

void number(std::vector<node>& nodes, int& next) {
  for (node& n : nodes) {
    n.id = next++;
    number(n.body, next);
    number(n.other, next);
  }
}

std::string counter(int depth) { return "R" + std::to_string(10 + depth); }
std::string label(const node& n) { return "LB" + std::to_string(n.id); }
std::string runs(const node& n) { return std::to_string(n.k); }

/// The program in 840D spelling; `open`: the depths of the loops around it.
std::string structured(const std::vector<node>& nodes, int depth, std::vector<int> open) {
  std::string s;
  for (const node& n : nodes) {
    const std::string r = counter(depth);
    std::vector<int> inner = open;
    inner.push_back(depth);
    switch (n.kind) {
      case node::move: {
        s += "G1 X=";
        for (int d : open) s += counter(d) + "+";
        s += std::to_string(n.k) + " Y" + std::to_string(n.k) + " F100\n";
        break;
      }
      case node::for_loop: s += "FOR " + r + "=1 TO " + runs(n) + "\n" + structured(n.body, depth + 1, inner) + "ENDFOR\n"; break;
      case node::while_loop:
        s += r + "=0\nWHILE " + r + "<" + runs(n) + "\n" + r + "=" + r + "+1\n" + structured(n.body, depth + 1, inner) +
             "ENDWHILE\n";
        break;
      case node::repeat_until:
        s += r + "=0\nREPEAT ; until\n" + r + "=" + r + "+1\n" + structured(n.body, depth + 1, inner) + "UNTIL " + r +
             ">=" + runs(n) + "\n";
        break;
      case node::endless:
        s += r + "=0\nLOOP\n" + r + "=" + r + "+1\n" + structured(n.body, depth + 1, inner) + "IF " + r + ">=" + runs(n) +
             " GOTOF " + label(n) + "\nENDLOOP\n" + label(n) + ":\n";
        break;
      case node::branch:
        s += std::string("IF ") + (n.k % 2 == 1 ? "2>1" : "1>2") + "\n" + structured(n.body, depth + 1, open) + "ELSE\n" +
             structured(n.other, depth + 1, open) + "ENDIF\n";
        break;
      case node::skip: s += "GOTOF " + label(n) + "\n" + structured(n.body, depth + 1, open) + label(n) + ":\n"; break;
      case node::section:
        s += label(n) + ":\n" + structured(n.body, depth + 1, open) + "REPEAT " + label(n) + " P=" + runs(n) + "\n";
        break;
    }
  }
  return s;
}

/// The same program run by hand: every loop and repeat written out, each value a number.
void unrolled(const std::vector<node>& nodes, int depth, std::map<int, int> values, std::string& s) {
  for (const node& n : nodes) {
    const std::string r = counter(depth);
    switch (n.kind) {
      case node::move: {
        int x = n.k;
        for (const auto& [d, v] : values) x += v;
        s += "G1 X" + std::to_string(x) + " Y" + std::to_string(n.k) + " F100\n";
        break;
      }
      case node::for_loop:
        for (int i = 1; i <= n.k; ++i) {
          values[depth] = i;
          unrolled(n.body, depth + 1, values, s);
        }
        values.erase(depth);
        break;
      case node::while_loop:
      case node::repeat_until:
      case node::endless:
        s += r + "=0\n";
        for (int i = 1; i <= n.k; ++i) {
          s += r + "=" + std::to_string(i) + "\n";
          values[depth] = i;
          unrolled(n.body, depth + 1, values, s);
        }
        values.erase(depth);
        if (n.kind == node::endless) s += label(n) + ":\n";
        break;
      case node::branch: unrolled(n.k % 2 == 1 ? n.body : n.other, depth + 1, values, s); break;
      case node::skip: s += label(n) + ":\n"; break;
      case node::section:
        for (int i = 0; i <= n.k; ++i) {
          s += label(n) + ":\n";
          unrolled(n.body, depth + 1, values, s);
        }
        break;
    }
  }
}

/// The blocks as the comparison sees them: no place, and the text only of what passes through.
std::vector<block> compared(std::vector<block> blocks) {
  for (block& b : blocks) {
    b.where = {};
    b.call_chain = 0;  // where it was called from: the twin has no calls
    if (!b.passthrough) b.text.clear();
  }
  return blocks;
}

read_result read_ok(std::string_view text) {
  read_result r = siemens::read(text, "q.mpf");
  for (const auto& e : r.errors) UNSCOPED_INFO(e.to_string());
  REQUIRE(r.ok());
  return r;
}

std::string errors_of(std::string_view text, std::uint64_t max_lines = 100'000'000) {
  read_limits limits;
  limits.max_executed_lines = max_lines;
  const read_result r = read(id_of<siemens::dialect>(), text, "q.mpf", limits);
  std::string out;
  for (const auto& e : r.errors) out += e.to_string() + "\n";
  return out;
}

std::string plain(double v) { return siemens::detail::plain_number_text(v); }

std::vector<std::string> texts(const read_result& r) {
  std::vector<std::string> out;
  for (const block& b : r.parsed.blocks) out.push_back(b.text);
  return out;
}

}  // namespace

TEST_CASE("siemens control flow: a structured program reads as its unrolled twin", "[siemens][flow]") {
  rc::prop("loops, IF, GOTOF, LOOP and REPEAT sections run as written out by hand", [] {
    std::vector<node> program = *draw_body(0);
    int next = 0;
    number(program, next);
    const std::string source = "TRAORI\n" + structured(program, 0, {}) + "M30\n";
    std::string twin = "TRAORI\n";
    unrolled(program, 0, {}, twin);
    twin += "M30\n";
    RC_LOG() << source << "----\n" << twin;
    const read_result a = siemens::read(source, "a.mpf");
    const read_result b = siemens::read(twin, "b.mpf");
    for (const auto& e : a.errors) RC_LOG() << e.to_string() << "\n";
    RC_ASSERT(a.ok());
    RC_ASSERT(b.ok());
    RC_ASSERT(compared(a.parsed.blocks) == compared(b.parsed.blocks));
    // The executed program reads back alone, to the same blocks.
    const read_result back = siemens::read(siemens::write(a.parsed), "back.mpf");
    RC_ASSERT(back.ok());
    RC_ASSERT(compared(back.parsed.blocks) == compared(a.parsed.blocks));
  });
}

TEST_CASE("siemens control flow: each construct", "[siemens][flow]") {
  // R parameters and variables with expressions; the assignment's text gets its value.
  const auto r = read_ok("DEF REAL _D=2*3, _E\nDEF INT NN=4\nR1=_D/4+NN\nG1 X=R1*2 Y=-_D Z=SIN(90)*2 F=R1*100\n");
  CHECK(texts(r)[2] == "R1=5.5");
  CHECK(r.parsed.blocks[3].axes.x_mm == 11);
  CHECK(r.parsed.blocks[3].axes.y_mm == -6);
  CHECK(r.parsed.blocks[3].axes.z_mm == 2);
  CHECK(r.parsed.blocks[3].feed == 550);
  // Labels and block numbers as jump targets; GOTOC goes on when the label is missing.
  CHECK(texts(read_ok("N10 GOTOF N30\nN20 G1 X1\nN30 G1 X2\n")) == std::vector<std::string>{"N30 G1 X2"});
  CHECK(texts(read_ok("GOTOC NOWHERE\nG1 X1\n")) == std::vector<std::string>{"G1 X1"});
  CHECK(texts(read_ok("R1=0\nN5 TOP: R1=R1+1\nIF R1<3 GOTOB TOP\n")) ==
        std::vector<std::string>{"R1=0", "N5 TOP: R1=1", "N5 TOP: R1=2", "N5 TOP: R1=3"});
  CHECK(texts(read_ok("MARK: G1 X5\n"))[0] == "MARK: G1 X5");
  CHECK(read_ok("MARK: G1 X5\n").parsed.blocks[0].axes.x_mm == 5);
  // REPEATB: one block; REPEAT a b: a section after the end, as 840D programs keep them.
  CHECK(texts(read_ok("PA: G1 X1\nREPEATB PA P=2\nM30\n")) == std::vector<std::string>{"PA: G1 X1", "PA: G1 X1", "PA: G1 X1", "M30"});
  CHECK(texts(read_ok("G1 X0\nREPEAT SEC SEC_END P=2\nM30\nSEC:\nG1 X9\nSEC_END:\nG1 X7\n")) ==
        std::vector<std::string>{"G1 X0", "G1 X9", "G1 X9", "M30", "SEC:", "G1 X9", "SEC_END:", "G1 X7"});
  // A label alone makes no block (it was passed through, "not understood"); a comment after it stays.
  const auto labels = read_ok("GOTOF END\nG1 X1\nEND:\nN40 LB1:\nLB2: ; note\nM30\n");
  CHECK(texts(labels) == std::vector<std::string>{"LB2: ; note", "M30"});
  CHECK(labels.parsed.blocks[0].comment == "note");
  CHECK(!labels.parsed.blocks[0].passthrough);
  // A label alone is still a line: REPEATB runs it (nothing), not the lines after it.
  CHECK(texts(read_ok("PA:\nG1 X1\nREPEATB PA P=2\nG1 X3\nM30\n")) == std::vector<std::string>{"G1 X1", "G1 X3", "M30"});
  // After the end, the section is kept as text: never read, never run.
  CHECK(read_ok("M30\nSEC:\nG1 X=R99\n").parsed.blocks[2].passthrough);
  // The end as the word reader reads it, a blank or a sign before its value (it ran on before).
  CHECK(read_ok("M 30\nSEC:\nG1 X=R99\n").parsed.blocks[2].passthrough);
  CHECK(read_ok("N10 M+02\nSEC:\nG1 X=R99\n").parsed.blocks[2].passthrough);
  // A FOR counter after the loop; a loop that never ends stops at the bound.
  CHECK(texts(read_ok("FOR R1=1 TO 2\nENDFOR\nR2=R1\n")).back() == "R2=3");
  CHECK(errors_of("LOOP\nG1 X1\nENDLOOP\n", 1000) ==
        "q.mpf:3:1: error: more than 1000 lines executed: the loop at line 1 may never end (--max-executed-lines "
        "raises the bound)\n");
}

TEST_CASE("siemens control flow: refusals name the construct", "[siemens][flow]") {
  CHECK(errors_of("GOTOF END\n") == "q.mpf:1:1: error: jump to END: no such label after this line\n");
  CHECK(errors_of("IF $AA_IM[X]>5 GOTOF L1\nL1:\n") ==
        "q.mpf:1:4: error: system variable $AA_IM is the machine's state, not fixed by the program\n");
  CHECK(errors_of("G1 X=R7\n") == "q.mpf:1:6: error: parameter R7 is read before it is assigned: its value is the machine's\n");
  CHECK(errors_of("RET\n") ==
        "q.mpf:1:1: error: RET: the end of a subprogram, in the main program (M30, M2 or M17 end it)\n");
  CHECK(errors_of("WHILE 1\nG1 X1\n") == "q.mpf:1:1: error: a loop without its end\n");
  CHECK(errors_of("IF 1 G1 X1\n").find("IF: expected a jump") != std::string::npos);
  CHECK(errors_of("ENDLABEL:\n").find("ENDLABEL") != std::string::npos);
  CHECK(errors_of("DEF INT NN=2.5\n") == "q.mpf:1:12: error: variable NN is an INT: 2.5 is not a whole number\n");
  CHECK(errors_of("R1=1/0\n").find("q.mpf:1:") == 0);
}

TEST_CASE("siemens control flow: a CAM-style program with R parameters and a GOTOF loop translates as "
          "its unrolled twin", "[siemens][flow]") {
  using namespace kin5;
  using From = machines::sajo_12000p;
  using To = machines::dmu_80p;
  // Z levels stepped down in R parameters, a backward jump per level, the tool tilted by A and B.
  const std::string cam =
      "%_N_LEVELS_MPF\n"
      "N10 DEF REAL _DZ=-1.5, _FEED=800\n"
      "N20 R1=2 R2=0\n"
      "N30 TRAORI\n"
      "N40 G0 X0 Y0 Z50 A-20 B10\n"
      "N50 LEVEL: R2=R2+1\n"
      "N60 G1 X=10*R2 Y=5 Z=R1+R2*_DZ A=-20-R2*5 B=10+R2*2 F=_FEED\n"
      "N70 G1 X=10*R2+20 Y=-5 A=-20-R2*5 B=15+R2*2\n"
      "N80 IF R2<3 GOTOB LEVEL\n"
      "N90 TRAFOOF\n"
      "N100 M30\n";
  std::string twin = "%_N_LEVELS_MPF\nN10 DEF REAL _DZ=-1.5, _FEED=800\nN20 R1=2 R2=0\nN30 TRAORI\nN40 G0 X0 Y0 Z50 A-20 B10\n";
  for (int k = 1; k <= 3; ++k) {
    twin += "N50 LEVEL: R2=" + std::to_string(k) + "\n";
    twin += "N60 G1 X" + std::to_string(10 * k) + " Y5 Z" + plain(2 - 1.5 * k) + " A" + std::to_string(-20 - 5 * k) +
            " B" + std::to_string(10 + 2 * k) + " F800\n";
    twin += "N70 G1 X" + std::to_string(10 * k + 20) + " Y-5 A" + std::to_string(-20 - 5 * k) + " B" +
            std::to_string(15 + 2 * k) + "\n";
  }
  twin += "N90 TRAFOOF\nN100 M30\n";
  const read_result source = read_ok(cam);
  const auto t = translate<From, To>(source.parsed);
  for (const auto& e : t.errors) UNSCOPED_INFO(e.to_string());
  REQUIRE(t.ok());
  const auto u = translate<From, To>(read_ok(twin).parsed);
  REQUIRE(u.ok());
  CHECK(siemens::write(t.output) == siemens::write(u.output));
  // Each target block's tool axis is the source block's, mapped through the setup.
  const rigid_transform d_T_s = default_setup<From, To>();
  std::vector<const block*> in, out;
  for (const block& b : source.parsed.blocks)
    if (b.axes.a_deg) in.push_back(&b);
  for (const block& b : t.output.blocks)
    if (b.axes.b_deg || b.axes.c_deg) out.push_back(&b);
  REQUIRE(in.size() == 7);
  REQUIRE(out.size() == in.size());
  for (std::size_t k = 0; k < in.size(); ++k) {
    const vec3 u_s = tool_axis<From>({to_radians(degrees{*in[k]->axes.b_deg}), to_radians(degrees{*in[k]->axes.a_deg})});
    const vec3 u_t = tool_axis<To>({to_radians(degrees{out[k]->axes.c_deg.value_or(0)}), to_radians(degrees{*out[k]->axes.b_deg})});
    CHECK(angle_between(d_T_s.map_direction(u_s), u_t).value < 1e-5);
  }
}
