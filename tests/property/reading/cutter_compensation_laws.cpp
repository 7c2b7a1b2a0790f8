// Cutter radius compensation between every ordered pair of dialects. The table, written here
// independently of the code (docs/dialects/compensation.md): the side (left/right) is kept in the
// XY plane with the tool along Z; ISO/Fanuc and LinuxCNC name the radius by a register (`G41 D n`,
// D n holding tool n's radius), Siemens takes the active tool's first edge (`D1`), Heidenhain the
// called tool's. So a radius of another register than the loaded tool's is refused by Siemens and
// Heidenhain, compensation on by APT (a GOTO point is the tool's position), and by Heidenhain a
// change of side without R0 between. Between LinuxCNC and another controller (its entry move ends
// elsewhere) compensation is translated only where it starts and ends straight on: the entry
// move runs on in the direction of the next move, the exit move in the direction of the last
// compensated one, with nothing but those moves between the switch and them.
//
// 1. law: a generated program (tool 1 changed, G17, tool-tip tracking on, straight moves with the
//    tool along Z, each stepping X by 1 and Y by -1, 0 or 1, compensation switched left, right and
//    off, with the loaded tool's register or another's) in each source dialect, translated into
//    each target (`reverse` into APT): read back, the output has the same side and the same
//    tool's radius at every move, or the translation is refused with the documented message at
//    the block the table names.
// 2. table: one row per refusal of an ISO program (tilted tool, G18, a setup turning the plane,
//    output in machine coordinates, an arc start-up, another tool's register, LinuxCNC).
// 3. table: entries and exits between ISO and LinuxCNC, both ways: straight on along lines and
//    into and out of tangent arcs, written with rounded coordinates (accepted); at an angle, into
//    a plunge, with a block between, a change of side (refused at the switch, naming why). An
//    entry or exit along an arc, which every reader refuses itself, is given to
//    `compensation_ends` directly.
// 4. property: the directions compensation_ends.hpp compares, against points a small step along
//    each move, in every quadrant and both senses of an arc.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

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

/// Between LinuxCNC and another controller: the line of the block that switched compensation on
/// or off where the entry or exit would run differently. Every move of these programs steps X by
/// 1, so two moves run straight on when their Y steps are equal.
std::optional<std::size_t> uneven_end(const std::vector<block>& blocks) {
  enum class waiting { none, entry, first, exit } w = waiting::none;
  std::size_t at = 0;
  std::optional<double> entry_step, last_step;
  modal_state m;
  for (const block& b : blocks) {
    const std::optional<double> y_before = m.y_mm;
    const cutter_side was = m.radius_compensation.value_or(cutter_side::off);
    m.apply(b);
    const cutter_side now = m.radius_compensation.value_or(cutter_side::off);
    const bool says_on = b.state.radius_compensation && now != cutter_side::off;
    const bool says_off = now == cutter_side::off && was != cutter_side::off;
    const bool moves = is_motion(b);
    const std::optional<double> step = moves && y_before ? std::optional(*m.y_mm - *y_before) : std::nullopt;
    if (says_on && was != cutter_side::off) return b.where.line;
    if (says_on && w == waiting::exit) return at;
    if (w == waiting::first && (says_off || !moves)) return at;
    if (w != waiting::none && !moves && !(w == waiting::entry && says_off)) return at;
    if (w == waiting::first) {
      if (step != entry_step) return at;
      w = waiting::none;
    }
    if (says_on) at = b.where.line, w = waiting::entry;
    if (w == waiting::entry && moves && now != cutter_side::off) {
      entry_step = step, w = waiting::first;
    } else if (says_off) {
      at = b.where.line, w = w == waiting::entry ? waiting::none : waiting::exit;
    }
    if (w == waiting::exit && moves) {
      if (step != last_step) return at;
      w = waiting::none;
    }
    if (moves) last_step = now == cutter_side::off ? std::nullopt : step;
  }
  return std::nullopt;
}

