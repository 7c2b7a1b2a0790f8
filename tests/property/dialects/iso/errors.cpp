// ISO input beyond its bad-input table (errors.txt, read by the dialect laws): reading goes on
// after an error, words that are not errors, what the writer refuses.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/iso/dialect.hpp>

using namespace kin5::program;

TEST_CASE("iso: reading goes on after an error and keeps every line") {
  const read_result r = iso::read("G95\nG1 X1.\nG1 Y\n", "t.nc");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[0].to_string() == "t.nc:1:1: error: feed per revolution (G95) is not supported");
  CHECK(r.errors[1].to_string() == "t.nc:3:4: error: word 'Y' has no value");
  REQUIRE(r.parsed.blocks.size() == 3);
  CHECK(r.parsed.blocks[1].axes.x_mm == 1.0);
}

TEST_CASE("iso: harmless words and resets are not errors") {
  const read_result r = iso::read("G52 X0 Y0\nG69\nG50\nG49\nG90\nG10 L2 P1 X5.\n", "t.nc");
  // G10 (offsets set from the program) is refused; the others read fine.
  REQUIRE(r.errors.size() == 1);
  CHECK(r.errors[0].to_string() ==
        "t.nc:6:1: error: G10: setting offsets from the program is not supported (later moves would use other offsets)");
  CHECK(r.parsed.blocks[0].kept_words == std::vector<std::string>{"G52", "X0", "Y0"});
  CHECK(!r.parsed.blocks[0].moves());
}

TEST_CASE("iso: G4 X1.5 dwells, its X is no position") {
  // Fanuc: G04 dwell, the time in X (seconds, with a decimal point) or P (milliseconds).
  const read_result dwell = iso::read("G4 X1.5\nN7 G04 P250 (wait)\nG4 X0\n", "t.nc");
  REQUIRE(dwell.ok());
  const auto& b = dwell.parsed.blocks;
  CHECK((b[0].axes.empty() && b[0].kept_words.empty() && b[0].state.dwell_s == 1.5));
  CHECK((b[1].number == 7 && b[1].comment == "wait" && b[1].state.dwell_s == 0.25 && b[1].only_dwell()));
  CHECK(b[2].state.dwell_s == 0.0);
  CHECK(iso::write(dwell.parsed) == "G4 X1.5\nN7 G4 X0.25 (wait)\nG4 X0.\n");
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
