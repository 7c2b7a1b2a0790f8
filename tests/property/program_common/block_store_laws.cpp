// A block store gives back exactly the blocks put in, in order: every field, whatever is
// present, including strings with any bytes, extreme numbers, records across chunk ends, blocks
// of other files than the store's, and chunks spilled to its temporary file past a small budget.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/block_store.hpp>

namespace {

using namespace kin5::program;

/// Some value, or none.
template <class T>
std::optional<T> maybe(const rc::Gen<T>& g) {
  if (*rc::gen::inRange(0, 2) == 0) return std::nullopt;
  return *g;
}

/// Any finite double (`==` on blocks compares values, and NaN equals nothing).
rc::Gen<double> any_double() {
  return rc::gen::oneOf(rc::gen::map(rc::gen::arbitrary<double>(), [](double v) { return std::isfinite(v) ? v : 1.5; }),
                        rc::gen::element(0.0, -0.0, 1e9, -1e9, std::numeric_limits<double>::denorm_min(),
                                         std::numeric_limits<double>::max()));
}

rc::Gen<std::string> any_string() {
  return rc::gen::oneOf(rc::gen::arbitrary<std::string>(), rc::gen::container<std::string>(
                                                               *rc::gen::inRange(0, 300), rc::gen::arbitrary<char>()));
}

kin5::vec3 any_vec3() { return {*any_double(), *any_double(), *any_double()}; }

template <class E>
std::optional<E> maybe_element(std::initializer_list<E> values) {
  return maybe(rc::gen::elementOf(std::vector<E>(values)));
}

/// Every field of the state words, each present or not. The structured binding names every
/// field: one added to `state_words` stops this from compiling until it is drawn here.
state_words any_state() {
  state_words s;
  auto& [tool_change, tool_spindle_axis, tool_length_delta_mm, tool_radius_delta_mm, length_compensation,
         length_register, radius_compensation, radius_register, cutting_edge, spindle, coolant_flood, coolant_mist,
         work_offset, working_plane, distance, dwell_s, stop] = s;
  tool_change = *rc::gen::arbitrary<bool>();
  tool_spindle_axis = maybe_element({spindle_axis::x, spindle_axis::y, spindle_axis::z});
  tool_length_delta_mm = maybe(any_double());
  tool_radius_delta_mm = maybe(any_double());
  length_compensation = maybe(rc::gen::arbitrary<bool>());
  length_register = maybe(rc::gen::arbitrary<long long>());
  radius_compensation = maybe_element({cutter_side::off, cutter_side::left, cutter_side::right});
  radius_register = maybe(rc::gen::arbitrary<long long>());
  cutting_edge = maybe(rc::gen::arbitrary<long long>());
  spindle = maybe_element(
      {spindle_rotation::clockwise, spindle_rotation::counter_clockwise, spindle_rotation::stopped});
  coolant_flood = maybe(rc::gen::arbitrary<bool>());
  coolant_mist = maybe(rc::gen::arbitrary<bool>());
  if (*rc::gen::inRange(0, 2))
    work_offset = kin5::program::work_offset{
        *rc::gen::element(work_offset_family::g54, work_offset_family::extended, work_offset_family::siemens,
                          work_offset_family::preset),
        *rc::gen::arbitrary<int>()};
  working_plane = maybe_element({arc_plane::xy, arc_plane::zx, arc_plane::yz});
  distance = maybe_element({distance_mode::absolute, distance_mode::incremental});
  dwell_s = maybe(any_double());
  stop = maybe_element({program_stop::stop, program_stop::optional_stop});
  return s;
}

/// Every field of a block, each present or not. As in `any_state`, the structured binding names
/// every field of `block`.
block any_block(const std::string& file) {
  block b;
  auto& [where, call_chain, text, number, program_begin, program_end, comment, tcp, feed_mode, metric, tool, tool_name,
         spindle_rpm, m_codes, motion, axes, arc, feed, feed_rapid, machine_coordinates, machine_reference, kept_words, passthrough,
         framing, assignment, state, alarm] = b;
  // Mostly the store's file; now and then one a call ran, by name.
  const std::string in_file = *rc::gen::inRange(0, 4) ? file : *rc::gen::element<std::string>("sub.h", "L100.spf", "");
  where = {in_file, *rc::gen::inRange<std::size_t>(0, 1u << 31), *rc::gen::inRange<std::size_t>(0, 5000)};
  call_chain = *rc::gen::oneOf(rc::gen::just<std::uint32_t>(0), rc::gen::arbitrary<std::uint32_t>());
  text = *any_string();
  number = maybe(rc::gen::arbitrary<long long>());
  program_begin = maybe(any_string());
  program_end = maybe(any_string());
  comment = maybe(any_string());
  tcp = maybe(rc::gen::arbitrary<bool>());
  feed_mode = maybe_element({feed_unit::per_minute, feed_unit::inverse_time});
  metric = maybe(rc::gen::arbitrary<bool>());
  tool = maybe(rc::gen::arbitrary<long long>());
  tool_name = maybe(any_string());
  spindle_rpm = maybe(any_double());
  m_codes = *rc::gen::container<std::vector<int>>(*rc::gen::inRange(0, 4), rc::gen::arbitrary<int>());
  motion = maybe_element({motion_kind::rapid, motion_kind::linear, motion_kind::arc_cw, motion_kind::arc_ccw});
  auto& [x_mm, y_mm, z_mm, a_deg, b_deg, c_deg, tool_axis] = axes;
  x_mm = maybe(any_double());
  y_mm = maybe(any_double());
  z_mm = maybe(any_double());
  a_deg = maybe(any_double());
  b_deg = maybe(any_double());
  c_deg = maybe(any_double());
  if (*rc::gen::inRange(0, 2)) tool_axis = any_vec3();
  if (*rc::gen::inRange(0, 2)) {
    auto& [plane, centre_mm, radius_mm] = arc.emplace();
    plane = *rc::gen::element(arc_plane::xy, arc_plane::zx, arc_plane::yz);
    if (*rc::gen::inRange(0, 2)) centre_mm = any_vec3();
    radius_mm = maybe(any_double());
  }
  feed = maybe(any_double());
  feed_rapid = *rc::gen::arbitrary<bool>();
  machine_coordinates = *rc::gen::arbitrary<bool>();
  if (machine_coordinates)
    machine_reference = *rc::gen::element(machine_position::machine_zero, machine_position::reference_point,
                                          machine_position::second_reference, machine_position::stored_position,
                                          machine_position::second_stored_position, machine_position::tool_axis_limit,
                                          machine_position::builder_position);
  kept_words = *rc::gen::container<std::vector<std::string>>(*rc::gen::inRange(0, 4), any_string());
  passthrough = *rc::gen::arbitrary<bool>();
  framing = *rc::gen::arbitrary<bool>();
  assignment = *rc::gen::arbitrary<bool>();
  if (*rc::gen::inRange(0, 3)) state = any_state();  // often, but not always, empty
  if (*rc::gen::inRange(0, 2)) alarm = alarm_stop{*any_string(), maybe(rc::gen::arbitrary<long long>())};
  return b;
}

/// Doubles compared by their bits, so that -0.0 comes back as -0.0.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("replay gives back every block pushed, in order, field for field") {
  rc::prop("random blocks, some without their text; small chunks spilled past a small budget or none", [] {
    const std::string file = *any_string();
    const auto n = *rc::gen::inRange<std::size_t>(0, 60);
    std::vector<block> in;
    std::vector<bool> keep;
    const bool small = *rc::gen::arbitrary<bool>();
    block_store store(file, small ? 512 : block_store::default_chunk_bytes, small ? 256 : block_store::default_first_chunk_bytes);
    if (small) store.memory_bytes(*rc::gen::inRange<std::size_t>(0, 4096));
    for (std::size_t k = 0; k < n; ++k) {
      in.push_back(any_block(file));
      keep.push_back(*rc::gen::arbitrary<bool>());
      store.push(in.back(), keep.back());
    }
    RC_ASSERT(store.size() == n);
    RC_ASSERT(store.error().empty());
    for (int pass = 0; pass < 2; ++pass) {  // a replay leaves the store as it was
      std::size_t k = 0;
      RC_ASSERT(store.replay([&](const block& b) {
        RC_ASSERT(k < n);
        block expected = in[k];
        if (!keep[k]) expected.text.clear();
        RC_ASSERT(b == expected);
        if (b.axes.x_mm) RC_ASSERT(same_bits(*b.axes.x_mm, *expected.axes.x_mm));
        if (b.feed) RC_ASSERT(same_bits(*b.feed, *expected.feed));
        ++k;
      }));
      RC_ASSERT(k == n);
    }
  });
}

