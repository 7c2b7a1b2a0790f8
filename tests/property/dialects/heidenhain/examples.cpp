// Real-world Heidenhain habits on a small hand-written program in the style of NX output and
// hand edits (unnumbered header, repeated numbers, `~` continuation, `*` sections, `;`-disabled
// lines, other encodings in comments, CRLF), with hand-derived expectations.
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/address_words.hpp>
#include <kin5/program/heidenhain/dialect.hpp>
#include <kin5/program/iso/dialect.hpp>
#include <kin5/program/read_limits.hpp>

#include "../called_dir.hpp"

using namespace kin5::program;
using kin5::vec3;

namespace {
const std::string program_text =
    "BEGIN PGM BRACKET MM\r\n"
    "M129\r\n"
    "PLANE RESET STAY\r\n"
    "BLK FORM 0.1 Z X-32.746~\r\n"
    "Y-32.697 Z-74.399; BLANK\r\n"
    "1 ; \r\n"
    "2 ;  OPERATION: ROUGH - TOOL: T3 D10.0\r\n"
    "3 TOOL CALL  3 Z S8000\r\n"
    "4 L X-450. Y-10. FMAX M91\r\n"
    "5 L B0.0 C0.0 FMAX\r\n"
    "6 l x61. y.5 fmax m3\r\n"
    "\r\n"
    "6 L Z-.25 F1000. M8 ; plunge\r\n"
    "* - FINISH \xC4\xE3\r\n"
    "8 CC X+10 Y+0\r\n"
    "9 C X+20 Y+0 DR- R0\r\n"
    "10 CR X+30 Y+10 R+10 DR+\r\n"
    "11 LN X+1 Y+2 Z+3 TX+0 TY-0.7071068 TZ+0.7071068 F500\r\n"
    "12 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\r\n"
    "13 L X+34.983 Y+118.526 Z+9.1 B+17.067 C+87.479 R0 F1137 M128\r\n"
    "14 ;L X+0 Y+0 M128\r\n"
    "15 FUNCTION RESET TCPM\r\n"
    "16 TOOL DEF 5\r\n"
    "17\r\n"
    "18 M5 M9\r\n"
    "19 M30\r\n"
    "20 END PGM BRACKET MM\r\n";
}  // namespace

TEST_CASE("heidenhain: a program in NX and hand-edit style") {
  const read_result r = heidenhain::read(program_text, "b.h");
  REQUIRE(r.errors.empty());
  CHECK(r.warnings.empty());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 25);
  CHECK((b[0].program_begin == "BRACKET" && b[0].metric == true && !b[0].number));
  CHECK((b[1].tcp == false && b[1].m_codes.empty()));
  CHECK((b[2].passthrough && b[2].text == "PLANE RESET STAY"));
  CHECK((b[3].passthrough && b[3].text == "BLK FORM 0.1 Z X-32.746~\nY-32.697 Z-74.399; BLANK"));
  CHECK((b[4].number == 1 && b[4].comment == " " && b[4].where.line == 6));
  CHECK(b[5].comment == "  OPERATION: ROUGH - TOOL: T3 D10.0");
  CHECK((b[6].tool == 3 && b[6].spindle_rpm == 8000.0 && b[6].kept_words == std::vector<std::string>{"Z"}));
  CHECK((b[6].state.tool_change && b[6].m_codes.empty()));  // TOOL CALL n is a tool change
  CHECK((b[7].motion == motion_kind::rapid && b[7].feed_rapid && b[7].axes.x_mm == -450.0 && b[7].axes.y_mm == -10.0));
  CHECK((b[7].machine_coordinates && b[7].m_codes == std::vector<int>{91}));
  CHECK((b[8].axes.b_deg == 0.0 && b[8].axes.c_deg == 0.0 && !b[8].axes.has_linear()));
  CHECK((b[9].number == 6 && b[9].axes.x_mm == 61.0 && b[9].axes.y_mm == 0.5 && b[9].state.spindle == spindle_rotation::clockwise));
  CHECK((b[10].number == 6 && b[10].where.line == 13 && b[10].axes.z_mm == -0.25 && b[10].feed == 1000.0));
  CHECK((b[10].motion == motion_kind::linear && !b[10].feed_rapid && b[10].comment == " plunge"));
  CHECK((b[11].comment == " - FINISH \xC4\xE3" && !b[11].number));
  // CC gives X and Y; Z comes from the last position (Z-.25).
  REQUIRE(b[12].arc);
  CHECK((b[12].arc->centre_mm == vec3{10, 0, -0.25} && b[12].arc->plane == arc_plane::xy));
  CHECK((!b[12].motion && !b[12].moves()));
  REQUIRE(b[13].arc);
  CHECK((b[13].motion == motion_kind::arc_cw && b[13].axes.x_mm == 20.0 && b[13].axes.y_mm == 0.0));
  CHECK((b[13].arc->centre_mm == vec3{10, 0, -0.25} && b[13].kept_words == std::vector<std::string>{"R0"}));
  REQUIRE(b[14].arc);
  CHECK((b[14].motion == motion_kind::arc_ccw && b[14].arc->radius_mm == 10.0 && !b[14].arc->centre_mm));
  CHECK((b[15].motion == motion_kind::linear && b[15].axes.tool_axis == vec3{0, -0.7071068, 0.7071068}));
  CHECK((b[15].axes.z_mm == 3.0 && b[15].feed == 500.0));
  CHECK((b[16].tcp == true && b[16].kept_words == std::vector<std::string>{"F TCP", "AXIS POS", "PATHCTRL AXIS"}));
  // Table 1, row 1, DMU side (docs/golden.md).
  CHECK((b[17].axes.x_mm == 34.983 && b[17].axes.y_mm == 118.526 && b[17].axes.z_mm == 9.1));
  CHECK((b[17].axes.b_deg == 17.067 && b[17].axes.c_deg == 87.479 && b[17].feed == 1137.0 && b[17].tcp == true));
  CHECK((b[17].m_codes.empty() && b[17].kept_words == std::vector<std::string>{"R0"}));
  CHECK((b[18].comment == "L X+0 Y+0 M128" && !b[18].tcp));
  CHECK(b[19].tcp == false);
  CHECK((b[20].passthrough && b[20].text == "16 TOOL DEF 5"));
  CHECK((b[21].number == 17 && !b[21].comment && !b[21].passthrough && !b[21].motion));
  CHECK((b[22].m_codes.empty() && b[22].state.spindle == spindle_rotation::stopped &&
         b[22].state.coolant_flood == false && b[22].state.coolant_mist == false));
  CHECK(b[23].m_codes == std::vector<int>{30});
  CHECK((b[24].program_end == "BRACKET" && b[24].metric == true));
}

