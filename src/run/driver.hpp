// rupture/run/driver.hpp
// Runs a validated case to its end time and writes the run directory:
//   DIR/run.json       input echo, version, sizes, dt, timing, status (see output/run_json.hpp)
//   DIR/history.csv    energy history (output/history.hpp)
//   DIR/particles.xdmf + DIR/snapshots/*.h5   particle snapshots (output/snapshot.hpp)
//   DIR/crack_tip.csv, DIR/crack_stretches.csv crack tip and separated stretches (E10, E11)
//   DIR/interface/*.csv                       interface profiles (output/interface_csv.hpp)
//   DIR/checkpoint/checkpoint.bin              last checkpoint (run/checkpoint.hpp)
// An unstable run stops with status "failed" and a diagnosis; what was written stays valid.
// While running, history.csv, the crack files and run.json (status "running", heartbeat) are
// brought up to date every kFlushSeconds of wall time, so a killed run keeps its record up to
// then. A failed write stops the run (status "failed", stop_reason "io_error", the operating
// system's reason). SIGINT/SIGTERM stop it after the current step with a checkpoint (status
// "interrupted"); run_case with RunOptions::resume continues from the checkpoint, bit for bit.
// Distributed (RunOptions::comm of N > 1 ranks): each rank steps its block's particles, the
// energies in history.csv and run.json are sums over the ranks, rank 0 writes every file; a
// failure on one rank stops all of them with its diagnosis; checkpoints hold a part file per
// rank and resume on any number of ranks (run/checkpoint_ranks.hpp). Not yet distributed
// (refused before any work, naming the key): nested levels and [loads] velocity regions
// (parallel/halo.hpp), Mach-angle readings on runs with interfaces.
#pragma once
#include <string>

#include <vector>

#include "cohesive/crack_tip.hpp"
#include "input/case.hpp"
#include "parallel/comm.hpp"
#include "run/run_context.hpp"

namespace rupture {

inline constexpr double kFlushSeconds = 2.0;  // wall time between updates of the record files

struct RunOptions {
  std::string output_dir;
  bool progress = true;
  bool overwrite = false;            // a fresh run deletes another run's files in output_dir
  bool resume = false;               // continue from output_dir's checkpoint (same case)
  double checkpoint_interval = 0.0;  // simulated s between checkpoints (0: none; on resume: keep)
  long stop_after_steps = 0;         // tests: stop as if interrupted after this step (0: never)
  CaseSource source;                 // kept in checkpoints, for `rupture resume`
  // The processes running the case together (mpirun -n N: parallel/halo.hpp); rank 0 writes
  // the run directory. Every rank calls run_case with the same case and options.
  Comm comm = Comm::single();
  // Distributed: re-split when the measured load drifts (parallel/rebalance.cpp); false keeps
  // the split of t = 0 (results then do not depend on timings, even at round-off).
  bool rebalance = true;
};

// How a run ended; the CLI maps it to its exit code.
enum class Outcome { completed, unstable, io_error, interrupted, error };

struct RunResult {
  bool ok = false;
  Outcome outcome = Outcome::error;
  std::string status;       // as in run.json: completed | failed | interrupted
  std::string message;  // diagnosis when !ok
  std::string stop_reason;  // see RunRecord::stop_reason
  long steps = 0;
  double simulated_time = 0.0;         // s
  double wall_seconds = 0.0;           // s
  double particle_updates_per_second = 0.0;
  double cohesive_seconds = 0.0;       // wall time in the cohesive phases, s
  double growth_seconds = 0.0;         // wall time in crack growth (tips read, segments laid), s
  double energy_balance_error = 0.0;   // relative, largest over the history after 1 us
  double energy_balance_error_final = 0.0;  // relative, last history sample
  std::vector<CrackSummary> cracks;    // one per cohesive interface
  int ranks = 1;                       // processes (distributed runs)
  std::vector<long> particles_per_rank;  // at t = 0, after the split
  std::vector<long> particles_per_rank_end;  // at the end of the run
  long migrations = 0;                 // particle migrations between ranks
  long rebalances = 0;                 // new splits when the load drifted (parallel/halo.hpp)
  long reach_widenings = 0;            // times the ranks' reach widened for far-moved faces (parallel/halo.hpp)
  double exchange_bytes_per_step = 0.0;  // bytes a rank sends its neighbours per step (mean over ranks)
  double exchange_seconds = 0.0;       // wall time in the exchanges, the largest over the ranks, s
  // Each rank's largest resident memory over the run (getrusage: set-up, steps, outputs), MiB.
  std::vector<double> peak_memory_per_rank;
};

RunResult run_case(const Case& c, const RunOptions& options);

}  // namespace rupture
