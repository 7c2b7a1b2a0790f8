// Canonical operations (program/canonical/): a block and its operations say the same, both ways.
// Blocks are drawn with every field (block_generators.hpp); operations are drawn kind by kind,
// every kind and every field, in the order of execution, as one block's. Then: block →
// operations → block is the identity; operations → block → operations is the identity; and
// any sequence that is not one block's (out of order, a kind twice, two moves, another origin,
// an operation against its own rule) is refused, never turned into a block that reads back
// otherwise.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <kin5/program/block.hpp>
#include <kin5/program/canonical/block_operations.hpp>
#include <kin5/program/canonical/print.hpp>

#include "block_generators.hpp"

namespace kin5::program::canonical {
/// An operation in a failed case's log, as `kin5 canon` prints it, after its line and column.
inline void showValue(const operation& op, std::ostream& os) {
  const source_location& at = origin_of(op).where;
  os << at.line << ":" << at.column << ": " << operation_printer().text(op);
}
}  // namespace kin5::program::canonical

namespace {

using namespace kin5::program;
using namespace kin5::test::blocks;
namespace can = kin5::program::canonical;

/// Whether `ops` begin with their block's start, share its origin and follow the order of
/// execution.
bool ordered(const std::vector<can::operation>& ops) {
  if (ops.empty() || !std::holds_alternative<can::block_start>(ops.front())) return false;
  for (std::size_t k = 1; k < ops.size(); ++k)
    if (ops[k].index() < ops[k - 1].index() || !(can::origin_of(ops[k]) == can::origin_of(ops.front()))) return false;
  return true;
}

/// Axis words with every field drawn, each present or not; `non_empty`: at least one.
axis_words any_axes(bool non_empty = false) {
  axis_words w;
  auto& [x_mm, y_mm, z_mm, a_deg, b_deg, c_deg, tool_axis] = w;
  x_mm = maybe(any_double()), y_mm = maybe(any_double()), z_mm = maybe(any_double());
  a_deg = maybe(any_double()), b_deg = maybe(any_double()), c_deg = maybe(any_double());
  if (*rc::gen::inRange(0, 2)) tool_axis = any_vec3();
  if (non_empty && w.empty()) x_mm = *any_double();
  return w;
}

arc_words any_circle() {
  arc_words a;
  auto& [plane, centre_mm, radius_mm] = a;
  plane = *rc::gen::element(arc_plane::xy, arc_plane::zx, arc_plane::yz);
  if (*rc::gen::inRange(0, 2)) centre_mm = any_vec3();
  radius_mm = maybe(any_double());
  return a;
}

/// Two optionals of which at least one is present.
template <class A, class B>
std::pair<std::optional<A>, std::optional<B>> one_or_both(const rc::Gen<A>& a, const rc::Gen<B>& b) {
  switch (*rc::gen::inRange(0, 3)) {
    case 0: return {*a, std::nullopt};
    case 1: return {std::nullopt, *b};
    default: return {*a, *b};
  }
}

/// The operations of one block, drawn kind by kind: each kind present or not (a maker's M
/// function and a kept word up to three times), every field drawn, at most one move, circle
/// data only beside a move that is no arc.
std::vector<can::operation> any_operations(const std::string& file) {
  const can::origin o{{file, *rc::gen::inRange<std::size_t>(0, 1u << 31), *rc::gen::inRange<std::size_t>(0, 5000)},
                     *rc::gen::oneOf(rc::gen::just<std::uint32_t>(0), rc::gen::arbitrary<std::uint32_t>())};
  std::vector<can::operation> ops;
  const auto some = [] { return *rc::gen::inRange(0, 3) == 0; };
  ops.push_back(can::block_start{o, maybe(rc::gen::arbitrary<long long>()), *any_string()});
  if (some()) ops.push_back(can::begin_program{o, *any_string()});
  if (some()) ops.push_back(can::comment{o, *any_string()});
  if (some()) ops.push_back(can::raise_alarm{o, alarm_stop{*any_string(), maybe(rc::gen::arbitrary<long long>())}});
  if (some()) ops.push_back(can::framing{o});
  if (some()) ops.push_back(can::pass_through{o});
  if (some()) ops.push_back(can::parameter_assignment{o});
  if (some()) ops.push_back(can::set_feed_mode{o, *rc::gen::element(feed_unit::per_minute, feed_unit::inverse_time)});
  if (some()) ops.push_back(can::set_feed_rate{o, *any_double()});
  if (some()) ops.push_back(can::rapid_feed{o});
  if (some()) ops.push_back(can::set_spindle_speed{o, *any_double()});
  if (some()) ops.push_back(can::select_tool{o, *rc::gen::arbitrary<long long>()});
  if (some()) ops.push_back(can::select_tool_by_name{o, *any_string()});
  if (some()) ops.push_back(can::change_tool{o});
  if (some()) ops.push_back(can::select_tool_axis{o, *rc::gen::element(spindle_axis::x, spindle_axis::y, spindle_axis::z)});
  if (some()) {
    const auto [length, radius] = one_or_both(any_double(), any_double());
    ops.push_back(can::set_tool_oversize{o, length, radius});
  }
  if (some())
    ops.push_back(can::set_spindle{o, *rc::gen::element(spindle_rotation::clockwise, spindle_rotation::counter_clockwise,
                                                        spindle_rotation::stopped)});
  if (some()) {
    const auto [flood, mist] = one_or_both(rc::gen::arbitrary<bool>(), rc::gen::arbitrary<bool>());
    ops.push_back(can::set_coolant{o, flood, mist});
  }
  for (int k = *rc::gen::inRange(0, 4); k > 0; --k) ops.push_back(can::machine_function{o, *rc::gen::arbitrary<int>()});
  if (some()) ops.push_back(can::dwell{o, *any_double()});
  if (some()) ops.push_back(can::select_plane{o, *rc::gen::element(arc_plane::xy, arc_plane::zx, arc_plane::yz)});
  if (some()) ops.push_back(can::use_length_units{o, *rc::gen::element(can::length_unit::mm, can::length_unit::inch)});
  if (some()) {
    const auto [side, number] = one_or_both(rc::gen::element(cutter_side::off, cutter_side::left, cutter_side::right),
                                            rc::gen::arbitrary<long long>());
    ops.push_back(can::set_radius_compensation{o, side, number});
  }
  if (some()) {
    const auto [on, number] = one_or_both(rc::gen::arbitrary<bool>(), rc::gen::arbitrary<long long>());
    ops.push_back(can::set_length_compensation{o, on, number});
  }
  if (some()) ops.push_back(can::select_cutting_edge{o, *rc::gen::arbitrary<long long>()});
  if (some()) ops.push_back(can::set_tool_tip_tracking{o, *rc::gen::arbitrary<bool>()});
  if (some())
    ops.push_back(can::select_work_offset{
        o, work_offset{*rc::gen::element(work_offset_family::g54, work_offset_family::extended,
                                         work_offset_family::siemens, work_offset_family::preset),
                       *rc::gen::arbitrary<int>()}});
  for (int k = *rc::gen::inRange(0, 4); k > 0; --k) ops.push_back(can::kept_word{o, *any_string()});
  if (some())
    ops.push_back(can::set_distance_mode{o, *rc::gen::element(distance_mode::absolute, distance_mode::incremental)});
  const int move = *rc::gen::inRange(0, 6);  // none, rapid, linear, arc, modal, machine
  if (move != 3 && some()) ops.push_back(can::arc_data{o, any_circle()});
  switch (move) {
    case 1: ops.push_back(can::rapid_move{o, any_axes()}); break;
    case 2: ops.push_back(can::linear_move{o, any_axes()}); break;
    case 3: {
      std::optional<arc_words> circle;
      if (*rc::gen::inRange(0, 2)) circle = any_circle();
      ops.push_back(can::arc_move{o, *rc::gen::arbitrary<bool>(), any_axes(), circle});
      break;
    }
    case 4: ops.push_back(can::modal_move{o, any_axes(true)}); break;
    case 5: {
      const std::optional<motion_kind> motion = maybe_element(
          {motion_kind::rapid, motion_kind::linear, motion_kind::arc_cw, motion_kind::arc_ccw});
      ops.push_back(can::machine_move{
          o,
          *rc::gen::element(machine_position::machine_zero, machine_position::reference_point,
                            machine_position::second_reference, machine_position::stored_position,
                            machine_position::second_stored_position, machine_position::builder_position,
                            machine_position::tool_axis_limit),
          motion, any_axes()});
      break;
    }
    default: break;
  }
  if (some()) ops.push_back(can::stop{o, *rc::gen::element(program_stop::stop, program_stop::optional_stop)});
  if (some()) ops.push_back(can::end_program{o, *any_string()});
  return ops;
}

}  // namespace

