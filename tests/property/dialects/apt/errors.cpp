// APT input beyond its bad-input table (errors.txt, read by the dialect laws): reading goes on
// after an error, a tool change, what the writer refuses (arcs CIRCLE cannot say, and every
// construct of another dialect that has no APT form: never a `$$` comment in its place).
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/dialect.hpp>

using namespace kin5::program;

TEST_CASE("apt: reading goes on after an error and keeps every statement") {
  const read_result r = apt::read("GOTO/1,2\nGOTO/0,0,0\nGOTO/Z,0,0\n", "t.cls");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[0].to_string() == "t.cls:1:1: error: GOTO needs 3 or 6 values");
  CHECK(r.errors[1].to_string() == "t.cls:3:6: error: 'Z' is not a number");
  CHECK(r.parsed.blocks.size() == 3);
  CHECK(r.parsed.blocks[1].axes.x_mm == 0.0);
}

TEST_CASE("apt: LOAD/TOOL and LOADTL are a tool change, SELECT/TOOL a selection, what only describes passes through") {
  const read_result r = apt::read("LOAD/TOOL,12\nloadtl / 3\nSELECT/TOOL,6\nCUTTER/6,0,3\nmultax/ on\n", "t.cls");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 5);
  CHECK((b[0].tool == 12 && b[0].state.tool_change && !b[0].passthrough));
  CHECK((b[1].tool == 3 && b[1].state.tool_change));
  CHECK((b[2].tool == 6 && !b[2].state.tool_change && b[2].m_codes.empty() && !b[2].passthrough));  // a tool made ready, as ISO's T6 alone
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

