// rupture/core/atomic_file.cpp
#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/errors.hpp"

namespace rupture {
namespace {

std::string parent_dir(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// Drops a temporary file that could not be completed (frees the space a full disk needs for
// run.json), keeping errno for the message.
[[noreturn]] void fail_and_remove(const std::string& what, const std::string& tmp, int fd) {
  const int err = errno;
  if (fd >= 0) ::close(fd);
  ::unlink(tmp.c_str());
  errno = err;
  throw_io_error(what, tmp);
}

}  // namespace

void throw_io_error(const std::string& what, const std::string& path) {
  const int err = errno;
  throw IoError(fmt::format("{} '{}': {}", what, path,
                            err ? std::strerror(err) : "unknown reason (errno not set)"));
}

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw_io_error("cannot create", tmp);
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      fail_and_remove("error while writing", tmp, fd);
    }
    data += n;
    left -= std::size_t(n);
  }
  if (::fsync(fd) != 0) fail_and_remove("error while writing", tmp, fd);
  if (::close(fd) != 0) fail_and_remove("error while writing", tmp, -1);
  commit_file(tmp, path);
}

void commit_file(const std::string& tmp_path, const std::string& path) {
  // Files written by other libraries (HDF5) are synced here; ours already are (cheap then).
  const int fd = ::open(tmp_path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw_io_error("cannot open", tmp_path);
  if (::fsync(fd) != 0) fail_and_remove("error while writing", tmp_path, fd);
  ::close(fd);
  if (std::rename(tmp_path.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp_path.c_str());
    errno = err;
    throw_io_error(fmt::format("cannot rename '{}' to", tmp_path), path);
  }
  const int dfd = ::open(parent_dir(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {  // best effort: some file systems cannot sync a directory
    ::fsync(dfd);
    ::close(dfd);
  }
}

}  // namespace rupture
