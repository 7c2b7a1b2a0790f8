/// @file program/linuxcnc/lexer.hpp
/// The first stage of the LinuxCNC reader: ISO's lexer (iso/lexer.hpp: address words, `( … )`
/// and `;` comments, `#` parameters and `[ … ]` expressions refused) after one check of
/// LinuxCNC's own. A line that starts with an o-word (`o100 sub`, `o<probe> call`, `o101 while
/// [#1 LT 3]`) is control flow, refused at the `o`, naming it (LinuxCNC User Manual, "O Codes");
/// an `O` word elsewhere is the reader's to refuse.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "../iso/lexer.hpp"
#include "../lexing.hpp"
#include "../text.hpp"

namespace kin5::program::linuxcnc {

using iso::lex_problem;
using iso::word;

namespace detail {

/// The o-word starting at `i` as written up to its keyword: "o100 while", "o<probe> call".
inline std::string o_word_text(std::string_view s, std::size_t i, std::size_t end) {
  std::size_t k = i + 1;
  if (k < end && s[k] == '<') {
    const std::size_t close = s.find('>', k);
    k = close == std::string_view::npos || close >= end ? end : close + 1;
  }
  while (k < end && (is_digit(s[k]) || is_space(s[k]))) ++k;
  while (k < end && is_letter(s[k])) ++k;
  return std::string(lexing::trim(s.substr(i, k - i)));
}

}  // namespace detail

/// The o-word that starts the line from `i` to `end` (after an optional block number), as the
/// problem that stops the line; nothing when the line starts otherwise.
inline std::optional<lex_problem> o_word(std::string_view s, std::size_t i, std::size_t end) {
  i = lexing::skip_blanks(s.substr(0, end), i);
  if (i < end && (s[i] == 'n' || s[i] == 'N')) {
    std::size_t k = i + 1;
    while (k < end && is_digit(s[k])) ++k;
    if (k > i + 1) i = lexing::skip_blanks(s.substr(0, end), k);
  }
  if (i < end && (s[i] == 'o' || s[i] == 'O'))
    return lex_problem{i + 1, "o-word control flow (" + detail::o_word_text(s, i, end) + ") is not supported"};
  return std::nullopt;
}

/// The comment of the line from `i` to `end` that LinuxCNC acts on: the last one (User Manual,
/// "G-code Overview", "Comments": only the last comment of a line is read as an active comment;
/// a `;` comment is always the last). Its text without the delimiters and its column; nothing
/// for a line without comments or with one not closed (the lexer refuses that).
inline std::optional<std::pair<std::string_view, std::size_t>> last_comment(std::string_view s, std::size_t i,
                                                                            std::size_t end) {
  std::optional<std::pair<std::string_view, std::size_t>> last;
  while (i < end) {
    if (s[i] == ';') return std::pair{s.substr(i + 1, end - i - 1), i + 1};
    if (s[i] != '(') {
      ++i;
      continue;
    }
    const std::size_t close = s.find(')', i);
    if (close == std::string_view::npos || close >= end) return last;
    last = std::pair{s.substr(i + 1, close - i - 1), i + 1};
    i = close + 1;
  }
  return last;
}

/// Whether comment text `c` is the active comment `name` (upper case, with its comma when it
/// takes one): after leading blanks, in either case, blanks allowed before the comma (the
/// manual's "Messages" allows them; the interpreter does not, so kin5 takes both spellings).
inline bool is_active(std::string_view c, std::string_view name) {
  std::size_t k = lexing::skip_blanks(c, 0);
  const bool comma = !name.empty() && name.back() == ',';
  const std::string_view word = comma ? name.substr(0, name.size() - 1) : name;
  for (char l : word) {
    if (k >= c.size() || to_upper(c[k]) != l) return false;
    ++k;
  }
  if (!comma) return true;  // `PYRELOAD`: the interpreter compares the start only
  k = lexing::skip_blanks(c, k);
  return k < c.size() && c[k] == ',';
}

/// Whether comment text `c` would act on LinuxCNC (interp_convert.cc, `convert_comment`; the
/// emccanon `PROBEOPEN`, `PROBECLOSE`): show a message, write a file, run Python or abort. Text
/// another dialect kept as a plain comment must not say so in a LinuxCNC program.
inline bool acts(std::string_view c) {
  for (std::string_view name : {"MSG,", "DEBUG,", "PRINT,", "LOG,", "LOGOPEN,", "LOGAPPEND,", "LOGCLOSE", "PY,",
                                "PYRUN,", "PYRELOAD", "ABORT,", "PROBEOPEN", "PROBECLOSE"})
    if (is_active(c, name)) return true;
  return false;
}

/// An abort, `(ABORT, message)` as the line's last comment (User Manual, "G-code Overview":
/// "Abort Messages"; the interpreter's `convert_comment`): the program stops there with an error
/// showing the message, trimmed of blanks. Its column, and the comment's whole text as the lexer
/// adds it to the block's comment (`lexing::trim`).
struct abort_comment {
  std::string message;
  std::size_t column = 0;
  std::string text;
};

/// The abort of the line from `i` to `end`, if its last comment is one.
inline std::optional<abort_comment> abort_of(std::string_view s, std::size_t i, std::size_t end) {
  const auto c = last_comment(s, i, end);
  if (!c || !is_active(c->first, "ABORT,")) return std::nullopt;
  const std::size_t comma = c->first.find(',');
  return abort_comment{std::string(lexing::trim(c->first.substr(comma + 1))), c->second,
                       std::string(lexing::trim(c->first))};
}

/// The active comment that changes what runs and has no meaning kin5 reads, as the problem that
/// stops the line (the interpreter's `convert_comment`): `(PY, …)`, `(PYRUN, …)` and
/// `(PYRELOAD)` run embedded Python, which may set parameters and so change the motion.
/// `(ABORT, …)` is an alarm stop (`abort_of`). `(MSG, …)`, `(DEBUG, …)`, `(PRINT, …)`, the `LOG`
/// and `PROBEOPEN` comments only show or record text: comments.
inline std::optional<lex_problem> stopping_comment(std::string_view s, std::size_t i, std::size_t end) {
  const auto c = last_comment(s, i, end);
  if (!c) return std::nullopt;
  for (std::string_view py : {"PY,", "PYRUN,", "PYRELOAD"})
    if (is_active(c->first, py))
      return lex_problem{c->second, "(" + std::string(py) + (py.back() == ',' ? " …)" : ")") + ": embedded Python is not supported (it may set "
                                    "parameters and change the motion)"};
  return std::nullopt;
}

}  // namespace kin5::program::linuxcnc
