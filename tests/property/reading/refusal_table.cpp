// Faithful or refused: every construct a reader does not read into the model, and that could
// change what the machine does, is an error at its first character naming it — never a comment,
// never dropped. One row per construct: the input and the exact error. Constructs that only
// describe the program pass through (a comment in another dialect), and the table says so too.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/apt/dialect.hpp>
#include <kin5/program/heidenhain/dialect.hpp>
#include <kin5/program/iso/dialect.hpp>
#include <kin5/program/siemens/dialect.hpp>
#include <kin5/translate/source_checks.hpp>

using namespace kin5::program;

namespace {

struct row {
  std::string text;   // the program
  std::string error;  // the one error it must give; empty: read, no error
};

template <class Read>
void check_rows(const std::vector<row>& rows, Read&& read) {
  for (const row& r : rows) {
    INFO(r.text);
    const read_result got = read(r.text);
    std::string all;
    for (const diagnostic& d : got.errors) all += d.to_string() + "\n";
    INFO(all);
    if (r.error.empty()) {
      CHECK(got.errors.empty());
      continue;
    }
    REQUIRE(got.errors.size() == 1);
    CHECK(got.errors[0].to_string() == r.error);
  }
}

}  // namespace

TEST_CASE("apt: statements that may change the motion are read or refused at their major word") {
  const std::vector<row> rows{
      {"GOTO/0,0,5\nCYCLE/DRILL,FEDTO,2.5,MMPM,700,RAPTO,3,RTRCTO,10\nGOTO/5,5,5\nCYCLE/OFF\n",
       ""},  // placeholder replaced below: two errors
      {"CYCLE/OFF\n",
       "t.cls:1:1: error: CYCLE/OFF: fixed cycles are not supported (the points that follow would be holes made by "
       "the cycle, not positions to feed to)"},
      {"  cycle/deep2,FEDTO,10\n",
       "t.cls:1:3: error: CYCLE/DEEP2: fixed cycles are not supported (the points that follow would be holes made by "
       "the cycle, not positions to feed to)"},
      {"INSERT/G05.1 Q1\n",
       "t.cls:1:1: error: INSERT: text a post copies into the NC program as code; its effect cannot be known"},
      {"TLAXIS/0,0,1\n",
       "t.cls:1:1: error: TLAXIS: a tool-axis statement is not supported (it tilts the tool for the GOTOs that follow)"},
      {"CUTCOM/LEFT,1\n", "t.cls:1:1: error: CUTCOM/LEFT: cutter radius compensation is not supported in CL data yet"},
      {"DELAY/1.5\n", "t.cls:1:1: error: DELAY: a dwell is not supported in CL data yet"},
      {"CSYS/0,-0.984808,-0.173648,0,1,0,0,0,0,-0.173648,0.984808,0\n",
       "t.cls:1:1: error: CSYS: a coordinate system other than the identity is not supported (the points that "
       "follow are in another frame)"},
      {"MSYS/10,0,0,1,0,0,0,1,0\n",
       "t.cls:1:1: error: MSYS: a coordinate system other than the identity is not supported (the points that "
       "follow are in another frame)"},
      {"TRNTYP/WORLD,0,0,0\n", "t.cls:1:1: error: TRNTYP/WORLD: a transformation of the points that follow is not supported"},
      {"ORIGIN/10,0,0\n", "t.cls:1:1: error: ORIGIN/10: a transformation of the points that follow is not supported"},
      {"LOAD/WIRE,3\n", "t.cls:1:1: error: LOAD/WIRE: only LOAD/TOOL,n (a tool change) is read"},
      {"LOAD/TOOL,4,ADJUST,4\n", "t.cls:1:1: error: LOAD/TOOL needs one tool number"},
      {"COOLNT/THRU\n", "t.cls:1:1: error: COOLNT/THRU is not supported (only ON, FLOOD, MIST and OFF are read)"},
      {"UNITS/FEET\n", "t.cls:1:1: error: UNITS/FEET is not supported (only MM and INCHES are read)"},
      {"ROTABL/30,CLW\n",
       "t.cls:1:1: error: APT statement ROTABL is not supported: only statements known not to change the motion are "
       "passed on"},
      {"AUXFUN/126\n",
       "t.cls:1:1: error: APT statement AUXFUN is not supported: only statements known not to change the motion are "
       "passed on"},
      {"CSI_SET_FLUTE_LENGTH/44.\n",
       "t.cls:1:1: error: APT statement CSI_SET_FLUTE_LENGTH is not supported: only statements known not to change "
       "the motion are passed on"},
      {"FROM/0,0,100\n",
       "t.cls:1:1: error: APT statement FROM is not supported: only statements known not to change the motion are "
       "passed on"},
      {"GOHOME\n",
       "t.cls:1:1: error: APT statement GOHOME is not supported: only statements known not to change the motion are "
       "passed on"},
      // Read into the model or only describing: no error.
      {"LOAD/TOOL,12\n", ""},
      {"LOADTL/3\n", ""},
      {"UNIT/MM\n", ""},
      {"MULTAX/ON\nMULTAX\nCUTTER/6,0,3,1.8,31,0,45\nTLDATA/MILL,6,0,50,0\nSELECT/TOOL,6\nMACHIN/MILL,1\n", ""},
      {"CSYS/1,0,0,0,0,1,0,0,0,0,1,0\nMSYS/0,0,0,1,0,0,0,1,0\nTOOL PATH/ROUGH,TOOL,EM10\nEND-OF-PATH\n", ""},
  };
  std::vector<row> single(rows.begin() + 1, rows.end());
  check_rows(single, [](const std::string& t) { return apt::read(t, "t.cls"); });

  // A drilling cycle and its cancel: both refused, the positions between are never fed to.
  const read_result cycle = apt::read(rows[0].text, "t.cls");
  REQUIRE(cycle.errors.size() == 2);
  CHECK(cycle.errors[0].where.line == 2);
  CHECK(cycle.errors[0].construct == "CYCLE");
  CHECK(cycle.errors[1].where.line == 4);
}

