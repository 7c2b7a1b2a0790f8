/// @file program/linuxcnc/reader.hpp
/// The LinuxCNC (RS274NGC) reader: ISO's reader (iso/reader.hpp) with the words LinuxCNC reads
/// otherwise (`own_words`), read first. Where the grammar is ISO's (G0–G3, G17–G19, G20/G21,
/// G90, G93/G94, T, M6, M3–M5, M7–M9, M0/M1, M2/M30, `( … )` and `;` comments, `%`) the ISO
/// reader reads it. LinuxCNC's own:
/// | words | read as |
/// |---|---|
/// | `M428`, `G12.1 P1` | tool-tip tracking on (the TCP kinematics of the 5-axis trt configurations) |
/// | `M429`, `G13.1` | tracking off (identity kinematics) |
/// | `G43` (the loaded tool: its number is the register once an M6 has said it), `G43 H n` (tool n's table entry), `G49` | `state.length_compensation`, `length_register` |
/// | `G41`/`G42` (the loaded tool's radius), `G41 D n`/`G42 D n` (tool n's), `G40` | `state.radius_compensation`, `radius_register` |
/// | `G54` … `G59`, `G59.1` … `G59.3` | `state.work_offset` 1 … 9 |
/// | `G64 P… Q…`, `G91.1` | kept words (path blending tolerance, incremental arc centres: the default) |
/// The lines run through the interpreter with LinuxCNC's statements (statements.hpp: o-words,
/// parameter settings) and parameters (parameter_rules.hpp): numbered (`#1 = 5000`) or named
/// (`#<feed> = [#1 * 2]`, `F#<feed>`; the name read in lower case without blanks), words whose
/// value is a parameter or an expression evaluated as in ISO (iso/reader.hpp). Setting or reading
/// a predefined one (`#<_x>`) is refused.
/// Refused at the word: `M430`, `G12.1` with another type, a kinematics switch on a line with
/// motion or M6, `G43.1`/`G43.2`, ISO codes LinuxCNC does not have (`G43.4`, `G43.5`, `G54.1`,
/// `G50`), `(ABORT, …)` and `(PY, …)` as a line's last comment (lexer.hpp), splines `G5`–`G5.3`, `G90.1`, `M61`, `H` without G43, `D` without G41/G42, `G41.1`/`G42.1`, `G4`
/// with axis words, without P, with a negative P or with other words (`G4 P1.5` alone is
/// `state.dwell_s`); under tracking, a move while G43 does not hold the
/// loaded tool's length (the point programmed would not be the tool tip).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../iso/reader.hpp"
#include "../iso/vocabulary.hpp"
#include "../lexing.hpp"
#include "../modal.hpp"
#include "../transmission.hpp"
#include "expression.hpp"
#include "lexer.hpp"
#include "parameter_rules.hpp"
#include "statements.hpp"
#include "vocabulary.hpp"

namespace kin5::program::linuxcnc::detail {

using iso::detail::g_code;

/// The words of one line that give other words their meaning.
struct line_words {
  const word* g43 = nullptr;    ///< G43 (or a refused G43.n): H is its tool
  const word* g12_1 = nullptr;  ///< G12.1: P is the kinematics type
  const word* p = nullptr;      ///< P of G12.1
  const word* g4 = nullptr;     ///< G4: P is the dwell (seconds); no axis words
  const word* dwell_p = nullptr;  ///< the P of G4
  const word* offset = nullptr; ///< the work-offset word
  const word* tcp = nullptr;    ///< the kinematics switch (M428, M429, G12.1, G13.1)
  const word* axis = nullptr;   ///< the first axis word
  const word* t = nullptr;      ///< the T word (the tool an M6 of the line loads)
  const word* g41 = nullptr;    ///< G41 or G42: D is its tool
  bool g64 = false, radius = false, m6 = false, d = false;
};

/// The G name of a G code times ten: 430 → "G43", 591 → "G59.1".
inline std::string g_name(int g) {
  std::string name(1, 'G');  // appended to, not `"G" + …`: GCC 12 warns falsely (-Wrestrict) on that
  name += std::to_string(g / 10);
  if (g % 10) name += '.', name += std::to_string(g % 10);
  return name;
}

/// The words LinuxCNC reads otherwise than ISO (see the file comment), and the modal record the
/// tracking check needs: the tool selected and loaded, whether G43 holds the loaded tool's
/// length, whether tracking is on.
class own_words {
 public:
  /// Refuses a line whose active comment runs Python (lexer.hpp); notes its abort, which `take`
  /// makes the block's alarm stop. An abort on a parameter assignment's line is refused: kin5
  /// reads that line as the assignment alone. A line that starts with an o-word is a statement
  /// (statements.hpp), never read here.
  std::optional<lex_problem> line(std::string_view s, std::size_t first, std::size_t end) {
    abort_.reset();
    if (auto p = stopping_comment(s, first, end)) return p;
    abort_ = abort_of(s, first, end);
    if (abort_ && assigns(s, first, end))
      return lex_problem{abort_->column, "(ABORT, …) on a line that sets a parameter is not supported: put the abort "
                                         "on a line of its own"};
    return std::nullopt;
  }

