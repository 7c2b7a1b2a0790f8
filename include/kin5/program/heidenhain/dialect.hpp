/// @file program/heidenhain/dialect.hpp
/// Heidenhain conversational (Klartext) programs, as an entry of `program::dialects`: the reader
/// (lexer.hpp → reader.hpp, motion.hpp), the writer (writer.hpp), and what the dialect declares
/// of itself. The full description, with examples, is docs/dialects/heidenhain.md.
///
/// ```cpp
/// namespace hh = kin5::program::heidenhain;
/// auto r = hh::read("15 L X+34.983 Y+118.526 Z+9.1 B+17.067 C+87.479 R0 F1137 M128\n", "part.h");
/// if (r.ok()) std::string text = hh::write(r.parsed);  // "0 L X+34.983 … M128\n"
/// ```
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "../block.hpp"
#include "../dialect_id.hpp"
#include "../read_limits.hpp"
#include "reader.hpp"
#include "writer.hpp"

namespace kin5::program::heidenhain {

/// Reads a Heidenhain conversational program. Never throws on bad input: problems are in
/// `errors` (and `warnings`), each at the offending word's line and column.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(id_named("heidenhain"), text, std::move(file_name), static_cast<block_reader>(&read_blocks));
}

/// The Heidenhain conversational dialect: its id, capabilities, file markers, reader and writer.
struct dialect {
  static constexpr std::string_view name = "heidenhain";
  static constexpr capabilities can{.tcp_switch = true, .rotary_axis_words = true, .tool_axis_vectors = true,
                                    .arcs = true, .arc_centre_block = true, .tool_names = true,
                                    .work_offsets = {{{work_offset_family::preset, 0, 65535}}}};
  static constexpr std::array<marker, 3> markers{{{"BEGIN PGM", marker::place::block_start},
                                                  {"M128", marker::place::anywhere},
                                                  {"FUNCTION TCPM", marker::place::anywhere}}};
  /// TNC 640 User's Manual DIN/ISO 1/2015, §19.3 p. 631 (also Cycle 9's dwell); M91/M92 move in
  /// machine coordinates and a TNC has no standard M7 (docs/dialects/heidenhain.md).
  static constexpr controller reads{.usual = {3, 3, 1, 7}, .finest = {4, 4, 3, 7}, .m7_mist_coolant = false,
                                    .m91_m92_machine_coordinates = true, .dwell = detail::dwell_steps};
  /// Catalog machines whose controller reads it (Tian 2010's DMU 80P; Liu 2010's DMU 50V).
  static constexpr std::array<std::string_view, 2> default_for{"dmu-80p", "dmu-50v"};
  /// Kept words a comment would lose: TOOL CALL's tool axis when it is not Z.
  static constexpr std::array<kept_word_effect, 2> lost_as_comment{
      {{"X", kept_word_effect::match::whole, "a tool axis other than Z in TOOL CALL"},
       {"Y", kept_word_effect::match::whole, "a tool axis other than Z in TOOL CALL"}}};
  using write_options = heidenhain::write_options;
  using writer = heidenhain::writer;
  static void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                          const block_sink& on_block) {
    heidenhain::read_blocks(text, file_name, diagnostics, on_block);
  }
  /// The same, running at most `limits.max_executed_lines` lines.
  static void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                          const block_sink& on_block, const read_limits& limits) {
    heidenhain::read_blocks(text, file_name, diagnostics, on_block, interp::execution_limits{limits.max_executed_lines});
  }
  static std::string write(const program& p, const write_options& options) { return heidenhain::write(p, options); }
};

}  // namespace kin5::program::heidenhain