TEST_CASE("apt: LOAD/TOOL and LOADTL are a tool change; what only describes passes through") {
  const read_result r = apt::read("LOAD/TOOL,12\nloadtl / 3\nSELECT/TOOL,6\nCUTTER/6,0,3\n", "t.cls");
  REQUIRE(r.ok());
  const auto& b = r.parsed.blocks;
  REQUIRE(b.size() == 4);
  CHECK((b[0].tool == 12 && b[0].m_codes == std::vector<int>{6} && !b[0].passthrough));
  CHECK((b[1].tool == 3 && b[1].m_codes == std::vector<int>{6}));
  CHECK((b[2].passthrough && !b[2].tool));  // a tool made ready: no change, no motion
  CHECK(b[3].passthrough);
  // Written back in APT the change is LOADTL; in ISO it is T n M6.
  CHECK(apt::write(r.parsed) == "LOADTL/12\nLOADTL/3\nSELECT/TOOL,6\nCUTTER/6,0,3\n");
}

TEST_CASE("heidenhain: blocks that may change the motion are read or refused at their keyword") {
  const std::string cycle_tail = ": fixed cycles are refused until kin5 reads them (their holes and pockets would be lost)";
  const std::vector<row> rows{
      {"5 CYCL DEF 200 DRILLING~\n  Q200=2 ;SET-UP CLEARANCE~\n  Q201=-12 ;DEPTH\n",
       "t.h:1:3: error: CYCL DEF 200 is not supported" + cycle_tail},
      {"CYCL DEF 1.0 PECKING\nCYCL DEF 1.1 SET UP 2\n", "t.h:1:1: error: CYCL DEF 1 is not supported" + cycle_tail},
      {"CYCL DEF 9.0 DWELL TIME\nCYCL DEF 9.1 DWELL 1.5\n",
       "t.h:1:1: error: CYCL DEF 9 (dwell time) is not supported yet: the dwell would be lost"},
      {"CYCL DEF 32.0 TOLERANCE\nCYCL DEF 32.1 T0.01\n",
       "t.h:1:1: error: CYCL DEF 32 (tolerance) is not supported yet: the contour tolerance would be lost"},
      {"CYCL DEF 247 DATUM SETTING ~\n  Q339=+1 ;DATUM NUMBER\n", ""},  // preset 1 (work_offset_laws.cpp)
      {"CYCL DEF 247 DATUM SETTING\n  Q339=+1 ;DATUM NUMBER\n",
       "t.h:1:1: error: CYCL DEF 247 (datum setting) without Q339 in its block: the preset it selects is not known"},
      {"7 CYCL CALL M13\n",
       "t.h:1:3: error: CYCL CALL: a cycle call is not supported (fixed cycles are refused until kin5 reads them)"},
      {"L X+10 Y+20 R0 FMAX M99\n",
       "t.h:1:21: error: M99: a cycle call is not supported (fixed cycles are refused until kin5 reads them)"},
      {"M89\n", "t.h:1:1: error: M89: a cycle call is not supported (fixed cycles are refused until kin5 reads them)"},
      {"LBL 1\n", "t.h:1:1: error: LBL: labels are not supported (the path would depend on the calls and repeats)"},
      {"CALL LBL 1 REP 2\n",
       "t.h:1:1: error: CALL LBL: program and label calls are not supported (the motion they make would be lost)"},
      {"CALL PGM TNC:\\SUB.H\n",
       "t.h:1:1: error: CALL PGM: program and label calls are not supported (the motion they make would be lost)"},
      {"FN 9: IF +Q1 EQU +0 GOTO LBL 1\n", "t.h:1:1: error: FN: functions other than FN 0 (a constant) are not supported"},
      {"PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX\n",
       "t.h:1:1: error: PLANE SPATIAL changes the working frame; kin5 does not model frame changes"},
      {"M140 MB MAX\n",
       "t.h:1:6: error: 'MB' in an M block is not supported (M140 MB retracts, M120 looks ahead: the machine would do "
       "something else)"},
      {"TOOL CALL \"BALL_D8\" Z S12000\n",
       "t.h:1:1: error: TOOL CALL: only TOOL CALL n with an axis, S, F, DL and DR is read (a tool called by name or "
       "with other words is not supported)"},
      {"FUNCTION TCPM F CONT AXIS POS PATHCTRL AXIS\n",
       "t.h:1:15: error: FUNCTION TCPM F CONT is not supported (kin5 reads F TCP, AXIS POS, PATHCTRL AXIS)"},
      {"FUNCTION TCPM F TCP AXIS POS PATHCTRL VECTOR\n",
       "t.h:1:30: error: FUNCTION TCPM PATHCTRL VECTOR is not supported (kin5 reads F TCP, AXIS POS, PATHCTRL AXIS)"},
      {"FUNCTION RESET TCPM F\n", "t.h:1:21: error: FUNCTION RESET TCPM: words after it are not supported"},
      {"SEL TABLE \"TNC:\\TABLE\\HOLES.PNT\"\n",
       "t.h:1:1: error: SEL TABLE: program and label calls are not supported (the motion they make would be lost)"},
      {"PATTERN DEF\n",
       "t.h:1:1: error: unknown keyword 'PATTERN' is not supported: only blocks known not to change the motion are "
       "passed on"},
      // Read, or changing nothing: no error.
      {"STOP\n", ""},
      {"TOOL DEF 5\nBLK FORM 0.1 Z X+0 Y+0 Z-40\nPLANE RESET STAY\nQ1 = 5\n", ""},
      {"CYCL DEF 7.0 DATUM SHIFT\nCYCL DEF 7.1 X+0\nCYCL DEF 19.0 WORKING PLANE\nCYCL DEF 19.1 A+0 B+0\n", ""},
      {"FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\nFUNCTION RESET TCPM\n", ""},
  };
  check_rows(rows, [](const std::string& t) { return heidenhain::read(t, "t.h"); });
  const read_result stop = heidenhain::read("STOP ; check\n", "t.h");
  REQUIRE(stop.ok());
  CHECK((stop.parsed.blocks[0].m_codes == std::vector<int>{0} && stop.parsed.blocks[0].comment == " check"));
}

