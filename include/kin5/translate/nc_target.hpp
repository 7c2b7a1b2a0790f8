/// @file translate/nc_target.hpp
/// The target side for an NC machine `to` (a `machine_model` value), in two passes over the
/// source steps:
///
///     plan:  u_target = target_T_source.map_direction(u_source)   → rotary_planner_values
///     write: tip_target_mm = target_T_source.map_point(tip_source_mm),
///            the planned angles of `to` (degrees), F by the feed policy → one output block
///
/// Arcs are written in the plane the setup maps theirs onto (direction flipped when its normal
/// lands on a negative axis), or refused; plane words G17–G19 are mapped the same way. A block
/// the target cannot reach is an error with its gap; a branch switch, and a rotary axis swinging
/// round for little change of the tool axis (past a pole), are warnings with the angle, poles included. Blocks that are not
/// motion are copied, their dialect text carried over (`carry_over.hpp`).
/// @code
///   kin5::translate_detail::nc_target target(To::model, target_T_source, kin5::feed_policy::tcp,
///                                            from_dialect, to_dialect, false);
///   for (const auto& s : steps) target.plan(s);
///   target.finish_plan();
///   for (std::size_t k = 0; k < blocks.size(); ++k) target.write(blocks[k], steps[k], result, emit, on_report);
/// @endcode
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "../core/rigid.hpp"
#include "../kinematics/branch_plan.hpp"
#include "../kinematics/inverse_pose.hpp"
#include "../program/block.hpp"
#include "../program/modal.hpp"
#include "carry_over.hpp"
#include "feed.hpp"
#include "machine_output.hpp"
#include "options.hpp"
#include "rotary_move.hpp"
#include "slide_travel.hpp"
#include "source_walk.hpp"

namespace kin5::translate_detail {

/// The target side for an NC machine `to`: branch choice over the program (first pass), then
/// feed and output blocks (second pass).
class nc_target {
 public:
  static constexpr bool plans_with_tool_axis = true;  // `plan` needs it; `write` uses the planned angles
  /// `switch_tcp_on`: switch tool-tip tracking on in the first motion block and off at the
  /// program end (`post`, whose CL input has no TCP words).
  nc_target(const machine_model& to, const rigid_transform& target_T_source, feed_policy feed,
            program::dialect source_language, program::dialect output_language, bool switch_tcp_on)
      : to_(to),
        target_T_source_(target_T_source),
        feed_(feed),
        source_language_(source_language),
        output_language_(output_language),
        switch_tcp_on_(switch_tcp_on),
        planner_(to) {}

  /// A tool axis this close to the target's reach, or a planned angle this far past a travel limit,
  /// counts as on the edge (angle_tolerance.hpp); before the first `plan`.
  void set_tool_axis_tolerance(radians tolerance) {
    inverse_options options;
    const radians at_least{tolerance.value > 1e-9 ? tolerance.value : 1e-9};  // inverse's own rounding
    options.reach_tolerance = at_least;
    options.travel_slack = at_least;
    reach_tolerance_ = travel_slack_ = at_least;
    planner_ = rotary_planner_values(to_, options);
  }

  /// Where the part sits and the tool lengths: each block's slides are then checked against the
  /// target's linear travel (`common_options::placement`), with the length of the tool in effect
  /// (tool_lengths.hpp); before the first `write`.
  void set_placement(const std::optional<run_inputs>& placement, tool_lengths lengths = {}) {
    placement_ = placement;
    lengths_ = tool_length_tracker(std::move(lengths), "--tool-length");
  }

  /// Motion as TCP or in machine coordinates (`mode`, else the dialect's; machine coordinates
  /// need the placement), pieces within `tolerance_mm`; after `set_placement`.
  void set_output(std::optional<output_mode> mode, double tolerance_mm) {
    machine_mode_ = mode.value_or(default_output_mode(output_language_)) == output_mode::machine && placement_;
    if (machine_mode_)
      machine_ = machine_writer(to_, *placement_, tolerance_mm, supports_inverse_time(output_language_),
                                feed_ == feed_policy::inverse_time);
  }

  /// Cutter radius compensation in effect at block `b`, kept only where the target offsets the
  /// same contour (docs/dialects/compensation.md): the setup turns about Z only (so the plane and
  /// the side stay), and motion is written as the tool tip, not in machine coordinates. False,
  /// with an error at the block, when refused.
  bool compensation_kept(const program::block& b, const source_step& s, translation& out) const {
    const char* why = norm(target_T_source_.map_direction(unit_z) - unit_z) > 1e-9
                          ? "the setup between the machines turns the XY plane (the side is kept only by a setup "
                            "turning about Z)"
                      : machine_mode_ && s.what == source_step::kind::motion
                          ? "motion written in machine coordinates (--output-mode machine) has no contour to offset"
                          : nullptr;
    if (why) out.errors.push_back(at(b, std::string("cutter radius compensation: ") + why));
    return why == nullptr;
  }

  /// First pass: the step of every block, in order. With each tool axis the planner is told
  /// the source's angles where they are the target's (`source_angles`) and the source's sweep.
  void plan(const source_step& s) {
    if (s.what != source_step::kind::motion) return;
    const double n = double(s.pieces.size() + 1);
    for (std::size_t k = 0; k < s.pieces.size(); ++k) {
      const vec3 u_target = normalized(target_T_source_.map_direction(s.pieces[k].axis));
      planner_.add(u_target, {source_angles(s, double(k + 1) / n, u_target), {}});
    }
    const vec3 u_target = normalized(target_T_source_.map_direction(s.u_source));
    sweep_target_.clear();
    for (const vec3& u_source : s.sweep) sweep_target_.push_back(normalized(target_T_source_.map_direction(u_source)));
    planner_.add(u_target, {source_angles(s, 1.0, u_target), sweep_target_});
  }
  void finish_plan() { path_ = planner_.finish(); }

