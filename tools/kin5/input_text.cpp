// Reading a program's text within the read limits (input_text.hpp).
#include "input_text.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <new>

namespace kin5::tool {

std::optional<std::string> read_input(const std::string& path, const program::read_limits& limits,
                                      std::string& error) {
  std::FILE* f = stdin;
  if (path != "-") {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
      error = "is a directory";
      return std::nullopt;
    }
    f = std::fopen(path.c_str(), "rb");
    if (!f) {
      error = std::strerror(errno);
      return std::nullopt;
    }
  }
  // One byte past the limit is enough for the reader to say where the text breaks it.
  const std::size_t most = limits.max_file_bytes + (limits.max_file_bytes < SIZE_MAX ? 1 : 0);
  std::string bytes;
  bool failed = false;
  int saved = 0;
  try {
    struct stat st {};
    if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0)  // one allocation for a file
      bytes.reserve(std::min(static_cast<std::size_t>(st.st_size), most));
    constexpr std::size_t chunk = 1 << 20;
    while (bytes.size() < most) {
      const std::size_t old = bytes.size();
      const std::size_t want = std::min(chunk, most - old);
      bytes.resize(old + want);
      const std::size_t got = std::fread(bytes.data() + old, 1, want, f);
      bytes.resize(old + got);
      if (got < want) break;
      if (std::memchr(bytes.data() + old, '\0', got)) break;  // binary: refused at that byte
    }
    failed = std::ferror(f) != 0;
    saved = errno;
  } catch (const std::bad_alloc&) {
    failed = true;
    saved = ENOMEM;
  }
  if (f != stdin) std::fclose(f);
  if (failed) {
    error = saved == ENOMEM ? "not enough memory to hold it; --max-file-bytes lowers the most read"
                            : std::strerror(saved);
    return std::nullopt;
  }
  return bytes;
}

void add_limit_options(CLI::App* sub, program::read_limits& limits) {
  sub->add_option("--max-file-bytes", limits.max_file_bytes,
                  "Refuse an input larger than this many bytes (a number, or with a unit: 100MB, 2GiB); "
                  "default 1GiB")
      ->transform(CLI::AsSizeValue(true))
      ->check(CLI::Range(std::size_t{1}, std::numeric_limits<std::size_t>::max()));
  sub->add_option("--max-line-bytes", limits.max_line_bytes,
                  "Refuse a line of the input longer than this many bytes (a number, or with a unit: 64KiB, "
                  "32MiB); default 16MiB")
      ->transform(CLI::AsSizeValue(true))
      ->check(CLI::Range(std::size_t{1}, std::numeric_limits<std::size_t>::max()));
  sub->add_option("--max-block-words", limits.max_block_words,
                  "Refuse a line of the input with more words than this (every run of letters, number after a "
                  "blank and other mark counts); default 100000")
      ->check(CLI::Range(std::size_t{1}, std::numeric_limits<std::size_t>::max()));
  sub->add_option("--max-executed-lines", limits.max_executed_lines,
                  "Refuse a program that executes more lines than this, counting each pass of a loop or call "
                  "(it may loop for ever); default 100000000")
      ->check(CLI::Range(std::uint64_t{1}, std::numeric_limits<std::uint64_t>::max()));
  sub->add_option("--max-memory-bytes", limits.max_memory_bytes,
                  "Keep at most this many bytes of executed blocks in memory between the two passes of a "
                  "translation; the rest wait in a temporary file (a number, or with a unit: 64MiB); default 256MiB")
      ->transform(CLI::AsSizeValue(true))
      ->check(CLI::Range(std::size_t{1}, std::numeric_limits<std::size_t>::max()));
  sub->add_option("--include-dir", limits.include_dirs,
                  "Directory where a call of another file (M98 P1000, G65 P1000, o<name> call, CALL PGM SUB, "
                  "Siemens L100) finds it; repeatable, searched in the order given, after the calling "
                  "program's own directory for CALL PGM and L100 (docs/user-guide.md)")
      ->allow_extra_args(false)
      ->check(CLI::ExistingDirectory);
}

}  // namespace kin5::tool
