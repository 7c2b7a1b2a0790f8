// Hand-written Siemens programs in the styles found in real 840D output, each checked against
// values worked out by hand (Table 1 of Tian et al. 2010, docs/golden.md, for the SAJO blocks).
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/address_words.hpp>
#include <kin5/program/read_limits.hpp>
#include <kin5/program/siemens/dialect.hpp>

#include "../called_dir.hpp"

namespace {

using namespace kin5::program;
using kin5::vec3;

read_result read_ok(std::string_view text) {
  read_result r = siemens::read(text, "q.mpf");
  for (const auto& e : r.errors) UNSCOPED_INFO(e.to_string());
  REQUIRE(r.ok());
  return r;
}

}  // namespace

TEST_CASE("siemens: Table 1 blocks, with and without spaces", "[siemens][quirks]") {
  const auto r = read_ok(
      "N10 G1 X-34.983Y9.100Z118.526A-77.954B3.536F1091\n"
      "N20 X-33.824 Y9.118 Z117.545 A-77.913 B4.027 F1093\n");
  REQUIRE(r.parsed.blocks.size() == 2);
  const block& a = r.parsed.blocks[0];
  CHECK(a.number == 10);
  CHECK(a.motion == motion_kind::linear);
  CHECK(a.axes.x_mm == -34.983);
  CHECK(a.axes.y_mm == 9.1);
  CHECK(a.axes.z_mm == 118.526);
  CHECK(a.axes.a_deg == -77.954);
  CHECK(a.axes.b_deg == 3.536);
  CHECK_FALSE(a.axes.c_deg);
  CHECK(a.feed == 1091);
  const block& b = r.parsed.blocks[1];
  CHECK_FALSE(b.motion);  // modal: the block says nothing about G1
  CHECK(b.axes.x_mm == -33.824);
  CHECK(b.axes.b_deg == 4.027);
  CHECK(b.feed == 1093);
  CHECK(siemens::write(r.parsed) ==
        "N10 G1 X-34.983 Y9.1 Z118.526 A-77.954 B3.536 F1091\n"
        "N20 X-33.824 Y9.118 Z117.545 A-77.913 B4.027 F1093\n");
}

TEST_CASE("siemens: a whole program with header, set-up, TRAORI and end", "[siemens][quirks]") {
  const auto r = read_ok(
      "%_N_SAJO_MPF\r\n"
      ";$PATH=/_N_MPF_DIR\r\n"
      "N10 G17 G90 G71 G94 SOFT FFWON G642\r\n"
      "N20 T=\"MILL_6\" D1 M6\r\n"
      "N30 S4000 M3\r\n"
      "\r\n"
      "N40 TRAORI(1)\r\n"
      "N50 G0 SUPA Z0\r\n"
      "N60 G153 G0 X0 Y0\r\n"
      "N70 TRAFOOF\r\n"
      "N80 M30\r\n");
  const auto& bl = r.parsed.blocks;
  REQUIRE(bl.size() == 10);
  CHECK(bl[0].program_begin == "SAJO");
  CHECK(bl[1].comment == "$PATH=/_N_MPF_DIR");
  CHECK(bl[2].kept_words == std::vector<std::string>{"SOFT", "FFWON", "G642"});
  CHECK((bl[2].state.working_plane == arc_plane::xy && bl[2].state.distance == distance_mode::absolute));
  CHECK(bl[2].metric == true);
  CHECK(bl[2].feed_mode == feed_unit::per_minute);
  CHECK(bl[3].kept_words == std::vector<std::string>{"D1"});
  CHECK(bl[3].tool_name == "MILL_6");
  CHECK_FALSE(bl[3].tool);
  CHECK((bl[3].state.tool_change && bl[3].m_codes.empty()));
  CHECK(bl[4].spindle_rpm == 4000);
  CHECK(bl[4].state.spindle == spindle_rotation::clockwise);
  CHECK(bl[5].where.line == 7);  // the empty line is skipped but counted
  CHECK(bl[5].tcp == true);
  CHECK(bl[6].machine_coordinates);
  CHECK(bl[6].motion == motion_kind::rapid);
  CHECK(bl[6].axes.z_mm == 0);
  CHECK(bl[7].machine_coordinates);
  CHECK(bl[8].tcp == false);
  CHECK(bl[9].m_codes.empty());  // M30 is in program_end only
  CHECK(bl[9].program_end == "SAJO");
  CHECK(r.warnings.empty());
  // The path statement as read: `;$PATH=` in the first column (`; $PATH=` would be a comment).
  CHECK(siemens::write(r.parsed) ==
        "%_N_SAJO_MPF\n"
        ";$PATH=/_N_MPF_DIR\n"
        "N10 G710 G94 G90 G17 SOFT FFWON G642\n"
        "N20 T=\"MILL_6\" D1 M6\n"
        "N30 S4000 M3\n"
        "N40 TRAORI\n"
        "N50 SUPA G0 Z0\n"
        "N60 SUPA G0 X0 Y0\n"
        "N70 TRAFOOF\n"
        "N80 M30\n");
}

