/// @file program/haas/dialect.hpp
/// Haas mill G code (the Next Generation Control), as an entry of `program::dialects`: the
/// reader (reader.hpp, built on ISO's), the writer (writer.hpp, built on ISO's), and what the
/// dialect declares of itself. Not ISO: tool center point control is `G234 H n` (no G43.4, no
/// G43.5 with vectors), additional work offsets are `G154 P1` … `P99` (and `G110` … `G129`), not
/// `G54.1 P n`; `G04 P` is seconds with a decimal point, milliseconds without.
/// docs/dialects/haas.md lists every word with its manual section.
///
/// ```cpp
/// namespace haas = kin5::program::haas;
/// auto r = haas::read("T2 M06\nG234 H02\nG01 X1. B-5. C15. F60.\n", "umc.nc");
/// if (r.ok()) std::string text = haas::write(r.parsed);
/// ```
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "../block.hpp"
#include "../dialect_id.hpp"
#include "../iso/vocabulary.hpp"
#include "reader.hpp"
#include "writer.hpp"

namespace kin5::program::haas {

/// Reads Haas mill G code. Never throws on bad input: problems are in `errors`.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(id_named("haas"), text, std::move(file_name), &read_blocks);
}

/// The Haas dialect: its capabilities, file markers, reader and writer.
struct dialect {
  static constexpr std::string_view name = "haas";
  static constexpr capabilities can{.inverse_time_feed = true, .tcp_switch = true, .rotary_axis_words = true,
                                    .arcs = true,
                                    .work_offsets = {{{work_offset_family::g54, 1, 6}, {work_offset_family::extended, 1, 99, "G154 P"}}}};
  /// TCPC and the additional work offsets: no other dialect writes them.
  static constexpr std::array<marker, 2> markers{{{"G234", marker::place::anywhere},
                                                  {"G154", marker::place::anywhere}}};
  /// ISO's (iso/vocabulary.hpp `fanuc_reads`: IS-C, `( … )` comments, S a whole number; inch
  /// lengths to 0.0001 in, HA5; its dwells, which `G04 P` takes as vocabulary.hpp says).
  static constexpr controller reads = iso::detail::fanuc_reads;
  /// Catalog machines whose controller reads it: none (no Haas machine is in the catalog; a
  /// program for one names the dialect: `--from-dialect haas`, `--to-dialect haas`).
  static constexpr std::array<std::string_view, 0> default_for{};
  /// Kept words a comment would lose: none (the dwell, TCPC and offsets are read into the model).
  static constexpr std::array<kept_word_effect, 0> lost_as_comment{};
  using write_options = haas::write_options;
  using writer = haas::writer;
  static void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                          const block_sink& on_block) {
    haas::read_blocks(text, file_name, diagnostics, on_block);
  }
  static std::string write(const program& p, const write_options& options) { return haas::write(p, options); }
};

}  // namespace kin5::program::haas
