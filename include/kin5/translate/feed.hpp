/// @file translate/feed.hpp
/// Feed policies of a translation — one table, `feed_policies` (name, value, help), read by the
/// library and the command line alike — and the formulas they use, (K15)–(K17) = [000:20-23]:
///
///     t = l_s / f_s = l_d / f_d,   l = √(Δx² + Δy² + Δz² + Δrot₁² + Δrot₂²)  (mm and degrees),
///     f_d = f_s · l_d / l_s                                                  (K17) = [000:23]
///
/// `tcp` keeps F: under tool-tip tracking F is the tip speed relative to the part, and the tip
/// path is the same on both machines (the setup is rigid), so the time per block is already
/// kept. `block_time` applies (K17) literally, counting degrees as millimetres as a controller
/// does without TCP; it does *not* reproduce Table 1's F column (docs/golden.md).
/// `inverse_time` writes G93, F = 1 / block time in minutes, which needs a dialect that has it
/// (Siemens, ISO). Spindle speed is copied unchanged in every policy ([000:24-25]). Feeds carry
/// their unit in their names: `_mm_per_min` (tool-tip speed, G94), `_per_min` (inverse time).
/// @code
///   const auto policy = kin5::parse_feed_policy("block-time");  // empty for an unknown name
///   for (const auto& p : kin5::feed_policies) std::cout << p.name << ": " << p.help << '\n';
/// @endcode
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "../core/vec.hpp"
#include "../program/block.hpp"
#include "../program/dialect.hpp"

namespace kin5 {

/// How the F of a translated block is obtained.
enum class feed_policy {
  block_time,    ///< (K17): f_d = f_s · l_d / l_s, keeps the (K16) time per block
  tcp,           ///< F unchanged: tool-tip speed, right for TRAORI/M128/G43.4 programs
  inverse_time,  ///< G93, F = 1 / (block time in minutes)
};

/// One row of `feed_policies`.
struct feed_policy_entry {
  std::string_view name;  ///< as the command line spells it
  feed_policy policy;
  std::string_view help;  ///< one line for a user
};

/// Every feed policy, the default (`tcp`) first: the one list the library and the tool read.
inline constexpr std::array<feed_policy_entry, 3> feed_policies{{
    {"tcp", feed_policy::tcp, "F kept (tool-tip speed; right for TRAORI/M128/G43.4 programs)"},
    {"block-time", feed_policy::block_time, "F scaled to keep each block's time, the paper's eq 23"},
    {"inverse-time", feed_policy::inverse_time, "G93, F = 1/block time"},
}};

/// The name of policy `p` in `feed_policies`.
constexpr std::string_view name(feed_policy p) {
  for (const auto& entry : feed_policies)
    if (entry.policy == p) return entry.name;
  return "?";
}

/// The policy named `s` in `feed_policies`; empty for any other name (never a default).
constexpr std::optional<feed_policy> parse_feed_policy(std::string_view s) {
  for (const auto& entry : feed_policies)
    if (s == entry.name) return entry.policy;
  return std::nullopt;
}

/// Whether dialect `d` can write inverse-time feed (its `capabilities`: G93, FEDRAT/INVERS).
constexpr bool supports_inverse_time(program::dialect d) { return program::capabilities_of(d).inverse_time_feed; }

/// Why a program in dialect `d` cannot be written with feed policy `p`, if it cannot.
inline std::optional<std::string> feed_refusal(feed_policy p, program::dialect d) {
  if (p == feed_policy::inverse_time && !supports_inverse_time(d))
    return "inverse-time feed (G93) cannot be written in " + std::string(program::name(d));
  return std::nullopt;
}

/// (K16): the block length √(Δx² + Δy² + Δz² + Σ Δrot²), linear deltas in mm and rotary deltas
/// in degrees, mixed as the paper does.
inline double block_length(const vec3& delta_xyz_mm, std::span<const double> delta_rotary_deg) {
  double sum = squared_norm(delta_xyz_mm);
  for (double d : delta_rotary_deg) sum += d * d;
  return std::sqrt(sum);
}

/// (K17) = [000:23]: f_d = f_s · l_d / l_s, lengths by (K16). A block of zero source length
/// keeps F.
constexpr double block_time_feed_mm_per_min(double source_feed_mm_per_min, double source_length,
                                            double target_length) {
  return source_length > 0.0 ? source_feed_mm_per_min * target_length / source_length : source_feed_mm_per_min;
}

/// Inverse-time F (1/min) of a block of `path_length` (mm of tip path, or degrees for a pure
/// rotation) run at `feed_mm_per_min`: 1 / t with t = length / feed. Empty for a zero length.
constexpr std::optional<double> inverse_time_feed_per_min(double feed_mm_per_min, double path_length) {
  if (!(path_length > 0.0) || !(feed_mm_per_min > 0.0)) return std::nullopt;
  return feed_mm_per_min / path_length;
}

}  // namespace kin5