  /// Second pass: block `b` (whose step is `s`) → `emit`; reports to `on_report`.
  template <class Emit, class Report>
  void write(const program::block& read, const source_step& s, translation& out, Emit&& emit, Report&& on_report) {
    if (s.what == source_step::kind::failed) return;
    // CL data: the FEDRAT/INVERS in effect is each feed move's own F, as inverse time in NC needs.
    const bool cl_source = program::capabilities_of(source_language_).cl_data;
    std::optional<program::block> timed;
    if (cl_source && s.what == source_step::kind::motion && !s.rapid &&
        s.feed_mode == program::feed_unit::inverse_time && !read.feed && s.feed_inverse_per_min)
      timed = read, timed->feed = s.feed_inverse_per_min;
    const program::block& b = timed ? *timed : read;
    if (s.what == source_step::kind::passthrough) {
      emit(carried_over(b, source_language_, output_language_));
      if (!b.framing) ++out.passed_through;  // a tape mark: the writer frames its own program
      machine_.forget();
      return;
    }
    if (s.what == source_step::kind::machine) return write_machine_move(b, s, out, emit);
    if (s.positioning) return write_positioning(b, s, out, emit, on_report);
    if (s.compensated && !compensation_kept(b, s, out)) return;
    if (program::changes_tool(b) || s.length_entry != length_entry_) tool_changed_ = true, length_entry_ = s.length_entry;
    if (placement_ && s.what == source_step::kind::motion && !tool_length_at(b, s, out)) return;
    program::block o = b;
    if (auto error = map_plane_words(o, target_T_source_.rotation)) {
      out.errors.push_back(at(b, *error));
      return;
    }
    carry_over(o, source_language_, output_language_);
    if (b.feed_mode) source_inverse_time_ = *b.feed_mode == program::feed_unit::inverse_time;
    if (cl_source && source_inverse_time_ && s.what == source_step::kind::copy) o.feed.reset();  // on each move
    if (source_inverse_time_ && !supports_inverse_time(output_language_)) {
      // Each move's time is kept by a per-minute F (write_feed); G93 itself has no equivalent,
      // and an F without a move takes effect on the next move, where it is converted.
      if (o.feed_mode == program::feed_unit::inverse_time) o.feed_mode.reset();
      if (s.what == source_step::kind::copy) o.feed.reset();
    }
    if (s.what == source_step::kind::copy) {
      write_copy(b, s, std::move(o), out, emit);
      return;
    }
    if (restate_motion_ && !o.motion) o.motion = s.motion;  // after the rapid of a machine move
    restate_motion_ = false;
    if (machine_mode_) return write_machine(b, s, std::move(o), out, emit, on_report);
    write_motion(b, s, std::move(o), out, emit, on_report);
  }

 private:
  machine_model to_;
  rigid_transform target_T_source_;
  feed_policy feed_;
  program::dialect source_language_, output_language_;
  bool switch_tcp_on_;
  rotary_planner_values planner_;
  rotary_path_values path_;
  radians reach_tolerance_{1e-9}, travel_slack_{1e-9};  // the planner's (set_tool_axis_tolerance)
  std::optional<run_inputs> placement_;
  bool machine_mode_ = false;  // motion written in machine coordinates (machine_output.hpp)
  bool length_switched_on_ = false;  // machine coordinates: length compensation said for `post`
  machine_writer machine_;
  tool_length_tracker lengths_;
  std::optional<long long> length_entry_;  // the tool-table entry in effect (source_step::length_entry)
  bool tool_changed_ = false;              // since the last motion written in machine coordinates
  bool output_inverse_time_ = false, tcp_switched_on_ = false, inverse_time_error_ = false;
  bool output_tcp_ = false;  // tool-tip tracking on in the output after the last block written
  bool restate_feed_ = false;  // the F in effect in the output is a piece's, not the program's
  bool source_inverse_time_ = false;  // G93 (FEDRAT/INVERS) in effect in the source
  std::optional<std::size_t> previous_motion_;  // motion index of the last written motion
  int branch_off_pole_ = -1;                    // branch of the last written motion off a pole
  source_step previous_step_;                   // its step
  std::size_t next_motion_ = 0;                 // motion index of the next motion block

  std::vector<vec3> sweep_target_;  // the sweep of the block planned last, target frame
  bool restate_motion_ = false;     // a move in machine coordinates wrote a motion word of its own

  /// Block `b`'s words other than its move, for a move in machine coordinates of the target:
  /// machine zero (the target's G53, SUPA, M91), no source M91 / M92, and no G91 of a `G91 G28`
  /// (the target's move is absolute); the motion said (rapid, or a feed move at the F in effect).
  program::block machine_block(const program::block& b, const source_step& s) const {
    program::block o = b;
    o.text.clear();
    o.axes = {};
    o.arc.reset();
    o.machine_coordinates = true;
    o.machine_reference = program::machine_position::machine_zero;
    std::erase_if(o.m_codes, [](int m) { return m == 91 || m == 92; });
    if (o.state.distance == program::distance_mode::incremental) o.state.distance.reset();
    carry_over(o, source_language_, output_language_);
    o.motion = s.rapid ? program::motion_kind::rapid : program::motion_kind::linear;
    o.feed_rapid = false;
    if (!s.rapid) o.feed = s.feed_mm_per_min;
    return o;
  }

