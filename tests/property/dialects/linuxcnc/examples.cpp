// LinuxCNC habits on small hand-written programs, with hand-derived expectations: what its
// 5-axis configurations and CAM posts for them write.
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/address_words.hpp>
#include <kin5/program/io.hpp>
#include <kin5/program/linuxcnc/dialect.hpp>
#include <kin5/program/read_limits.hpp>

#include "../called_dir.hpp"
#include "../example.hpp"

using namespace kin5::program;

namespace {
using strings = std::vector<std::string>;
}

TEST_CASE("linuxcnc: a trt program: M428/M429, G43 without H, G59.1, G93, G4 P in seconds") {
  const std::string text =
      "%\n"
      "(MSG, load the fixture)\n"
      "g21 g17 g90 g40 g94 g64 p0.01 g91.1\n"
      "G59.1\n"
      "T7 M6\n"
      "G43\n"
      "S9000 M3 M8 M7\n"
      "M428 ; tcp kinematics\n"
      "G0 X1.5 Y-2 Z40 A-10 C20\n"
      "G93\n"
      "G1 X2 Z-.25 A-12 C25 F96.5\n"
      "G94\n"
      "G4 P1.5\n"
      "M429\n"
      "G49\n"
      "G12.1 P1\n"
      "G13.1\n"
      "M2\n"
      "%\n";
  const auto b = kin5::test::read_example<linuxcnc::dialect>(text, "l.ngc", 19);
  CHECK(b[0].passthrough);
  CHECK(b[1].comment == "MSG, load the fixture");
  CHECK(b[2].kept_words == strings{"g91.1", "g64", "p0.01"});
  CHECK((b[2].state.working_plane == arc_plane::xy && b[2].state.distance == distance_mode::absolute &&
         b[2].state.radius_compensation == cutter_side::off));
  CHECK(b[2].metric == true);
  CHECK(b[3].state.work_offset == work_offset{work_offset_family::g54, 7});
  CHECK((b[4].tool == 7 && b[4].state.tool_change && b[4].m_codes.empty()));
  CHECK((b[5].state.length_compensation == true && b[5].state.length_register == 7));  // G43: the loaded T7
  CHECK((b[6].m_codes.empty() && b[6].state.spindle == spindle_rotation::clockwise && b[6].state.coolant_flood == true &&
         b[6].state.coolant_mist == true));
  CHECK((b[7].tcp == true && b[7].comment == "tcp kinematics" && b[7].m_codes.empty()));
  CHECK((b[8].motion == motion_kind::rapid && b[8].axes.a_deg == -10.0 && b[8].axes.c_deg == 20.0));
  CHECK(b[9].feed_mode == feed_unit::inverse_time);
  CHECK((b[10].feed == 96.5 && b[10].axes.z_mm == -0.25));
  CHECK((b[12].kept_words.empty() && b[12].state.dwell_s == 1.5));
  CHECK(b[13].tcp == false);
  CHECK((b[14].state.length_compensation == false && !b[14].tcp));
  CHECK(b[15].tcp == true);
  CHECK(b[16].tcp == false);
  CHECK(b[17].program_end == "M2");
}

TEST_CASE("linuxcnc: G43 H n holds the loaded tool n, M6 in a line runs before its G43") {
  const read_result ok = linuxcnc::read("T3 M6 G43 H3\nM428\nG1 X1 A2 F100\n", "l.ngc");
  CHECK(ok.errors.empty());
  CHECK(ok.parsed.blocks[0].state.length_register == 3);
  const read_result other = linuxcnc::read("T3 M6 G43 H4\nM428\nG1 X1 A2 F100\nG1 X2\n", "l.ngc");
  REQUIRE(other.errors.size() == 1);  // once, at the first move
  CHECK(other.errors[0].where.line == 3);
}

TEST_CASE("linuxcnc: the writer spells tracking, length and offsets its own way") {
  const read_result r = linuxcnc::read("N5 G59.3 T2 M6 G43 H2\nM428\nG1 X1 Y2 Z3 B4 F500\nM429 G49\n", "l.ngc");
  REQUIRE(r.errors.empty());
  CHECK(linuxcnc::write(r.parsed) ==
        "N5 G59.3 G43 H2 T2 M6\n"
        "M428\n"
        "G1 X1 Y2 Z3 B4 F500\n"
        "G49 M429\n");
}

TEST_CASE("linuxcnc: another dialect's program gets % lines, G43 before tracking, M429 around its tool changes") {
  // Its own % lines only: the source's tape marks are never copied, not even as comments.
  const read_result iso_in = read(*parse_dialect("iso"),
                                  "%\nO12\nT1 M6\nG43.4 H1\nG1 X1. Y2. Z3. B4. C5. F500\nT2 M6\nG43.4 H2\nG1 X2.\nG49\nM30\n%\n", "i.nc");
  REQUIRE(iso_in.errors.empty());
  const std::string out = write(*parse_dialect("linuxcnc"), iso_in.parsed);
  CHECK(out ==
        "%\n"
        "(PROGRAM 12)\n"
        "T1 M6\n"
        "G43 H1\n"  // a line of its own: LinuxCNC runs M428 before G43 of the same line
        "M428 (G43.4 H1)\n"
        "G1 X1 Y2 Z3 B4 C5 F500\n"
        "M429\n"
        "T2 M6\n"
        "G43\n"
        "M428\n"
        "G43 H2\n"
        "M428 (G43.4 H2)\n"
        "G1 X2\n"
        "M429 (G49)\n"
        "G49\n"
        "M30\n"
        "%\n");
  const read_result back = linuxcnc::read(out, "back.ngc");
  CHECK(back.errors.empty());
  // Without G43.4 H2 the source moves tool 2 with H1, tool 1's length: no LinuxCNC G43 under M428
  // says that (its kinematics take the length from G43), so the move is refused.
  const read_result h1_kept =
      read(*parse_dialect("iso"), "T1 M6\nG43.4 H1\nG1 X1. Y2. Z3. B4. C5. F500\nT2 M6\nG1 X2.\n", "k.nc");
  REQUIRE(h1_kept.errors.empty());
  CHECK_THROWS_WITH(write(*parse_dialect("linuxcnc"), h1_kept.parsed),
                    Catch::Contains("k.nc:5: block cannot be written in LinuxCNC: a move under tracking while G43 "
                                    "does not hold the loaded tool's length"));
}

