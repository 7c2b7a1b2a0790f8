// LinuxCNC input beyond its bad-input table (errors.txt, read by the dialect laws): reading goes
// on after an error in a line; an error in the program's flow ends the run.
#include <catch2/catch.hpp>

#include <kin5/program/linuxcnc/dialect.hpp>

using namespace kin5::program;

TEST_CASE("linuxcnc: reading goes on after an error and keeps every line") {
  const read_result r = linuxcnc::read("M430\nG1 X1 F100\nG1 X2 X3\nG1 Y2\n", "t.ngc");
  CHECK(r.errors.size() == 2);
  CHECK(r.parsed.blocks.size() == 4);
  CHECK(r.parsed.blocks[3].axes.y_mm == 2.0);
}

TEST_CASE("linuxcnc: an error in the program's flow ends the run there") {
  // Where the flow would go on after a subroutine without its end is unknown: no later line runs.
  const read_result r = linuxcnc::read("M430\nG1 X1 F100\no1 sub\nG1 Y2\n", "t.ngc");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[1].to_string() == "t.ngc:3:1: error: subprogram o1 has no end");
  CHECK(r.parsed.blocks.size() == 2);
}
