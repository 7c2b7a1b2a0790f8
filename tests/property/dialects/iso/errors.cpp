// Bad ISO input: each case is an input text and the exact diagnostic it must produce.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/iso/dialect.hpp>

#include "contract.hpp"

using namespace kin5::program;

/// The law "bad input gives exact diagnostics" (laws.cpp) reads each text and compares.
std::vector<kin5::test::bad_input> kin5::test::contract<iso::dialect>::bad_inputs() {
  struct bad {
    std::string text, diagnostic;
  };
  const std::vector<bad> cases{
      {"G1 X\n", "t.nc:1:4: error: word 'X' has no value"},
      // a rate the writer cannot write back with the controller's 3 decimals (4 for an inch feed)
      {"S.0101\n", "t.nc:1:1: error: the spindle speed 0.0101 cannot be written with 3 decimals, the most the controller reads (it would read as another value)"},
      {"G1 X1. F.0004\n", "t.nc:1:8: error: the feed 0.0004 cannot be written with 3 decimals, the most the controller reads (it would read as 0)"},
      {"G20\nG1 X1. F.00004\n", "t.nc:2:8: error: the feed 4e-05 cannot be written with 4 decimals, the most the controller reads (it would read as 0)"},
      {"G1 X- 5\n", "t.nc:1:4: error: word 'X' has no value"},
      {"G1 10\n", "t.nc:1:4: error: number with no address letter"},
      {"G1 X2000000000\n", "t.nc:1:4: error: value out of range"},
      {"G1 X1.2.3\n", "t.nc:1:4: error: malformed number '1.2.3'"},
      {"G1 X10 U5\n", "t.nc:1:8: error: unknown word 'U5'"},
      {"G1 X1\x01\n", "t.nc:1:6: error: unexpected byte 0x01"},
      {"G1 X1 $\n", "t.nc:1:7: error: unexpected character '$'"},
      {"G1 X1 X2\n", "t.nc:1:7: error: word 'X' appears twice"},
      {"G1 X#1\n", "t.nc:1:4: error: expressions and parameters in axis words are not supported"},
      {"G1 Y [1+2]\n", "t.nc:1:4: error: expressions and parameters in axis words are not supported"},
      {"#100=5\n", "t.nc:1:1: error: expressions and parameters are not supported"},
      {"  G91 G1 X10\n", "t.nc:1:3: error: incremental positioning (G91) is not supported"},
      {"G21\nG1 X1.\nG20\n", "t.nc:3:1: error: G20 after motion: a unit change inside a program is not supported"},
      {"G95 F0.1\n", "t.nc:1:1: error: feed per revolution (G95) is not supported"},
      {"G68.2 X0 Y0 Z0 I0 J45 K0\n", "t.nc:1:1: error: G68.2 changes the working frame; kin5 does not model frame changes"},
      {"G68 X0 Y0 R30\n", "t.nc:1:1: error: G68 changes the working frame; kin5 does not model frame changes"},
      {"G51 X0 Y0 P2\n", "t.nc:1:1: error: G51 changes the working frame; kin5 does not model frame changes"},
      {"G52 X10\n", "t.nc:1:1: error: G52 changes the working frame; kin5 does not model frame changes"},
      {"G81 X0 Y0 Z-5 R2 F100\n", "t.nc:1:1: error: canned cycle G81 is not supported"},
      {"G0 X0 Y0 Z0\nG2 X10 Y0\n", "t.nc:2:1: error: arc needs I, J, K or R"},
      {"G2 X10 I5\n", "t.nc:1:8: error: arc centre needs a known start point"},
      {"G0 X0 Y0 Z0\nG17 G2 X1 Y1 I1 K1\n", "t.nc:2:17: error: word 'K' is not in the arc plane"},
      {"G1 X1 I0.5\n", "t.nc:1:7: error: word 'I' needs G2, G3 or G43.5"},
      {"G43.5 H1\nG1 X1 I0 J1\n", "t.nc:2:7: error: tool-axis vector needs I, J and K"},
      {"G1 X1 (open\n", "t.nc:1:7: error: comment is not closed"},
      {"G0 G1 X1\n", "t.nc:1:4: error: two motion words in one block"},
      {"T1.5 M6\n", "t.nc:1:1: error: tool number must be a whole number"},
      {"/G1 X1\n", "t.nc:1:1: error: block delete (/) is not supported"},
      {"o100 sub\n", "t.nc:1:1: error: o-word control flow is not supported"},
  };
  std::vector<bad_input> out;
  for (const bad& c : cases) out.push_back({c.text, {c.diagnostic}});
  return out;
}

TEST_CASE("iso: reading goes on after an error and keeps every line") {
  const read_result r = iso::read("G95\nG1 X1\nG1 Y\n", "t.nc");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[0].to_string() == "t.nc:1:1: error: feed per revolution (G95) is not supported");
  CHECK(r.errors[1].to_string() == "t.nc:3:4: error: word 'Y' has no value");
  REQUIRE(r.parsed.blocks.size() == 3);
  CHECK(r.parsed.blocks[1].axes.x_mm == 1.0);
}

TEST_CASE("iso: harmless words and resets are not errors") {
  const read_result r = iso::read("G52 X0 Y0\nG69\nG50\nG49\nG90\nG10 L2 P1 X5\n", "t.nc");
  // G10 (offsets set from the program) is refused; the others read fine.
  REQUIRE(r.errors.size() == 1);
  CHECK(r.errors[0].to_string() ==
        "t.nc:6:1: error: G10: setting offsets from the program is not supported (later moves would use other offsets)");
  CHECK(r.parsed.blocks[0].kept_words == std::vector<std::string>{"G52", "X0", "Y0"});
  CHECK(!r.parsed.blocks[0].moves());
}

TEST_CASE("iso: the writer names the block it cannot write") {
  program p;
  p.language = id_of<iso::dialect>();
  block b;
  b.where = {"part.nc", 3, 1};
  b.motion = motion_kind::linear;
  b.axes.x_mm = 1;
  b.axes.tool_axis = kin5::vec3{0, 0, 1};
  p.blocks.push_back(b);
  CHECK_THROWS_WITH(iso::write(p), "part.nc:3: block cannot be written in ISO: a tool-axis vector needs G43.5");
}