  /// The linear words of `o` for machine step `s` (block `b`): each axis at the target's home
  /// plus the source's distance from its own, within the target's travel; false, with an error,
  /// when a home is not known or the place is past the travel.
  bool linear_from_homes(const program::block& b, const source_step& s, program::block& o, translation& out) const {
    std::optional<double>* words[3] = {&o.axes.x_mm, &o.axes.y_mm, &o.axes.z_mm};
    for (std::size_t i = 0; i < 3; ++i) {
      if (!s.from_home_mm[i]) continue;
      const linear_axis& axis = to_.linear(i);
      const char letter = to_char(axis.letter);
      if (!axis.home_mm) {
        out.errors.push_back(at(b, std::string(program::machine_position_name(b.machine_reference)) + " of " + letter +
                                       " needs the target machine's home of " + letter + ": give home_mm in [linear." +
                                       letter + "] of its machine file (--to-file; docs/machine-files.md)"));
        return false;
      }
      const double value = *axis.home_mm + *s.from_home_mm[i];
      if (!axis.travel.contains(value, inverse_options{}.linear_slack_mm)) {
        out.errors.push_back(at(b, std::string(to_.geometry.id) + " cannot reach this move in machine coordinates: " +
                                       letter + "=" + fixed(value, 3) + " (" + fixed(*s.from_home_mm[i], 3) +
                                       " mm from its home) is outside its travel [" + fixed(axis.travel.lower_mm, 3) +
                                       ", " + fixed(axis.travel.upper_mm, 3) + "] mm"));
        return false;
      }
      *words[i] = value;
    }
    return true;
  }

  /// A move of the linear axes in machine coordinates (machine_moves.hpp): each axis at the
  /// target's home plus the source's distance from its own, within the target's travel.
  template <class Emit>
  void write_machine_move(const program::block& b, const source_step& s, translation& out, Emit&& emit) {
    if (!s.rapid && (feed_ == feed_policy::inverse_time || output_inverse_time_)) {
      out.errors.push_back(at(b, std::string(program::machine_position_name(b.machine_reference)) +
                                     " at a feed per minute is not written in inverse time (G93): write it at rapid"));
      return;
    }
    program::block o = machine_block(b, s);
    if (s.to_limit) {  // along the tool axis: Z to the top of its travel where the tool stands along Z
      if (tool_along_z()) {
        o.axes.z_mm = to_.linear(2).travel.upper_mm;
      } else {  // only M140 MB MAX says it: a block of M functions
        o.machine_reference = program::machine_position::tool_axis_limit;
        o.motion.reset();
      }
      restate_motion_ = true;
      machine_.forget();
      return emit(std::move(o));
    }
    if (!linear_from_homes(b, s, o, out)) return;
    if (!s.rapid) restate_feed_ = true;
    restate_motion_ = true;
    machine_.forget();
    emit(std::move(o));
  }

  /// Whether the target's tool stands along its Z slide, up: no head turns it (or the heads'
  /// angles written last leave it there) and the tool and Z point along the machine's +Z.
  bool tool_along_z() const {
    if (norm(to_.tool_reference() - unit_z) > 1e-12 || norm(to_.linear(2).direction - unit_z) > 1e-12) return false;
    bool heads = false;
    for (std::size_t i = 0; i < to_.rotary_count; ++i) heads = heads || to_.rotary(i).side == mount::head;
    if (!heads) return true;
    if (!previous_motion_ || !path_.angles[*previous_motion_]) return false;
    const kin5::rotary_values& angles = *path_.angles[*previous_motion_];
    return norm(heads_carry(to_, angles, unit_z) - heads_carry(to_, angles, vec3{}) - unit_z) <= 1e-9;
  }

  /// A rotary positioning in machine coordinates of the retracted tool (`source_step::positioning`):
  /// the target's planned angles for the same tool axis, no tip, no path to check.
  template <class Emit, class Report>
  void write_positioning(const program::block& b, const source_step& s, translation& out, Emit&& emit,
                         Report&& on_report) {
    const std::size_t j = next_motion_++;
    if (!report_motion(b, s, j, out, on_report)) return;
    program::block o = machine_block(b, s);
    o.machine_coordinates = b.machine_coordinates;  // `G0 B30 C45` stays a move of the part's frame
    if (!linear_from_homes(b, s, o, out)) return;   // `G91 G28 X0 Y0 B0`: X and Y home as it turns
    for (std::size_t i = 0; i < to_.rotary_count; ++i)
      rotary_word(o.axes, to_.rotary(i).letter) = to_degrees((*path_.angles[j])[i]).value;
    previous_motion_ = j;
    previous_step_ = s;
    restate_motion_ = true;
    machine_.forget();
    emit(std::move(o));
  }

  /// The source's commanded angles at fraction `t` of motion step `s` (1: its end; between, the
  /// control's linear move from its start), as the target's angles, when they are the target's:
  /// the target names the same axes in the same order, the angles lie within its travel (one
  /// within the slack past a limit taken as on it), and they give its tool axis `u_target` there. A target whose axes are the source's then runs
  /// the source's own moves, branch and sweeps included.
  std::optional<kin5::rotary_values> source_angles(const source_step& s, double t, const vec3& u_target) const {
    if (s.rotary_count != to_.rotary_count || (t < 1.0 && !s.rotary_start_deg)) return std::nullopt;
    kin5::rotary_values angles{};
    for (std::size_t i = 0; i < to_.rotary_count; ++i) {
      if (s.rotary_letters[i] != to_char(to_.rotary(i).letter)) return std::nullopt;
      const double start_deg = s.rotary_start_deg ? (*s.rotary_start_deg)[i] : 0.0;
      angles[i] = to_radians(degrees{t < 1.0 ? start_deg + t * (s.rotary_source_deg[i] - start_deg) : s.rotary_source_deg[i]});
      const rotary_travel& travel = to_.rotary(i).travel;
      if (!travel.contains(angles[i], travel_slack_)) return std::nullopt;
      if (!travel.continuous)  // within the slack past a limit: on it, as `inverse` clamps
        angles[i] = radians{std::clamp(angles[i].value, to_radians(travel.lower).value, to_radians(travel.upper).value)};
    }
    if (!(angle_between(tool_axis(to_, angles), u_target).value <= reach_tolerance_.value)) return std::nullopt;
    return angles;
  }