TEST_CASE("siemens: spelling quirks", "[siemens][quirks]") {
  const auto r = read_ok("g1 x+10. y-.5 z = .25 a=+0 f=.5 t 7\rn0020G0X-450.Y2\r  N30\tg01 d02 g017 x 1\tM 03");
  REQUIRE(r.parsed.blocks.size() == 3);
  const block& a = r.parsed.blocks[0];
  CHECK(a.motion == motion_kind::linear);
  CHECK(a.axes.x_mm == 10);
  CHECK(a.axes.y_mm == -0.5);
  CHECK(a.axes.z_mm == 0.25);
  CHECK(a.axes.a_deg == 0);
  CHECK(a.feed == 0.5);
  CHECK(a.tool == 7);
  const block& b = r.parsed.blocks[1];
  CHECK(b.where == source_location{"q.mpf", 2, 1});
  CHECK(b.number == 20);
  CHECK(b.motion == motion_kind::rapid);
  CHECK(b.axes.x_mm == -450);
  CHECK(b.axes.y_mm == 2);
  const block& c = r.parsed.blocks[2];
  CHECK(c.where == source_location{"q.mpf", 3, 3});
  CHECK(c.text == "  N30\tg01 d02 g017 x 1\tM 03");
  CHECK(c.kept_words == std::vector<std::string>{"D2"});
  CHECK(c.state.working_plane == arc_plane::xy);
  CHECK(c.number == 30);
  CHECK(c.axes.x_mm == 1);
  CHECK((c.m_codes.empty() && c.state.spindle == spindle_rotation::clockwise));
}

TEST_CASE("siemens: comments of both kinds, bytes kept as they are", "[siemens][quirks]") {
  const auto r = read_ok("G1 (first) X1 ;  caf\xe9 \xff\x01 \nG1 X2 (only)\n(whole line)\n;\n");
  REQUIRE(r.parsed.blocks.size() == 4);
  CHECK(r.parsed.blocks[0].comment == "first caf\xe9 \xff\x01");
  CHECK(r.parsed.blocks[0].axes.x_mm == 1);
  CHECK(r.parsed.blocks[1].comment == "only");
  CHECK(r.parsed.blocks[2].comment == "whole line");
  CHECK_FALSE(r.parsed.blocks[2].moves());
  CHECK(r.parsed.blocks[3].comment == "");
  CHECK(siemens::write(r.parsed) == "G1 X1 ; first caf\xe9 \xff\x01\nG1 X2 ; only\n; whole line\n;\n");
}

TEST_CASE("siemens: I=AC(…) is the centre's own coordinate, under G90 and G91 alike", "[siemens][quirks]") {
  const auto r = read_ok(
      "G0 X30 Y20 Z5\n"
      "G2 X40 Y20 I=AC(35) J=AC(20)\n"     // centre (35, 20, 5)
      "G91 G3 X-10 Y0 I=AC(35) J=0\n"      // back to (30, 20): centre (35, 20 + 0, 5)
      "G90 G17 G2 X40 Y20 I5 J=AC(20)\n");  // one absolute, one offset: (30 + 5, 20, 5)
  const auto& bl = r.parsed.blocks;
  REQUIRE(bl.size() == 4);
  for (std::size_t i = 1; i < 4; ++i) {
    REQUIRE(bl[i].arc);
    CHECK(bl[i].arc->centre_mm == vec3{35, 20, 5});
  }
}

