// Whether an output of a program command would overwrite its input: `-o` or `--report` naming
// IN directly, through a symbolic link or by another hard link, `-` (stdout) redirected onto IN,
// or IN `-` (stdin) redirected from OUT; and `-o` and `--report` naming one file. Files are
// compared by device and inode, which every name of a file shares; only regular files count (a
// terminal or /dev/null read and written is no loss).
//
//   if (const auto why = overwrite_refusal(in, out, report)) { print(*why); return usage; }
#pragma once

#include <optional>
#include <string>

namespace kin5::tool {

/// A regular file as the kernel knows it: device and inode.
struct file_identity {
  unsigned long long device = 0, inode = 0;
  friend bool operator==(const file_identity&, const file_identity&) = default;
};

/// The regular file `path` names, links followed ('-': whatever `fd` is); nothing when it is
/// absent or not a regular file.
std::optional<file_identity> identity_of(const std::string& path, int fd);

/// Why the run must not start (a usage error), or nothing: OUT (`output`, '-' stdout) or the
/// report (`report`, empty for none) is the input file (`input`, '-' stdin), or OUT and the
/// report are one file.
std::optional<std::string> overwrite_refusal(const std::string& input, const std::string& output,
                                             const std::string& report);

}  // namespace kin5::tool
