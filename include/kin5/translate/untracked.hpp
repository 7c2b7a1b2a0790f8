/// @file translate/untracked.hpp
/// Motion without tool-tip tracking (TCP off), read as machine coordinates: the programmed
/// X Y Z is the untracked program point (G8), so the slides are x = D⁻¹(W·xyz − g), and with
/// the commanded angles the whole chain (G6) gives the tool tip and tool axis in the workpiece
/// frame. Between two blocks a controller interpolates every axis linearly in one parameter
/// s ∈ [0, 1] (the slides are affine in xyz, so interpolating xyz interpolates them):
///
///     tip(s) = (G6)( D⁻¹(W·xyz(s) − g), θ(s) ),  xyz(s), θ(s) linear in s          (G9)
///
/// With θ constant the map is affine and rigid, so the tip moves on a straight line (and an arc
/// on an arc); when θ moves it does not, and `pieces_within` finds how many equal steps of s
/// keep the tip within a tolerance of the chords between them (docs/theory.md, (G9)).
/// @code
///   const kin5::run_inputs source{.tool_length_mm = 50.0, .work_offset = {mat3::identity(), {0, 0, -200}}};
///   const kin5::translate_detail::untracked_move move{start_mm, end_mm, start_angles, end_angles};
///   const auto n = kin5::translate_detail::pieces_within(m, source, move, 0.005);  // empty: too many
///   for (std::size_t k = 1; n && k <= *n; ++k) use(move.at(m, source, double(k) / *n).tip_mm);
/// @endcode
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include "../core/vec.hpp"
#include "../kinematics/forward.hpp"
#include "../kinematics/inverse_pose.hpp"

namespace kin5::translate_detail {

/// The tool pose machine `m` gives for the untracked program point `xyz_mm` (TCP off) and the
/// commanded angles `angles`, with the source's work offset and tool length `in`: (G8) then (G6).
inline tool_pose untracked_pose(const machine_model& m, const vec3& xyz_mm, const kin5::rotary_values& angles,
                                const run_inputs& in) {
  return forward(m, axis_values{axes_for_untracked_point(m, xyz_mm, in), angles}, in);
}

/// One block read as machine coordinates: its program points and commanded angles at the
/// start and at the end, which the controller interpolates linearly (G9).
struct untracked_move {
  vec3 start_mm{}, end_mm{};
  kin5::rotary_values start{}, end{};

  /// The tool pose at parameter `s` ∈ [0, 1] of the block.
  tool_pose at(const machine_model& m, const run_inputs& in, double s) const {
    kin5::rotary_values angles{};
    for (std::size_t i = 0; i < angles.size(); ++i) angles[i] = radians{start[i].value + s * (end[i].value - start[i].value)};
    return untracked_pose(m, start_mm + s * (end_mm - start_mm), angles, in);
  }
};

/// Distance (mm) from point `p` to the segment from `a` to `b`.
inline double distance_to_segment(const vec3& p, const vec3& a, const vec3& b) {
  const vec3 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return norm(p - (a + t * ab));
}

/// Samples per piece at which `pieces_within` measures the tip's distance from the chord.
inline constexpr std::size_t samples_per_piece = 16;

/// The largest distance, over `samples_per_piece` points inside each of `n` equal pieces of
/// `move`, from the tip path to that piece's chord (mm).
inline double largest_chord_deviation(const machine_model& m, const run_inputs& in, const untracked_move& move,
                                      std::size_t n) {
  double worst = 0.0;
  vec3 a = move.at(m, in, 0.0).tip_mm;
  for (std::size_t k = 0; k < n; ++k) {
    const vec3 b = move.at(m, in, double(k + 1) / double(n)).tip_mm;
    for (std::size_t j = 1; j < samples_per_piece; ++j) {
      const double s = (double(k) + double(j) / double(samples_per_piece)) / double(n);
      worst = std::max(worst, distance_to_segment(move.at(m, in, s).tip_mm, a, b));
    }
    a = b;
  }
  return worst;
}

/// The number of equal pieces of `move` whose chords keep the tip path within half of
/// `tolerance_mm` at every sample (the other half is margin for what the samples miss); empty
/// when that needs more than `max_pieces`. 1 for a block whose rotary axes do not move.
inline std::optional<std::size_t> pieces_within(const machine_model& m, const run_inputs& in,
                                                const untracked_move& move, double tolerance_mm,
                                                std::size_t max_pieces = 100000) {
  const double aim_mm = 0.5 * tolerance_mm;
  std::size_t n = 1;
  for (;;) {
    const double deviation_mm = largest_chord_deviation(m, in, move, n);
    if (deviation_mm <= aim_mm) return n;
    // A chord's deviation falls with the square of the piece length; aim a little below.
    const double grow = std::sqrt(deviation_mm / (0.8 * aim_mm));
    const double next = std::ceil(double(n) * std::max(grow, 1.25));
    if (!(next <= double(max_pieces))) return std::nullopt;
    n = std::max(n + 1, static_cast<std::size_t>(next));
  }
}

}  // namespace kin5::translate_detail
