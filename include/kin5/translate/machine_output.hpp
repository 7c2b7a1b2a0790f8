/// @file translate/machine_output.hpp
/// Output in machine coordinates (`output_mode::machine`): each target pose is written as the
/// target's axis values, X Y Z the untracked program point (G8) of its slides (G7) and the
/// rotary words its angles, with no tool-tip tracking. A controller interpolates those values
/// linearly between two blocks, so the tip leaves the straight path TCP would keep; a block is
/// cut into m pieces whose ends lie on the source's path (tip and angles advanced by equal
/// steps, as a TCP control moves them) and whose joint-interpolated tip stays within a tolerance
/// of the chords between them (G10, docs/theory.md):
///
///     tip_k = tip₀ + (k/m) Δtip,  θ_k = θ₀ + (k/m) Δθ,  xyz_k = (G8)((G7)(tip_k, θ_k))       (G10)
/// @code
///   const kin5::translate_detail::joint_path path{start_tip_mm, end_tip_mm, start_angles, end_angles};
///   const auto m = kin5::translate_detail::machine_pieces_within(to, placement, path, 0.005);
///   for (std::size_t k = 1; m && k <= *m; ++k) write(path.program_point(to, placement, double(k) / *m));
/// @endcode
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "../core/rigid.hpp"
#include "../kinematics/forward.hpp"
#include "../kinematics/inverse_pose.hpp"
#include "../program/block.hpp"
#include "../program/dialect.hpp"
#include "feed.hpp"
#include "untracked.hpp"

namespace kin5 {

/// What an NC target's motion blocks say: the tool tip under tool-tip tracking, or the
/// machine's own axis values without it.
enum class output_mode {
  tcp,      ///< X Y Z the tool tip in the workpiece frame, tool-tip tracking switched on
  machine,  ///< X Y Z the untracked program point (G8) of the slides, no tool-tip tracking
};

/// The name the command line gives `m`.
constexpr std::string_view name(output_mode m) { return m == output_mode::tcp ? "tcp" : "machine"; }

/// The mode named `s`; empty for any other name.
constexpr std::optional<output_mode> parse_output_mode(std::string_view s) {
  if (s == "tcp") return output_mode::tcp;
  if (s == "machine") return output_mode::machine;
  return std::nullopt;
}

/// The mode dialect `d` is written in unless told: TCP where it can switch tool-tip tracking on.
constexpr output_mode default_output_mode(program::dialect d) {
  return program::capabilities_of(d).tcp_switch ? output_mode::tcp : output_mode::machine;
}

namespace translate_detail {

/// The word of rotary axis `l` in `w` (degrees).
inline std::optional<double>& rotary_word(program::axis_words& w, axis_letter l) {
  return l == axis_letter::A ? w.a_deg : (l == axis_letter::B ? w.b_deg : w.c_deg);
}

/// The program point (G8) of machine `m` with placement `in` whose slides put the tool tip at
/// `tip_mm` (workpiece frame) with the angles `angles`: (G7) then (G8).
inline vec3 program_point_for(const machine_model& m, const vec3& tip_mm, const kin5::rotary_values& angles,
                              const run_inputs& in) {
  return untracked_point(m, linear_axes_for(m, angles, in.work_offset.map_point(tip_mm), in), in);
}

/// program_T_work at fixed angles: the rigid map from the tip (workpiece frame) to the program
/// point (G8) that puts it there. Rigid because (G7) and (G8) are, for fixed angles.
inline rigid_transform program_T_work(const machine_model& m, const kin5::rotary_values& angles, const run_inputs& in) {
  const vec3 o = program_point_for(m, {}, angles, in);
  const vec3 c0 = program_point_for(m, unit_x, angles, in) - o, c1 = program_point_for(m, unit_y, angles, in) - o,
             c2 = program_point_for(m, unit_z, angles, in) - o;
  return {mat3{{vec3{c0.x, c1.x, c2.x}, vec3{c0.y, c1.y, c2.y}, vec3{c0.z, c1.z, c2.z}}}, o};
}

/// One target block to be written in machine coordinates: the tip (target workpiece frame) and
/// the angles at its start and at its end; a TCP control would move both by equal steps.
struct joint_path {
  vec3 start_tip_mm{}, end_tip_mm{};
  kin5::rotary_values start{}, end{};

