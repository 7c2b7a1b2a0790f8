/// @file program/linuxcnc/dialect.hpp
/// LinuxCNC G code (RS274NGC as LinuxCNC's interpreter reads it), as an entry of
/// `program::dialects`: the reader (lexer.hpp → reader.hpp, built on ISO's), the writer
/// (writer.hpp, built on ISO's), and what the dialect declares of itself. Not ISO: no G43.4,
/// G43.5, G54.1 or G68.2; tool-tip tracking is a kinematics switch (`M428` / `M429` in the 5-axis
/// trt configurations, `G12.1 P1` / `G13.1`); `G43` without H is the loaded tool's length; G4 P
/// is seconds; o-words. docs/dialects/linuxcnc.md lists every word with its manual section.
///
/// ```cpp
/// namespace lc = kin5::program::linuxcnc;
/// auto r = lc::read("T1 M6\nG43\nM428\nG1 X10 A-5 C20 F800\n", "part.ngc");
/// if (r.ok()) std::string text = lc::write(r.parsed);
/// ```
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "../block.hpp"
#include "../dialect_id.hpp"
#include "reader.hpp"
#include "writer.hpp"

namespace kin5::program::linuxcnc {

/// Reads LinuxCNC G code. Never throws on bad input: problems are in `errors`.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(id_named("linuxcnc"), text, std::move(file_name), &read_blocks);
}

/// The LinuxCNC dialect: its capabilities, file markers, reader and writer.
struct dialect {
  static constexpr std::string_view name = "linuxcnc";
  static constexpr capabilities can{.inverse_time_feed = true, .tcp_switch = true, .rotary_axis_words = true,
                                    .arcs = true, .work_offsets = {{{work_offset_family::g54, 1, 9}}}};
  /// The kinematics switches of its 5-axis configurations: no other dialect writes them.
  static constexpr std::array<marker, 2> markers{{{"M428", marker::place::anywhere},
                                                  {"M429", marker::place::anywhere}}};
  /// LinuxCNC reads any decimals (User Manual, "G-code Overview", "Numbers"); feeds and speeds
  /// to the ISO reader's finest, which it shares; `( … )` are comments. M6, M5 and M9 act before
  /// the line's move ("G-code Overview", "G-code Order of Execution": change tool, spindle and
  /// coolant come before "perform motion", stops after it).
  static constexpr controller reads{.usual = {3, 3, 1, 7}, .finest = {6, 6, 3, 7}, .paren_comments = true,
                                    .dwell = linuxcnc::dwell_steps, .spindle_off_before_motion = true,
                                    .tangent_compensation_entry = true};
  /// Catalog machines whose controller reads it: LinuxCNC's own 5-axis simulation machines.
  static constexpr std::array<std::string_view, 2> default_for{"xyzac-trt", "xyzbc-trt"};
  /// Kept words a comment would lose: none (its dwell is `state.dwell_s`).
  static constexpr std::array<kept_word_effect, 0> lost_as_comment{};
  using write_options = linuxcnc::write_options;
  using writer = linuxcnc::writer;
  static void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                          const block_sink& on_block) {
    linuxcnc::read_blocks(text, file_name, diagnostics, on_block);
  }
  static std::string write(const program& p, const write_options& options) { return linuxcnc::write(p, options); }
};

}  // namespace kin5::program::linuxcnc