TEST_CASE("siemens: arcs get absolute centres from incremental I J K", "[siemens][quirks]") {
  const auto r = read_ok(
      "G0 X10 Y0 Z5\n"
      "G17 G3 X0 Y10 I-10 J0\n"    // centre (10-10, 0+0, 5) = (0, 0, 5)
      "G18 G2 X-20 Z5 I-10 K0\n"   // from (0, 10, 5): centre (-10, 10, 5)
      "X0 Z25 CR=-10\n"            // modal G2, radius form, plane zx
      "G19 G3 Y10 Z15 J0 K-5 I2\n"  // from (0, 10, 25): centre (2, 10, 20)
      "G1 X0 Y0\n");
  const auto& bl = r.parsed.blocks;
  REQUIRE(bl.size() == 6);
  CHECK_FALSE(bl[0].arc);
  REQUIRE(bl[1].arc);
  CHECK(bl[1].motion == motion_kind::arc_ccw);
  CHECK(bl[1].arc->plane == arc_plane::xy);
  CHECK(bl[1].arc->centre_mm == vec3{0, 0, 5});
  REQUIRE(bl[2].arc);
  CHECK(bl[2].motion == motion_kind::arc_cw);
  CHECK(bl[2].arc->plane == arc_plane::zx);
  CHECK(bl[2].arc->centre_mm == vec3{-10, 10, 5});
  REQUIRE(bl[3].arc);
  CHECK_FALSE(bl[3].motion);
  CHECK(bl[3].arc->plane == arc_plane::zx);
  CHECK_FALSE(bl[3].arc->centre_mm);
  CHECK(bl[3].arc->radius_mm == -10);
  REQUIRE(bl[4].arc);
  CHECK(bl[4].arc->plane == arc_plane::yz);
  CHECK(bl[4].arc->centre_mm == vec3{2, 10, 20});
  CHECK_FALSE(bl[5].arc);
  CHECK(siemens::write(r.parsed) ==
        "G0 X10 Y0 Z5\n"
        "G17 G3 X0 Y10 I-10 J0\n"
        "G18 G2 X-20 Z5 I-10 K0\n"
        "X0 Z25 CR=-10\n"
        "G19 G3 Y10 Z15 I2 J0 K-5\n"
        "G1 X0 Y0\n");
}

TEST_CASE("siemens: TRAORI forms, tool-axis vectors, MSG and resets", "[siemens][quirks]") {
  const auto r = siemens::read(
      "TRAORI\n"
      "traori(1)\n"
      "TRAORI(2, 0, 0, 1)\n"
      "G1 X1 Y2 Z3 A3=0 B3=-.6 C3=.8 MSG(\"tilted\")\n"
      "MSG(\"alone\")\n"
      "CYCLE800()\n"
      "TRANS\n"
      "CYCLE800(0,\"TC1\",200000,57,0,0,0,0,0,0,0,0,0,-1,100,1)\n",
      "q.mpf");
  REQUIRE(r.ok());
  const auto& bl = r.parsed.blocks;
  REQUIRE(bl.size() == 8);
  CHECK(bl[0].tcp == true);
  CHECK(bl[1].tcp == true);
  CHECK(bl[2].tcp == true);
  REQUIRE(r.warnings.size() == 1);
  CHECK(r.warnings[0].to_string("warning") == "q.mpf:3:1: warning: arguments of TRAORI(2, 0, 0, 1) are not kept; written as TRAORI");
  CHECK(bl[3].axes.tool_axis == vec3{0, -0.6, 0.8});
  CHECK(bl[3].kept_words == std::vector<std::string>{"MSG(\"tilted\")"});
  CHECK(bl[4].passthrough);
  CHECK(bl[5].kept_words == std::vector<std::string>{"CYCLE800()"});
  CHECK(bl[6].kept_words == std::vector<std::string>{"TRANS"});
  CHECK(bl[7].kept_words.size() == 1);
  CHECK(siemens::write(r.parsed) ==
        "TRAORI\nTRAORI\nTRAORI\nMSG(\"tilted\") G1 X1 Y2 Z3 A3=0 B3=-0.6 C3=0.8\nMSG(\"alone\")\nCYCLE800()\nTRANS\n"
        "CYCLE800(0,\"TC1\",200000,57,0,0,0,0,0,0,0,0,0,-1,100,1)\n");
}

