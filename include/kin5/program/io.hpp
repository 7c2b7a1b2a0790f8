/// @file program/io.hpp
/// One entry point for every NC dialect: `read` and `write` take the dialect as a value and call
/// the reader or writer of that entry of `program::dialects` (program/dialect.hpp);
/// `guess_dialect` recognises a program by markers only one language uses.
///
/// Example:
/// @code
///   namespace kp = kin5::program;
///   auto in = kp::read(*kp::parse_dialect("siemens"), text, "part.mpf");
///   if (!in.ok()) { for (auto& e : in.errors) std::cerr << e.to_string() << '\n'; return; }
///   std::string nc = kp::write(*kp::default_dialect("dmu-80p"), in.parsed);
/// @endcode
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "block.hpp"
#include "dialect.hpp"
#include "read_limits.hpp"
#include "text.hpp"

namespace kin5::program {

/// Reads `text` (the bytes of a file, any line endings) as a program in dialect `d`.
/// `file_name` is only used in the locations of blocks and diagnostics. A text that breaks
/// `limits` (read_limits.hpp) is not read: its one error names the place and the limit.
template <class List = dialects>
read_result read(dialect d, std::string_view text, std::string file_name, const read_limits& limits = {}) {
  if (auto broken = check_limits(text, limits, file_name)) {
    read_result refused;
    refused.parsed.language = d;
    refused.parsed.file = std::move(file_name);
    refused.add_error(std::move(*broken));
    return refused;
  }
  const read_limits_scope scope(limits);
  return visit_dialect<List>(
      d,
      [&]<class D>(std::type_identity<D>) {
        if constexpr (requires(read_result& r, const block_sink& sink) { D::read_blocks(text, file_name, r, sink, limits); }) {
          read_result result;  // a reader that executes the program: within `limits.max_executed_lines`
          result.parsed.language = d;
          result.parsed.file = std::move(file_name);
          D::read_blocks(text, result.parsed.file, result,
                         [&](block&& b) { result.parsed.blocks.push_back(std::move(b)); }, limits);
          return result;
        } else {
          return read_whole(d, text, std::move(file_name), &D::read_blocks);
        }
      },
      [] { return read_result{}; });
}

/// Reads `text` in dialect `d` block by block: `on_block` receives each block in file order as soon
/// as it is read, and errors and warnings go to `diagnostics` (its `parsed` is not touched). This
/// is `read` without the program: memory stays constant, however long the text. A text that
/// breaks `limits` gives no block and one error, as `read`.
inline void read_blocks(dialect d, std::string_view text, const std::string& file_name, read_result& diagnostics,
                        const block_sink& on_block, const read_limits& limits = {}) {
  if (auto broken = check_limits(text, limits, file_name)) {
    diagnostics.add_error(std::move(*broken));
    return;
  }
  const read_limits_scope scope(limits);
  visit_dialect(
      d,
      [&]<class D>(std::type_identity<D>) {
        if constexpr (requires { D::read_blocks(text, file_name, diagnostics, on_block, limits); })
          D::read_blocks(text, file_name, diagnostics, on_block, limits);  // a reader that runs the program
        else
          D::read_blocks(text, file_name, diagnostics, on_block);
        return true;
      },
      [] { return false; });
}

namespace detail {
template <class List>
struct write_options_of;
template <class... D>
struct write_options_of<std::tuple<D...>> {
  using type = std::tuple<typename D::write_options...>;
};
template <class List>
struct writer_of;
template <class... D>
struct writer_of<std::tuple<D...>> {
  using type = std::variant<typename D::writer...>;
};
}  // namespace detail

/// Writer settings for `write`: one `write_options` per dialect, each defaulting to that writer's
/// own defaults; only the written dialect's are used. `settings.of<siemens::dialect>()` is one.
struct write_settings {
  typename detail::write_options_of<dialects>::type options{};
  /// The program's unit when known ahead (`program_unit`, units.hpp), for writers whose dialect
  /// states it once at the top (their `write_options::program_metric`).
  std::optional<bool> program_metric;
  /// The program's name when known ahead, for writers that name their program at the top
  /// (their `write_options::program_name`).
  std::optional<std::string> program_name;

  template <class D>
  typename D::write_options& of() {
    return std::get<typename D::write_options>(options);
  }
  template <class D>
  const typename D::write_options& of() const {
    return std::get<typename D::write_options>(options);
  }
};

/// Writes `p` in dialect `d`, whatever dialect it was read from.
/// Throws `std::invalid_argument` (from the dialect's writer) when a block cannot be written
/// in `d`; the message names the block's source location.
inline std::string write(dialect d, const program& p, const write_settings& settings = {}) {
  return visit_dialect(
      d, [&]<class D>(std::type_identity<D>) { return D::write(p, settings.of<D>()); }, [] { return std::string(); });
}

/// The writer of one dialect, block by block: `write(program)` without the program. The ISO
/// writer is told no tool-axis vectors follow a TCP switch (G43.4, not G43.5): a streaming
/// writer cannot look ahead, and a tool-axis vector then fails with a clear error.
class block_writer {
 public:
  block_writer(dialect d, dialect source, std::string file, const write_settings& settings = {})
      : writer_(make(d, source, std::move(file), settings)) {}

