// The output file of the program commands; see output_file.hpp for what each kind of OUT gets.
#include "output_file.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace kin5::tool {
namespace {

constexpr std::size_t flush_threshold = std::size_t{1} << 20;

// ---- the one named temporary file, removed by the signal handlers --------------------------

/// The signals after which a named temporary file is removed before the process dies: every one
/// whose default action ends the process and that can be caught — those sent to stop a run
/// (TERM, INT, HUP, QUIT), limits (XCPU; XFSZ and PIPE are ignored, see
/// `ignore_write_signals`), timers (ALRM, VTALRM, PROF), the user's and the real-time ones, and
/// those of a fault (ABRT, SEGV, BUS, FPE, ILL, TRAP, SYS). Not KILL, which cannot be caught.
const std::vector<int>& cleanup_signals() {
  static const std::vector<int> signals = [] {
    std::vector<int> s = {SIGHUP, SIGINT,  SIGQUIT,   SIGILL,  SIGTRAP, SIGABRT, SIGBUS, SIGFPE,
                          SIGUSR1, SIGSEGV, SIGUSR2, SIGALRM, SIGTERM, SIGXCPU, SIGVTALRM, SIGPROF, SIGSYS};
#ifdef SIGIO
    s.push_back(SIGIO);  // SIGPOLL
#endif
#ifdef SIGPWR
    s.push_back(SIGPWR);
#endif
#ifdef SIGSTKFLT
    s.push_back(SIGSTKFLT);
#endif
#ifdef SIGRTMIN
    for (int sig = SIGRTMIN; sig <= SIGRTMAX; ++sig) s.push_back(sig);
#endif
    return s;
  }();
  return signals;
}

/// Whether `sig` reports a fault of the instruction that raised it, which must not be blocked.
bool is_fault(int sig) { return sig == SIGSEGV || sig == SIGBUS || sig == SIGFPE || sig == SIGILL || sig == SIGTRAP; }

char named_temp[PATH_MAX];                  // the path, valid while `named_temp_set`
volatile std::sig_atomic_t named_temp_set = 0;

extern "C" void remove_named_temp_and_die(int sig) {
  if (named_temp_set) ::unlink(named_temp);  // async-signal-safe
  // SA_RESETHAND restored the default action: the process dies of `sig` once this returns.
  ::raise(sig);
}

/// Installs the handlers once, on the signals whose action is still the default (a signal the
/// caller ignores, as under nohup, stays ignored).
void install_cleanup_handlers() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  for (int sig : cleanup_signals()) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction action {};
    action.sa_handler = remove_named_temp_and_die;
    ::sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    ::sigaction(sig, &action, nullptr);
  }
}

/// Blocks the cleanup signals for its lifetime, so that a name is never created or removed
/// without the registry knowing it.
class signals_blocked {
 public:
  signals_blocked() {
    sigset_t set;
    ::sigemptyset(&set);
    for (int sig : cleanup_signals())
      if (!is_fault(sig)) ::sigaddset(&set, sig);  // a fault while blocked is undefined behaviour
    ::sigprocmask(SIG_BLOCK, &set, &old_);
  }
  ~signals_blocked() { ::sigprocmask(SIG_SETMASK, &old_, nullptr); }
  signals_blocked(const signals_blocked&) = delete;
  signals_blocked& operator=(const signals_blocked&) = delete;

 private:
  sigset_t old_;
};

bool register_named_temp(const std::string& path) {
  if (named_temp_set || path.size() >= sizeof named_temp) return false;
  std::memcpy(named_temp, path.c_str(), path.size() + 1);
  named_temp_set = 1;
  return true;
}

void unregister_named_temp() { named_temp_set = 0; }

// ---- paths ---------------------------------------------------------------------------------

std::string directory_of(const std::string& path) {
  const auto slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string file_name_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// `path` with every symbolic link of its last component followed (a dangling link gives the
/// path it names); errno set and nothing on a loop or an unreadable link.
bool follow_links(std::string& path) {
  for (int hop = 0; hop < 40; ++hop) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) return errno == ENOENT;
    if (!S_ISLNK(st.st_mode)) return true;
    char link[PATH_MAX];
    const ssize_t n = ::readlink(path.c_str(), link, sizeof link - 1);
    if (n < 0) return false;
    const std::string to(link, static_cast<std::size_t>(n));
    path = !to.empty() && to[0] == '/' ? to : directory_of(path) + "/" + to;
  }
  errno = ELOOP;
  return false;
}

