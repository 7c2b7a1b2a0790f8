// Siemens input beyond its bad-input table (errors.txt, read by the dialect laws): every line of
// bad input is still a block; what is passed through; what the writer refuses.
#include <cstddef>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/siemens/dialect.hpp>

#include "../bad_inputs.hpp"

using namespace kin5::program;

TEST_CASE("siemens: every line of bad input is still a block", "[siemens][errors]") {
  // Control statements (statements.hpp) give no block, and an error in one stops the run: their
  // rows are left out.
  const auto has_control = [](const std::string& text) {
    bool control = false;
    for_each_line(text, [&](const text_line& l) {
      const auto s = siemens::statements{}.statement_of(l);
      control = control || s.kind != interp::statement_kind::ordinary || s.error;
    });
    return control;
  };
  for (const kin5::test::bad_input& c : kin5::test::bad_inputs_of<siemens::dialect>()) {
    if (c.errors.empty() || has_control(c.text)) continue;  // the rows that read without error
    INFO("input: " << c.text);
    std::size_t lines = c.text.ends_with('\n') ? 0 : 1;
    for (char ch : c.text) lines += ch == '\n';
    CHECK(siemens::read(c.text, "bad.mpf").parsed.blocks.size() == lines);
  }
}

TEST_CASE("siemens: lines without axis words that change nothing are passthrough, not errors", "[siemens][errors]") {
  // Cycles, jumps, M=, G4 and the like are refused instead (errors.txt); a label alone gives no
  // block (control_flow.cpp).
  for (const std::string text : {"R1=5", "MSG(\"drilling\")", "N20 STOPRE", "DEF REAL DEPTH", "_X=-2.5"}) {
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
  p.language = id_named("iso");  // a program read in ISO: this folder needs only its id
  p.file = "in.nc";
  block b;
  b.where = {"in.nc", 7, 1};
  p.blocks.push_back(b);

  p.blocks[0] = block{};
  p.blocks[0].where = {"in.nc", 3, 1};
  p.blocks[0].motion = motion_kind::arc_cw;
  p.blocks[0].axes.x_mm = 10;
  p.blocks[0].arc = arc_words{arc_plane::xy, kin5::vec3{5, 0, 0}, std::nullopt};
  CHECK_THROWS_WITH(siemens::write(p), "in.nc:3: arc centre needs a known start point (X Y Z)");

  p.blocks[0].feed_rapid = true;
  CHECK_THROWS_WITH(siemens::write(p), "in.nc:3: an arc at rapid traverse cannot be written");
}
