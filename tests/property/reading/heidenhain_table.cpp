// Heidenhain spellings of real programs, text → model → text: `F MAX` (hyperMILL), `~` after a
// `;comment` (the TNC's own layout of cycle parameters), Q parameters used as word values; the
// parameter uses that are refused, each with its message; and the control flow a TNC runs
// (labels, subprogram calls, section repeats, FN 9 jumps), each program read as the same blocks
// as its unrolled twin.
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/heidenhain/dialect.hpp>

using namespace kin5::program;

namespace {
std::vector<std::string> errors_of(const std::string& text) {
  std::vector<std::string> out;
  for (const diagnostic& d : heidenhain::read(text, "t.h").errors) out.push_back(d.to_string());
  return out;
}

// Blocks equal apart from their text (the spelling differs by design).
void same_blocks(std::vector<block> a, std::vector<block> b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i].text = b[i].text = "";
    CHECK(a[i] == b[i]);
  }
}
}  // namespace

TEST_CASE("heidenhain: spellings read as their plain equivalent and written plain") {
  struct row {
    std::string spelled, plain;
  };
  const std::vector<row> rows = {
      {"L X+1 Y+2 R0 F MAX M3\n", "L X+1 Y+2 R0 FMAX M3\n"},
      {"L X+1 Y+2 R0 f  max\n", "L X+1 Y+2 R0 FMAX\n"},
      {"FN 0: Q1=+1131 ; XY FEED\nL X+10 FQ1\n", "FN 0: Q1=+1131 ; XY FEED\nL X+10 F1131\n"},
      {"FN 0:Q2=754\nL Z-5 F Q2\n", "FN 0:Q2=754\nL Z-5 F754\n"},
      {"Q3 = 25.5\nL X-Q3 Y+Q3 ZQ3 FMAX\n", "Q3 = 25.5\nL X-25.5 Y+25.5 Z+25.5 FMAX\n"},
      {"FN 0: Q1=5\nL X+Q1 F100\nFN 0: Q1=7\nL X+Q1\n", "FN 0: Q1=5\nL X+5 F100\nFN 0: Q1=7\nL X+7\n"},
      {"L X+1 ;first~\n  Y+2 F100 ;second\n", "L X+1 Y+2 F100 ;first second\n"},
      {"L X+1 FMAX\n* - NOTE~~\n", "L X+1 FMAX\n* - NOTE\n"},  // no `~` kept at a comment's end
      {"L X+1 FMAX\n* - NOTE ~ ~\n", "L X+1 FMAX\n* - NOTE\n"},
      {"L~\n\nL X+1 FMAX\n", "L\n\nL X+1 FMAX\n"},  // a move without coordinates, kept as a comment
      // two comments in one block, joined: the `*` text ends in `~` where the `;` comment began
      {"*~;x~\n", "*x\n"},
      {"L X+1 FMAX\n* a~ ;b~\n\n", "L X+1 FMAX\n*b  a\n"},
  };
  for (const row& r : rows) {
    INFO(r.spelled);
    const read_result spelled = heidenhain::read(r.spelled, "t.h");
    const read_result plain = heidenhain::read(r.plain, "t.h");
    REQUIRE(spelled.errors.empty());
    REQUIRE(plain.errors.empty());
    same_blocks(spelled.parsed.blocks, plain.parsed.blocks);
    CHECK(heidenhain::write(spelled.parsed) == heidenhain::write(plain.parsed));
  }
}

TEST_CASE("heidenhain: a block whose number follows a `~` line is written as one block") {
  // Written with the old number's line after the new number's `0 ~`, `14` read as a keyword.
  const read_result r = heidenhain::read("  ~\n14 Q1=2\n", "t.h");
  REQUIRE(r.errors.empty());
  const std::string written = heidenhain::write(r.parsed);
  INFO(written);
  CHECK(errors_of(written).empty());
  CHECK(written.find("14") == std::string::npos);
}

TEST_CASE("heidenhain: `~` lines before a passthrough's text stay when no number follows them") {
  // Dropped, the text read back would lack them (seed-1 fuzzing).
  const read_result r = heidenhain::read("~\n~\nBLK FORM 0.1 Z X+0 Y+0 Z-40\n", "t.h");
  REQUIRE(r.errors.empty());
  const std::string written = heidenhain::write(r.parsed);
  INFO(written);
  CHECK(errors_of(written).empty());
  CHECK(written.find("1 ~\n~\nBLK FORM 0.1 Z X+0 Y+0 Z-40\n") != std::string::npos);  // after BEGIN PGM
}

