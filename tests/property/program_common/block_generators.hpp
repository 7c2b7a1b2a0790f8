/// @file block_generators.hpp
/// RapidCheck generators of blocks with every field drawn (block.hpp, state_words.hpp), each
/// present or not: strings with any bytes, extreme numbers. Structured bindings name every
/// field, so a field added to `block` or `state_words` stops these from compiling until it is
/// drawn here. Used by the block store's laws and the canonical operations' laws.
#pragma once

#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include <kin5/program/block.hpp>

namespace kin5::test::blocks {

using namespace kin5::program;

/// Some value, or none.
template <class T>
std::optional<T> maybe(const rc::Gen<T>& g) {
  if (*rc::gen::inRange(0, 2) == 0) return std::nullopt;
  return *g;
}

/// Any finite double (`==` on blocks compares values, and NaN equals nothing).
inline rc::Gen<double> any_double() {
  return rc::gen::oneOf(rc::gen::map(rc::gen::arbitrary<double>(), [](double v) { return std::isfinite(v) ? v : 1.5; }),
                        rc::gen::element(0.0, -0.0, 1e9, -1e9, std::numeric_limits<double>::denorm_min(),
                                         std::numeric_limits<double>::max()));
}

inline rc::Gen<std::string> any_string() {
  return rc::gen::oneOf(rc::gen::arbitrary<std::string>(), rc::gen::container<std::string>(
                                                               *rc::gen::inRange(0, 300), rc::gen::arbitrary<char>()));
}

inline kin5::vec3 any_vec3() { return {*any_double(), *any_double(), *any_double()}; }

template <class E>
std::optional<E> maybe_element(std::initializer_list<E> values) {
  return maybe(rc::gen::elementOf(std::vector<E>(values)));
}

/// Every field of the state words, each present or not. The structured binding names every
/// field: one added to `state_words` stops this from compiling until it is drawn here.
inline state_words any_state() {
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
inline block any_block(const std::string& file) {
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

}  // namespace kin5::test::blocks
