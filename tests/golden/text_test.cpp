// NC text through the whole chain: Siemens text read → translate → Heidenhain text written →
// read again. Also the rules for blocks that are not plain motion: TCP off, machine
// coordinates, passthrough, comments and M functions kept in order.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/kin5.hpp>
#include <kin5/translate/by_id.hpp>
#include <kin5/program/apt/dialect.hpp>
#include <kin5/program/heidenhain/dialect.hpp>
#include <kin5/program/iso/dialect.hpp>
#include <kin5/program/siemens/dialect.hpp>

#include "program_builder.hpp"

using kin5::machines::dmu_80p;
using kin5::machines::sajo_12000p;
namespace siemens = kin5::program::siemens;
namespace heidenhain = kin5::program::heidenhain;

namespace {

constexpr const char* table1_mpf =
    "; Table 1 of Tian et al. 2010 on the SAJO 12000P\n"
    "T1 M6\n"
    "S4000 M3\n"
    "TRAORI\n"
    "G1 X-34.983 Y9.1 Z118.526 A-77.954 B3.536 F1091\n"
    "X-33.824 Y9.118 Z117.545 A-77.913 B4.027 F1093\n"
    "X-32.674 Y9.153 Z116.558 A-77.918 B4.588 F1094\n"
    "X-31.531 Y9.203 Z115.567 A-77.963 B5.158 F1096\n"
    "TRAFOOF\n"
    "M30\n";

}  // namespace

TEST_CASE("Siemens Table 1 text -> Heidenhain text on the DMU 80P") {
  const auto in = siemens::read(table1_mpf, "table1.mpf");
  REQUIRE(in.ok());
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(in.parsed, {});
  REQUIRE(t.ok());
  CHECK(t.blocks_read == in.parsed.blocks.size());
  CHECK(t.blocks_written == t.blocks_read);
  const std::string text = heidenhain::write(t.output);
  CAPTURE(text);
  // The first motion, as Table 1 prints it for the DMU (F as the source: tcp policy).
  CHECK(text.find("L X+34.983 Y+118.526 Z+9.1 B+17.067 C+87.479") != std::string::npos);
  CHECK(text.find("M128") != std::string::npos);  // TRAORI → M128
  CHECK(text.find("M129") != std::string::npos);  // TRAFOOF → M129
  const auto back = heidenhain::read(text, "table1.h");
  REQUIRE(back.ok());
  std::vector<kin5::program::axis_words> moves;
  for (const auto& b : back.parsed.blocks)
    if (b.moves()) moves.push_back(b.axes);
  REQUIRE(moves.size() == 4);
  CHECK(*moves[3].x_mm == 31.531);
  CHECK(*moves[3].y_mm == 115.567);
  CHECK(*moves[3].z_mm == 9.203);
  CHECK(*moves[3].b_deg == 17.054);
  CHECK(*moves[3].c_deg == 89.106);
}

TEST_CASE("motion without TCP is an error naming the line, with the rotary message once rotary axes moved") {
  const auto in = siemens::read("G1 X1 Y2 Z3 F100\nA-10 B5\nTRAORI\nX2\n", "off.mpf");
  REQUIRE(in.ok());
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(in.parsed, {});
  REQUIRE(t.errors.size() == 2);
  CHECK(t.errors[0].where.line == 1);
  CHECK(t.errors[0].message.find("without tool-tip tracking (TCP)") != std::string::npos);
  CHECK(t.errors[1].where.line == 2);
  CHECK(t.errors[1].message ==
        "rotary motion without tool-tip tracking (TCP): its tool tip depends on where the part sits and on the tool "
        "length; give the source's --source-work-offset and --source-tool-length to read it as machine coordinates");
  CHECK(t.blocks_written == t.blocks_read - 2);  // accounted for: written or an error
}