TEST_CASE("canonical operations: block, operations, block") {
  rc::prop("every field of any block comes back, from operations in the order of execution", [] {
    const block b = any_block(*any_string());
    const std::vector<can::operation> ops = can::operations_of(b);
    RC_ASSERT(ordered(ops));
    const std::optional<block> back = can::block_of(ops);
    RC_ASSERT(back.has_value());
    RC_ASSERT(*back == b);
  });
}

TEST_CASE("canonical operations: operations, block, operations") {
  rc::prop("one block's operations, every kind and field drawn, come back as they were", [] {
    const std::vector<can::operation> ops = any_operations(*any_string());
    const std::optional<block> b = can::block_of(ops);
    RC_ASSERT(b.has_value());
    RC_ASSERT(can::operations_of(*b) == ops);
  });
  rc::prop("operations that are not one block's are refused, never read back otherwise", [] {
    std::vector<can::operation> ops = any_operations(*any_string());
    const std::size_t n = ops.size();
    const auto at = [&] { return *rc::gen::inRange<std::size_t>(0, n); };
    switch (*rc::gen::inRange(0, 5)) {
      case 0: std::swap(ops[at()], ops[at()]); break;
      case 1: {
        const std::size_t k = at();
        ops.insert(ops.begin() + static_cast<std::ptrdiff_t>(k), ops[k]);
        break;
      }
      case 2: {
        can::operation& op = ops[at()];
        std::visit([](auto& o) { o.from.where.line += 1; }, op);
        break;
      }
      case 3: ops.erase(ops.begin() + static_cast<std::ptrdiff_t>(at())); break;
      default: {  // an operation against its own rule, or a second move
        const can::origin o = can::origin_of(ops.front());
        const can::operation odd = *rc::gen::element<can::operation>(
            can::set_coolant{o, {}, {}}, can::set_tool_oversize{o, {}, {}}, can::set_radius_compensation{o, {}, {}},
            can::set_length_compensation{o, {}, {}}, can::modal_move{o, {}}, can::linear_move{o, {}});
        const auto place = std::find_if(ops.begin(), ops.end(), [&](const can::operation& op) { return op.index() > odd.index(); });
        ops.insert(place, odd);
        break;
      }
    }
    if (const std::optional<block> b = can::block_of(ops)) RC_ASSERT(can::operations_of(*b) == ops);
  });
}

