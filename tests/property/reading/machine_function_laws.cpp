// Spindle, coolant and program stops between every ordered pair of dialects. A generated ISO
// program (S, M3/M4/M5, M7/M8/M9, M0/M1 and moves) is read, written in the source dialect and
// read back there (the source program), then written in the target dialect and read back by the
// target's own reader. At every move the three must agree on the spindle (direction and speed),
// the coolant (flood and mist) and the stops passed since the last move. These are the
// writers' law: which M functions may cross dialects at all is the translation's table
// (translate/m_codes.hpp: M7 into Heidenhain is refused there); a writer itself may refuse only
// nothing here (a refusal fails the law; `documented_refusal` names the only one a future
// writer may add: mist coolant, M7).
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>

#include <kin5/program/io.hpp>

#include "../m_numbers.hpp"
#include "dialect_pairs.hpp"

using namespace kin5::program;

namespace {

/// What the machine does at one move: the spindle, the coolant and the stops before it.
struct at_move {
  std::optional<int> spindle;  // 3, 4 or 5: the last M3/M4/M5
  std::optional<double> rpm;   // the last S
  bool flood = false, mist = false;
  int stops = 0, optional_stops = 0;  // M0 and M1 since the previous move
  friend bool operator==(const at_move&, const at_move&) = default;
};

/// The state at each move of `blocks`, from the M functions every dialect shares (M3 M4 M5,
/// M7 M8 M9, M0 M1; Heidenhain M13/M14 are M3/M4 with M8) and S.
std::vector<at_move> trace_of(const std::vector<block>& blocks) {
  std::vector<at_move> out;
  at_move now;
  for (const block& b : blocks) {
    if (b.spindle_rpm) now.rpm = *b.spindle_rpm;
    for (int m : kin5::test::m_numbers_of(b)) {
      if (m == 3 || m == 4 || m == 5) now.spindle = m;
      if (m == 13 || m == 14) now.spindle = m - 10, now.flood = true;
      if (m == 7) now.mist = true;
      if (m == 8) now.flood = true;
      if (m == 9) now.flood = now.mist = false;
      if (m == 0) ++now.stops;
      if (m == 1) ++now.optional_stops;
    }
    if (b.moves()) {
      out.push_back(now);
      now.stops = now.optional_stops = 0;
    }
  }
  return out;
}

/// An ISO program of spindle, coolant and stop words between moves.
std::string draw_iso_text() {
  std::string text = "G90 G94 G21\n";
  const int n = *rc::gen::inRange(1, 30);
  double x = 0;
  for (int k = 0; k < n; ++k) {
    switch (*rc::gen::inRange(0, 8)) {
      case 0:
        text += "S" + std::to_string(*rc::gen::inRange(1, 24000)) + " M" +
                std::to_string(*rc::gen::element(3, 4)) + "\n";
        break;
      case 1:
        text += "M5\n";
        break;
      case 2:
        text += "S" + std::to_string(*rc::gen::inRange(1, 24000)) + "\n";
        break;
      case 3:
        text += "M" + std::to_string(*rc::gen::element(7, 8, 9)) + "\n";
        break;
      case 4:
        text += "M" + std::to_string(*rc::gen::element(0, 1)) + "\n";
        break;
      default:
        x += 1;
        text += "G1 X" + std::to_string(x) + " Y2.5 Z10. F500.\n";
    }
  }
  return text + "M30\n";
}

/// Whether `why` is a refusal a writer may make for these words: mist coolant (M7) where the
/// dialect has no equivalent. No writer refuses it today (every run is tagged "written").
bool documented_refusal(const std::string& why) { return why.find("M7") != std::string::npos; }

}  // namespace

TEST_CASE("machine functions: every ordered pair of dialects keeps spindle, coolant and stops at every move") {
  using kin5::test::all_dialects;
  kin5::test::check_each_pair(all_dialects(), all_dialects(), [](dialect from, dialect to) {
    const read_result iso = read(id_of<iso::dialect>(), draw_iso_text(), "gen.nc");
    RC_ASSERT(iso.ok());
    const std::vector<at_move> want = trace_of(iso.parsed.blocks);
    // Written in `d` and read back there, or empty where the writer refused (documented only).
    const auto through = [&want](dialect d, const program& p) -> std::optional<program> {
      std::string text;
      try {
        text = write(d, p);
      } catch (const std::invalid_argument& e) {
        RC_ASSERT(documented_refusal(e.what()));
        RC_TAG("refused");
        return std::nullopt;
      }
      read_result back = read(d, text, "back");
      RC_ASSERT(back.ok());
      RC_ASSERT(trace_of(back.parsed.blocks) == want);
      return std::move(back.parsed);
    };
    const std::optional<program> source = through(from, iso.parsed);  // the source program
    if (!source || !through(to, *source)) return;
    RC_TAG("written");
  }, kin5::test::pairs::distinct);
}

