// Heidenhain spellings of real programs, text → model → text: `F MAX` (hyperMILL), `~` after a
// `;comment` (the TNC's own layout of cycle parameters), Q parameters assigned a number and used
// as word values; and the parameter uses that are refused, each with its message.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

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

TEST_CASE("heidenhain: Q parameters that are not constants of the file are refused at the word") {
  struct row {
    std::string text;
    std::vector<std::string> errors;
  };
  const std::vector<row> rows = {
      {"L X+10 FQ5\n", {"t.h:1:8: error: parameter Q5 is not assigned earlier in this file: its value is the machine's"}},
      {"L X+Q1\nFN 0: Q1=5\n", {"t.h:1:3: error: parameter Q1 is not assigned earlier in this file: its value is the machine's"}},
      {"FN 0: Q1=Q2\nL X+10 FQ1\n", {"t.h:2:8: error: parameter Q1 is computed at line 1; only a parameter assigned a number is read"}},
      {"FN 1: Q1=+1+2\nL X+10 F Q1\n", {"t.h:2:8: error: parameter Q1 is computed at line 1; only a parameter assigned a number is read"}},
      {"Q1 = 5 * 2\nL X+Q1\n", {"t.h:2:3: error: parameter Q1 is computed at line 1; only a parameter assigned a number is read"}},
      {"FN 0: Q120=30\nL A+Q120 FMAX\n", {"t.h:2:3: error: parameter Q120 is set by the control (Q100-Q199), not a constant of this file"}},
      // The labels, calls and jumps are refused too (tests/property/dialects/heidenhain/errors.txt), each at its line.
      {"FN 0: Q1=5\nL X+Q1\nCALL LBL 1\nLBL 1\nLBL 0\n",
       {"t.h:2:3: error: parameter Q1 in a program with control flow (CALL LBL at line 3): its value depends on the path",
        "t.h:3:1: error: CALL LBL: program and label calls are not supported (the motion they make would be lost)",
        "t.h:4:1: error: LBL: labels are not supported (the path would depend on the calls and repeats)",
        "t.h:5:1: error: LBL: labels are not supported (the path would depend on the calls and repeats)"}},
      {"FN 0: Q1=5\nFN 9: IF +Q1 EQU +5 GOTO LBL 1\nL X+Q1\n",
       {"t.h:2:1: error: FN: functions other than FN 0 (a constant) and FN 14 (an error) are not supported",
        "t.h:3:3: error: parameter Q1 in a program with control flow (FN 9 at line 2): its value depends on the path"}},
  };
  for (const row& r : rows) {
    INFO(r.text);
    CHECK(errors_of(r.text) == r.errors);
  }
}