TEST_CASE("heidenhain: cycle parameters after `,comment~` stay in their cycle's block") {
  // The cycle itself is refused (tests/property/dialects/heidenhain/errors.txt), once, at its
  // first line: its parameter lines are part of its block, not blocks of their own.
  const std::string text =
      "CYCL DEF 200 DRILLING~\n"
      "  Q200=2 ;SET-UP CLEARANCE~\n"
      "  Q201=-20 ;DEPTH~\n"
      "  Q206=150 ;FEED RATE FOR PLNGNG\n"
      "L Z+5 FMAX\n";
  const read_result r = heidenhain::read(text, "t.h");
  REQUIRE(r.errors.size() == 1);
  CHECK(r.errors[0].where.line == 1);
  REQUIRE(r.parsed.blocks.size() == 2);
  CHECK(r.parsed.blocks[0].passthrough);
  CHECK(r.parsed.blocks[0].text == text.substr(0, text.find("\nL Z")));
  CHECK(r.parsed.blocks[1].where.line == 5);
  CHECK(heidenhain::write(r.parsed).find("Q206=150 ;FEED RATE FOR PLNGNG\n") != std::string::npos);
}

TEST_CASE("heidenhain: a word reads its Q parameter's value at the time the block runs") {
  struct row {
    std::string with_parameters, plain;
  };
  const std::vector<row> rows = {
      {"FN 1: Q1=+1+2\nL X+10 F Q1\n", "FN 1: Q1=+1+2\nL X+10 F3\n"},
      {"Q1 = 5 * 2\nL X+Q1\n", "Q1 = 5 * 2\nL X+10\n"},
      {"FN 0: Q2=4\nQ1 = SQRT Q2 + 2^3\nL X-Q1\n", "FN 0: Q2=4\nQ1 = SQRT Q2 + 2^3\nL X-10\n"},
      {"FN 0: Q1=3\nFN 8: Q2 = +Q1 LEN +4\nFN 13: Q3 = +0 ANG -Q1\nL X+Q2 C+Q3\n",
       "FN 0: Q1=3\nFN 8: Q2 = +Q1 LEN +4\nFN 13: Q3 = +0 ANG -Q1\nL X+5 C+270\n"},
      {"QL1 = 2.5\nQR2 = -QL1\nL XQL1 Y+QR2 Z-QR2\n", "QL1 = 2.5\nQR2 = -QL1\nL X+2.5 Y-2.5 Z+2.5\n"},
  };
  for (const row& r : rows) {
    INFO(r.with_parameters);
    const read_result with = heidenhain::read(r.with_parameters, "t.h");
    const read_result plain = heidenhain::read(r.plain, "t.h");
    REQUIRE(with.errors.empty());
    REQUIRE(plain.errors.empty());
    same_blocks(with.parsed.blocks, plain.parsed.blocks);
  }
}

TEST_CASE("heidenhain: Q parameters without a value are refused, naming why") {
  struct row {
    std::string text;
    std::vector<std::string> errors;
  };
  const std::vector<row> rows = {
      {"L X+10 FQ5\n", {"t.h:1:8: error: parameter Q5 is read before it is assigned: its value is the machine's"}},
      {"L X+Q1\nFN 0: Q1=5\n", {"t.h:1:3: error: parameter Q1 is read before it is assigned: its value is the machine's"}},
      // an assignment's error stops the run: what follows depends on the value
      {"FN 0: Q1=Q2\nL X+10 FQ1\n", {"t.h:1:10: error: parameter Q2 is read before it is assigned: its value is the machine's"}},
      {"FN 0: Q120=30\nL A+Q120 FMAX\n",
       {"t.h:1:7: error: parameter Q120 is set by the control (Q100-Q199), not a value of this program"}},
      {"L A+Q120 FMAX\n", {"t.h:1:3: error: parameter Q120 is set by the control (Q100-Q199), not a value of this program"}},
  };
  for (const row& r : rows) {
    INFO(r.text);
    CHECK(errors_of(r.text) == r.errors);
  }
}

namespace {
// The blocks a program runs, without their text and place (a twin's lines stand elsewhere).
std::vector<block> run_blocks(const std::string& text) {
  const read_result r = heidenhain::read(text, "t.h");
  std::string errors;
  for (const diagnostic& d : r.errors) errors += d.to_string() + "\n";
  INFO(text);
  CHECK(errors == "");
  std::vector<block> out = r.parsed.blocks;
  for (block& b : out) b.text.clear(), b.where = {}, b.call_chain = 0, b.comment.reset();
  return out;
}
}  // namespace