TEST_CASE("linuxcnc: what LinuxCNC cannot say is refused, naming the block") {
  program p;
  p.language = id_of<iso::dialect>();
  p.file = "i.nc";
  block vector_move;
  vector_move.where = {"i.nc", 4, 1};
  vector_move.motion = motion_kind::linear;
  vector_move.axes.tool_axis = kin5::vec3{0, 0, 1};
  p.blocks = {vector_move};
  CHECK_THROWS_WITH(linuxcnc::write(p), "i.nc:4: block cannot be written in LinuxCNC: a tool-axis vector (LinuxCNC has "
                                        "no G43.5; its trt kinematics take A, B, C words)");
  block extended;
  extended.where = {"i.nc", 6, 1};
  extended.state.work_offset = work_offset{work_offset_family::extended, 3};
  p.blocks = {extended};
  CHECK_THROWS_WITH(linuxcnc::write(p), "i.nc:6: block cannot be written in LinuxCNC: work offset G54.1 P3 has no "
                                        "LinuxCNC form (G54 … G59.3; --work-offset-map names one)");
}

TEST_CASE("linuxcnc: markers: M428 names LinuxCNC, the ISO G43.4 does not") {
  CHECK(guess_dialect("G43\nM428\n") == id_of<linuxcnc::dialect>());
  CHECK(guess_dialect("G43.4 H1\n") == id_of<iso::dialect>());
}

TEST_CASE("linuxcnc: a number written only in a named parameter counts for the program's resolution") {
  // `X#<z>` with `#<z> = 10.1234` is the literal X10.1234, whatever case and blanks spell the name.
  const dialect id = id_of<linuxcnc::dialect>();
  const auto r = scan_resolution("#<Z Safe> = 10.1234\n#<_b>=-0.12345\nG1 X1.5 Y2 F100\nG1 X#<zsafe> B-#<_B>\n", id);
  CHECK(r.linear_decimals == 4);
  CHECK(r.angle_decimals == 5);
  const auto computed = scan_resolution("#<z> = 10.1234\n#<z> = [#1 * 2]\nG1 X#<z> Y1.5\n", id);
  CHECK(computed.linear_decimals == 1);
}

TEST_CASE("linuxcnc: o<name> call of a subroutine in name.ngc, from the include directories") {
  const called_dir dir("linuxcnc-calls");
  // The file holds the subroutine (LinuxCNC's subroutine path); its own locals, its own file.
  dir.write("corner.ngc", "%\n(a corner)\no<corner> sub\n#<d> = [#1 * 2]\nG1 X#<d> Y#2 F100\no<corner> endsub\nM2\n%\n");
  dir.write("twice.ngc", "o<twice> sub\no<corner> call [#1] [1]\no<corner> call [#1] [2]\no<twice> endsub\n");
  const std::string main = "G21 G90\no<twice> call [5]\nG0 Z10\nM2\n";
  read_limits limits;
  limits.include_dirs = {dir.path.string()};
  {
    const read_limits_scope scope(limits);
    const read_result r = linuxcnc::read(main, "main.ngc");
    REQUIRE(r.errors.empty());
    std::vector<std::string> moves;
    for (const block& b : r.parsed.blocks)
      if (b.axes.x_mm || b.axes.z_mm)
        moves.push_back(std::filesystem::path(b.where.file.str()).filename().string() + ":" + std::to_string(b.where.line) + " " +
                        (b.axes.x_mm ? "X" + std::to_string(static_cast<int>(*b.axes.x_mm)) : "") +
                        (b.axes.y_mm ? "Y" + std::to_string(static_cast<int>(*b.axes.y_mm)) : "") +
                        (b.axes.z_mm ? "Z" + std::to_string(static_cast<int>(*b.axes.z_mm)) : ""));
    CHECK(moves == strings{"corner.ngc:5 X10Y1", "corner.ngc:5 X10Y2", "main.ngc:3 Z10"});
  }
  const read_result none = linuxcnc::read(main, "main.ngc");
  REQUIRE(none.errors.size() == 1);
  CHECK(none.errors[0].to_string() ==
        "main.ngc:2:1: error: call of o<twice>: no label o<twice> in this file, and no directory to look for its file "
        "twice.ngc in (--include-dir DIR names the directory that holds it)");
}

TEST_CASE("linuxcnc: a call's arguments take the caller's values (rs274: X3.)") {
  const read_result r =
      linuxcnc::read("#1 = 5\no<a> call [3]\nM2\no<a> sub\no<b> call [#1]\no<a> endsub\no<b> sub\nG1 X#1 F100\no<b> endsub\n",
                     "args.ngc");
  REQUIRE(r.errors.empty());
  std::vector<double> x;
  for (const block& b : r.parsed.blocks)
    if (b.axes.x_mm) x.push_back(*b.axes.x_mm);
  CHECK(x == std::vector<double>{3.});
}
