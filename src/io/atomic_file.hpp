// rupture/io/atomic_file.hpp
// Files appear whole or not at all: content goes to "<path>.tmp" which is then renamed over
// <path> (rename is atomic on POSIX file systems). A crash leaves the previous version intact.
#pragma once
#include <string>

namespace rupture {

void write_file_atomic(const std::string& path, const std::string& content);

// Renames a finished temporary file into place; throws std::runtime_error on failure.
void commit_file(const std::string& tmp_path, const std::string& path);

}  // namespace rupture
