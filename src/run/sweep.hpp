// rupture/run/sweep.hpp
// `rupture sweep CASE -o DIR --vary KEY=V1,V2,... [--vary ...] [--set ...] [-j K]`: the
// Cartesian product of the varied values, each run a separate `rupture run` process (so a run
// that fails, even by crashing, leaves the others running) into DIR/<name built from the
// values>, K at a time with the threads split between them. Resumable: a run whose
// DIR/<name>/rupture.out says status=completed is not run again, one with a checkpoint is
// resumed (`rupture resume`), any other is started afresh. Every combination is validated
// before any run starts; an invalid one is reported in its row and not run. DIR/summary.csv
// (rewritten atomically after every run) holds one row per run: the varied values, the
// status, the crack summary the run printed (crack.* key=value lines), the energy error and
// the wall time. SIGINT/SIGTERM are passed on to the running runs (which write a checkpoint),
// and the sweep exits with 4 after writing the summary.
#pragma once
#include <string>
#include <vector>

namespace rupture {

struct SweepAxis {
  std::string key;                  // dotted input key, e.g. boundary.impact.velocity
  std::vector<std::string> values;  // as written (TOML values)
};

struct SweepOptions {
  std::string case_path;            // the case file
  std::string dir;                  // the sweep directory
  std::string exe;                  // the rupture executable the runs are started with
  std::vector<SweepAxis> axes;      // --vary, in order: the first varies slowest
  std::vector<std::string> sets;    // --set for every run
  int jobs = 1;                     // runs at a time
  int threads = 0;                  // threads in all (0: the machine's); split between jobs
  double checkpoint_interval = 0.0; // passed to each run (0: the runs' default)
  bool quiet = false;
};

// "KEY=V1,V2,..." -> axis. Values are split at commas outside brackets and quotes, so
// arrays ([0.0,-0.06]) and strings ("a,b") stay whole. Throws InputError naming the argument.
SweepAxis parse_vary(const std::string& arg);

// The directory name of one combination: "<last key part>_<value>" joined by "__", with
// characters other than letters, digits, '.', '-', '+' replaced by '_'. Distinct combinations
// get distinct names (a clash throws InputError naming both).
std::string sweep_run_name(const std::vector<SweepAxis>& axes, const std::vector<std::size_t>& pick);

// Runs the sweep. Returns 0 when every run completed, 1 when some failed or were invalid,
// 4 when interrupted. Throws InputError for a bad case or option before any run starts.
int run_sweep(const SweepOptions& options);

}  // namespace rupture