TEST_CASE("siemens: lines that may change the motion are read or refused at their word") {
  const std::string call_tail = "(…): a call kin5 does not read is not supported (a cycle or subprogram: the motion it makes would be lost)";
  const std::vector<row> rows{
      {"N10 CYCLE81(10,0,1,-5)\n", "t.mpf:1:5: error: CYCLE81" + call_tail},
      {"CYCLE832(0.01,_ORI_FINISH,0.1)\n", "t.mpf:1:1: error: CYCLE832" + call_tail},
      {"POCKET3(50,0,1,-10,40,30)\n", "t.mpf:1:1: error: POCKET3" + call_tail},
      {"L100\n", "t.mpf:1:1: error: L100: a subprogram call is not supported (the motion it makes would be lost)"},
      {"GOTOF END\n", "t.mpf:1:1: error: GOTOF: control flow is not supported (the path would depend on it)"},
      {"WHILE R1>5\n", "t.mpf:1:1: error: WHILE: control flow is not supported (the path would depend on it)"},
      {"REPEAT START END P=3\n", "t.mpf:1:1: error: REPEAT: control flow is not supported (the path would depend on it)"},
      {"G41 D1\n", "t.mpf:1:1: error: G41: cutter radius compensation is not supported yet (the path would be off by the radius)"},
      {"G4 F2\n", "t.mpf:1:1: error: G4: a dwell is not supported yet (the dwell would be lost)"},
      {"M=3\n", "t.mpf:1:1: error: unknown word 'M=3'"},
      {"R2=R1*2\n", ""},  // placeholder, checked below: an expression assigned is refused
      {"G75\n", "t.mpf:1:1: error: unknown word 'G75'"},
      // Changing nothing: no error.
      {"DEF REAL DEPTH\nR1=5\n_Z_HOME=610.\nEND:\nSTOPRE\nMSG(\"roughing\")\n%\n", ""},
      {"WORKPIECE(,\"\",,\"BOX\",0,0,-50,-80,0,0,100,100)\nN20 R3 = -2.5 ; depth\n", ""},
  };
  std::vector<row> checked;
  for (const row& r : rows)
    if (r.text != "R2=R1*2\n") checked.push_back(r);
  check_rows(checked, [](const std::string& t) { return siemens::read(t, "t.mpf"); });
  CHECK_FALSE(siemens::read("R2=R1*2\n", "t.mpf").ok());
  const read_result jump = siemens::read("IF R1>5 GOTOF L1\n", "t.mpf");  // each keyword at its column
  REQUIRE(jump.errors.size() == 2);
  CHECK(jump.errors[0].to_string() == "t.mpf:1:1: error: IF: control flow is not supported (the path would depend on it)");
  CHECK(jump.errors[1].to_string() == "t.mpf:1:9: error: GOTOF: control flow is not supported (the path would depend on it)");
  const read_result call = siemens::read("CALL \"SUB1\"\n", "t.mpf");  // and its name, an unknown word
  REQUIRE_FALSE(call.ok());
  CHECK(call.errors[0].to_string() ==
        "t.mpf:1:1: error: CALL: a subprogram call is not supported (the motion it makes would be lost)");
  CHECK_FALSE(siemens::read("R1=5 M3\n", "t.mpf").ok());  // an M function beside it: not only an assignment
}

