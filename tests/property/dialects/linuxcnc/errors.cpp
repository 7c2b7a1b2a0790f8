// LinuxCNC input beyond its bad-input table (errors.txt, read by the dialect laws): reading goes
// on after an error.
#include <catch2/catch.hpp>

#include <kin5/program/linuxcnc/dialect.hpp>

using namespace kin5::program;

TEST_CASE("linuxcnc: reading goes on after an error and keeps every line") {
  const read_result r = linuxcnc::read("M430\nG1 X1 F100\no1 sub\nG1 Y2\n", "t.ngc");
  CHECK(r.errors.size() == 2);
  CHECK(r.parsed.blocks.size() == 4);
  CHECK(r.parsed.blocks[3].axes.y_mm == 2.0);
}