  /// The angles at parameter `s` ∈ [0, 1].
  kin5::rotary_values angles_at(double s) const {
    kin5::rotary_values a{};
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = radians{start[i].value + s * (end[i].value - start[i].value)};
    return a;
  }
  /// The tip at parameter `s`, on the source's straight path.
  vec3 tip_at(double s) const { return start_tip_mm + s * (end_tip_mm - start_tip_mm); }
  /// The program point (G8) at parameter `s`: what a block ending there writes as X Y Z.
  vec3 program_point(const machine_model& m, const run_inputs& in, double s) const {
    return program_point_for(m, tip_at(s), angles_at(s), in);
  }
  /// The move a controller without TCP makes from parameter `a` to `b`: the axis values of both
  /// ends, interpolated linearly (untracked.hpp).
  untracked_move machine_move(const machine_model& m, const run_inputs& in, double a, double b) const {
    return {program_point(m, in, a), program_point(m, in, b), angles_at(a), angles_at(b)};
  }
};

/// The largest distance (mm), sampled `samples_per_piece` times in each of `n` equal pieces of
/// `path`, from the tip a controller without TCP moves between the pieces' ends to their chord.
inline double largest_joint_deviation(const machine_model& m, const run_inputs& in, const joint_path& path,
                                      std::size_t n) {
  double worst = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    worst = std::max(worst, largest_chord_deviation(m, in, path.machine_move(m, in, double(k) / double(n),
                                                                             double(k + 1) / double(n)), 1));
  return worst;
}

/// The number of equal pieces of `path` whose machine-coordinate moves keep the tip within half
/// of `tolerance_mm` of their chords (the other half is margin for what the samples miss), 1
/// when the angles do not move; empty when that needs more than `max_pieces`.
inline std::optional<std::size_t> machine_pieces_within(const machine_model& m, const run_inputs& in,
                                                        const joint_path& path, double tolerance_mm,
                                                        std::size_t max_pieces = 100000) {
  if (path.start == path.end) return 1;
  const double aim_mm = 0.5 * tolerance_mm;
  std::size_t n = 1;
  for (;;) {
    const double deviation_mm = largest_joint_deviation(m, in, path, n);
    if (deviation_mm <= aim_mm) return n;
    const double grow = std::sqrt(deviation_mm / (0.8 * aim_mm));  // deviation falls as 1/n²
    const double next = std::ceil(double(n) * std::max(grow, 1.25));
    if (!(next <= double(max_pieces))) return std::nullopt;
    n = std::max(n + 1, static_cast<std::size_t>(next));
  }
}


/// Refusals of a block written in machine coordinates.
inline constexpr std::string_view machine_too_many =
    "rotary move in machine coordinates needs more than 100000 pieces to stay within --tolerance";
inline constexpr std::string_view machine_whole_block =
    "rotary move in machine coordinates, cut into pieces, that also says (give it a block of its own): ";
inline constexpr std::string_view machine_after_tool_change =
    "feed move in machine coordinates whose rotary axes move, the first after a tool change: where the change left "
    "the axes is not known, so neither is the tool tip's path; position with a rapid move first";

/// The pose a machine-coordinate output last wrote: the tip (target workpiece frame) and angles.
struct written_pose {
  vec3 tip_mm{};
  kin5::rotary_values angles{};
};

/// Writes target poses of machine `to` in machine coordinates, block by block: from the pose
/// written last to the next, in as many pieces as (G10) needs, each keeping its share of the
/// move's time, (K15) = Tian et al. 2010, eq. (20). The F of a piece is 1/t in inverse time
/// when its rotary axes move and the dialect has inverse time (or everything is in inverse
/// time), else the (K16) length of its axis values over t, (K17) = Tian et al. 2010, eq. (23),
/// which a control without TCP reads back as the same time.
class machine_writer {
 public:
  machine_writer() = default;
  /// `inverse_time`: the output dialect has it; `all_inverse_time`: every feed move is so written.
  machine_writer(const machine_model& to, const run_inputs& placement, double tolerance_mm, bool inverse_time,
                 bool all_inverse_time)
      : to_(to), in_(placement), tolerance_mm_(tolerance_mm), inverse_time_(inverse_time), all_inverse_time_(all_inverse_time) {}

