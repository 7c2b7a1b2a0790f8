/// @file translate/cl_target.hpp
/// The target side for APT CL data (`reverse`): each motion block becomes one
/// GOTO/x,y,z,i,j,k with the tool tip and tool axis of its source step, in the source
/// workpiece frame (CL data names no machine, so there is no setup and nothing to plan). F is
/// kept: CL feed is tool-tip feed, and an inverse-time F (G93) stays one, `FEDRAT/INVERS`: each
/// GOTO is the whole of its source block, so 1/(block time) means the same time. TCP switches
/// become comments (CL data is tool-tip data). An arc keeps its plane, direction and centre (found
/// from a signed radius where the source gives one: `arc_centre_mm`), which the APT writer
/// writes as CIRCLE and the GOTO of its end. A rotary sweep of 180° or more under tool-tip
/// tracking, which one GOTO cannot say, becomes GOTO points along it (`swept_into`). Blocks that
/// are not motion are copied, their dialect text carried over (`carry_over.hpp`).
/// @code
///   kin5::translate_detail::cl_target target(source_language);
///   target.write(block, step, result, emit, on_report);  // GOTO/tip_source_mm, u_source
/// @endcode
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "../kinematics/matchability.hpp"
#include "../program/block.hpp"
#include "../program/modal.hpp"
#include "carry_over.hpp"
#include "options.hpp"
#include "source_walk.hpp"

namespace kin5::translate_detail {

/// The target side for APT CL data: GOTO/x,y,z,i,j,k per motion block (no planning).
class cl_target {
 public:
  static constexpr bool plans_with_tool_axis = false;  // `plan` is empty; `write` writes the axis
  explicit cl_target(program::dialect source_language) : source_language_(source_language) {}

  void set_tool_axis_tolerance(radians) {}  // nothing to reach: CL data names no machine
  void set_placement(const std::optional<run_inputs>&, tool_lengths = {}) {}  // no slides either
  void plan(const source_step&) {}
  void finish_plan() {}

  /// Second pass: block `b` (whose step is `s`) → `emit`; reports to `on_report`.
  template <class Emit, class Report>
  void write(const program::block& b, const source_step& s, translation& out, Emit&& emit, Report&& on_report) {
    if (s.what == source_step::kind::failed) return;
    if (s.what == source_step::kind::passthrough) {
      emit(carried_over(b, source_language_, program::cl_data_dialect()));
      if (!b.framing) ++out.passed_through;  // a tape mark: the writer frames its own program
      return;
    }
    if (s.what == source_step::kind::machine || s.positioning) {
      out.errors.push_back(at(b, std::string(program::machine_position_name(b.machine_reference)) +
                                     " has no APT form: GOTO points are the part's, and GOHOME is the FROM point in "
                                     "APT but the machine's home (every axis) to many posts, so no statement says "
                                     "it; translate to an NC dialect instead"));
      return;
    }
    program::block o = b;
    carry_over(o, source_language_, program::cl_data_dialect());
    if (o.tcp) {  // CL data is tool-tip data: tracking is implied
      if (!o.comment) o.comment = *o.tcp ? "tool-tip tracking on" : "tool-tip tracking off";
      o.tcp.reset();
    }
    if (b.feed_mode) source_inverse_time_ = *b.feed_mode == program::feed_unit::inverse_time;
    if (s.what == source_step::kind::copy) {
      o.arc.reset();
      if (o.feed_mode) inverse_time_ = *o.feed_mode == program::feed_unit::inverse_time;
      else if (o.feed) restore_unit(o, std::nullopt);
      emit(std::move(o));
      return;
    }
    block_report report{b.where, s.principal ? matchability::direct : matchability::other_branch, {}, {}, {}, 0.0};
    report.call_chain = b.call_chain;
    if (!s.principal) report.why = "the source pose is on the second solution branch of the source machine (K3)";
    on_report(std::move(report));
    if (program::is_arc(s.motion) && !arc_into(o, b, s, out)) return;
    // A rotary feed move read as machine coordinates: each piece keeps its share of the block's
    // time T, (K15) = Tian et al. 2010, eq. (20), as FEDRAT/INVERS n/T (its tip may stand still).
    const bool timed = s.rotary_moves && !s.rapid;
    if (timed && !s.block_time_min) {
      out.errors.push_back(at(b, "feed move without tool-tip tracking whose rotary axes move: its time is not known"));
      return;
    }
    if (!s.sweep.empty() && !s.untracked && !swept_into(b, s, out, emit)) return;
    const double pieces_per_min = timed ? double(s.pieces.size() + 1) / *s.block_time_min : 0.0;
    for (const tool_pose& piece : s.pieces) {  // the pieces before the block's end
      program::block p;
      p.where = b.where;
      p.motion = s.rapid ? program::motion_kind::rapid : program::motion_kind::linear;
      p.axes.x_mm = piece.tip_mm.x, p.axes.y_mm = piece.tip_mm.y, p.axes.z_mm = piece.tip_mm.z;
      p.axes.tool_axis = piece.axis;
      if (timed) feed_in(p, pieces_per_min, program::feed_unit::inverse_time);
      ++out.blocks_added;
      emit(std::move(p));
    }
    o.text.clear();
    o.axes = {};
    o.axes.x_mm = s.tip_source_mm.x, o.axes.y_mm = s.tip_source_mm.y, o.axes.z_mm = s.tip_source_mm.z;
    o.axes.tool_axis = s.u_source;
    o.motion = program::is_arc(s.motion) ? s.motion : s.rapid ? program::motion_kind::rapid : program::motion_kind::linear;
    if (s.rapid) o.feed.reset();
    o.feed_mode.reset();
    if (swept_inverse_per_min_) feed_in(o, *swept_inverse_per_min_, program::feed_unit::inverse_time);
    swept_inverse_per_min_.reset();
    if (timed) feed_in(o, pieces_per_min, program::feed_unit::inverse_time);
    else if (!s.rapid) restore_unit(o, s.feed_mm_per_min);
    emit(std::move(o));
  }

