/// @file program/called_files.hpp
/// Where a call of another file finds it: the include directories of the reading
/// (`read_limits::include_dirs`, the tool's `--include-dir`), searched in the order given; in
/// each, the dialect's file names for the call (`interp::statement::files`) in their order. A
/// name matches a file of the same name, else one whose name differs only in the case of ASCII
/// letters (a program saved on another system as `o1000.NC`); of several such, the first in
/// byte order. The first directory that holds one of the names gives the file. Its text is
/// loaded whole and checked against the reading's limits (read_limits.hpp) and transmission
/// bytes (transmission.hpp) as the main text is.
#pragma once

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "interp/executor.hpp"
#include "read_limits.hpp"
#include "text.hpp"
#include "transmission.hpp"

namespace kin5::program {

/// Whether `a` and `b` are the same but for the case of ASCII letters.
constexpr bool same_name_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  for (std::size_t i = 0; i < a.size(); ++i)
    if (lower(a[i]) != lower(b[i])) return false;
  return true;
}

/// The file in directory `dir` named `name`, or differing only in case (see the file comment).
inline std::optional<std::filesystem::path> file_named(const std::filesystem::path& dir, const std::string& name) {
  std::error_code ec;
  const std::filesystem::path exact = dir / name;
  if (std::filesystem::is_regular_file(exact, ec)) return exact;
  std::optional<std::filesystem::path> found;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string entry = it->path().filename().string();
    if (!same_name_ignoring_case(entry, name) || !it->is_regular_file(ec)) continue;
    if (!found || entry < found->filename().string()) found = it->path();
  }
  return found;
}

/// The first file in `dirs` named one of `names` (see the file comment), or none. A name with
/// directories before it (`parts/SUB.h`, relative to each of `dirs`) has its last part matched.
inline std::optional<std::filesystem::path> find_called_file(const std::vector<std::string>& dirs,
                                                             const std::vector<std::string>& names) {
  for (const std::string& dir : dirs)
    for (const std::string& name : names) {
      const std::filesystem::path relative(name);
      const std::filesystem::path in = relative.has_parent_path() ? std::filesystem::path(dir) / relative.parent_path() : std::filesystem::path(dir);
      if (auto f = file_named(in, relative.filename().string())) return f;
    }
  return std::nullopt;
}

/// The text of the file at `path` for a call: its bytes without transmission bytes, or `error`
/// saying why it cannot be run (unreadable, past `limits`, a byte-order mark or ETX inside).
inline interp::called_file load_called_file(const std::filesystem::path& path, const read_limits& limits) {
  interp::called_file out{path.string(), {}};
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) return out.error = "cannot be read (" + ec.message() + ")", out;
  if (size > limits.max_file_bytes)
    return out.error = "longer than the file-size limit of " + std::to_string(limits.max_file_bytes) +
                       " bytes; --max-file-bytes raises it",
           out;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  if (!(in && bytes << in.rdbuf()) && size > 0) return out.error = "cannot be read", out;
  out.text = std::move(bytes).str();
  if (auto broken = check_limits(out.text, limits, out.path))
    return out.error = "line " + std::to_string(broken->where.line) + ", column " + std::to_string(broken->where.column) +
                       ": " + broken->message,
           out;
  const transmitted_text t = strip_transmission(out.text);
  if (t.body.find("\xEF\xBB\xBF") != std::string_view::npos || t.body.find('\x03') != std::string_view::npos)
    return out.error = "a byte-order mark or end-of-transmission byte inside the program", out;
  out.text = std::string(t.body);
  return out;
}

/// The directory of the file at `path` when it is a file on disk (a program read from a file,
/// not from a standard input or a text in memory), for a dialect whose calls are relative to the
/// calling program's directory (Heidenhain `CALL PGM`); else none.
inline std::optional<std::string> directory_of_file(const std::string& path) {
  std::error_code ec;
  if (path.empty() || !std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

/// Where a call that looks beside its caller first (Heidenhain `CALL PGM`, a Siemens subprogram)
/// finds one of `names`: the directory of `calling_file`, then `include_dirs`, in order.
struct beside_caller_result {
  std::optional<std::filesystem::path> path;  ///< the file found, if any
  std::string not_found;                      ///< else where it was not: "not in the calling program's directory …"
};

/// The file one of `names` is, looked for beside `calling_file` and then in `include_dirs`.
inline beside_caller_result find_beside_caller(const std::string& calling_file, const std::vector<std::string>& names,
                                               const std::vector<std::string>& include_dirs) {
  std::vector<std::string> dirs;
  const auto here = directory_of_file(calling_file);
  if (here) dirs.push_back(*here);
  dirs.insert(dirs.end(), include_dirs.begin(), include_dirs.end());
  if (auto path = find_called_file(dirs, names)) return {std::move(path), {}};
  const bool included = !include_dirs.empty();
  return {std::nullopt, here && included ? "not in the calling program's directory nor in the include directories"
                        : here           ? "not in the calling program's directory"
                        : included       ? "not in the include directories"
                                         : "no directory to look for it in"};
}

/// The executor's opener for calls of files in `limits.include_dirs` (none when it names no
/// directory: a call of a file is then refused, naming the file).
inline interp::file_opener called_file_opener(const read_limits& limits) {
  if (limits.include_dirs.empty()) return {};
  return [limits](const std::string&, const std::vector<std::string>& names) -> std::optional<interp::called_file> {
    const auto path = find_called_file(limits.include_dirs, names);
    if (!path) return std::nullopt;
    return load_called_file(*path, limits);
  };
}

}  // namespace kin5::program