TEST_CASE("motion without TCP at the zero pose, length on, is the tracked motion, elsewhere it is refused") {
  // Every rotary axis at 0 turns nothing: the point programmed is the tip with tracking or
  // without, so the untracked section translates as the tracked one does (the target tracks it).
  const std::string head = "T1 D1 M6\nTRAORI\nG1 X0 Y0 Z50 A0 B0 F500\n";
  const auto untracked = siemens::read(head + "TRAFOOF\nG1 X10 Y5 Z40\nG2 X20 Y5 CR=5\nTRAORI\nG1 X21\nM30\n", "z.mpf");
  const auto tracked = siemens::read(head + "G1 X10 Y5 Z40\nG2 X20 Y5 CR=5\nG1 X21\nM30\n", "t.mpf");
  REQUIRE((untracked.ok() && tracked.ok()));
  const auto u = kin5::translate<sajo_12000p, dmu_80p>(untracked.parsed, {});
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(tracked.parsed, {});
  REQUIRE(u.errors.empty());
  REQUIRE(t.errors.empty());
  std::vector<kin5::program::block> um, tm;
  for (const auto& b : u.output.blocks)
    if (b.moves()) um.push_back(b);
  for (const auto& b : t.output.blocks)
    if (b.moves()) tm.push_back(b);
  REQUIRE(um.size() == tm.size());
  for (std::size_t i = 0; i < um.size(); ++i) {
    CHECK(um[i].axes == tm[i].axes);
    CHECK(um[i].arc == tm[i].arc);
  }
  // Off the zero pose, or without the tool length, the tip depends on where the part sits; a
  // block that turns no rotary axis is not called rotary motion.
  const auto off = siemens::read(head + "G1 A-10\nTRAFOOF\nG1 X10 Y5 Z40\nM30\n", "o.mpf");
  const auto gauge = siemens::read(head + "TRAFOOF\nD0\nG1 X10 Y5 Z40\nM30\n", "g.mpf");
  REQUIRE((off.ok() && gauge.ok()));
  const auto o = kin5::translate<sajo_12000p, dmu_80p>(off.parsed, {});
  const auto g = kin5::translate<sajo_12000p, dmu_80p>(gauge.parsed, {});
  REQUIRE(o.errors.size() == 1);
  CHECK(o.errors[0].where.line == 6);
  CHECK(o.errors[0].message.starts_with("motion without tool-tip tracking (TCP): its tool tip depends on"));
  REQUIRE(!g.errors.empty());
  CHECK(g.errors[0].where.line == 6);
}

TEST_CASE("machine-coordinate moves are refused at their block, the rest is still checked") {
  // SUPA Z0 is the SAJO's own Z axis position: it means nothing on the DMU 80P.
  const auto in = siemens::read(
      "; start\nG0 SUPA Z0\nTRAORI\nG0 X0 Y0 Z50 A-45 B30\nM8\nG1 Z10 F200\nSUPA Z0\nM30\n", "mc.mpf");
  REQUIRE(in.ok());
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(in.parsed, kin5::test::options(kin5::feed_policy::tcp, kin5::program::id_of<kin5::program::siemens::dialect>()));
  REQUIRE(t.errors.size() == 2);
  CHECK(t.errors[0].where.line == 2);
  CHECK(t.errors[1].where.line == 7);
  CHECK(t.errors[0].message.find("a move in machine coordinates") == 0);
  CHECK_FALSE(t.ok());  // the tool writes nothing (cli_program: machine-coordinates)
  REQUIRE(t.reports.size() == 2);  // the two moves between them were planned
}

