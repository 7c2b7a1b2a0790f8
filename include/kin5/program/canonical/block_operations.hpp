/// @file program/canonical/block_operations.hpp
/// A block as its canonical operations, and the operations of one block as the block:
/// `operations_of(b)` gives them in the order a control executes a block's words (the order of
/// `operation`'s alternatives, operation.hpp), each field of the block in exactly one operation;
/// `block_of(ops)` gives the block back. `block_of(operations_of(b)) == b` for every block whose
/// `machine_reference` is `machine_zero` outside machine coordinates (as block.hpp has it), and
/// `operations_of(*block_of(ops)) == ops` whenever `block_of` gives a block.
///
/// What a block says is what its text says: modal state is not applied (a block's `modal_move`
/// runs in the motion mode in effect; program/modal.hpp carries it).
/// @code
///   kin5::program::block b;                          // ISO `N10 G1 X5 F200 M8`
///   b.number = 10, b.motion = kin5::program::motion_kind::linear, b.axes.x_mm = 5, b.feed = 200;
///   b.state.coolant_flood = true;
///   auto ops = kin5::program::canonical::operations_of(b);
///   // block_start, set_feed_rate, set_coolant, linear_move
///   auto back = kin5::program::canonical::block_of(ops);   // *back == b
/// @endcode
#pragma once

#include <cstddef>
#include <iterator>
#include <optional>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "../../core/field_count.hpp"
#include "../block.hpp"
#include "operation.hpp"

