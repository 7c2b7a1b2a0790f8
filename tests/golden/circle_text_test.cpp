// Arcs through CL data as text, each row worked out by hand: a quarter circle of radius 10 about
// (0, 0, 5) in each principal plane, both ways round, reversed from ISO (`kin5 reverse`: G2/G3
// with I J K become `CIRCLE/xc,yc,zc,i,j,k,r` and the GOTO of the end) and posted back (`kin5
// post`: the CIRCLE becomes G2/G3 with the same centre). The plane vector is the plane's normal
// (XY +Z, ZX +Y, YZ +X), reversed for a clockwise arc: Creo's right-hand rule (docs/dialects/
// apt.md, "Circles"). The tool stays along +Z (A0 C0 on the AC trunnion), so every GOTO ends
// 0,0,1 and the ISO block is the tip.
#include <algorithm>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/kin5.hpp>
#include <kin5/translate/by_id.hpp>

namespace {

using kin5::program::dialect;
using kin5::program::id_of;

/// `text` in dialect `from` through `t` into `to`: the text, or the first error.
std::string through(kin5::block_translator& t, std::string text, dialect from, dialect to) {
  kin5::string_sink out;
  const auto run = kin5::stream_text(t, std::move(text), from, "in", to, out);
  if (run.ok(t)) return out.text;
  if (!run.input.errors.empty()) return run.input.errors.front().to_string();
  if (run.writer_error) return run.writer_error->to_string();
  return t.result().errors.empty() ? "not ok" : t.result().errors.front().to_string();
}

struct row {
  const char* what;
  const char* start;  // X Y Z of the arc's start, ISO words
  const char* arc;    // the ISO arc block
  const char* cl;     // its CIRCLE and GOTO
};

// Start, end and I J K (the centre from the start) are the same numbers in both columns.
const std::vector<row> rows = {
    {"XY, counter-clockwise: +Z", "X10. Y0. Z5.", "G3 X0. Y10. I-10. J0.", "CIRCLE/0,0,5,0,0,1,10\nGOTO/0,10,5,0,0,1\n"},
    {"XY, clockwise: -Z", "X10. Y0. Z5.", "G2 X0. Y-10. I-10. J0.", "CIRCLE/0,0,5,0,0,-1,10\nGOTO/0,-10,5,0,0,1\n"},
    {"ZX, counter-clockwise: +Y", "X0. Y0. Z15.", "G18 G3 X10. Z5. I0. K-10.",
     "CIRCLE/0,0,5,0,1,0,10\nGOTO/10,0,5,0,0,1\n"},
    {"ZX, clockwise: -Y", "X0. Y0. Z15.", "G18 G2 X-10. Z5. I0. K-10.",
     "CIRCLE/0,0,5,0,-1,0,10\nGOTO/-10,0,5,0,0,1\n"},
    {"YZ, counter-clockwise: +X", "X0. Y10. Z5.", "G19 G3 Y0. Z15. J-10. K0.",
     "CIRCLE/0,0,5,1,0,0,10\nGOTO/0,0,15,0,0,1\n"},
    {"YZ, clockwise: -X", "X0. Y10. Z5.", "G19 G2 Y0. Z-5. J-10. K0.",
     "CIRCLE/0,0,5,-1,0,0,10\nGOTO/0,0,-5,0,0,1\n"},
};

/// The GOTO of a row's start, as CL text.
std::string start_goto(const row& r) {
  std::string s = r.start, out = "GOTO/";
  for (char c : s)
    if (c == ' ') out += ',';
    else if (c != 'X' && c != 'Y' && c != 'Z' && c != '.') out += c;
  return out + ",0,0,1\n";
}

}  // namespace

TEST_CASE("reverse: an ISO quarter circle is CIRCLE and the GOTO of its end") {
  const dialect iso = id_of<kin5::program::iso::dialect>();
  for (const row& r : rows) {
    CAPTURE(r.what);
    const std::string nc = std::string("G21 G90\nT1 M6\nG43.4 H1\nG1 ") + r.start + " A0. C0. F200.\n" + r.arc + "\nM30\n";
    // from the feed on: what the lines before say of the tool and tracking is not this test's
    const std::string cl = "FEDRAT/MMPM,200\n" + start_goto(r) + r.cl + "FINI\n";
    auto t = kin5::make_reverse("ac-trunnion", iso, "in");
    const std::string out = through(*t, nc, iso, kin5::program::cl_data_dialect());
    CHECK(out.substr(out.size() - std::min(out.size(), cl.size())) == cl);
  }
}

TEST_CASE("post: a CIRCLE is the ISO arc with the same centre, radius and direction") {
  const dialect iso = id_of<kin5::program::iso::dialect>(), apt = kin5::program::cl_data_dialect();
  for (const row& r : rows) {
    CAPTURE(r.what);
    const std::string cl = "UNITS/MM\nLOADTL/1\nFEDRAT/MMPM,200\n" + start_goto(r) + r.cl + "FINI\n";
    const std::string nc = std::string("%\nO0001\nG21\nT1 M6\nG94 F200.\nG1 G43.4 H1 ") + r.start + " A0. C0.\n" + r.arc +
                           "\nG49 M30\n%\n";
    auto t = kin5::make_post("ac-trunnion", apt, iso, "in");
    CHECK(through(*t, cl, apt, iso) == nc);
  }
}

TEST_CASE("post: a CIRCLE in Heidenhain is its CC and C with DR+ for counter-clockwise") {
  const dialect tnc = id_of<kin5::program::heidenhain::dialect>(), apt = kin5::program::cl_data_dialect();
  const std::string cl = "UNITS/MM\nLOADTL/1\nFEDRAT/MMPM,200\nGOTO/10,0,5,0,0,1\nCIRCLE/0,0,5,0,0,1,10\nGOTO/0,10,5\n"
                         "CIRCLE/0,0,5,0,0,-1,10\nGOTO/10,0,5\nFINI\n";
  auto t = kin5::make_post("ac-trunnion", apt, tnc, "in");
  const std::string nc = through(*t, cl, apt, tnc);
  CHECK(nc.find("CC X+0 Y+0\n4 C X+0 Y+10 DR+\n5 C X+10 Y+0 DR-\n") != std::string::npos);
}