TEST_CASE("Heidenhain CC and C on the DMU 80P become a G18 arc on the SAJO") {
  // DMU: B = 90°, C = 0 gives u_d = (1/√2, 1/2, 1/2) (docs/golden.md). T u_d = (−1/√2, 1/2, 1/2) on the
  // SAJO: −sin A = 1/2, so A = −30°, and B = atan2(−1/√2, 1/2) = −54.735610° (K2).
  // Arc: XY plane on the DMU, normal Z_d, T Z_d = +Y_s: G18 on the SAJO, direction kept.
  const char* h =
      "0 BEGIN PGM ARC MM\n"
      "1 L X+10 Y+0 Z+5 B+90 C+0 R0 F500 M128\n"
      "2 CC X+0 Y+0\n"
      "3 C X+0 Y+10 DR+\n"
      "4 END PGM ARC MM\n";
  const auto in = heidenhain::read(h, "arc.h");
  REQUIRE(in.ok());
  const auto t = kin5::translate<dmu_80p, sajo_12000p>(
      in.parsed, kin5::test::options(kin5::feed_policy::tcp, kin5::program::id_of<kin5::program::siemens::dialect>()));
  REQUIRE(t.ok());
  CHECK(t.blocks_written == t.blocks_read);
  const kin5::program::block* line = nullptr;
  const kin5::program::block* arc = nullptr;
  for (const auto& b : t.output.blocks) {
    if (b.moves() && !b.arc) line = &b;
    if (b.moves() && b.arc) arc = &b;
  }
  REQUIRE(line);
  REQUIRE(arc);
  CHECK(std::abs(*line->axes.a_deg - -30.0) <= 1e-9);
  CHECK(std::abs(*line->axes.b_deg - -54.735610) <= 1e-6);
  CHECK(std::abs(*line->axes.x_mm - -10.0) <= 1e-12);
  CHECK(std::abs(*line->axes.y_mm - 5.0) <= 1e-12);
  CHECK(std::abs(*line->axes.z_mm - 0.0) <= 1e-12);
  CHECK(arc->motion == kin5::program::motion_kind::arc_ccw);
  CHECK(arc->arc->plane == kin5::program::arc_plane::zx);
  CHECK(kin5::norm(*arc->arc->centre_mm - kin5::vec3{0, 5, 0}) <= 1e-12);
  CHECK(std::abs(*arc->axes.x_mm - 0.0) <= 1e-12);
  CHECK(std::abs(*arc->axes.z_mm - 10.0) <= 1e-12);
  // Written as Siemens text the arc would need G18, under which an 840D applies the tool length
  // along Y and turns the tool orientation of TRAORI (docs/dialects/siemens.md): refused at the arc
  // by the writer of a Heidenhain program's blocks, as the tool writes them.
  kin5::program::program blocks = t.output;
  blocks.language = kin5::program::id_of<kin5::program::heidenhain::dialect>();
  CHECK_THROWS_WITH(siemens::write(blocks),
                    Catch::Contains("G18 while tool length compensation may be on: an 840D would apply the "
                                    "tool length along Y"));
}

TEST_CASE("post switches TCP on in the first motion block and off at the program end") {
  kin5::program::program cl;
  cl.language = kin5::program::id_of<kin5::program::apt::dialect>();
  cl.file = "p.cl";
  for (int k = 0; k < 3; ++k) {
    kin5::program::block b;
    b.where = {cl.file, static_cast<std::size_t>(k + 1), 1};
    if (k < 2) {
      b.motion = kin5::program::motion_kind::linear;
      b.axes.x_mm = k, b.axes.y_mm = 0.0, b.axes.z_mm = 10.0;
      b.axes.tool_axis = kin5::vec3{0.0, 0.6, 0.8};
      b.feed = 300.0;
    } else {
      b.program_end = "FINI";
    }
    cl.blocks.push_back(b);
  }
  const auto t = kin5::post<dmu_80p>(cl, kin5::program::id_of<kin5::program::heidenhain::dialect>());
  REQUIRE(t.ok());
  REQUIRE(t.output.blocks.size() == 3);
  CHECK(t.output.blocks[0].tcp == true);
  CHECK_FALSE(t.output.blocks[1].tcp.has_value());
  CHECK(t.output.blocks[2].tcp == false);
  // u = (0, 0.6, 0.8) on the DMU 80P: (K7) B = arccos(2k − 1) = arccos(0.6) = 53.130102°.
  CHECK(std::abs(*t.output.blocks[0].axes.b_deg - 53.130102354) <= 1e-6);
  CHECK(kin5::norm(kin5::tool_axis<dmu_80p>({kin5::to_radians(kin5::degrees{*t.output.blocks[0].axes.c_deg}),
                                             kin5::to_radians(kin5::degrees{*t.output.blocks[0].axes.b_deg})}) -
                   kin5::vec3{0.0, 0.6, 0.8}) <= 1e-12);
}

