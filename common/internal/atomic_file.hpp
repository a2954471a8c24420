// Checked, atomic file output: nothing half-written, a full disk is an error.
//
//   if (auto err = write_file_atomic(path, text)) ... // err->str():
//                                                     // "PATH: write failed: No space left on device"
//
// A regular file (or a new one) is written to PATH.tmp.XXXXXX in the same
// folder, every write and the close are checked, then it is renamed onto
// PATH: readers see the old file or the whole new one, never a part. On any
// failure the temporary file is removed and PATH is left as it was.
// A path that exists and is not a regular file (/dev/null, /dev/full, a
// FIFO, /dev/stdout) is written in place, every write checked (a device
// cannot be replaced by a rename). A directory is refused ("is a directory").
//
// Signals: the write itself is not interrupted by our SIGINT/SIGTERM
// handlers (they only set a flag, common/limits.hpp), so a campaign that
// stops between files leaves only whole files. Library code returns the
// Diagnostic; tools/cli_common.hpp's write_text_file throws it as
// the command line's UserError (tools/user_error.hpp).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/diagnostic.hpp"

namespace gridlock {

namespace detail {

inline bool write_all(int fd, std::string_view text, int& err) {
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      err = errno;
      return false;
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  return true;
}

// The files this process reads, by device and inode (a name can differ: links,
// "./", "../"), with the name the user gave.
struct ProtectedFile {
  dev_t dev;
  ino_t ino;
  std::string name;
};
inline std::mutex& protected_mutex() {
  static std::mutex m;
  return m;
}
inline std::vector<ProtectedFile>& protected_files() {
  static std::vector<ProtectedFile> files;
  return files;
}

}  // namespace detail

// Inputs are sacred: protect_input(path) records the regular file path
// names (by device and inode; "-", devices and missing paths are ignored),
// and from then on stage_file, commit_file and remove_own_file refuse to
// write over, rename onto or remove it ("PATH: output would overwrite the
// input NAME"). Thread-safe; commands call it for every file they read,
// before any output is written (tools/cli_common.hpp, guard_paths).
inline void protect_input(const std::string& path) {
  struct stat st {};
  if (path == "-" || ::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return;
  std::lock_guard<std::mutex> lock(detail::protected_mutex());
  for (const auto& f : detail::protected_files())
    if (f.dev == st.st_dev && f.ino == st.st_ino) return;
  detail::protected_files().push_back({st.st_dev, st.st_ino, path});
}

// The protected input that path names now (same device and inode), or "".
inline std::string protected_input_at(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return "";
  std::lock_guard<std::mutex> lock(detail::protected_mutex());
  for (const auto& f : detail::protected_files())
    if (f.dev == st.st_dev && f.ino == st.st_ino) return f.name;
  return "";
}

// Removes path, a file gridlock wrote, unless it is a protected input
// (then "PATH: will not remove the input NAME"); a missing file is fine.
inline MaybeError remove_own_file(const std::string& path) {
  if (std::string in = protected_input_at(path); !in.empty())
    return Diagnostic{path, 0, "will not remove the input " + in};
  if (::unlink(path.c_str()) != 0 && errno != ENOENT)
    return Diagnostic{path, 0, std::string("cannot remove: ") + std::strerror(errno)};
  return std::nullopt;
}

// While alive, SIGINT, SIGTERM and SIGHUP are held back (blocked for this
// thread) and delivered when it ends: a temporary file is never left behind
// by a Ctrl-C or a kill, because the signal takes effect only after the
// rename or the removal. (SIGKILL cannot be held back: it can leave a
// PATH.tmp.XXXXXX file, never a half-written PATH.)
class DeferSignals {
 public:
  DeferSignals() {
    sigset_t s;
    sigemptyset(&s);
    sigaddset(&s, SIGINT);
    sigaddset(&s, SIGTERM);
    sigaddset(&s, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &s, &old_);
  }
  ~DeferSignals() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
  DeferSignals(const DeferSignals&) = delete;
  DeferSignals& operator=(const DeferSignals&) = delete;

 private:
  sigset_t old_;
};

// A file written but not yet in place: stage_file writes text to a
// temporary file next to path (or, for a device, straight to it);
// commit_file renames it into place; discard_file removes it. Several files
// can so be staged and committed together (nothing in place if one fails).
struct StagedFile {
  std::string path;
  std::string tmp;  // "" once committed or discarded, or when written in place
};

inline MaybeError stage_file(const std::string& path, std::string_view text, StagedFile& out) {
  out = StagedFile{path, ""};
  if (std::string in = protected_input_at(path); !in.empty())
    return Diagnostic{path, 0, "output would overwrite the input " + in};
  struct stat st {};
  bool exists = ::stat(path.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) return Diagnostic{path, 0, "is a directory, not a file"};
  if (exists && !S_ISREG(st.st_mode)) {
    int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return Diagnostic{path, 0, std::string("cannot write file: ") + std::strerror(errno)};
    int err = 0;
    bool ok = detail::write_all(fd, text, err);
    if (::close(fd) != 0 && ok) ok = false, err = errno;
    if (!ok) return Diagnostic{path, 0, std::string("write failed: ") + std::strerror(err)};
    return std::nullopt;
  }
  std::string tmp = path + ".tmp.XXXXXX";
  int fd = ::mkstemp(tmp.data());
  if (fd < 0) return Diagnostic{path, 0, std::string("cannot write file: ") + std::strerror(errno)};
  int err = 0;
  bool ok = detail::write_all(fd, text, err);
  const mode_t mode = exists ? (st.st_mode & 07777) : 0644;
  if (ok && ::fchmod(fd, mode) != 0) ok = false, err = errno;
  if (::close(fd) != 0 && ok) ok = false, err = errno;
  if (!ok) {
    ::unlink(tmp.c_str());
    return Diagnostic{path, 0, std::string("write failed: ") + std::strerror(err)};
  }
  out.tmp = tmp;
  return std::nullopt;
}

inline MaybeError commit_file(StagedFile& f) {
  if (f.tmp.empty()) return std::nullopt;
  if (std::string in = protected_input_at(f.path); !in.empty()) {
    ::unlink(f.tmp.c_str());
    f.tmp.clear();
    return Diagnostic{f.path, 0, "output would overwrite the input " + in};
  }
  if (::rename(f.tmp.c_str(), f.path.c_str()) != 0) {
    int err = errno;
    ::unlink(f.tmp.c_str());
    f.tmp.clear();
    return Diagnostic{f.path, 0, std::string("write failed: ") + std::strerror(err)};
  }
  f.tmp.clear();
  return std::nullopt;
}

inline void discard_file(StagedFile& f) {
  if (!f.tmp.empty()) ::unlink(f.tmp.c_str());
  f.tmp.clear();
}

// Writes text to path atomically (see above). Mode of a new file: 0644;
// an existing regular file keeps its mode.
inline MaybeError write_file_atomic(const std::string& path, std::string_view text) {
  DeferSignals hold;  // no temporary file outlives a signal
  StagedFile f;
  if (auto e = stage_file(path, text, f)) return e;
  return commit_file(f);
}

}  // namespace gridlock
