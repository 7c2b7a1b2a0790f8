// Outputs that would overwrite the input (same_file.hpp).
#include "same_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

namespace kin5::tool {

std::optional<file_identity> identity_of(const std::string& path, int fd) {
  struct stat st {};
  const int got = path == "-" ? ::fstat(fd, &st) : ::stat(path.c_str(), &st);
  if (got != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  return file_identity{static_cast<unsigned long long>(st.st_dev), static_cast<unsigned long long>(st.st_ino)};
}

namespace {

/// How a message names an output path: "-o part.h", "-o - (stdout)".
std::string named(const std::string& option, const std::string& path) {
  return option + " " + path + (path == "-" ? " (stdout)" : "");
}

}  // namespace

std::optional<std::string> overwrite_refusal(const std::string& input, const std::string& output,
                                             const std::string& report) {
  const auto in = identity_of(input, STDIN_FILENO);
  const auto out = identity_of(output, STDOUT_FILENO);
  std::optional<file_identity> rep;
  if (!report.empty()) rep = identity_of(report, STDOUT_FILENO);
  const std::string input_name = input == "-" ? "the file stdin reads the input from" : "the input file " + input;
  const std::string fix = "; the run would replace what it reads: write to another file";
  if (in && out && *in == *out) return named("-o", output) + " is " + input_name + fix;
  if (in && rep && *in == *rep) return named("--report", report) + " is " + input_name + fix;
  if (out && rep && *out == *rep)
    return named("--report", report) + " and " + named("-o", output) + " are the same file; give the report its own";
  return std::nullopt;
}

}  // namespace kin5::tool
