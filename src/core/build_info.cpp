// rupture/core/build_info.cpp
#include "core/build_info.hpp"

#include <fmt/format.h>

#include "core/build_info_values.hpp"  // generated: RUPTURE_GIT_COMMIT, RUPTURE_GIT_DIRTY

namespace rupture {
namespace {

std::string compiler_name() {
#if defined(__clang__)
  return fmt::format("Clang {}.{}.{}", __clang_major__, __clang_minor__, __clang_patchlevel__);
#elif defined(__GNUC__)
  return fmt::format("GCC {}.{}.{}", __GNUC__, __GNUC_MINOR__, __GNUC_PATCHLEVEL__);
#else
  return "unknown compiler";
#endif
}

}  // namespace

const BuildInfo& build_info() {
  static const BuildInfo info{RUPTURE_VERSION, RUPTURE_GIT_COMMIT, RUPTURE_GIT_DIRTY, compiler_name(),
                              RUPTURE_BUILD_TYPE};
  return info;
}

std::string version_line() {
  const BuildInfo& b = build_info();
  return fmt::format("rupture {} (commit {}{}; {}, {})", b.version, b.commit.substr(0, 12), b.dirty ? ", dirty" : "",
                     b.compiler, b.build_type.empty() ? "no build type" : b.build_type);
}

}  // namespace rupture
