/// @file machines/toml_bounds.hpp
/// What a TOML file of kin5's (a machine file, a tool table) may hold before toml++ parses it,
/// and reading one within its size. toml++ recurses once per level of a dotted key or table
/// name (`a.b.c…`): a 40,000-part key overflowed the stack. A cheap scan of the text, before the
/// parse, refuses at its line and column
///   * a key (dotted, or a table name) longer than `max_key_bytes` (256),
///   * nesting deeper than `max_nesting` (32): the parts of the table name in force, plus those
///     of each key and each inline table or array around a value — a machine file nests 3 deep
///     (`[linear.X]`, `direction = [ … ]`), a tool table 2;
/// and `read_toml_file` reads at most `max_file_bytes` (4 MiB, some 60,000 tools) of a file,
/// refusing a larger one (or a device that never ends) without reading it to its end.
/// The scan also refuses a non-ASCII byte outside strings and comments (TOML's syntax is ASCII
/// there, so such a file is wrong anyway), and one first after a backslash in a basic string
/// (blanks and line ends between them): toml++ 3.3 asks whether such a character is whitespace with a function that
/// reaches `TOML_UNREACHABLE` (undefined behaviour) for many code points (U+03E9, U+00A7 …).
/// Standard library only.
/// @code
///   if (auto v = kin5::toml_bounds_violation(text))
///     error(v->line, v->column, v->message);   // before toml::parse(text)
/// @endcode
#pragma once

#include <cctype>
#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace kin5 {

/// The bounds of a TOML file of kin5's.
struct toml_bounds {
  static constexpr std::size_t max_file_bytes = std::size_t{4} << 20;
  static constexpr std::size_t max_key_bytes = 256;
  static constexpr std::size_t max_nesting = 32;
};

/// A bound broken, at a line and column (1-based; columns count code points, as toml++'s do).
struct toml_bound_violation {
  unsigned line = 1, column = 1;
  std::string message;
};

namespace toml_bounds_detail {

/// A cursor over the text that keeps its line and column.
struct cursor {
  std::string_view text;
  std::size_t i = 0;
  unsigned line = 1, column = 1;
  /// Where a backslash in a basic string is followed (after blanks) by a non-ASCII character.
  std::optional<std::pair<unsigned, unsigned>> after_line_end{};

  bool done() const { return i >= text.size(); }
  char peek(std::size_t ahead = 0) const { return i + ahead < text.size() ? text[i + ahead] : '\0'; }
  bool starts(std::string_view s) const { return text.substr(i, s.size()) == s; }
  void next() {
    if (text[i] == '\n') ++line, column = 1;
    else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++column;  // not a UTF-8 continuation byte
    ++i;
  }
  /// Notes the place of the first text after a backslash (here) when it is a non-ASCII
  /// character: after blanks (and line ends, `multi_line`), where toml++ asks whether it is
  /// whitespace.
  void note_after_backslash(bool multi_line) {
    std::size_t k = i;
    unsigned l = line, col = column;
    while (k < text.size() && (text[k] == ' ' || text[k] == '\t' || text[k] == '\r' || (multi_line && text[k] == '\n'))) {
      if (text[k] == '\n') ++l, col = 1;
      else ++col;
      ++k;
    }
    if (k < text.size() && static_cast<unsigned char>(text[k]) >= 0x80 && !after_line_end)
      after_line_end = std::pair{l, col};
  }
  /// Past the string starting here (`"`, `'`, `"""`, `'''`); an unterminated one ends at its
  /// line's end (single-line) or the text's (multi-line): toml++ then says what is wrong.
  void skip_string() {
    const char q = text[i];
    const bool basic = q == '"';
    const std::string_view triple = basic ? std::string_view("\"\"\"") : std::string_view("'''");
    if (starts(triple)) {
      next(), next(), next();
      while (!done() && !starts(triple)) {
        if (basic && text[i] == '\\' && i + 1 < text.size()) {
          next();
          note_after_backslash(true);
          std::size_t k = i;  // a line-ending backslash: blanks, a line end, then the next text
          while (k < text.size() && (text[k] == ' ' || text[k] == '\t' || text[k] == '\r')) ++k;
          if (k < text.size() && text[k] == '\n') {
            while (!done() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) next();
            continue;
          }
        }
        next();
      }
      for (int k = 0; k < 3 && !done(); ++k) next();
      for (int k = 0; k < 2 && peek() == q; ++k) next();  // up to two quotes of the content before the close
      return;
    }
    next();
    while (!done() && text[i] != q && text[i] != '\n') {
      if (basic && text[i] == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
        next();
        note_after_backslash(false);
      }
      next();
    }
    if (!done() && text[i] == q) next();
  }
  /// Past a comment, up to its line's end.
  void skip_comment() {
    while (!done() && text[i] != '\n') next();
  }
};

inline std::string too_long(std::string_view what) {
  return std::string(what) + " longer than " + std::to_string(toml_bounds::max_key_bytes) +
         " bytes: a kin5 machine file or tool table keeps its keys short";
}

/// Whether `ch` opens a string where the last byte but blanks before it was `prev`: a quote where
/// a value, a key or a key's part begins. A quote glued to a word (`1'…'`) opens none for
/// toml++, which reads on through the word's end; so it opens none here either.
constexpr bool opens_string(char ch, char prev) {
  return (ch == '"' || ch == '\'') &&
         (prev == '=' || prev == '[' || prev == '{' || prev == ',' || prev == '.' || prev == '\n');
}

/// One step of `c` through a dotted key or table name: past a string that opens there (`last`
/// becomes its quote), else past one byte, a dot counted into `parts` and `last` set to it unless
/// it is blank. False, the cursor unmoved, at a non-ASCII byte outside a string.
inline bool step_dotted_name(cursor& c, char& last, std::size_t& parts) {
  if (opens_string(c.peek(), last)) {
    c.skip_string(), last = '"';
    return true;
  }
  if (static_cast<unsigned char>(c.peek()) >= 0x80) return false;
  if (c.peek() == '.') ++parts;
  if (c.peek() != ' ' && c.peek() != '\t') last = c.peek();
  c.next();
  return true;
}

inline std::string non_ascii() {
  return "a non-ASCII character outside a string or comment (a quote or bracket glued to a word opens nothing), or first "
         "after a backslash in a string: TOML reads only ASCII there";
}

inline std::string too_deep() {
  return "nested more than " + std::to_string(toml_bounds::max_nesting) +
         " levels deep (table names, dotted keys, inline tables and arrays): a kin5 machine file nests 3";
}

}  // namespace toml_bounds_detail

