/// @file program/read_limits.hpp
/// The bounds on what a reader takes in: the size of the file, of a line and the words of a
/// line, and text only (no NUL byte). `check_limits` finds the first place a text breaks one in
/// a single pass before any dialect's lexer runs, so that reading costs memory in proportion to
/// the limits, not to whatever bytes arrive (`/dev/zero`, a line of 60 MiB). `program::read`
/// and `read_blocks` (io.hpp) check them; the tool's options `--max-file-bytes`,
/// `--max-line-bytes`, `--max-block-words`, `--max-executed-lines` and `--max-memory-bytes` (what
/// a translation keeps in memory) raise or lower them
/// (docs/reliability.md gives the defaults' reasons). They also carry where a program's calls of
/// other files look for them (`include_dirs`, `--include-dir`) and what the source machine says
/// of the positions its home moves leave (`rotary_home_deg`).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "block.hpp"
#include "text.hpp"

namespace kin5::program {

/// What a reader accepts. The defaults are far beyond any real program (CAM output of 100 MB
/// with lines of under 100 bytes; a comment line of a few MB).
struct read_limits {
  std::size_t max_file_bytes = std::size_t{1} << 30;  ///< the whole text: 1 GiB
  std::size_t max_line_bytes = std::size_t{16} << 20;  ///< one line without its ending: 16 MiB
  /// Words of one line, counted as `starts_word` does (a block continued over several lines,
  /// Heidenhain `~` or APT `$`, is counted line by line).
  std::size_t max_block_words = 100'000;
  /// Lines a program's interpreter executes in all, counting each pass of a loop or call again
  /// (interp/executor.hpp): past it the program is taken to loop for ever and refused there.
  std::uint64_t max_executed_lines = 100'000'000;
  /// Bytes of executed blocks a translation's first pass keeps in memory for its second
  /// (block_store.hpp): past it, the full chunks of records wait in a temporary file
  /// (`--max-memory-bytes`). 256 MiB: about 3.8 million motion blocks.
  std::size_t max_memory_bytes = std::size_t{256} << 20;
  /// Directories a call of another file searches, in order (called_files.hpp; the tool's
  /// `--include-dir`). None: such a call is refused, naming the file it needs.
  std::vector<std::string> include_dirs{};
  /// A, B, C: the commanded angle at each rotary axis' reference point, from the source
  /// machine's file (`home_deg`; a translation sets it from the machine it reads for). A move to
  /// the reference point (G28) leaves the axis there, so an incremental word after it reaches a
  /// known angle; empty: not known, and such a word is refused.
  std::array<std::optional<double>, 3> rotary_home_deg{};
};

namespace detail {
inline thread_local const read_limits* reading_limits = nullptr;
}  // namespace detail

/// The limits of the reading under way on this thread (`read_limits_scope`), or the defaults:
/// for a reader whose entry point takes none (`max_executed_lines`, read where lines run).
inline const read_limits& current_read_limits() {
  static const read_limits defaults{};
  return detail::reading_limits ? *detail::reading_limits : defaults;
}

/// Makes `limits` this thread's `current_read_limits()` while it lives. It keeps the address of
/// `limits`, which must outlive it: a temporary does not compile.
class read_limits_scope {
 public:
  explicit read_limits_scope(const read_limits& limits) : saved_(detail::reading_limits) {
    detail::reading_limits = &limits;
  }
  explicit read_limits_scope(read_limits&&) = delete;
  ~read_limits_scope() { detail::reading_limits = saved_; }
  read_limits_scope(const read_limits_scope&) = delete;
  read_limits_scope& operator=(const read_limits_scope&) = delete;

