// Work-offset selections between every ordered pair of dialects. The table below is the one of
// docs/dialects/*.md, written here independently of the code: which selections each dialect's
// reader gives and its writer writes, and which mean the same across dialects (G54, G55, … in ISO,
// LinuxCNC and Siemens, the control's first settable zero offsets, as far as the target has the
// number: Siemens to G57, ISO to G59, LinuxCNC to G59.3). Everything else crosses only by
// the user's mapping (`--work-offset-map`), and without one it is refused.
//
// 1. writers and readers: a generated program of selections and moves, written by the target's
//    writer and read back by its reader, selects the same offset at every move; or the writer
//    refuses it, exactly when the table says the target has no such selection.
// 2. translation: the program, as text of its own dialect, translated (`translate`, or `reverse`
//    into APT) with a random mapping: the output read back selects at every move what the table
//    and the mapping say, or the run is refused with one error per selection without an
//    equivalent, naming it, and nothing is written.
#include <map>
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

using family = work_offset_family;
const std::vector<dialect> every_dialect = kin5::test::all_dialects();
/// The dialects that select work offsets (CL data select none).
const std::vector<dialect> writing_dialects = {id_of<siemens::dialect>(), id_of<heidenhain::dialect>(), id_of<iso::dialect>(),
                                               id_of<linuxcnc::dialect>(), id_of<haas::dialect>()};

/// What the reader of `d` gives and its writer writes (the documented table).
bool selects(dialect d, const work_offset& w) {
  if (d == id_of<iso::dialect>())
    return (w.family == family::g54 && w.number >= 1 && w.number <= 6) ||
           (w.family == family::extended && w.number >= 1 && w.number <= 300);
  if (d == id_of<siemens::dialect>())
    return (w.family == family::g54 && w.number >= 1 && w.number <= 4) ||
           (w.family == family::siemens && (w.number == 0 || (w.number >= 505 && w.number <= 599)));
  if (d == id_of<heidenhain::dialect>()) return w.family == family::preset && w.number >= 0 && w.number <= 65535;
  if (d == id_of<linuxcnc::dialect>()) return w.family == family::g54 && w.number >= 1 && w.number <= 9;  // G54 … G59.3
  if (d == id_of<haas::dialect>())  // G54 … G59, G154 P1 … P99
    return (w.family == family::g54 && w.number >= 1 && w.number <= 6) ||
           (w.family == family::extended && w.number >= 1 && w.number <= 99);
  return false;
}

/// A selection of any family, mostly one that some dialect has.
work_offset any_selection() {
  switch (*rc::gen::inRange(0, 5)) {
    case 0: return {family::g54, *rc::gen::inRange(1, 7)};
    case 1: return {family::extended, *rc::gen::inRange(1, 301)};
    case 2: return {family::siemens, *rc::gen::element(0, 505, 540, 599)};
    case 3: return {family::preset, *rc::gen::element(0, 1, 7, 65535)};
    default: return {family::g54, *rc::gen::inRange(7, 10)};  // G59.1 … G59.3: LinuxCNC's alone
  }
}

/// A selection the reader of `d` gives (not APT's: it has none).
work_offset selection_of(dialect d) {
  if (d == id_of<iso::dialect>()) {
    if (*rc::gen::inRange(0, 2)) return {family::extended, *rc::gen::inRange(1, 301)};
    return {family::g54, *rc::gen::inRange(1, 7)};
  }
  if (d == id_of<siemens::dialect>()) {
    switch (*rc::gen::inRange(0, 3)) {
      case 0: return {family::siemens, 0};
      case 1: return {family::siemens, *rc::gen::inRange(505, 600)};
      default: return {family::g54, *rc::gen::inRange(1, 5)};
    }
  }
  if (d == id_of<linuxcnc::dialect>()) return {family::g54, *rc::gen::inRange(1, 10)};
  if (d == id_of<haas::dialect>()) {
    if (*rc::gen::inRange(0, 2)) return {family::extended, *rc::gen::inRange(1, 100)};
    return {family::g54, *rc::gen::inRange(1, 7)};
  }
  return {family::preset, *rc::gen::inRange(0, 65536)};
}