  /// A block that is not motion: an arc centre on its own is mapped; feed and TCP words follow
  /// the policy.
  template <class Emit>
  void write_copy(const program::block& b, const source_step& s, program::block&& o, translation& out, Emit&& emit) {
    if (machine_mode_) machine_writer::without_tcp(o), o.feed.reset(), o.feed_mode.reset();
    if (b.arc && b.arc->centre_mm) {  // an arc centre on its own (Heidenhain CC)
      const vec3 centre_source_mm = s.untracked ? *s.arc_source.centre_mm : *b.arc->centre_mm;
      if (machine_mode_ && !machine_.last()) {
        out.errors.push_back(at(b, "circle centre in machine coordinates while the rotary axes' position is not known"));
        return;
      }
      const rigid_transform frame_T_source =
          machine_mode_ ? program_T_work(to_, machine_.last()->angles, machine_.placement()) * target_T_source_
                        : target_T_source_;
      const auto mapped = principal_plane(frame_T_source.rotation * plane_normal(b.arc->plane));
      if (!mapped) {
        out.errors.push_back(at(b, "circular move cannot be mapped: plane " + std::string(plane_name(b.arc->plane)) +
                                       " has no principal image on the target"));
        return;
      }
      o.arc->plane = mapped->first;
      o.arc->centre_mm = frame_T_source.map_point(centre_source_mm);
      if (!program::capabilities_of(output_language_).arc_centre_block) {  // arcs carry their own centre: a note
        const vec3 centre_target_mm = *o.arc->centre_mm;
        if (!o.comment)
          o.comment = "circle centre X" + fixed(centre_target_mm.x, 3) + " Y" + fixed(centre_target_mm.y, 3) + " Z" +
                      fixed(centre_target_mm.z, 3);
        o.arc.reset();
      }
    }
    if (feed_ == feed_policy::inverse_time && b.feed_mode != program::feed_unit::inverse_time) {
      o.feed.reset();
      o.feed_mode.reset();
    }
    if (feed_ == feed_policy::inverse_time && o.feed_mode) output_inverse_time_ = true;  // a G93 of its own
    if (tcp_switched_on_ && output_tcp_ && b.program_end && !o.tcp) o.tcp = false;
    if (o.tcp) output_tcp_ = *o.tcp;
    emit(std::move(o));
  }

  /// Tool-tip tracking of motion block `o` (step `s`) in the output: on for a block written as TCP
  /// that the source did not track (`post`'s CL data, motion read as machine coordinates or at
  /// the source's zero pose).
  void switch_tcp(const source_step& s, program::block& o) {
    if (switch_tcp_on_ || s.untracked || s.zero_pose) {
      if (output_tcp_) o.tcp.reset();
      else o.tcp = true, tcp_switched_on_ = true;
      output_tcp_ = true;
    } else if (o.tcp) {
      output_tcp_ = *o.tcp;
    }
  }

  /// A motion block: the planned angles, the mapped tip (or arc), the feed.
  template <class Emit, class Report>
  void write_motion(const program::block& b, const source_step& s, program::block&& o, translation& out, Emit&& emit,
                    Report&& on_report) {
    const std::size_t first = next_motion_;
    next_motion_ += s.pieces.size() + 1;
    const std::size_t j = next_motion_ - 1;  // the block's end; its pieces come before it
    for (std::size_t k = 0; k < s.pieces.size(); ++k)
      if (!piece_reachable(b, s, first + k, s.pieces[k].tip_mm, out)) return;
    if (!report_motion(b, s, j, out, on_report)) return;
    // Under --feed inverse-time the output's feed mode is the policy's, never the source's word:
    // a source G94 beside the G93 feed would read the time's inverse as mm/min.
    if (feed_ == feed_policy::inverse_time) o.feed_mode.reset();
    for (std::size_t k = 0; k < s.pieces.size(); ++k) write_piece(b, s, k, first + k, o, out, emit);
    const kin5::rotary_values& angles_target = *path_.angles[j];
    const vec3 tip_target_mm = target_T_source_.map_point(s.tip_source_mm);
    std::array<double, 2> angles_target_deg{};
    for (std::size_t i = 0; i < to_.rotary_count; ++i) angles_target_deg[i] = to_degrees(angles_target[i]).value;

    o.text.clear();
    o.axes = {};
    switch_tcp(s, o);
    if (program::is_arc(s.motion)) {
      if (!write_arc(b, s, angles_target, target_T_source_, o, out)) return;
    } else {
      o.axes.x_mm = tip_target_mm.x, o.axes.y_mm = tip_target_mm.y, o.axes.z_mm = tip_target_mm.z;
      for (std::size_t i = 0; i < to_.rotary_count; ++i) rotary_word(o.axes, to_.rotary(i).letter) = angles_target_deg[i];
    }
    if (!s.pieces.empty()) o.number.reset(), o.comment.reset(), o.feed_mode.reset();  // on the first piece
    if (s.rotary_moves && s.block_time_min) {
      const vec3 start_target_mm = target_T_source_.map_point(
          s.pieces.empty() ? *s.start_source_mm : s.pieces.back().tip_mm);
      o.feed.reset();
      piece_feed(b, s, s.pieces.size() + 1, tip_target_mm - start_target_mm, j, o, out);
      restate_feed_ = true;  // the next block at the program's F says it again
    } else {
      if (restate_feed_ && feed_ == feed_policy::tcp && !s.rapid && !o.feed && s.feed_mm_per_min)
        o.feed = *s.feed_mm_per_min;
      write_feed(b, s, tip_target_mm, angles_target_deg, o, out);
      if (!s.rapid && o.feed) restate_feed_ = false;
    }
    warn_rotary_move(b, j, out);
    previous_motion_ = j;
    previous_step_ = s;
    emit(std::move(o));
  }

