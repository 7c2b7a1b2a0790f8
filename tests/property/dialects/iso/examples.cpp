// Real-world ISO / Fanuc and LinuxCNC habits on small hand-written programs, with
// hand-derived expectations.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/address_words.hpp>
#include <kin5/program/iso/dialect.hpp>
#include <kin5/program/read_limits.hpp>

#include "../called_dir.hpp"
#include "../example.hpp"

using namespace kin5::program;

namespace {
using strings = std::vector<std::string>;
}

TEST_CASE("iso: a Fanuc post style program with G43.4, homing and arcs") {
  const std::string text =
      "%\r\n"
      "O0042 (BRACKET)\r\n"
      "N10 G40 G17 G49 G90 G80 G21\r\n"
      "N20 G91 G28 Z0. M05\r\n"
      "N30 G28 X0. Y0. B0.\r\n"
      "T05 M06\r\n"
      "G05.1 Q1\r\n"
      "G54\r\n"
      "G90 G00 B-30. C45. S8000 M03\r\n"
      "G43.4 G90 X10. Y-5.5 H05\r\n"
      "Z3.\r\n"
      "G01 Z-1. F250.\r\n"
      "X20.\r\n"
      "G02 X25. Y-.5 I5. J0\r\n"
      "G03 X30. Y-5.5 R5.\r\n"
      "g1x35.y-5.5b-29.5c+44.8\r\n"
      "G49\r\n"
      "G05.1 Q0\r\n"
      "M30\r\n"
      "%\r\n";
  const read_result r = iso::read(text, "b.nc");
  REQUIRE(r.errors.empty());
  CHECK(r.warnings.empty());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 20);
  CHECK((b[0].passthrough && b[0].text == "%"));
  CHECK((b[1].program_begin == "0042" && b[1].comment == "BRACKET"));
  CHECK(b[2].number == 10);
  CHECK(b[2].kept_words == strings{"G80"});
  CHECK((b[2].state.radius_compensation == cutter_side::off && b[2].state.working_plane == arc_plane::xy &&
         b[2].state.distance == distance_mode::absolute));
  CHECK((b[2].tcp == false && b[2].metric == true));
  CHECK((b[3].machine_coordinates && b[3].machine_reference == machine_position::reference_point &&
         b[3].kept_words.empty() && b[3].axes.z_mm == 0.0));
  CHECK(b[3].state.distance == distance_mode::incremental);
  CHECK((b[3].m_codes.empty() && b[3].state.spindle == spindle_rotation::stopped));
  CHECK((b[4].machine_coordinates && b[4].axes.b_deg == 0.0));
  CHECK((b[5].tool == 5 && b[5].state.tool_change && b[5].m_codes.empty()));
  CHECK(b[6].kept_words == strings{"G05.1", "Q1"});
  CHECK((b[7].kept_words.empty() && b[7].state.work_offset == work_offset{work_offset_family::g54, 1}));
  CHECK((b[8].motion == motion_kind::rapid && b[8].axes.b_deg == -30.0 && b[8].axes.c_deg == 45.0));
  CHECK((b[8].spindle_rpm == 8000.0 && b[8].state.spindle == spindle_rotation::clockwise));
  CHECK(b[8].state.distance == distance_mode::absolute);
  CHECK((b[9].tcp == true && b[9].kept_words.empty() && b[9].axes.x_mm == 10.0));
  CHECK((b[9].state.length_compensation == true && b[9].state.length_register == 5));
  CHECK((!b[10].motion && b[10].axes.z_mm == 3.0));
  CHECK((b[11].motion == motion_kind::linear && b[11].feed == 250.0));
  // Arc from (20, -5.5, -1): centre 5 mm further in X.
  REQUIRE(b[13].arc);
  CHECK(b[13].motion == motion_kind::arc_cw);
  CHECK(b[13].arc->plane == arc_plane::xy);
  CHECK(b[13].arc->centre_mm == kin5::vec3{25, -5.5, -1});
  REQUIRE(b[14].arc);
  CHECK((b[14].arc->radius_mm == 5.0 && !b[14].arc->centre_mm));
  CHECK((b[15].motion == motion_kind::linear && b[15].axes.x_mm == 35.0 && b[15].axes.c_deg == 44.8));
  CHECK((b[16].tcp == false && b[16].state.length_compensation == false));
  CHECK(b[18].program_end == "M30");
  CHECK(b[19].passthrough);
}

