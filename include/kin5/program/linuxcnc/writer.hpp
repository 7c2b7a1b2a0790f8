/// @file program/linuxcnc/writer.hpp
/// Blocks written as LinuxCNC G code: the ISO writer (iso/writer.hpp) writes each block's line,
/// and this one writes what LinuxCNC spells otherwise, in front of it: tool-tip tracking as
/// `M428` / `M429` (the remaps of the 5-axis trt configurations), tool length as `G43` [`H n`] /
/// `G49`, work offsets 1 … 9 as `G54` … `G59.3`, a program name as a comment. A program read in
/// another dialect is framed by `%` lines (the first line, and the last, written by `finish`), never
/// by a copy of the other dialect's frame, refuses a block after its end unless it is only a
/// comment (program_end.hpp), and gets around each tool
/// change what tracking needs there: `M429` before the `M6`, `G43` and `M428` after; tracking
/// switched on gets a `G43` first when the loaded tool's length is not in effect. A tool-axis
/// vector (LinuxCNC has no G43.5) and a work offset LinuxCNC does not select throw
/// `std::invalid_argument` naming the block's `file:line`. Cutter radius compensation is written
/// as ISO writes it; where its entry or exit would run differently here the translation has
/// refused it already (translate/compensation_ends.hpp). A dwell is `G4 P…` (seconds), a line of its own.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../dialect_id.hpp"
#include "../dwell.hpp"
#include "../number.hpp"
#include "../iso/writer.hpp"
#include "../machine_functions.hpp"
#include "../program_end.hpp"
#include "../text.hpp"
#include "../tool_length.hpp"
#include "../work_offsets.hpp"
#include "lexer.hpp"
#include "vocabulary.hpp"

namespace kin5::program::linuxcnc {

/// Decimals written for each kind of number: as ISO's (`iso::write_options`).
struct write_options : iso::write_options {};

/// Writes blocks as LinuxCNC G code one at a time (see the file comment), in constant memory.
class writer {
 public:
  /// A writer for blocks read from `source`: the ISO writer writes LinuxCNC's own kept words and
  /// `%` lines back as they are, another dialect's as comments.
  explicit writer(dialect_id source, std::string file = {}, const write_options& chosen = {})
      : same_(source == id_named("linuxcnc")),
        iso_(same_ ? id_named("iso") : id_named("linuxcnc"), std::move(file), iso_options(chosen)) {}

  /// Appends the lines of block `b` to `out`; throws `std::invalid_argument` naming the block
  /// when LinuxCNC cannot say it.
  void write(std::string& out, const block& b) {
    // Another dialect's comment that reads as an active one here (`; ABORT, …` would stop the
    // program, `; PY, …` run Python): written with `- ` before it, a plain comment.
    if (!same_ && ((b.comment && acts(*b.comment)) || (b.passthrough && acts(b.text)))) {
      block quiet = b;
      if (b.comment && acts(*b.comment)) quiet.comment = "- " + *b.comment;
      if (b.passthrough && acts(b.text)) quiet.text = "- " + b.text;
      return write(out, quiet);
    }
    if (!same_) {
      if (b.framing) return;  // another dialect's frame (`%`, `;$PATH=`): the `%` lines stand for it
      if (end_.after_end(b)) {
        if (b.comment && !b.comment->empty()) out += iso::detail::as_comment(*b.comment) + '\n';
        return;
      }
      if (!opened_) out += "%\n", opened_ = true;
    }
    if (b.passthrough) return iso_.write(out, b);
    if (b.alarm) {  // a line of its own, before the block's other words (the comment acts first)
      if (abort(out, b)) return;
    }
    if (b.state.dwell_s) return dwell(out, b);
    if (b.axes.tool_axis) fail(b, "a tool-axis vector (LinuxCNC has no G43.5; its trt kinematics take A, B, C words)");
    std::vector<std::string> own, length;
    std::string before, after;
    if (b.tool_name)  // LinuxCNC's T takes a number: a name is not written as something else
      fail(b, "a tool by name (\"" + *b.tool_name + "\") has no LinuxCNC form (T takes a number; --tool-map NAME=n gives one)");
    if (b.tool) selected_ = *b.tool;
    if (!same_) source_.apply(b);
    tool_change(b, before, after);  // M6 runs before G43 of the same line (its order of execution)
    own_words(b, own, length);
    // LinuxCNC runs M428/M429 (user M codes) before G43/G49 of the same line ("G-code Order of
    // Execution"): a switch of another dialect gets its length on a line of its own, G43 before
    // M428, G49 after M429.
    const bool length_line = !same_ && b.tcp && !length.empty();
    if (!length_line) own.insert(own.end(), length.begin(), length.end());
    if (length_line && *b.tcp) before += with_words("", length);
    tracking(b, own, before);
    if (length_line && !*b.tcp) (b.moves() || changes_tool(b) ? before : after) += with_words("", length);
    if (!same_ && tracking_ && !length_of_loaded_ && is_motion(b))
      fail(b, "a move under tracking while G43 does not hold the loaded tool's length (G43 H n of another tool, or "
              "G49): the TCP kinematics take the tool length from G43");
    std::string line;
    iso_line(line, b);
    out += before + with_words(line, own) + after;
  }

