// Siemens constructs that change what later blocks do: `MCALL CYCLE81(…)` makes every later
// position a drilling cycle, so it is refused at the MCALL; `MCALL` alone cancels such a call and
// changes nothing here, so it is kept (written back as is).
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/siemens/dialect.hpp>

using namespace kin5::program;

TEST_CASE("siemens: a modal cycle call is refused at MCALL, its cancel is kept") {
  const read_result r = siemens::read("G0 X0 Y0 Z10\nMCALL CYCLE81(10.,0.,3.,-6.)\nX-12.5 Y-58.\nMCALL\nM30\n", "t.mpf");
  REQUIRE(r.errors.size() == 1);
  CHECK(r.errors[0].to_string() ==
        "t.mpf:2:1: error: MCALL CYCLE81: a modal cycle call is not supported (the cycle would run at every later position)");
  const read_result cancel = siemens::read("MCALL\nG0 X0 Y0 Z10\nM30\n", "t.mpf");
  REQUIRE(cancel.ok());
  CHECK(cancel.parsed.blocks[0].kept_words == std::vector<std::string>{"MCALL"});
  CHECK(siemens::write(cancel.parsed).find("MCALL\n") != std::string::npos);
}
