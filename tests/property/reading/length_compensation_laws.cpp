// Tool length compensation between every ordered pair of dialects. The table, written here
// independently of the code (docs/dialects/*.md): ISO/Fanuc and LinuxCNC say whose length applies
// by a register (`G43 H n`, H n holding tool n's length) and may switch it off (`G49`); Siemens
// applies the active tool's own (`D1`, off `D0`), Heidenhain and APT the called tool's, always.
// So a length of another register than the loaded tool's is refused by Siemens, Heidenhain and
// APT (at the block that says it, and at a move under it), a move with the length off by
// Heidenhain and APT, and by LinuxCNC a tracked move whose G43 is not the loaded tool's.
//
// Siemens keeps `D n` as a word when reading; the law reads it by the table (`with_d_words`).
//
// 1. writers and readers: a generated ISO or LinuxCNC program of tool changes, G43 H (equal and
//    unequal to the loaded tool), G49 and moves, as its own reader gives it, written by the
//    target's writer and read back by its reader, applies the same tool's length (or none) at every move; or the writer refuses
//    with the documented message, exactly where the table says.
// 2. translation: the same under tool-tip tracking (`G43.4 H n`, LinuxCNC `G43 H n` + M428),
//    translated (`translate`, or `reverse` into APT): the output read back applies the same
//    length at every move, or the translation is refused with the documented message.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>

#include <kin5/kin5.hpp>

#include "dialect_pairs.hpp"
#include "law_move.hpp"
#include "law_translation.hpp"

using namespace kin5;
using namespace kin5::program;
using program_text = kin5::program::program;

namespace {

const dialect iso_d = id_of<iso::dialect>(), linuxcnc_d = id_of<linuxcnc::dialect>(), siemens_d = id_of<siemens::dialect>(),
              heidenhain_d = id_of<heidenhain::dialect>(), apt_d = id_of<apt::dialect>(), haas_d = id_of<haas::dialect>();
const std::vector<dialect> every_dialect = kin5::test::all_dialects();
const std::vector<dialect> register_dialects = {iso_d, linuxcnc_d, haas_d};  // their readers give G43 H

/// Whether dialect `d` applies the loaded tool's length whatever the program says (the table).
bool length_with_tool(dialect d) { return d == heidenhain_d || d == apt_d; }

/// Whose length applies at a move of a program in dialect `d` in state `m`: "tool n" (the
/// length of entry n), "none", or "unknown".
std::string applied(const modal_state& m, dialect d) {
  const auto tool = [](std::optional<long long> n) { return n ? "tool " + std::to_string(*n) : std::string("unknown"); };
  if (m.length_compensation == false) return "none";
  if (m.length_compensation == true) return tool(m.length_register ? m.length_register : m.active_tool);
  return length_with_tool(d) ? tool(m.active_tool) : "unknown";
}

/// Block `b` of dialect `d` with its Siemens `D n` (kept as written by the reader) read as the
/// table says: `D0` switches the length off, `D1` … on with the active tool's own.
block with_d_words(const block& b, dialect d) {
  block r = b;
  if (d != siemens_d) return r;
  for (const std::string& w : b.kept_words)
    if (w.size() > 1 && w[0] == 'D' && w.find_first_not_of("0123456789", 1) == std::string::npos)
      r.state.length_compensation = std::stoll(w.substr(1)) != 0;
  return r;
}

/// The length applied at each move of `blocks`, read as dialect `d`.
std::vector<std::string> trace_of(const std::vector<block>& blocks, dialect d) {
  std::vector<std::string> t;
  modal_state m;
  for (const block& b : blocks) {
    m.apply(with_d_words(b, d));
    if (is_motion(b)) t.push_back(applied(m, d));
  }
  return t;
}

/// What writing `blocks` in `to` is refused for, first: the message's documented words, with
/// the block's line; empty when nothing is.
std::optional<std::pair<std::string, std::size_t>> expected_refusal(const std::vector<block>& blocks, dialect to) {
  modal_state m;
  for (const block& b : blocks) {
    m.apply(b);
    const tool_length t = length_in_effect(m);
    const bool says_on = b.state.length_compensation == true;
    if (to == siemens_d || length_with_tool(to))
      if (t == tool_length::other && (says_on || is_motion(b))) return std::pair{std::string("tool length compensation H"), b.where.line};
    if (length_with_tool(to) && t == tool_length::off && is_motion(b))
      return std::pair{std::string("a move with tool length compensation off (G49)"), b.where.line};
    if (to == linuxcnc_d && m.tcp && t != tool_length::own && is_motion(b))
      return std::pair{std::string("a move under tracking while G43 does not hold the loaded tool's length"), b.where.line};
  }
  return std::nullopt;
}

block tool_change(long long tool) {
  block b;
  b.tool = tool;
  b.state.tool_change = true;
  return b;
}

/// `G43 H n` (ISO; LinuxCNC sometimes `G43` alone, the loaded tool), or with tracking ISO's
/// `G43.4 H n`; LinuxCNC's M428 is a block of its own after it.
block length_on(dialect from, long long tool, bool tracking) {
  block b;
  b.state.length_compensation = true;
  if (kin5::test::fanuc_grammar(from) || *rc::gen::inRange(0, 3) != 0)
    b.state.length_register = *rc::gen::element(tool, tool, *rc::gen::inRange<long long>(1, 4));
  if (tracking && kin5::test::fanuc_grammar(from)) b.tcp = true;
  return b;
}

block length_off(dialect from, bool tracking) {
  block b;
  b.state.length_compensation = false;
  if (tracking && kin5::test::fanuc_grammar(from)) b.tcp = false;
  return b;
}

block tracking_switch(bool on) {
  block b;
  b.tcp = on;
  return b;
}

/// Blocks as the reader of `from` gives them: a tool change and its length first, then changes,
/// G43 H, G49 and moves; with `tracking`, the moves are tracked (B/C words) and G49, a change
/// and G43 come as one sequence, tracking off around the change.
std::vector<block> draw_program(dialect from, bool tracking) {
  std::vector<block> out;
  long long tool = *rc::gen::inRange<long long>(1, 4);
  const auto push_length = [&] {
    out.push_back(length_on(from, tool, tracking));
    if (tracking && from == linuxcnc_d) out.push_back(tracking_switch(true));
  };
  out.push_back(tool_change(tool));
  push_length();
  const int n = *rc::gen::inRange(1, 12);
  double x = 0;
  for (int k = 0; k < n; ++k) {
    const int what = *rc::gen::inRange(0, 6);
    if (tracking && what < 3) {  // G49 (tracking off), the change, the new tool's length
      if (from == linuxcnc_d) out.push_back(tracking_switch(false));
      out.push_back(length_off(from, true));
      out.push_back(tool_change(tool = *rc::gen::inRange<long long>(1, 4)));
      push_length();
    } else if (what == 0) {
      out.push_back(tool_change(tool = *rc::gen::inRange<long long>(1, 4)));
    } else if (what == 1) {
      out.push_back(length_on(from, tool, false));
    } else if (what == 2) {
      out.push_back(length_off(from, false));
    } else {
      out.push_back(kin5::test::law_move(x += 1, tracking));
    }
  }
  for (std::size_t i = 0; i < out.size(); ++i) out[i].where = {"gen", i + 1, 1};
  return out;
}

}  // namespace

