// Heidenhain's two TCP switches (`write_options::tcp`, the tool's --tcp-word): a program of
// another dialect written with M128/M129 or with FUNCTION TCPM / FUNCTION RESET TCPM reads back
// with the same moves under the same tool-tip tracking, each form written only as chosen, and
// no TOOL CALL while tracking is on (the control refuses one under M128 or FUNCTION TCPM).
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <kin5/program/heidenhain/dialect.hpp>
#include <kin5/program/iso/dialect.hpp>

using namespace kin5::program;

namespace {

/// One move as the control runs it: where to, and whether tracking is on for it.
struct tracked_move {
  std::optional<double> x_mm, a_deg;
  bool tcp = false;
  bool operator==(const tracked_move&) const = default;
};

/// The moves of `p` with the tracking in effect for each; `tool_call_under_tcp` is set when a
/// TOOL CALL block comes while tracking is on.
std::vector<tracked_move> moves_of(const program& p, bool& tool_call_under_tcp) {
  std::vector<tracked_move> out;
  bool tcp = false;
  for (const block& b : p.blocks) {
    if (b.tcp) tcp = *b.tcp;
    const bool change = b.state.tool_change;
    if (change && tcp) tool_call_under_tcp = true;
    if (b.moves()) out.push_back({b.axes.x_mm, b.axes.a_deg, tcp});
  }
  return out;
}

/// A program as an ISO reader would give it: moves, some switching TCP on or off, and tool
/// changes (`T n M6`) between them.
program draw_iso_program() {
  program p;
  p.language = id_of<iso::dialect>();
  p.file = "t.nc";
  const int n = *rc::gen::inRange(1, 25);
  for (int k = 0; k < n; ++k) {
    block b;
    b.where = {"t.nc", static_cast<std::size_t>(k + 1), 1};
    switch (*rc::gen::inRange(0, 4)) {
      case 0:  // a tool change
        b.tool = *rc::gen::inRange(1, 99);
        b.state.tool_change = true;
        break;
      case 1:  // TCP switched with a move, or alone
      case 2:
        b.tcp = *rc::gen::arbitrary<bool>();
        if (*rc::gen::arbitrary<bool>()) break;
        [[fallthrough]];
      default:  // a move
        b.motion = motion_kind::linear;
        b.axes.x_mm = *rc::gen::inRange(-500, 500) * 1.0;
        b.axes.a_deg = *rc::gen::inRange(-90, 90) * 1.0;
        b.feed = 1000.0;
    }
    p.blocks.push_back(std::move(b));
  }
  return p;
}

}  // namespace

TEST_CASE("heidenhain: M128 and FUNCTION TCPM outputs run the same moves under the same tracking") {
  rc::prop("either TCP word", [] {
    const program source = draw_iso_program();
    bool under_source = false;
    const std::vector<tracked_move> wanted = moves_of(source, under_source);
    for (const heidenhain::tcp_word form : {heidenhain::tcp_word::m128, heidenhain::tcp_word::function_tcpm}) {
      heidenhain::write_options options;
      options.tcp = form;
      const std::string text = heidenhain::write(source, options);
      const read_result back = heidenhain::read(text, "t.h");
      RC_ASSERT(back.ok());
      bool under_tcp = false;
      RC_ASSERT(moves_of(back.parsed, under_tcp) == wanted);
      RC_ASSERT(!under_tcp);
      const bool m_words = text.find("M128") != std::string::npos || text.find("M129") != std::string::npos;
      const bool function_words = text.find("TCPM") != std::string::npos;
      if (form == heidenhain::tcp_word::m128) RC_ASSERT(!function_words);
      else RC_ASSERT(!m_words);
    }
  });
}

TEST_CASE("heidenhain: FUNCTION TCPM read as Heidenhain is rewritten in the chosen form") {
  const read_result in = heidenhain::read(
      "BEGIN PGM T MM\nFUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\nL X+1 A+2 F100\nFUNCTION RESET TCPM\n"
      "END PGM T MM\n",
      "t.h");
  REQUIRE(in.ok());
  heidenhain::write_options options;
  CHECK(heidenhain::write(in.parsed, options).find("1 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n") !=
        std::string::npos);  // no form chosen: the program's own
  options.tcp = heidenhain::tcp_word::m128;
  const std::string m128 = heidenhain::write(in.parsed, options);
  CHECK(m128.find("TCPM") == std::string::npos);
  CHECK(m128.find("1 M128\n") != std::string::npos);
  options.tcp = heidenhain::tcp_word::function_tcpm;
  const std::string tcpm = heidenhain::write(in.parsed, options);
  CHECK(tcpm.find("1 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n") != std::string::npos);
  CHECK(tcpm.find("3 FUNCTION RESET TCPM\n") != std::string::npos);
  CHECK(tcpm.find("M12") == std::string::npos);
}