TEST_CASE("heidenhain: M140 MB MAX is a retract along the tool axis, M92 the builder's point, both written back") {
  const std::string text = "0 BEGIN PGM T MM\n1 M140 MB MAX M9 M117\n2 L X-450 Y-10 FMAX M92\n3 L Z+0 R0 FMAX M91\n4 END PGM T MM\n";
  const read_result r = heidenhain::read(text, "t.h");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  CHECK((b[1].machine_coordinates && b[1].machine_reference == machine_position::tool_axis_limit && b[1].axes.empty()));
  // M9 beside it is the coolant switched off (a state word), M117 the machine maker's number.
  CHECK((b[1].state.coolant_flood == false && b[1].state.coolant_mist == false));
  CHECK(b[1].m_codes == std::vector<int>{117});
  CHECK((b[2].machine_coordinates && b[2].machine_reference == machine_position::builder_position));
  CHECK((b[3].machine_coordinates && b[3].machine_reference == machine_position::machine_zero));
  const std::string written = heidenhain::write(r.parsed);
  CHECK_THAT(written, Catch::Contains("M140 MB MAX M9 M117"));
  const read_result back = heidenhain::read(written, "t.h");
  REQUIRE(back.ok());
  for (std::size_t k = 0; k < b.size(); ++k) {
    CHECK(back.parsed.blocks[k].machine_reference == b[k].machine_reference);
    CHECK(back.parsed.blocks[k].m_codes == b[k].m_codes);
    CHECK(back.parsed.blocks[k].state == b[k].state);
  }
  // Another dialect has no M140 MB MAX, nor M92: a bare write refuses them, never a G53.
  CHECK_THROWS_WITH(iso::write(r.parsed), Catch::Contains("M140 MB MAX"));
}

TEST_CASE("heidenhain: an M word said again after another of its group is read once, and writes back the same") {
  // Found by the fuzzer: M3 M3 M4 M3 kept the last M3 as a number, which the writer left out
  // (it writes each M function once), so the block read back without it.
  const read_result r = heidenhain::read("0 BEGIN PGM T MM\n1 M3 M3 M4 M3\n2 END PGM T MM\n", "t.h");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks[1];
  CHECK(b.state.spindle == spindle_rotation::clockwise);
  CHECK(b.m_codes == std::vector<int>{4});
  const read_result back = heidenhain::read(heidenhain::write(r.parsed), "t.h");
  REQUIRE(back.ok());
  CHECK(back.parsed.blocks[1].m_codes == b.m_codes);
  CHECK(back.parsed.blocks[1].state == b.state);
}

