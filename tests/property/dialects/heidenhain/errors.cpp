// Bad Heidenhain input: each case is an input text and the exact diagnostic it must produce.
// Columns are counted by hand (1-based bytes).
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/heidenhain/dialect.hpp>

#include "contract.hpp"

using namespace kin5::program;

namespace {
std::vector<std::string> errors_of(const std::string& text) {
  std::vector<std::string> out;
  for (const diagnostic& d : heidenhain::read(text, "t.h").errors) out.push_back(d.to_string());
  return out;
}
}  // namespace

/// The law "bad input gives exact diagnostics" (laws.cpp) reads each text and compares.
std::vector<kin5::test::bad_input> kin5::test::contract<heidenhain::dialect>::bad_inputs() {
  struct bad {
    std::string text, diagnostic;
  };
  const std::vector<bad> cases{
      {"L X+1 Y\n", "t.h:1:7: error: word 'Y' has no value"},
      // a rate the writer cannot write back with the TNC's 3 decimals
      {"L X+1 F0.0004\n", "t.h:1:7: error: the feed 0.0004 cannot be written with 3 decimals, the most the controller reads (it would read as 0)"},
      {"TOOL CALL 1 Z S0.0101\n", "t.h:1:15: error: the spindle speed 0.0101 cannot be written with 3 decimals, the most the controller reads (it would read as another value)"},
      {"5 L X+1 F\n", "t.h:1:9: error: word 'F' has no value"},
      {"L X+1 +5\n", "t.h:1:7: error: number without an address letter"},
      {"L X+1.2.3\n", "t.h:1:3: error: malformed number '+1.2.3'"},
      {"L X+ 5\n", "t.h:1:3: error: word 'X' has a malformed value"},
      {"L X+2000000000\n", "t.h:1:3: error: value out of range"},
      {"L X+1 Y-2 X+2\n", "t.h:1:11: error: axis 'X' given twice"},
      {"L X+Q1*2\n", "t.h:1:3: error: expressions and parameters in axis words are not supported"},
      {"L XQL1 Y+0\n", "t.h:1:3: error: expressions and parameters in axis words are not supported"},
      {"12 L Z=Q5\n", "t.h:1:6: error: expressions and parameters in axis words are not supported"},
      {"L IX+5 Y+0\n", "t.h:1:3: error: incremental positioning (IX) is not supported"},
      {"l ib-90\n", "t.h:1:3: error: incremental positioning (IB) is not supported"},
      {"L X+1\x01\n", "t.h:1:6: error: unexpected byte 0x01"},
      {"L X+1 \xC3\xA4\n", "t.h:1:7: error: unexpected byte 0xC3"},
      {"L X+1 FU0.1\n", "t.h:1:7: error: unknown word 'FU0.1'"},
      {"L X+1 M3.5\n", "t.h:1:7: error: word 'M' needs a whole number"},
      {"L X+5 FMAX F100\n", "t.h:1:1: error: F and FMAX in one block"},
      {"BEGIN PGM P INCH\n", "t.h:1:13: error: inch programs are not supported"},
      {"END PGM P inch\n", "t.h:1:11: error: inch programs are not supported"},
      {"BEGIN PGM\n", "t.h:1:1: error: BEGIN PGM needs a name and a unit"},
      {"PLANE SPATIAL SPA+0 SPB+45 SPC+0 STAY\n",
       "t.h:1:1: error: PLANE SPATIAL changes the working frame; kin5 does not model frame changes"},
      {"3 plane projected PROPR+0 PROMIN+30 ROT+0 MOVE\n",
       "t.h:1:3: error: PLANE PROJECTED changes the working frame; kin5 does not model frame changes"},
      {"CYCL DEF 19.1 A+0 B+45 C+0\n",
       "t.h:1:1: error: CYCL DEF 19 changes the working frame; kin5 does not model frame changes"},
      {"CYCL DEF 7.1 X+10\n", "t.h:1:1: error: CYCL DEF 7 changes the working frame; kin5 does not model frame changes"},
      {"CYCL DEF 10.1 ROT+30\n",
       "t.h:1:1: error: CYCL DEF 10 changes the working frame; kin5 does not model frame changes"},
      {"TRANS DATUM AXIS X+10\n",
       "t.h:1:1: error: TRANS DATUM changes the working frame; kin5 does not model frame changes"},
      {"FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n", "t.h:1:21: error: FUNCTION TCPM AXIS SPAT is not supported"},
      {"C X+1 Y+2 DR+\n", "t.h:1:1: error: arc C needs a circle centre (CC) before it"},
      {"CC X+0 Y+0\r\nC X+1 Y+0\r\n", "t.h:2:1: error: arc needs a direction (DR+ or DR-)"},
      {"CR X+1 Y+2 DR-\n", "t.h:1:1: error: CR needs a radius (R)"},
      {"CC X+1 Y+2 Z+3\n", "t.h:1:1: error: CC takes at most two coordinates"},
      {"CC X+1 F100\n", "t.h:1:8: error: unknown word 'F100'"},
      {"X+5 Y+2\n", "t.h:1:1: error: axis word 'X' without a motion keyword"},
      {"APPR LT X+10 Y+5 LEN15 RR F100\n", "t.h:1:1: error: 'APPR' is not supported"},
      {"7 RND R5\n", "t.h:1:3: error: 'RND' is not supported"},
      {"LP PR+10 PA+30\n", "t.h:1:1: error: 'LP' is not supported"},
      {"SHIFT X+5\n", "t.h:1:1: error: unknown keyword 'SHIFT' in a block with axis words"},
      {"M3 X+5\n", "t.h:1:4: error: axis word 'X' without a motion keyword"},
      {"M3 M8 IZ-2\n", "t.h:1:7: error: axis word 'IZ' without a motion keyword"},
      {"99999999999999999999 L X+1\n", "t.h:1:1: error: block number out of range"},
      {"CYCL DEF 7.0 DATUM SHIFT\n  cycl def 7.1  X+5\n",
       "t.h:2:3: error: CYCL DEF 7 changes the working frame; kin5 does not model frame changes"},
      {"CYCL DEF 7.0 DATUM SHIFT~\nX+0\x02\n", "t.h:2:4: error: unexpected byte 0x02"},
  };
  std::vector<bad_input> out;
  for (const bad& c : cases) out.push_back({c.text, {c.diagnostic}});
  return out;
}

