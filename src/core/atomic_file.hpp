// rupture/core/atomic_file.hpp
// Files appear whole or not at all: content goes to "<path>.tmp", is flushed to the disk
// (fsync) and then renamed over <path> (rename is atomic on POSIX file systems), and the
// directory is synced so the rename itself survives a crash. A crash or a full disk leaves the
// previous version intact. Every failure throws IoError naming the file and the operating
// system's reason (strerror), and removes the incomplete temporary file.
#pragma once
#include <string>

namespace rupture {

void write_file_atomic(const std::string& path, const std::string& content);

// Flushes a finished temporary file to the disk and renames it into place (then syncs the
// directory); throws IoError on failure.
void commit_file(const std::string& tmp_path, const std::string& path);

// "<what> '<path>': <strerror(errno)>" as an IoError (errno read at the call).
[[noreturn]] void throw_io_error(const std::string& what, const std::string& path);

}  // namespace rupture
