// Tool changes between every ordered pair of dialects. A generated program of tool changes
// (`T n M6`, `T n` … `M6`, `TOOL CALL n`, `LOADTL/n`, and by name where the source calls tools
// by name: `T="MILL_D10"`, `TOOL CALL "MILL_D10"`), tool-tip tracking switched on and off, and
// moves is written by the target's writer and read back by the target's own reader; the two
// programs must agree, move by move, on the tool in the spindle (number or name) and on
// tool-tip tracking, and the target must never change a tool while tracking is on (every
// control switches it off for the change: Heidenhain M129 / FUNCTION RESET TCPM, Siemens
// TRAFOOF, ISO G49). A target that takes only numbers refuses a name, naming it.
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>

#include <kin5/program/io.hpp>

#include "../m_numbers.hpp"
#include "dialect_pairs.hpp"
#include "law_move.hpp"

using namespace kin5::program;

namespace {

/// What a program says at one move: the tool in the spindle and whether tracking is on.
struct at_move {
  std::optional<long long> tool;
  std::optional<std::string> name;
  bool tcp = false;
  friend bool operator==(const at_move&, const at_move&) = default;
};

struct trace {
  std::vector<at_move> moves;
  bool change_under_tcp = false;  // a tool change while tracking was on
};

bool has_m(const block& b, int m) {
  for (int k : kin5::test::m_numbers_of(b))
    if (k == m) return true;
  return false;
}

/// The tool and tracking at each move of `blocks`: T selects, M6 (every reader's tool change)
/// loads the selected tool.
trace trace_of(const std::vector<block>& blocks) {
  trace t;
  std::optional<long long> selected, active;
  std::optional<std::string> selected_name, active_name;
  bool tcp = false;
  for (const block& b : blocks) {
    if (b.tool) selected = b.tool, selected_name.reset();
    if (b.tool_name) selected_name = b.tool_name, selected.reset();
    if (has_m(b, 6)) {
      if (tcp && !(b.tcp && !*b.tcp)) t.change_under_tcp = true;
      active = selected, active_name = selected_name;
    }
    if (b.tcp) tcp = *b.tcp;
    if (b.moves()) t.moves.push_back({active, active_name, tcp});
  }
  return t;
}

/// Whether the reader of `d` reads a tool selected alone (`T5`, its M6 later) as a selection:
/// one written by its writer and read back by its reader.
bool reads_a_selection(dialect d) {
  program p;
  p.language = d;
  block b;
  b.tool = 5;
  p.blocks = {b};
  const read_result back = read(d, write(d, p), "selection");
  for (const block& r : back.parsed.blocks)
    if (r.tool == 5 && !has_m(r, 6)) return true;
  return false;
}

/// The tool of a change or selection: a number, or where `names` (the source calls tools by
/// name) sometimes a name both Siemens and a TNC take.
void draw_tool(block& b, bool names) {
  if (names && *rc::gen::inRange(0, 3) == 0) b.tool_name = *rc::gen::element<std::string>("MILL_D10", "BALL-R3.5", "T#1");
  else b.tool = *rc::gen::inRange<long long>(1, 100);
}

/// Whether block list `blocks` calls a tool by name.
bool names_a_tool(const std::vector<block>& blocks) {
  for (const block& b : blocks)
    if (b.tool_name) return true;
  return false;
}

/// A program as the reader of `from` gives it: changes, selections, tracking, moves.
std::vector<block> draw_program(dialect from) {
  std::vector<block> out;
  const bool tracking = capabilities_of(from).tcp_switch;  // CL data has no TCP word
  const bool selects = reads_a_selection(from);           // T alone, M6 later
  const bool names = capabilities_of(from).tool_names;
  const int n = *rc::gen::inRange(1, 25);
  double x = 0;
  for (int k = 0; k < n; ++k) {
    block b;
    switch (*rc::gen::inRange(0, 6)) {
      case 0:  // a change naming its tool: T5 M6, TOOL CALL 5, LOADTL/5, TOOL CALL "MILL_D10"
        draw_tool(b, names);
        b.state.tool_change = true;
        break;
      case 1:  // T5 … M6
        if (!selects) continue;
        draw_tool(b, names);
        out.push_back(b);
        b = block{};
        b.state.tool_change = true;
        break;
      case 2:
        if (!tracking) continue;
        b.tcp = *rc::gen::arbitrary<bool>();
        break;
      default:
        b = kin5::test::law_move(x += 1);
    }
    out.push_back(b);
  }
  return out;
}

}  // namespace

TEST_CASE("tool changes: every ordered pair of dialects keeps the tool and tracking at every move") {
  using kin5::test::all_dialects;
  kin5::test::check_each_pair(all_dialects(), all_dialects(), [](dialect from, dialect to) {
    program p;
    p.language = from;
    p.file = "gen";
    p.blocks = draw_program(from);
    std::string text;
    try {
      text = write(to, p);
    } catch (const std::invalid_argument& e) {
      // only a change with no tool number, ISO tracking with no tool for its H, or a name where
      // the target takes numbers may be refused
      const std::string why = e.what();
      const bool name_refused = why.find("a tool by name (\"") != std::string::npos;
      RC_ASSERT(!name_refused || (names_a_tool(p.blocks) && !capabilities_of(to).tool_names));
      RC_ASSERT((name_refused || why.find("tool change (M6) without a tool number") != std::string::npos ||
                 why.find("tracking switched on before any tool change") != std::string::npos));
      return;
    }
    RC_ASSERT(!names_a_tool(p.blocks) || capabilities_of(to).tool_names);
    const read_result back = read(to, text, "back");
    RC_ASSERT(back.ok());
    const trace want = trace_of(p.blocks), got = trace_of(back.parsed.blocks);
    RC_ASSERT(got.moves.size() == want.moves.size());
    for (std::size_t k = 0; k < want.moves.size(); ++k) {
      RC_ASSERT(got.moves[k].tool == want.moves[k].tool);
      RC_ASSERT(got.moves[k].name == want.moves[k].name);
      if (capabilities_of(to).tcp_switch) RC_ASSERT(got.moves[k].tcp == want.moves[k].tcp);
    }
    RC_ASSERT(!got.change_under_tcp);
  }, kin5::test::pairs::distinct);
}