  /// A motion block in machine coordinates (machine_output.hpp): each pose it reaches (its
  /// source pieces' ends, then its own) from the pose written last, in the pieces (G10) needs,
  /// each with its share of the block's time.
  template <class Emit, class Report>
  void write_machine(const program::block& b, const source_step& s, program::block&& o, translation& out, Emit&& emit,
                     Report&& on_report) {
    const std::size_t first = next_motion_, count = s.pieces.size() + 1;
    next_motion_ += count;
    for (std::size_t k = 0; k + 1 < count; ++k)
      if (!piece_reachable(b, s, first + k, s.pieces[k].tip_mm, out)) return;
    if (!report_motion(b, s, first + count - 1, out, on_report)) return;
    o.text.clear();
    machine_writer::without_tcp(o);
    if (switch_tcp_on_ && !length_switched_on_) o.state.length_compensation = true;  // post: the tool's length
    length_switched_on_ = true;
    if (tool_changed_ && !s.rapid && machine_.last() && *path_.angles[first] != machine_.last()->angles)
      return out.errors.push_back(at(b, std::string(machine_after_tool_change)));
    if (!s.start_source_mm || tool_changed_) machine_.forget();  // from where a tool change left the axes
    tool_changed_ = false;
    const bool from_known = machine_.last().has_value();
    const std::optional<double> time_min = from_known ? machine_time(b, s, out) : std::nullopt;
    if (!s.rapid && !time_min && from_known) return;  // refused
    if (program::is_arc(s.motion)) return write_machine_arc(b, s, std::move(o), first, out, emit);
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t j = first + k;
      const written_pose pose{target_T_source_.map_point(k + 1 < count ? s.pieces[k].tip_mm : s.tip_source_mm),
                              *path_.angles[j]};
      const auto n = machine_.pieces_to(pose);
      const char* words = n && *n > 1 ? words_of_a_whole_block(b) : nullptr;
      if (!n || words)
        return out.errors.push_back(at(b, !n ? std::string(machine_too_many) : std::string(machine_whole_block) + words));
      for (std::size_t i = 1; i <= *n; ++i) {
        const bool end = k + 1 == count && i == *n;
        program::block p;
        if (end) p = std::move(o);
        else p.where = b.where, p.motion = s.motion, p.feed_rapid = s.rapid && b.feed_rapid, p.number = o.number,
             p.comment = o.comment, o.number.reset(), o.comment.reset();  // the first piece's
        machine_.piece(p, pose, i, *n, time_min ? std::optional<double>(*time_min / double(count)) : std::nullopt,
                       s.feed_mm_per_min, s.rapid);
        const vec3 xyz_mm{*p.axes.x_mm, *p.axes.y_mm, *p.axes.z_mm};
        if (auto past = slides_past_travel(axes_for_untracked_point(to_, xyz_mm, machine_.placement())))
          return out.errors.push_back(at(b, std::string(to_.geometry.id) + " cannot reach a piece of this block (" +
                                                angles_text(s) + "): " + past->why));
        if (!end) ++out.blocks_added;
        emit(std::move(p));
      }
      warn_rotary_move(b, j, out);
      previous_motion_ = j;
      machine_.arrive(pose);
    }
    previous_step_ = s;
  }

  /// An arc in machine coordinates: at fixed angles the program point is a rigid map of the tip,
  /// so the arc is mapped like the setup's (its plane through the map) and keeps its F.
  template <class Emit>
  void write_machine_arc(const program::block& b, const source_step& s, program::block&& o, std::size_t j,
                         translation& out, Emit&& emit) {
    const kin5::rotary_values& angles = *path_.angles[j];
    o.axes = {};
    if (!write_arc(b, s, angles, program_T_work(to_, angles, machine_.placement()) * target_T_source_, o, out)) return;
    const bool inverse = s.feed_mode == program::feed_unit::inverse_time;
    machine_.keep_feed(o, inverse ? b.feed : s.feed_mm_per_min, s.feed_mode);
    warn_rotary_move(b, j, out);
    previous_motion_ = j;
    previous_step_ = s;
    machine_.arrive({target_T_source_.map_point(s.tip_source_mm), angles});
    emit(std::move(o));
  }

  /// The target's tool length at motion block `b` (step `s`) into the placement: the length of
  /// the tool in effect (tool_lengths.hpp); false, with an error, when it is not known.
  bool tool_length_at(const program::block& b, const source_step& s, translation& out) {
    std::string why;
    const auto length = lengths_.length_mm(s.length_entry, why);
    if (!length) {
      out.errors.push_back(at(b, "the target's tool length: " + why));
      return false;
    }
    placement_->tool_length_mm = *length;
    machine_.set_tool_length(*length);
    return true;
  }

