/// @file program/block.hpp
/// The dialect-neutral model of an NC program: a sequence of blocks, each remembering where it
/// came from (file, line, column) and what it says: lengths in millimetres (an inch program's
/// reader converts, exactly, ×25.4; `metric` says which unit the text used), angles in degrees.
///
/// Readers (one per dialect, `program/<dialect>/`) build it; writers turn it back
/// into text; the translator maps the motion content between machines and keeps the rest in
/// order. A block holds only what its source text says: modal state (the motion mode, the last
/// position, whether tool-tip tracking is on) is the consumer's to carry, with `modal_state`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "../core/vec.hpp"
#include "alarm_stop.hpp"
#include "call_chain.hpp"
#include "dialect_id.hpp"
#include "printable.hpp"
#include "resolution.hpp"
#include "source_location.hpp"
#include "state_words.hpp"

namespace kin5::program {

/// Motion commanded by a block.
enum class motion_kind {
  rapid,    ///< G0, FMAX, RAPID
  linear,   ///< G1, L, GOTO
  arc_cw,   ///< G2, C DR-
  arc_ccw,  ///< G3, C DR+
};

/// How F is to be read.
enum class feed_unit {
  per_minute,    ///< G94: mm/min (tool-tip speed under TCP)
  inverse_time,  ///< G93: 1 / block time in minutes
};

/// Axis words of a block as written: absolute values, millimetres and degrees.
struct axis_words {
  std::optional<double> x_mm, y_mm, z_mm;
  std::optional<double> a_deg, b_deg, c_deg;
  /// Tool-axis vector written in the block (APT `GOTO/x,y,z,i,j,k`, G43.5 `I J K`,
  /// Heidenhain `LN … TX TY TZ`), as written (not necessarily unit).
  std::optional<vec3> tool_axis;

  friend bool operator==(const axis_words&, const axis_words&) = default;

  bool has_linear() const { return x_mm || y_mm || z_mm; }
  bool has_rotary() const { return a_deg || b_deg || c_deg; }
  bool empty() const { return !has_linear() && !has_rotary() && !tool_axis; }
};

/// Circle data of G2/G3 or Heidenhain CC/C/CR.
struct arc_words {
  arc_plane plane = arc_plane::xy;
  std::optional<vec3> centre_mm;     ///< absolute centre, when the dialect gives one
  std::optional<double> radius_mm;   ///< signed radius (CR / R), when given instead
  friend bool operator==(const arc_words&, const arc_words&) = default;
};

/// Where the axis words of a block in machine coordinates (`block::machine_coordinates`) take
/// the axes, as each control defines it (docs/dialects/*.md, "Machine coordinates").
enum class machine_position {
  machine_zero,      ///< positions from the machine's zero: G53, SUPA, Siemens G53/G153, M91
  reference_point,   ///< G28 (Fanuc, Haas): each axis named to its reference point, through the
                     ///< intermediate point the words give (part coordinates, G90 or G91)
  second_reference,  ///< G30: each axis named to the second reference point, through the words' point
  stored_position,   ///< LinuxCNC G28: to the position the control keeps in parameters
                     ///< #5161–#5166, through the words' point
  second_stored_position,  ///< LinuxCNC G30: to the one in #5181–#5186, through the words' point
  builder_position,  ///< M92: positions from a point the machine builder sets
  /// Heidenhain `M140 MB MAX`: along the tool axis to the end of the travel, away from the part;
  /// the block has no axis words.
  tool_axis_limit,
};

/// One block of an NC program (one line; an APT statement with its `$` continuations).
struct block {
  source_location where;              ///< first character of the block
  /// The calls open when the block ran, as an id into the run's `call_chains`
  /// (`read_result::calls`); 0: none, the block ran at the top level.
  std::uint32_t call_chain = 0;
  std::string text;                   ///< source text without the line ending
  std::optional<long long> number;    ///< N number or Heidenhain block number

