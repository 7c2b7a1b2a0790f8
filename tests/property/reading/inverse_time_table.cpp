// Inverse-time feed through `reverse`: an ISO program with G93 becomes APT CL data whose
// FEDRAT/INVERS values are the source's F (one GOTO per source block: the same block time),
// and per-minute feeds after G94 are FEDRAT/MMPM again.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <kin5/machines/catalog.hpp>
#include <kin5/program/io.hpp>
#include <kin5/translate/translate.hpp>

using namespace kin5;

TEST_CASE("inverse time: G93 blocks are written as FEDRAT/INVERS by reverse") {
  const std::string text =
      "G43.4 H1\n"
      "G94 G1 X0. Y0. Z100. A0. C0. F1000.\n"
      "G93 G1 X10. F20.\n"
      "G1 X20. F30.\n"
      "G94 G1 X30. F1000.\n"
      "M30\n";
  const program::read_result nc = program::read(program::id_of<program::iso::dialect>(), text, "t.nc");
  REQUIRE(nc.ok());
  const translation cl = reverse<machines::ac_trunnion>(nc.parsed);
  REQUIRE(cl.errors.empty());
  const std::string apt = program::write(program::id_of<program::apt::dialect>(), cl.output);
  INFO(apt);
  CHECK(apt.find("FEDRAT/MMPM,1000\n") != std::string::npos);
  CHECK(apt.find("FEDRAT/INVERS,20\n") != std::string::npos);
  CHECK(apt.find("FEDRAT/INVERS,30\n") != std::string::npos);
  CHECK(apt.find("FEDRAT/MMPM,1000\n", apt.find("FEDRAT/INVERS,30")) != std::string::npos);
  const program::read_result back = program::read(program::id_of<program::apt::dialect>(), apt, "t.cls");
  REQUIRE(back.ok());
}

namespace {

std::string two_decimals(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  return text;
}

/// The time (minutes) of every feed move of `blocks` after the first: inverse time 1/F, per
/// minute the tip path (from the previous point, linear axes only: the programs below keep
/// their rotary axes still or move the tip with them under TCP) over F.
std::vector<double> move_times(const std::vector<program::block>& blocks) {
  std::vector<double> out;
  program::feed_unit mode = program::feed_unit::per_minute;
  std::optional<vec3> at;
  for (const program::block& b : blocks) {
    if (b.feed_mode) mode = *b.feed_mode;
    if (!b.moves()) continue;
    const vec3 to{*b.axes.x_mm, *b.axes.y_mm, *b.axes.z_mm};
    if (at && b.feed && !b.feed_rapid && b.motion != program::motion_kind::rapid)
      out.push_back(mode == program::feed_unit::inverse_time ? 1.0 / *b.feed : norm(to - *at) / *b.feed);
    at = to;
  }
  return out;
}

translation into_heidenhain(const std::string& iso_text) {
  const program::read_result nc = program::read(program::id_of<program::iso::dialect>(), iso_text, "t.nc");
  REQUIRE(nc.ok());
  translate_options options;
  options.output_dialect = program::id_of<program::heidenhain::dialect>();
  return translate<machines::ac_trunnion, machines::ac_trunnion>(nc.parsed, options);
}

}  // namespace

TEST_CASE("inverse time: into Heidenhain each move keeps its time as a per-minute F") {
  const std::string text =
      "G43.4 H1\n"
      "G94 G1 X0. Y0. Z100. A0. C0. F1000.\n"
      "G93 G1 X10. F20.\n"          // 10 mm in 1/20 min: F200
      "G1 X20. Y5. Z90. F7.5\n"     // 15 mm in 1/7.5 min: F112.5
      "G1 X20.5 F600.\n"            // 0.5 mm in 1/600 min: F300
      "G94 G1 X30. F1000.\n"
      "M30\n";
  const translation t = into_heidenhain(text);
  REQUIRE(t.errors.empty());
  const std::string hh = program::write(program::id_of<program::heidenhain::dialect>(), t.output);
  INFO(hh);
  const program::read_result back = program::read(program::id_of<program::heidenhain::dialect>(), hh, "t.h");
  REQUIRE(back.ok());
  const program::read_result source = program::read(program::id_of<program::iso::dialect>(), text, "t.nc");
  const std::vector<double> want = move_times(source.parsed.blocks), got = move_times(back.parsed.blocks);
  REQUIRE(got.size() == want.size());
  for (std::size_t k = 0; k < want.size(); ++k) CHECK(got[k] == Approx(want[k]).epsilon(1e-9));
  CHECK(hh.find("F200") != std::string::npos);
  CHECK(hh.find("F112.5") != std::string::npos);
  CHECK(hh.find("F300") != std::string::npos);
}

