// Bad APT input: each case is an input text and the exact diagnostic it must produce.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/apt/dialect.hpp>

#include "contract.hpp"

using namespace kin5::program;

/// The law "bad input gives exact diagnostics" (laws.cpp) reads each text and compares.
std::vector<kin5::test::bad_input> kin5::test::contract<apt::dialect>::bad_inputs() {
  struct bad {
    std::string text, diagnostic;
  };
  const std::vector<bad> cases{
      {"GOTO/1,2\n", "t.cls:1:1: error: GOTO needs 3 or 6 values"},
      // a rate the writer cannot write back with its 6 decimals (7 for a feed in inches)
      {"SPINDL/0.0000004,CLW\n", "t.cls:1:8: error: the spindle speed 4e-07 cannot be written with 6 decimals, the most the controller reads (it would read as 0)"},
      {"FEDRAT/MMPM,0.0000101\n", "t.cls:1:13: error: the feed 1.01e-05 cannot be written with 6 decimals, the most the controller reads (it would read as another value)"},
      {"UNITS/INCHES\nFEDRAT/0.00000004\n", "t.cls:2:8: error: the feed 4e-08 cannot be written with 7 decimals, the most the controller reads (it would read as 0)"},
      {"GOTO/1,2,3,4\n", "t.cls:1:1: error: GOTO needs 3 or 6 values"},
      {"GOTO\n", "t.cls:1:1: error: GOTO needs 3 or 6 values"},
      {"  goto/1,2,3,0,0\n", "t.cls:1:3: error: GOTO needs 3 or 6 values"},
      {"GOTO/1,X,3\n", "t.cls:1:8: error: 'X' is not a number"},
      {"GOTO/1,2,1E5\n", "t.cls:1:10: error: malformed number '1E5'"},
      {"GOTO/1.2.3,2,3\n", "t.cls:1:6: error: malformed number '1.2.3'"},
      {"GOTO/1, - 2,3\n", "t.cls:1:9: error: '- 2' is not a number"},
      {"GOTO/1,,3\n", "t.cls:1:8: error: GOTO value is missing"},
      {"GOTO/1,2,2000000000\n", "t.cls:1:10: error: value out of range"},
      {"GOTO/1,2\x01,3\n", "t.cls:1:9: error: unexpected byte 0x01"},
      {"FEDRAT/MMPR,0.1\n", "t.cls:1:8: error: feed per revolution is not supported"},
      {"FEDRAT/\n", "t.cls:1:1: error: FEDRAT needs a feed value"},
      {"SPINDL/SMM,200\n", "t.cls:1:8: error: constant surface speed is not supported"},
      {"LOADTL/2.5\n", "t.cls:1:8: error: tool number must be a whole number"},
      {"RAPID/5\n", "t.cls:1:7: error: unexpected '5' after RAPID"},
      // Found by apt_fuzz: a '$' kept inside free text came back as a continuation.
      {"PARTNO A$B\n", "t.cls:1:9: error: '$' in PARTNO text is ambiguous (continuation or comment in APT)"},
      {"PARTNO\f\f$\f\f$\f$ $$ c\n", "t.cls:1:9: error: '$' in PARTNO text is ambiguous (continuation or comment in APT)"},
      {"PPRINT/cost $5\n", "t.cls:1:13: error: '$' in PPRINT text is ambiguous (continuation or comment in APT)"},
      {"CIRCLE/0,0,0,0,0,1,5\n", "t.cls:1:1: error: circular CL data (CIRCLE) is not supported"},
      {"GOTO/1,$\r\n 2, Q\r\n", "t.cls:2:5: error: 'Q' is not a number"},
  };
  std::vector<bad_input> out;
  for (const bad& c : cases) out.push_back({c.text, {c.diagnostic}});
  return out;
}

TEST_CASE("apt: reading goes on after an error and keeps every statement") {
  const read_result r = apt::read("GOTO/1,2\nGOTO/0,0,0\nGOTO/Z,0,0\n", "t.cls");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[0].to_string() == "t.cls:1:1: error: GOTO needs 3 or 6 values");
  CHECK(r.errors[1].to_string() == "t.cls:3:6: error: 'Z' is not a number");
  CHECK(r.parsed.blocks.size() == 3);
  CHECK(r.parsed.blocks[1].axes.x_mm == 0.0);
}

TEST_CASE("apt: the writer names the block it cannot write") {
  program p;
  p.language = id_of<apt::dialect>();
  block b;
  b.where = {"part.cls", 12, 1};
  b.motion = motion_kind::linear;
  b.axes.x_mm = 1, b.axes.y_mm = 2, b.axes.z_mm = 3, b.axes.b_deg = 30;
  p.blocks.push_back(b);
  CHECK_THROWS_WITH(apt::write(p), "part.cls:12: block cannot be written in APT: rotary axis words (A, B, C) have no APT form");
  p.blocks[0].axes.b_deg.reset();
  p.blocks[0].axes.z_mm.reset();
  CHECK_THROWS_WITH(apt::write(p), "part.cls:12: block cannot be written in APT: GOTO needs x, y and z");
  p.blocks[0].axes.z_mm = 3;
  p.blocks[0].motion = motion_kind::arc_cw;
  CHECK_THROWS_AS(apt::write(p), std::invalid_argument);
}
