/// @file program/apt/lexer.hpp
/// The first stage of the APT reader: physical lines grouped into statements (`$` at the end of a
/// line's code continues it on the next line; `$$` starts a comment to the end of the line), and
/// a statement's code split into its major word and its comma-separated arguments, each at its
/// offset, which `statement::at` turns back into a line and column. What a statement means is
/// the reader's (reader.hpp).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../block.hpp"
#include "../lexing.hpp"
#include "../text.hpp"

namespace kin5::program::apt {

/// One statement: its physical lines joined by '\n', with a map from offsets to locations.
struct statement {
  std::string text;      ///< source text, lines joined by '\n', outer blanks trimmed
  std::string content;   ///< `text` with comments, continuation `$` and line ends blanked
  std::string comment;   ///< `$$` comment text of all its lines, trimmed, joined by ' '
  bool has_comment = false;
  lexing::line_map lines;  ///< where each physical line starts in `text`

  source_location at(const file_name& file, std::size_t offset) const {
    const auto [line, column] = lines.locate(offset);
    return {file, line, column};
  }
};

/// One comma-separated argument of a statement: its text (trimmed) and offset in the statement.
struct argument {
  std::string_view text;
  std::size_t offset = 0;
};

/// A statement's code: `MAJOR/arg,arg` or `MAJOR arg` (PARTNO), with the offsets of each part.
struct code {
  std::string major;            ///< upper case
  std::size_t major_at = 0;     ///< offset of the major word
  std::size_t rest = 0;         ///< offset after the major word (and its `/`)
  bool slash = false;           ///< `/` follows the major word
  std::string_view tail;        ///< the text after it, trimmed
};

namespace detail {

/// Adds physical line `raw` (blanks before `skip` removed) to `st`; true when its code ends in `$`.
inline bool add_line(statement& st, std::string_view raw, const text_line& line, std::size_t skip) {
  raw.remove_prefix(skip);
  if (!st.text.empty()) st.text += '\n', st.content += ' ';
  st.lines.add(st.text.size(), line.number, skip + 1);
  const std::size_t base = st.text.size();
  st.text += raw;
  st.content += raw;
  const std::size_t dollars = raw.find("$$");
  std::string_view code = raw.substr(0, dollars);
  if (dollars != std::string_view::npos) {
    const std::string_view c = lexing::trim(raw.substr(dollars + 2));
    if (st.has_comment && !c.empty() && !st.comment.empty()) st.comment += ' ';
    st.comment += c;
    st.has_comment = true;
    for (std::size_t k = base + dollars; k < st.content.size(); ++k) st.content[k] = ' ';
  }
  code = lexing::trim(code);
  if (code.empty() || code.back() != '$') return false;
  const std::size_t pos = static_cast<std::size_t>(code.data() - raw.data()) + code.size() - 1;
  st.content[base + pos] = ' ';
  return true;
}

}  // namespace detail

/// Groups physical lines into statements and calls `f(statement&&)` for each, in order; blank
/// lines are skipped.
template <class F>
void for_each_statement(std::string_view text, F&& f) {
  const auto lines = split_lines(text);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::size_t lead = lexing::skip_blanks(lines[i].text, 0);
    if (lead == lines[i].text.size()) continue;
    statement st;
    while (detail::add_line(st, lines[i].text, lines[i], st.lines.empty() ? lead : 0) && i + 1 < lines.size()) ++i;
    while (!st.text.empty() && is_space(st.text.back())) st.text.pop_back();
    st.content.resize(st.text.size());
    f(std::move(st));
  }
}

/// The statements of `text`, in order; blank lines are skipped.
inline std::vector<statement> statements(std::string_view text) {
  std::vector<statement> out;
  for_each_statement(text, [&](statement&& st) { out.push_back(std::move(st)); });
  return out;
}

/// The major word of a statement's `content`, and where its arguments start.
inline code split_code(std::string_view content) {
  code c;
  std::size_t k = lexing::skip_blanks(content, 0);
  c.major_at = k;
  while (k < content.size() && (is_letter(content[k]) || is_digit(content[k]) || content[k] == '_')) ++k;
  c.major = lexing::upper(content.substr(c.major_at, k - c.major_at));
  c.rest = lexing::skip_blanks(content, k);
  c.slash = c.rest < content.size() && content[c.rest] == '/';
  if (c.slash) ++c.rest;
  c.tail = lexing::trim(content.substr(c.rest));
  return c;
}

/// The comma-separated arguments of `content` from `offset` on.
inline std::vector<argument> arguments(std::string_view content, std::size_t offset) {
  std::vector<argument> args;
  std::size_t start = offset;
  for (std::size_t k = offset; k <= content.size(); ++k) {
    if (k == content.size() || content[k] == ',') {
      const std::string_view piece = content.substr(start, k - start);
      args.push_back({lexing::trim(piece), start + lexing::skip_blanks(piece, 0)});
      start = k + 1;
    }
  }
  return args;
}

}  // namespace kin5::program::apt