  const run_inputs& placement() const { return in_; }
  /// The tool length from the next move on (a tool change: `forget` the position too).
  void set_tool_length(double length_mm) { in_.tool_length_mm = length_mm; }
  /// The pose written last, while the position is known.
  const std::optional<written_pose>& last() const { return last_; }
  /// The position is no longer known (a block passed through).
  void forget() { last_.reset(); }

  /// The path from the last pose to `to` (from `to` itself when none is known).
  joint_path path_to(const written_pose& to) const {
    const written_pose& from = last_ ? *last_ : to;
    return {from.tip_mm, to.tip_mm, from.angles, to.angles};
  }
  /// How many pieces the move to `to` needs; empty when more than (G10) allows.
  std::optional<std::size_t> pieces_to(const written_pose& to) const {
    return machine_pieces_within(to_, in_, path_to(to), tolerance_mm_);
  }

  /// The axis words and F of piece `k` (1 … `n`) of the move to `to` in block `p`: X Y Z the
  /// program point (G8), the angles in degrees; `time_min` the whole move's time, if known
  /// (rapid: none, and no F); `feed` the F to keep when the time is not known.
  void piece(program::block& p, const written_pose& to, std::size_t k, std::size_t n, std::optional<double> time_min,
             std::optional<double> feed, bool rapid) {
    const joint_path path = path_to(to);
    const double s0 = double(k - 1) / double(n), s1 = double(k) / double(n);
    const vec3 xyz_mm = path.program_point(to_, in_, s1);
    const kin5::rotary_values angles = path.angles_at(s1);
    p.axes = {};
    p.axes.x_mm = xyz_mm.x, p.axes.y_mm = xyz_mm.y, p.axes.z_mm = xyz_mm.z;
    std::array<double, 2> delta_deg{};
    for (std::size_t i = 0; i < to_.rotary_count; ++i) {
      rotary_word(p.axes, to_.rotary(i).letter) = to_degrees(angles[i]).value;
      delta_deg[i] = to_degrees(angles[i] - path.angles_at(s0)[i]).value;
    }
    p.feed.reset(), p.feed_mode.reset();
    if (rapid) return;
    const bool turns = delta_deg[0] != 0.0 || delta_deg[1] != 0.0;
    if (time_min && *time_min > 0.0) {
      const double t = *time_min / double(n);
      if (all_inverse_time_ || (turns && inverse_time_)) {
        p.feed = 1.0 / t;
        unit(p, program::feed_unit::inverse_time);
        return;
      }
      const double length = block_length(xyz_mm - path.program_point(to_, in_, s0),
                                         std::span<const double>(delta_deg.data(), to_.rotary_count));
      if (length > 0.0) p.feed = length / t, unit(p, program::feed_unit::per_minute);
      return;
    }
    if (feed) p.feed = *feed, unit(p, program::feed_unit::per_minute);
  }

  /// The move to `to` is written.
  void arrive(const written_pose& to) { last_ = to; }

  /// Feed words of a block that keeps its F as written (an arc at fixed angles: rigid, so F is
  /// still the tip speed; or a block already in inverse time).
  void keep_feed(program::block& p, std::optional<double> feed, program::feed_unit u) {
    p.feed = feed, p.feed_mode.reset();
    if (feed) unit(p, u);
  }

  /// The tool-tip tracking words of block `o`, for an output without TCP: switching TCP on
  /// becomes switching the tool length compensation on (the program point (G8) is read with the
  /// tool length along the tool reference); switching it off leaves the length in effect.
  static void without_tcp(program::block& o) {
    if (o.tcp && *o.tcp) o.state.length_compensation = true;
    o.tcp.reset();
  }

 private:
  machine_model to_{};
  run_inputs in_{};
  double tolerance_mm_ = 0.005;
  bool inverse_time_ = false, all_inverse_time_ = false;
  bool in_inverse_time_ = false;  // G93 in effect in the output
  std::optional<written_pose> last_;

  /// Says the feed unit in `p` when it changes.
  void unit(program::block& p, program::feed_unit u) {
    const bool inverse = u == program::feed_unit::inverse_time;
    if (inverse != in_inverse_time_) p.feed_mode = u, in_inverse_time_ = inverse;
  }
};

}  // namespace translate_detail
}  // namespace kin5
