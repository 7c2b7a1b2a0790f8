// What stays in effect from block to block (modal_state): each rule of program/modal.hpp
// checked on examples, and over random programs against a second, independent formulation
// that looks backwards from each block for the words that decide each value.
#include <optional>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/modal.hpp>

namespace {

using namespace kin5::program;

template <class T>
std::optional<T> maybe(const rc::Gen<T>& g, int one_in = 3) {
  if (*rc::gen::inRange(0, one_in) != 0) return std::nullopt;
  return *g;
}

/// A block with a few words drawn from small sets, so that random programs repeat and override
/// values often.
block any_block() {
  block b;
  b.tool = maybe(rc::gen::inRange<long long>(1, 4));
  b.spindle_rpm = maybe(rc::gen::element(1000.0, 2500.0));
  b.metric = maybe(rc::gen::arbitrary<bool>(), 6);
  b.feed_mode = maybe(rc::gen::element(feed_unit::per_minute, feed_unit::inverse_time), 4);
  b.feed = maybe(rc::gen::element(5.0, 800.0, 1200.0), 2);
  b.motion = maybe(rc::gen::element(motion_kind::rapid, motion_kind::linear, motion_kind::arc_cw), 3);
  b.axes.x_mm = maybe(rc::gen::element(0.0, 10.0), 2);
  b.feed_rapid = *rc::gen::inRange(0, 8) == 0;
  b.machine_coordinates = *rc::gen::inRange(0, 10) == 0;
  if (*rc::gen::inRange(0, 15) == 0) b.program_end = "M30";
  state_words& s = b.state;
  s.tool_change = *rc::gen::inRange(0, 4) == 0;
  s.tool_spindle_axis = maybe(rc::gen::element(spindle_axis::x, spindle_axis::z), 5);
  s.length_compensation = maybe(rc::gen::arbitrary<bool>(), 3);
  s.length_register = maybe(rc::gen::inRange<long long>(1, 4), 3);
  s.radius_compensation = maybe(rc::gen::element(cutter_side::off, cutter_side::left, cutter_side::right), 3);
  s.radius_register = maybe(rc::gen::inRange<long long>(1, 4), 3);
  s.cutting_edge = maybe(rc::gen::inRange<long long>(0, 3), 5);
  s.spindle = maybe(rc::gen::element(spindle_rotation::clockwise, spindle_rotation::counter_clockwise,
                                     spindle_rotation::stopped), 3);
  s.coolant_flood = maybe(rc::gen::arbitrary<bool>(), 3);
  s.coolant_mist = maybe(rc::gen::arbitrary<bool>(), 3);
  s.work_offset = maybe(rc::gen::element(work_offset{work_offset_family::g54, 1},
                                         work_offset{work_offset_family::extended, 1},
                                         work_offset{work_offset_family::preset, 2}), 4);
  s.working_plane = maybe(rc::gen::element(arc_plane::xy, arc_plane::zx, arc_plane::yz), 4);
  s.distance = maybe(rc::gen::element(distance_mode::absolute, distance_mode::incremental), 4);
  s.dwell_s = maybe(rc::gen::element(0.5, 2.0), 6);
  s.stop = maybe(rc::gen::element(program_stop::stop, program_stop::optional_stop), 6);
  return b;
}

// ---- the reference: for block i, search blocks i, i-1, ..., 0 for the words that decide ----

template <class T, class Get>
std::optional<T> last_given(const std::vector<block>& p, std::size_t i, Get get) {
  for (std::size_t j = i + 1; j-- > 0;)
    if (auto v = get(p[j])) return *v;
  return std::nullopt;
}

std::optional<long long> expected_active_tool(const std::vector<block>& p, std::size_t i) {
  for (std::size_t j = i + 1; j-- > 0;)
    if (p[j].state.tool_change) return last_given<long long>(p, j, [](const block& b) { return b.tool; });
  return std::nullopt;
}

/// The register in effect: that of the last block naming one or switching the compensation on
/// (switched on without one: the active tool's own, no number).
template <class Names, class SwitchesOn>
std::optional<long long> expected_register(const std::vector<block>& p, std::size_t i, Names names,
                                           SwitchesOn switches_on) {
  for (std::size_t j = i + 1; j-- > 0;) {
    if (auto r = names(p[j])) return *r;
    if (switches_on(p[j])) return std::nullopt;
  }
  return std::nullopt;
}

feed_unit expected_mode(const std::vector<block>& p, std::size_t i) {
  return last_given<feed_unit>(p, i, [](const block& b) { return b.feed_mode; }).value_or(feed_unit::per_minute);
}

bool is_feed_move(const std::vector<block>& p, std::size_t k) {
  const auto kind = last_given<motion_kind>(p, k, [](const block& b) { return b.motion; });
  return p[k].moves() && !p[k].feed_rapid && kind && *kind != motion_kind::rapid;
}

/// F in effect at block i: the last F given, unless the feed mode changed since, or (inverse
/// time) a feed move has used it before block i.
std::optional<double> expected_feed(const std::vector<block>& p, std::size_t i) {
  for (std::size_t j = i + 1; j-- > 0;) {
    if (p[j].feed) {
      for (std::size_t k = j; k < i; ++k)
        if (expected_mode(p, k) == feed_unit::inverse_time && is_feed_move(p, k)) return std::nullopt;
      return p[j].feed;
    }
    const feed_unit before = j > 0 ? expected_mode(p, j - 1) : feed_unit::per_minute;
    if (p[j].feed_mode && *p[j].feed_mode != before) return std::nullopt;
  }
  return std::nullopt;
}

void check_against_reference(const std::vector<block>& p, std::size_t i, const modal_state& m) {
  auto last = [&](auto get) {
    using T = typename std::decay_t<decltype(get(p[0]))>::value_type;
    return last_given<T>(p, i, get);
  };
  RC_ASSERT(m.selected_tool == last([](const block& b) { return b.tool; }));
  RC_ASSERT(m.active_tool == expected_active_tool(p, i));
  RC_ASSERT(m.tool_spindle_axis == last([](const block& b) { return b.state.tool_spindle_axis; }));
  RC_ASSERT(m.length_compensation == last([](const block& b) { return b.state.length_compensation; }));
  RC_ASSERT(m.length_register ==
            expected_register(p, i, [](const block& b) { return b.state.length_register; },
                              [](const block& b) { return b.state.length_compensation == true; }));
  RC_ASSERT(m.radius_compensation == last([](const block& b) { return b.state.radius_compensation; }));
  RC_ASSERT(m.radius_register ==
            expected_register(p, i, [](const block& b) { return b.state.radius_register; },
                              [](const block& b) {
                                return b.state.radius_compensation && *b.state.radius_compensation != cutter_side::off;
                              }));
  RC_ASSERT(m.cutting_edge == last([](const block& b) { return b.state.cutting_edge; }));
  RC_ASSERT(m.spindle == last([](const block& b) { return b.state.spindle; }));
  RC_ASSERT(m.spindle_rpm == last([](const block& b) { return b.spindle_rpm; }));
  RC_ASSERT(m.coolant_flood == last([](const block& b) { return b.state.coolant_flood; }));
  RC_ASSERT(m.coolant_mist == last([](const block& b) { return b.state.coolant_mist; }));
  RC_ASSERT(m.work_offset == last([](const block& b) { return b.state.work_offset; }));
  RC_ASSERT(m.working_plane == last([](const block& b) { return b.state.working_plane; }));
  RC_ASSERT(m.distance == last([](const block& b) { return b.state.distance; }));
  RC_ASSERT(m.metric == last([](const block& b) { return b.metric; }));
  bool ended = false;
  for (std::size_t j = 0; j <= i; ++j) ended = ended || p[j].program_end.has_value();
  RC_ASSERT(m.ended == ended);
  RC_ASSERT(m.feed_mode == expected_mode(p, i));
  RC_ASSERT(m.feed == expected_feed(p, i));
}

block with(auto&& set) {
  block b;
  set(b);
  return b;
}

modal_state run(const std::vector<block>& p) {
  modal_state m;
  for (const auto& b : p) m.apply(b);
  return m;
}

}  // namespace