/// Selections and moves as the reader of `from` gives them; under tool-tip tracking with the
/// rotary words of a B/C machine when `rotary` (for the translation), else plain X Y Z moves.
std::vector<block> draw_program(dialect from, bool rotary) {
  std::vector<block> out;
  if (rotary) out = kin5::test::tracking_start(from);  // tool 1, tracking on with its length
  const int n = *rc::gen::inRange(1, 12);
  double x = 0;
  for (int k = 0; k < n; ++k) {
    block b;
    if (*rc::gen::inRange(0, 3) == 0) {
      b.state.work_offset = selection_of(from);
    } else {
      b = kin5::test::law_move(x += 1, rotary);
    }
    out.push_back(b);
  }
  return out;
}

/// The selection in effect at each move of `blocks`.
std::vector<std::optional<work_offset>> trace_of(const std::vector<block>& blocks) {
  std::vector<std::optional<work_offset>> t;
  std::optional<work_offset> current;
  for (const block& b : blocks) {
    if (b.state.work_offset) current = b.state.work_offset;
    if (b.moves()) t.push_back(current);
  }
  return t;
}

/// Whether `d` names its first settable zero offsets G54, G55, … (ISO, LinuxCNC, Siemens, Haas).
bool g_code_offsets(dialect d) {
  return d == id_of<iso::dialect>() || d == id_of<siemens::dialect>() || d == id_of<linuxcnc::dialect>() ||
         d == id_of<haas::dialect>();
}

/// The same selection in `to` without a mapping: the same dialect, or G54 … in two G-code
/// dialects where the target has that one (Siemens G54 … G57, ISO G54 … G59, LinuxCNC … G59.3),
/// or additional offset n between ISO (G54.1 P n) and Haas (G154 P n) where the target has it.
bool same_meaning(const work_offset& w, dialect from, dialect to) {
  const bool additional = w.family == family::extended && (from == id_of<iso::dialect>() || from == id_of<haas::dialect>());
  return from == to ||
         (g_code_offsets(from) && g_code_offsets(to) && (w.family == family::g54 || additional) && selects(to, w));
}

}  // namespace

TEST_CASE("work offsets: the table of selections is each dialect's capability") {
  for (const dialect d : every_dialect)
    for (const family f : {family::g54, family::extended, family::siemens, family::preset})
      for (int n = 0; n <= 1000; ++n) CHECK(capabilities_of(d).writes({f, n}) == selects(d, {f, n}));
  CHECK(capabilities_of(id_of<heidenhain::dialect>()).writes({family::preset, 65535}));
  CHECK_FALSE(capabilities_of(id_of<heidenhain::dialect>()).writes({family::preset, 65536}));
}

TEST_CASE("work offsets: every ordered pair of dialects writes a selection it has and refuses one it lacks") {
  kin5::test::check_each_pair(writing_dialects, every_dialect, [](dialect from, dialect to) {
    program_text p = kin5::test::law_program(from, "gen", draw_program(from, false));
    bool writable = true;
    for (const block& b : p.blocks)
      if (b.state.work_offset && !selects(to, *b.state.work_offset)) writable = false;
    std::string text;
    try {
      text = write(to, p);
    } catch (const std::invalid_argument& e) {
      RC_ASSERT(!writable);
      RC_ASSERT(std::string(e.what()).find("work offset") != std::string::npos);
      return;
    }
    RC_ASSERT(writable);
    const read_result back = read(to, text, "back");
    RC_ASSERT(back.ok());
    RC_ASSERT(trace_of(back.parsed.blocks) == trace_of(p.blocks));
  });
}

