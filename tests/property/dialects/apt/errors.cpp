// APT input beyond its bad-input table (errors.txt, read by the dialect laws): reading goes on
// after an error, a tool change, what the writer refuses.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/apt/dialect.hpp>

using namespace kin5::program;

TEST_CASE("apt: reading goes on after an error and keeps every statement") {
  const read_result r = apt::read("GOTO/1,2\nGOTO/0,0,0\nGOTO/Z,0,0\n", "t.cls");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[0].to_string() == "t.cls:1:1: error: GOTO needs 3 or 6 values");
  CHECK(r.errors[1].to_string() == "t.cls:3:6: error: 'Z' is not a number");
  CHECK(r.parsed.blocks.size() == 3);
  CHECK(r.parsed.blocks[1].axes.x_mm == 0.0);
}

TEST_CASE("apt: LOAD/TOOL and LOADTL are a tool change, SELECT/TOOL a selection; what only describes passes through") {
  const read_result r = apt::read("LOAD/TOOL,12\nloadtl / 3\nSELECT/TOOL,6\nCUTTER/6,0,3\nmultax/ on\n", "t.cls");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 5);
  CHECK((b[0].tool == 12 && b[0].m_codes == std::vector<int>{6} && !b[0].passthrough));
  CHECK((b[1].tool == 3 && b[1].m_codes == std::vector<int>{6}));
  CHECK((b[2].tool == 6 && b[2].m_codes.empty() && !b[2].passthrough));  // a tool made ready, as ISO's T6 alone
  CHECK(b[3].passthrough);
  CHECK((b[4].kept_words == std::vector<std::string>{"MULTAX/ON"} && !b[4].passthrough));
  // Written back in APT the change is LOADTL; in ISO it is T n M6.
  CHECK(apt::write(r.parsed) == "LOADTL/12\nLOADTL/3\nSELECT/TOOL,6\nCUTTER/6,0,3\nMULTAX/ON\n");
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
