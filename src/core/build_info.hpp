// rupture/core/build_info.hpp
// Which code made a result: the version (CMakeLists.txt project VERSION), the git commit the
// build was made from and whether its tracked files had changes ("dirty"), the compiler and the
// build type. `rupture --version` prints version_line(); run.json records every field, so a
// figure can say which code made it. The commit is read at build time (cmake/build_info.cmake);
// "unknown" outside a git checkout.
#pragma once
#include <string>

namespace rupture {

struct BuildInfo {
  std::string version;     // e.g. 0.1.0
  std::string commit;      // 40 hex digits, or "unknown"
  bool dirty = false;      // the tree had uncommitted changes to tracked files
  std::string compiler;    // e.g. "GCC 12.2.0"
  std::string build_type;  // CMAKE_BUILD_TYPE: Release, Debug, ...
};

const BuildInfo& build_info();

// "rupture 0.1.0 (commit 1234abcd5678, dirty; GCC 12.2.0, Release)".
std::string version_line();

}  // namespace rupture