TEST_CASE("length compensation: every ordered pair of dialects applies the same tool's length at every move") {
  kin5::test::check_each_pair(register_dialects, every_dialect, [](dialect from, dialect to) {
    program_text p = kin5::test::law_program(from, "gen", draw_program(from, false));
    const read_result source = read(from, write(from, p), "gen");  // as its own reader gives it
    RC_ASSERT(source.ok());
    p.blocks = source.parsed.blocks;
    const auto refusal = expected_refusal(p.blocks, to);
    std::string text;
    try {
      text = write(to, p);
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      RC_ASSERT(refusal.has_value());
      RC_ASSERT(what.find(":" + std::to_string(refusal->second) + ": ") != std::string::npos);
      RC_ASSERT(what.find(refusal->first) != std::string::npos);
      return;
    }
    RC_ASSERT(!refusal);
    const read_result back = read(to, text, "back");
    RC_ASSERT(back.ok());
    RC_ASSERT(trace_of(back.parsed.blocks, to) == trace_of(p.blocks, from));
  });
}

TEST_CASE("length compensation: translation keeps the tool's length at every tracked move, or refuses") {
  using M = machines::dmu_80p;  // to itself: the setup is the identity
  kin5::test::check_each_pair(register_dialects, every_dialect, [](dialect from, dialect to) {
    const program_text p = kin5::test::law_program(from, "m", draw_program(from, true));
    const std::string text = write(from, p);
    const read_result source = read(from, text, "m");
    if (!source.ok()) {  // LinuxCNC refuses a tracked move without the loaded tool's G43 itself
      RC_ASSERT(from == linuxcnc_d);
      RC_ASSERT(expected_refusal(p.blocks, linuxcnc_d).has_value());
      return;
    }
    const auto t = kin5::test::law_translator<M>(from, to, "m");
    string_sink out;
    const auto run = stream_text(*t, text, from, "m", to, out);
    RC_ASSERT(run.input.ok());
    if (const auto refusal = expected_refusal(source.parsed.blocks, to)) {
      RC_ASSERT(!run.ok(*t));
      RC_ASSERT(run.writer_error.has_value());
      RC_ASSERT(run.writer_error->where.line == refusal->second);
      RC_ASSERT(run.writer_error->message.find(refusal->first) != std::string::npos);
      return;
    }
    RC_ASSERT(run.ok(*t));
    const read_result back = read(to, out.text, "back");
    RC_ASSERT(back.ok());
    RC_ASSERT(trace_of(back.parsed.blocks, to) == trace_of(source.parsed.blocks, from));
  });
}