TEST_CASE("run-time dispatch by catalog id matches the template, unknown ids are errors") {
  const auto in = siemens::read(table1_mpf, "table1.mpf");
  REQUIRE(in.ok());
  const auto options = kin5::test::options();
  const auto by_type = kin5::translate<sajo_12000p, dmu_80p>(in.parsed, options);
  const auto by_id = kin5::translate("sajo-12000p", "dmu-80p", in.parsed, options);
  REQUIRE(by_id.ok());
  CHECK(heidenhain::write(by_id.output) == heidenhain::write(by_type.output));
  const auto unknown = kin5::translate("sajo-12000p", "no-such-machine", in.parsed, options);
  REQUIRE(unknown.errors.size() == 1);
  CHECK(unknown.errors[0].message.find("unknown machine 'no-such-machine'") != std::string::npos);
  CHECK(unknown.errors[0].message.find("dmu-80p") != std::string::npos);  // lists the known ids
  CHECK_FALSE(kin5::reverse("nope", in.parsed).ok());
  CHECK_FALSE(kin5::post("nope", in.parsed, kin5::program::id_of<kin5::program::iso::dialect>()).ok());
  CHECK(kin5::reverse("sajo-12000p", in.parsed).ok());
}

TEST_CASE("Siemens-only words reach a Heidenhain program as comments, never as code") {
  const auto in = siemens::read(
      "G64 G17 D1\n"
      "SOFT\n"  // a cycle such as CYCLE832 is refused by the reader, not carried as a comment
      "TRAORI\n"
      "G1 G64 X-34.983 Y9.1 Z118.526 A-77.954 B3.536 F1091 ; first cut\n"
      "TRAFOOF\n",
      "words.mpf");
  REQUIRE(in.ok());
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(in.parsed, {});
  REQUIRE(t.ok());
  CHECK(t.blocks_written == t.blocks_read);
  const std::string text = heidenhain::write(t.output);
  CAPTURE(text);
  // Every line that mentions a Siemens-only word carries it after ';' (a Heidenhain comment).
  std::size_t start = 0, lines_with_words = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    for (const char* word : {"SOFT", "G64", "D1"}) {  // (G54 is a work offset: work_offset_laws.cpp)
      const auto at = line.find(word);
      if (at == std::string::npos) continue;
      ++lines_with_words;
      const auto semicolon = line.find(';');
      CHECK(semicolon != std::string::npos);
      CHECK(semicolon < at);
    }
    start = end + 1;
  }
  CHECK(lines_with_words >= 3);
  // The Heidenhain reader accepts the result, with the motion intact.
  const auto back = heidenhain::read(text, "words.h");
  CHECK(back.ok());
}

