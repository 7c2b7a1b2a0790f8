// Bad input for the Siemens reader: each case is a program and the exact diagnostics it must
// give (`file:line:col: error: message`, columns counting bytes from 1). The expectations follow
// the rules in docs/dialects/siemens.md, written by hand.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/siemens/dialect.hpp>

#include "contract.hpp"

namespace {

using namespace kin5::program;


const std::string frame = " changes the working frame; kin5 does not model frame changes";
const std::string expr = "expressions and parameters in axis words are not supported";

const std::vector<kin5::test::bad_input> cases = {
    // letters without numbers, numbers without letters, truncated words
    {"G1 X", {"bad.mpf:1:4: error: word 'X' has no value"}},
    // a rate the writer cannot write back with the controller's 3 decimals
    {"G1 X1 F100 S.0101", {"bad.mpf:1:12: error: the spindle speed 0.0101 cannot be written with 3 decimals, the most the controller reads (it would read as another value)"}},
    {"G1 X1 F.0004", {"bad.mpf:1:7: error: the feed 0.0004 cannot be written with 3 decimals, the most the controller reads (it would read as 0)"}},
    {"G1 X10 Y", {"bad.mpf:1:8: error: word 'Y' has no value"}},
    {"G1 X=10 Y=", {"bad.mpf:1:9: error: word 'Y' has no value"}},
    {"G1 X-", {"bad.mpf:1:4: error: word 'X' has no value"}},
    {"G1 X10 20", {"bad.mpf:1:8: error: number '20' has no address letter"}},
    {"G1 X10 .5", {"bad.mpf:1:8: error: number '.5' has no address letter"}},
    {"N10 -3", {"bad.mpf:1:5: error: number '-3' has no address letter"}},
    // NaN, infinity, huge and malformed values
    {"G1 X1e999", {"bad.mpf:1:4: error: malformed number '1e999'"}},
    {"G1 X99999999999", {"bad.mpf:1:4: error: value out of range"}},
    {"G1 Y-1000000000.5", {"bad.mpf:1:4: error: value out of range"}},
    {"G1 XNAN", {"bad.mpf:1:4: error: value out of range"}},
    {"G1 X=INF", {"bad.mpf:1:4: error: value out of range"}},
    {"G1 X1.2.3", {"bad.mpf:1:4: error: malformed number '1.2.3'"}},
    {"G1 X=1.2.3", {"bad.mpf:1:4: error: malformed number '1.2.3'"}},
    {"G1 X10 F-5", {"bad.mpf:1:8: error: value out of range"}},
    // unknown words in a block with axis words
    {"G1 X10 U5", {"bad.mpf:1:8: error: unknown word 'U5'"}},
    {"G1 X10 FOO", {"bad.mpf:1:8: error: unknown word 'FOO'"}},
    {"G1 G41 X10", {"bad.mpf:1:4: error: G41: cutter radius compensation is not supported yet (the path would be off by the radius)"}},
    {"G1 X10 ADIS=0.5", {"bad.mpf:1:8: error: unknown word 'ADIS'"}},
    {"G1 X10 M=3", {"bad.mpf:1:8: error: unknown word 'M=3'"}},
    {"G1 X10 S=R1", {"bad.mpf:1:8: error: expressions and parameters are not supported"}},
    {"/N10 G1 X5", {"bad.mpf:1:1: error: block skip '/' is not supported"}},
    // binary garbage
    {"G1 X10 \x01", {"bad.mpf:1:8: error: unexpected byte 0x01"}},
    {"\x7fG1 X1", {"bad.mpf:1:1: error: unexpected byte 0x7f"}},
    {"G1 X10 \xc3\xa9", {"bad.mpf:1:8: error: unexpected byte 0xc3"}},
    {std::string("G1 X1\0Y2", 8), {"bad.mpf:1:6: error: unexpected byte 0x00"}},
    // the same word twice, conflicting words
    {"G1 X10 X20", {"bad.mpf:1:8: error: word 'X' appears twice"}},
    {"N1 N2 G1 X1", {"bad.mpf:1:4: error: word 'N' appears twice"}},
    {"G1 X1 F100 F200", {"bad.mpf:1:12: error: word 'F' appears twice"}},
    {"G0 G1 X1", {"bad.mpf:1:4: error: conflicting words 'G0' and 'G1'"}},
    {"TRAORI TRAFOOF", {"bad.mpf:1:8: error: conflicting words 'TRAORI' and 'TRAFOOF'"}},
    {"N1.5 G1 X1", {"bad.mpf:1:1: error: word 'N' needs a whole number"}},
    {"T1.5", {"bad.mpf:1:1: error: word 'T' needs a whole number"}},
    // expressions and parameters
    {"G1 X=R1", {"bad.mpf:1:4: error: " + expr}},
    {"G1 X=10+R2", {"bad.mpf:1:4: error: " + expr}},
    {"G1 Y=AC(5)", {"bad.mpf:1:4: error: " + expr}},
    {"G1 XQ1", {"bad.mpf:1:4: error: " + expr}},
    {"G1 X#100", {"bad.mpf:1:4: error: " + expr}},
    {"G1 X[1]", {"bad.mpf:1:4: error: " + expr}},
    {"G1 X10 CR=R5", {"bad.mpf:1:8: error: " + expr}},
    // incremental positioning, units
    {"G91 G1 X10", {"bad.mpf:1:1: error: incremental positioning (G91) is not supported"}},
    {"G1 X=IC(5)", {"bad.mpf:1:4: error: incremental positioning (IC) is not supported"}},
    {"G70", {"bad.mpf:1:1: error: inch programs are not supported"}},
    {"G71\nG1 X1\nG700 X2", {"bad.mpf:3:1: error: inch programs are not supported"}},
    // frame changes
    {"CYCLE800(0,\"TC1\",200000,57,0,0,0,30,0,0,0,0,0,1)", {"bad.mpf:1:1: error: CYCLE800" + frame}},
    {"TRANS X10", {"bad.mpf:1:1: error: TRANS" + frame}},
    {"N5 AROT Z45", {"bad.mpf:1:4: error: AROT" + frame}},
    {"ROT RPL=45", {"bad.mpf:1:1: error: ROT" + frame}},
    {"G58 X10", {"bad.mpf:1:1: error: G58" + frame}},
    {"TOFRAME", {"bad.mpf:1:1: error: TOFRAME" + frame}},
    {"$P_PFRAME=CTRANS(X,10)", {"bad.mpf:1:1: error: $P_PFRAME" + frame}},
    // arcs and vectors
    {"G1 X10 CR=5", {"bad.mpf:1:8: error: word 'CR' needs G2 or G3"}},
    {"G1 X10 I5", {"bad.mpf:1:8: error: word 'I' needs G2 or G3"}},
    {"G2 X10 I5", {"bad.mpf:1:8: error: arc start point is not known"}},
    {"G0 X0 Y0 Z0\nG2 X10", {"bad.mpf:2:4: error: arc needs a centre (I J K) or a radius (CR=)"}},
    {"G0 X0 Y0 Z0\nG3 X10 I5 CR=5", {"bad.mpf:2:8: error: arc has both a centre and a radius"}},
    {"G0 X0 Y0 Z0\nSUPA Z0\nG2 X10 I5 J0", {"bad.mpf:3:8: error: arc start point is not known"}},
    {"G1 A3=1 X5", {"bad.mpf:1:4: error: tool-axis vector needs A3, B3 and C3"}},
    {"G1 A3=1 B3=0 C3=0 A10", {"bad.mpf:1:4: error: rotary axes and a tool-axis vector in one block"}},
    {"G0 X0 Y0 Z0\nG2 X1 CR=", {"bad.mpf:2:7: error: word 'CR' has no value"}},
    {"G1 B3=0 C3=1 A3=", {"bad.mpf:1:14: error: word 'A3' has no value"}},
    {"G0 X0 Y0 Z0\nG2 X1 Y1 I=R1 J0", {"bad.mpf:2:10: error: " + expr}},
    {"G1 X=1e5 Y2", {"bad.mpf:1:4: error: malformed number '1e5'"}},
    // unclosed things
    {"G1 X10 (open", {"bad.mpf:1:8: error: comment '(' is not closed"}},
    {"MSG(\"open", {"bad.mpf:1:4: error: missing ')'"}},
    {"T=\"open", {"bad.mpf:1:3: error: string is not closed"}},
    // reading goes on after errors: one diagnostic per problem, in line order
    {"G1 X\nG1 Y\nG1 Z10", {"bad.mpf:1:4: error: word 'X' has no value", "bad.mpf:2:4: error: word 'Y' has no value"}},
    {"G1 X=R1 Y20 U1", {"bad.mpf:1:4: error: " + expr, "bad.mpf:1:13: error: unknown word 'U1'"}},
};

}  // namespace