TEST_CASE("heidenhain: labels, calls, section repeats and jumps run as a TNC runs them") {
  struct row {
    std::string structured, unrolled;
  };
  const std::vector<row> rows = {
      // a section repeat runs its section once more per REP (TNC 640 User's Manual, "Program section repeats")
      {"L X+0 FMAX\nLBL 1\nL X+1 FMAX\nCALL LBL 1 REP 2\nL X+9 FMAX\n",
       "L X+0 FMAX\nL X+1 FMAX\nL X+1 FMAX\nL X+1 FMAX\nL X+9 FMAX\n"},
      // a subprogram after M30 runs where it is called, up to its LBL 0, and not after M30; END PGM is read
      {"BEGIN PGM P MM\nCALL LBL \"S\"\nL X+1 FMAX\nCALL LBL 2\nM30\nLBL \"S\"\nL X+5 FMAX\nLBL 0\nLBL 2\nL X+6 FMAX\nLBL 0\n"
       "END PGM P MM\n",
       "BEGIN PGM P MM\nL X+5 FMAX\nL X+1 FMAX\nL X+6 FMAX\nM30\nEND PGM P MM\n"},
      // a subprogram the flow runs into before M30 runs once, its LBL 0 doing nothing
      {"LBL 1\nL X+1 FMAX\nLBL 0\nCALL LBL 1\nM2\n", "L X+1 FMAX\nL X+1 FMAX\nM2\n"},
      // FN 9 to FN 12 jump when the comparison holds; a jump leaves a section repeat it skips out of
      {"FN 0: Q1=+2\nFN 9: IF +Q1 EQU +2 GOTO LBL 1\nL X+1 FMAX\nLBL 1\nFN 10: IF +Q1 NE +2 GOTO LBL 2\nL X+2 FMAX\n"
       "LBL 2\nFN 11: IF +Q1 GT +1 GOTO LBL 3\nL X+3 FMAX\nLBL 3\nFN 12: IF +Q1 LT +1 GOTO LBL 4\nL X+4 FMAX\nLBL 4\n",
       "FN 0: Q1=+2\nL X+2 FMAX\nL X+4 FMAX\n"},
      // a loop of a jump back, counting down: the values each pass reads
      {"FN 0: Q1=+3\nLBL \"TOP\"\nL X+Q1 FMAX\nFN 2: Q1 = +Q1 - +1\nFN 11: IF +Q1 GT +0 GOTO LBL \"TOP\"\nL X+0 FMAX\n",
       "FN 0: Q1=+3\nL X+3 FMAX\nFN 2: Q1 = +Q1 - +1\nL X+2 FMAX\nFN 2: Q1 = +Q1 - +1\nL X+1 FMAX\nFN 2: Q1 = +Q1 - +1\n"
       "L X+0 FMAX\n"},
      // a jump from a subprogram to another label, whose LBL 0 ends the call (hyperMILL's CuttingEdgesCheck)
      {"FN 0: Q1900=2\nCALL LBL \"CHECK\"\nL X+Q1901 FMAX\nM30\nLBL \"CHECK\"\nFN 9: IF +Q1900 EQU +1 GOTO LBL \"E1\"\n"
       "FN 9: IF +Q1900 EQU +2 GOTO LBL \"E2\"\nLBL 0\nLBL \"E1\"\nFN 0: Q1901=4\nLBL 0\nLBL \"E2\"\nFN 0: Q1901=3\nLBL 0\n",
       "FN 0: Q1900=2\nFN 0: Q1901=3\nL X+3 FMAX\nM30\n"},
      // a block continued with `~` after a call: its Q lines are the cycle's, not assignments
      {"LBL 1\nL X+1 FMAX\nLBL 0\nCALL LBL 1\nCYCL DEF 247 DATUM SETTING ~\n  Q339=+1 ;DATUM NUMBER\nM30\n",
       "L X+1 FMAX\nL X+1 FMAX\nCYCL DEF 247 DATUM SETTING ~\n  Q339=+1 ;DATUM NUMBER\nM30\n"},
  };
  for (const row& r : rows) {
    INFO(r.structured);
    CHECK(run_blocks(r.structured) == run_blocks(r.unrolled));
  }
}

TEST_CASE("heidenhain: a program that loops for ever stops at the bound on the lines run") {
  read_result r;
  heidenhain::read_blocks("LBL 1\nL X+1 FMAX\nFN 9: IF +0 EQU +0 GOTO LBL 1\n", "t.h", r, [](block&&) {},
                          interp::execution_limits{1000});
  REQUIRE(r.errors.size() == 1);
  CHECK(r.errors[0].to_string() ==
        "t.h:2:1: error: more than 1000 lines executed: a jump may repeat for ever (--max-executed-lines raises the bound)");
}

namespace {
// A structured program drawn at random, printed in Heidenhain's spelling, and run by the test
// itself into its unrolled twin: moves (literal or Q values, negated or not), assignments (FN 0,
// formulas), section repeats, calls of subprograms written after M30, FN 9 jumps over a part.
struct flow_program {
  explicit flow_program(unsigned seed) : random(seed) {}

  std::mt19937 random;
  std::map<int, long> q;  // the test's own values of Q1 to Q4, each assigned first
  std::vector<std::string> subprograms;
  int labels = 0;

