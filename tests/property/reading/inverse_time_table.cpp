// Inverse-time feed through `reverse`: an ISO program with G93 becomes APT CL data whose
// FEDRAT/INVERS values are the source's F (one GOTO per source block: the same block time),
// and per-minute feeds after G94 are FEDRAT/MMPM again.
#include <string>

#include <catch2/catch.hpp>

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
