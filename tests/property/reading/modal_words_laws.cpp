// Working plane (G17/G18/G19), distance mode (G90/G91) and radius compensation cancel (G40)
// between every ordered pair of dialects. The table, written here independently of the code
// (docs/dialects/*.md): ISO, LinuxCNC and Siemens read and write the three as codes; Heidenhain
// and APT write no word for them, because their text is absolute and uncompensated anyway and
// every circle carries its own plane (a Heidenhain CC line; APT writes no circles from NC), so
// the plane is compared there through the arcs only, not as a state; both refuse G91. Siemens
// refuses G18/G19 of another dialect while a tool length may be in effect (the 840D turns the
// length with the plane; docs/dialects/siemens.md), as here, where no D0 is ever said; and the
// translation refuses a Siemens source's move under its own G18/G19 for the same reason.
//
// 1. writers and readers: a generated program of state words and moves, written by the target's
//    writer and read back by its reader, is in the same effective state at every move (absolute,
//    XY and no compensation where nothing was said), and a target that has the words says by each
//    move all that the source said (the machine may start in another state); or the writer
//    refuses G91, exactly where the table says it cannot say it.
// 2. translation: the program, as text of its own dialect, translated (`translate`, or `reverse`
//    into APT): the output read back is in the same effective state at every move, and says as
//    much as in 1.
#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
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

const std::vector<dialect> every_dialect = kin5::test::all_dialects();
/// The dialects whose readers give these state words.
const std::vector<dialect> reading_dialects = {id_of<iso::dialect>(), id_of<linuxcnc::dialect>(), id_of<siemens::dialect>(),
                                              id_of<haas::dialect>()};

/// Whether dialect `d` writes the working plane as a word (the documented table).
bool writes_plane(dialect d) { return d != id_of<heidenhain::dialect>() && d != id_of<apt::dialect>(); }
/// Whether dialect `d` can say incremental positioning.
bool writes_incremental(dialect d) { return d != id_of<heidenhain::dialect>() && d != id_of<apt::dialect>(); }

/// Whether writing `blocks` of dialect `from` in `to` is refused for a G18/G19 under a tool
/// length (Siemens from another dialect; the programs here never switch the length off).
bool plane_turns_length(dialect from, dialect to, const std::vector<block>& blocks) {
  if (to != id_of<siemens::dialect>() || from == to) return false;
  for (const block& b : blocks)
    if (b.state.working_plane && *b.state.working_plane != arc_plane::xy) return true;
  return false;
}
constexpr const char* plane_refusal = "while tool length compensation may be on";

/// Whether a Siemens source moves under its own G18/G19: refused by the translation, which reads
/// the point as the tip along the tool axis where the 840D puts the length along Y or X.
bool moves_under_turned_length(dialect from, const std::vector<block>& blocks) {
  if (from != id_of<siemens::dialect>()) return false;
  modal_state m;
  for (const block& b : blocks) {
    m.apply(b);
    if (is_motion(b) && m.working_plane && *m.working_plane != arc_plane::xy) return true;
  }
  return false;
}

/// The effective state at a move: plane (when compared), distance mode, radius compensation.
using effective = std::tuple<std::optional<arc_plane>, distance_mode, cutter_side>;

/// The state in effect at each move of `blocks`; the plane only when `with_plane`.
std::vector<effective> trace_of(const std::vector<block>& blocks, bool with_plane) {
  std::vector<effective> t;
  modal_state m;
  for (const block& b : blocks) {
    m.apply(b);
    if (!is_motion(b)) continue;
    t.emplace_back(with_plane ? std::optional<arc_plane>(m.working_plane.value_or(arc_plane::xy)) : std::nullopt,
                   m.distance.value_or(distance_mode::absolute), m.radius_compensation.value_or(cutter_side::off));
  }
  return t;
}

/// Which of the plane, the distance mode and the radius compensation have been said by each
/// move of `blocks`. The machine may start in any state (left by MDI or another program), so an
/// output must say at each move at least what its source said by then.
using said = std::array<bool, 3>;
std::vector<said> said_of(const std::vector<block>& blocks) {
  std::vector<said> t;
  modal_state m;
  for (const block& b : blocks) {
    m.apply(b);
    if (is_motion(b)) t.push_back({m.working_plane.has_value(), m.distance.has_value(), m.radius_compensation.has_value()});
  }
  return t;
}