namespace kin5::program::canonical {

// Every field of `block` is mapped: those of `origin_fields` to each operation's origin, these
// 25 to operations (`append_operations` and `detail::block_builder`): text, number,
// program_begin, program_end, comment, tcp, feed_mode, metric, tool, tool_name, spindle_rpm,
// m_codes, motion, axes, arc, feed, feed_rapid, machine_coordinates, machine_reference,
// kept_words, passthrough, framing, assignment, state, alarm. `axis_words`, `arc_words`,
// `work_offset` and `alarm_stop` go whole into the operations that hold them.
static_assert(field_count<block>() == std::tuple_size_v<decltype(origin_fields)> + 25,
              "a field of `block` has no canonical operation: map it in block_operations.hpp (a field every "
              "operation carries: a member of `origin` and a pair in `origin_fields`) and draw it in "
              "canonical_laws");
static_assert(field_count<origin>() == std::tuple_size_v<decltype(origin_fields)>,
              "every member of `origin` has its pair in `origin_fields`");
static_assert(field_count<state_words>() == 17,
              "a field of `state_words` has no canonical operation: map it in block_operations.hpp and draw it in "
              "canonical_laws");

/// The members of each operation that `append_operations` and `block_of` map, `from` included,
/// in the order of `operation`'s alternatives.
inline constexpr std::size_t operation_fields[] = {3, 2, 2, 2, 1, 1, 1, 2, 2, 1, 2, 2, 2, 1, 2, 3, 2, 3, 2,
                                                   2, 2, 2, 3, 3, 2, 2, 2, 2, 2, 2, 2, 2, 4, 2, 4, 2, 2};
static_assert(std::size(operation_fields) == operation_kinds, "every kind of operation has its count");
static_assert(
    []<std::size_t... k>(std::index_sequence<k...>) {
      return ((field_count<std::variant_alternative_t<k, operation>>() == operation_fields[k]) && ...);
    }(std::make_index_sequence<operation_kinds>{}),
    "a member of an operation has no mapping: map it in append_operations and block_of, count it in "
    "operation_fields and draw it in canonical_laws");

/// Appends the operations of `b` to `out`, in the order of execution (operation.hpp).
inline void append_operations(const block& b, std::vector<operation>& out) {
  const origin o = origin_of(b);
  const state_words& s = b.state;
  out.push_back(block_start{o, b.number, b.text});
  if (b.program_begin) out.push_back(begin_program{o, *b.program_begin});
  if (b.comment) out.push_back(comment{o, *b.comment});
  if (b.alarm) out.push_back(raise_alarm{o, *b.alarm});
  if (b.framing) out.push_back(framing{o});
  if (b.passthrough) out.push_back(pass_through{o});
  if (b.assignment) out.push_back(parameter_assignment{o});
  if (b.feed_mode) out.push_back(set_feed_mode{o, *b.feed_mode});
  if (b.feed) out.push_back(set_feed_rate{o, *b.feed});
  if (b.feed_rapid) out.push_back(rapid_feed{o});
  if (b.spindle_rpm) out.push_back(set_spindle_speed{o, *b.spindle_rpm});
  if (b.tool) out.push_back(select_tool{o, *b.tool});
  if (b.tool_name) out.push_back(select_tool_by_name{o, *b.tool_name});
  if (s.tool_change) out.push_back(change_tool{o});
  if (s.tool_spindle_axis) out.push_back(select_tool_axis{o, *s.tool_spindle_axis});
  if (s.tool_length_delta_mm || s.tool_radius_delta_mm)
    out.push_back(set_tool_oversize{o, s.tool_length_delta_mm, s.tool_radius_delta_mm});
  if (s.spindle) out.push_back(set_spindle{o, *s.spindle});
  if (s.coolant_flood || s.coolant_mist) out.push_back(set_coolant{o, s.coolant_flood, s.coolant_mist});
  for (int m : b.m_codes) out.push_back(machine_function{o, m});
  if (s.dwell_s) out.push_back(dwell{o, *s.dwell_s});
  if (s.working_plane) out.push_back(select_plane{o, *s.working_plane});
  if (b.metric) out.push_back(use_length_units{o, *b.metric ? length_unit::mm : length_unit::inch});
  if (s.radius_compensation || s.radius_register)
    out.push_back(set_radius_compensation{o, s.radius_compensation, s.radius_register});
  if (s.length_compensation || s.length_register)
    out.push_back(set_length_compensation{o, s.length_compensation, s.length_register});
  if (s.cutting_edge) out.push_back(select_cutting_edge{o, *s.cutting_edge});
  if (b.tcp) out.push_back(set_tool_tip_tracking{o, *b.tcp});
  if (s.work_offset) out.push_back(select_work_offset{o, *s.work_offset});
  for (const std::string& w : b.kept_words) out.push_back(kept_word{o, w});
  if (s.distance) out.push_back(set_distance_mode{o, *s.distance});
  const bool arc = !b.machine_coordinates && (b.motion == motion_kind::arc_cw || b.motion == motion_kind::arc_ccw);
  if (b.arc && !arc) out.push_back(arc_data{o, *b.arc});
  if (b.machine_coordinates) {
    out.push_back(machine_move{o, b.machine_reference, b.motion, b.axes});
  } else if (b.motion) {
    switch (*b.motion) {
      case motion_kind::rapid: out.push_back(rapid_move{o, b.axes}); break;
      case motion_kind::linear: out.push_back(linear_move{o, b.axes}); break;
      case motion_kind::arc_cw:
      case motion_kind::arc_ccw: out.push_back(arc_move{o, *b.motion == motion_kind::arc_cw, b.axes, b.arc}); break;
    }
  } else if (!b.axes.empty()) {
    out.push_back(modal_move{o, b.axes});
  }
  if (s.stop) out.push_back(stop{o, *s.stop});
  if (b.program_end) out.push_back(end_program{o, *b.program_end});
}

/// The operations of `b`, in the order of execution (operation.hpp).
inline std::vector<operation> operations_of(const block& b) {
  std::vector<operation> out;
  append_operations(b, out);
  return out;
}

namespace detail {
/// Puts one operation into the block it builds; false when the operation breaks its own rule
/// (an empty `modal_move`, a `set_coolant` that says nothing, …) or says a field the block has
/// already (circle data beside an arc's own).
struct block_builder {
  block& b;
  bool operator()(const block_start& o) {
    b.number = o.number, b.text = o.text;
    return true;
  }
  bool operator()(const begin_program& o) { return b.program_begin = o.name, true; }
  bool operator()(const comment& o) { return b.comment = o.text, true; }
  bool operator()(const raise_alarm& o) { return b.alarm = o.alarm, true; }
  bool operator()(const framing&) { return b.framing = true; }
  bool operator()(const pass_through&) { return b.passthrough = true; }
  bool operator()(const parameter_assignment&) { return b.assignment = true; }
  bool operator()(const set_feed_mode& o) { return b.feed_mode = o.mode, true; }
  bool operator()(const set_feed_rate& o) { return b.feed = o.per_min, true; }
  bool operator()(const rapid_feed&) { return b.feed_rapid = true; }
  bool operator()(const set_spindle_speed& o) { return b.spindle_rpm = o.rpm, true; }
  bool operator()(const select_tool& o) { return b.tool = o.number, true; }
  bool operator()(const select_tool_by_name& o) { return b.tool_name = o.name, true; }
  bool operator()(const change_tool&) { return b.state.tool_change = true; }
  bool operator()(const select_tool_axis& o) { return b.state.tool_spindle_axis = o.axis, true; }
  bool operator()(const set_tool_oversize& o) {
    b.state.tool_length_delta_mm = o.length_delta_mm, b.state.tool_radius_delta_mm = o.radius_delta_mm;
    return o.length_delta_mm || o.radius_delta_mm;
  }
  bool operator()(const set_spindle& o) { return b.state.spindle = o.rotation, true; }
  bool operator()(const set_coolant& o) {
    b.state.coolant_flood = o.flood, b.state.coolant_mist = o.mist;
    return o.flood || o.mist;
  }
  bool operator()(const machine_function& o) { return b.m_codes.push_back(o.number), true; }
  bool operator()(const dwell& o) { return b.state.dwell_s = o.duration_s, true; }
  bool operator()(const select_plane& o) { return b.state.working_plane = o.plane, true; }
  bool operator()(const use_length_units& o) { return b.metric = o.unit == length_unit::mm, true; }
  bool operator()(const set_radius_compensation& o) {
    b.state.radius_compensation = o.side, b.state.radius_register = o.register_number;
    return o.side || o.register_number;
  }
  bool operator()(const set_length_compensation& o) {
    b.state.length_compensation = o.on, b.state.length_register = o.register_number;
    return o.on || o.register_number;
  }
  bool operator()(const select_cutting_edge& o) { return b.state.cutting_edge = o.number, true; }
  bool operator()(const set_tool_tip_tracking& o) { return b.tcp = o.on, true; }
  bool operator()(const select_work_offset& o) { return b.state.work_offset = o.offset, true; }
  bool operator()(const kept_word& o) { return b.kept_words.push_back(o.word), true; }
  bool operator()(const set_distance_mode& o) { return b.state.distance = o.mode, true; }
  bool operator()(const arc_data& o) { return b.arc = o.circle, true; }
  bool operator()(const rapid_move& o) { return move(motion_kind::rapid, o.to); }
  bool operator()(const linear_move& o) { return move(motion_kind::linear, o.to); }
  bool operator()(const arc_move& o) {
    if (b.arc) return false;  // circle data said twice
    b.arc = o.circle;
    return move(o.clockwise ? motion_kind::arc_cw : motion_kind::arc_ccw, o.to);
  }
  bool operator()(const modal_move& o) { return b.axes = o.to, !o.to.empty(); }
  bool operator()(const machine_move& o) {
    b.machine_coordinates = true, b.machine_reference = o.reference, b.motion = o.motion, b.axes = o.to;
    return true;
  }
  bool operator()(const stop& o) { return b.state.stop = o.kind, true; }
  bool operator()(const end_program& o) { return b.program_end = o.name, true; }

