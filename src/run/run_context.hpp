// rupture/run/run_context.hpp
// Everything a run carries from one time step to the next besides the Case: the solver state,
// the crack trackers, the energy history, the output schedules and the snapshot writer. The
// run's start (run/run_setup.cpp) makes it fresh or from a checkpoint (run/checkpoint.hpp), which
// holds all of it, so a resumed run continues bit for bit.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cohesive/crack_tip.hpp"
#include "cohesive/mach_angle.hpp"
#include "output/history.hpp"
#include "output/snapshot.hpp"
#include "output/stations.hpp"
#include "output/stress_intensity.hpp"
#include "solver/crack_growth.hpp"
#include "solver/run_state.hpp"

namespace rupture {

// Fires at multiples of an interval of simulated time (never when the interval is 0).
struct Schedule {
  double interval = 0.0, next = 0.0;
  long count = 1;  // next = count * interval: no round-off accumulates over a long run
  Schedule() = default;
  explicit Schedule(double dt) : interval(dt), next(dt) {}
  bool due(double t, double eps) const { return interval > 0 && t >= next - eps; }
  void advance(double t, double eps) {
    if (interval <= 0) return;  // never fires (a stop without a checkpoint interval lands here)
    while (next <= t + eps) next = double(++count) * interval;
  }
};

// Where the case came from: `rupture resume` rebuilds the identical Case from it (the original
// text and overrides, so no number goes through a print/parse round trip).
struct CaseSource {
  std::string text;                    // the case file as read
  std::string origin;                  // its path when the run started (for messages)
  std::vector<std::string> overrides;  // --set key=value, in order
};

// Every member must also be written in run/checkpoint.cpp (restart is bitwise).
struct RunContext {
  RunState s;  // the levels, the clock and the sums (solver/run_state.hpp)
  History history;
  std::vector<CrackTracker> cracks;           // one per interface
  std::vector<MachReading> mach;              // Mach-angle readings (theory E12), all interfaces
  std::unique_ptr<SnapshotWriter> snapshots;  // null without snapshots
  double eps = 0.0;                           // absorbs round-off in accumulated time, s
  Schedule hist, snap, prof, crack, checkpoint;
  Schedule mach_schedule;  // Mach-angle readings (output.mach_interval)
  std::vector<StationSeries> stations;  // per [stations] entry: the rows recorded so far
  Schedule station_schedule;            // output.station_interval (0: every step)
  std::vector<TipSeries> tips;          // per interface: J, K at its tips (stress_intensity)
  Schedule tip_schedule;                // output.crack_sample_interval where any interface has
                                        // stress_intensity (else never)
  std::vector<CrackGrowthRecord> growth;  // per interface: its grown segments (solver/crack_growth.hpp)
  // Set by the run's set-up: lays recorded segments on the case's interfaces again (a restore
  // calls it before it reads the state that holds their nodes; solver/crack_growth.hpp).
  std::function<void(RunState&, std::vector<CrackGrowthRecord>&)> regrow;
  // After a restore, once the particles are back: the faces of the interfaces the grown cracks
  // meet (solver/crack_growth.hpp rejoin_cracks).
  std::function<void(RunState&, const std::vector<CrackGrowthRecord>&)> rejoin;
  int interface_files = 0;   // interface/*.csv written so far
  double wall_before = 0.0;  // wall seconds of earlier segments (resumed runs)
  double growth_seconds = 0.0;  // wall time in crack growth (tips read, segments laid), whole run, s
  int segments = 1;          // 1 + number of resumptions
  std::string run_id;        // the run's identity (run.json "run_id"): a resume checks it
};

}  // namespace rupture