namespace {

/// A block of `file` at line `line` moving linearly to (x, y, z) mm.
block goto_block(const char* file, std::size_t line, double x, double y, double z) {
  block b;
  b.where = {file, line, 1};
  b.motion = motion_kind::linear;
  b.axes.x_mm = x, b.axes.y_mm = y, b.axes.z_mm = z;
  return b;
}

/// An arc block of `file` at line `line` to (x, y, z) about `centre` in `plane`.
block arc_block(std::size_t line, double x, double y, double z, arc_plane plane, kin5::vec3 centre, bool clockwise) {
  block b = goto_block("arc.nc", line, x, y, z);
  b.motion = clockwise ? motion_kind::arc_cw : motion_kind::arc_ccw;
  b.arc = arc_words{plane, centre, std::nullopt};
  return b;
}

/// `blocks` read as ISO (`language`), written as APT: the text, or the writer's message.
std::string written(std::vector<block> blocks, dialect language = id_of<iso::dialect>()) {
  program p;
  p.language = language;
  p.blocks = std::move(blocks);
  try {
    return apt::write(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

}  // namespace

TEST_CASE("apt: an arc is CIRCLE (centre at the start's height, vector by the right-hand rule) and its GOTO") {
  const block start = goto_block("arc.nc", 1, 10, 0, 5);
  CHECK(written({start, arc_block(2, 0, 10, 5, arc_plane::xy, {0, 0, 0}, false)}) ==
        "GOTO/10,0,5\nCIRCLE/0,0,5,0,0,1,10\nGOTO/0,10,5\nFINI\n");  // FINI: the source gave no end
  CHECK(written({start, arc_block(2, 0, -10, 5, arc_plane::xy, {0, 0, 5}, true)}) ==
        "GOTO/10,0,5\nCIRCLE/0,0,5,0,0,-1,10\nGOTO/0,-10,5\nFINI\n");
  // start and end 0.004 mm either side of the radius: r is their mean, and the text reads back
  const std::string off = written({goto_block("arc.nc", 1, 10.004, 0, 5), arc_block(2, 0, 9.996, 5, arc_plane::xy, {0, 0, 5}, false)});
  CHECK(off == "GOTO/10.004,0,5\nCIRCLE/0,0,5,0,0,1,10\nGOTO/0,9.996,5\nFINI\n");
  CHECK(apt::read(off, "back.cls").ok());
  // a helix: the end 2 mm higher along the vector
  CHECK(written({start, arc_block(2, 0, 10, 7, arc_plane::xy, {0, 0, 5}, false)}) ==
        "GOTO/10,0,5\nCIRCLE/0,0,5,0,0,1,10\nGOTO/0,10,7\nFINI\n");
}

TEST_CASE("apt: the writer refuses an arc CIRCLE cannot say") {
  const block start = goto_block("arc.nc", 1, 10, 0, 5);
  const std::string why = "arc.nc:2: block cannot be written in APT: ";
  CHECK(written({arc_block(2, 0, 10, 5, arc_plane::xy, {0, 0, 5}, false)}) ==
        why + "an arc whose start point is not known (CIRCLE follows the GOTO of its start)");
  CHECK(written({start, arc_block(2, 0, 10.1, 5, arc_plane::xy, {0, 0, 5}, false)}) ==
        why + "the arc's start and end are not on one circle about its centre (radii 10 and 10.1)");
  block tilted = arc_block(2, 0, 10, 5, arc_plane::xy, {0, 0, 5}, false);
  tilted.axes.tool_axis = kin5::vec3{0, 0.1, 1};
  CHECK(written({start, tilted}) == why + "the tool axis changes during the arc (CIRCLE keeps the tool axis)");
  block rapid = arc_block(2, 0, 10, 5, arc_plane::xy, {0, 0, 5}, false);
  rapid.feed_rapid = true;
  CHECK(written({start, rapid}) == why + "a rapid arc (CIRCLE is a feed move)");
  block no_centre = arc_block(2, 0, 10, 5, arc_plane::xy, {0, 0, 5}, false);
  no_centre.arc->centre_mm.reset();
  no_centre.arc->radius_mm = 10;
  CHECK(written({start, no_centre}) == why + "an arc without its centre or direction (CIRCLE needs both)");
}

TEST_CASE("apt: what another dialect says that has no APT form is refused, never a $$ comment") {
  const block start = goto_block("in.nc", 1, 10, 0, 5);
  const std::string why = "in.nc:2: block cannot be written in APT: ";
  block m50 = goto_block("in.nc", 2, 20, 0, 5);
  m50.m_codes = {50};
  CHECK(written({start, m50}) == why + "M function M50 has no APT statement");
  block home = goto_block("in.nc", 2, 0, 0, 0);
  home.machine_coordinates = true;
  CHECK(written({start, home}) ==
        why + "a move in machine coordinates (G53, G28, G30, SUPA, M91, M92) has no APT form (GOTO points are in the "
              "part's frame)");
  block named;
  named.where = {"in.nc", 2, 1};
  named.tool_name = "BALL_D8";
  CHECK(written({start, named}) == why + "a tool by name (\"BALL_D8\") has no APT form (LOADTL takes a number; --tool-map NAME=n gives one)");
  // G93 F2, then G94 and a feed move without F: FEDRAT/INVERS,2 would still be in effect
  block inverse = goto_block("in.nc", 2, 20, 0, 5);
  inverse.feed_mode = feed_unit::inverse_time, inverse.feed = 2;
  block per_minute = goto_block("in.nc", 3, 30, 0, 5);
  per_minute.feed_mode = feed_unit::per_minute;
  CHECK(written({start, inverse, per_minute}) ==
        "in.nc:3: block cannot be written in APT: a feed move per minute (G94) without its own F: the FEDRAT in effect "
        "is in the other unit, and APT changes the unit only with a value");
  per_minute.feed = 300;
  CHECK(written({start, inverse, per_minute}) ==
        "GOTO/10,0,5\nFEDRAT/INVERS,2\nGOTO/20,0,5\nFEDRAT/MMPM,300\nGOTO/30,0,5\nFINI\n");
}

TEST_CASE("apt: a kept word whose effect a comment would lose is refused, a harmless one is a $$ comment") {
  block lost;
  lost.where = {"in.mpf", 2, 1};
  lost.kept_words = {"D2"};  // another edge's length (D0 is read as the length off: no loss)
  const std::string text = written({lost}, id_of<siemens::dialect>());
  CHECK(text.rfind("in.mpf:2: block cannot be written in APT: D2 (", 0) == 0);
  CHECK(text.find("a $$ comment would lose it") != std::string::npos);
  block plane;
  plane.where = {"in.nc", 2, 1};
  plane.text = "G17 G40";
  plane.kept_words = {"G17", "G40"};
  CHECK(written({plane}) == "$$ G17 G40\nFINI\n");
}
