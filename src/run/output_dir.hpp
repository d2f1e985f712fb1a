// rupture/run/output_dir.hpp
// One run per directory, so `rupture plot` never mixes runs: a directory that holds any of a
// run's files (run_files()) belongs to that run. `rupture run` refuses it unless --overwrite,
// which deletes exactly those entries (and their .tmp leftovers) and nothing else: files of the
// user's own in the directory stay. `rupture resume DIR` reuses its own directory.
#pragma once
#include <string>
#include <vector>

namespace rupture {

// Entries a run (or `rupture plot`) writes directly under its directory.
const std::vector<std::string>& run_files();
// Prefixes of the per-interface files a run writes there (PREFIX + interface name + ".csv").
const std::vector<std::string>& run_file_prefixes();

// Creates `dir` if needed. If it holds another run's files: throws InputError naming them and
// --overwrite, or with overwrite = true deletes them first.
void prepare_output_dir(const std::string& dir, bool overwrite);

}  // namespace rupture
