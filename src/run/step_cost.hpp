// rupture/run/step_cost.hpp
// The measured cost of a case's time step, for `rupture check`'s predicted run time (issue
// "Speed"): the state is built as for a run and advanced a few steps on the case's threads, and
// the mean wall time of a step is scaled to the run's step count. A step's cost hardly changes
// during a run (the particles, the grid windows and the interface loops are the same every
// step), so a few steps after a warm-up one predict the stepping. The big output files
// (snapshots, interface profiles) are timed by writing one of each into a temporary directory
// and counted as often as the run writes them; the small ones (history, crack tip) are not.
#pragma once
#include <cstddef>
#include <vector>

#include "input/case.hpp"

namespace rupture {

struct StepCost {
  double setup_seconds = 0.0;           // building the state (seeding, grid, interfaces), s
  int steps = 0;                        // steps timed, after one warm-up step
  double step_seconds = 0.0;            // mean wall time of one timed step, s
  double ns_per_particle_update = 0.0;  // step_seconds / particles, ns
  std::size_t particles = 0;
  double snapshot_seconds = 0.0;   // one snapshot (0 without snapshots), s
  double interface_seconds = 0.0;  // one set of interface profiles (0 without them), s
  // Nested levels with per-level time steps: finest steps per step of each level (coarsest
  // first), and the particle-updates per finest step they give (empty / 0 otherwise).
  std::vector<int> level_periods;
  double updates_per_finest_step = 0.0;
};

// Times at least `min_steps` and at most `max_steps` steps (nested levels with per-level time
// steps: whole cycles of the longest period, whatever the two say), stopping early once `budget_seconds`
// of stepping have passed. Throws what the solver throws (an unstable start is reported as a
// run would report it).
StepCost measure_step_cost(const Case& c, double budget_seconds = 1.0, int min_steps = 3,
                           int max_steps = 20);

// The predicted wall time of the run of `c` in `steps` steps: set-up, the steps at the measured
// cost, and the snapshots and interface profiles it writes (at t = 0, at every multiple of the
// interval and at the end).
double predicted_wall_seconds(const StepCost& cost, const Case& c, long steps);

}  // namespace rupture