/// The law "bad input gives exact diagnostics" (laws.cpp) reads each text and compares.
std::vector<kin5::test::bad_input> kin5::test::contract<siemens::dialect>::bad_inputs() { return cases; }

TEST_CASE("siemens: every line of bad input is still a block", "[siemens][errors]") {
  for (const auto& c : cases) {
    INFO("input: " << c.text);
    std::size_t lines = 1;
    for (char ch : c.text) lines += ch == '\n';
    CHECK(siemens::read(c.text, "bad.mpf").parsed.blocks.size() == lines);
  }
}

TEST_CASE("siemens: lines without axis words that change nothing are passthrough, not errors", "[siemens][errors]") {
  // Cycles, jumps, M=, G4 and the like are refused instead (tests/property/reading/refusal_table.cpp).
  for (const std::string text : {"R1=5", "MSG(\"drilling\")", "N20 STOPRE", "DEF REAL DEPTH", "_X=-2.5", "LOOP_END:"}) {
    INFO("input: " << text);
    const read_result r = siemens::read(text, "p.mpf");
    REQUIRE(r.ok());
    REQUIRE(r.parsed.blocks.size() == 1);
    const block& b = r.parsed.blocks[0];
    CHECK(b.passthrough);
    CHECK(b.text == text);
    CHECK_FALSE(b.moves());
    CHECK(b.m_codes.empty());
  }
}

TEST_CASE("siemens: writer refuses what Siemens cannot express", "[siemens][errors]") {
  program p;
  p.language = id_of<iso::dialect>();
  p.file = "in.nc";
  block b;
  b.where = {"in.nc", 7, 1};
  b.metric = false;
  p.blocks.push_back(b);
  CHECK_THROWS_WITH(siemens::write(p), "in.nc:7: inch units cannot be written; kin5 writes millimetres");

  p.blocks[0] = block{};
  p.blocks[0].where = {"in.nc", 3, 1};
  p.blocks[0].motion = motion_kind::arc_cw;
  p.blocks[0].axes.x_mm = 10;
  p.blocks[0].arc = arc_words{arc_plane::xy, kin5::vec3{5, 0, 0}, std::nullopt};
  CHECK_THROWS_WITH(siemens::write(p), "in.nc:3: arc centre needs a known start point (X Y Z)");

  p.blocks[0].feed_rapid = true;
  CHECK_THROWS_WITH(siemens::write(p), "in.nc:3: an arc at rapid traverse cannot be written");
}
