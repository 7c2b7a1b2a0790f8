/// @file program/haas/writer.hpp
/// Blocks written as Haas mill G code: the ISO writer (iso/writer.hpp) with Haas's codes
/// (`haas_spelling`): tool center point control `G234 H n` where ISO writes `G43.4 H n` (also
/// after a tool change under TCPC), `G49` off; additional work offsets `G154 P1` … `P99`; a
/// dwell `G4 P1.5`, seconds with a decimal point; the program framed by `%`, `O` and its number,
/// `%` as ISO frames it. A tool-axis vector (Haas has no G43.5), a tool called by name and a work
/// offset Haas does not select throw `std::invalid_argument` naming the block's `file:line`.
/// docs/dialects/haas.md gives the manual's section for each form.
#pragma once

#include <string>
#include <utility>

#include "../block.hpp"
#include "../dialect_id.hpp"
#include "../iso/writer.hpp"
#include "vocabulary.hpp"

namespace kin5::program::haas {

/// Decimals written for each kind of number: as ISO's (`iso::write_options`); the spelling is
/// always Haas's.
struct write_options : iso::write_options {};

/// Writes blocks as Haas G code one at a time (see the file comment), in constant memory.
class writer {
 public:
  /// A writer for blocks read from `source`: the ISO writer writes a Haas program's own kept
  /// words and passthrough lines back as they are, another dialect's as comments.
  explicit writer(dialect_id source, std::string file = {}, const write_options& chosen = {})
      : iso_(source == id_named("haas") ? id_named("iso") : id_named("haas"), std::move(file), haas_options(chosen)) {}

  /// Appends the line of block `b` to `out`; throws `std::invalid_argument` naming the block
  /// when Haas cannot say it.
  void write(std::string& out, const block& b) { iso_.write(out, b, false); }

  /// `M30` when the source gave no end, then `%` (a program read in another dialect).
  void finish(std::string& out) { iso_.finish(out); }

 private:
  iso::writer iso_;

  static iso::write_options haas_options(iso::write_options o) {
    o.spell = haas_spelling;
    return o;
  }
};

/// Writes `p` as Haas G code (see the file comment).
inline std::string write(const program& p, const write_options& options = {}) {
  write_options chosen = options;
  if (!chosen.program_name) chosen.program_name = name_of(p);
  writer w(p.language, p.file, chosen);
  std::string out;
  for (const block& b : p.blocks) w.write(out, b);
  w.finish(out);
  return out;
}

}  // namespace kin5::program::haas
