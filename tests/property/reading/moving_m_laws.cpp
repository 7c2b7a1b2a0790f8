// M functions on a block that moves, through CL data and back. A generated program of moves
// under tool-tip tracking, each move perhaps with a spindle, a coolant and a stop M function of
// its own, is written in an NC dialect, reversed into APT CL data (`reverse`, as text) and posted
// back into the same dialect (`post`, as text). Read with the dialect's own reader, both must run
// every move with the same spindle and coolant and stop at the same places: each M function stays
// on its move. When an M function in a moving block acts is the controller's
// (docs/dialects/apt.md, "M functions on a moving block"), written here independently of the
// code: M3 M4 M7 M8 at the block's start, M0 M1 after the move, M5 M9 after it too except on
// LinuxCNC, which runs them before the move.
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>

#include <kin5/kin5.hpp>

#include "../m_numbers.hpp"
#include "law_translation.hpp"

using namespace kin5;
using namespace kin5::program;
using program_text = kin5::program::program;

namespace {

const std::vector<dialect> nc_dialects = {id_of<iso::dialect>(), id_of<linuxcnc::dialect>(), id_of<siemens::dialect>(),
                                          id_of<heidenhain::dialect>(), id_of<haas::dialect>()};

/// What the machine does during one move, and the stops just before it.
struct at_move {
  std::optional<int> spindle;  // 3, 4 or 5: the last M3/M4/M5 in effect
  bool flood = false, mist = false;
  int stops = 0, optional_stops = 0;  // M0 and M1 between the previous move and this one
  friend bool operator==(const at_move&, const at_move&) = default;
  friend std::ostream& operator<<(std::ostream& o, const at_move& a) {
    return o << "{M" << a.spindle.value_or(-1) << (a.flood ? " flood" : "") << (a.mist ? " mist" : "") << " stops "
             << a.stops << "/" << a.optional_stops << "}";
  }
};

/// `now` after M function `m`.
void apply(at_move& now, int m) {
  if (m == 3 || m == 4 || m == 5) now.spindle = m;
  if (m == 13 || m == 14) now.spindle = m - 10, now.flood = true;
  if (m == 7) now.mist = true;
  if (m == 8) now.flood = true;
  if (m == 9) now.flood = now.mist = false;
  if (m == 0) ++now.stops;
  if (m == 1) ++now.optional_stops;
}

/// Whether M function `m` in a moving block of dialect `d` acts after the move (the table above).
bool after_move(int m, dialect d) {
  if (m == 0 || m == 1) return true;
  return (m == 5 || m == 9) && d != id_of<linuxcnc::dialect>();
}

/// The state during each move of `blocks` (dialect `d`), and at the end after the last one.
std::vector<at_move> trace_of(const std::vector<block>& blocks, dialect d) {
  std::vector<at_move> out;
  at_move now;
  for (const block& b : blocks) {
    const std::vector<int> ms = kin5::test::m_numbers_of(b);
    for (int m : ms)
      if (!b.moves() || !after_move(m, d)) apply(now, m);
    if (!b.moves()) continue;
    out.push_back(now);
    now.stops = now.optional_stops = 0;
    for (int m : ms)
      if (after_move(m, d)) apply(now, m);
  }
  out.push_back(now);
  return out;
}

/// A tool change, tracking on, a spindle start, then moves of a B/C machine with M functions
/// on them and between them (no M7 where the controller has none: Heidenhain).
std::vector<block> draw_program(dialect from) {
  std::vector<block> out(3);
  out[0].tool = 1, out[0].state.tool_change = true;
  out[1].tcp = true;
  if (from == id_of<linuxcnc::dialect>()) out[1].state.length_compensation = true;  // G43 M428
  out[2].spindle_rpm = 1000, out[2].state.spindle = spindle_rotation::clockwise;
  const bool mist = controller_of(from).m7_mist_coolant;
  const int n = *rc::gen::inRange(1, 12);
  double x = 0;
  for (int k = 0; k < n; ++k) {
    block b;
    if (*rc::gen::inRange(0, 4) != 0) {
      b.motion = motion_kind::linear;
      b.axes.x_mm = x += 1, b.axes.y_mm = 2.5, b.axes.z_mm = 10, b.axes.b_deg = 10, b.axes.c_deg = 20;
      b.feed = 500;
    }
    if (const int s = *rc::gen::inRange(0, 6); s >= 3) b.m_codes.push_back(s);
    if (const int c = *rc::gen::inRange(6, 10); c >= 8 || (c == 7 && mist)) b.m_codes.push_back(c);
    if (const int t = *rc::gen::inRange(-2, 2); t >= 0) b.m_codes.push_back(t);
    if (b.m_codes.empty() && !b.moves()) b.m_codes.push_back(9);
    out.push_back(b);
  }
  return out;
}

/// `text` in dialect `from` through `t` into dialect `to`; the output read back, or an empty
/// program (the run failed: the caller asserts).
read_result run(block_translator& t, const std::string& text, dialect from, dialect to) {
  string_sink out;
  const auto r = stream_text(t, text, from, "m", to, out);
  RC_ASSERT(r.ok(t));
  return read(to, out.text, "back");
}

}  // namespace

TEST_CASE("moving M functions: reverse then post keeps each spindle, coolant and stop on its move") {
  using M = machines::dmu_80p;
  for (const dialect from : nc_dialects) {
    const bool ok = rc::check(std::string(name(from)) + " -> apt -> " + std::string(name(from)), [from] {
      const program_text p = kin5::test::law_program(from, "m", draw_program(from));
      const std::string text = write(from, p);
      const read_result source = read(from, text, "m");
      RC_ASSERT(source.ok());
      const auto want = trace_of(source.parsed.blocks, from);
      RC_ASSERT(trace_of(p.blocks, from) == want);
      const dialect apt_d = id_of<apt::dialect>();
      const auto cl = run(*kin5::test::law_translator<M>(from, apt_d, "m"), text, from, apt_d);
      RC_ASSERT(cl.ok());
      const std::string cl_text = write(apt_d, cl.parsed);
      const auto back = run(*kin5::test::law_translator<M>(apt_d, from, "m"), cl_text, apt_d, from);
      RC_ASSERT(back.ok());
      RC_ASSERT(trace_of(back.parsed.blocks, from) == want);
    });
    CHECK(ok);
  }
}