TEST_CASE("a program end is written once in every dialect") {
  namespace iso = kin5::program::iso;
  namespace apt = kin5::program::apt;
  const auto s = siemens::read("%_N_P_MPF\nN10 M30\nN20 M5 M2\n", "end.mpf");
  REQUIRE(s.ok());
  CHECK(s.parsed.blocks[1].m_codes.empty());  // the end lives in program_end only
  CHECK(s.parsed.blocks[1].program_end == "P");
  CHECK((s.parsed.blocks[2].m_codes.empty() && s.parsed.blocks[2].state.spindle == kin5::program::spindle_rotation::stopped));
  CHECK(s.parsed.blocks[2].program_end == "M2");
  // `M5 M2` after the end never runs on the source control: another dialect refuses it (written
  // after the target's end it would not run either; before it, it would run where the source never
  // did); Siemens writes its own program as read.
  const std::string after_end = "end.mpf:3: block after the program end (line 2): the source control never runs it";
  CHECK_THROWS_WITH(iso::write(s.parsed), after_end);
  CHECK_THROWS_WITH(heidenhain::write(s.parsed), after_end);
  CHECK_THROWS_WITH(apt::write(s.parsed), after_end);
  CHECK(siemens::write(s.parsed) == "%_N_P_MPF\nN10 M30\nN20 M5 M2\n");

  // Heidenhain: M30 is an M function, END PGM the end; M91 is machine coordinates (G53, SUPA).
  const auto h = heidenhain::read("0 BEGIN PGM P MM\n1 L Z+0 FMAX M91\n2 M30\n3 END PGM P MM\n", "end.h");
  REQUIRE(h.ok());
  // The run ends at M30: END PGM (its unit again) writes nothing after it, no second end.
  CHECK(iso::write(h.parsed) == "%\nO0001 (P)\nN0 G21\nN1 G53 G0 Z0.\nN2 M30\n%\n");
  CHECK(siemens::write(h.parsed) == "%_N_PGM_P_MPF\n;$PATH=/_N_MPF_DIR\nN0 G710\nN1 SUPA G0 Z0\nN2 M30\n");

  // A tool change is written once: TOOL CALL and LOADTL are the change, no M6 beside them.
  const auto tc = siemens::read("T1 M6\nS6000 M3\n", "tool.mpf");
  REQUIRE(tc.ok());
  CHECK(heidenhain::write(tc.parsed) == "0 BEGIN PGM PGM MM\n1 TOOL CALL 1 Z\n2 TOOL CALL S6000\n3 M3\n4 END PGM PGM MM\n");
  CHECK(apt::write(tc.parsed) == "LOADTL/1\nSPINDL/6000,CLW\nFINI\n");  // CL data end with FINI
  CHECK(iso::write(tc.parsed) == "%\nO0001\nT1 M6\nS6000 M3\nM30\n%\n");  // a FANUC program ends with M30, %

  const auto i = iso::read("O1234\nN5 M30\n", "end.nc");
  REQUIRE(i.ok());
  CHECK(heidenhain::write(i.parsed) == "0 BEGIN PGM 1234 MM\n1 M30\n2 END PGM 1234 MM\n");
  CHECK(siemens::write(i.parsed) == "%_N_PGM_1234_MPF\n;$PATH=/_N_MPF_DIR\nN5 M30\n");  // a legal name
  // The tape marks and ;$PATH= frame the program: BEGIN/END PGM stand for them, no copy as text.
  const auto tape = iso::read("%\nO1234\nN5 M30\n%\n", "end.nc");
  REQUIRE(tape.ok());
  CHECK(tape.parsed.blocks[0].framing);
  CHECK(heidenhain::write(tape.parsed) == "0 BEGIN PGM 1234 MM\n1 M30\n2 END PGM 1234 MM\n");
  const auto path = siemens::read("%_N_P_MPF\n;$PATH=/_N_MPF_DIR\nN10 M30\n", "path.mpf");
  REQUIRE(path.ok());
  CHECK(path.parsed.blocks[1].framing);
  CHECK(heidenhain::write(path.parsed) == "0 BEGIN PGM P MM\n1 M30\n2 END PGM P MM\n");
}