  /// The time (min) of feed move `b` (step `s`) on the source: its own in inverse time, the
  /// (K16) time of a block read as machine coordinates, else its tip path over F. Empty for a
  /// rapid or a move from an unknown start; empty, with an error, when F is not known.
  std::optional<double> machine_time(const program::block& b, const source_step& s, translation& out) const {
    if (s.rapid || !s.start_source_mm) return std::nullopt;
    if (s.feed_mode == program::feed_unit::inverse_time) {
      if (b.feed && *b.feed > 0.0) return 1.0 / *b.feed;
      out.errors.push_back(at(b, "inverse-time feed move without its own F: its time is not known"));
      return std::nullopt;
    }
    if (s.block_time_min) return s.block_time_min;
    const double length = path_length(s);
    if (s.feed_mm_per_min && *s.feed_mm_per_min > 0.0) return length / *s.feed_mm_per_min;
    out.errors.push_back(at(b, "feed move at no known feed: its time in machine coordinates is not known"));
    return std::nullopt;
  }

  /// Piece `k` (motion `j`) of subdivided block `b`, before its end: a straight move of the tip,
  /// the first with the block's comment and number, each with its share of the block's time.
  template <class Emit>
  void write_piece(const program::block& b, const source_step& s, std::size_t k, std::size_t j,
                   const program::block& whole, translation& out, Emit&& emit) {
    program::block p;
    p.where = b.where;
    p.motion = s.motion;
    p.feed_rapid = s.rapid && b.feed_rapid;
    if (k == 0) p.number = whole.number, p.comment = whole.comment, p.feed_mode = whole.feed_mode;
    switch_tcp(s, p);
    const vec3 tip_target_mm = target_T_source_.map_point(s.pieces[k].tip_mm);
    p.axes.x_mm = tip_target_mm.x, p.axes.y_mm = tip_target_mm.y, p.axes.z_mm = tip_target_mm.z;
    for (std::size_t i = 0; i < to_.rotary_count; ++i)
      rotary_word(p.axes, to_.rotary(i).letter) = to_degrees((*path_.angles[j])[i]).value;
    const vec3 start_target_mm = target_T_source_.map_point(k == 0 ? *s.start_source_mm : s.pieces[k - 1].tip_mm);
    if (!s.rapid) piece_feed(b, s, s.pieces.size() + 1, tip_target_mm - start_target_mm, j, p, out);
    warn_rotary_move(b, j, out);
    previous_motion_ = j;
    ++out.blocks_added;
    emit(std::move(p));
  }

  /// F of one of `n` equal pieces of an untracked block whose rotary axes move, the tip moving by
  /// `chord_mm` into motion `j`: the piece keeps its share of the block's time T, (K15), as the
  /// tip's speed |chord| n / T, or in inverse time n / T (a source in inverse time, or the
  /// policy); a piece whose tip stands still is timed over the target's rotary degrees, (K16).
  void piece_feed(const program::block& b, const source_step& s, std::size_t n, const vec3& chord_mm, std::size_t j,
                  program::block& o, translation& out) {
    if (s.rapid) return;
    const double time_min = *s.block_time_min / double(n);
    if (feed_ == feed_policy::inverse_time || s.feed_mode == program::feed_unit::inverse_time) {
      if (auto error = feed_refusal(program::feed_unit::inverse_time == s.feed_mode ? feed_policy::inverse_time : feed_,
                                    output_language_)) {
        if (!inverse_time_error_) out.errors.push_back(at(b, *error));
        inverse_time_error_ = true;
      }
      o.feed = 1.0 / time_min;  // a source in inverse time stays so: its G93 is carried over
      if (feed_ == feed_policy::inverse_time && !output_inverse_time_)
        o.feed_mode = program::feed_unit::inverse_time, output_inverse_time_ = true;
      return;
    }
    double length = norm(chord_mm);
    if (!(length > 1e-9) && j > 0 && path_.angles[j - 1]) {
      std::array<double, 2> delta_deg{};
      for (std::size_t i = 0; i < to_.rotary_count; ++i)
        delta_deg[i] = to_degrees((*path_.angles[j])[i] - (*path_.angles[j - 1])[i]).value;
      length = block_length({}, std::span<const double>(delta_deg.data(), to_.rotary_count));
    }
    if (length > 0.0) o.feed = length / time_min;
  }

  /// Whether piece `j` of block `b` (tip `tip_source_mm`) is within the target's reach and
  /// travel; false, with an error, when not.
  bool piece_reachable(const program::block& b, const source_step& s, std::size_t j, const vec3& tip_source_mm,
                       translation& out) const {
    std::string why;
    if (!path_.angles[j])
      why = "tool axis " + fixed(to_degrees(path_.gap[j]).value, 3) + "° outside the reach of " + std::string(to_.geometry.id);
    else if (auto past = slide_past_travel(tip_source_mm, *path_.angles[j]))
      why = past->why;
    if (why.empty()) return true;
    out.errors.push_back(at(b, std::string(to_.geometry.id) + " cannot reach a piece of this block (" + angles_text(s) +
                                   "): " + why));
    return false;
  }