  /// #3000 is one of the program's parameters (#31–#5000): no assignment stops the program.
  static constexpr long alarm_parameter = 0;

  /// G28 / G30 go to the positions in parameters #5161–#5166 / #5181–#5186 (User Manual, "G28,
  /// G28.1", "G30, G30.1"), which the control keeps, not the program.
  static constexpr bool stored_homes = true;
  /// A comment ends at its first `)` (User Manual, "G-code Overview", "Comments"; lexer.hpp).
  static constexpr iso::comment_nesting comments = iso::comment_nesting::flat;

  using syntax = statements;
  /// #1–#30 local to a call, #31–#5000 the program's, named ones (parameter_rules.hpp).
  static interp::parameter_rules parameter_rules() { return linuxcnc::parameter_rules(); }
  static parsed_expression read_value(std::string_view text, std::size_t line, std::size_t column) {
    return linuxcnc::read_value(text, line, column);
  }

  /// No letter is ISO's whole address here: LinuxCNC rounds no parameter. A fraction in T, H, D
  /// or M is an error on it ("non-integer value for integer"), and in kin5 where those words are
  /// read; S and P are reals.
  static bool whole_address(char) { return false; }
  /// Integers are whole units (User Manual, "G-code Overview", "Numbers"): no letter's unit
  /// depends on a decimal point.
  static bool point_decides_unit(char) { return false; }

  /// Reads and removes from `words` the words LinuxCNC reads itself, and makes the line's abort
  /// its alarm stop (the comment without it).
  template <class Error>
  void take(std::vector<word>& words, block& b, Error&& error) {
    if (abort_) {
      b.alarm = alarm_stop{abort_->message, std::nullopt};
      if (b.comment && b.comment->ends_with(abort_->text)) {
        b.comment->resize(b.comment->size() - abort_->text.size());
        while (!b.comment->empty() && b.comment->back() == ' ') b.comment->pop_back();
        if (b.comment->empty()) b.comment.reset();
      }
    }
    line_words l;
    for (const word& w : words) classify(w, l);
    std::vector<word> rest;
    for (const word& w : words)
      if (!own(w, b, l, error)) rest.push_back(w);
    finish(b, l, error);
    loaded_length(b, l);
    loaded_radius(b, l, error);
    words = std::move(rest);
  }

  /// Follows tools, G43 and tracking; refuses a tracked move without the loaded tool's length,
  /// and a dwell with other words. Before the first G43 the control tracks with the length
  /// offset it had (tool length 0 on a control just started, else the last G43's, even that of
  /// an earlier program: M6 and M2/M30 leave it alone; rs274 shows no length call at either),
  /// which the program does not say: such a move is refused, not read with length 0.
  template <class Error>
  void check(const block& b, Error&& error) {
    if (b.state.dwell_s && !b.only_dwell())
      error(b.where.column, "G4: a dwell is read in a block of its own (N, P and a comment): every other dialect writes "
                            "it so");
    if (b.tool) selected_ = *b.tool;
    if (changes_tool(b)) loaded_ = selected_, length_of_loaded_ = false, refused_ = false;
    if (const auto& on = b.state.length_compensation) {
      const auto& h = b.state.length_register;
      length_of_loaded_ = *on && (!h || (loaded_ && *h == *loaded_));
      refused_ = false;
    }
    if (b.tcp) tracking_ = *b.tcp, refused_ = false;
    if (!tracking_ || length_of_loaded_ || !is_motion(b) || refused_) return;
    refused_ = true;  // once until G43, M6 or a switch
    error(b.where.column, "a move under TCP kinematics without G43 for the loaded tool: the length offset in effect "
                          "is whatever was set before (LinuxCNC keeps it across M6 and from one program to the "
                          "next), so the point programmed is not known to be the tool tip; put G43, or G43 H n "
                          "with the loaded tool n, after each M6 and before the first move");
  }

 private:
  std::optional<long long> selected_, loaded_;
  bool length_of_loaded_ = false, tracking_ = false, refused_ = false;
  std::optional<abort_comment> abort_;  // the abort of the line being read

  /// Whether the line from `i` to `end` sets a parameter: `#` first, after a block number.
  static bool assigns(std::string_view s, std::size_t i, std::size_t end) {
    i = lexing::skip_blanks(s.substr(0, end), i);
    if (i < end && (s[i] == 'n' || s[i] == 'N')) {
      std::size_t k = i + 1;
      while (k < end && is_digit(s[k])) ++k;
      if (k > i + 1) i = lexing::skip_blanks(s.substr(0, end), k);
    }
    return i < end && s[i] == '#';
  }

