/// @file feed.hpp
/// Feed policies of a translation, and the block-time feed of the paper, (K15)–(K17) =
/// [000:20-23]:
///
///     t = l_s / f_s = l_d / f_d,   l = √(Δx² + Δy² + Δz² + Δrot₁² + Δrot₂²)  (mm and degrees),
///     f_d = f_s · l_d / l_s                                                  (K17) = [000:23]
///
/// `tcp` keeps F: under tool-tip tracking F is the tip speed relative to the part, and the tip
/// path is the same on both machines (the setup is rigid), so the time per block is already
/// kept. `block_time` applies (K17) literally, counting degrees as millimetres as a controller
/// does without TCP; it does *not* reproduce Table 1's F column (docs/golden.md). `inverse_time`
/// writes G93, F = 1 / block time in minutes, which needs a dialect that has it (Siemens, ISO).
/// Spindle speed is copied unchanged in every policy ([000:24-25]).
#pragma once

#include <cmath>
#include <optional>
#include <span>
#include <string_view>

#include "../program/block.hpp"
#include "../core/vec.hpp"

namespace kin5 {

/// How the F of a translated block is obtained.
enum class feed_policy {
  block_time,    ///< (K17): f_d = f_s · l_d / l_s, keeps the (K16) time per block
  tcp,           ///< F unchanged: tool-tip speed, right for TRAORI/M128/G43.4 programs
  inverse_time,  ///< G93, F = 1 / (block time in minutes)
};

constexpr std::string_view name(feed_policy p) {
  switch (p) {
    case feed_policy::block_time: return "block-time";
    case feed_policy::tcp: return "tcp";
    case feed_policy::inverse_time: return "inverse-time";
  }
  return "?";
}

/// The policy named `s` ("block-time", "tcp", "inverse-time"), if any.
constexpr std::optional<feed_policy> parse_feed_policy(std::string_view s) {
  for (feed_policy p : {feed_policy::block_time, feed_policy::tcp, feed_policy::inverse_time})
    if (s == name(p)) return p;
  return std::nullopt;
}

/// Whether dialect `d` can write inverse-time feed (G93).
constexpr bool supports_inverse_time(program::dialect d) {
  return d == program::dialect::siemens || d == program::dialect::iso;
}

/// (K16): the block length √(Δx² + Δy² + Δz² + Σ Δrot²), linear deltas in mm and rotary deltas
/// in degrees, mixed as the paper does.
inline double block_length(const vec3& delta_xyz_mm, std::span<const double> delta_rotary_deg) {
  double sum = squared_norm(delta_xyz_mm);
  for (double d : delta_rotary_deg) sum += d * d;
  return std::sqrt(sum);
}

/// (K17) = [000:23]: f_d = f_s · l_d / l_s. A block of zero source length keeps F.
constexpr double block_time_feed(double source_feed, double source_length, double target_length) {
  return source_length > 0.0 ? source_feed * target_length / source_length : source_feed;
}

/// Inverse-time F (1/min) of a block of `path_length` (mm of tip path, or degrees for a pure
/// rotation) run at `feed_per_minute`: 1 / t with t = length / feed. Empty for a zero length.
constexpr std::optional<double> inverse_time_feed(double feed_per_minute, double path_length) {
  if (!(path_length > 0.0) || !(feed_per_minute > 0.0)) return std::nullopt;
  return feed_per_minute / path_length;
}

}  // namespace kin5
