// Heidenhain input beyond its bad-input table (errors.txt, read by the dialect laws): reading
// goes on after an error, what is not an error, what the writer refuses.
#include <stdexcept>
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
}  // namespace

TEST_CASE("heidenhain: reading goes on after an error and keeps every block") {
  const read_result r = heidenhain::read("1 L X+1 Y\n2 L X+2 Y+3\n3 L X+Q1*2\n", "t.h");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[0].to_string() == "t.h:1:9: error: word 'Y' has no value");
  CHECK(r.errors[1].to_string() == "t.h:3:5: error: an expression in an axis word is not supported (a TNC reads a number or a Q parameter: X+Q1)");
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

TEST_CASE("heidenhain: STOP is a program stop (M0), its comment kept") {
  const read_result stop = heidenhain::read("STOP ; check\n", "t.h");
  REQUIRE(stop.ok());
  CHECK((stop.parsed.blocks[0].state.stop == program_stop::stop && stop.parsed.blocks[0].comment == " check"));
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
  p.language = id_named("iso");  // a program read in ISO: this folder needs only its id
  p.file = "part.nc";
  block b;
  b.where = {"part.nc", 12, 1};
  b.motion = motion_kind::linear;
  b.axes.x_mm = 1;
  b.metric = false;
  p.blocks.push_back(b);
  // An inch program without a header of its own is framed BEGIN PGM … INCH; a block after a
  // later unit change is written in that unit too.
  CHECK(heidenhain::write(p) == "0 BEGIN PGM PGM INCH\n1 L X+0.0394\n2 END PGM PGM INCH\n");
  p.blocks.push_back(b);
  p.blocks[1].metric = true;
  CHECK(heidenhain::write(p) == "0 BEGIN PGM PGM INCH\n1 L X+0.0394\n2 L X+0.0394\n3 END PGM PGM INCH\n");
  p.blocks.pop_back();
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
