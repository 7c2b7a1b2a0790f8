// The output of a program command: written as it is made, but seen by nobody until the run has
// succeeded, and never half-written.
//
// What OUT is decides how it is written (checked when the object is made, before any input is
// read, so that a refusal costs nothing):
//   * absent, or a regular file: the text goes to an unnamed temporary file in OUT's directory
//     (O_TMPFILE), linked into place on `commit` — a file that never had a name cannot be left
//     behind by any exit, SIGKILL included. Where the file system has no O_TMPFILE, a named
//     temporary file `.OUT.kin5-XXXXXX` is used instead, removed on every exit the process can
//     catch (an error, and every signal whose default action ends the process but KILL: TERM,
//     INT, HUP, QUIT, XCPU, ALRM, USR1, the real-time ones, a fault's …); those signals are
//     blocked while it is created or renamed.
//     An existing OUT keeps its permission bits and, where allowed, its owner and group.
//   * a symbolic link: written through to the file it names (the link itself is kept).
//   * a FIFO, a character device, or '-' (stdout): the text is spooled to an unnamed temporary
//     file and copied to OUT only on `commit`, so a failed run writes nothing there.
//   * refused, with the reason in `error()`: a directory, a block device, a socket, a read-only
//     file (no write bit in its mode, or not writable by this process) and a file with several
//     hard links (a rename would leave the other names on the old program).
//
// `ignore_write_signals()` makes SIGPIPE and SIGXFSZ (a closed pipe, a file-size limit) into
// write errors (EPIPE, EFBIG) that the commands report and exit 2 on, instead of deaths.
#pragma once

#include <string>

namespace kin5::tool {

/// Turns SIGPIPE and SIGXFSZ into write errors (EPIPE, EFBIG) for the whole process.
void ignore_write_signals();

/// The output program: `buffer()` to append text, `flush_if_full()` as it grows, `commit()` once
/// the run has succeeded; destroyed without a commit, it leaves OUT and the directory unchanged.
class output_file {
 public:
  /// Checks what `path` is ('-': stdout); `ok()` false with `error()` set if it is refused.
  explicit output_file(std::string path);
  output_file(const output_file&) = delete;
  output_file& operator=(const output_file&) = delete;
  ~output_file();

  /// False once OUT is refused or anything has failed; `error()` says why.
  bool ok() const { return !failed_; }
  const std::string& error() const { return error_; }

  /// The text not yet written out; append to it, then call `flush_if_full`.
  std::string& buffer() { return buffer_; }

  /// Writes the buffer to the temporary file once it holds 1 MiB or more.
  bool flush_if_full();

  /// Finishes OUT: the rest of the text, fsync, then the link or rename into place (or the copy
  /// to a FIFO, a device or stdout). False, with `error()` set, if any of it failed.
  bool commit();

  /// Drops the text and the temporary file; OUT is untouched.
  void abandon();

 private:
  enum class kind { file, stream };
  std::string path_;     // OUT as given
  std::string target_;   // the file to replace (symbolic links followed), for kind::file
  kind kind_ = kind::file;
  std::string buffer_;
  int fd_ = -1;          // the temporary file, once opened
  bool opened_ = false;  // open_temporary has run
  bool unnamed_ = false; // fd_ has no name (O_TMPFILE or unlinked)
  bool failed_ = false;
  std::string error_;

  bool classify();
  bool open_temporary();
  bool flush();
  bool link_into_place();
  bool copy_to_stream();
  bool fail(const std::string& why);
  bool fail_errno(const std::string& what, int err);
};

}  // namespace kin5::tool