TEST_CASE("a store with a budget of a few KiB replays what an unbounded one does") {
  rc::prop("generated programs of motion blocks, called or not, in default chunks", [] {
    const auto n = *rc::gen::inRange<std::size_t>(0, 6000);
    block_store bounded("p.h"), unbounded("p.h");
    std::vector<block> in;
    bounded.memory_bytes(*rc::gen::inRange<std::size_t>(1, 8192));
    unbounded.memory_bytes(std::numeric_limits<std::size_t>::max());
    for (std::size_t k = 0; k < n; ++k) {
      block b;
      b.where = {k % 11 == 0 ? file_name() : k % 7 ? "p.h" : "sub.h", k + 1, 1};  // no name, too
      b.call_chain = static_cast<std::uint32_t>(k % 5);
      b.number = static_cast<long long>(k);
      b.motion = motion_kind::linear;
      b.axes.x_mm = *any_double(), b.axes.y_mm = static_cast<double>(k), b.axes.a_deg = *any_double();
      if (k % 3 == 0) b.comment = *any_string();
      bounded.push(b);
      unbounded.push(b);
      in.push_back(b);
    }
    RC_ASSERT(unbounded.spilled_chunks() == 0);
    RC_ASSERT(bounded.chunks() == unbounded.chunks());
    RC_ASSERT(bounded.chunks() <= 1 || bounded.spilled_chunks() == bounded.chunks() - 1);
    std::vector<block> expected;
    RC_ASSERT(unbounded.replay([&](const block& b) { expected.push_back(b); }));
    RC_ASSERT(expected == in);
    std::size_t k = 0;
    RC_ASSERT(bounded.replay([&](const block& b) {
      RC_ASSERT(k < expected.size());
      RC_ASSERT(b == expected[k]);
      ++k;
    }));
    RC_ASSERT(k == n);
  });
}