  /// Reports motion block `b` (its `j`-th motion); false, with an error, when the target cannot
  /// reach it.
  template <class Report>
  bool report_motion(const program::block& b, const source_step& s, std::size_t j, translation& out,
                     Report&& on_report) {
    block_report report{b.where, matchability::direct, {}, {}, {}, 0.0};
    report.call_chain = b.call_chain;
    if (!path_.angles[j]) {
      report.match = matchability::unreachable;
      report.gap = path_.gap[j];
      report.why = "tool axis " + fixed(to_degrees(path_.gap[j]).value, 3) + "° outside the reach of " +
                   std::string(to_.geometry.id);
      out.errors.push_back(at(b, std::string(to_.geometry.id) + " cannot reach this block (" + angles_text(s) + "): " + report.why));
      on_report(std::move(report));
      return false;
    }
    if (auto past = s.positioning ? std::nullopt : slide_past_travel(s.tip_source_mm, *path_.angles[j])) {
      report.match = matchability::unreachable;
      report.linear_excess_mm = past->excess_mm;
      report.why = past->why;
      out.errors.push_back(at(b, std::string(to_.geometry.id) + " cannot reach this block (" + angles_text(s) + "): " + report.why));
      on_report(std::move(report));
      return false;
    }
    if (!s.principal) {
      report.match = matchability::other_branch;
      report.why = "the source pose is on the second solution branch of the source machine (K3); a closed-form "
                   "translation on the principal branch would turn the table 180° off (E6)";
    }
    on_report(std::move(report));
    if (path_.sweep_lost[j]) {  // reached, but not along the source's path
      out.errors.push_back(at(b, sweep_refusal(s)));
      return false;
    }
    return true;
  }

  /// Why block step `s`, whose source sweeps (`source_step::sweep`), is refused: no move of the
  /// target's axes turns its tool axis along the source's path.
  std::string sweep_refusal(const source_step& s) const {
    std::size_t axis = 0;
    const std::array<double, 2> start_deg = s.rotary_start_deg.value_or(s.rotary_source_deg);
    for (std::size_t i = 1; i < s.rotary_count; ++i)
      if (std::abs(s.rotary_source_deg[i] - start_deg[i]) > std::abs(s.rotary_source_deg[axis] - start_deg[axis])) axis = i;
    const std::string letter(1, s.rotary_letters[axis]);
    return std::string(to_.geometry.id) + " cannot follow this block's rotary sweep (" + letter + " turns by " +
           fixed(s.rotary_source_deg[axis] - start_deg[axis], 3) + "° from " + letter + "=" + fixed(start_deg[axis], 3) +
           "): its axes would turn the tool along another path through the part; program the sweep as moves of "
           "less than " + fixed(sweep_angle.value, 0) + "° each";
  }

  /// With a placement, the slides X, Y, Z (G7) of the source tip `tip_source_mm` with the planned angles:
  /// the one farthest past its travel (slide_travel.hpp). An arc is checked at its end point.
  std::optional<slide_excess> slide_past_travel(const vec3& tip_source_mm, const kin5::rotary_values& angles) const {
    if (!placement_) return std::nullopt;
    const vec3 tip_target_mm = target_T_source_.map_point(tip_source_mm);
    return slides_past_travel(linear_axes_for(to_, angles, placement_->work_offset.map_point(tip_target_mm), *placement_));
  }

  /// With a placement, the slide of `slides_mm` farthest past its travel (slide_travel.hpp).
  std::optional<slide_excess> slides_past_travel(const vec3& slides_mm) const {
    if (!placement_) return std::nullopt;
    return translate_detail::slide_past_travel(to_, slides_mm, *placement_);
  }

  /// The words of an arc: end point, direction and centre in the plane the setup maps the
  /// source plane onto; false, with an error, when that is no principal plane or the target's
  /// rotary axes would move during the arc.
  bool write_arc(const program::block& b, const source_step& s, const kin5::rotary_values& angles_target,
                 const rigid_transform& frame_T_source, program::block& o, translation& out) const {
    const arc_path& arc_source = s.arc_source;
    const vec3 tip_target_mm = frame_T_source.map_point(s.tip_source_mm);
    const auto mapped = principal_plane(frame_T_source.rotation * plane_normal(arc_source.plane));
    if (!mapped) {
      out.errors.push_back(at(b, "circular move cannot be mapped: plane " + std::string(plane_name(arc_source.plane)) +
                                     " maps to a plane that is not XY, ZX or YZ on the target"));
      return false;
    }
    if (previous_motion_ && path_.angles[*previous_motion_] &&
        rotary_step_cost(to_, *path_.angles[*previous_motion_], angles_target) > 1e-9) {
      out.errors.push_back(at(b, "circular move cannot be mapped: the target's rotary axes would move during it"));
      return false;
    }
    const auto [plane_target, flipped] = *mapped;
    const vec3 start_target_mm = frame_T_source.map_point(*s.start_source_mm);
    for (program::arc_plane plane : {program::arc_plane::yz, program::arc_plane::zx, program::arc_plane::xy}) {
      const double v_mm = normal_component(tip_target_mm, plane);  // yz → x, zx → y, xy → z
      std::optional<double>& word = plane == program::arc_plane::yz   ? o.axes.x_mm
                                    : plane == program::arc_plane::zx ? o.axes.y_mm
                                                                      : o.axes.z_mm;
      if (plane != plane_target || math::abs(v_mm - normal_component(start_target_mm, plane)) > 1e-9) word = v_mm;
    }
    using program::motion_kind;
    o.motion = flipped ? (s.motion == motion_kind::arc_cw ? motion_kind::arc_ccw : motion_kind::arc_cw) : s.motion;
    program::arc_words arc_target{plane_target, std::nullopt, arc_source.radius_mm};
    if (arc_source.centre_mm) arc_target.centre_mm = frame_T_source.map_point(*arc_source.centre_mm);
    o.arc = arc_target;
    return true;
  }

