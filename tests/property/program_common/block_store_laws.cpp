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

#include "block_generators.hpp"

namespace {

using namespace kin5::program;
using kin5::test::blocks::any_block;
using kin5::test::blocks::any_double;
using kin5::test::blocks::any_string;

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