TEST_CASE("records that do not fit the rest of a chunk start a new one, however large") {
  block_store store("big.mpf");
  std::vector<block> in;
  for (std::size_t k = 0; k < 40; ++k) {  // 40 blocks of 100 kB of text: 4 MB over several chunks
    block b;
    b.where = {"big.mpf", k + 1, 1};
    b.text = std::string(100000 + k, static_cast<char>('a' + k % 26));
    b.number = static_cast<long long>(k);
    in.push_back(b);
    store.push(b);
  }
  block huge;  // larger than a chunk
  huge.where = {"big.mpf", 41, 1};
  huge.comment = std::string(3u << 20, 'x');
  in.push_back(huge);
  store.push(huge);
  std::size_t k = 0;
  store.replay([&](const block& b) { CHECK(b == in[k++]); });
  CHECK(k == in.size());
}

namespace {

/// A block whose record is exactly `bytes` long (at least the record of its empty comment):
/// a comment of the right length, found from the record size of the empty one.
block block_of_record_size(std::size_t bytes, std::size_t line) {
  block b;
  b.where = {"c.mpf", line, 1};
  b.comment = std::string();
  block_store probe("c.mpf");
  probe.push(b);
  const std::size_t empty = probe.bytes();  // the comment's size takes one byte in it
  if (bytes <= empty) return b;
  const auto leb = [](std::size_t n) {
    std::size_t k = 1;
    while (n >>= 7) ++k;
    return k;
  };
  std::size_t length = bytes - empty + 1;  // record = empty - 1 + leb(length) + length
  while (length > 0 && empty - 1 + leb(length) + length > bytes) --length;
  b.comment = std::string(length, 'c');
  return b;
}

}  // namespace

TEST_CASE("records of any size, on either side of every chunk boundary and in any order") {
  rc::prop("a small chunk; sizes relative to the space left, to the chunk, or small", [] {
    const auto chunk = *rc::gen::inRange<std::size_t>(40, 600);
    const auto first = *rc::gen::oneOf(rc::gen::inRange<std::size_t>(1, chunk + 1), rc::gen::just(chunk));
    const auto n = *rc::gen::inRange<std::size_t>(1, 40);
    block_store store("c.mpf", chunk, first);
    std::vector<block> in;
    // The store's rule as a model: a record that does not fit what is left of the last chunk
    // starts a new chunk, of max(next, record) bytes, where next is `first`, then doubles after
    // each chunk up to `chunk`.
    std::size_t chunks = 0, capacity = 0, used = 0, total = 0, next = first;
    for (std::size_t k = 0; k < n; ++k) {
      const auto d = *rc::gen::inRange<long>(-3, 4);
      const std::size_t left = chunks ? capacity - used : 0;
      const std::size_t base = *rc::gen::element(left, chunk, 2 * chunk, chunk / 2, std::size_t{0}, 5 * chunk);
      const auto wanted = static_cast<std::size_t>(std::max<long>(1, static_cast<long>(base) + d));
      in.push_back(block_of_record_size(wanted, k + 1));
      const std::size_t before = store.bytes();
      store.push(in.back());
      const std::size_t record = store.bytes() - before;
      if (chunks == 0 || capacity - used < record) {
        capacity = std::max(next, record), used = 0, ++chunks;
        next = std::min(chunk, 2 * next);
      }
      used += record;
      total += record;
      RC_ASSERT(store.chunks() == chunks);
    }
    RC_ASSERT(store.bytes() == total);
    std::size_t k = 0;
    store.replay([&](const block& b) {
      RC_ASSERT(k < in.size());
      RC_ASSERT(b == in[k]);
      ++k;
    });
    RC_ASSERT(k == in.size());
  });
}

TEST_CASE("a record larger than a chunk, then small ones: each after it starts a chunk of its own") {
  // The 1 MiB chunks of the tool: a 1.1 MB comment line first, then ordinary blocks.
  block_store store("y.mpf");
  std::vector<block> in;
  block huge;
  huge.where = {"y.mpf", 1, 1};
  huge.comment = std::string(1100000, 'c');
  in.push_back(huge);
  store.push(huge);
  CHECK(store.chunks() == 1);
  for (std::size_t k = 0; k < 3; ++k) {
    block b;
    b.where = {"y.mpf", k + 2, 1};
    b.axes.x_mm = static_cast<double>(k);
    b.comment = std::string(100, 'd');
    in.push_back(b);
    store.push(b);
  }
  CHECK(store.chunks() == 2);
  std::size_t k = 0;
  store.replay([&](const block& b) { CHECK(b == in[k++]); });
  CHECK(k == in.size());
}