TEST_CASE("work offsets: translation writes the same selection, the mapped one, or refuses at the selection") {
  using M = machines::dmu_80p;
  kin5::test::check_each_pair(writing_dialects, every_dialect, [](dialect from, dialect to) {
    program_text p = kin5::test::law_program(from, "w", draw_program(from, true));
    const std::string text = write(from, p);
    // A mapping of some of the program's selections: to one of the target's, to one it
    // lacks, or dropped.
    std::map<std::pair<int, int>, std::optional<work_offset>> chosen;
    common_options common;
    for (const block& b : p.blocks) {
      if (!b.state.work_offset || *rc::gen::inRange(0, 2) == 0) continue;
      const work_offset w = *b.state.work_offset;
      if (chosen.count({static_cast<int>(w.family), w.number})) continue;
      std::optional<work_offset> target;
      const int kind = *rc::gen::inRange(0, 3);
      if (kind == 0 && to != id_of<apt::dialect>()) target = selection_of(to);
      if (kind == 1) target = any_selection();
      chosen[{static_cast<int>(w.family), w.number}] = target;
      const std::string entry = map_key(w) + "=" + (target ? map_key(*target) : "");
      RC_ASSERT(common.work_offsets.add(entry));
    }
    // What the table and the mapping say each selection becomes; the refused ones.
    std::vector<block> want = p.blocks;
    std::size_t refused = 0;
    for (block& b : want) {
      if (!b.state.work_offset) continue;
      const work_offset w = *b.state.work_offset;
      const auto m = chosen.find({static_cast<int>(w.family), w.number});
      if (m != chosen.end()) {
        if (m->second && !selects(to, *m->second)) ++refused;
        b.state.work_offset = m->second;
      } else if (!same_meaning(w, from, to)) {
        ++refused;
      }
    }
    translate_options options;
    options.common = common;
    const auto t = kin5::test::law_translator<M>(from, to, "w", options);
    string_sink out;
    const auto run = stream_text(*t, text, from, "w", to, out);
    RC_ASSERT(run.input.ok());
    if (refused) {
      RC_ASSERT(t->result().errors.size() == refused);
      for (const diagnostic& d : t->result().errors) {
        RC_ASSERT(d.option.rfind("--work-offset-map ", 0) == 0);
        RC_ASSERT(d.message.find(d.construct + ":") == 0);
      }
      RC_ASSERT(out.text.empty());
      return;
    }
    RC_ASSERT(run.ok(*t));
    const read_result back = read(to, out.text, "back");
    RC_ASSERT(back.ok());
    RC_ASSERT(trace_of(back.parsed.blocks) == trace_of(want));
  });
}