  long draw(long low, long high) { return std::uniform_int_distribution<long>(low, high)(random); }
  static std::string signed_number(long v) { return (v < 0 ? "-" : "+") + std::to_string(v < 0 ? -v : v); }

  // Appends `count` items to `text` (structured) and what they run to `twin`.
  void items(int depth, int count, std::string& text, std::string& twin) {
    for (int i = 0; i < count; ++i) item(depth, text, twin);
  }

  void item(int depth, std::string& text, std::string& twin) {
    switch (draw(0, depth > 0 ? 2 : 5)) {
      case 0: {  // a move
        const long y = draw(-50, 50);
        if (draw(0, 1)) {
          const int k = static_cast<int>(draw(1, 4));
          const bool negated = draw(0, 1);
          text += "L X" + std::string(negated ? "-" : "+") + "Q" + std::to_string(k) + " Y" + signed_number(y) + " FMAX\n";
          twin += "L X" + signed_number(negated ? -q[k] : q[k]) + " Y" + signed_number(y) + " FMAX\n";
        } else {
          const long x = draw(-50, 50);
          text += "L X" + signed_number(x) + " Y" + signed_number(y) + " FMAX\n";
          twin += "L X" + signed_number(x) + " Y" + signed_number(y) + " FMAX\n";
        }
        break;
      }
      case 1: {  // an assignment: the same line in both, run in both
        const int k = static_cast<int>(draw(1, 4)), j = static_cast<int>(draw(1, 4));
        const long v = draw(-9, 9);
        std::string line;
        if (draw(0, 1)) {
          line = "Q" + std::to_string(k) + " = Q" + std::to_string(j) + " + " + std::to_string(v < 0 ? -v : v) + "\n";
          q[k] = q[j] + (v < 0 ? -v : v);
        } else {
          line = "FN 0: Q" + std::to_string(k) + " = " + signed_number(v) + "\n";
          q[k] = v;
        }
        text += line, twin += line;
        break;
      }
      case 2: {  // FN 9 over a part: the part runs when the comparison fails
        const int label = ++labels;
        const int k = static_cast<int>(draw(1, 4));
        const long against = draw(-3, 3);
        const bool taken = q[k] == against;
        text += "FN 9: IF +Q" + std::to_string(k) + " EQU " + signed_number(against) + " GOTO LBL " + std::to_string(label) + "\n";
        std::string skipped;
        const std::map<int, long> before = q;
        items(depth + 1, static_cast<int>(draw(1, 2)), text, skipped);
        if (taken) q = before;  // not run: the values stay
        else twin += skipped;
        text += "LBL " + std::to_string(label) + "\n";
        break;
      }
      case 3: {  // a section repeat
        const int label = ++labels;
        const long rep = draw(1, 3);
        text += "LBL " + std::to_string(label) + "\n";
        // The section's text once; its runs, each with the values of its pass.
        const std::size_t start = text.size();
        const std::mt19937 at_start = random;
        const int at_labels = labels;
        for (long pass = 0; pass <= rep; ++pass) {
          std::string section;
          random = at_start, labels = at_labels;  // the same section each pass
          items(depth + 1, static_cast<int>(draw(1, 3)), section, twin);
          if (pass == 0) text.insert(start, section);
        }
        text += "CALL LBL " + std::to_string(label) + " REP " + std::to_string(rep) + "\n";
        break;
      }
      default: {  // a call of a new subprogram, written after M30
        const std::string name = "\"SUB" + std::to_string(subprograms.size()) + "\"";
        std::string body;
        const std::size_t index = subprograms.size();
        subprograms.emplace_back();
        items(depth + 1, static_cast<int>(draw(1, 3)), body, twin);
        subprograms[index] = "LBL " + name + "\n" + body + "LBL 0\n";
        text += "CALL LBL " + name + "\n";
        break;
      }
    }
  }
};
}  // namespace

TEST_CASE("heidenhain: a structured program runs to the blocks of its unrolled twin") {
  rc::prop("labels, calls, repeats and jumps", [] {
    flow_program p(*rc::gen::arbitrary<unsigned>());
    std::string text = "BEGIN PGM P MM\n";
    for (int k = 1; k <= 4; ++k) text += "FN 0: Q" + std::to_string(k) + " = " + p.signed_number(p.q[k] = p.draw(-3, 3)) + "\n";
    std::string twin = text;
    p.items(0, static_cast<int>(p.draw(1, 8)), text, twin);
    text += "M30\n", twin += "M30\n";
    for (const std::string& s : p.subprograms) text += s;
    text += "END PGM P MM\n", twin += "END PGM P MM\n";
    RC_LOG() << text << "---\n" << twin;
    RC_ASSERT(run_blocks(text) == run_blocks(twin));
  });
}