/// A fresh, unused name for a temporary file beside `target`: `.NAME.kin5-XXXXXX`.
std::string temp_name_beside(const std::string& target) {
  static std::atomic<unsigned> counter{0};
  const auto now = static_cast<unsigned long long>(std::chrono::steady_clock::now().time_since_epoch().count());
  unsigned long long x = now ^ (static_cast<unsigned long long>(::getpid()) << 20) ^ (counter++ * 0x9e3779b97f4a7c15ull);
  static constexpr char letters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::string suffix;
  for (int i = 0; i < 6; ++i, x /= 62) suffix += letters[x % 62];
  return directory_of(target) + "/." + file_name_of(target) + ".kin5-" + suffix;
}

/// Writes all of `bytes` to `fd`; false with errno set on failure.
bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

/// The reason for errno `err`, with a hint for the two that signals used to stand for.
std::string reason(int err) {
  std::string why = std::strerror(err);
  if (err == EPIPE) why += " (the reading end was closed)";
  if (err == EFBIG) why += " (a file-size limit, as set by ulimit -f)";
  return why;
}

/// Whether the O_TMPFILE file `fd` can be linked by name (through /proc).
bool linkable(int fd) {
  const std::string proc = "/proc/self/fd/" + std::to_string(fd);
  return ::access(proc.c_str(), F_OK) == 0;
}

/// An unnamed temporary file in `dir`: O_TMPFILE, or else a named one unlinked at once.
int open_unnamed(const std::string& dir, bool allow_unlinked_fallback) {
#ifdef O_TMPFILE
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) {
    if (linkable(fd) || allow_unlinked_fallback) return fd;
    ::close(fd);
  }
#endif
  if (!allow_unlinked_fallback) return -1;
  std::string temp = dir + "/.kin5-spool-XXXXXX";
  const signals_blocked blocked;
  const int named = ::mkostemp(temp.data(), O_CLOEXEC);
  if (named >= 0) ::unlink(temp.c_str());
  return named;
}

}  // namespace

void ignore_write_signals() {
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
}

// ---- output_file ---------------------------------------------------------------------------

output_file::output_file(std::string path) : path_(std::move(path)) { classify(); }

output_file::~output_file() { abandon(); }

bool output_file::fail(const std::string& why) {
  abandon();
  if (!failed_) error_ = why;
  failed_ = true;
  return false;
}

bool output_file::fail_errno(const std::string& what, int err) {
  return fail(what.empty() ? reason(err) : what + ": " + reason(err));
}

/// Decides how OUT is written, or refuses it.
bool output_file::classify() {
  if (path_ == "-") {
    kind_ = kind::stream;
    return true;
  }
  if (path_.empty()) return fail("no file name");
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0) {
    if (errno != ENOENT) return fail_errno("", errno);
    target_ = path_;  // absent, or a link to an absent file: created where the link points
    if (!follow_links(target_)) return fail_errno("", errno);
    return true;
  }
  if (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode)) {
    kind_ = kind::stream;
    return true;
  }
  if (S_ISDIR(st.st_mode)) return fail("is a directory");
  if (S_ISBLK(st.st_mode)) return fail("is a block device; kin5 writes regular files, FIFOs and character devices");
  if (S_ISSOCK(st.st_mode)) return fail("is a socket; kin5 writes regular files, FIFOs and character devices");
  if (!S_ISREG(st.st_mode)) return fail("is not a regular file, a FIFO or a character device");
  if (st.st_nlink > 1)
    return fail("has " + std::to_string(st.st_nlink) +
                " hard links; replacing it would leave the other names on the old program (write to a new file)");
  if ((st.st_mode & 0222) == 0 || ::faccessat(AT_FDCWD, path_.c_str(), W_OK, AT_EACCESS) != 0)
    return fail("is read-only; kin5 does not replace it (make it writable first)");
  target_ = path_;
  if (!follow_links(target_)) return fail_errno("", errno);
  return true;
}

