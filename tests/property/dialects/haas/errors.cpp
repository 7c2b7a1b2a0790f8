// Haas input beyond its bad-input table (errors.txt, read by the dialect laws): reading goes on
// after an error, and the codes Haas spells otherwise than Fanuc read into the same model.
#include <catch2/catch.hpp>

#include <kin5/program/haas/dialect.hpp>
#include <kin5/program/iso/dialect.hpp>

using namespace kin5::program;

TEST_CASE("haas: reading goes on after an error and keeps every line") {
  const read_result r = haas::read("G43.4 H1\nG1 X1. F100.\nG154 P100\nG1 Y2.\n", "t.nc");
  CHECK(r.errors.size() == 2);
  REQUIRE(r.parsed.blocks.size() == 4);
  CHECK(r.parsed.blocks[3].axes.y_mm == 2.0);
}

TEST_CASE("haas: G234, G154 and G04 P read as ISO's G43.4, G54.1 and G4 X do") {
  const read_result h = haas::read("G234 H7\nG154 P12\nG04 P2.5\nG04 P250\n", "h.nc");
  const read_result f = iso::read("G43.4 H7\nG54.1 P12\nG4 X2.5\nG4 P250\n", "h.nc");
  REQUIRE((h.ok() && f.ok()));
  REQUIRE(h.parsed.blocks.size() == f.parsed.blocks.size());
  for (std::size_t k = 0; k < h.parsed.blocks.size(); ++k) {
    block a = h.parsed.blocks[k], b = f.parsed.blocks[k];
    a.text.clear(), b.text.clear();
    CHECK(a == b);
  }
}
