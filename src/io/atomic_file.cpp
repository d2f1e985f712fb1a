// rupture/io/atomic_file.cpp
#include "io/atomic_file.hpp"

#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <stdexcept>

namespace rupture {

void write_file_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(fmt::format("cannot write '{}'", tmp));
    out << content;
    out.flush();
    if (!out) throw std::runtime_error(fmt::format("error while writing '{}'", tmp));
  }
  commit_file(tmp, path);
}

void commit_file(const std::string& tmp_path, const std::string& path) {
  if (std::rename(tmp_path.c_str(), path.c_str()) != 0)
    throw std::runtime_error(fmt::format("cannot rename '{}' to '{}'", tmp_path, path));
}

}  // namespace rupture
