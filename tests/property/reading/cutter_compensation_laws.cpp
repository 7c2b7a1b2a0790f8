// Cutter radius compensation between every ordered pair of dialects. The table, written here
// independently of the code (docs/dialects/compensation.md): the side (left/right) is kept in the
// XY plane with the tool along Z; ISO/Fanuc and LinuxCNC name the radius by a register (`G41 D n`,
// D n holding tool n's radius), Siemens takes the active tool's first edge (`D1`), Heidenhain the
// called tool's. So a radius of another register than the loaded tool's is refused by Siemens and
// Heidenhain, compensation on by APT (a GOTO point is the tool's position), any compensation
// between LinuxCNC and another controller (its entry move ends elsewhere), and by Heidenhain a
// change of side without R0 between.
//
// 1. law: a generated program (tool 1 changed, G17, tool-tip tracking on, straight moves with the
//    tool along Z, compensation switched left, right and off, with the loaded tool's register or
//    another's) in each source dialect, translated into each target (`reverse` into APT): read
//    back, the output has the same side and the same tool's radius at every move, or the
//    translation is refused with the documented message at the block the table names.
// 2. table: one row per refusal of an ISO program (tilted tool, G18, a setup turning the plane,
//    output in machine coordinates, an arc start-up, another tool's register, LinuxCNC).
#include <memory>
#include <optional>
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
const std::vector<dialect> nc_sources = {iso_d, linuxcnc_d, siemens_d, heidenhain_d, haas_d};  // APT refuses CUTCOM

/// Side and whose radius at one move: "left tool", "right other", "off".
std::string at_move(const modal_state& m) {
  const tool_radius r = radius_in_effect(m);
  if (r == tool_radius::off) return "off";
  return std::string(*m.radius_compensation == cutter_side::left ? "left" : "right") +
         (r == tool_radius::own ? " own" : " other");
}

/// The side and radius at each move of `blocks`.
std::vector<std::string> trace_of(const std::vector<block>& blocks) {
  std::vector<std::string> t;
  modal_state m;
  for (const block& b : blocks) {
    m.apply(b);
    if (is_motion(b)) t.push_back(at_move(m));
  }
  return t;
}

/// What translating `blocks` (read in `from`) into `to` is refused for, first: the message's
/// documented words and the block's line; empty when nothing is.
std::optional<std::pair<std::string, std::size_t>> expected_refusal(const std::vector<block>& blocks, dialect from,
                                                                    dialect to) {
  modal_state m;
  for (const block& b : blocks) {
    const cutter_side before = m.radius_compensation.value_or(cutter_side::off);
    m.apply(b);
    const bool says_on = b.state.radius_compensation && *b.state.radius_compensation != cutter_side::off;
    const tool_radius r = radius_in_effect(m);
    if (says_on && (from == linuxcnc_d) != (to == linuxcnc_d))
      return std::pair{std::string("cutter radius compensation between"), b.where.line};
    if (says_on && to == apt_d) return std::pair{std::string("a GOTO point is the tool's position"), b.where.line};
    if ((to == siemens_d || to == heidenhain_d) && r == tool_radius::other && (says_on || is_motion(b)))
      return std::pair{std::string("cutter radius compensation D"), b.where.line};
    if (to == heidenhain_d && from != heidenhain_d && says_on && before != cutter_side::off &&
        before != *b.state.radius_compensation)
      return std::pair{std::string("changes side without being switched off"), b.where.line};
  }
  return std::nullopt;
}

/// `G1 X<x> Y<y> Z10 B0 C20`: a straight move with the tool along Z (B0 on the DMU 80P).
block move(double x_mm, double y_mm) {
  block b = kin5::test::law_move(x_mm, true);
  b.axes.y_mm = y_mm, b.axes.b_deg = 0;
  return b;
}

/// Compensation switched to `side` as `from` says it, on a block of its own or on `on`.
void switch_side(block& on, dialect from, cutter_side side) {
  on.state.radius_compensation = side;
  if (side == cutter_side::off || (!kin5::test::fanuc_grammar(from) && from != linuxcnc_d)) return;
  if (kin5::test::fanuc_grammar(from) || *rc::gen::inRange(0, 3) != 0)  // LinuxCNC: sometimes without D, the loaded tool
    on.state.radius_register = *rc::gen::element(1LL, 1LL, 1LL, 2LL);
}

/// Blocks of a program in `from`: tool 1, G17, tracking, the first move, then moves with
/// compensation switched (on its move, or on a line of its own before it), and off at the end.
std::vector<block> draw_program(dialect from) {
  std::vector<block> out = kin5::test::tracking_start(from);
  if (from == heidenhain_d) out[0].kept_words = {"Z"};  // TOOL CALL 1 Z: the working plane XY
  block plane;
  plane.state.working_plane = arc_plane::xy;
  if (from == siemens_d) plane.kept_words = {"D1"};  // the first edge, its radius
  out.push_back(plane);
  out.push_back(move(0, 0));
  cutter_side side = cutter_side::off;
  const int n = *rc::gen::inRange(1, 10);
  double x = 0;
  for (int k = 0; k < n; ++k) {
    block b = move(x += 1, static_cast<double>(k % 2));
    if (*rc::gen::inRange(0, 3) == 0) {
      const cutter_side next = *rc::gen::element(cutter_side::off, cutter_side::left, cutter_side::right);
      if (next != side) {
        block& where = *rc::gen::arbitrary<bool>() || from == heidenhain_d ? b : out.emplace_back();
        switch_side(where, from, side = next);
      }
    }
    out.push_back(b);
  }
  block last = move(x + 1, 0);
  if (side != cutter_side::off) last.state.radius_compensation = cutter_side::off;
  out.push_back(last);
  for (std::size_t i = 0; i < out.size(); ++i) out[i].where = {"gen", i + 1, 1};
  return out;
}