TEST_CASE("APT feed-only, rapid-only and units blocks in the G-code and Heidenhain dialects") {
  namespace iso = kin5::program::iso;
  const auto a = kin5::program::apt::read(
      "PARTNO X\nUNITS/MM\nFEDRAT/MMPM,800\nRAPID\nGOTO/1,2,3\nGOTO/4,5,6\nGOTO/7,8,9\nFINI\n", "a.cls");
  REQUIRE(a.ok());
  // An L needs coordinates: F moves to the next cutting move, RAPID is the next move's FMAX.
  CHECK(heidenhain::write(a.parsed) ==
        "0 BEGIN PGM X MM\n"
        "1 ;UNITS/MM\n"
        "2 ;FEDRAT/MMPM,800\n"
        "3 ;RAPID\n"
        "4 L X+1 Y+2 Z+3 FMAX\n"
        "5 L X+4 Y+5 Z+6 F800\n"
        "6 L X+7 Y+8 Z+9\n"
        "7 M30\n"
        "8 END PGM X MM\n");
  // G code has words for all of them.
  CHECK(siemens::write(a.parsed) ==
        "%_N_PGM_X_MPF\n;$PATH=/_N_MPF_DIR\nG710\nG94 F800\nG0\nG0 X1 Y2 Z3\nG1 X4 Y5 Z6\nG1 X7 Y8 Z9\nM30\n");
  CHECK(iso::write(a.parsed) ==
        "%\nO0001 (X)\nG21\nG94 F800.\nG0\nG0 X1. Y2. Z3.\nG1 X4. Y5. Z6.\nG1 X7. Y8. Z9.\nM30\n%\n");
  const auto back = heidenhain::read(heidenhain::write(a.parsed), "a.h");
  CHECK(back.ok());

  // A Siemens block with nothing Siemens-writable left is a comment, not a dropped line.
  kin5::program::program p;
  p.language = kin5::program::id_of<kin5::program::apt::dialect>();
  kin5::program::block empty;
  empty.text = "UNITS/XYZ";
  p.blocks = {empty};
  CHECK(siemens::write(p) == "%_N_PGM_MPF\n;$PATH=/_N_MPF_DIR\n; UNITS/XYZ\nM30\n");  // no end given: M30
  CHECK(heidenhain::write(p) == "0 BEGIN PGM PGM MM\n1 ;UNITS/XYZ\n2 END PGM PGM MM\n");
}

TEST_CASE("kin5 post of APT CL data to Heidenhain: no coordinate-less L, no empty block") {
  const auto a = kin5::program::apt::read("UNITS/MM\nRAPID\nGOTO/0,-20,60,0,0,1\nFEDRAT/MMPM,800\n"
                                          "GOTO/0,-20,10,0,0,1\nGOTO/10,-20,10,0,0,1\nFINI\n", "cl.apt");
  REQUIRE(a.ok());
  const auto t = kin5::post("dmu-80p", a.parsed, kin5::program::id_of<kin5::program::heidenhain::dialect>());
  REQUIRE(t.ok());
  // Written as the tool streams it: blocks of CL data, whose understood statements (UNITS,
  // RAPID, FEDRAT) leave no line of their own.
  auto from_cl = t.output;
  from_cl.language = kin5::program::id_of<kin5::program::apt::dialect>();
  const std::string text = heidenhain::write(from_cl);
  CAPTURE(text);
  CHECK(text.find("0 BEGIN PGM PGM MM\n1 L X+0 Y-20 Z+60") == 0);
  CHECK(text.find("FMAX M128\n2 L X+0 Y-20 Z+10") != std::string::npos);
  CHECK(text.find(" F800\n3 L X+10 Y-20 Z+10") != std::string::npos);
  for (std::size_t at = text.find('\n'); at != std::string::npos && at + 1 < text.size(); at = text.find('\n', at + 1)) {
    std::size_t k = at + 1;
    while (k < text.size() && text[k] >= '0' && text[k] <= '9') ++k;
    CHECK(text[k] != '\n');  // no block that is only its number
  }
  CHECK(text.find("L F") == std::string::npos);
  CHECK(text.find("L FMAX") == std::string::npos);
  CHECK(heidenhain::read(text, "cl.h").ok());
}

