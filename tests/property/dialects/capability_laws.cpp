// Each dialect's `capabilities` (program/dialect_id.hpp) checked against its writer and reader:
// a construct the dialect declares it can express is written so that its own reader reads it
// back; one it declares it cannot is refused with std::invalid_argument (tool-tip tracking
// switches are the exception: a dialect without them writes the rest and leaves a note). The
// translation trusts these flags, so a flag that lies fails here.
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <kin5/program/dialect.hpp>

#include "contracts.hpp"
#include "every_dialect.hpp"

namespace {

using namespace kin5::program;
using kin5::test::for_every_dialect;
using kin5::test::read_as;
using kin5::test::write_as;

block move(double x_mm, double y_mm, double z_mm, std::size_t line) {
  block b;
  b.where = {"in.nc", line, 1};
  b.motion = motion_kind::linear;
  b.axes.x_mm = x_mm, b.axes.y_mm = y_mm, b.axes.z_mm = z_mm;
  b.feed = 500;
  return b;
}

program of(std::vector<block> blocks) {
  program p;
  p.language = id_of<iso::dialect>();
  p.file = "in.nc";
  p.blocks = std::move(blocks);
  return p;
}

/// The blocks D reads back from what it wrote of `p`; nothing if its writer refused `p`.
template <class D>
std::optional<std::vector<block>> written_and_read(const program& p) {
  std::string text;
  try {
    text = write_as<D>(p);
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
  const read_result r = read_as<D>(text);
  INFO(text);
  REQUIRE(r.ok());
  return r.parsed.blocks;
}

template <class F>
bool any_block(const std::optional<std::vector<block>>& blocks, F&& f) {
  if (blocks)
    for (const block& b : *blocks)
      if (f(b)) return true;
  return false;
}

template <class D>
struct inverse_time_feed {
  static void check() {
    block b = move(1, 2, 3, 4);
    b.feed_mode = feed_unit::inverse_time;
    b.feed = 2.5;
    const auto back = written_and_read<D>(of({b}));
    CHECK(back.has_value() == D::can.inverse_time_feed);
    CHECK(any_block(back, [](const block& r) { return r.feed_mode == feed_unit::inverse_time && r.feed == 2.5; }) ==
          D::can.inverse_time_feed);
  }
};
const bool law_1 = for_every_dialect<inverse_time_feed>("capability: inverse-time feed", "[dialects][capabilities]");

template <class D>
struct rotary_axis_words {
  static void check() {
    block b = move(1, 2, 3, 4);
    b.axes.b_deg = 30;
    const auto back = written_and_read<D>(of({b}));
    CHECK(back.has_value() == D::can.rotary_axis_words);
    CHECK(any_block(back, [](const block& r) { return r.axes.b_deg == 30.0; }) == D::can.rotary_axis_words);
  }
};
const bool law_2 = for_every_dialect<rotary_axis_words>("capability: rotary axis words", "[dialects][capabilities]");

/// A move to (0, 0, 0), then a clockwise half circle to (10, 0, 0) about (5, 0, 0) in XY.
program half_circle() {
  block arc = move(10, 0, 0, 5);
  arc.motion = motion_kind::arc_cw;
  arc.arc = arc_words{arc_plane::xy, kin5::vec3{5, 0, 0}, std::nullopt};
  return of({move(0, 0, 0, 4), arc});
}

template <class D>
struct arcs {
  static void check() {
    const auto back = written_and_read<D>(half_circle());
    CHECK(back.has_value() == D::can.arcs);
    CHECK(any_block(back, [](const block& r) { return r.motion == motion_kind::arc_cw && r.axes.x_mm == 10.0; }) ==
          D::can.arcs);
  }
};
const bool law_3 = for_every_dialect<arcs>("capability: arcs", "[dialects][capabilities]");

template <class D>
struct arc_centre_block {
  static void check() {
    if (!D::can.arcs) return;
    const auto back = written_and_read<D>(half_circle());
    REQUIRE(back.has_value());
    // The centre is a block of its own only where the dialect says so: blocks of geometry are
    // counted, not the frame a writer puts around the program (`%`, `O0001`, `M30`, `%_N_…_MPF`).
    const auto blocks = std::count_if(back->begin(), back->end(), [](const block& r) { return r.moves() || r.arc; });
    CHECK((static_cast<std::size_t>(blocks) > half_circle().blocks.size()) == D::can.arc_centre_block);
  }
};
const bool law_4 = for_every_dialect<arc_centre_block>("capability: arc centre as a block", "[dialects][capabilities]");

/// A tool change: tracking needs a tool's length (ISO writes G43.4 with the tool's H, and its
/// reader refuses G43.4 without an H the program has said).
block change_to_tool_1() {
  block b;
  b.where = {"in.nc", 2, 1};
  b.tool = 1;
  b.state.tool_change = true;
  return b;
}

/// Tool-tip tracking switched on, then a move with a tool-axis vector.
program tracked_vector_move() {
  block on;
  on.where = {"in.nc", 3, 1};
  on.tcp = true;
  block b = move(1, 2, 3, 4);
  b.axes.tool_axis = kin5::vec3{0, 0.6, 0.8};
  return of({change_to_tool_1(), on, b});
}

template <class D>
struct tool_axis_vectors {
  static void check() {
    const auto back = written_and_read<D>(tracked_vector_move());
    CHECK(back.has_value() == D::can.tool_axis_vectors);
    CHECK(any_block(back, [](const block& r) { return r.axes.tool_axis == kin5::vec3{0, 0.6, 0.8}; }) ==
          D::can.tool_axis_vectors);
  }
};
const bool law_5 = for_every_dialect<tool_axis_vectors>("capability: tool-axis vectors", "[dialects][capabilities]");

template <class D>
struct tcp_switch {
  static void check() {
    block on;
    on.where = {"in.nc", 3, 1};
    on.tcp = true;
    const auto back = written_and_read<D>(of({change_to_tool_1(), on, move(1, 2, 3, 4)}));
    REQUIRE(back.has_value());  // never refused: without the words, the rest is written
    CHECK(any_block(back, [](const block& r) { return r.tcp == true; }) == D::can.tcp_switch);
  }
};
const bool law_6 = for_every_dialect<tcp_switch>("capability: tool-tip tracking switches", "[dialects][capabilities]");

template <class D>
struct cl_data {
  static void check() {
    block b = move(1, 2, 3, 4);
    b.axes.y_mm.reset(), b.axes.z_mm.reset();
    // Cutter-location data names the whole tool tip in every move; NC text may name one axis.
    CHECK(written_and_read<D>(of({b})).has_value() == !D::can.cl_data);
  }
};
const bool law_7 = for_every_dialect<cl_data>("capability: cutter-location data", "[dialects][capabilities]");

template <class D>
struct tool_names {
  static void check() {
    block change;
    change.where = {"in.nc", 2, 1};
    change.tool_name = "MILL_D10";
    change.state.tool_change = true;
    // A dialect that calls tools by name writes the name and reads it back; one that takes only
    // numbers refuses it (a number made up for it would call another tool).
    const auto back = written_and_read<D>(of({change, move(1, 2, 3, 4)}));
    CHECK(back.has_value() == D::can.tool_names);
    CHECK(any_block(back, [](const block& r) { return r.tool_name == "MILL_D10" && !r.tool; }) == D::can.tool_names);
  }
};
const bool law_8 = for_every_dialect<tool_names>("capability: tools called by name", "[dialects][capabilities]");

}  // namespace