TEST_CASE("siemens: program ends, names and odd lines", "[siemens][quirks]") {
  const auto r = read_ok("N1 M2\n%MPF123\n   \n%\nM30\n%_N_SUB_SPF\nM17\n");
  const auto& bl = r.parsed.blocks;
  REQUIRE(bl.size() == 7);
  CHECK(bl[0].program_end == "M2");  // no header yet: the end word
  CHECK(bl[0].m_codes.empty());       // an end M code lives in program_end only
  CHECK(bl[1].program_begin == "MPF123");
  CHECK(bl[2].passthrough);  // blanks only
  CHECK(bl[3].passthrough);  // a bare '%'
  CHECK(bl[4].program_end == "MPF123");
  CHECK(bl[5].program_begin == "SUB_SPF");
  CHECK(bl[6].m_codes == std::vector<int>{17});
  CHECK_FALSE(bl[6].program_end);
  CHECK(siemens::write(r.parsed) == "N1 M2\n%_N_MPF123_MPF\n   \n%\nM30\n%_N_SUB_SPF\nM17\n");
}

TEST_CASE("siemens: writing another dialect's program", "[siemens][quirks]") {
  program p;
  p.language = id_of<heidenhain::dialect>();
  p.file = "part.h";
  block begin;
  begin.number = 0;
  begin.program_begin = "PART 1";
  begin.metric = true;
  block tcp;
  tcp.number = 1;
  tcp.tcp = true;
  tcp.kept_words = {"M126"};
  block rapid;
  rapid.number = 2;
  rapid.motion = motion_kind::linear;
  rapid.feed_rapid = true;
  rapid.axes.z_mm = 100;
  block next;
  next.number = 3;
  next.axes.x_mm = 5;
  next.feed = 500;
  next.comment = "cut";
  block cycle;
  cycle.number = 4;
  cycle.passthrough = true;
  cycle.text = "4 CYCL DEF 200 BOHREN";
  block end;
  end.number = 5;
  end.program_end = "PART 1";
  p.blocks = {begin, tcp, rapid, next, cycle, end};
  CHECK(siemens::write(p) ==
        "%_N_PART_1_MPF\n"
        ";$PATH=/_N_MPF_DIR\n"
        "N0 G710\n"
        "N1 TRAORI ; M126\n"
        "N2 G0 Z100\n"
        "N3 G1 X5 F500 ; cut\n"
        "; 4 CYCL DEF 200 BOHREN\n"
        "N5 M30\n");
}

TEST_CASE("siemens: write options set the decimals", "[siemens][quirks]") {
  siemens::write_options o;
  o.linear_decimals = 1;
  o.angle_decimals = 2;
  o.feed_decimals = 0;
  o.vector_decimals = 4;
  const auto v = read_ok("G1 X-34.983 A-77.954 F1091.25 S4000.4\nG1 A3=0.123456789 B3=0 C3=1\n");
  CHECK(siemens::write(v.parsed, o) == "G1 X-35 A-77.95 F1091 S4000\nG1 A3=0.1235 B3=0 C3=1\n");
}

TEST_CASE("siemens: a number written only in an R parameter counts for the program's resolution") {
  // `X=R1` with `R1=10.1234` is the literal X10.1234: 4 decimals for positions; `F=-R2`, an
  // angle in `B=R3`; a parameter assigned an expression counts no more.
  const dialect id = id_of<siemens::dialect>();
  const auto r = scan_resolution("N10 R1=10.1234 R2=250.5\nN20 R3=-12.12345\nN30 G1 X=R1 Y2.5 B=R3 F=-R2\n", id);
  CHECK(r.linear_decimals == 4);
  CHECK(r.angle_decimals == 5);
  CHECK(r.feed_decimals == 1);
  const auto computed = scan_resolution("R1=10.1234\nR1=R2*2\nG1 X=R1 Y1.5\n", id);
  CHECK(computed.linear_decimals == 1);
  // User variables likewise: assigned, declared with a value (`,` between names), used by name
  // in any case.
  const auto variables =
      scan_resolution("N10 DEF REAL _A=1.5,Depth=-2.12345\nN20 _F=250.25 _Z=10.1234\nN30 G1 X=_z Y=-depth B=_A F=_F\n", id);
  CHECK(variables.linear_decimals == 5);
  CHECK(variables.angle_decimals == 1);
  CHECK(variables.feed_decimals == 2);
  const auto forgotten = scan_resolution("_Z=10.1234\n_Z=R1*2\nG1 X=_Z Y1.5\n", id);
  CHECK(forgotten.linear_decimals == 1);
}