TEST_CASE("iso: LinuxCNC style: M428 remap, semicolon comments, G93, G43 is not TCP") {
  const std::string text =
      "%\n"
      "M428 ;TCP:xyzbc\n"
      "G00 G17 G40 G90 G94\n"
      "T3 M6\n"
      "G43 H3 Z12.5 M08\n"
      "G93\n"
      "G01 X1.5 Y-2. Z-.25 B10. C-90. F120.75\n"
      "G94\n"
      "M2\n"
      "%\n";
  const auto b = kin5::test::read_example<iso::dialect>(text, "l.ngc", 10);
  CHECK((b[1].m_codes == std::vector<int>{428} && !b[1].tcp && b[1].comment == "TCP:xyzbc"));
  CHECK((b[2].motion == motion_kind::rapid && b[2].feed_mode == feed_unit::per_minute));
  CHECK((!b[4].tcp && b[4].kept_words.empty() && b[4].state.coolant_flood == true && b[4].m_codes.empty()));
  CHECK((b[4].state.length_compensation == true && b[4].state.length_register == 3));
  CHECK(b[5].feed_mode == feed_unit::inverse_time);
  CHECK((b[6].feed == 120.75 && b[6].axes.z_mm == -0.25 && b[6].axes.c_deg == -90.0));
  CHECK(b[8].program_end == "M2");
}

TEST_CASE("iso: G43.5 vectors, arcs inside G43.5, other planes") {
  const std::string text =
      "G43.5 H2 I0 J0 K1.\n"
      "G1 X10. Y0 Z5. I0 J-.6 K.8 F1000\n"
      "G2 X20. Y0 I5. J0\n"
      "G18 G3 X30. Z5. I5. K-1.\n"
      "G19 G2 Y5. Z10. R7.\n"
      "G49\n";
  const read_result r = iso::read(text, "v.nc");
  REQUIRE(r.errors.empty());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 6);
  CHECK((b[0].tcp == true && b[0].axes.tool_axis == kin5::vec3{0, 0, 1}));
  CHECK(b[1].axes.tool_axis == kin5::vec3{0, -0.6, 0.8});
  CHECK((!b[2].axes.tool_axis && b[2].arc->centre_mm == kin5::vec3{15, 0, 5}));
  CHECK(b[3].arc->plane == arc_plane::zx);
  CHECK(b[3].arc->centre_mm == kin5::vec3{25, 0, 4});  // from (20, 0, 5)
  CHECK((b[4].arc->plane == arc_plane::yz && b[4].arc->radius_mm == 7.0));
  // Written back: G43.5 because vectors follow, arcs in their planes.
  CHECK(iso::write(r.parsed) ==
        "G43.5 H2 I0. J0. K1.\n"
        "G1 X10. Y0. Z5. I0. J-0.6 K0.8 F1000.\n"
        "G2 X20. Y0. I5. J0.\n"
        "G18 G3 X30. Z5. I5. K-1.\n"
        "G19 G2 Y5. Z10. R7.\n"
        "G49\n");
}

TEST_CASE("iso: comments keep non-UTF-8 bytes, lone CR ends lines, blank lines are skipped") {
  const read_result r = iso::read("(caf\xe9 \x80)\r\r  \rG0 X1.", "c.nc");
  REQUIRE(r.errors.empty());
  REQUIRE(r.parsed.blocks.size() == 2);
  CHECK(r.parsed.blocks[0].comment == "caf\xe9 \x80");
  CHECK(r.parsed.blocks[1].where == source_location{"c.nc", 4, 1});
}

TEST_CASE("iso: a comment inside a comment ends with the comment around it") {
  // NX's posts list their tools as comments holding comments; the control skips all of it.
  // Text between the inner and the outer ')' would be code on a control that ends a comment at
  // its first ')': refused there.
  const read_result r =
      iso::read("(#12= (SLOT_D6 (ROUGH)  ))\nG0 X1. (A (B) ) Y2.\n(OPEN (INNER)\n(A (B) X5.)\n", "n.nc");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[0].where == source_location{"n.nc", 3, 1});
  CHECK(r.errors[0].message == "comment is not closed");
  CHECK(r.errors[1].where == source_location{"n.nc", 4, 8});
  CHECK(r.errors[1].message.starts_with("text after a comment inside a comment: "));
  REQUIRE(r.parsed.blocks.size() >= 2);
  CHECK(r.parsed.blocks[0].comment == "#12= (SLOT_D6 (ROUGH)  )");
  CHECK((r.parsed.blocks[1].comment == "A (B)" && r.parsed.blocks[1].axes.y_mm == 2.0));
}

