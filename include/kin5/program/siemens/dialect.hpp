/// @file program/siemens/dialect.hpp
/// Siemens 840D programs (G code under TRAORI), as an entry of `program::dialects`: the reader
/// (lexer.hpp → words.hpp → reader.hpp), the writer (writer.hpp), and what the dialect declares
/// of itself. docs/dialects/siemens.md lists every word.
///
/// ```cpp
/// namespace s = kin5::program::siemens;
/// auto r = s::read("N10 G1 Y9.1 Z118.526 B3.536 F1091\n", "part.mpf");
/// if (r.ok()) std::string text = s::write(r.parsed);  // "N10 G1 Y9.1 … F1091\n"
/// ```
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "../block.hpp"
#include "../dialect_id.hpp"
#include "reader.hpp"
#include "writer.hpp"

namespace kin5::program::siemens {

/// Reads a Siemens 840D program. Never throws on bad input: problems are in `errors`.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(id_named("siemens"), text, std::move(file_name), &read_blocks);
}

/// The Siemens 840D dialect: its id, capabilities, file markers, reader and writer.
struct dialect {
  static constexpr std::string_view name = "siemens";
  static constexpr capabilities can{.inverse_time_feed = true, .tcp_switch = true, .rotary_axis_words = true,
                                    .tool_axis_vectors = true, .arcs = true, .tool_names = true,
                                    .work_offsets = {{{work_offset_family::g54, 1, 4},
                                                      {work_offset_family::siemens, 505, 599},
                                                      {work_offset_family::siemens, 0, 0}}}};
  static constexpr std::array<marker, 3> markers{{{"%_N_", marker::place::block_start},
                                                  {"TRAORI", marker::place::anywhere},
                                                  {"TRAFOOF", marker::place::anywhere}}};
  /// 840Di Manual (HBI) 06/2003 §10.3.1: input rounded to MD10200/MD10210 (docs/dialects/siemens.md).
  static constexpr controller reads{.usual = {3, 3, 1, 7}, .finest = {6, 6, 3, 9}, .dwell = detail::dwell_steps,
                                    .plane_turns_tool_length = true};
  /// Catalog machines whose controller reads it (Tian 2010's SAJO 12000P; the usual one for the rest).
  static constexpr std::array<std::string_view, 4> default_for{"sajo-12000p", "ac-trunnion", "ac-head",
                                                               "b-head-a-tilted-table"};
  /// Kept words a comment would lose: another edge than D1 (D0 is read as length compensation
  /// off, `state.length_compensation`, which every writer says its own way).
  static constexpr std::array<kept_word_effect, 1> lost_as_comment{
      {{"D1", kept_word_effect::match::other_code,
        "another cutting edge's length and radius than the first's (D1, the tool's own)"}}};
  using write_options = siemens::write_options;
  using writer = siemens::writer;
  static void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                          const block_sink& on_block) {
    siemens::read_blocks(text, file_name, diagnostics, on_block);
  }
  /// The same within `limits` (its `max_executed_lines`: the program runs under the interpreter).
  static void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                          const block_sink& on_block, const read_limits& limits) {
    siemens::read_blocks(text, file_name, diagnostics, on_block, limits);
  }
  static std::string write(const program& p, const write_options& options) { return siemens::write(p, options); }
};

}  // namespace kin5::program::siemens
