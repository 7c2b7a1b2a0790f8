// Dwells between every ordered pair of dialects. The table, written here independently of the
// code (docs/dialects/*.md): every dialect reads and writes a dwell of seconds, in a block of its
// own — ISO `G4 X…`/`G4 P…` (ms), Haas `G4 P…` (seconds with a point, ms without), LinuxCNC
// `G4 P…`, Siemens `G4 F…`, Heidenhain Cycle 9, APT `DELAY/…` — and each controller takes only
// some durations: ISO and Haas whole ms up to 9999.999 s, Heidenhain whole ms up to 3600 s, the
// others any to 6 decimals.
//
// 1. writers and readers: a program of moves and dwells of random durations, written in the
//    source dialect and read back there, then written in the target dialect and read back by the
//    target's reader, has the same dwells (the same seconds, in the same order) between the same
//    moves; or the target's writer refuses, with the documented message, a dwell its controller
//    does not take — and only then.
// 2. translation: the same for `translate` (NC to NC), `reverse` (into APT) and `post` (from APT),
//    whose first pass refuses such a dwell at its block.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
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

using kin5::test::all_dialects;
using kin5::test::check_each_pair;
using kin5::test::pairs;

/// The longest dwell and the decimals of a second each controller takes (the table above).
dwell_input documented(dialect d) {
  if (d == id_of<iso::dialect>() || d == id_of<haas::dialect>()) return {3, 9999.999};
  if (d == id_of<heidenhain::dialect>()) return {3, 3600.0};
  return {6, 1e9};
}

/// Whether the documented controller of `d` takes a dwell of `s` seconds.
bool takes(dialect d, double s) {
  const dwell_input in = documented(d);
  const double steps = s * std::pow(10.0, in.decimals);
  return s >= 0 && s <= in.longest_s && std::abs(steps - std::round(steps)) < 1e-6 * std::max(1.0, steps);
}

/// The dwells before each move of `blocks`, and (last) those after the last move.
std::vector<std::vector<double>> trace_of(const std::vector<block>& blocks) {
  std::vector<std::vector<double>> t(1);
  for (const block& b : blocks) {
    if (b.state.dwell_s) t.back().push_back(*b.state.dwell_s);
    if (b.moves()) t.emplace_back();
  }
  return t;
}

/// A dwell: mostly one every controller takes (whole ms up to 3600 s), sometimes one past a
/// TNC's 3600 s or finer than a millisecond (4 decimals).
double draw_dwell() {
  switch (*rc::gen::inRange(0, 16)) {
    case 0: return *rc::gen::inRange(3600001, 20000000) / 1000.0;
    case 1: return *rc::gen::inRange(0, 100000) / 10000.0;
    default: return *rc::gen::inRange(0, 3600000) / 1000.0;
  }
}

/// What a drawn program is for: writing (X Y Z moves), translating NC (a tool change, then B
/// and C moves under tracking), posting CL data (millimetres, a tool change, tool-axis moves).
enum class use { writing, nc, cl };

/// Moves and dwells, as the model holds them, for use `u` and source `from` (durations finer
/// than a millisecond included).
std::vector<block> draw_program(use u, dialect from) {
  std::vector<block> out;
  if (u == use::nc) out = kin5::test::tracking_start(from);
  if (u == use::cl) {  // UNITS/MM, LOADTL/1
    block change;
    change.metric = true;
    change.tool = 1;
    change.state.tool_change = true;
    out.push_back(change);
  }
  const int n = *rc::gen::inRange(1, 12);
  double x = 0;
  for (int k = 0; k < n; ++k) {
    block b;
    if (*rc::gen::inRange(0, 2) == 0) {
      b.state.dwell_s = draw_dwell();
    } else {
      b = kin5::test::law_move(x += 1, u == use::nc);
      if (u == use::cl) b.axes.tool_axis = vec3{0, 0, 1};
    }
    out.push_back(b);
  }
  return out;
}

/// Whether `why` refuses a dwell of `p` that `to`'s controller does not take, as documented.
bool documented_refusal(const std::string& why, const std::vector<block>& p, dialect to) {
  for (const block& b : p)
    if (b.state.dwell_s && !takes(to, *b.state.dwell_s) &&
        why.find("a dwell of " + seconds_text(*b.state.dwell_s) + " s is not one the") != std::string::npos)
      return true;
  return false;
}

bool all_taken(const std::vector<block>& p, dialect to) {
  for (const block& b : p)
    if (b.state.dwell_s && !takes(to, *b.state.dwell_s)) return false;
  return true;
}

}  // namespace

TEST_CASE("dwell: every ordered pair of dialects keeps each dwell between the same moves, or refuses it") {
  check_each_pair(all_dialects(), all_dialects(), [](dialect from, dialect to) {
    program_text model;
    model.language = id_of<apt::dialect>();  // a reader that gives any of these durations
    model.file = "gen";
    model.blocks = draw_program(use::writing, from);
    const std::vector<std::vector<double>> want = trace_of(model.blocks);
    std::string source_text, target_text;
    try {
      source_text = write(from, model);
    } catch (const std::invalid_argument& e) {
      RC_ASSERT(documented_refusal(e.what(), model.blocks, from));
      RC_TAG("refused");
      return;
    }
    RC_ASSERT(all_taken(model.blocks, from));
    const read_result source = read(from, source_text, "source");
    RC_ASSERT(source.ok());
    RC_ASSERT(trace_of(source.parsed.blocks) == want);
    try {
      target_text = write(to, source.parsed);
    } catch (const std::invalid_argument& e) {
      RC_ASSERT(documented_refusal(e.what(), model.blocks, to));
      RC_TAG("refused");
      return;
    }
    RC_ASSERT(all_taken(model.blocks, to));
    const read_result back = read(to, target_text, "back");
    RC_ASSERT(back.ok());
    RC_ASSERT(trace_of(back.parsed.blocks) == want);
    RC_TAG("written");
  }, pairs::distinct);
}

TEST_CASE("dwell: translation keeps each dwell between the same moves, or refuses it at its block") {
  using M = machines::dmu_80p;  // to itself: the setup is the identity
  check_each_pair(all_dialects(), all_dialects(), [](dialect from, dialect to) {
    const bool cl = from == id_of<apt::dialect>();
    if (cl && to == from) return;  // post writes NC programs
    // As if read from CL data: any duration, no text of a G-code dialect.
    const program_text p = kin5::test::law_program(id_of<apt::dialect>(), "m", draw_program(cl ? use::cl : use::nc, from));
    std::string text;
    try {
      text = write(from, p);
    } catch (const std::invalid_argument& e) {
      RC_ASSERT(documented_refusal(e.what(), p.blocks, from));
      return;
    }
    const auto t = kin5::test::law_translator<M>(from, to, "m");
    string_sink out;
    const auto run = stream_text(*t, text, from, "m", to, out);
    RC_ASSERT(run.input.ok());
    if (!all_taken(p.blocks, to)) {  // refused in the first pass: nothing written
      RC_ASSERT(!run.ok(*t));
      RC_ASSERT(out.text.empty());
      RC_TAG("refused");
      return;
    }
    RC_ASSERT(run.ok(*t));
    const read_result back = read(to, out.text, "back");
    RC_ASSERT(back.ok());
    RC_ASSERT(trace_of(back.parsed.blocks) == trace_of(p.blocks));
    RC_TAG("written");
  });
}