  /// F of motion block `b` by the feed policy (see feed.hpp); rapid moves carry none, and a
  /// source already in inverse time keeps its F.
  void write_feed(const program::block& b, const source_step& s, const vec3& tip_target_mm,
                  const std::array<double, 2>& angles_target_deg, program::block& o, translation& out) {
    if (s.rapid) {
      if (o.feed) restate_feed_ = true;  // `G0 X… F300`: F300 is for the feed moves after it
      o.feed.reset();
    } else if (s.feed_mode == program::feed_unit::inverse_time) {
      // Already inverse time: the block time is kept by construction, or by a per-minute F.
      if (!supports_inverse_time(output_language_)) per_minute_keeping_time(b, s, o, out);
      else if (feed_ == feed_policy::inverse_time && !output_inverse_time_)
        o.feed_mode = program::feed_unit::inverse_time, output_inverse_time_ = true;
    } else if (feed_ == feed_policy::block_time && s.feed_mm_per_min) {
      o.feed = block_time_feed_mm_per_min(*s.feed_mm_per_min, source_length(s), target_length(tip_target_mm, angles_target_deg));
    } else if (feed_ == feed_policy::inverse_time && s.feed_mm_per_min) {
      if (auto error = feed_refusal(feed_, output_language_)) {
        if (!inverse_time_error_) out.errors.push_back(at(b, *error));
        inverse_time_error_ = true;
      }
      o.feed = inverse_time_feed_per_min(*s.feed_mm_per_min, path_length(s));
      if (!o.feed) {
        // No block time to invert (a move from an unknown start, or one of zero length): in G93
        // every feed move needs its F, so this one keeps its per-minute F in G94, as `--feed
        // tcp` writes it; the next feed move returns to G93.
        o.feed = *s.feed_mm_per_min;
        if (output_inverse_time_) o.feed_mode = program::feed_unit::per_minute, output_inverse_time_ = false;
        return;
      }
      if (!output_inverse_time_) o.feed_mode = program::feed_unit::inverse_time, output_inverse_time_ = true;
    }
  }

  /// An inverse-time move (its time 1/F minutes) for a dialect without inverse time: the
  /// per-minute F that keeps its time, F = tool-tip path length × F, the tip path being the same
  /// on both machines (the setup is rigid). Refused when the tip does not move (a rotation
  /// alone: no tip speed gives its time) or its start is not known; a feed too small to write
  /// is refused by the writer.
  void per_minute_keeping_time(const program::block& b, const source_step& s, program::block& o, translation& out) {
    const std::string cannot = " cannot keep its time in " + std::string(program::name(output_language_)) +
                               ", which has no inverse-time feed";
    if (!s.feed_inverse_per_min) return out.errors.push_back(at(b, "inverse-time move without F" + cannot));
    if (!s.start_source_mm) return out.errors.push_back(at(b, "inverse-time move from an unknown start point" + cannot));
    const double tip_mm = program::is_arc(s.motion) ? arc_length_mm(s.arc_source, *s.start_source_mm, s.tip_source_mm)
                                                    : norm(s.tip_source_mm - *s.start_source_mm);
    if (!(tip_mm > 0.0))
      return out.errors.push_back(at(b, "inverse-time move whose tool tip does not move (a rotation alone)" + cannot));
    o.feed = tip_mm * *s.feed_inverse_per_min;
  }

  /// (K16) length of the source block from the previous motion (0 for the first).
  double source_length(const source_step& s) const {
    if (!previous_motion_) return 0.0;
    return block_length(s.tip_source_mm - previous_step_.tip_source_mm, source_rotary_delta(previous_step_, s).span());
  }

  /// (K16) length of the target block from the previous motion (0 for the first).
  double target_length(const vec3& tip_target_mm, const std::array<double, 2>& angles_target_deg) const {
    if (!previous_motion_) return 0.0;
    std::array<double, 2> delta_deg{};
    for (std::size_t i = 0; i < to_.rotary_count; ++i)
      delta_deg[i] = angles_target_deg[i] - to_degrees((*path_.angles[*previous_motion_])[i]).value;
    const vec3 previous_tip_target_mm = target_T_source_.map_point(previous_step_.tip_source_mm);
    return block_length(tip_target_mm - previous_tip_target_mm,
                        std::span<const double>(delta_deg.data(), to_.rotary_count));
  }

  /// The path an inverse-time block is timed over: the tool-tip path (mm; the arc's length for
  /// an arc), or for a pure re-orientation the source's (K16) length in degrees.
  double path_length(const source_step& s) const {
    double length = 0.0;
    if (s.start_source_mm)
      length = program::is_arc(s.motion) ? arc_length_mm(s.arc_source, *s.start_source_mm, s.tip_source_mm)
                                         : norm(s.tip_source_mm - *s.start_source_mm);
    if (!(length > 0.0) && previous_motion_)
      length = block_length({}, source_rotary_delta(previous_step_, s).span());
    return length;
  }

  /// Warnings at motion `j` (rotary_move.hpp): a change of solution branch from the last motion
  /// off a pole (pole blocks in between, where both branches meet, included), else a sudden turn;
  /// none for the source's own move or a move along its sweep, which the source made itself.
  void warn_rotary_move(const program::block& b, std::size_t j, translation& out) {
    const int before = branch_off_pole_;
    if (!path_.pole[j]) branch_off_pole_ = path_.branch[j];
    if (!previous_motion_) return;
    if (path_.source[j] && path_.source[*previous_motion_]) return;  // the source's own move
    if (path_.swept[j]) return;  // along the source's sweep, which the source made
    std::optional<branch_change> change;
    if (!path_.pole[j] && before >= 0 && before != path_.branch[j])
      change = branch_change{before, path_.branch[j], (path_.branches[*previous_motion_] & path_.branches[j]) != 0};
    if (auto warning = rotary_move_warning(to_, *path_.angles[*previous_motion_], *path_.angles[j], change))
      out.warnings.push_back(at(b, std::move(*warning)));
  }
};

}  // namespace kin5::translate_detail
