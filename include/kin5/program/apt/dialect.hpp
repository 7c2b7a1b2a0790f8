/// @file program/apt/dialect.hpp
/// APT cutter-location data (CL data), as an entry of `program::dialects`: the reader
/// (lexer.hpp → reader.hpp), the writer (writer.hpp), and what the dialect declares of itself.
/// One block per statement (`MAJOR/args`, with `$` at a line end continuing it on the next line).
/// Numbers are plain decimals (program/number.hpp). docs/dialects/apt.md lists every statement.
///
/// ```cpp
/// auto r = kin5::program::apt::read("GOTO/10,0,5,0,0,1\n", "part.cls");
/// std::string text = kin5::program::apt::write(r.parsed);   // "GOTO/10,0,5,0,0,1\n"
/// ```
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "../block.hpp"
#include "../dialect_id.hpp"
#include "reader.hpp"
#include "writer.hpp"

namespace kin5::program::apt {

/// Reads APT CL data. Never throws on bad input: problems are in `errors`.
inline read_result read(std::string_view text, std::string file_name) {
  return read_whole(id_named("apt"), text, std::move(file_name), &read_blocks);
}

/// The APT CL data dialect: its id, capabilities, file markers, reader and writer.
struct dialect {
  static constexpr std::string_view name = "apt";
  static constexpr capabilities can{.cl_data = true, .inverse_time_feed = true, .tool_axis_vectors = true, .arcs = true};
  static constexpr std::array<marker, 3> markers{{{"PARTNO", marker::place::block_start},
                                                  {"GOTO/", marker::place::block_start},
                                                  {"FEDRAT/", marker::place::block_start}}};
  /// CL data: no controller; the CAM system's arithmetic.
  static constexpr controller reads{.usual = {3, 3, 1, 7}, .finest = {6, 6, 6, 9}, .dwell = detail::dwell_steps};
  /// No machine reads CL data.
  static constexpr std::array<std::string_view, 0> default_for{};
  /// Its reader keeps no word a comment would lose.
  static constexpr std::array<kept_word_effect, 0> lost_as_comment{};
  using write_options = apt::write_options;
  using writer = apt::writer;
  static void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                          const block_sink& on_block) {
    apt::read_blocks(text, file_name, diagnostics, on_block);
  }
  static std::string write(const program& p, const write_options& options) { return apt::write(p, options); }
};

}  // namespace kin5::program::apt

// The CL writer asks the source dialect's controller and kept words (`controller_from`,
// `lost_from`, writer.hpp), which the list defines: of the dialects' headers, this one alone
// includes the list, at its end.
#include "../dialect.hpp"
