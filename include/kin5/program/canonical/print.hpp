/// @file program/canonical/print.hpp
/// One line of text per canonical operation, for people (`kin5 canon`): its name, then its
/// values, each with its unit. Lengths are millimetres whatever the program's unit, angles
/// degrees, numbers in their shortest form that reads back to the same value, text quoted with
/// the bytes a terminal acts on written `\xHH` (printable.hpp).
/// @code
///   kin5::program::canonical::operation_printer p;
///   p.text(kin5::program::canonical::linear_move{{}, {.x_mm = 5, .a_deg = 30}});   // "linear_move X=5mm A=30deg"
/// @endcode
#pragma once

#include <charconv>
#include <string>
#include <string_view>
#include <variant>

#include "../printable.hpp"
#include "operation.hpp"

namespace kin5::program::canonical {

/// Writes operations as text, one at a time, in program order: it keeps the feed mode the
/// operations set (the unit of F) and the text of the block under way (what `framing`,
/// `pass_through` and `parameter_assignment` keep).
class operation_printer {
 public:
  /// `op` as one line without its end: "name value…".
  std::string text(const operation& op) {
    std::string out(name_of(op));
    std::visit([&](const auto& o) { values(o, out); }, op);
    return out;
  }

 private:
  feed_unit feed_mode_ = feed_unit::per_minute;
  std::string block_text_;

  static std::string number(double v) {
    char text[64];
    const auto r = std::to_chars(text, text + sizeof text, v);
    return std::string(text, r.ptr);
  }
  static std::string quoted(std::string_view s) {
    std::string out(1, '"');
    out += printable(s);
    out += '"';
    return out;
  }
  static void add(std::string& out, std::string_view word) { (out += ' ') += word; }
  static void add_length(std::string& out, std::string_view name, double mm) {
    add(out, std::string(name) + "=" + number(mm) + "mm");
  }
  static std::string vector_text(const vec3& v) {
    return "(" + number(v.x) + "," + number(v.y) + "," + number(v.z) + ")";
  }
  static void add_axes(std::string& out, const axis_words& w) {
    const std::optional<double> linear[] = {w.x_mm, w.y_mm, w.z_mm}, rotary[] = {w.a_deg, w.b_deg, w.c_deg};
    for (int k = 0; k < 3; ++k)
      if (linear[k]) add_length(out, std::string(1, "XYZ"[k]), *linear[k]);
    for (int k = 0; k < 3; ++k)
      if (rotary[k]) add(out, std::string(1, "ABC"[k]) + "=" + number(*rotary[k]) + "deg");
    if (w.tool_axis) add(out, "tool_axis=" + vector_text(*w.tool_axis));
  }
  static std::string_view plane_name(arc_plane p) { return p == arc_plane::xy ? "xy" : p == arc_plane::zx ? "zx" : "yz"; }
  static void add_circle(std::string& out, const arc_words& a) {
    add(out, "plane=" + std::string(plane_name(a.plane)));
    if (a.centre_mm) add(out, "centre=" + vector_text(*a.centre_mm) + "mm");
    if (a.radius_mm) add_length(out, "radius", *a.radius_mm);
  }
  static std::string_view motion_name(motion_kind k) {
    switch (k) {
      case motion_kind::rapid: return "rapid";
      case motion_kind::linear: return "linear";
      case motion_kind::arc_cw: return "arc_cw";
      case motion_kind::arc_ccw: return "arc_ccw";
    }
    return "";
  }
  static std::string_view position_name(machine_position p) {
    switch (p) {
      case machine_position::machine_zero: return "machine_zero";
      case machine_position::reference_point: return "reference_point";
      case machine_position::second_reference: return "second_reference";
      case machine_position::stored_position: return "stored_position";
      case machine_position::second_stored_position: return "second_stored_position";
      case machine_position::builder_position: return "builder_position";
      case machine_position::tool_axis_limit: return "tool_axis_limit";
    }
    return "";
  }
  static std::string on_off(bool on) { return on ? "on" : "off"; }