/// What translating `blocks` (read in `from`) into `to` is refused for, first: the message's
/// documented words and the block's line; empty when nothing is. The source walk's refusals
/// (LinuxCNC's entries and exits) come before the writer's.
std::optional<std::pair<std::string, std::size_t>> expected_refusal(const std::vector<block>& blocks, dialect from,
                                                                    dialect to) {
  if ((from == linuxcnc_d) != (to == linuxcnc_d))
    if (const auto line = uneven_end(blocks)) return std::pair{std::string("cutter radius compensation between"), *line};
  modal_state m;
  for (const block& b : blocks) {
    const cutter_side before = m.radius_compensation.value_or(cutter_side::off);
    m.apply(b);
    const bool says_on = b.state.radius_compensation && *b.state.radius_compensation != cutter_side::off;
    const tool_radius r = radius_in_effect(m);
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

/// Blocks of a program in `from`: tool 1, G17, tracking, the first move, then moves stepping X by
/// 1 and Y by -1, 0 or 1, half of them as the move before (so that many run straight on) with compensation switched (on its move,
/// or on a line of its own before it), and off at the end: straight on, or back to Y0.
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
  double x = 0, y = 0, dy = 0;
  for (int k = 0; k < n; ++k) {
    if (*rc::gen::arbitrary<bool>()) dy = *rc::gen::element(-1.0, 0.0, 1.0);  // else straight on
    block b = move(x += 1, y += dy);
    if (*rc::gen::inRange(0, 3) == 0) {
      const cutter_side next = *rc::gen::element(cutter_side::off, cutter_side::left, cutter_side::right);
      if (next != side) {
        block& where = *rc::gen::arbitrary<bool>() || from == heidenhain_d ? b : out.emplace_back();
        switch_side(where, from, side = next);
      }
    }
    out.push_back(b);
  }
  block last = move(x + 1, *rc::gen::arbitrary<bool>() ? y + dy : 0);
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
    const auto refusal = expected_refusal(source.parsed.blocks, from, to);
    const auto trace = trace_of(source.parsed.blocks);
    const bool compensated = std::any_of(trace.begin(), trace.end(), [](const std::string& m) { return m != "off"; });
    RC_CLASSIFY(compensated && !refusal, "translated with compensation");
    RC_CLASSIFY(refusal.has_value(), "refused");
    if (refusal) {
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
    RC_ASSERT(trace_of(back.parsed.blocks) == trace);
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

TEST_CASE("cutter compensation: entries and exits between ISO and LinuxCNC, straight on or refused at the switch") {
  // Line 5 is the first move, to X0 Y0 with the tool along Z; the rows' lines follow it.
  const auto program = [](dialect from, const std::string& body) {
    return from == iso_d ? "T1 M6\nG43.4 H1\nG17\nG90\nG1 X0. Y0. Z10. B0. C20. F500.\n" + body + "G49\nM30\n"
                         : "T1 M6\nG43 M428\nG17\nG90\nG1 X0. Y0. Z10. B0. C20. F500.\n" + body + "M429\nM2\n";
  };
  struct row {
    std::string body;
    std::size_t line;  // 0: translated
    std::string reason;
  };
  const std::vector<row> rows = {
      // Straight on along lines: in along +X, out along -X.
      {"G41 D1 G1 X10.\nG1 X20.\nG1 Y10.\nG1 X5.\nG40 G1 X-5.\n", 0, ""},
      // Into a counter-clockwise arc whose tangent at (10, 0) is +X; out along +Y after a line.
      {"G41 D1 G1 X10.\nG3 X20. Y10. I0. J10.\nG1 Y20.\nG40 G1 Y30.\n", 0, ""},
      // Out of a clockwise arc whose tangent at its end (10, 30) is +X.
      {"G42 D1 G1 Y10.\nG1 Y20.\nG2 X10. Y30. I10. J0.\nG40 G1 X20.\n", 0, ""},
      // At 30 degrees, the points rounded to three decimals.
      {"G41 D1 G1 X8.66 Y5.\nG1 X17.321 Y10.\nG1 X8.66 Y15.\nG1 X0. Y10.\nG1 X-8.66 Y5.\nG40 G1 X-17.321 Y0.\n", 0, ""},
      // The switch on a line of its own, a comment between it and its move.
      {"G41 D1\n(LEAD IN)\nG1 X10.\nG1 X20.\nG40\nG1 X30.\n", 0, ""},
      // At an angle, by 0.05 mm at the end of the next move: more than rounding explains.
      {"G41 D1 G1 X8.66 Y5.\nG1 X17.33 Y10.\nG40 G1 X30.\n", 6, "is not collinear with the contour's first element (line 7)"},
      {"G41 D1 G1 X10. Y5.\nG1 X20.\nG40 G1 X30.\n", 6, "is not collinear with the contour's first element (line 7)"},
      {"G41 D1 G1 X10.\nG1 Z5.\nG1 X20.\nG40 G1 X30.\n", 6, "the contour's first element (line 7) does not move in the XY plane"},
      {"G41 D1\nM8\nG1 X10.\nG1 X20.\nG40 G1 X30.\n", 6, "line 7 stands between the switch and its move"},
      {"G41 D1 G1 X10.\nG40 G1 X20.\n", 6, "switched off (line 7) before the contour's first element"},
      {"G41 D1 G1 X10.\nG1 X20.\nG40 G1 X25. Y-5.\n", 8, "the exit move (line 8) is not collinear with the contour's last element"},
      {"G41 D1 G1 X10.\nG1 X20.\nG40\nG0 Z50.\n", 8, "the direction of the exit move (line 9) or of the contour's last element"},
      {"G41 D1 G1 X10.\nG1 X20.\nG42 G1 X30.\n", 8, "switched on again while on"},
  };
  for (const row& r : rows)
    for (const dialect from : {iso_d, linuxcnc_d}) {
      const dialect to = from == iso_d ? linuxcnc_d : iso_d;
      const std::string text = program(from, r.body);
      INFO(name(from) << " into " << name(to) << ":\n" << text);
      const read_result source = read(from, text, "m");
      REQUIRE(source.ok());
      const auto t = kin5::test::law_translator<machines::dmu_80p>(from, to, "m");
      string_sink out;
      const auto run = stream_text(*t, text, from, "m", to, out);
      REQUIRE(run.input.ok());
      if (r.line == 0) {
        REQUIRE(run.ok(*t));
        const read_result back = read(to, out.text, "back");
        REQUIRE(back.ok());
        CHECK(trace_of(back.parsed.blocks) == trace_of(source.parsed.blocks));
        continue;
      }
      CHECK_FALSE(run.ok(*t));
      REQUIRE_FALSE(t->result().errors.empty());
      const diagnostic& first = t->result().errors.front();
      CHECK(first.where.line == r.line);
      CHECK(first.message.find("cutter radius compensation between " + std::string(name(from)) + " and " +
                               std::string(name(to)) + ": ") == 0);
      CHECK(first.message.find(r.reason) != std::string::npos);
    }
}

TEST_CASE("cutter compensation: the directions compared are the moves' own, in every quadrant and sense") {
  using kin5::translate_detail::arc_path;
  using kin5::translate_detail::planar_direction;
  using kin5::translate_detail::planar_move;
  using kin5::translate_detail::runs_straight_on;
  using kin5::translate_detail::xy_direction;
  rc::prop("an arc's direction at either end is the derivative of its points along the motion", [] {
    const vec3 centre_mm{*rc::gen::inRange(-100000, 100000) / 1000.0, *rc::gen::inRange(-100000, 100000) / 1000.0, 0.0};
    const double radius_mm = *rc::gen::inRange(500, 100000) / 1000.0;
    const double from_rad = *rc::gen::inRange(0, 62831) / 10000.0, sweep_rad = *rc::gen::inRange(1000, 62831) / 10000.0;
    const bool clockwise = *rc::gen::arbitrary<bool>();
    const double to_rad = from_rad + (clockwise ? -sweep_rad : sweep_rad);
    const double z_mm = *rc::gen::inRange(-50, 50);
    const auto point = [&](double a) { return vec3{centre_mm.x + radius_mm * std::cos(a), centre_mm.y + radius_mm * std::sin(a), z_mm}; };
    // d/da (cos a, sin a) = (-sin a, cos a): the sense of increasing a, counter-clockwise.
    const auto along = [&](double a) {
      const double sense = clockwise ? -1.0 : 1.0;
      return vec3{-sense * std::sin(a), sense * std::cos(a), 0.0};
    };
    arc_path arc;
    arc.plane = arc_plane::xy, arc.clockwise = clockwise, arc.centre_mm = centre_mm;
    const planar_move m{point(from_rad), point(to_rad), &arc};
    const auto at_start = xy_direction(m, false), at_end = xy_direction(m, true);
    RC_ASSERT(at_start.has_value() && at_end.has_value());
    RC_ASSERT(norm(at_start->unit - along(from_rad)) < 1e-9);
    RC_ASSERT(norm(at_end->unit - along(to_rad)) < 1e-9);
    RC_ASSERT(std::abs(at_start->length_mm - radius_mm) < 1e-9);
  });
  rc::prop("a straight move's direction is its XY chord; none without XY motion or a start", [] {
    const vec3 a{*rc::gen::inRange(-1000, 1000) / 10.0, *rc::gen::inRange(-1000, 1000) / 10.0, *rc::gen::inRange(-1000, 1000) / 10.0};
    const vec3 b{*rc::gen::inRange(-1000, 1000) / 10.0, *rc::gen::inRange(-1000, 1000) / 10.0, *rc::gen::inRange(-1000, 1000) / 10.0};
    const auto d = xy_direction(planar_move{a, b, nullptr}, *rc::gen::arbitrary<bool>());
    const double chord_mm = std::hypot(b.x - a.x, b.y - a.y);
    if (chord_mm == 0.0) {
      RC_ASSERT(!d.has_value());
      return;
    }
    RC_ASSERT(d.has_value());
    RC_ASSERT(std::abs(d->length_mm - chord_mm) < 1e-9);
    RC_ASSERT(norm(d->unit - vec3{(b.x - a.x) / chord_mm, (b.y - a.y) / chord_mm, 0.0}) < 1e-12);
    RC_ASSERT(!xy_direction(planar_move{std::nullopt, b, nullptr}, false).has_value());
    RC_ASSERT(!xy_direction(planar_move{a, vec3{a.x, a.y, b.z}, nullptr}, false).has_value());
  });
  rc::prop("three collinear points rounded to 0.001 mm run straight on; turned by twice the allowance they do not", [] {
    const double heading = *rc::gen::inRange(0, 62831) / 10000.0;
    const vec3 u{std::cos(heading), std::sin(heading), 0.0};
    const vec3 a{*rc::gen::inRange(-100000, 100000) / 1000.0, *rc::gen::inRange(-100000, 100000) / 1000.0, 0.0};
    const double l1_mm = *rc::gen::inRange(1000, 200000) / 1000.0, l2_mm = *rc::gen::inRange(1000, 200000) / 1000.0;
    const auto rounded = [](const vec3& p) { return vec3{std::round(p.x * 1000) / 1000, std::round(p.y * 1000) / 1000, 0.0}; };
    const vec3 p = a + l1_mm * u, q = p + l2_mm * u;
    const auto entry = xy_direction(planar_move{rounded(a), rounded(p), nullptr}, false);
    const auto next = xy_direction(planar_move{rounded(p), rounded(q), nullptr}, false);
    RC_ASSERT(entry.has_value() && next.has_value());
    RC_ASSERT(runs_straight_on(*entry, *next, 0.001));
    RC_ASSERT(!runs_straight_on(*entry, planar_direction{-next->unit, next->length_mm}, 0.001));  // turned back
    const double allowance = std::sqrt(2.0) * 0.001 * (1.0 / entry->length_mm + 1.0 / next->length_mm);
    const double turn = std::asin(std::min(1.0, 2.0 * allowance)) * (*rc::gen::arbitrary<bool>() ? 1.0 : -1.0);
    const vec3 turned{entry->unit.x * std::cos(turn) - entry->unit.y * std::sin(turn),
                      entry->unit.x * std::sin(turn) + entry->unit.y * std::cos(turn), 0.0};
    RC_ASSERT(!runs_straight_on(*entry, planar_direction{turned, next->length_mm}, 0.001));
  });
}

TEST_CASE("cutter compensation: an entry or exit along an arc is refused at its switch") {
  using kin5::translate_detail::arc_path;
  using kin5::translate_detail::compensation_ends;
  using kin5::translate_detail::planar_move;
  arc_path arc;
  arc.plane = arc_plane::xy, arc.centre_mm = vec3{0, 10, 0};
  block on, line, off;
  on.where = {"m", 6, 1}, line.where = {"m", 7, 1}, off.where = {"m", 8, 1};
  on.state.radius_compensation = cutter_side::left, off.state.radius_compensation = cutter_side::off;
  const auto left = cutter_side::left, none = cutter_side::off;
  {  // G41 G3 X10 Y10 I0 J10 from X0 Y0
    compensation_ends ends;
    const auto r = ends.follow(on, none, left, planar_move{vec3{0, 0, 0}, vec3{10, 10, 0}, &arc}, false, 0.001);
    REQUIRE(r.has_value());
    CHECK(r->where.line == 6);
    CHECK(r->reason.find("the entry move is an arc") == 0);
  }
  {  // G41 G1 X10, G1 X20, G40 G3 X30 Y10 I0 J10
    compensation_ends ends;
    arc.centre_mm = vec3{20, 10, 0};
    CHECK_FALSE(ends.follow(on, none, left, planar_move{vec3{0, 0, 0}, vec3{10, 0, 0}, nullptr}, false, 0.001));
    CHECK_FALSE(ends.follow(line, left, left, planar_move{vec3{10, 0, 0}, vec3{20, 0, 0}, nullptr}, false, 0.001));
    const auto r = ends.follow(off, left, none, planar_move{vec3{20, 0, 0}, vec3{30, 10, 0}, &arc}, false, 0.001);
    REQUIRE(r.has_value());
    CHECK(r->where.line == 8);
    CHECK(r->reason.find("the exit move is an arc") == 0);
  }
}
