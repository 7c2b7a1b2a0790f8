/// @file program/iso/dialect.hpp
/// ISO / Fanuc G code, as an entry of `program::dialects` (LinuxCNC's, program/linuxcnc/, builds on it): the
/// reader (lexer.hpp → reader.hpp), the writer (writer.hpp), and what the dialect declares of
/// itself. docs/dialects/iso.md lists every word.
///
/// ```cpp
/// namespace iso = kin5::program::iso;
/// auto r = iso::read("N10 G1 Y9.1 Z118.5 B3.5 C-77.9 F1091\n", "part.nc");
/// if (r.ok()) std::string text = iso::write(r.parsed);  // "N10 G1 Y9.1 … F1091.\n"
/// ```
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "../block.hpp"
#include "../dialect_id.hpp"
#include "reader.hpp"
#include "writer.hpp"

namespace kin5::program::iso {

/// Reads ISO / Fanuc G code. Never throws on bad input: problems are in `errors`.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(id_named("iso"), text, std::move(file_name), &read_blocks);
}

/// The ISO / Fanuc dialect: its id, capabilities, file markers, reader and writer.
struct dialect {
  static constexpr std::string_view name = "iso";
  static constexpr capabilities can{.inverse_time_feed = true, .tcp_switch = true, .rotary_axis_words = true,
                                    .tool_axis_vectors = true, .arcs = true,
                                    .work_offsets = {{{work_offset_family::g54, 1, 6}, {work_offset_family::extended, 1, 300}}}};
  static constexpr std::array<marker, 2> markers{{{"G43.4", marker::place::anywhere},
                                                  {"G43.5", marker::place::anywhere}}};
  /// A Fanuc-style controller's (vocabulary.hpp: IS-C, `( … )` comments, S whole, G4 X).
  static constexpr controller reads = detail::fanuc_reads;
  /// Catalog machines whose controller reads it (CN1624613's 4-axis machine).
  static constexpr std::array<std::string_view, 1> default_for{"a-rotary-4axis"};
  /// Kept words a comment would lose: none (the dwell and tool length compensation are read into
  /// the model and translated or refused by the writers).
  static constexpr std::array<kept_word_effect, 0> lost_as_comment{};
  using write_options = iso::write_options;
  using writer = iso::writer;
  static void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                          const block_sink& on_block) {
    iso::read_blocks(text, file_name, diagnostics, on_block);
  }
  static std::string write(const program& p, const write_options& options) { return iso::write(p, options); }
};

}  // namespace kin5::program::iso