TEST_CASE("iso: words that may change the motion are read or refused at their word") {
  const std::vector<row> rows{
      {"G81 X10. Y20. Z-5. R2. F100.\n", "t.nc:1:1: error: canned cycle G81 is not supported"},
      {"M98 P1000\n", "t.nc:1:1: error: M98: a subprogram call is not supported (the motion it makes would be lost)"},
      {"M97 P20\n", "t.nc:1:1: error: M97: a subprogram call is not supported (the motion it makes would be lost)"},
      {"N40 M99\n", "t.nc:1:5: error: M99: a subprogram return or loop is not supported (the path would depend on it)"},
      {"G65 P9010 A1. B2.\n", "t.nc:1:1: error: G65: a macro call is not supported (the motion it makes would be lost)"},
      {"G10 L2 P1 X0. Y0. Z0.\n",
       "t.nc:1:1: error: G10: setting offsets from the program is not supported (later moves would use other offsets)"},
      {"G92 X0. Y0.\n",
       "t.nc:1:1: error: G92: a coordinate system shift is not supported (the points that follow are in another frame)"},
      {"G52 X10. Y0.\n", "t.nc:1:1: error: G52 changes the working frame; kin5 does not model frame changes"},
      {"G68.2 X0 Y0 Z0 I0 J45. K0\n", "t.nc:1:1: error: G68.2 changes the working frame; kin5 does not model frame changes"},
      {"G41 D1\n",
       "t.nc:1:1: error: G41: cutter radius compensation is not supported yet (the path would be off by the radius)"},
      {"G42 X10. D2\n",
       "t.nc:1:1: error: G42: cutter radius compensation is not supported yet (the path would be off by the radius)"},
      {"G29\n", "t.nc:1:1: error: unknown word 'G29'"},
      {"U5.\n", "t.nc:1:1: error: unknown word 'U5.'"},
      // Read, or changing nothing: no error.
      {"%\nO1234 (PART)\nG17 G40 G80 G90 G54\nG05.1 Q1\nG52 X0 Y0 Z0\n%\n", ""},
  };
  check_rows(rows, [](const std::string& t) { return iso::read(t, "t.nc"); });
  // G4 X1.5 dwells 1.5 s: its X is no position (Fanuc: G04 dwell, X or P).
  const read_result dwell = iso::read("G4 X1.5\n", "t.nc");
  REQUIRE(dwell.ok());
  CHECK((dwell.parsed.blocks[0].axes.empty() && dwell.parsed.blocks[0].kept_words == std::vector<std::string>{"G4", "X1.5"}));
  CHECK(iso::read("G4 Y2.\n", "t.nc").errors.at(0).to_string() == "t.nc:1:4: error: word 'Y' in a dwell block (G4)");
}

