/// @file law_move.hpp
/// `law_move(x_mm, rotary)`: the feed move the per-pair reading laws put between the words they
/// test, `G1 X<x_mm> Y2.5 Z10 F500` as a block, with `B10 C20` when `rotary` (a B/C machine
/// under tool-tip tracking, for the laws that translate). The laws step `x_mm` by 1 per move, so
/// that every move goes somewhere and a lost or doubled move shows in the trace.
/// `tracking_start(from)`: what a translated law program opens with, tool 1 changed and
/// tool-tip tracking on with that tool's length (LinuxCNC says `G43` too: its reader refuses a
/// move under TCP kinematics without it).
#pragma once

#include <vector>

#include <kin5/program/block.hpp>
#include <kin5/program/dialect.hpp>

namespace kin5::test {

inline program::block law_move(double x_mm, bool rotary = false) {
  program::block b;
  b.motion = program::motion_kind::linear;
  b.axes.x_mm = x_mm, b.axes.y_mm = 2.5, b.axes.z_mm = 10;
  if (rotary) b.axes.b_deg = 10, b.axes.c_deg = 20;
  b.feed = 500;
  return b;
}

inline std::vector<program::block> tracking_start(program::dialect from) {
  program::block change, on;
  change.tool = 1;
  change.state.tool_change = true;
  on.tcp = true;
  if (from == program::id_of<program::linuxcnc::dialect>()) on.state.length_compensation = true;  // G43 M428
  return {change, on};
}

}  // namespace kin5::test
