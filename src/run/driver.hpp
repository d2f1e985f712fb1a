// rupture/run/driver.hpp
// Runs a validated case to its end time and writes the run directory:
//   DIR/run.json       input echo, version, sizes, dt, timing, status (see io/run_json.hpp)
//   DIR/history.csv    energy history (io/history.hpp)
//   DIR/particles.xdmf + DIR/snapshots/*.h5   particle snapshots (io/snapshot.hpp)
//   DIR/crack_tip.csv, DIR/crack_stretches.csv crack tip and separated stretches (E10, E11)
//   DIR/interface/*.csv                       interface profiles (io/interface_csv.hpp)
// An unstable run stops with status "failed" and a diagnosis; what was written stays valid.
#pragma once
#include <string>

#include <vector>

#include "cohesive/crack_tip.hpp"
#include "io/case.hpp"

namespace rupture {

struct RunOptions {
  std::string output_dir;
  bool progress = true;
};

struct RunResult {
  bool ok = false;
  std::string message;  // diagnosis when !ok
  std::string stop_reason;  // see RunRecord::stop_reason
  long steps = 0;
  double simulated_time = 0.0;         // s
  double wall_seconds = 0.0;           // s
  double particle_updates_per_second = 0.0;
  double cohesive_seconds = 0.0;       // wall time in the cohesive phases, s
  double energy_balance_error = 0.0;   // relative, largest over the history after 1 us
  double energy_balance_error_final = 0.0;  // relative, last history sample
  std::vector<CrackSummary> cracks;    // one per cohesive interface
};

RunResult run_case(const Case& c, const RunOptions& options);

}  // namespace rupture
