// program/io.hpp: the dialect table, dialect recognition, and read/write dispatch.
#include <kin5/program/io.hpp>

#include <catch2/catch.hpp>

namespace kp = kin5::program;

// default_dialect and guess_dialect are constexpr: these hold if the file compiles.
static_assert(kp::default_dialect("sajo-12000p") == kp::id_of<kp::siemens::dialect>());
static_assert(kp::default_dialect("dmu-80p") == kp::id_of<kp::heidenhain::dialect>());
static_assert(kp::default_dialect("dmu-50v") == kp::id_of<kp::heidenhain::dialect>());
static_assert(kp::default_dialect("ac-trunnion") == kp::id_of<kp::siemens::dialect>());
static_assert(kp::default_dialect("ac-head") == kp::id_of<kp::siemens::dialect>());
static_assert(kp::default_dialect("b-head-a-tilted-table") == kp::id_of<kp::siemens::dialect>());
static_assert(kp::default_dialect("a-rotary-4axis") == kp::id_of<kp::iso::dialect>());
static_assert(!kp::default_dialect("dmu80p"));
static_assert(!kp::default_dialect(""));

static_assert(kp::guess_dialect("0 BEGIN PGM P MM\n1 L X+1 FMAX\n") == kp::id_of<kp::heidenhain::dialect>());
static_assert(kp::guess_dialect("%_N_PART_MPF\nN10 G1 X1\n") == kp::id_of<kp::siemens::dialect>());
static_assert(kp::guess_dialect("N10 G1 X1\nN20 traori\n") == kp::id_of<kp::siemens::dialect>());  // any case
static_assert(kp::guess_dialect("PARTNO P\nGOTO/1,2,3\nFINI\n") == kp::id_of<kp::apt::dialect>());
static_assert(kp::guess_dialect("O1000\nG43.4 H1\nG1 X1\n") == kp::id_of<kp::iso::dialect>());
static_assert(kp::guess_dialect("N1 M128\r\nN2 L X+1\r\n") == kp::id_of<kp::heidenhain::dialect>());
static_assert(!kp::guess_dialect("G1 X1 Y2\nM30\n"));                  // no marker
static_assert(!kp::guess_dialect("N10 TRAORI\nN20 M128\n"));           // two dialects
static_assert(!kp::guess_dialect("N10 M1280\nN20 XTRAORI=1\n"));      // not whole words
static_assert(!kp::guess_dialect(""));

TEST_CASE("read and write dispatch on the dialect value", "[io]") {
  const auto in = kp::read(kp::id_of<kp::siemens::dialect>(), "N10 TRAORI\nN20 G1 X1.5 Y2 Z3 A-10 B20 F500\n", "p.mpf");
  REQUIRE(in.ok());
  REQUIRE(in.parsed.blocks.size() == 2);
  CHECK(in.parsed.blocks[1].where == kp::source_location{"p.mpf", 2, 1});
  CHECK(in.parsed.blocks[1].axes.x_mm == 1.5);
  CHECK(in.parsed.blocks[1].axes.a_deg == -10.0);

  const std::string heidenhain = kp::write(kp::id_of<kp::heidenhain::dialect>(), in.parsed);
  CHECK(heidenhain.find("L X+1.5 Y+2 Z+3 A-10 B+20 F500") != std::string::npos);
  const std::string siemens = kp::write(kp::id_of<kp::siemens::dialect>(), in.parsed);
  CHECK(siemens.find("X1.5 Y2 Z3 A-10 B20 F500") != std::string::npos);

  const auto cl = kp::read(kp::id_of<kp::apt::dialect>(), "GOTO/1,2,3,0,0,1\n", "p.cls");
  REQUIRE(cl.ok());
  CHECK(kp::write(kp::id_of<kp::apt::dialect>(), cl.parsed) == "GOTO/1,2,3,0,0,1\n");
  // Rotary axis words have no APT form: the writer refuses, naming the block.
  CHECK_THROWS_AS(kp::write(kp::id_of<kp::apt::dialect>(), in.parsed), std::invalid_argument);
}

TEST_CASE("read reports errors with their location, in any dialect", "[io]") {
  const auto s = kp::read(kp::id_of<kp::siemens::dialect>(), "N10 G1 X1\nN20 TRANS X1\n", "bad.mpf");
  REQUIRE(s.errors.size() == 1);
  CHECK(s.errors[0].where.line == 2);
  CHECK(s.errors[0].where.column == 5);
  // G91 after an absolute X is read, to the position it reaches (it was refused before).
  const auto g91 = kp::read(kp::id_of<kp::siemens::dialect>(), "N10 G1 X1\nN20 G91 X1\n", "ok.mpf");
  REQUIRE(g91.ok());
  CHECK(g91.parsed.blocks[1].axes.x_mm == 2);
  const auto a = kp::read(kp::id_of<kp::apt::dialect>(), "GOTO/1,2\n", "bad.cls");
  REQUIRE(a.errors.size() == 1);
  CHECK(a.errors[0].where.line == 1);
}