TEST_CASE("iso: the lines after M30 are read, whatever ends them, up to a program of the file") {
  for (const std::string eol : {"\n", "\r\n", "\r"}) {
    const read_result r = iso::read("G0 X1." + eol + "M30" + eol + eol + "G0 X2." + eol + "%" + eol + "O100" + eol + "G0 X3." + eol, "c.nc");
    REQUIRE(r.errors.empty());
    REQUIRE(r.parsed.blocks.size() == 4);
    CHECK(r.parsed.blocks[2].axes.x_mm == 2.0);
    CHECK(r.parsed.blocks[2].where == source_location{"c.nc", 4, 1});
    CHECK(r.parsed.blocks[3].framing);
  }
}

TEST_CASE("iso: blocks from another dialect") {
  program p;
  p.language = id_of<heidenhain::dialect>();
  block l;
  l.text = "L X+1 Y+2 FMAX M91";
  l.motion = motion_kind::linear;
  l.feed_rapid = true;
  l.axes.x_mm = 1, l.axes.y_mm = 2;
  l.machine_coordinates = true;
  block cyc;
  cyc.text = "CYCL DEF 7.0 (DATUM)";
  cyc.passthrough = true;
  block k;
  k.text = "BLK FORM 0.1 Z";
  k.kept_words = {"BLK FORM 0.1 Z"};
  p.blocks = {l, cyc, k};
  // Framed as a FANUC program: %, the O line, the blocks, M30 (the source gives no end), %.
  CHECK(iso::write(p) == "%\nO0001\nG53 G0 X1. Y2.\n;CYCL DEF 7.0 (DATUM)\n(BLK FORM 0.1 Z)\nM30\n%\n");
}

TEST_CASE("iso: a line not understood is refused and changes nothing, spaced kept words write back as they were") {
  // G29 is not understood: refused, and the G18 beside it must not select the ZX plane.
  const std::string text = "G0 X0 Y0 Z0\nG18 G29\nG2 X10. Y0 I5.\nG 28 Z0\nO004200404\n";
  const read_result r = iso::read(text, "p.nc");
  REQUIRE(r.errors.size() == 1);
  CHECK(r.errors[0].to_string() == "p.nc:2:5: error: unknown word 'G29'");
  const auto& b = r.parsed.blocks;
  CHECK(b[2].arc->plane == arc_plane::xy);
  CHECK(b[2].arc->centre_mm == kin5::vec3{5, 0, 0});
  CHECK(b[4].program_begin == "004200404");
  const read_result ok = iso::read("G0 X0 Y0 Z0\nG 80 G 28 Z0\nO004200404\n", "p.nc");
  REQUIRE(ok.ok());
  // G 28 is `machine_reference`, spelled by the writer; G 80 is kept as written.
  CHECK(iso::write(ok.parsed) == "G0 X0. Y0. Z0.\nG 80 G28 Z0.\nO004200404\n");
}

TEST_CASE("iso: a parameter in a whole-number word reads as the control rounds it") {
  // FANUC Custom Macro B: a real value used where an integer is required is rounded to the
  // nearest whole number (1000.5 -> 1001, 1.4 -> 1, 3.5 -> 4); axis words keep every decimal.
  const std::string text =
      "#1 = 1000.5\n"
      "#2 = 1.4\n"
      "#3 = 3.5\n"
      "#4 = 10.1234\n"
      "T#2 M6\n"
      "G43 H#2\n"
      "S#1 M#3\n"
      "G1 X#4 F500.\n";
  const read_result r = iso::read(text, "p.nc");
  REQUIRE(r.errors.empty());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 8);
  CHECK(b[4].tool == 1);
  CHECK(b[5].state.length_compensation == true);
  CHECK(b[5].state.length_register == 1);
  CHECK(b[6].spindle_rpm == 1001.0);
  CHECK((b[6].m_codes.empty() && b[6].state.spindle == spindle_rotation::counter_clockwise));
  CHECK(b[7].axes.x_mm == 10.1234);
}

TEST_CASE("iso: a number written only in a parameter counts for the program's resolution") {
  // `X#1` with `#1 = 10.1234` is the literal X10.1234: 4 decimals for positions, so the output
  // keeps them; a parameter reassigned to a coarser number counts as that from then on.
  const dialect iso_id = id_of<iso::dialect>();
  const auto r = scan_resolution("N5 #1 = 10.1234\n#2=-0.12345\nG1 X1.5 Y2. F100.\nG1 X#1 B-#2 (X#2)\n", iso_id);
  CHECK(r.linear_decimals == 4);
  CHECK(r.angle_decimals == 5);
  const auto later = scan_resolution("#1 = 1.5\nG1 Z#1\n#1 = 1.12345\n", iso_id);
  CHECK(later.linear_decimals == 1);
  const auto unassigned = scan_resolution("G1 X#7 Y1.25\n", iso_id);
  CHECK(unassigned.linear_decimals == 2);
}