TEST_CASE("inverse time: into Heidenhain a random program's moves keep their times") {
  // The rotary axes turn too: under tool-tip tracking the control feeds along the tip's path,
  // so the distance that keeps a move's time is the tip's, not the (K16) axis distance that
  // counts degrees as millimetres (a writer using it fails here).
  rc::prop("each output move's time is the source's, within the written F's last decimal", [] {
    std::string text = "G43.4 H1\nG94 G1 X0. Y0. Z0. A0. C0. F1000.\nG93\n";
    const int n = *rc::gen::inRange(1, 30);
    double x = 0;  // X grows by 1 mm or more: every move's tip moves
    for (int k = 0; k < n; ++k) {
      x += *rc::gen::inRange(100, 5001) / 100.0;
      const auto coordinate = [] { return two_decimals(*rc::gen::inRange(-500, 501) / 100.0); };
      const std::string a = two_decimals(*rc::gen::inRange(-9000, 9001) / 100.0);
      const std::string c = two_decimals(*rc::gen::inRange(-17000, 17001) / 100.0);
      text += "G1 X" + two_decimals(x) + " Y" + coordinate() + " Z" + coordinate() + " A" + a + " C" + c + " F" +
              two_decimals(*rc::gen::inRange(10000, 100001) / 100.0) + "\n";
    }
    const program::read_result source = program::read(program::id_of<program::iso::dialect>(), text, "t.nc");
    RC_ASSERT(source.ok());
    const std::vector<double> want = move_times(source.parsed.blocks);
    const translation t = into_heidenhain(text);
    RC_ASSERT(t.errors.empty());
    const program::read_result back = program::read(
        program::id_of<program::heidenhain::dialect>(), program::write(program::id_of<program::heidenhain::dialect>(), t.output), "t.h");
    RC_ASSERT(back.ok());
    const std::vector<double> got = move_times(back.parsed.blocks);
    RC_ASSERT(got.size() == want.size());
    for (std::size_t k = 1; k < want.size(); ++k) {  // the first is the per-minute approach
      // F (100 mm/min or more) is written to 0.1 mm/min; the positions exactly (2 decimals).
      RC_ASSERT(std::abs(got[k] - want[k]) <= want[k] * 0.05 / 100.0 + 1e-12);
    }
  });
}

TEST_CASE("inverse time: into Heidenhain a move whose tip does not move is refused") {
  const translation t = into_heidenhain("G43.4 H1\nG94 G1 X0. Y0. Z100. A0. C0. F1000.\nG93 G1 C30. F20.\nM30\n");
  REQUIRE(t.errors.size() == 1);
  CHECK(t.errors.front().to_string() ==
        "t.nc:3:1: error: inverse-time move whose tool tip does not move (a rotation alone) cannot keep its time in "
        "heidenhain, which has no inverse-time feed");
}

TEST_CASE("inverse time: a feed move without its own F is refused at the block by the Fanuc-grammar readers") {
  // In G93 F is not modal there: each G1, G2, G3 block gives its time (docs/dialects/iso.md).
  // A rapid needs none; the row's second move lacks F.
  const std::string message =
      "error: feed move in inverse time (G93) without its own F: in G93 each G1, G2 and G3 block gives its time as F "
      "(write F in this block)";
  struct row {
    program::dialect d;
    std::string text, where;
  };
  const std::vector<row> rows = {
      {program::id_of<program::iso::dialect>(), "G93 G1 X10. F20.\nG0 X0.\n  G1 X20.\n", "t:3:3: "},
      {program::id_of<program::haas::dialect>(), "G93 G1 X10. F20.\nG0 X0.\n  G1 X20.\n", "t:3:3: "},
      {program::id_of<program::linuxcnc::dialect>(), "G93 G1 X10 F20\nG0 X0\n  G1 X20\n", "t:3:3: "},
      {program::id_of<program::iso::dialect>(), "G93\nG2 X10. R5. F2.\nX0. R5.\n", "t:3:1: "},
  };
  for (const row& r : rows) {
    INFO(r.text);
    const program::read_result got = program::read(r.d, r.text, "t");
    REQUIRE(got.errors.size() == 1);
    CHECK(got.errors.front().to_string() == r.where + message);
    // The same program with F on its last move too reads.
    const bool point = r.d != program::id_of<program::linuxcnc::dialect>();
    std::string fixed = r.text;
    fixed.insert(fixed.size() - 1, point ? " F30." : " F30");
    CHECK(program::read(r.d, fixed, "t").ok());
  }
}

TEST_CASE("inverse time: a Siemens feed move without F takes the F in effect since G93, or is refused") {
  // On the 840D F stays in effect, and a switch between G93 and G94 needs a new one
  // (docs/dialects/siemens.md): the block gets the F in effect written into it, its time.
  const auto siemens = program::id_of<program::siemens::dialect>();
  const program::read_result carried = program::read(siemens, "G93 G1 X10 F20\nX20\nG0 X0\nG1 X5\n", "t");
  REQUIRE(carried.ok());
  REQUIRE(carried.parsed.blocks.size() == 4);
  CHECK(carried.parsed.blocks[1].feed == 20.0);
  CHECK_FALSE(carried.parsed.blocks[2].feed.has_value());  // a rapid takes none
  CHECK(carried.parsed.blocks[3].feed == 20.0);
  const program::read_result switched = program::read(siemens, "G94 G1 X0 F100\nG93\n  G1 X20\n", "t");
  REQUIRE(switched.errors.size() == 1);
  CHECK(switched.errors.front().to_string() ==
        "t:3:3: error: feed move in inverse time (G93) without F since G93: the block's time is not known (write F "
        "in this block)");
}