TEST_CASE("modal state after every block equals the backward-looking reference", "[modal]") {
  rc::prop("random programs", [] {
    const auto p = *rc::gen::container<std::vector<block>>(*rc::gen::inRange(1, 40), rc::gen::exec(any_block));
    modal_state m;
    for (std::size_t i = 0; i < p.size(); ++i) {
      m.apply(p[i]);
      check_against_reference(p, i, m);
    }
  });
}

TEST_CASE("a T word selects, a change loads the selected tool", "[modal]") {
  const auto select5 = with([](block& b) { b.tool = 5; });                      // ISO T5
  const auto change = with([](block& b) { b.state.tool_change = true; });       // M6
  const auto call7 = with([](block& b) { b.tool = 7, b.state.tool_change = true; });  // TOOL CALL 7
  CHECK_FALSE(run({select5}).active_tool);
  CHECK(run({select5, change}).active_tool == 5);
  CHECK(run({select5, change, with([](block& b) { b.tool = 9; })}).active_tool == 5);  // T9: the next tool
  CHECK(run({select5, change, call7}).active_tool == 7);
  CHECK_FALSE(run({change}).active_tool);  // M6 with nothing selected: the tool is not known
}

TEST_CASE("a tool change leaves the length and radius compensation as they were", "[modal]") {
  const auto g43_h5 = with([](block& b) { b.state.length_compensation = true, b.state.length_register = 5; });
  const auto m6 = with([](block& b) { b.tool = 6, b.state.tool_change = true; });
  const auto m = run({g43_h5, m6});  // on a Fanuc the old H5 stays in effect until a new G43 H
  CHECK(m.length_compensation == true);
  CHECK(m.length_register == 5);
}