TEST_CASE("canonical operations: what is refused") {
  const can::origin o{{"t.ngc", 4, 1}};
  const can::operation start = can::block_start{o, 40, "N40 G1 X1 M8"};
  using ops = std::vector<can::operation>;
  axis_words x1;
  x1.x_mm = 1;
  CHECK(can::block_of(ops{start}).has_value());
  CHECK_FALSE(can::block_of(ops{}));
  CHECK_FALSE(can::block_of(ops{can::linear_move{o, {}}}));                                     // no block start
  CHECK_FALSE(can::block_of(ops{start, can::linear_move{o, {}}, can::set_coolant{o, true, {}}}));  // out of order
  CHECK_FALSE(can::block_of(ops{start, can::set_feed_rate{o, 1}, can::set_feed_rate{o, 2}}));      // F twice
  CHECK_FALSE(can::block_of(ops{start, can::linear_move{o, {}}, can::modal_move{o, x1}}));  // two moves
  CHECK_FALSE(can::block_of(ops{start, can::set_coolant{o, {}, {}}}));                          // says nothing
  CHECK_FALSE(can::block_of(ops{start, can::modal_move{o, {}}}));                               // moves nothing
  CHECK_FALSE(can::block_of(ops{start, can::arc_data{o, {}}, can::arc_move{o, true, {}, {}}}));  // circle data twice
  CHECK_FALSE(can::block_of(ops{start, can::set_feed_rate{{{"t.ngc", 5, 1}}, 1}}));              // another block's
  CHECK(can::block_of(ops{start, can::machine_function{o, 428}, can::machine_function{o, 428}}).has_value());
}

TEST_CASE("canonical operations: a block in the order of execution, and as text") {
  block b;  // LinuxCNC `N40 G21 G1 X1 Y2 A30 F200 S8000 T2 M6 M3 M8 (cut)`, as its reader gives it
  b.where = {"t.ngc", 4, 1};
  b.text = "N40 G21 G1 X1 Y2 A30 F200 S8000 T2 M6 M3 M8 (cut)";
  b.number = 40;
  b.metric = true;
  b.motion = motion_kind::linear;
  b.axes.x_mm = 1, b.axes.y_mm = 2, b.axes.a_deg = 30;
  b.feed = 200;
  b.spindle_rpm = 8000;
  b.tool = 2;
  b.state.tool_change = true;
  b.state.spindle = spindle_rotation::clockwise;
  b.state.coolant_flood = true;
  b.comment = "cut";
  std::vector<std::string> lines;
  can::operation_printer printer;
  for (const can::operation& op : can::operations_of(b)) lines.push_back(printer.text(op));
  CHECK(lines == std::vector<std::string>{"block_start N40 \"N40 G21 G1 X1 Y2 A30 F200 S8000 T2 M6 M3 M8 (cut)\"",
                                          "comment \"cut\"", "set_feed_rate 200mm/min", "set_spindle_speed 8000rpm",
                                          "select_tool 2", "change_tool", "set_spindle clockwise",
                                          "set_coolant flood=on", "use_length_units mm",
                                          "linear_move X=1mm Y=2mm A=30deg"});

  block arc;  // G93 G2 X1 Y0 I0.5 J0 F4 in inverse time
  arc.feed_mode = feed_unit::inverse_time;
  arc.feed = 4;
  arc.motion = motion_kind::arc_cw;
  arc.axes.x_mm = 1, arc.axes.y_mm = 0.1;
  arc.arc = arc_words{arc_plane::xy, kin5::vec3{0.5, 0, 0}, std::nullopt};
  lines.clear();
  for (const can::operation& op : can::operations_of(arc)) lines.push_back(printer.text(op));
  CHECK(lines == std::vector<std::string>{"block_start \"\"", "set_feed_mode inverse_time", "set_feed_rate 4/min",
                                          "arc_move clockwise X=1mm Y=0.1mm plane=xy centre=(0.5,0,0)mm"});
}