  bool move(motion_kind kind, const axis_words& to) {
    b.motion = kind, b.axes = to;
    return true;
  }
};
}  // namespace detail

/// The block whose operations `ops` are, or nothing when they are not one block's: they must
/// begin with its `block_start`, share its origin, follow the order of execution (operation.hpp)
/// with each kind at most once (`machine_function` and `kept_word` once per word), hold at most
/// one move, and keep each operation's own rule (motion.hpp, tool.hpp, machine.hpp).
inline std::optional<block> block_of(std::span<const operation> ops) {
  if (ops.empty() || !std::holds_alternative<block_start>(ops.front())) return std::nullopt;
  block b;
  const origin& from = origin_of(ops.front());
  place_origin(b, from);
  detail::block_builder builder{b};
  std::size_t last = 0;
  bool moved = false;
  for (std::size_t k = 0; k < ops.size(); ++k) {
    const operation& op = ops[k];
    const std::size_t kind = op.index();
    const bool repeats = std::holds_alternative<machine_function>(op) || std::holds_alternative<kept_word>(op);
    if (k > 0 && (kind < last || (kind == last && !repeats))) return std::nullopt;
    if (is_move(op) && std::exchange(moved, true)) return std::nullopt;
    if (!(origin_of(op) == from) || !std::visit(builder, op)) return std::nullopt;
    last = kind;
  }
  return b;
}

}  // namespace kin5::program::canonical