  void values(const block_start& o, std::string& out) {
    block_text_ = o.text;
    if (o.number) add(out, "N" + std::to_string(*o.number));
    add(out, quoted(o.text));
  }
  void values(const begin_program& o, std::string& out) { add(out, quoted(o.name)); }
  void values(const comment& o, std::string& out) { add(out, quoted(o.text)); }
  void values(const raise_alarm& o, std::string& out) {
    add(out, quoted(o.alarm.message));
    if (o.alarm.number) add(out, "number=" + std::to_string(*o.alarm.number));
  }
  void values(const framing&, std::string& out) { add(out, quoted(block_text_)); }
  void values(const pass_through&, std::string& out) { add(out, quoted(block_text_)); }
  void values(const parameter_assignment&, std::string& out) { add(out, quoted(block_text_)); }
  void values(const set_feed_mode& o, std::string& out) {
    feed_mode_ = o.mode;
    add(out, o.mode == feed_unit::per_minute ? "per_minute" : "inverse_time");
  }
  void values(const set_feed_rate& o, std::string& out) {
    add(out, number(o.per_min) + (feed_mode_ == feed_unit::per_minute ? "mm/min" : "/min"));
  }
  void values(const rapid_feed&, std::string&) {}
  void values(const set_spindle_speed& o, std::string& out) { add(out, number(o.rpm) + "rpm"); }
  void values(const select_tool& o, std::string& out) { add(out, std::to_string(o.number)); }
  void values(const select_tool_by_name& o, std::string& out) { add(out, quoted(o.name)); }
  void values(const change_tool&, std::string&) {}
  void values(const select_tool_axis& o, std::string& out) {
    add(out, o.axis == spindle_axis::x ? "X" : o.axis == spindle_axis::y ? "Y" : "Z");
  }
  void values(const set_tool_oversize& o, std::string& out) {
    if (o.length_delta_mm) add_length(out, "length", *o.length_delta_mm);
    if (o.radius_delta_mm) add_length(out, "radius", *o.radius_delta_mm);
  }
  void values(const set_spindle& o, std::string& out) {
    add(out, o.rotation == spindle_rotation::clockwise           ? "clockwise"
             : o.rotation == spindle_rotation::counter_clockwise ? "counter_clockwise"
                                                                 : "stopped");
  }
  void values(const set_coolant& o, std::string& out) {
    if (o.flood) add(out, "flood=" + on_off(*o.flood));
    if (o.mist) add(out, "mist=" + on_off(*o.mist));
  }
  void values(const machine_function& o, std::string& out) { add(out, "M" + std::to_string(o.number)); }
  void values(const dwell& o, std::string& out) { add(out, number(o.duration_s) + "s"); }
  void values(const select_plane& o, std::string& out) { add(out, plane_name(o.plane)); }
  void values(const use_length_units& o, std::string& out) { add(out, o.unit == length_unit::mm ? "mm" : "inch"); }
  void values(const set_radius_compensation& o, std::string& out) {
    if (o.side) add(out, *o.side == cutter_side::off ? "off" : *o.side == cutter_side::left ? "left" : "right");
    if (o.register_number) add(out, "register=" + std::to_string(*o.register_number));
  }
  void values(const set_length_compensation& o, std::string& out) {
    if (o.on) add(out, on_off(*o.on));
    if (o.register_number) add(out, "register=" + std::to_string(*o.register_number));
  }
  void values(const select_cutting_edge& o, std::string& out) { add(out, std::to_string(o.number)); }
  void values(const set_tool_tip_tracking& o, std::string& out) { add(out, on_off(o.on)); }
  void values(const select_work_offset& o, std::string& out) {
    const work_offset_family f = o.offset.family;
    add(out, f == work_offset_family::g54        ? "g54"
             : f == work_offset_family::extended ? "extended"
             : f == work_offset_family::siemens  ? "siemens"
                                                 : "preset");
    add(out, std::to_string(o.offset.number));
  }
  void values(const kept_word& o, std::string& out) { add(out, quoted(o.word)); }
  void values(const set_distance_mode& o, std::string& out) {
    add(out, o.mode == distance_mode::absolute ? "absolute" : "incremental");
  }
  void values(const arc_data& o, std::string& out) { add_circle(out, o.circle); }
  void values(const rapid_move& o, std::string& out) { add_axes(out, o.to); }
  void values(const linear_move& o, std::string& out) { add_axes(out, o.to); }
  void values(const arc_move& o, std::string& out) {
    add(out, o.clockwise ? "clockwise" : "counter_clockwise");
    add_axes(out, o.to);
    if (o.circle) add_circle(out, *o.circle);
  }
  void values(const modal_move& o, std::string& out) { add_axes(out, o.to); }
  void values(const machine_move& o, std::string& out) {
    add(out, position_name(o.reference));
    if (o.motion) add(out, motion_name(*o.motion));
    add_axes(out, o.to);
  }
  void values(const stop& o, std::string& out) { add(out, o.kind == program_stop::stop ? "always" : "optional"); }
  void values(const end_program& o, std::string& out) {
    if (!o.name.empty()) add(out, quoted(o.name));
  }
};

}  // namespace kin5::program::canonical
