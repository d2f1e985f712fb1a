// rupture/run/output_dir.cpp
#include "run/output_dir.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "core/errors.hpp"

namespace rupture {

const std::vector<std::string>& run_files() {
  static const std::vector<std::string> names{
      "run.json",       "history.csv", "crack_tip.csv", "crack_stretches.csv",
      "particles.xdmf", "snapshots",   "interface",     "checkpoint",
      "figures"};
  return names;
}

const std::vector<std::string>& run_file_prefixes() {
  static const std::vector<std::string> prefixes{"crack_tip_", "crack_stretches_", "rupture_time_"};
  return prefixes;
}

void prepare_output_dir(const std::string& dir, bool overwrite) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(fmt::format("output '{}' exists and is not a directory", dir));
  std::vector<fs::path> found;
  for (const std::string& name : run_files())
    for (const std::string& entry : {name, name + ".tmp"})
      if (fs::exists(fs::path(dir) / entry, ec)) found.push_back(fs::path(dir) / entry);
  // Per-interface crack files, named after interfaces the old run may have had and this one not.
  if (fs::is_directory(dir, ec))
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
      const std::string f = e.path().filename().string();
      for (const std::string& prefix : run_file_prefixes())
        if (f.size() > prefix.size() && f.compare(0, prefix.size(), prefix) == 0 &&
            (f.ends_with(".csv") || f.ends_with(".csv.tmp")))
          found.push_back(e.path());
    }
  if (!found.empty() && !overwrite) {
    std::string names;
    for (const fs::path& p : found) names += (names.empty() ? "" : ", ") + p.filename().string();
    throw InputError(fmt::format(
        "output directory '{}' holds another run's files ({}); choose another directory, pass "
        "--overwrite to delete them, or continue that run with: rupture resume {}",
        dir, names, dir));
  }
  for (const fs::path& p : found) {
    fs::remove_all(p, ec);
    if (ec) throw IoError(fmt::format("cannot delete '{}': {}", p.string(), ec.message()));
  }
  fs::create_directories(dir, ec);
  if (ec) throw IoError(fmt::format("cannot create directory '{}': {}", dir, ec.message()));
}

}  // namespace rupture