  std::optional<std::string> program_begin;  ///< BEGIN PGM / % O… / PARTNO: the program name
  /// Set on the block that ends the program text: END PGM, M2 / M30 (Siemens, ISO), FINI. An M
  /// code that ends the program lives here only, never also in `m_codes`, so a writer writes
  /// one end per block (Siemens and ISO writers never write M2 / M30 twice in a block). The value
  /// is the program's name where known (END PGM name, the Siemens `%_N_` header's), "M2" or
  /// "M30" when the source wrote that word and gives no name (ISO; Siemens M2), else empty.
  /// In Heidenhain the text ends at END PGM: an M2 / M30 on an M line there is an ordinary M
  /// function in `m_codes`.
  std::optional<std::string> program_end;
  std::optional<std::string> comment;        ///< comment text, without its delimiters
  std::optional<bool> tcp;                   ///< tool-tip tracking switched on (true) or off (false)
  std::optional<feed_unit> feed_mode;        ///< G93 / G94
  std::optional<bool> metric;                ///< G71/G21/MM (true), G70/G20/INCH (false)
  std::optional<long long> tool;             ///< tool call / T number
  std::optional<std::string> tool_name;      ///< TOOL CALL "NAME", T="NAME": the tool by name
  std::optional<double> spindle_rpm;         ///< S
  /// M functions whose meaning is the machine maker's (M428, M126, …), as read. Those with one
  /// meaning in every dialect are state words instead (`state`; machine_functions.hpp), the
  /// program end is `program_end`, TCP switches `tcp`.
  std::vector<int> m_codes;
  std::optional<motion_kind> motion;         ///< set when the block commands a motion word (G0-G3, L, C)
  axis_words axes;                           ///< axis words present in the block
  std::optional<arc_words> arc;              ///< circle data of an arc block
  std::optional<double> feed;                ///< F: mm/min per minute (inch/min converted), 1/min in inverse time
  bool feed_rapid = false;                   ///< FMAX / RAPID: the move is at rapid traverse
  /// Axis words in machine coordinates (G53, G28/G30 intermediate points, M91/M92): not
  /// workpiece positions, so never run through kinematics.
  bool machine_coordinates = false;
  /// What the axis words of a block in machine coordinates name; `machine_zero` otherwise.
  machine_position machine_reference = machine_position::machine_zero;
  /// Words the reader recognised as not changing geometry (G17, G40, G54, G90, G64, H1, D1, …),
  /// as written. The writer of the same dialect writes them back in place; a writer of another
  /// dialect writes them into a comment, so nothing is lost silently.
  std::vector<std::string> kept_words;
  /// Not understood and with no axis words: written back unchanged (same dialect) or
  /// carried as text (another dialect) — never interpreted.
  bool passthrough = false;
  /// Text that only frames the program for transfer or storage, with no effect on motion: the
  /// tape marks `%` of ISO and LinuxCNC, Siemens `;$PATH=…`. The writer of the same dialect
  /// writes it back; a writer of another dialect writes its own frame instead, never this text.
  bool framing = false;
  /// A number assigned to a parameter (`#1=500.`, `R1=5000`, `Q1 = 5000`): the reader recorded
  /// it and puts it in every word that uses the parameter, so the block itself does nothing.
  /// Kept as text like `passthrough` (a comment in another dialect), but understood: no
  /// "not understood" warning.
  bool assignment = false;
  /// Tool change, compensation, spindle, coolant, work offset, plane, distance mode, dwell and
  /// stop, as the text says them (state_words.hpp). Readers fill these instead of `m_codes` and
  /// `kept_words` for the words they map, so every such word has one meaning in every dialect.
  state_words state;
  /// The program stops here with an alarm and its message (alarm_stop.hpp).
  std::optional<alarm_stop> alarm;

  /// Whether the block moves any axis.
  bool moves() const { return !axes.empty(); }

  /// The block without where it stands and how it was written: no location, call chain, text
  /// or number.
  block unplaced() const {
    block rest = *this;
    rest.where = {};
    rest.call_chain = 0;
    rest.text.clear();
    rest.number.reset();
    return rest;
  }

  /// Whether the block is a dwell and says nothing else but its number and comment: the block
  /// of its own every dialect's dwell takes (program/dwell.hpp).
  bool only_dwell() const {
    block rest = unplaced();
    rest.comment.reset();
    rest.state.dwell_s.reset();
    return state.dwell_s && rest == block{};
  }

  /// Whether the block is an alarm stop and says nothing else but its number: what every
  /// dialect's reader gives (LinuxCNC's ABORT may share its line; it acts first).
  bool only_alarm() const {
    block rest = unplaced();
    rest.alarm.reset();
    return alarm && rest == block{};
  }

  /// Whether the block is an alarm stop with at most a comment besides its number.
  bool only_alarm_and_comment() const {
    block rest = *this;
    rest.comment.reset();
    return rest.only_alarm();
  }

  friend bool operator==(const block&, const block&) = default;
};

/// A program as read: its blocks in file order.
struct program {
  dialect language{};  ///< the first entry of `program::dialects` unless a reader sets it
  std::string file;
  std::vector<block> blocks;
};

/// Where a streaming reader (`read_blocks`) puts each block it has read, in file order.
using block_sink = std::function<void(block&&)>;

/// A problem found in the input, tied to the place it was found.
struct diagnostic {
  source_location where;
  std::string message;
  /// The construct refused or warned about, by the name `--allow` takes ("unset-rotary"), when
  /// it has one; empty otherwise.
  std::string construct{};
  /// The option that resolves it ("--allow unset-rotary", "--angle-tolerance"), when one does.
  std::string option{};
  /// The calls open at `where` when it ran inside a called subprogram or file, outermost first
  /// (call_chain.hpp); empty at the top level.
  std::vector<source_location> called_from{};

