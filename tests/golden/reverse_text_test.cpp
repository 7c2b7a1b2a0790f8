// `kin5 reverse` as text: NC programs of every dialect into APT CL data, through the streaming
// driver the tool runs, each row with its CL text worked out by hand. Every tool axis here is
// +Z (all rotary angles 0) under tool-tip tracking, so each GOTO is the block's X Y Z with
// 0,0,1. The rows are the order of a moving block's M functions (docs/dialects/apt.md, "M
// functions on a moving block"): spindle and coolant on before the GOTO; SPINDL/OFF,
// COOLNT/OFF, STOP and OPSTOP after it, except from LinuxCNC, which stops the spindle and the
// coolant before the move.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/kin5.hpp>
#include <kin5/translate/by_id.hpp>

namespace {

using kin5::program::dialect;
using kin5::program::id_of;

/// `text` (dialect `d`) reversed on catalog machine `machine`: the CL text, or the first error.
std::string reversed(const char* machine, dialect d, std::string text) {
  auto t = kin5::make_reverse(machine, d, "in");
  kin5::string_sink out;
  const auto run = kin5::stream_text(*t, std::move(text), d, "in", kin5::program::cl_data_dialect(), out);
  if (run.ok(*t)) return out.text;
  if (!run.input.errors.empty()) return run.input.errors.front().to_string();
  if (run.writer_error) return run.writer_error->to_string();
  return t->result().errors.empty() ? "not ok" : t->result().errors.front().to_string();
}

struct row {
  const char* what;
  const char* machine;
  dialect d;
  const char* nc;
  const char* cl;  // the CL text, or the error
};

}  // namespace

TEST_CASE("reverse: an M function of a moving block is written where its controller runs it") {
  const auto iso = id_of<kin5::program::iso::dialect>(), lc = id_of<kin5::program::linuxcnc::dialect>();
  const auto sie = id_of<kin5::program::siemens::dialect>(), tnc = id_of<kin5::program::heidenhain::dialect>();
  const std::vector<row> rows = {
      {"ISO: M3 M8 start the move, M5 M9 and M1 end it, M30 after the last", "ac-trunnion", iso,
       "G21 G90\nT1 M6\nG43.4 H1\nG1 X1. Y2. Z3. A0. C0. F200. S8000 M3 M8\nX4. M5 M9\nX5. M1\nX6. M30\n",
       "UNITS/MM\nLOADTL/1\n$$ tool-tip tracking on\nSPINDL/8000,CLW\nCOOLNT/ON\nFEDRAT/MMPM,200\nGOTO/1,2,3,0,0,1\n"
       "GOTO/4,2,3,0,0,1\nSPINDL/OFF\nCOOLNT/OFF\nGOTO/5,2,3,0,0,1\nOPSTOP\nGOTO/6,2,3,0,0,1\nFINI\n"},
      {"ISO: a tool change beside a move is the machine maker's", "ac-trunnion", iso,
       "G21 G90\nT1 M6\nG43.4 H1\nG1 X1. Y2. Z3. A0. C0. F200.\nT1 M6 X4.\n",  // T1 again: H1 stays its own
       "in:5:1: error: block cannot be written in APT: tool change (M6) in a block that moves (before or after the "
       "move?)"},
      {"Siemens: M5 M9 and M0 after the move", "sajo-12000p", sie,
       "N10 T1 M6\nN20 TRAORI\nN30 G1 X1 Y2 Z3 A0 B0 F200 S8000 M3 M8\nN40 X4 M5 M9\nN50 X5 M0\nN60 TRAFOOF\nN70 M30\n",
       "LOADTL/1\n$$ tool-tip tracking on\nSPINDL/8000,CLW\nCOOLNT/ON\nFEDRAT/MMPM,200\nGOTO/1,2,3,0,0,1\n"
       "GOTO/4,2,3,0,0,1\nSPINDL/OFF\nCOOLNT/OFF\nGOTO/5,2,3,0,0,1\nSTOP\n$$ tool-tip tracking off\nFINI\n"},
      {"Heidenhain: M3 M8 at the block's start, M5 M9 M0 at its end", "dmu-80p", tnc,
       "0 BEGIN PGM G MM\n1 TOOL CALL 1 Z S8000\n2 M128\n3 L X+1 Y+2 Z+3 B+0 C+0 F200 M3 M8\n4 L X+4 M5 M9\n"
       "5 L X+5 M0\n6 M129\n7 END PGM G MM\n",
       "PARTNO G\nUNITS/MM\nLOADTL/1\nSPINDL/8000 $$ heidenhain: Z\n$$ tool-tip tracking on\nSPINDL/CLW\nCOOLNT/ON\n"
       "FEDRAT/MMPM,200\nGOTO/1,2,3,0,0,1\nGOTO/4,2,3,0,0,1\nSPINDL/OFF\nCOOLNT/OFF\nGOTO/5,2,3,0,0,1\nSTOP\n"
       "$$ tool-tip tracking off\nUNITS/MM\nFINI\n"},
      {"LinuxCNC: M5 M9 before the move, M0 after it", "xyzac-trt", lc,
       "G21 G90\nT1 M6\nG43\nM428\nG1 X1 Y2 Z3 A0 C0 F200 S8000 M3 M8\nX4 M5 M9\nX5 M0\nM429\nM2\n",
       "UNITS/MM\nLOADTL/1\n$$ G43\n$$ tool-tip tracking on\nSPINDL/8000,CLW\nCOOLNT/ON\nFEDRAT/MMPM,200\n"
       "GOTO/1,2,3,0,0,1\nSPINDL/OFF\nCOOLNT/OFF\nGOTO/4,2,3,0,0,1\nGOTO/5,2,3,0,0,1\nSTOP\n"
       "$$ tool-tip tracking off\nFINI\n"},
  };
  for (const row& r : rows) {
    CAPTURE(r.what);
    CHECK(reversed(r.machine, r.d, r.nc) == r.cl);
  }
}