  /// Appends block `b`'s text to `out`; throws `std::invalid_argument` as `write` does.
  void write(std::string& out, const block& b) {
    std::visit([&](auto& w) { w.write(out, b); }, writer_);
  }

  /// Appends what the dialect writes after the last block (Heidenhain: `END PGM`) to `out`;
  /// call once, after the last `write`.
  void finish(std::string& out) {
    std::visit(
        [&](auto& w) {
          if constexpr (requires { w.finish(out); }) w.finish(out);
        },
        writer_);
  }

 private:
  using any_writer = typename detail::writer_of<dialects>::type;
  any_writer writer_;

  static any_writer make(dialect d, dialect source, std::string file, const write_settings& settings) {
    return visit_dialect(
        d,
        [&]<class D>(std::type_identity<D>) {
          typename D::write_options o = settings.of<D>();
          if constexpr (requires { o.program_metric; }) o.program_metric = settings.program_metric;
          if constexpr (requires { o.program_name; })
            if (!o.program_name) o.program_name = settings.program_name;
          return any_writer(std::in_place_type<typename D::writer>, source, std::move(file), o);
        },
        []() -> any_writer { throw std::invalid_argument("block_writer: no such dialect"); });
  }
};

namespace detail {

/// Whether the upper-case keyword `keyword` occurs in `line`, case-insensitively, as a word of
/// its own: not preceded by a letter or digit, not followed by a digit (so `TRAORI` does not
/// match in `XTRAORI`, nor `M128` in `M1280`).
constexpr bool contains_keyword(std::string_view line, std::string_view keyword) {
  for (std::size_t i = 0; i + keyword.size() <= line.size(); ++i) {
    if (i > 0 && (is_letter(line[i - 1]) || is_digit(line[i - 1]))) continue;
    const std::size_t after = i + keyword.size();
    if (after < line.size() && is_digit(line[after])) continue;
    if (starts_with_keyword(line.substr(i), keyword)) return true;
  }
  return false;
}

/// `line` without leading blanks and a leading block number (`N10 `, `10 `).
constexpr std::string_view skip_block_number(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size() && is_space(line[i])) ++i;
  std::size_t j = i;
  if (j < line.size() && (line[j] == 'N' || line[j] == 'n')) ++j;
  const std::size_t digits = j;
  while (j < line.size() && is_digit(line[j])) ++j;
  if (j > digits && (j == line.size() || is_space(line[j]))) {
    i = j;
    while (i < line.size() && is_space(line[i])) ++i;
  }
  return line.substr(i);
}

/// Calls `f` with each piece of `line` outside comments, in order, as any dialect writes them:
/// `( … )` (ISO, Haas, LinuxCNC; Siemens strings and call arguments sit there too), to the end of
/// the line after `;` (Siemens, Heidenhain, LinuxCNC) or `$$` (APT), and whole lines that start
/// (after a block number) with `*` (Heidenhain) or `PPRINT` (APT). A marker in a comment says
/// nothing about the language (`; converted from G234` in a Siemens program).
template <class F>
constexpr void for_each_code_piece(std::string_view line, F&& f) {
  const std::string_view statement = skip_block_number(line);
  if (!statement.empty() && statement.front() == '*') return;
  if (starts_with_keyword(statement, "PPRINT")) return;
  std::size_t start = 0, i = 0;
  for (; i < line.size(); ++i) {
    const char c = line[i];
    if (c == ';' || (c == '$' && i + 1 < line.size() && line[i + 1] == '$')) break;
    if (c != '(') continue;
    f(line.substr(start, i - start));
    const std::size_t close = line.find(')', i);
    if (close == std::string_view::npos) return;
    start = close + 1;
    i = close;
  }
  f(line.substr(start, i - start));
}

}  // namespace detail

/// The dialect of `text` when it carries a marker that only one dialect uses, else nothing.
///
/// Markers are each entry's `markers` (a keyword at the start of a block, after an optional block
/// number, or anywhere in a line), outside comments (`detail::for_each_code_piece`). Text with markers of two dialects, or none, gives nothing: the
/// caller then decides (for example with `default_dialect`). Cost: one pass over the first 200 lines.
template <class List = dialects>
constexpr std::optional<dialect> guess_dialect(std::string_view text) {
  std::array<bool, std::tuple_size_v<List>> seen{};
  std::size_t start = 0, lines = 0;
  while (start < text.size() && lines < 200) {
    std::size_t end = start;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    bool first = true;  // the piece a block starts with
    detail::for_each_code_piece(text.substr(start, end - start), [&](std::string_view piece) {
      const std::string_view statement = detail::skip_block_number(piece);
      for_each_dialect<List>([&]<class D>(std::type_identity<D>, std::size_t i) {
        for (const marker& m : D::markers)
          if (m.where == marker::place::block_start ? first && starts_with_keyword(statement, m.keyword)
                                                    : detail::contains_keyword(piece, m.keyword))
            seen[i] = true;
      });
      first = false;
    });
    start = end + 1;
    ++lines;
  }
  std::optional<dialect> found;
  std::size_t count = 0;
  for_each_dialect<List>([&]<class D>(std::type_identity<D>, std::size_t i) {
    if (seen[i]) found = dialect(i), ++count;
  });
  return count == 1 ? found : std::nullopt;
}

}  // namespace kin5::program