/// The temporary file: for kind::file in OUT's directory, with OUT's mode (and owner where
/// allowed); for kind::stream an unnamed spool file in $TMPDIR (or /tmp), if one can be made.
bool output_file::open_temporary() {
  if (kind_ == kind::stream) {
    const char* tmp = std::getenv("TMPDIR");
    fd_ = open_unnamed(tmp && *tmp ? tmp : "/tmp", true);
    unnamed_ = fd_ >= 0;
    return true;  // no spool file: the text stays in memory until the commit
  }
  const std::string dir = directory_of(target_);
  const bool named_wanted = std::getenv("KIN5_OUTPUT_NAMED_TEMP") != nullptr;  // to test that path
  if (!named_wanted) fd_ = open_unnamed(dir, false);
  unnamed_ = fd_ >= 0;
  if (fd_ < 0) {
    install_cleanup_handlers();
    std::string temp = dir + "/." + file_name_of(target_) + ".kin5-XXXXXX";
    const signals_blocked blocked;
    fd_ = ::mkostemp(temp.data(), O_CLOEXEC);
    if (fd_ < 0) return fail_errno("cannot create a temporary file in '" + dir + "'", errno);
    if (!register_named_temp(temp)) {
      ::unlink(temp.c_str());
      return fail("the temporary file's path is too long: " + temp);
    }
  }
  struct stat existing {};
  if (::stat(target_.c_str(), &existing) == 0) {
    if (existing.st_uid != ::geteuid() || existing.st_gid != ::getegid())
      if (::fchown(fd_, existing.st_uid, existing.st_gid) != 0) (void)!::fchown(fd_, static_cast<uid_t>(-1), existing.st_gid);
    if (::fchmod(fd_, existing.st_mode & 07777) != 0) return fail_errno("", errno);
  } else {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    if (::fchmod(fd_, 0666 & ~mask) != 0) return fail_errno("", errno);
  }
  return true;
}

bool output_file::flush() {
  if (!opened_) {
    opened_ = true;
    if (!open_temporary()) return false;
  }
  if (fd_ < 0) return true;  // a stream without a spool file: the text stays in memory
  if (!write_all(fd_, buffer_)) return fail_errno("", errno);
  buffer_.clear();
  return true;
}

bool output_file::flush_if_full() {
  if (failed_) return false;
  return buffer_.size() < flush_threshold || flush();
}

/// Puts the finished temporary file at `target_`: a link for an unnamed file whose target is
/// absent, else a rename from a name beside it (signals blocked and the name registered).
bool output_file::link_into_place() {
  if (unnamed_) {
    const std::string proc = "/proc/self/fd/" + std::to_string(fd_);
    if (::linkat(AT_FDCWD, proc.c_str(), AT_FDCWD, target_.c_str(), AT_SYMLINK_FOLLOW) == 0) return true;
    if (errno != EEXIST) return fail_errno("", errno);
    install_cleanup_handlers();
    const signals_blocked blocked;
    for (int attempt = 0;; ++attempt) {
      const std::string temp = temp_name_beside(target_);
      if (::linkat(AT_FDCWD, proc.c_str(), AT_FDCWD, temp.c_str(), AT_SYMLINK_FOLLOW) == 0) {
        if (!register_named_temp(temp)) {
          ::unlink(temp.c_str());
          return fail("the temporary file's path is too long: " + temp);
        }
        break;
      }
      if (errno != EEXIST || attempt == 100) return fail_errno("", errno);
    }
  }
  const signals_blocked blocked;
  if (std::rename(named_temp, target_.c_str()) != 0) return fail_errno("", errno);
  unregister_named_temp();
  return true;
}

/// Copies the spool file, then the buffer, to stdout or to the FIFO or device at OUT.
bool output_file::copy_to_stream() {
  const int out = path_ == "-" ? STDOUT_FILENO : ::open(path_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (out < 0) return fail_errno("", errno);
  bool good = true;
  int err = 0;
  if (fd_ >= 0) {
    good = ::lseek(fd_, 0, SEEK_SET) == 0;
    char chunk[1 << 16];
    while (good) {
      const ssize_t n = ::read(fd_, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        good = n == 0;
        break;
      }
      good = write_all(out, std::string_view(chunk, static_cast<std::size_t>(n)));
    }
  }
  good = good && write_all(out, buffer_);
  if (!good) err = errno;
  if (out != STDOUT_FILENO && ::close(out) != 0 && good) good = false, err = errno;
  if (!good) return fail_errno("", err);
  buffer_.clear();
  return true;
}

bool output_file::commit() {
  if (failed_) return false;
  if (kind_ == kind::stream) {
    if (!copy_to_stream()) return false;
    abandon();
    return true;
  }
  if (!flush()) return false;
  if (::fsync(fd_) != 0) return fail_errno("", errno);
  if (!link_into_place()) return false;
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) return fail_errno("", errno);
  const int dir = ::open(directory_of(target_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) ::fsync(dir), ::close(dir);  // the new name on disk too
  return true;
}

void output_file::abandon() {
  if (fd_ >= 0) ::close(fd_), fd_ = -1;
  if (named_temp_set) {  // the named temporary file, or the name of an unnamed one not renamed
    const signals_blocked blocked;
    ::unlink(named_temp);
    unregister_named_temp();
  }
  buffer_.clear();
  buffer_.shrink_to_fit();
}

}  // namespace kin5::tool
