// Real-world Haas habits on small hand-written programs, with hand-derived expectations: a UMC
// program as CAM posts write it, and what the writer writes for another dialect's blocks.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/haas/dialect.hpp>
#include <kin5/program/heidenhain/dialect.hpp>
#include <kin5/program/iso/dialect.hpp>
#include <kin5/program/read_limits.hpp>

#include "../called_dir.hpp"
#include "../example.hpp"

using namespace kin5::program;

TEST_CASE("haas: a UMC program with G234, G154, leading zeros, inch and a dwell") {
  const std::string text =
      "%\n"
      "O04410 (UMC TCPC)\n"
      "N10 G20 G17 G90 G40 G49 G80\n"
      "N20 G154 P12\n"
      "N30 T2 M06\n"
      "N40 S8000 M03\n"
      "N50 G234 H02\n"
      "N60 G00 X1. Y-0.5 Z2. B0. C0.\n"
      "N70 G01 Z0.05 F25.\n"
      "N80 G04 P500\n"
      "N90 X1.05 B-5. C15.\n"
      "N100 G49\n"
      "N110 G04 P1.5\n"
      "N120 M30\n"
      "%\n";
  const auto b = kin5::test::read_example<haas::dialect>(text, "umc.nc", 15);
  CHECK(b[1].program_begin == "04410");
  CHECK((b[2].metric == false && b[2].tcp == false && b[2].state.length_compensation == false));
  CHECK(b[3].state.work_offset == work_offset{work_offset_family::extended, 12});
  CHECK((b[4].tool == 2 && b[4].state.tool_change && b[4].m_codes.empty()));
  CHECK((b[6].tcp == true && b[6].state.length_compensation == true && b[6].state.length_register == 2));
  CHECK((b[7].axes.x_mm == Approx(25.4) && b[7].axes.b_deg == 0.0));
  CHECK(b[8].feed == Approx(25 * 25.4));  // inches per minute, read as mm
  CHECK(b[9].state.dwell_s == 0.5);       // P without a point: milliseconds
  CHECK(b[9].only_dwell());
  CHECK((b[10].axes.b_deg == -5.0 && b[10].axes.c_deg == 15.0));
  CHECK((b[11].tcp == false && b[11].state.length_compensation == false));
  CHECK(b[12].state.dwell_s == 1.5);      // with a point: seconds
  CHECK(b[13].program_end == "M30");
}

TEST_CASE("haas: another dialect's program is written with G234, G154 and G04 P seconds") {
  const read_result r = iso::read(
      "%\nO0007\nG21 G17 G90\nT3 M6\nG54.1 P7\nG43.4 H3\nG1 X1. Y2. Z3. B4. C5. F100.\nG4 X2.5\nT4 M6\nG1 X3.\nM30\n%\n",
      "part.nc");
  REQUIRE(r.ok());
  CHECK(haas::write(r.parsed) ==
        "%\n"
        "O0007\n"
        "G90 G17 G21\n"
        "T3 M6\n"
        "G154 P7\n"
        "G234 H3\n"
        "G1 X1. Y2. Z3. B4. C5. F100.\n"
        "G4 P2.5\n"
        "G49\n"           // TCPC off for the tool change
        "T4 M6\n"
        "G234 H4\n"       // and on again, with the new tool's length
        "G1 X3.\n"
        "M30\n"
        "%\n");
}

TEST_CASE("haas: what Haas cannot say is refused by the writer, naming the block") {
  const read_result vector = iso::read("T1 M6\nG43.5 H1\nG1 X1. Y2. Z3. I0. J0. K1. F100.\n", "v.nc");
  REQUIRE(vector.ok());
  CHECK_THROWS_WITH(haas::write(vector.parsed),
                    "v.nc:3: block cannot be written in Haas: a tool-axis vector (no G43.5 here: tracking takes "
                    "rotary axis words)");
  const read_result offset = iso::read("G54.1 P100\n", "o.nc");
  REQUIRE(offset.ok());
  CHECK_THROWS_WITH(haas::write(offset.parsed),
                    "o.nc:1: block cannot be written in Haas: work offset G54.1 P100 has no Haas form "
                    "(--work-offset-map names one)");
  const read_result named = heidenhain::read("0 BEGIN PGM P MM\n1 TOOL CALL \"BALL\" Z S1000\n2 END PGM P MM\n", "n.h");
  REQUIRE(named.ok());
  CHECK_THROWS_WITH(haas::write(named.parsed),
                    "n.h:2: block cannot be written in Haas: a tool by name (\"BALL\") has no Haas form (T takes a "
                    "number; --tool-map NAME=n gives one)");
}

TEST_CASE("haas: M98 of a program in another file finds its number padded to five digits") {
  // A Haas keeps five-digit program numbers: M98 P1234 runs O01234, M98 P12 O00012.nc.
  const called_dir dir("haas-calls");
  dir.write("O01234", "O01234 (SIDE)\nG01 X1.5 F20.\nM99\n");
  dir.write("O00012.nc", "G01 Y2.5\nM99\n");
  read_limits limits;
  limits.include_dirs = {dir.path.string()};
  const read_limits_scope scope(limits);
  const read_result r = haas::read("G20\nM98 P1234\nM98 P12\nM30\n", "main.nc");
  REQUIRE(r.errors.empty());
  std::vector<std::string> moves;
  for (const block& b : r.parsed.blocks)
    if (b.axes.x_mm || b.axes.y_mm)
      moves.push_back(std::filesystem::path(b.where.file.str()).filename().string() + (b.axes.x_mm ? " X" : " Y"));
  CHECK(moves == std::vector<std::string>{"O01234 X", "O00012.nc Y"});
  // Not found: the refusal names the five-digit names too.
  const read_result none = haas::read("M98 P77\nM30\n", "main.nc");
  REQUIRE(none.errors.size() == 1);
  CHECK(none.errors[0].message == "call of O77: no label O77 in this file, nor a file O77, O77.nc, 77.nc, O00077, O00077.nc or 00077.nc in the include directories (--include-dir)");
}