TEST_CASE("across dialects, a kept word whose effect a comment would lose is refused at its block") {
  using kin5::translate_detail::check_kept_words;
  using kin5::translate_detail::source_context;
  struct case_row {
    dialect from;
    std::string text, error;  // error empty: carried as a comment, harmless
  };
  const std::vector<case_row> rows{
      {id_of<iso::dialect>(), "G4 P1500\n",
       "t:1:1: error: G4: a dwell of iso is not translated into heidenhain yet (it would become a comment)"},
      {id_of<iso::dialect>(), "G04 X1.5\n",  // X of a G4 is its time, not a position
       "t:1:1: error: G04: a dwell of iso is not translated into heidenhain yet (it would become a comment)"},
      {id_of<iso::dialect>(), "G43 H1\n",
       "t:1:1: error: G43: tool length compensation (G43, without tool-tip tracking) of iso is not translated into "
       "heidenhain yet (it would become a comment)"},
      {id_of<siemens::dialect>(), "T=\"BALL\"\n",
       "t:1:1: error: T=\"BALL\": a tool named in T= of siemens is not translated into heidenhain yet (it would "
       "become a comment)"},
      {id_of<siemens::dialect>(), "D0\n",
       "t:1:1: error: D0: tool length compensation off (D0) of siemens is not translated into heidenhain yet (it "
       "would become a comment)"},
      {id_of<iso::dialect>(), "G17 G40 G80 G90 G05.1 Q1\n", ""},
      {id_of<siemens::dialect>(), "G17 G40 G90 SOFT D1\n", ""},
  };
  for (const case_row& r : rows) {
    INFO(r.text);
    const read_result read = r.from == id_of<iso::dialect>() ? iso::read(r.text, "t") : siemens::read(r.text, "t");
    REQUIRE(read.ok());
    kin5::translation out;
    source_context ctx;
    ctx.language = r.from;
    ctx.output = id_of<heidenhain::dialect>();
    ctx.out = &out;
    const bool ok = check_kept_words(read.parsed.blocks.at(0), ctx);
    CHECK(ok == r.error.empty());
    if (r.error.empty()) continue;
    REQUIRE(out.errors.size() == 1);
    CHECK(out.errors[0].to_string() == r.error);
    ctx.output = r.from;  // the same dialect writes it back as code
    CHECK(check_kept_words(read.parsed.blocks.at(0), ctx));
  }
  // TOOL CALL along X or Y: a tool axis the other dialects cannot say.
  const read_result h = heidenhain::read("TOOL CALL 5 Y S1000\n", "t");
  REQUIRE(h.ok());
  source_context ctx;
  ctx.language = id_of<heidenhain::dialect>();
  ctx.output = id_of<iso::dialect>();
  CHECK_FALSE(check_kept_words(h.parsed.blocks.at(0), ctx));
}