  /// The closing `%` of a program read in another dialect (LinuxCNC User Manual, "G-code
  /// Overview", File requirements: a file demarcated by `%` lines, the first and the last).
  /// Call once, after the last `write`.
  void finish(std::string& out) {
    if (opened_ && !closed_) out += "%\n", closed_ = true;
  }

 private:
  bool same_;  // the blocks were read as LinuxCNC
  iso::writer iso_;
  bool opened_ = false, closed_ = false;  // the `%` lines written (another dialect's program)
  source_end end_;                        // where another dialect's program stops running
  bool tracking_ = false;                 // M428 in effect after the last block
  bool length_of_loaded_ = false;         // G43 holds the loaded tool's length
  modal_state source_;                    // the source program's state after the block (another dialect's)
  std::optional<long long> selected_, loaded_;

  /// LinuxCNC reads `X10` as 10 mm (LinuxCNC Manual, "G-Code Overview", numbers): no point needed.
  static iso::write_options iso_options(iso::write_options o) {
    o.decimal_point = false;
    o.frame = false;  // framed here, by `%` lines only
    o.whole_spindle_speed = false;  // S is a real (LinuxCNC User Manual, "G-code Overview", "S")
    o.stored_homes = true;          // G28 / G30: parameters #5161–#5166 / #5181–#5186 ("G28, G28.1")
    return o;
  }

  [[noreturn]] static void fail(const block& b, const std::string& why) {
    throw std::invalid_argument(b.where.file + ":" + std::to_string(b.where.line) +
                                ": block cannot be written in LinuxCNC: " + why);
  }

  /// `N10 G4 P1.5 (comment)`: a dwell, P in seconds and as many decimals as it has (LinuxCNC
  /// User Manual, "G-Codes", G4), in a block of its own as every dialect reads it.
  static void dwell(std::string& out, const block& b) {
    if (!b.only_dwell()) fail(b, "a dwell with other words (G4 takes a block of its own)");
    if (const std::string why = dwell_refusal(dwell_steps, *b.state.dwell_s); !why.empty()) fail(b, why);
    std::string line = b.number ? "N" + std::to_string(*b.number) + " G4 P" : std::string("G4 P");
    line += format_number(*b.state.dwell_s, dwell_steps.decimals);
    if (b.comment) line += " " + iso::detail::as_comment(*b.comment);
    out += line + '\n';
  }

  /// `N10 (ABORT, message)`: an alarm stop (User Manual, "G-code Overview", "Abort Messages");
  /// LinuxCNC numbers no alarm, so another dialect's number is not written. A message that
  /// would end the comment early or open another is refused.
  /// The block's comment goes before the abort on its line when the block says nothing else and
  /// the comment fits parentheses; whether the block is written whole.
  static bool abort(std::string& out, const block& b) {
    const std::string& message = b.alarm->message;
    if (message.find_first_of("()\n\r") != std::string::npos)
      fail(b, "an alarm message with parentheses or a line break has no LinuxCNC form ((ABORT, …) ends at the first "
              "')'): remove them from the message");
    std::string line = b.number ? "N" + std::to_string(*b.number) + " " : std::string();
    const bool with_comment = b.comment && !b.comment->empty() && b.only_alarm_and_comment() &&
                              b.comment->find_first_of("()\n\r") == std::string::npos && !acts(*b.comment);
    if (with_comment) line += "(" + *b.comment + ") ";
    out += line + (message.empty() ? "(ABORT,)\n" : "(ABORT, " + message + ")\n");
    return b.only_alarm() || with_comment;
  }

