/// @file translate/precision.hpp
/// How many decimals the output writes, per word class (linear, angle, feed and speed, tool-axis
/// vector): at least as many as the source writes, at least the output dialect's usual, and no
/// more than its controller reads —
///
///     decimals = min(max(source decimals, usual), finest)        per class
///     linear and angle = --digits when given (overrides both bounds, knowingly)
///
/// so a 4-decimal source is no longer written with 3, and a value is never written finer than
/// the controller's input resolution (where it would be an input error or silently rounded).
/// Positions or angles an NC source writes finer than the controller reads are refused
/// (`--digits` rounds them knowingly, with a warning wherever it writes fewer decimals than the
/// source: `--digits 0` moves a 3-decimal position by up to 0.5 mm); feeds and vectors finer
/// than it, angles derived from vectors and CL data's positions are written to the controller's
/// resolution with a warning. Angles and vectors are converted into each other where the source
/// has one and the output the other: a vector component's last place 10⁻ᵛ rad needs v − 1 decimals of a
/// degree; an angle's 10⁻ᵃ° (1.75·10⁻⁽ᵃ⁺²⁾ rad) needs a + 2 decimals of a vector.
///
/// The controllers' resolutions are data of each dialect (`reads`, a `program::controller`, in
/// `program/<dialect>/dialect.hpp`, which cites the manual; docs/dialects/*.md too).
/// @code
///   kin5::precision_notes notes;
///   const auto d = kin5::output_decimals(read.resolution, out, std::nullopt, &notes);
///   program::block_writer writer(out, source, file, kin5::write_settings_for(out, d));
/// @endcode
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "../program/io.hpp"
#include "../program/resolution.hpp"

namespace kin5 {

/// The source's decimals per class, angles and vectors standing in for each other where one is
/// missing (see the file comment); empty where the source writes neither.
inline program::number_resolution source_decimals(const program::number_resolution& source) {
  program::number_resolution r = source;
  if (!r.angle_decimals && source.vector_decimals) r.angle_decimals = *source.vector_decimals - 1;
  if (!r.vector_decimals && source.angle_decimals) r.vector_decimals = *source.angle_decimals + 2;
  if (!r.feed_decimals) r.feed_decimals = source.speed_decimals;
  else if (source.speed_decimals) r.feed_decimals = std::max(*r.feed_decimals, *source.speed_decimals);
  return r;
}

/// What `output_decimals` says about the source's resolution against the output controller's.
struct precision_notes {
  /// Positions or angles the source writes finer than the controller reads: refused (an error
  /// naming `--digits`), since rounding them changes what the machine does; empty if none.
  std::string refused;
  /// Other classes rounded to the controller's resolution (feeds, vectors, angles derived from
  /// a CL vector): a warning; empty if none.
  std::string rounded;
};

/// Half a unit of the last of `decimals` decimals, as text: "0.5" for 0, "0.0005" for 3.
inline std::string half_unit(int decimals) {
  return decimals <= 0 ? std::string("0.5") : "0." + std::string(static_cast<std::size_t>(decimals), '0') + "5";
}

/// The decimals to write a program whose source writes `source` in dialect `out` (see the file
/// comment), and in `notes` what cannot be kept. `--digits` (`digits`) chooses positions and
/// angles knowingly: nothing is refused then, but fewer decimals than the source writes are
/// a warning (`rounded`) that says how far a position or an angle may move. `source_is_cl`: the source is CL data, whose
/// decimals are the CAM system's arithmetic, not a controller's input: rounded with a warning.
/// `inch`: the program's lengths are inches, and every writer writes them with one decimal more
/// than `linear` (0.0001 in for 0.001 mm): the source's position decimals, the usual and the
/// finest are then counted in inches (a 5-decimal inch source is 5 decimals of an inch, which an
/// IS-C control reads), and `digits` is the inch decimals written (at least one).
inline program::word_decimals output_decimals(const program::number_resolution& source, program::dialect out,
                                              std::optional<int> digits, precision_notes* notes = nullptr,
                                              bool source_is_cl = false, bool inch = false) {
  const program::controller limits = program::controller_of(out);
  const program::number_resolution s = source_decimals(source);
  precision_notes said;
  auto pick = [&](const std::optional<int>& wanted, int usual, int finest, std::string_view what, bool written) {
    const int d = std::max(wanted.value_or(usual), usual);
    if (d <= finest) return d;
    std::string& to = written && !digits && !source_is_cl ? said.refused : said.rounded;
    to += (to.empty() ? "" : "; ") + std::string(what) + " with " + std::to_string(d) + " decimals, " +
          std::string(program::name(out)) + " reads " + std::to_string(finest);
    return finest;
  };
  program::word_decimals d;
  const int in = inch ? 1 : 0;  // the writers' one decimal more for inches
  d.linear = pick(s.linear_decimals, limits.usual.linear + in, limits.finest.linear + in,
                  inch ? "positions (inch)" : "positions", true) - in;
  d.angle = pick(s.angle_decimals, limits.usual.angle, limits.finest.angle, "angles", source.angle_decimals.has_value());
  d.feed = pick(s.feed_decimals, limits.usual.feed, limits.finest.feed, "feeds", false);
  d.vector = pick(s.vector_decimals, limits.usual.vector, limits.finest.vector, "tool-axis vectors", false);
  std::string coarser;  // what --digits rounds of the source's own decimals
  if (digits) {
    d.linear = std::max(*digits - in, 0);
    d.angle = *digits;
    said = {};
    const auto rounds = [&](const std::optional<int>& written, std::string_view what, std::string_view unit) {
      if (!written || *digits >= *written) return;
      coarser += (coarser.empty() ? "" : "; ") + std::string(what) + " written with " + std::to_string(*written) +
                 " decimals to " + std::to_string(*digits) + ": each may move by up to " + half_unit(*digits) + ' ' +
                 std::string(unit);
    };
    rounds(s.linear_decimals, "positions", inch ? "in" : "mm");
    rounds(source.angle_decimals, "angles", "deg");
  }
  if (notes) {
    if (!coarser.empty())
      notes->rounded = "--digits " + std::to_string(*digits) + " rounds the source's " + coarser +
                       " (fewer decimals than the program writes move the machine elsewhere)";
    if (!said.refused.empty())
      notes->refused = "the source writes " + said.refused + ": rounding them would move the machine elsewhere " +
                       "(--digits N rounds positions and angles knowingly)";
    if (!said.rounded.empty())
      notes->rounded = "the source writes " + said.rounded + ": written to the controller's resolution";
  }
  return d;
}

/// Writer settings for dialect `out` with decimals `d`: the user's `chosen` settings (e.g.
/// Heidenhain's TCP word) with the decimals of `out` replaced by `d`.
inline program::write_settings write_settings_for(program::dialect out, const program::word_decimals& d,
                                                  program::write_settings chosen = {}) {
  program::write_settings settings = std::move(chosen);
  program::for_each_dialect([&]<class D>(std::type_identity<D>, std::size_t i) {
    if (program::dialect(i) != out) return;
    auto& o = settings.of<D>();
    o.linear_decimals = d.linear;
    o.angle_decimals = d.angle;
    o.feed_decimals = d.feed;
    o.finest_feed_decimals = std::max(d.feed, program::controller_of(out).finest.feed);
    o.vector_decimals = d.vector;
  });
  return settings;
}

}  // namespace kin5