TEST_CASE("compensation switched on without a register uses the active tool's own entry", "[modal]") {
  const auto g43_h5 = with([](block& b) { b.state.length_compensation = true, b.state.length_register = 5; });
  const auto g43 = with([](block& b) { b.state.length_compensation = true; });
  const auto g49 = with([](block& b) { b.state.length_compensation = false; });
  CHECK_FALSE(run({g43_h5, g43}).length_register);
  CHECK(run({g43_h5, g49}).length_register == 5);  // off: the register is not forgotten
  const auto g41_d3 = with([](block& b) { b.state.radius_compensation = cutter_side::left, b.state.radius_register = 3; });
  const auto g42 = with([](block& b) { b.state.radius_compensation = cutter_side::right; });
  const auto g40 = with([](block& b) { b.state.radius_compensation = cutter_side::off; });
  CHECK_FALSE(run({g41_d3, g42}).radius_register);
  CHECK(run({g41_d3, g40}).radius_register == 3);
  CHECK(run({g41_d3, g40}).radius_compensation == cutter_side::off);
}

TEST_CASE("flood and mist coolant are independent, M9 switches both off", "[modal]") {
  const auto m7 = with([](block& b) { b.state.coolant_mist = true; });
  const auto m8 = with([](block& b) { b.state.coolant_flood = true; });
  const auto m9 = with([](block& b) { b.state.coolant_flood = false, b.state.coolant_mist = false; });
  const auto both = run({m7, m8});
  CHECK((both.coolant_mist == true && both.coolant_flood == true));
  const auto off = run({m7, m8, m9});
  CHECK((off.coolant_mist == false && off.coolant_flood == false));
}

TEST_CASE("a stopped spindle keeps its speed for the next start", "[modal]") {
  const auto m3_s = with([](block& b) { b.spindle_rpm = 6000.0, b.state.spindle = spindle_rotation::clockwise; });
  const auto m5 = with([](block& b) { b.state.spindle = spindle_rotation::stopped; });
  const auto m4 = with([](block& b) { b.state.spindle = spindle_rotation::counter_clockwise; });
  const auto m = run({m3_s, m5, m4});
  CHECK(m.spindle == spindle_rotation::counter_clockwise);
  CHECK(m.spindle_rpm == 6000.0);
}

TEST_CASE("F: kept per minute, dropped on a feed-mode change, used once in inverse time", "[modal]") {
  const auto g1 = [](double x) { return with([x](block& b) { b.motion = motion_kind::linear, b.axes.x_mm = x; }); };
  const auto f = [](double v) { return with([v](block& b) { b.feed = v; }); };
  const auto g93 = with([](block& b) { b.feed_mode = feed_unit::inverse_time; });
  const auto g94 = with([](block& b) { b.feed_mode = feed_unit::per_minute; });
  CHECK(run({f(800), g1(1), g1(2)}).feed == 800.0);
  CHECK_FALSE(run({f(800), g93}).feed);         // switching to inverse time drops 800 mm/min
  CHECK_FALSE(run({g93, f(2), g94}).feed);       // and back: a G94 needs a new F
  CHECK(run({f(800), g94}).feed == 800.0);       // the same mode again changes nothing
  modal_state m;
  for (const auto& b : {g93, f(2)}) m.apply(b);
  m.apply(g1(1));
  CHECK(m.feed == 2.0);                           // the move's own F
  m.apply(g1(2));
  CHECK_FALSE(m.feed);                            // the next feed move has none
  modal_state r;
  for (const auto& b : {g93, f(2), with([](block& b) { b.motion = motion_kind::rapid, b.axes.x_mm = 5.0; })}) r.apply(b);
  r.apply(g1(1));
  CHECK(r.feed == 2.0);                           // a rapid does not use the inverse-time F
}

TEST_CASE("the program has ended after M2, M30, END PGM or FINI", "[modal]") {
  CHECK_FALSE(run({with([](block& b) { b.tool = 1; })}).ended);
  CHECK(run({with([](block& b) { b.program_end = "M30"; }), with([](block& b) { b.tool = 1; })}).ended);
}