TEST_CASE("heidenhain: reading goes on after an error and keeps every block") {
  const read_result r = heidenhain::read("1 L X+1 Y\n2 L X+2 Y+3\n3 L X+Q1*2\n", "t.h");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[0].to_string() == "t.h:1:9: error: word 'Y' has no value");
  CHECK(r.errors[1].to_string() == "t.h:3:5: error: expressions and parameters in axis words are not supported");
  REQUIRE(r.parsed.blocks.size() == 3);
  CHECK(r.parsed.blocks[1].axes.x_mm == 2.0);
  CHECK(r.parsed.blocks[1].axes.y_mm == 3.0);
  CHECK(r.parsed.blocks[0].axes.x_mm == 1.0);
}

TEST_CASE("heidenhain: resets and control bytes inside comments are not errors") {
  for (const char* text : {"PLANE RESET STAY\n", "CYCL DEF 19.0 WORKING PLANE\n", "CYCL DEF 19.1\n",
                           "CYCL DEF 19.1 A+0 B+0.000 C-0\n", "CYCL DEF 7.1 X+0 Y+0 Z+0\n", "TRANS DATUM RESET\n",
                           "L X+1 ;\x01 odd\n", "* - \x7F section\n", "FUNCTION RESET TCPM\n", "CYCL DEF 11.1 SCL1\n"}) {
    INFO(text);
    CHECK(errors_of(text).empty());
  }
}

TEST_CASE("heidenhain: CYCL DEF 247 selects the preset of its Q339, the block kept whole") {
  const read_result r = heidenhain::read("0 CYCL DEF 247 DATUM SETTING~\n  Q339=+1 ;DATUM NUMBER\n1 L Z+5\n", "t.h");
  CHECK(r.errors.empty());
  REQUIRE(r.parsed.blocks.size() == 2);
  CHECK_FALSE(r.parsed.blocks[0].passthrough);
  CHECK(r.parsed.blocks[0].state.work_offset == work_offset{work_offset_family::preset, 1});
  CHECK(r.parsed.blocks[0].text == "0 CYCL DEF 247 DATUM SETTING~\n  Q339=+1 ;DATUM NUMBER");
  CHECK(r.parsed.blocks[1].where.line == 3);
}

TEST_CASE("heidenhain: the writer names the block it cannot write") {
  program p;
  p.language = id_of<iso::dialect>();
  p.file = "part.nc";
  block b;
  b.where = {"part.nc", 12, 1};
  b.motion = motion_kind::linear;
  b.axes.x_mm = 1;
  b.metric = false;
  p.blocks.push_back(b);
  CHECK_THROWS_WITH(heidenhain::write(p), "part.nc:12: block cannot be written in heidenhain: inch units");
  p.blocks[0].metric.reset();
  p.blocks[0].feed_mode = feed_unit::inverse_time;
  CHECK_THROWS_WITH(heidenhain::write(p), "part.nc:12: block cannot be written in heidenhain: inverse-time feed (G93)");
  p.blocks[0].feed_mode.reset();
  p.blocks[0].motion = motion_kind::arc_cw;
  CHECK_THROWS_WITH(heidenhain::write(p), "part.nc:12: block cannot be written in heidenhain: arc has neither a centre nor a radius");
  p.blocks[0].arc = arc_words{arc_plane::zx, std::nullopt, 5.0};
  CHECK_THROWS_WITH(heidenhain::write(p), "part.nc:12: block cannot be written in heidenhain: radius arc outside the working plane");
  p.blocks[0].motion = motion_kind::rapid;
  p.blocks[0].arc.reset();
  p.blocks[0].feed = 100;
  CHECK_THROWS_WITH(heidenhain::write(p), "part.nc:12: block cannot be written in heidenhain: block has both a feed and rapid traverse");
  p.blocks[0].where = {};
  CHECK_THROWS_WITH(heidenhain::write(p), "part.nc: block 0: block cannot be written in heidenhain: block has both a feed and rapid traverse");
}