/// Whether `output` says, at each move, all that `source` says (the same number of moves).
bool says_all(const std::vector<said>& output, const std::vector<said>& source) {
  if (output.size() != source.size()) return false;
  for (std::size_t i = 0; i < source.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k)
      if (source[i][k] && !output[i][k]) return false;
  return true;
}

/// Blocks of state words and moves as the reader of `from` gives them; under tool-tip tracking
/// with the rotary words of a B/C machine when `rotary` (for the translation), else X Y Z moves.
std::vector<block> draw_program(dialect from, bool rotary) {
  std::vector<block> out;
  if (rotary) out = kin5::test::tracking_start(from);  // tool 1, tracking on with its length
  const int n = *rc::gen::inRange(1, 12);
  double x = 0;
  for (int k = 0; k < n; ++k) {
    block b;
    if (*rc::gen::inRange(0, 3) == 0) {
      if (*rc::gen::inRange(0, 2)) b.state.working_plane = *rc::gen::element(arc_plane::xy, arc_plane::zx, arc_plane::yz);
      if (*rc::gen::inRange(0, 2)) b.state.distance = distance_mode::absolute;
      if (*rc::gen::inRange(0, 2) || b.state.empty()) b.state.radius_compensation = cutter_side::off;
    } else {
      b = kin5::test::law_move(x += 1, rotary);
    }
    out.push_back(b);
  }
  return out;
}

}  // namespace

TEST_CASE("modal words: every ordered pair of dialects writes the plane, G90 and G40 or says them by its text") {
  kin5::test::check_each_pair(reading_dialects, every_dialect, [](dialect from, dialect to) {
    program_text p = kin5::test::law_program(from, "gen", draw_program(from, false));
    // G91 between moves, cancelled before the next: only where the target cannot say it
    // (the readers of the others refuse a G91 outside a homing block).
    const bool incremental = !writes_incremental(to) && *rc::gen::inRange(0, 4) == 0;
    if (incremental) {
      block g91;
      g91.state.distance = distance_mode::incremental;
      p.blocks.insert(p.blocks.begin() + *rc::gen::inRange<std::size_t>(0, p.blocks.size() + 1), g91);
    }
    const bool turns = plane_turns_length(from, to, p.blocks);
    std::string text;
    try {
      text = write(to, p);
    } catch (const std::invalid_argument& e) {
      RC_ASSERT(incremental || turns);
      RC_ASSERT(std::string(e.what()).find(incremental ? "incremental positioning (G91)" : plane_refusal) !=
                std::string::npos);
      return;
    }
    RC_ASSERT(!incremental);
    RC_ASSERT(!turns);
    const read_result back = read(to, text, "back");
    RC_ASSERT(back.ok());
    RC_ASSERT(trace_of(back.parsed.blocks, writes_plane(to)) == trace_of(p.blocks, writes_plane(to)));
    if (writes_plane(to)) RC_ASSERT(says_all(said_of(back.parsed.blocks), said_of(p.blocks)));
  });
}

TEST_CASE("modal words: translation keeps the plane, G90 and G40 in every ordered pair of dialects") {
  using M = machines::dmu_80p;  // to itself: the setup is the identity, planes map to themselves
  kin5::test::check_each_pair(reading_dialects, every_dialect, [](dialect from, dialect to) {
    const program_text p = kin5::test::law_program(from, "m", draw_program(from, true));
    const std::string text = write(from, p);
    const auto t = kin5::test::law_translator<M>(from, to, "m");
    string_sink out;
    const auto run = stream_text(*t, text, from, "m", to, out);
    RC_ASSERT(run.input.ok());
    if (moves_under_turned_length(from, p.blocks)) {
      RC_ASSERT(!t->result().ok());
      RC_ASSERT(t->result().errors.front().message.find("motion under G1") != std::string::npos);
      RC_ASSERT(t->result().errors.front().message.find(plane_refusal) != std::string::npos);
      return;
    }
    if (plane_turns_length(from, to, p.blocks)) {
      RC_ASSERT(run.writer_error.has_value());
      RC_ASSERT(run.writer_error->message.find(plane_refusal) != std::string::npos);
      return;
    }
    RC_ASSERT(run.ok(*t));
    const read_result back = read(to, out.text, "back");
    RC_ASSERT(back.ok());
    RC_ASSERT(trace_of(back.parsed.blocks, writes_plane(to)) == trace_of(p.blocks, writes_plane(to)));
    if (writes_plane(to)) RC_ASSERT(says_all(said_of(back.parsed.blocks), said_of(p.blocks)));
  });
}