 private:
  program::dialect source_language_;
  bool inverse_time_ = false;         // FEDRAT/INVERS in effect in the output
  bool source_inverse_time_ = false;  // and in the source

  std::optional<double> swept_inverse_per_min_;  // the F of the end of a swept block in inverse time

  /// A sweep of the source (`source_step::sweep`: a rotary axis turning by 180° or more under
  /// tool-tip tracking), which one GOTO cannot say (its tool axis would turn the least way, a
  /// full turn not at all): a GOTO at each sample before the block's end, the tip where the
  /// control has it then, on the straight line from the start at the same fraction, each piece
  /// at the block's F (CL feed is tip feed), or in inverse time with its share of the block's
  /// time, n/T. False, with an error at block `b`, when its start is not known or it also says
  /// words whose moment among the pieces would be a guess.
  template <class Emit>
  bool swept_into(const program::block& b, const source_step& s, translation& out, Emit& emit) {
    const char* words = words_of_a_whole_block(b);
    if (!s.start_source_mm || words || program::is_arc(s.motion)) {
      out.errors.push_back(at(b, std::string("rotary sweep of 180° or more, which APT CL data says only as GOTO points "
                                             "along it, ") +
                                     (words ? std::string("in a block that also says ") + words + ": give it a block of its own"
                                      : program::is_arc(s.motion) ? "in a circular move"
                                                                  : "from an unknown start point")));
      return false;
    }
    const double n = double(s.sweep.size() + 1);
    const bool inverse = !s.rapid && s.feed_mode == program::feed_unit::inverse_time;
    if (inverse && !(b.feed && *b.feed > 0.0)) {
      out.errors.push_back(at(b, "inverse-time rotary sweep without its own F: the time of its GOTO points is not known"));
      return false;
    }
    for (std::size_t j = 0; j < s.sweep.size(); ++j) {
      const vec3 tip_mm = *s.start_source_mm + (double(j + 1) / n) * (s.tip_source_mm - *s.start_source_mm);
      program::block p;
      p.where = b.where;
      p.motion = s.rapid ? program::motion_kind::rapid : program::motion_kind::linear;
      p.axes.x_mm = tip_mm.x, p.axes.y_mm = tip_mm.y, p.axes.z_mm = tip_mm.z;
      p.axes.tool_axis = s.sweep[j];
      if (inverse) feed_in(p, n * *b.feed, program::feed_unit::inverse_time);
      ++out.blocks_added;
      emit(std::move(p));
    }
    if (inverse) swept_inverse_per_min_ = n * *b.feed;
    return true;
  }

  /// The arc of motion step `s` into `o` (the source frame is CL data's): plane and centre, the
  /// centre of a signed radius found from its start and end; false, with an error at block `b`,
  /// when the radius cannot reach the end.
  static bool arc_into(program::block& o, const program::block& b, const source_step& s, translation& out) {
    const auto centre = s.start_source_mm ? arc_centre_mm(s.arc_source, *s.start_source_mm, s.tip_source_mm) : std::nullopt;
    if (!centre) {
      out.errors.push_back(at(b, "circular move whose centre cannot be found (a radius shorter than half the chord)"));
      return false;
    }
    o.arc = program::arc_words{s.arc_source.plane, *centre, std::nullopt};
    return true;
  }

  /// The source's feed unit again in `o` after pieces in inverse time: said, with its F (`per_minute`,
  /// the F in effect per minute, when `o` has none).
  void restore_unit(program::block& o, std::optional<double> per_minute) {
    if (inverse_time_ == source_inverse_time_) return;
    if (!o.feed) o.feed = per_minute;
    if (o.feed) feed_in(o, *o.feed, source_inverse_time_ ? program::feed_unit::inverse_time : program::feed_unit::per_minute);
  }

  /// F `f` in unit `u` in block `p`, the unit said when it changes.
  void feed_in(program::block& p, double f, program::feed_unit u) {
    p.feed = f;
    const bool inverse = u == program::feed_unit::inverse_time;
    if (inverse != inverse_time_) p.feed_mode = u, inverse_time_ = inverse;
  }
};

}  // namespace kin5::translate_detail