  /// `G43` without H takes the length of the tool loaded now (LinuxCNC Manual, G43: "uses the
  /// currently loaded tool"; the line's M6 runs first), and keeps it after a later M6: its
  /// number is the register, once the program has loaded a tool.
  void loaded_length(block& b, const line_words& l) const {
    if (b.state.length_compensation != true || b.state.length_register || !l.g43 || g_code(l.g43->value) != 430) return;
    const std::optional<long long> loaded = !l.m6 ? loaded_ : l.t ? std::optional<long long>(static_cast<long long>(l.t->value)) : selected_;
    if (loaded) b.state.length_register = *loaded;
  }

  /// `G41`/`G42` without D take the radius of the tool loaded now (LinuxCNC User Manual, "G-Codes",
  /// "G41, G42 Cutter Compensation": the D word is optional, without it the loaded tool's radius
  /// is used; the line's M6 runs first): its number is the register. Before any M6 the tool in
  /// the spindle is not known, and after `T0 M6` there is none: refused.
  template <class Error>
  void loaded_radius(block& b, const line_words& l, Error&& error) const {
    if (!l.g41 || l.d) return;
    const std::optional<long long> loaded = !l.m6 ? loaded_ : l.t ? std::optional<long long>(static_cast<long long>(l.t->value)) : selected_;
    if (loaded && *loaded == 0)  // T0 M6 empties the spindle: no tool, no radius (the writers' D takes 1 or more)
      error(l.g41->column, std::string(l.g41->text) + " without D while tool 0 is loaded: the spindle holds no tool "
                                                      "whose radius it could apply (load a tool, or G41 D n names one)");
    else if (loaded) b.state.radius_register = *loaded;
    else error(l.g41->column, std::string(l.g41->text) + " without D before any M6: the radius of the tool in the "
                                                         "spindle is not known (G41 D n names the tool)");
  }

  static void classify(const word& w, line_words& l) {
    if (std::string_view("XYZABC").find(w.letter) != std::string_view::npos && !l.axis) l.axis = &w;
    if (w.letter == 'M' && w.value == 6) l.m6 = true;
    if (w.letter == 'T' && lexing::is_whole(w.value)) l.t = &w;
    if (w.letter == 'D') l.d = true;
    if (w.letter != 'G') return;
    const int g = g_code(w.value);
    if (g == 430 || g == 431 || g == 432 || g == 434 || g == 435) l.g43 = &w;
    if (g == 121) l.g12_1 = &w;
    if (g == 40) l.g4 = &w;
    if (g == 640) l.g64 = true;
    if (g == 410 || g == 420) l.radius = true, l.g41 = &w;
    if (g == 411 || g == 421) l.radius = true;  // its D is refused with it
  }

  /// Whether word `w` is LinuxCNC's own (read into `b`, or refused); false leaves it to ISO.
  template <class Error>
  bool own(const word& w, block& b, line_words& l, Error&& error) {
    switch (w.letter) {
      case 'G': return g_word(w, b, l, error);
      case 'M': return m_word(w, b, l, error);
      case 'H':
        if (!l.g43) return error(w.column, "word 'H' without G43 (H is the tool whose length G43 applies)"), true;
        if (g_code(l.g43->value) != 430) return true;  // the refused G43.n's
        if (!lexing::is_whole(w.value)) return error(w.column, "G43 H: the tool number must be a whole number"), true;
        b.state.length_register = static_cast<long long>(w.value);
        return true;
      case 'P':
        if (l.g12_1) return l.p = &w, true;
        if (l.g4 && !l.g64) {
          if (l.dwell_p) error(w.column, "word 'P' appears twice");
          return l.dwell_p = &w, true;
        }
        if (!l.g64) return false;
        b.kept_words.emplace_back(w.text);
        return true;
      case 'Q':
        if (!l.g64) return false;
        b.kept_words.emplace_back(w.text);
        return true;
      case 'D':
        if (l.radius) return false;
        return error(w.column, "word 'D' without G41 or G42 (D is the tool whose radius they apply)"), true;
      case 'O': return error(w.column, "word 'O' inside a line: o-words start a line"), true;
      default: return false;
    }
  }