TEST_CASE("modal words: each reader's spellings, and G91 resolved where its base is known") {
  struct row {
    dialect d;
    const char* text;
    std::optional<arc_plane> plane;
    std::optional<distance_mode> distance;
    std::optional<cutter_side> radius;
    const char* error;  // the first error, or empty
  };
  const auto iso = id_of<iso::dialect>(), lc = id_of<linuxcnc::dialect>(), sie = id_of<siemens::dialect>();
  const std::vector<row> rows = {
      {iso, "G90 G17 G40\n", arc_plane::xy, distance_mode::absolute, cutter_side::off, ""},
      {iso, "g18\n", arc_plane::zx, std::nullopt, std::nullopt, ""},
      {iso, "G19 G18\n", arc_plane::zx, std::nullopt, std::nullopt, ""},
      {iso, "G91 G28 Z0.\nG90\nG0 X1.\n", std::nullopt, distance_mode::absolute, std::nullopt, ""},
      // G91 left in effect by a home move: the next move is resolved and written after G90
      {iso, "G0 X0. Z5.\nG91 G28 Z0.\nG0 X1.\n", std::nullopt, distance_mode::absolute, std::nullopt, ""},
      {iso, "G91\n", std::nullopt, distance_mode::incremental, std::nullopt, ""},
      // a move under G91 holds positions: the model says G90 there
      {iso, "G0 X0.\nG91 G0 X1.\n", std::nullopt, distance_mode::absolute, std::nullopt, ""},
      {iso, "G91 G0 X1.\n", std::nullopt, std::nullopt, std::nullopt,
       "t:1:8: error: incremental X (G91 of line 1) from a position the program does not say: no absolute X since the start of the program, so the move would start from wherever the machine stands; program an absolute X (G90) before it"},
      {id_of<haas::dialect>(), "G90 G18 G40\n", arc_plane::zx, distance_mode::absolute, cutter_side::off, ""},
      {lc, "G19 G90 G40\n", arc_plane::yz, distance_mode::absolute, cutter_side::off, ""},
      {lc, "G91 G28 Z0\nG1 X1 F100\n", std::nullopt, std::nullopt, std::nullopt,
       "t:2:4: error: incremental X (G91 of line 1) from a position the program does not say: no absolute X since the start of the program, so the move would start from wherever the machine stands; program an absolute X (G90) before it"},
      {sie, "N10 G17 G90 G40\n", arc_plane::xy, distance_mode::absolute, cutter_side::off, ""},
      {sie, "N10 G018\n", arc_plane::zx, std::nullopt, std::nullopt, ""},
      {sie, "N10 G91 X1\n", std::nullopt, std::nullopt, std::nullopt,
       "t:1:9: error: incremental X (G91 of line 1) from a position the program does not say: no absolute X since the start of the program, so the move would start from wherever the machine stands; program an absolute X (G90) before it"},
      {sie, "N10 X0\nN20 G91 X1\n", std::nullopt, distance_mode::absolute, std::nullopt, ""},
      {sie, "N10 G91\n", std::nullopt, distance_mode::incremental, std::nullopt, ""},
  };
  for (const row& r : rows) {
    INFO(r.text);
    const read_result got = read(r.d, r.text, "t");
    if (*r.error) {
      REQUIRE_FALSE(got.errors.empty());
      CHECK(got.errors[0].to_string() == r.error);
      continue;
    }
    CHECK(got.errors.empty());
    modal_state m;
    for (const block& b : got.parsed.blocks) {
      m.apply(b);
      for (const std::string& w : b.kept_words)  // never kept as text: a comment elsewhere would lose them
        for (const char* g : {"G17", "G18", "G19", "G40", "G90", "G91"}) CHECK(w != g);
    }
    CHECK(m.working_plane == r.plane);
    CHECK(m.distance == r.distance);
    CHECK(m.radius_compensation == r.radius);
  }
}