namespace {

/// A program built by meaning, as a library user builds one: a tool change, spindle, coolant and
/// stops, set in `block::state` only (no M numbers).
program built_by_meaning() {
  program p;
  p.file = "meaning";
  const auto add = [&p](auto&& fill) {
    block b;
    b.where = {"meaning", p.blocks.size() + 1, 1};
    fill(b);
    p.blocks.push_back(b);
  };
  add([](block& b) { b.tool = 5, b.state.tool_change = true; });
  add([](block& b) { b.spindle_rpm = 6000, b.state.spindle = spindle_rotation::clockwise; });
  add([](block& b) { b.state.coolant_flood = true; });
  add([](block& b) { b.state.stop = program_stop::optional_stop; });
  add([](block& b) { b.state.spindle = spindle_rotation::stopped, b.state.coolant_flood = b.state.coolant_mist = false; });
  add([](block& b) { b.state.stop = program_stop::stop; });
  add([](block& b) { b.state.spindle = spindle_rotation::counter_clockwise; });
  add([](block& b) { b.program_end = ""; });
  return p;
}

/// The meanings `blocks` say, in order, one string each.
std::vector<std::string> meanings_of(const std::vector<block>& blocks) {
  std::vector<std::string> out;
  for (const block& b : blocks) {
    const state_words& s = b.state;
    if (s.tool_change) out.push_back("tool change " + std::to_string(b.tool.value_or(-1)));
    if (s.spindle) out.push_back("spindle " + std::to_string(static_cast<int>(*s.spindle)));
    if (s.coolant_flood) out.push_back(std::string("flood ") + (*s.coolant_flood ? "on" : "off"));
    if (s.coolant_mist) out.push_back(std::string("mist ") + (*s.coolant_mist ? "on" : "off"));
    if (s.stop) out.push_back(*s.stop == program_stop::stop ? "stop" : "optional stop");
  }
  return out;
}

/// The lines of `text` that say one of the program's meanings, in order.
std::vector<std::string> lines_with(const std::string& text, const std::vector<std::string>& wanted) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at, end - at);
    for (const std::string& w : wanted)
      if (line == w) out.push_back(line);
    at = end + 1;
  }
  return out;
}

}  // namespace

TEST_CASE("machine functions built by meaning: each NC dialect writes its own words and reads the meanings back") {
  const program p = built_by_meaning();
  // Each dialect's spelling of the program, line by line (docs/dialects/*.md).
  const std::vector<std::pair<dialect, std::vector<std::string>>> spelled = {
      {id_of<iso::dialect>(), {"T5 M6", "S6000 M3", "M8", "M1", "M5 M9", "M0", "M4"}},
      {id_of<haas::dialect>(), {"T5 M6", "S6000 M3", "M8", "M1", "M5 M9", "M0", "M4"}},
      {id_of<linuxcnc::dialect>(), {"T5 M6", "S6000 M3", "M8", "M1", "M5 M9", "M0", "M4"}},
      {id_of<siemens::dialect>(), {"T5 M6", "S6000 M3", "M8", "M1", "M5 M9", "M0", "M4"}},
      {id_of<heidenhain::dialect>(),
       {"1 TOOL CALL 5 Z", "2 TOOL CALL S6000", "3 M3", "4 M8", "5 M1", "6 M5 M9", "7 M0", "8 M4"}},
  };
  for (const auto& [d, lines] : spelled) {
    CAPTURE(name(d));
    const std::string text = write(d, p);
    CAPTURE(text);
    CHECK(lines_with(text, lines) == lines);
    const read_result back = read(d, text, "back");
    REQUIRE(back.ok());
    CHECK(meanings_of(back.parsed.blocks) == meanings_of(p.blocks));
    for (const block& b : back.parsed.blocks)  // every word read as its meaning (a TNC's M30 line is an M function)
      CHECK((b.m_codes.empty() || (d == id_of<heidenhain::dialect>() && b.m_codes == std::vector<int>{30})));
  }
}

TEST_CASE("machine functions built by meaning: APT CL data writes its statements and reads the meanings back") {
  program p = built_by_meaning();
  p.blocks[2].state.coolant_flood.reset(), p.blocks[2].state.coolant_mist = true;  // COOLNT/MIST as well
  const std::string text = write(id_of<apt::dialect>(), p);
  CAPTURE(text);
  CHECK(lines_with(text, {"LOADTL/5", "SPINDL/6000,CLW", "COOLNT/MIST", "OPSTOP", "SPINDL/OFF", "COOLNT/OFF", "STOP",
                          "SPINDL/CCLW"}) == std::vector<std::string>{"LOADTL/5", "SPINDL/6000,CLW", "COOLNT/MIST",
                                                                       "OPSTOP", "SPINDL/OFF", "COOLNT/OFF", "STOP",
                                                                       "SPINDL/CCLW"});
  const read_result back = read(id_of<apt::dialect>(), text, "back");
  REQUIRE(back.ok());
  CHECK(meanings_of(back.parsed.blocks) == meanings_of(p.blocks));
}

TEST_CASE("machine functions built by meaning: what no M function says is refused, not written otherwise") {
  block off;  // flood off, mist unsaid: M9 would switch mist off too
  off.state.coolant_flood = false;
  block mist;  // no standard M7 on a TNC
  mist.state.coolant_mist = true;
  for (const dialect d : {id_of<iso::dialect>(), id_of<siemens::dialect>(), id_of<heidenhain::dialect>()}) {
    program p;
    p.blocks = {off};
    CHECK_THROWS_WITH(write(d, p), Catch::Contains("one coolant switched off without the other"));
  }
  program p;
  p.blocks = {mist};
  CHECK_THROWS_WITH(write(id_of<heidenhain::dialect>(), p), Catch::Contains("mist coolant (M7)"));
  CHECK_NOTHROW(write(id_of<iso::dialect>(), p));
}
