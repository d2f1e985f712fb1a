// rupture/output/run_json.hpp
// DIR/run.json, the machine-readable record of a run. Stable keys (never renamed):
//   dt, steps, cells, particles, wall_seconds, particle_updates_per_second (SI units),
//   energy_balance_error, and for the first cohesive interface crack.initiation_time,
//   crack.sustained_speed, crack.peak_speed, crack.regime (as a nested "crack" object and,
//   for tools that look up dotted names, as flat "crack.*" keys with the same values),
// plus version, git_commit, git_dirty, compiler, build_type (core/build_info.hpp), status ("running" | "completed" | "failed" | "interrupted"), message, input (the
// merged input echo), and derived quantities. While running it is rewritten every few seconds
// with `heartbeat` (UTC, ISO 8601) and `heartbeat_unix` (s): a "running" record whose heartbeat
// is old belongs to a run that was killed. `checkpoint_time`/`checkpoint_step` name the last
// checkpoint, `segments` counts 1 + resumptions. A value that may be absent (no checkpoint yet,
// a crack that never initiated, a Mach angle not measured: -1 in the structs and the CLI lines)
// is null. Rewritten atomically.
#pragma once
#include <array>
#include <cmath>
#include <string>

#include "cohesive/crack_tip.hpp"
#include "input/case.hpp"
#include "solver/summary.hpp"

namespace rupture {

struct RunRecord {
  std::string status = "running";
  std::string message;
  // "end_time", "crack_reached_interface_end" (time.stop_at_interface_end), "failed"
  // (unstable), "io_error", "interrupted" or "error"
  std::string stop_reason;
  std::string run_id;             // the run's identity (made at its start, kept by checkpoints)
  std::string case_hash;          // FNV-1a of the case text and overrides the run started from
  std::string heartbeat;          // wall-clock time of this record, UTC ISO 8601
  double heartbeat_unix = 0.0;    // the same, s since 1970
  double checkpoint_time = -1.0;  // simulated time of the last checkpoint, s (-1: none)
  long checkpoint_step = -1;
  int segments = 1;               // 1 + number of resumptions
  long steps = 0;                 // steps taken
  double simulated_time = 0.0;    // s
  double wall_seconds = 0.0;
  double cohesive_seconds = 0.0;  // part of wall_seconds spent in the cohesive phases
  double growth_seconds = 0.0;    // part of wall_seconds spent in crack growth (tips read, segments laid)
  double particle_updates_per_second = 0.0;
  int threads = 1;
  int ranks = 1;  // processes of a distributed run (mpirun -n N)
  double kinetic_energy = 0.0, strain_energy = 0.0, external_work = 0.0;
  double energy_balance_error = 0.0;        // largest |error| after the first microsecond
  double energy_balance_error_final = 0.0;  // at the last history sample
  double min_cohesive_dt = INFINITY;        // smallest per-step cohesive limit of the run, s
  double cohesive_stored = 0.0, cohesive_dissipated = 0.0;
  std::vector<CrackSummary> cracks;  // one per interface
  // Per interface, its faces where they change field along the line, as they are now (upper,
  // lower; a growing crack that meets an interface changes them: solver/crack_junction.hpp).
  // Empty: the case's (InterfaceSpec::upper_faces / lower_faces).
  std::vector<std::array<std::vector<FaceField>, 2>> faces;
};

std::string run_json(const Case& c, const CaseSummary& s, const RunRecord& r);

// The "run_id" recorded in DIR/run.json ("" when the file or the entry is missing or unreadable).
std::string recorded_run_id(const std::string& dir);

}  // namespace rupture
