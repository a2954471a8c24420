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
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

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

}  // namespace detail

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
  StagedFile f;
  if (auto e = stage_file(path, text, f)) return e;
  return commit_file(f);
}

}  // namespace gridlock
