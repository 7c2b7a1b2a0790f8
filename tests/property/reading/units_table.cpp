// Inch programs, text → model → text: the model holds millimetres (×25.4 exactly for positions,
// arc data and per-minute feeds; inverse-time feeds and angles unchanged), and the writer of an
// inch program says inch and writes the values back in inches. One table per dialect that reads
// inch programs; a unit change after motion is refused.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/io.hpp>

using namespace kin5::program;

namespace {
bool near(std::optional<double> a, double b) { return a && std::abs(*a - b) <= 1e-9 * (1 + std::abs(b)); }

std::vector<std::string> errors_of(dialect d, const std::string& text) {
  std::vector<std::string> out;
  for (const diagnostic& e : read(d, text, "t").errors) out.push_back(e.to_string());
  return out;
}

// Reads `text`, writes it in `d`, reads that again: the two models' blocks agree, text aside.
void round_trip(dialect from, const std::string& text, dialect to, const std::string& written) {
  const read_result first = read(from, text, "t");
  REQUIRE(first.ok());
  const std::string out = write(to, first.parsed);
  CHECK(out == written);
  const read_result again = read(to, out, "t");
  REQUIRE(again.ok());
  REQUIRE(write(to, again.parsed) == out);
}
}  // namespace

TEST_CASE("units: ISO G20 programs are read in millimetres and written back in inches") {
  const std::string text =
      "%\nO1000\nG20 G17\nG0 X1.2345 Y-.5 Z2.\nG1 X2. F9.8\nG2 X3. Y-.5 I.5 J0. F10.\nG93 G1 X4. F2.5\nM30\n%\n";
  const read_result r = read(id_of<iso::dialect>(), text, "t");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 9);
  CHECK(b[2].metric == false);
  CHECK(near(b[3].axes.x_mm, 31.3563));
  CHECK(near(b[3].axes.y_mm, -12.7));
  CHECK(near(b[3].axes.z_mm, 50.8));
  CHECK(near(b[4].feed, 248.92));
  REQUIRE((b[5].arc && b[5].arc->centre_mm));
  CHECK((near(b[5].arc->centre_mm->x, 63.5) && near(b[5].arc->centre_mm->y, -12.7) && near(b[5].arc->centre_mm->z, 50.8)));
  CHECK(near(b[5].feed, 254.0));
  CHECK(near(b[6].feed, 2.5));  // inverse time: 1/min, not a length
  CHECK(near(b[6].axes.x_mm, 101.6));
  round_trip(id_of<iso::dialect>(), text, id_of<iso::dialect>(),
             "%\nO1000\nG17 G20\nG0 X1.2345 Y-0.5 Z2\nG1 X2 F9.8\nG2 X3 Y-0.5 I0.5 J0 F10\nG1 G93 X4 F2.5\nM30\n%\n");
}

TEST_CASE("units: APT UNITS/INCHES and FEDRAT/IPM are read in millimetres and written back in inches") {
  const std::string text =
      "PARTNO P\nUNITS/INCHES\nFEDRAT/9.8\nGOTO/1.2345,-.5,2.\nFEDRAT/IPM,10\nFEDRAT/MMPM,254\nGOTO/2,0,0\n"
      "FEDRAT/INVERS,2.5\nGOTO/3,0,0\nFINI\n";
  const read_result r = read(id_of<apt::dialect>(), text, "t");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 10);
  CHECK(b[1].metric == false);
  CHECK(near(b[2].feed, 248.92));
  CHECK(near(b[3].axes.x_mm, 31.3563));
  CHECK(near(b[4].feed, 254.0));
  CHECK(near(b[5].feed, 254.0));
  CHECK(near(b[7].feed, 2.5));
  round_trip(id_of<apt::dialect>(), text, id_of<apt::dialect>(),
             "PARTNO P\nUNITS/INCHES\nFEDRAT/IPM,9.8\nGOTO/1.2345,-0.5,2\nFEDRAT/IPM,10\nFEDRAT/IPM,10\nGOTO/2,0,0\n"
             "FEDRAT/INVERS,2.5\nGOTO/3,0,0\nFINI\n");
  const read_result mm = read(id_of<apt::dialect>(), "UNITS/MM\nFEDRAT/IPM,10\n", "t");
  REQUIRE(mm.ok());
  CHECK(near(mm.parsed.blocks[1].feed, 254.0));
}

TEST_CASE("units: an inch ISO program written as APT stays in inches") {
  round_trip(id_of<iso::dialect>(), "G20\nG1 X1. Y2. Z3. F10.\n", id_of<apt::dialect>(),
             "UNITS/INCHES\nFEDRAT/IPM,10\nGOTO/1,2,3\n");
}

TEST_CASE("units: a unit change after motion is refused at the unit word") {
  CHECK(errors_of(id_of<iso::dialect>(), "G21\nG1 X1. F100.\nG20\n") ==
        std::vector<std::string>{"t:3:1: error: G20 after motion: a unit change inside a program is not supported"});
  CHECK(errors_of(id_of<iso::dialect>(), "G20\nG1 X1. F10.\nG20 X2.\n").empty());
}
