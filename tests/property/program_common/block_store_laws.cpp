// A block store gives back exactly the blocks put in, in order: every field, whatever is
// present, including strings with any bytes, extreme numbers and records across chunk ends.
#include <cmath>
#include <cstring>
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

block any_block(const std::string& file) {
  block b;
  b.where = {file, *rc::gen::inRange<std::size_t>(0, 1u << 31), *rc::gen::inRange<std::size_t>(0, 5000)};
  b.text = *any_string();
  b.number = maybe(rc::gen::arbitrary<long long>());
  b.program_begin = maybe(any_string());
  b.program_end = maybe(any_string());
  b.comment = maybe(any_string());
  b.tcp = maybe(rc::gen::arbitrary<bool>());
  b.feed_mode = maybe(rc::gen::element(feed_unit::per_minute, feed_unit::inverse_time));
  b.metric = maybe(rc::gen::arbitrary<bool>());
  b.tool = maybe(rc::gen::arbitrary<long long>());
  b.spindle_rpm = maybe(any_double());
  b.m_codes = *rc::gen::container<std::vector<int>>(*rc::gen::inRange(0, 4), rc::gen::arbitrary<int>());
  b.motion = maybe(rc::gen::element(motion_kind::rapid, motion_kind::linear, motion_kind::arc_cw, motion_kind::arc_ccw));
  b.axes.x_mm = maybe(any_double());
  b.axes.y_mm = maybe(any_double());
  b.axes.z_mm = maybe(any_double());
  b.axes.a_deg = maybe(any_double());
  b.axes.b_deg = maybe(any_double());
  b.axes.c_deg = maybe(any_double());
  if (*rc::gen::inRange(0, 2)) b.axes.tool_axis = any_vec3();
  if (*rc::gen::inRange(0, 2)) {
    arc_words arc;
    arc.plane = *rc::gen::element(arc_plane::xy, arc_plane::zx, arc_plane::yz);
    if (*rc::gen::inRange(0, 2)) arc.centre_mm = any_vec3();
    arc.radius_mm = maybe(any_double());
    b.arc = arc;
  }
  b.feed = maybe(any_double());
  b.feed_rapid = *rc::gen::arbitrary<bool>();
  b.machine_coordinates = *rc::gen::arbitrary<bool>();
  b.kept_words = *rc::gen::container<std::vector<std::string>>(*rc::gen::inRange(0, 4), any_string());
  b.passthrough = *rc::gen::arbitrary<bool>();
  return b;
}

/// Doubles compared by their bits, so that -0.0 comes back as -0.0.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("replay gives back every block pushed, in order, field for field") {
  rc::prop("random blocks, some without their text", [] {
    const std::string file = *any_string();
    const auto n = *rc::gen::inRange<std::size_t>(0, 60);
    std::vector<block> in;
    std::vector<bool> keep;
    block_store store(file);
    for (std::size_t k = 0; k < n; ++k) {
      in.push_back(any_block(file));
      keep.push_back(*rc::gen::arbitrary<bool>());
      store.push(in.back(), keep.back());
    }
    RC_ASSERT(store.size() == n);
    std::size_t k = 0;
    store.replay([&](const block& b) {
      RC_ASSERT(k < n);
      block expected = in[k];
      if (!keep[k]) expected.text.clear();
      RC_ASSERT(b == expected);
      if (b.axes.x_mm) RC_ASSERT(same_bits(*b.axes.x_mm, *expected.axes.x_mm));
      if (b.feed) RC_ASSERT(same_bits(*b.feed, *expected.feed));
      ++k;
    });
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