  template <class Error>
  bool g_word(const word& w, block& b, line_words& l, Error&& error) {
    const int g = g_code(w.value);
    switch (g) {
      case 40: return true;  // the dwell: its P is read in `finish`
      case 430: b.state.length_compensation = true; return true;
      case 490: b.state.length_compensation = false; return true;
      case 431: case 432:
        return error(w.column, g_name(g) + ": a tool length offset other than the tool table's is not supported"), true;
      case 411: case 421:
        return error(w.column, g_name(g) + ": dynamic cutter compensation (the diameter in the program) is not "
                                           "supported"), true;
      case 434: case 435: case 541: case 500: case 501:
        return error(w.column, g_name(g) + " is not a LinuxCNC G code" + not_linuxcnc_hint(g)), true;
      case 50: case 51: case 52: case 53:
        return error(w.column, g_name(g) + ": spline and NURBS moves are not supported"), true;
      case 901: return error(w.column, "G90.1: absolute arc centres are not supported"), true;
      case 911: b.kept_words.emplace_back(w.text); return true;
      case 121: return switch_tcp(w, b, l, true, error), true;
      case 131: return switch_tcp(w, b, l, false, error), true;
      default: break;
    }
    const int n = (g >= 540 && g <= 590 && g % 10 == 0) ? g / 10 - 53 : (g >= 591 && g <= 593) ? g - 584 : 0;
    if (n == 0) return false;
    if (l.offset) return error(w.column, "two work offsets in one block"), true;
    l.offset = &w;
    b.state.work_offset = work_offset{work_offset_family::g54, n};
    return true;
  }

  static std::string not_linuxcnc_hint(int g) {
    if (g == 434 || g == 435) return " (tool-tip tracking is M428 or G12.1 there)";
    if (g == 541) return " (its work offsets are G54 … G59.3)";
    return "";
  }

  template <class Error>
  bool m_word(const word& w, block& b, line_words& l, Error&& error) {
    if (!lexing::is_whole(w.value)) return false;
    const int m = static_cast<int>(w.value);
    if (m == 428 || m == 429) return switch_tcp(w, b, l, m == 428, error), true;
    if (m == 430) return error(w.column, "M430: the user kinematics of the 5-axis configurations are not supported"), true;
    if (m == 61) return error(w.column, "M61: setting the loaded tool without a tool change is not supported"), true;
    return false;
  }

  template <class Error>
  static void switch_tcp(const word& w, block& b, line_words& l, bool on, Error&& error) {
    if (l.tcp) return error(w.column, "two kinematics switches in one block");
    l.tcp = &w;
    if (l.axis || l.m6)
      return error(w.column, std::string(w.text) + " on a line with " + (l.axis ? "motion" : "M6") +
                                 ": a kinematics switch goes on a line of its own");
    if (w.letter == 'M' || !on) b.tcp = on;  // G12.1: once its P is known
  }

  /// What the words of the line say together: G12.1's type, G4's P.
  template <class Error>
  static void finish(block& b, const line_words& l, Error&& error) {
    if (l.g12_1 && l.tcp == l.g12_1) {
      if (!l.p) error(l.g12_1->column, "G12.1 needs P, the kinematics type");
      else if (l.p->value != 1)
        error(l.p->column, "G12.1 " + std::string(l.p->text) +
                               ": only type 1, the TCP kinematics of the 5-axis trt configurations, is read");
      else b.tcp = true;
    }
    if (l.g4) dwell(b, l, error);
  }

  /// `G4 P1.5`: a dwell of P seconds, a real (LinuxCNC User Manual, "G-Codes", G4: "it is an
  /// error if the P number is negative"), read in a block of its own, as every other dialect
  /// writes it: with only N and a comment beside it.
  template <class Error>
  static void dwell(block& b, const line_words& l, Error&& error) {
    if (l.axis) return error(l.axis->column, std::string("word '") + l.axis->letter + "' in a dwell block (G4 takes P, seconds)");
    if (!l.dwell_p) return error(l.g4->column, "G4 needs P, the dwell in seconds");
    if (l.dwell_p->value < 0)
      return error(l.dwell_p->column, "G4 " + std::string(l.dwell_p->text) + ": a dwell time cannot be negative");
    if (const std::string why = dwell_refusal(dwell_steps, l.dwell_p->value); !why.empty())
      return error(l.dwell_p->column, "G4 " + std::string(l.dwell_p->text) + ": " + why);
    b.state.dwell_s = l.dwell_p->value;
  }
};

}  // namespace kin5::program::linuxcnc::detail

namespace kin5::program::linuxcnc {

/// Reads LinuxCNC G code block by block: `on_block` receives each block in file order as soon as
/// it is read; errors and warnings go to `diagnostics` (its `parsed` is not touched).
inline void read_blocks(std::string_view text, const std::string& file_name, read_result& diagnostics,
                        const block_sink& on_block) {
  read_transmitted(text, file_name, diagnostics, on_block, [&](std::string_view body, const block_sink& sink) {
    iso::detail::basic_reader<detail::own_words>(file_name, diagnostics, sink).run(body);
  });
}

}  // namespace kin5::program::linuxcnc