TEST_CASE("heidenhain: a tool call by name is read, TOOL CALL's axis sets the plane") {
  const read_result r = heidenhain::read(
      "TOOL CALL \"MILL_D10\" Z S5000 DL+0.1\nTOOL CALL 5 Y\nCR X+1 Z+0 R+5 DR+\nTOOL CALL \"\" Z\n", "n.h");
  REQUIRE(r.errors.size() == 2);
  CHECK(r.errors[0].to_string() ==
        "n.h:1:30: error: DL+0.1: a tool oversize in TOOL CALL is not supported yet (the path would move by it)");
  CHECK(r.errors[1].to_string() ==
        "n.h:4:1: error: TOOL CALL: only TOOL CALL n or \"name\" with an axis, S, F, DL and DR is read (a tool called "
        "with other words is not supported)");
  REQUIRE(r.parsed.blocks.size() == 4);
  CHECK(r.parsed.blocks[0].tool_name == "MILL_D10");
  CHECK_FALSE(r.parsed.blocks[0].tool);
  CHECK(r.parsed.blocks[0].state.tool_change);
  CHECK(r.parsed.blocks[0].spindle_rpm == 5000);
  CHECK(r.parsed.blocks[3].passthrough);
  CHECK((r.parsed.blocks[1].tool == 5 && r.parsed.blocks[1].kept_words == std::vector<std::string>{"Y"}));
  // TOOL CALL … Y makes ZX the working plane of the radius arc.
  REQUIRE(r.parsed.blocks[2].arc);
  CHECK(r.parsed.blocks[2].arc->plane == arc_plane::zx);
}

TEST_CASE("heidenhain: another END PGM name is read with a warning and written as the BEGIN PGM's") {
  // CAM posts write the part number in one and the file name in the other; a name moves nothing.
  const read_result r = heidenhain::read("BEGIN PGM PART-7 MM\nL X+1 Y+2 Z+3 R0 F100\nEND PGM 7 MM\n", "p.h");
  REQUIRE(r.errors.empty());
  REQUIRE(r.warnings.size() == 1);
  CHECK(r.warnings[0].where == source_location{"p.h", 3, 9});
  CHECK(r.warnings[0].message.starts_with("END PGM name 7 differs from BEGIN PGM's PART-7: "));
  const std::string written = heidenhain::write(r.parsed);
  CHECK(written.find("BEGIN PGM PART-7 MM\n") != std::string::npos);
  CHECK(written.find("END PGM PART-7 MM\n") != std::string::npos);
  CHECK(written.find("END PGM 7") == std::string::npos);
  const read_result back = heidenhain::read(written, "w.h");
  CHECK((back.errors.empty() && back.warnings.empty()));
}

TEST_CASE("heidenhain: the writer numbers blocks from 0 in Heidenhain style") {
  const read_result r = heidenhain::read(program_text, "b.h");
  const std::string expected =
      "0 BEGIN PGM BRACKET MM\n"
      "1 M129\n"
      "2 PLANE RESET STAY\n"
      "3 BLK FORM 0.1 Z X-32.746~\n"
      "Y-32.697 Z-74.399; BLANK\n"
      "4 ; \n"
      "5 ;  OPERATION: ROUGH - TOOL: T3 D10.0\n"
      "6 TOOL CALL 3 Z S8000\n"
      "7 L X-450 Y-10 FMAX M91\n"
      "8 L B+0 C+0 FMAX\n"
      "9 L X+61 Y+0.5 FMAX M3\n"
      "10 L Z-0.25 F1000 M8 ; plunge\n"
      "11 ; - FINISH \xC4\xE3\n"
      "12 CC X+10 Y+0\n"
      "13 C X+20 Y+0 DR- R0\n"
      "14 CR X+30 Y+10 R+10 DR+\n"
      "15 LN X+1 Y+2 Z+3 TX+0 TY-0.7071068 TZ+0.7071068 F500\n"
      "16 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
      "17 L X+34.983 Y+118.526 Z+9.1 B+17.067 C+87.479 R0 F1137 M128\n"
      "18 ;L X+0 Y+0 M128\n"
      "19 M129\n"
      "20 TOOL DEF 5\n"
      "21\n"
      "22 M5 M9\n"
      "23 M30\n"
      "24 END PGM BRACKET MM\n";  // the control pairs BEGIN PGM and END PGM by name
  CHECK(heidenhain::write(r.parsed) == expected);
}

