// Reading a program's text for the commands that take one (translate, reverse, post, match
// --program), within the limits of program/read_limits.hpp, and the options that set them:
//
//   prog::read_limits limits;
//   add_limit_options(sub, limits);
//   ...
//   std::string error;
//   auto bytes = read_input(path, limits, error);  // '-': stdin
//   if (!bytes) fail("cannot read '" + path + "': " + error);
//   // then program::read(d, *bytes, name, limits) or a translator with common_options::limits
//
// `read_input` stops reading at a chunk holding a NUL byte and one byte past --max-file-bytes,
// so that `/dev/zero`, `/dev/urandom` or a FIFO that never ends costs at most the limit; the
// reader's `check_limits` then names the place.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include <kin5/program/read_limits.hpp>

namespace kin5::tool {

/// The bytes of `path` ('-': stdin), read in binary mode up to the first 1 MiB chunk holding a
/// NUL byte, and at most `limits.max_file_bytes` + 1 bytes; nothing, with `error` set, when
/// the file cannot be read (a directory, no permission, an I/O error, no memory).
std::optional<std::string> read_input(const std::string& path, const program::read_limits& limits,
                                      std::string& error);

/// Adds --max-file-bytes, --max-line-bytes, --max-block-words, --max-executed-lines,
/// --max-memory-bytes and --include-dir (repeatable), which set `limits`, to `sub`.
void add_limit_options(CLI::App* sub, program::read_limits& limits);

}  // namespace kin5::tool