/// Where and why a run was refused: the first error of the translation or of its writer.
std::optional<diagnostic> refusal_of(const stream_result& run, block_translator& t) {
  if (!t.result().errors.empty()) return t.result().errors.front();
  return run.writer_error;
}

}  // namespace

TEST_CASE("cutter compensation: every ordered pair keeps the side and the tool's radius at every move, or refuses") {
  kin5::test::check_each_pair(nc_sources, kin5::test::all_dialects(), [](dialect from, dialect to) {
    const program_text p = kin5::test::law_program(from, "m", draw_program(from));
    const std::string text = write(from, p);
    const read_result source = read(from, text, "m");
    RC_ASSERT(source.ok());
    const auto t = kin5::test::law_translator<machines::dmu_80p>(from, to, "m");
    string_sink out;
    const auto run = stream_text(*t, text, from, "m", to, out);
    RC_ASSERT(run.input.ok());
    if (const auto refusal = expected_refusal(source.parsed.blocks, from, to)) {
      RC_ASSERT(!run.ok(*t));
      const auto got = refusal_of(run, *t);
      RC_ASSERT(got.has_value());
      RC_ASSERT(got->where.line == refusal->second);
      RC_ASSERT(got->message.find(refusal->first) != std::string::npos);
      return;
    }
    RC_ASSERT(run.ok(*t));
    const read_result back = read(to, out.text, "back");
    RC_ASSERT(back.ok());
    RC_ASSERT(trace_of(back.parsed.blocks) == trace_of(source.parsed.blocks));
  });
}

TEST_CASE("cutter compensation: each condition of the contract refused at its block, naming why") {
  // An ISO program for the DMU 80P: line 5 is the first move, line 6 switches compensation on.
  const auto program = [](const std::string& plane, const std::string& first, const std::string& on) {
    return "T1 M6\nG43.4 H1\n" + plane + "\nG90\n" + first + "\n" + on + "\nG1 X20. Y5.\nG40 G1 X30.\nG49\nM30\n";
  };
  const std::string straight = "G1 X0. Y0. Z10. B0. C20. F500.";
  enum class how_run { usual, turned_setup, machine_output };
  struct row {
    std::string text;
    dialect to;
    how_run how;
    std::size_t line;
    std::string message;
  };
  const auto options_for = [](how_run how) {
    translate_options o;
    if (how == how_run::turned_setup) o.setup = rigid_transform{rotation(unit_x, radians{0.5}), {}};
    if (how == how_run::machine_output) o.common.coordinates = output_mode::machine, o.common.placement = run_inputs{};
    return o;
  };
  const std::vector<row> rows = {
      {program("G17", straight, "G41 D1 G1 X10."), iso_d, how_run::usual, 0, ""},
      {program("G17", "G1 X0. Y0. Z10. B10. C20. F500.", "G41 D1 G1 X10."), iso_d, how_run::usual, 6,
       "cutter radius compensation: the tool axis is not along Z"},
      {program("G18", straight, "G41 D1 G1 X10."), siemens_d, how_run::usual, 6, "cutter radius compensation outside the XY plane (G18)"},
      {program("G17", straight, "G41 D1 G1 X10."), heidenhain_d, how_run::turned_setup, 6,
       "cutter radius compensation: the setup between the machines turns the XY plane"},
      {program("G17", straight, "G41 D1 G1 X10."), iso_d, how_run::machine_output, 6,
       "cutter radius compensation: motion written in machine coordinates"},
      {program("G17", straight, "G41 D2 G1 X10."), siemens_d, how_run::usual, 6, "cutter radius compensation D2 while tool 1 is loaded"},
      {program("G17", straight, "G41 D2 G1 X10."), heidenhain_d, how_run::usual, 6, "cutter radius compensation D2 while tool 1 is loaded"},
      {program("G17", straight, "G41 D1 G1 X10."), linuxcnc_d, how_run::usual, 6, "cutter radius compensation between iso and linuxcnc"},
      {program("G17", straight, "G41 D1 G1 X10."), apt_d, how_run::usual, 6, "a GOTO point is the tool's position"},
  };
  for (const row& r : rows) {
    INFO(r.text << "into " << name(r.to) << ": " << r.message);
    const auto t = kin5::test::law_translator<machines::dmu_80p>(iso_d, r.to, "m", options_for(r.how));
    string_sink out;
    const auto run = stream_text(*t, r.text, iso_d, "m", r.to, out);
    REQUIRE(run.input.ok());
    if (r.line == 0) {
      CHECK(run.ok(*t));
      continue;
    }
    CHECK_FALSE(run.ok(*t));
    bool found = false;
    for (const diagnostic& d : t->result().errors)
      found = found || (d.where.line == r.line && d.message.find(r.message) != std::string::npos);
    if (run.writer_error)
      found = found || (run.writer_error->where.line == r.line && run.writer_error->message.find(r.message) != std::string::npos);
    CHECK(found);
  }
  // Start-up in an arc is refused by the reader, at the word.
  const read_result arc = iso::read(program("G17", straight, "G2 G41 D1 X10. Y0. R5."), "m");
  REQUIRE(arc.errors.size() == 1);
  CHECK(arc.errors[0].to_string() == "m:6:4: error: G41: cutter radius compensation start-up in a circular move (allowed "
                                     "only in G0/G1)");
}