TEST_CASE("siemens: a reading without limits of its own takes the reading's, as the other dialects do") {
  // 20 passes of a loop of 3 lines: more than the reading's bound of 40 executed lines.
  const std::string text = "R1=0\nWHILE R1<20\nR1=R1+1\nENDWHILE\nM30\n";
  read_limits limits;
  limits.max_executed_lines = 40;
  const read_limits_scope scope(limits);
  const read_result r = siemens::read(text, "loop.mpf");
  REQUIRE(r.errors.size() == 1);
  CHECK(r.errors[0].message.starts_with("more than 40 lines executed"));
}

TEST_CASE("siemens: a subprogram named alone in a block runs its file, P times, to M17 or RET") {
  const called_dir dir("siemens-calls");
  // The control's own file name (_N_…_SPF) and a PC's (….SPF, any case); R parameters shared,
  // DEF variables the subprogram's own; its header, PROC line and M17 make no block.
  dir.write("_N_L100_SPF", "%_N_L100_SPF\n;$PATH=/_N_SPF_DIR\nG1 X=R1 F100\nR1=R1+1\nM17\n");
  dir.write("pocket.spf", "PROC POCKET\nDEF REAL _D=2\nG1 Y=_D\nRET\nG1 Y99\n");
  const std::string main = "%_N_MAIN_MPF\nN10 R1=5\nN20 L100 P2\nN30 POCKET ;comment\nN40 CALL \"L100\"\n"
                           "N50 PCALL POCKET P=R1-6\nN60 G0 Z10\nN70 M30\n";
  read_limits limits;
  limits.include_dirs = {dir.path.string()};
  {
    const read_limits_scope scope(limits);
    const read_result r = siemens::read(main, "main.mpf");
    REQUIRE(r.errors.empty());
    std::vector<std::string> moves;
    for (const block& b : r.parsed.blocks) {
      CHECK_FALSE((b.program_begin && b.where.file.str() != "main.mpf"));
      CHECK(b.m_codes != std::vector<int>{17});
      if (b.axes.x_mm || b.axes.y_mm || b.axes.z_mm)
        moves.push_back(std::filesystem::path(b.where.file.str()).filename().string() + ":" + std::to_string(b.where.line) +
                        (b.axes.x_mm ? " X" + std::to_string(static_cast<int>(*b.axes.x_mm)) : "") +
                        (b.axes.y_mm ? " Y" + std::to_string(static_cast<int>(*b.axes.y_mm)) : "") +
                        (b.axes.z_mm ? " Z" + std::to_string(static_cast<int>(*b.axes.z_mm)) : ""));
    }
    CHECK(moves == std::vector<std::string>{"_N_L100_SPF:3 X5", "_N_L100_SPF:3 X6", "pocket.spf:3 Y2",
                                            "_N_L100_SPF:3 X7", "pocket.spf:3 Y2", "pocket.spf:3 Y2", "main.mpf:7 Z10"});
  }
  // Without the directory, refused at the call, naming the files.
  const read_result none = siemens::read(main, "main.mpf");
  REQUIRE(none.errors.size() == 1);
  CHECK(none.errors[0].to_string() ==
        "main.mpf:3:1: error: call of subprogram L100: L100.SPF or _N_L100_SPF: no directory to look for it in (a name "
        "alone in a block calls a subprogram; --include-dir DIR names the directory that holds it)");
  // M30 in a subprogram's file, parameters in its PROC line, an end never reached: refused there.
  dir.write("ENDS.SPF", "G1 X1\nM30\n");
  dir.write("ARGS.SPF", "PROC ARGS(REAL _X)\nG1 X=_X\nM17\n");
  dir.write("OPEN.SPF", "G1 X1\n");
  const read_limits_scope scope(limits);
  const auto error_of = [](const std::string& called) {
    const read_result r = siemens::read(called + "\nM30\n", "m.mpf");
    REQUIRE_FALSE(r.errors.empty());
    return std::filesystem::path(r.errors[0].where.file.str()).filename().string() + ":" +
           std::to_string(r.errors[0].where.line) + ": " + r.errors[0].message;
  };
  CHECK(error_of("ENDS").starts_with("ENDS.SPF:2: the end of the program (M2, M30) in a subprogram's file"));
  CHECK(error_of("ARGS").starts_with("ARGS.SPF:1: PROC ARGS(REAL _X): a subprogram with parameters"));
  CHECK(error_of("OPEN").starts_with("OPEN.SPF:1: the called file ends without returning to the call from line 1"));
}