TEST_CASE("iso: an incremental rotary word after G28 counts from the source machine's reference angle") {
  // G28 sends B to its reference point; the machine file's home_deg says which angle that is.
  const std::string text = "G21 G90\nG0 X0. Y0. Z50. B10. C20.\nG91 G28 B0.\nG0 B-37.576\nG28 C0.\nG0 C5.\n";
  const read_result unknown = iso::read(text, "h.nc");
  REQUIRE(unknown.errors.size() == 2);
  CHECK(unknown.errors[0].where == source_location{"h.nc", 4, 4});
  CHECK(unknown.errors[0].message.starts_with("incremental B (G91 of line 3) from a position the program does not say"));
  CHECK(unknown.errors[0].message.ends_with(", or give home_deg in B's [[rotary]] table of the source machine file, the "
                                            "angle G28 leaves it at (--from-file; docs/machine-files.md)"));
  CHECK(unknown.errors[1].where == source_location{"h.nc", 6, 4});
  read_limits limits;
  limits.rotary_home_deg = {std::nullopt, -90.0, 0.5};  // A, B, C
  const read_limits_scope scope(limits);
  const read_result r = iso::read(text, "h.nc");
  REQUIRE(r.errors.empty());
  std::vector<double> b, c;
  for (const block& k : r.parsed.blocks) {
    if (k.axes.b_deg && !k.machine_coordinates) b.push_back(*k.axes.b_deg);
    if (k.axes.c_deg && !k.machine_coordinates) c.push_back(*k.axes.c_deg);
  }
  CHECK(b == std::vector<double>{10., -127.576});
  CHECK(c == std::vector<double>{20., 5.5});
}

TEST_CASE("iso: M98 and G65 of a program in another file run it when its directory is given") {
  const called_dir dir("iso-calls");
  dir.write("o1000.NC", "%\nO1000 (POCKET)\nG1 X#100 F100.\n#100 = #100 + 1.\nM99\n%\n");  // another case
  dir.write("O0020", "O0020\nG1 Y#1\nM99\n");                                              // padded to 4 digits
  dir.write("1003.nc", "G1 Z1.\nG1 Z#101\nM99\n");
  const std::string main = "#100 = 1.\nM98 P21000\nG65 P20 A7.\nM98 P1003\nM30\n";
  read_limits limits;
  limits.include_dirs = {(dir.path / "none").string(), dir.path.string()};
  {
    const read_limits_scope scope(limits);
    const read_result r = iso::read(main, "main.nc");
    REQUIRE(r.errors.size() == 1);  // #101 has no value: the error is in the called file, at its line
    CHECK(r.errors[0].where.file.str() == (dir.path / "1003.nc").string());
    CHECK(r.errors[0].where.line == 2);
    std::vector<double> x, y;
    for (const block& b : r.parsed.blocks) {
      if (b.axes.x_mm) x.push_back(*b.axes.x_mm);
      if (b.axes.y_mm) y.push_back(*b.axes.y_mm);
      CHECK_FALSE(b.framing);  // a called file's % lines are its own, not the program's
    }
    CHECK(x == std::vector<double>{1., 2.});
    CHECK(y == std::vector<double>{7.});
    CHECK(r.parsed.blocks[1].where.file.str() == (dir.path / "o1000.NC").string());
    CHECK(r.parsed.blocks[1].where.line == 3);
  }
  // Without the directory, the call is refused at its line, naming the files it would need.
  const read_result none = iso::read(main, "main.nc");
  REQUIRE_FALSE(none.errors.empty());
  CHECK(none.errors[0].to_string() ==
        "main.nc:2:1: error: call of O1000: no label O1000 in this file, and no directory to look for its file O1000, "
        "O1000.nc or 1000.nc in (--include-dir DIR names the directory that holds it)");
  // M30 in a called program is refused: it ends with M99.
  dir.write("O7.nc", "G1 X1.\nM30\n");
  const read_limits_scope scope(limits);
  const read_result ends = iso::read("M98 P7\nM30\n", "main.nc");
  REQUIRE_FALSE(ends.errors.empty());
  CHECK(ends.errors[0].where.line == 2);
  CHECK(ends.errors[0].message.starts_with("the end of the program (M30, M2) in a called program"));
}
