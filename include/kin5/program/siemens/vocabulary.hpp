/// @file program/siemens/vocabulary.hpp
/// The Siemens 840D words kin5 knows without interpreting them, shared by the reader (which
/// keeps them, or refuses frame changes) and the writer (which writes them back in place).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "../dwell.hpp"
#include "../lexing.hpp"
#include "../number.hpp"
#include "../text.hpp"

namespace kin5::program::siemens::detail {

/// The most decimals of a feed or spindle speed (F, S) the controller reads (840Di Manual (HBI)
/// 06/2003 §10.3.1): the writer's finest, and the reader refuses a rate these cannot write back
/// (`unwritable_rate`).
inline constexpr int finest_rate_decimals = 3;

/// The dwells the 840D takes with `G4 F`: F is a real number of seconds (SINUMERIK 840D sl
/// Fundamentals 05/2017, "Dwell time (G4)"), written with any decimals a source gives, to 6.
inline constexpr dwell_input dwell_steps{6, 1e9};

/// The alarm number written for another dialect's alarm stop: `SETAL(65000)`, the first of the
/// user cycle alarms, whose reaction stops the program (docs/dialects/siemens.md). SETAL takes
/// the cycle alarms 60000 … 69999; those below 65000 are Siemens' own cycles'.
inline constexpr long long default_alarm_number = 65000;
inline constexpr long long first_alarm_number = 60000, last_alarm_number = 69999;

constexpr bool is_ident_char(char c) { return is_letter(c) || is_digit(c) || c == '_'; }
constexpr bool is_axis_letter(char c) { return c == 'X' || c == 'Y' || c == 'Z' || c == 'A' || c == 'B' || c == 'C'; }
constexpr bool is_centre_letter(char c) { return c == 'I' || c == 'J' || c == 'K'; }
/// Axis and centre letters: a word with one of them is geometry.
constexpr bool is_geometry_letter(char c) { return is_axis_letter(c) || is_centre_letter(c); }

/// A byte that may not appear outside comments and strings.
constexpr bool is_bad_byte(char c) { return lexing::is_control(c) || static_cast<unsigned char>(c) >= 0x80; }

inline std::string frame_message(std::string_view construct) {
  return std::string(construct) + " changes the working frame; kin5 does not model frame changes";
}

/// Words kept as written (after upper-casing) that do not change geometry. `FNORM` is the
/// feed as every dialect means it, F constant over the block (SINUMERIK 840D sl Fundamentals
/// 05/2017, ch. 8, "Feedrate characteristic (FNORM, FLIN, FCUB, FPO)"); FLIN, FCUB and FPO,
/// which make F vary along the block, stay unknown words.
inline bool is_kept_keyword(std::string_view w) {
  static constexpr std::array<std::string_view, 18> words = {
      "SOFT", "BRISK", "DRIVE", "FFWON", "FFWOF", "FNORM", "CUT2D", "CUT2DF", "ORIWKS", "ORIMKS",
      "ORIAXES", "ORIVECT", "COMPOF", "COMPON", "COMPCAD", "COMPCURV", "TOROTOF", "PAROTOF"};
  return std::find(words.begin(), words.end(), w) != words.end();
}

/// G codes kept as written: they change no geometry. (G17–G19, G40 and G90 are read into the
/// block's state.)
inline bool is_kept_g(long long g) {
  return g == 9 || g == 60 || g == 64 || (g >= 641 && g <= 645) || (g >= 601 && g <= 603);
}

/// Frame words that are harmless alone (they reset the programmable frame) and errors with axes.
inline bool is_frame_reset_keyword(std::string_view w) {
  return w == "TRANS" || w == "ATRANS" || w == "ROT" || w == "AROT" || w == "SCALE" || w == "ASCALE" ||
         w == "MIRROR" || w == "AMIRROR";
}

/// Frame words that always change the frame.
inline bool is_frame_keyword(std::string_view w) {
  return w == "TRAFRAME" || w == "TOFRAME" || w == "TOROT" || w == "PAROT" || w == "TOFRAMEX" ||
         w == "TOFRAMEY" || w == "TOFRAMEZ";
}

/// Kept words written after T rather than before the motion word: `D1`, `H2`.
/// The reader stores kept words in that order too (the others first), so writing keeps them.
inline bool is_late_kept(std::string_view w) {
  return w.size() > 1 && (w[0] == 'D' || w[0] == 'H') && is_digit(w[1]);
}

/// Splits a call's arguments at top-level commas.
inline std::vector<std::string_view> split_args(std::string_view args) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  bool in_string = false;
  int depth = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const char c = args[i];
    if (c == '"') in_string = !in_string;
    if (in_string) continue;
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if (c == ',' && depth == 0) {
      out.push_back(lexing::trim(args.substr(start, i - start)));
      start = i + 1;
    }
  }
  out.push_back(lexing::trim(args.substr(start)));
  return out;
}

/// `CYCLE800()` or a CYCLE800 call whose offsets and angles (arguments 5 to 13) are all zero.
inline bool is_cycle800_reset(std::string_view args) {
  if (lexing::trim(args).empty()) return true;
  const auto a = split_args(args);
  if (a.size() < 13) return false;
  for (std::size_t i = 4; i < 13; ++i) {
    if (a[i].empty()) continue;
    const auto n = read_number(a[i]);
    if (n.length != a[i].size() || n.value != 0.0) return false;
  }
  return true;
}

/// Whether a line kin5 does not read is known to change nothing, so that it may pass through (a
/// comment in another dialect): `%` lines, `DEF` declarations, `MSG(…)`, `WORKPIECE(…)` (the
/// simulation's blank), `STOPRE`, a label `NAME:`. A line of assignments of numbers (`R1=5`,
/// `_Z_HOME=610.`) passes too, said by parameters.hpp, which reads them (`only_assignments`).
/// Any other line kin5 does not read is refused.
inline bool changes_nothing(std::string_view line) {
  std::size_t k = lexing::skip_blanks(line, 0);
  if (k < line.size() && line[k] == '%') return true;
  std::string s = lexing::upper(line.substr(k, line.find(';') == std::string_view::npos ? line.size() - k
                                                                                          : line.find(';') - k));
  std::string_view t = lexing::trim(s);
  if (t.size() > 1 && t[0] == 'N' && is_digit(t[1])) {  // the block number
    std::size_t e = 1;
    while (e < t.size() && is_digit(t[e])) ++e;
    if (e < t.size() && !is_space(t[e])) return false;
    t = lexing::trim(t.substr(e));
  }
  const auto one_call = [&](std::string_view name) {
    return t.rfind(name, 0) == 0 && t.back() == ')' && t.find(')') == t.size() - 1;
  };
  if (t.empty() || t == "STOPRE" || t.rfind("DEF ", 0) == 0 || one_call("MSG(") || one_call("WORKPIECE(")) return true;
  std::size_t e = 0;
  while (e < t.size() && is_ident_char(t[e])) ++e;
  return e > 0 && e + 1 == t.size() && t[e] == ':' && !is_digit(t[0]);  // a label
}

}  // namespace kin5::program::siemens::detail