 private:
  const read_limits* saved_;
};

/// Whether byte `c` after byte `previous` (a blank at the line's start) starts a word in the
/// count of `read_limits::max_block_words`: a run of letters (and bytes from 0x80, as in a
/// comment in UTF-8) after any other byte; a digit, point or sign after a blank; any other mark
/// (`=`, `(`, `;`, a control byte). At least as many as any dialect's lexer makes of the line.
constexpr bool starts_word(char previous, char c) {
  const auto letter_like = [](char b) { return is_letter(b) || static_cast<unsigned char>(b) >= 0x80; };
  if (is_space(c)) return false;
  if (letter_like(c)) return !letter_like(previous);
  if (is_digit(c) || c == '.' || c == '+' || c == '-') return is_space(previous);
  return true;
}

/// Whether every run of bytes between two LFs (or an end) in `text` is at most `most` bytes
/// long. One look per `most` + 1 bytes, from the end of that window back to its last LF: a
/// run within a window that holds an LF is no longer than the window, so the text costs about
/// `text.size() / most` short searches, not one per line.
constexpr bool lf_runs_within(std::string_view text, std::size_t most) {
  std::size_t start = 0;  // the start of a run
  while (text.size() - start > most) {
    const std::size_t lf = text.substr(start, most + 1).rfind('\n');
    if (lf == std::string_view::npos) return false;
    start += lf + 1;
  }
  return true;
}

/// The first place where `text` breaks `limits`, as an error naming the limit and the option
/// that raises it; none when it keeps them all. In file order: a NUL byte (binary data, refused
/// whatever the limits), a line longer than `max_line_bytes` (at its first byte past it), a
/// line of more than `max_block_words` words (at the first word past them), the text going on
/// past `max_file_bytes` (at its first byte past it). Lines as `for_each_line` splits them.
inline std::optional<diagnostic> check_limits(std::string_view text, const read_limits& limits,
                                              const std::string& file) {
  std::optional<diagnostic> found;
  const auto at = [&](std::size_t line, std::size_t column, std::string message) {
    found = diagnostic{source_location{file, line, column}, std::move(message)};
  };
  const char* const first = text.data();
  const void* const nul = std::memchr(first, '\0', text.size());
  const std::size_t nul_at = nul ? static_cast<std::size_t>(static_cast<const char*>(nul) - first) : text.size();
  const std::size_t scan_to = nul_at < limits.max_file_bytes ? nul_at : limits.max_file_bytes;
  // Lines no longer than the words limit need no count of their words (a word takes a byte),
  // and a line holds no LF: when every run between LFs is that short, nothing is broken.
  if (scan_to == text.size() && lf_runs_within(text, std::min(limits.max_line_bytes, limits.max_block_words)))
    return found;
  std::size_t stop_line = 1, stop_line_offset = 0;  // the line the stop falls in, and where it starts
  for_each_line(text, [&](const text_line& line) {
    const auto offset = static_cast<std::size_t>(line.text.data() - first);
    if (found || offset > scan_to) return;
    stop_line = line.number, stop_line_offset = offset;
    const std::size_t checked = std::min(line.text.size(), scan_to - offset);  // the bytes before the stop
    if (checked > limits.max_line_bytes) {
      at(line.number, limits.max_line_bytes + 1,
         "a line longer than the line-length limit of " + std::to_string(limits.max_line_bytes) +
             " bytes; --max-line-bytes raises it");
      return;
    }
    if (checked <= limits.max_block_words) return;  // a word takes a byte at least
    std::size_t words = 0;
    char previous = ' ';
    for (std::size_t i = 0; i < checked; ++i) {
      const char c = line.text[i];
      if (starts_word(previous, c) && ++words > limits.max_block_words) {
        at(line.number, i + 1,
           "more words in one line than the words-per-block limit of " + std::to_string(limits.max_block_words) +
               "; --max-block-words raises it");
        return;
      }
      previous = c;
    }
  });
  if (!found && scan_to < text.size())
    at(stop_line, scan_to - stop_line_offset + 1,
       scan_to == nul_at ? std::string("a NUL byte (0x00): binary data, not an NC program; give the program's text")
                         : "the input goes on past the file-size limit of " + std::to_string(limits.max_file_bytes) +
                               " bytes; --max-file-bytes raises it");
  return found;
}

}  // namespace kin5::program