TEST_CASE("work offsets: each reader's spellings, and the refusals around them") {
  struct row {
    dialect d;
    const char* text;
    std::optional<work_offset> selected;
    const char* error;  // the first error, or empty
  };
  const std::vector<row> rows = {
      {id_of<iso::dialect>(), "G54\n", work_offset{family::g54, 1}, ""},
      {id_of<iso::dialect>(), "G90 G59 G17\n", work_offset{family::g54, 6}, ""},
      {id_of<iso::dialect>(), "G54.1 P48\n", work_offset{family::extended, 48}, ""},
      {id_of<iso::dialect>(), "P7 G54.1\n", work_offset{family::extended, 7}, ""},
      {id_of<iso::dialect>(), "G54.1\n", std::nullopt, "t:1:1: error: G54.1 needs P n, the number of the extended work offset"},
      {id_of<iso::dialect>(), "G54.1 P0\n", std::nullopt,
       "t:1:7: error: G54.1 P: the extended work offset's number must be a whole number from 1 to 300"},
      {id_of<iso::dialect>(), "G54 G55\n", std::nullopt, "t:1:5: error: two work offsets in one block"},
      {id_of<iso::dialect>(), "G54 G54.1 P2\n", std::nullopt, "t:1:1: error: two work offsets in one block"},
      {id_of<haas::dialect>(), "G154 P99\n", work_offset{family::extended, 99}, ""},
      {id_of<haas::dialect>(), "G110\n", work_offset{family::extended, 1}, ""},
      {id_of<haas::dialect>(), "G129\n", work_offset{family::extended, 20}, ""},
      {id_of<haas::dialect>(), "G59\n", work_offset{family::g54, 6}, ""},
      {id_of<haas::dialect>(), "G54.1 P2\n", std::nullopt,
       "t:1:1: error: G54.1 is not a Haas G code (its additional work offsets are G154 P1 … P99)"},
      {id_of<siemens::dialect>(), "N10 G54\n", work_offset{family::g54, 1}, ""},
      {id_of<siemens::dialect>(), "N10 G57\n", work_offset{family::g54, 4}, ""},
      {id_of<siemens::dialect>(), "N10 G505\n", work_offset{family::siemens, 505}, ""},
      {id_of<siemens::dialect>(), "N10 G599\n", work_offset{family::siemens, 599}, ""},
      {id_of<siemens::dialect>(), "N10 G500\n", work_offset{family::siemens, 0}, ""},
      {id_of<siemens::dialect>(), "N10 G54 G505\n", std::nullopt, "t:1:9: error: two work offsets in one block"},
      {id_of<siemens::dialect>(), "N10 G58 X10\n", std::nullopt,
       "t:1:5: error: G58 changes the working frame; kin5 does not model frame changes"},
      {id_of<heidenhain::dialect>(), "1 CYCL DEF 247 DATUM SETTING ~\n  Q339=+3 ;DATUM NUMBER\n", work_offset{family::preset, 3}, ""},
      {id_of<heidenhain::dialect>(), "1 CYCL DEF 247 DATUM SETTING Q339=+0\n", work_offset{family::preset, 0}, ""},
      {id_of<heidenhain::dialect>(), "1 CYCL DEF 247 DATUM SETTING\n", std::nullopt,
       "t:1:3: error: CYCL DEF 247 (datum setting) without Q339 in its block: the preset it selects is not known"},
      {id_of<heidenhain::dialect>(), "1 CYCL DEF 247 DATUM SETTING ~\n  Q339=+Q5\n", std::nullopt,
       "t:2:3: error: CYCL DEF 247 (datum setting): only Q339=n, a preset number from 0 to 65535, is read"},
      {id_of<heidenhain::dialect>(), "1 CYCL DEF 247 Q339=+1.5\n", std::nullopt,
       "t:1:16: error: CYCL DEF 247 (datum setting): only Q339=n, a preset number from 0 to 65535, is read"},
      {id_of<heidenhain::dialect>(), "1 CYCL DEF 7.0 DATUM SHIFT\n2 CYCL DEF 7.1 X+10\n", std::nullopt,
       "t:2:3: error: CYCL DEF 7 changes the working frame; kin5 does not model frame changes"},
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
    std::optional<work_offset> selected;
    for (const block& b : got.parsed.blocks)
      if (b.state.work_offset) selected = b.state.work_offset;
    CHECK(selected == r.selected);
  }
}

TEST_CASE("work offsets: --work-offset-map entries") {
  work_offset_map map;
  CHECK(map.add("G54=1,g55=2"));
  CHECK(map.add("G54.1P7=G505"));
  CHECK(map.add("G500="));
  CHECK(map.target_of({family::g54, 1}) == std::optional<std::optional<work_offset>>(work_offset{family::preset, 1}));
  CHECK(map.target_of({family::g54, 2}) == std::optional<std::optional<work_offset>>(work_offset{family::preset, 2}));
  CHECK(map.target_of({family::extended, 7}) ==
        std::optional<std::optional<work_offset>>(work_offset{family::siemens, 505}));
  CHECK(map.target_of({family::siemens, 0}) == std::optional<std::optional<work_offset>>(std::optional<work_offset>{}));
  CHECK_FALSE(map.target_of({family::g54, 3}));
  for (const char* bad : {"G54", "G54=X", "G53=1", "G54=1", "G56=1,G56=2", "=1", "G54.1=1", "G504=1", "-1=G54", "G54=+1"})
    CHECK_FALSE(map.add(bad));
  CHECK_FALSE(map.target_of({family::g54, 4}));  // nothing of a refused list is kept
}