TEST_CASE("heidenhain: blocks from another dialect are written, and what has no Heidenhain form is kept as a comment") {
  program p;
  p.language = id_of<iso::dialect>();
  p.file = "in.nc";
  block b;
  b.program_begin = "O1234 BRACKET";
  p.blocks.push_back(b);
  b = {};
  b.passthrough = true;
  b.text = "G05.1 Q1";
  p.blocks.push_back(b);
  b = {};
  b.motion = motion_kind::linear;
  b.axes.x_mm = 10;
  b.kept_words = {"G17", "G40"};
  p.blocks.push_back(b);
  b = {};
  b.motion = motion_kind::arc_ccw;  // G3 X20 Y0 I5 J0 from X10 Y0: the centre comes first as CC
  b.axes.x_mm = 20;
  b.axes.y_mm = 0;
  b.arc = arc_words{arc_plane::xy, vec3{15, 0, 0}, std::nullopt};
  b.feed = 250;
  p.blocks.push_back(b);
  b = {};
  b.tool = 4;
  b.state.tool_change = true;
  p.blocks.push_back(b);
  b = {};
  b.motion = motion_kind::rapid;  // G53 G0 Z0
  b.axes.z_mm = 0;
  b.machine_coordinates = true;
  p.blocks.push_back(b);
  b = {};
  b.program_end = "";
  b.comment = "end";
  p.blocks.push_back(b);
  CHECK(heidenhain::write(p) ==
        "0 BEGIN PGM O1234_BRACKET MM\n"
        "1 ;G05.1 Q1\n"
        "2 L X+10 ;kept: G17 G40\n"
        "3 CC X+15 Y+0\n"
        "4 C X+20 Y+0 DR+ F250\n"
        "5 TOOL CALL 4 Z\n"  // TOOL CALL is the tool change: the ISO M6 is not written again
        "6 L Z+0 FMAX M91\n"
        "7 M30 ;end\n"  // ISO's end of program run, then the frame's closing line
        "8 END PGM O1234_BRACKET MM\n");
}

TEST_CASE("heidenhain: an L without coordinates is not written, its F goes to the next move") {
  const auto r = heidenhain::read("0 L X+1 Y+2 Z+3 FMAX\n1 L F800 M3\n2 L X+4\n3 L X+5\n4 L FMAX\n5 L Z+6\n", "t.h");
  REQUIRE(r.ok());
  CHECK(heidenhain::write(r.parsed) ==
        "0 BEGIN PGM PGM MM\n"
        "1 L X+1 Y+2 Z+3 FMAX\n"
        "2 M3\n"
        "3 L X+4 F800\n"
        "4 L X+5\n"
        "5 ;L FMAX\n"
        "6 L Z+6\n"
        "7 END PGM PGM MM\n");
}

TEST_CASE("heidenhain: a number written only in a Q parameter counts for the program's resolution") {
  // `L X+Q1` with `Q1 = +10.1234` is the literal X+10.1234; `F Q2` a feed of 2 decimals.
  const dialect id = id_of<heidenhain::dialect>();
  const auto r = scan_resolution("0 BEGIN PGM P MM\n1 Q1 = +10.1234\n2 FN 0: Q2 = 250.25\n3 L X+Q1 Y+1.5 F Q2\n"
                                 "4 L Y-Q1 R0 FMAX\n5 END PGM P MM\n", id);
  CHECK(r.linear_decimals == 4);
  CHECK(r.feed_decimals == 2);
  const auto unused = scan_resolution("1 Q1 = +10.1234\n2 L X+1.5 R0 FMAX\n", id);
  CHECK(unused.linear_decimals == 1);
}

namespace {
/// Each move of `r` as "FILE:LINE X…Y…Z…", the file without its directory, whole millimetres.
std::vector<std::string> moves_of(const read_result& r) {
  std::vector<std::string> out;
  for (const block& b : r.parsed.blocks)
    if (b.axes.x_mm || b.axes.y_mm || b.axes.z_mm)
      out.push_back(std::filesystem::path(b.where.file.str()).filename().string() + ":" + std::to_string(b.where.line) + " " +
                    (b.axes.x_mm ? "X" + std::to_string(static_cast<int>(*b.axes.x_mm)) : "") +
                    (b.axes.y_mm ? "Y" + std::to_string(static_cast<int>(*b.axes.y_mm)) : "") +
                    (b.axes.z_mm ? "Z" + std::to_string(static_cast<int>(*b.axes.z_mm)) : ""));
  return out;
}
}  // namespace