  /// Work offset, G43 [H n] / G49: LinuxCNC Manual, "G-Codes", G54–G59.3 and G43, G49.
  void own_words(const block& b, std::vector<std::string>& own, std::vector<std::string>& length) {
    if (const auto& w = b.state.work_offset) {
      if (w->family != work_offset_family::g54 || w->number < 1 || w->number > 9)
        fail(b, "work offset " + kin5::program::spelling(*w) + " has no LinuxCNC form (G54 … G59.3; --work-offset-map names one)");
      own.push_back(kin5::program::spelling(*w));
    }
    if (const auto& on = b.state.length_compensation) {
      length.push_back(*on ? "G43" : "G49");
      const auto& h = b.state.length_register;
      if (*on && h) length.push_back("H" + std::to_string(*h));
      length_of_loaded_ = *on && (!h || (loaded_ && *h == *loaded_));
    }
  }

  static bool changes_tool(const block& b) { return kin5::program::changes_tool(b); }

  /// Another dialect's tool change under tracking: identity kinematics for the change (M429),
  /// then the new tool's length and tracking again.
  void tool_change(const block& b, std::string& before, std::string& after) {
    if (!changes_tool(b)) return;
    loaded_ = selected_;
    length_of_loaded_ = false;
    if (same_ || !tracking_ || b.tcp) return;
    before += "M429\n";
    after += "G43\nM428\n";
    // G43 is the new tool's length; the source's may still be another register's (ISO G43.4 H1
    // kept over T2 M6): then its next move is refused (`write`).
    length_of_loaded_ = length_in_effect(source_) != tool_length::other;
  }


  /// M428 / M429: in the block's line, or on a line of their own before a block that moves or
  /// changes the tool (the reader refuses a switch on such a line).
  void tracking(const block& b, std::vector<std::string>& own, std::string& before) {
    if (!b.tcp) return;
    const std::string word = *b.tcp ? "M428" : "M429";
    if (*b.tcp && !same_ && !length_of_loaded_ && !b.state.length_compensation) before += "G43\n", length_of_loaded_ = true;
    if (b.moves() || changes_tool(b)) before += word + "\n";
    else own.push_back(word);
    tracking_ = *b.tcp;
  }

  /// The ISO writer's line of `b` without what this writer writes itself.
  void iso_line(std::string& line, const block& b) {
    block rest = b;
    if (rest.alarm) rest.alarm.reset(), rest.text.clear();  // written already (`abort`)
    rest.tcp.reset();
    rest.state.work_offset.reset();
    rest.state.length_compensation.reset();
    rest.state.length_register.reset();
    if (b.program_begin) rest.comment = "PROGRAM " + *b.program_begin + (b.comment ? " " + *b.comment : "");
    rest.program_begin.reset();
    try {
      iso_.write(line, rest);
    } catch (const std::invalid_argument& e) {
      std::string why = e.what();
      const std::string iso = "cannot be written in ISO";
      if (const auto at = why.find(iso); at != std::string::npos) why.replace(at, iso.size(), "cannot be written in LinuxCNC");
      throw std::invalid_argument(why);
    }
  }

  /// `line` with `own` words after its block number (the ISO writer writes one line).
  static std::string with_words(const std::string& line, const std::vector<std::string>& own) {
    if (own.empty()) return line;
    std::string words;
    for (const std::string& w : own) words += (words.empty() ? "" : " ") + w;
    if (line.empty()) return words + "\n";  // the ISO writer had nothing to say
    std::size_t at = 0;
    if (!line.empty() && line[0] == 'N') {
      at = 1;
      while (at < line.size() && is_digit(line[at])) ++at;
      if (at < line.size() && line[at] == ' ') ++at;
    }
    const bool more = at < line.size() && line[at] != '\n';
    std::string out = line.substr(0, at);
    if (at > 0 && out.back() != ' ') out += ' ';
    return out + words + (more ? " " : "") + line.substr(at);
  }
};

/// Writes `p` as LinuxCNC G code (see the file comment).
inline std::string write(const program& p, const write_options& options = {}) {
  writer w(p.language, p.file, options);
  std::string out;
  for (const block& b : p.blocks) w.write(out, b);
  w.finish(out);
  return out;
}

}  // namespace kin5::program::linuxcnc