TEST_CASE("a dwell in every dialect, as its manual spells it, and through translation") {
  namespace iso = kin5::program::iso;
  namespace apt = kin5::program::apt;
  namespace linuxcnc = kin5::program::linuxcnc;
  const auto cl = apt::read("DELAY/1.5\nDELAY/0.25 $$ wait\n", "d.cls");
  REQUIRE(cl.ok());
  // Each a block of its own: Fanuc G04 X (seconds with a point), LinuxCNC G4 P (seconds),
  // Siemens G4 F (seconds), Heidenhain Cycle 9 (two blocks), APT DELAY.
  CHECK(iso::write(cl.parsed) == "%\nO0001\nG4 X1.5\nG4 X0.25 (wait)\nM30\n%\n");  // framed (iso.md)
  CHECK(linuxcnc::write(cl.parsed) == "%\nG4 P1.5\nG4 P0.25 (wait)\n%\n");
  CHECK(siemens::write(cl.parsed) == "%_N_PGM_MPF\n;$PATH=/_N_MPF_DIR\nG4 F1.5\nG4 F0.25 ; wait\nM30\n");
  CHECK(heidenhain::write(cl.parsed) ==
        "0 BEGIN PGM PGM MM\n"
        "1 CYCL DEF 9.0 DWELL TIME\n"
        "2 CYCL DEF 9.1 DWELL 1.5\n"
        "3 CYCL DEF 9.0 DWELL TIME\n"
        "4 CYCL DEF 9.1 DWELL 0.25 ;wait\n"
        "5 END PGM PGM MM\n");
  CHECK(apt::write(cl.parsed) == "DELAY/1.5\nDELAY/0.25 $$ wait\n");
  // ISO P is milliseconds; a whole second is written with its point.
  const auto i = iso::read("N10 G04 P2000\n", "d.nc");
  REQUIRE(i.ok());
  CHECK(iso::write(i.parsed) == "N10 G4 X2.\n");
  CHECK(siemens::write(i.parsed) == "%_N_PGM_MPF\n;$PATH=/_N_MPF_DIR\nN10 G4 F2\nM30\n");
  // A Heidenhain program's own Cycle 9 is written back once, its 9.0 as it was.
  const auto h = heidenhain::read("0 BEGIN PGM D MM\n1 CYCL DEF 9.0 DWELL TIME\n2 CYCL DEF 9.1 DWELL1.5\n3 END PGM D MM\n", "d.h");
  REQUIRE(h.ok());
  CHECK(heidenhain::write(h.parsed) ==
        "0 BEGIN PGM D MM\n1 CYCL DEF 9.0 DWELL TIME\n2 CYCL DEF 9.1 DWELL 1.5\n3 END PGM D MM\n");
  // In another dialect the 9.0 header is a comment, the 9.1 the dwell.
  CHECK(siemens::write(h.parsed) == "%_N_PGM_D_MPF\n;$PATH=/_N_MPF_DIR\nN0 G710\n; 1 CYCL DEF 9.0 DWELL TIME\nN2 G4 F1.5\nN3 G710 M30\n");

  // Translated between the moves it stands between (SAJO 12000P to DMU 80P).
  const auto s = siemens::read("T1 M6\nTRAORI\nG1 X-34.983 Y9.1 Z118.526 A-77.954 B3.536 F1091\nG4 F2.5\n"
                               "X-33.824 Y9.118 Z117.545 A-77.913 B4.027 F1093\nM30\n", "d.mpf");
  REQUIRE(s.ok());
  const auto t = kin5::translate<sajo_12000p, dmu_80p>(s.parsed, {});
  REQUIRE(t.ok());
  auto from_siemens = t.output;  // written as the tool streams it: blocks read as Siemens
  from_siemens.language = kin5::program::id_of<siemens::dialect>();
  const std::string text = heidenhain::write(from_siemens);
  CAPTURE(text);
  CHECK(text.find(" F1091\n4 CYCL DEF 9.0 DWELL TIME\n5 CYCL DEF 9.1 DWELL 2.5\n6 L X+33.824") != std::string::npos);
  // A dwell the TNC cannot take is refused at its block, before anything is written.
  const auto long_dwell = siemens::read("T1 M6\nTRAORI\nG4 F4000\n", "long.mpf");
  REQUIRE(long_dwell.ok());
  const auto refused = kin5::translate<sajo_12000p, dmu_80p>(long_dwell.parsed, {});
  REQUIRE_FALSE(refused.ok());
  REQUIRE(refused.errors.size() == 1);
  CHECK(refused.errors[0].to_string() ==
        "long.mpf:3:1: error: a dwell of 4000 s is not one the heidenhain controller takes (0 to 3600 s in steps of 0.001 s)");
}