TEST_CASE("heidenhain: CALL PGM runs the program in another file to its END PGM, with the caller's Q") {
  const called_dir dir("heidenhain-calls");
  // Q parameters are shared with the caller; QL are each program's own (TNC 640 User's Manual,
  // "Calling any program as a subprogram"; "Principle and overview" of Q parameters).
  dir.write("SUB.H", "0 BEGIN PGM SUB MM\n1 L X+Q1 R0 F100\n2 Q1 = Q1 + 1\n3 QL1 = 7\n4 L Y+QL1\n5 END PGM SUB MM\n");
  std::filesystem::create_directories(dir.path / "parts");
  dir.write("parts/DEEP.h", "0 BEGIN PGM DEEP MM\n1 L Z+5 ~\n  FMAX\n2 END PGM DEEP MM\n3 L Z+99\n");
  const std::string main = "0 BEGIN PGM MAIN MM\n1 Q1 = 10\n2 QL1 = 3\n3 CALL PGM SUB ;first\n4 CALL PGM sub.h\n"
                           "5 L X+QL1\n6 CALL PGM parts\\DEEP\n7 CALL PGM TNC:\\nc_prog\\SUB.H\n8 END PGM MAIN MM\n";
  read_limits limits;
  limits.include_dirs = {(dir.path / "none").string(), dir.path.string()};
  {
    const read_limits_scope scope(limits);
    const read_result r = heidenhain::read(main, "main.h");
    REQUIRE(r.errors.empty());
    CHECK(moves_of(r) == std::vector<std::string>{"SUB.H:2 X10", "SUB.H:5 Y7", "SUB.H:2 X11", "SUB.H:5 Y7",
                                                  "main.h:6 X3", "DEEP.h:2 Z5", "SUB.H:2 X12", "SUB.H:5 Y7"});
    std::size_t begins = 0, ends = 0;
    for (const block& b : r.parsed.blocks) begins += b.program_begin.has_value(), ends += b.program_end.has_value();
    CHECK((begins == 1 && ends == 1));  // the called programs' frames are not the program's
  }
  // Without the directory, the call is refused at its line, naming the file.
  const read_result none = heidenhain::read(main, "main.h");
  REQUIRE(none.errors.size() == 1);
  CHECK(none.errors[0].to_string() ==
        "main.h:4:3: error: call of PGM SUB: SUB.h: no directory to look for it in (--include-dir DIR names the "
        "directory that holds it)");
  // A program read from a file finds the programs it calls beside it, as the TNC does.
  dir.write("main.h", main);
  const read_result beside = heidenhain::read(main, (dir.path / "main.h").string());
  CHECK(beside.errors.empty());
  CHECK(moves_of(beside).size() == 8);
}

TEST_CASE("heidenhain: what a program CALL PGM runs may not do is refused in its own file") {
  const called_dir dir("heidenhain-called-errors");
  dir.write("BAD.h", "0 BEGIN PGM BAD MM\n1 L X+Q77 R0 FMAX\n2 END PGM BAD MM\n");
  dir.write("ENDS.h", "0 BEGIN PGM ENDS MM\n1 L X+1 R0 FMAX\n2 M30\n3 END PGM ENDS MM\n");
  dir.write("INCH.h", "0 BEGIN PGM INCH INCH\n1 L X+1 R0 FMAX\n2 END PGM INCH INCH\n");
  dir.write("OPEN.h", "0 BEGIN PGM OPEN MM\n1 L X+1 R0 FMAX\n");
  read_limits limits;
  limits.include_dirs = {dir.path.string()};
  const read_limits_scope scope(limits);
  const auto error_of = [](const std::string& called) {
    const read_result r = heidenhain::read("0 BEGIN PGM M MM\n1 CALL PGM " + called + "\n2 END PGM M MM\n", "m.h");
    REQUIRE_FALSE(r.errors.empty());
    return std::filesystem::path(r.errors[0].where.file.str()).filename().string() + ":" +
           std::to_string(r.errors[0].where.line) + ": " + r.errors[0].message;
  };
  CHECK(error_of("BAD").starts_with("BAD.h:2: "));
  CHECK(error_of("ENDS").starts_with("ENDS.h:3: M2 or M30 in a program that CALL PGM runs"));
  CHECK(error_of("INCH").starts_with("INCH.h:1: BEGIN PGM INCH: a called program in INCH from a program in MM"));
  CHECK(error_of("OPEN").starts_with("OPEN.h:2: the called file ends without returning to the call from line 2"));
}