/// The first bound `text` breaks (see the file comment), or nothing. Linear in the text's
/// length, with memory bounded by `max_nesting`.
inline std::optional<toml_bound_violation> toml_bounds_violation(std::string_view text) {
  using toml_bounds_detail::cursor;
  using toml_bounds_detail::opens_string;
  if (text.size() > toml_bounds::max_file_bytes)
    return toml_bound_violation{1, 1, "larger than " + std::to_string(toml_bounds::max_file_bytes) +
                                          " bytes, the most a kin5 machine file or tool table may be"};
  cursor c{text};
  std::vector<std::size_t> levels;    // what each open inline table or array adds to the nesting
  std::vector<char> brackets;         // and which it is: '[' or '{'
  std::size_t nesting = 0;            // the parts of the table name in force + the sum of `levels`
  std::size_t pending = 0;            // parts of the key whose value comes next
  bool expect_key = true;             // at a line's start outside any value, or after '{' or ','
  bool line_start = true;
  bool value_start = false;           // at the start of a value: after a key's '=', '[', ',' in an array
  bool glued = false;                 // a quote or bracket glued to a word on this line: toml++
                                      // reads on from there to report it, strings or not
  const auto non_ascii_here = [&] {
    return toml_bound_violation{c.line, c.column, toml_bounds_detail::non_ascii()};
  };
  while (!c.done()) {
    if (c.after_line_end)
      return toml_bound_violation{c.after_line_end->first, c.after_line_end->second, toml_bounds_detail::non_ascii()};
    const char ch = c.peek();
    if (ch == '\n') {
      c.next();
      line_start = true, glued = false;
      value_start = !brackets.empty() && brackets.back() == '[';
      if (brackets.empty()) expect_key = true, pending = 0;
      continue;
    }
    if (ch == ' ' || ch == '\t' || ch == '\r') {
      c.next();
      continue;
    }
    if (ch == '#') {
      c.skip_comment();
      continue;
    }
    if (static_cast<unsigned char>(ch) >= 0x80 && glued) return non_ascii_here();
    if (!expect_key && (ch == '"' || ch == '\'' || ch == '[' || ch == '{') && !(value_start || (ch == '[' && line_start))) {
      glued = true;  // a quote or bracket where no value begins: toml++ stops there and reads on
      c.next();
      continue;
    }
    const bool at_line_start = line_start;
    line_start = false;
    if (expect_key && at_line_start && brackets.empty() && ch == '[') {  // a table name: [a.b] or [[a.b]]
      const unsigned line = c.line, column = c.column;
      c.next();
      std::size_t parts = 1;
      if (c.peek() == '[') c.next(), ++parts;  // an array of tables: one level more
      const std::size_t start = c.i;
      char last = '[';
      while (!c.done() && c.peek() != ']' && c.peek() != '\n') {
        if (!toml_bounds_detail::step_dotted_name(c, last, parts)) return non_ascii_here();
        if (c.i - start > toml_bounds::max_key_bytes) return toml_bound_violation{line, column, toml_bounds_detail::too_long("a table name")};
        if (parts > toml_bounds::max_nesting) return toml_bound_violation{line, column, toml_bounds_detail::too_deep()};
      }
      nesting = parts;
      expect_key = false;  // the rest of the line: a closing bracket and a comment
      continue;
    }
    if (expect_key && ch != '}' && ch != ',') {  // a key, up to its '='
      const unsigned line = c.line, column = c.column;
      const std::size_t start = c.i;
      std::size_t parts = 1;
      char last = '.';  // a quoted part may open the key, or follow a dot
      while (!c.done() && c.peek() != '=' && c.peek() != '\n') {
        if (!toml_bounds_detail::step_dotted_name(c, last, parts)) return non_ascii_here();
        const bool blank = c.text[c.i - 1] == ' ' || c.text[c.i - 1] == '\t';  // blanks before '=' are no key
        if (!blank && c.i - start > toml_bounds::max_key_bytes) return toml_bound_violation{line, column, toml_bounds_detail::too_long("a key")};
        if (nesting + parts > toml_bounds::max_nesting) return toml_bound_violation{line, column, toml_bounds_detail::too_deep()};
      }
      if (!c.done() && c.peek() == '=') c.next();
      value_start = true;
      pending = parts;
      expect_key = false;
      continue;
    }
    if (ch == '"' || ch == '\'') {  // a value's string: value_start (else `glued`, above)
      c.skip_string();
      value_start = false;
      continue;
    }
    if (static_cast<unsigned char>(ch) >= 0x80) return non_ascii_here();  // bare keys, numbers, words: ASCII
    if (ch == '[' || ch == '{') {  // an array or inline table: the value of a key, or inside an array
      const std::size_t adds = pending ? pending : 1;
      if (nesting + adds > toml_bounds::max_nesting) return toml_bound_violation{c.line, c.column, toml_bounds_detail::too_deep()};
      levels.push_back(adds), brackets.push_back(ch);
      nesting += adds;
      pending = 0;
      expect_key = ch == '{';
      value_start = ch == '[';
      c.next();
      continue;
    }
    if (ch == ']' || ch == '}') {
      if (!brackets.empty()) {
        nesting -= levels.back();
        levels.pop_back(), brackets.pop_back();
      }
      pending = 0;
      value_start = false;
      c.next();
      continue;
    }
    if (ch == ',') {
      pending = 0;
      expect_key = !brackets.empty() && brackets.back() == '{';
      value_start = !brackets.empty() && brackets.back() == '[';
      c.next();
      continue;
    }
    value_start = false;
    c.next();  // a number, a date, true or false, or a stray byte: toml++ judges it
  }
  if (c.after_line_end)
    return toml_bound_violation{c.after_line_end->first, c.after_line_end->second, toml_bounds_detail::non_ascii()};
  return std::nullopt;
}

/// A file's text, or why it cannot be read.
struct toml_file_text {
  std::optional<std::string> text;
  std::string error;  ///< "Is a directory", "larger than 4194304 bytes …", strerror's text
};

/// Reads the file at `path` whole, but never more than `toml_bounds::max_file_bytes`: a
/// directory, an unreadable file (a read error: the error's text) and a larger file are refused.
inline toml_file_text read_toml_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return {std::nullopt, "is a directory"};
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return {std::nullopt, std::strerror(errno)};
  std::string text;
  char chunk[1 << 16];
  std::size_t got = 0;
  while (text.size() <= toml_bounds::max_file_bytes && (got = std::fread(chunk, 1, sizeof chunk, f)) > 0)
    text.append(chunk, got);
  const bool failed = std::ferror(f) != 0;
  const int err = errno;
  std::fclose(f);
  if (failed) return {std::nullopt, std::strerror(err)};
  if (text.size() > toml_bounds::max_file_bytes)
    return {std::nullopt, "larger than " + std::to_string(toml_bounds::max_file_bytes) +
                              " bytes, the most a kin5 machine file or tool table may be"};
  return {std::move(text), {}};
}

}  // namespace kin5