  /// Calls noted one by one in `to_string`, at most: the innermost; then the outermost says how
  /// many were left out (a call nested 64 deep).
  static constexpr std::size_t calls_noted = 8;

  /// `FILE:LINE:COL: error: message`, the format compilers use, so editors can jump to it, then
  /// for each open call, innermost first, a line `FILE:LINE:COL: note: called from here` (at
  /// most `calls_noted` of them and the outermost). The file name and the message may quote the
  /// input: bytes a terminal acts on are written `\xHH` (printable.hpp), so a program cannot
  /// send escape sequences through a diagnostic.
  std::string to_string(std::string_view severity = "error") const {
    std::string out = located(where);
    out.append(severity).append(": ").append(printable(message));
    const std::size_t n = called_from.size();
    for (std::size_t k = 0; k < n; ++k) {  // innermost first
      if (k == calls_noted && k + 1 < n) {
        out.append("\n").append(located(called_from.front())).append("note: called from here, through ");
        out.append(std::to_string(n - calls_noted - 1)).append(" more calls not shown");
        break;
      }
      out.append("\n").append(located(called_from[n - 1 - k])).append("note: called from here");
    }
    return out;
  }

 private:
  static std::string located(const source_location& at) {
    return printable(at.file.str()) + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": ";
  }
};

/// Diagnostics of one severity a reader keeps. Readers keep going after an error so that one
/// run lists them all, but only the first `max_kept_diagnostics` are kept and the others
/// counted, so that reading takes bounded memory whatever the input (4 MiB of NUL bytes are
/// 4,194,304 errors). The tool prints the first 100 of each severity in source order and the
/// count of the rest.
inline constexpr std::size_t max_kept_diagnostics = 1000;

/// Appends `d` to `kept` while it holds fewer than `max_kept_diagnostics`; else counts it in `more`.
inline void keep_or_count(std::vector<diagnostic>& kept, std::size_t& more, diagnostic&& d) {
  if (kept.size() < max_kept_diagnostics) kept.push_back(std::move(d));
  else ++more;
}
/// A reader's result: the program and its diagnostics; one with errors must not be translated.
struct read_result {
  program parsed;
  std::vector<diagnostic> errors;    ///< the first `max_kept_diagnostics` found (`add_error`)
  std::vector<diagnostic> warnings;  ///< accepted, but worth a look (printed as "warning:")
  std::size_t errors_not_kept = 0;   ///< errors found after the first `max_kept_diagnostics`
  std::size_t warnings_not_kept = 0;
  /// The call chains of the blocks read (`block::call_chain`): those the program's executor
  /// opened (interp/executor.hpp).
  call_chains calls{};
  /// The chain of the line being read (0: the top level): a reader running a program sets it
  /// before reading each line, stamps it on the line's blocks, and the errors and warnings
  /// added meanwhile say where they were called from (`diagnostic::called_from`).
  std::uint32_t reading_call = 0;
  void add_error(diagnostic d) { keep_or_count(errors, errors_not_kept, called(std::move(d))); }
  void add_warning(diagnostic d) { keep_or_count(warnings, warnings_not_kept, called(std::move(d))); }
  /// `d` with the calls open while the line being read runs, unless it has its own.
  diagnostic called(diagnostic d) const {
    if (reading_call != 0 && d.called_from.empty()) d.called_from = calls.sites(reading_call);
    return d;
  }
  std::size_t error_count() const { return errors.size() + errors_not_kept; }
  std::size_t warning_count() const { return warnings.size() + warnings_not_kept; }
  /// How finely the text writes its numbers. The streaming driver fills it from the text
  /// (`scan_resolution`) where the reader leaves it empty.
  number_resolution resolution{};
  bool ok() const { return errors.empty(); }
};

/// A dialect's streaming reader: calls the sink with each block of `text` in file order, and
/// puts errors and warnings in the `read_result` (whose `parsed` it leaves alone).
using block_reader = void (*)(std::string_view text, const std::string& file_name, read_result& diagnostics,
                              const block_sink& on_block);

/// The whole program `read_blocks` reads from `text`, blocks in file order, with its diagnostics:
/// each dialect's `read` is this.
inline read_result read_whole(dialect language, std::string_view text, std::string file_name,
                              block_reader read_blocks) {
  read_result result;
  result.parsed.language = language;
  result.parsed.file = std::move(file_name);
  read_blocks(text, result.parsed.file, result, [&](block&& b) { result.parsed.blocks.push_back(std::move(b)); });
  return result;
}

}  // namespace kin5::program
