// rupture/run/step_cost.cpp
#include "run/step_cost.hpp"

#include <omp.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "output/interface_csv.hpp"
#include "output/snapshot.hpp"
#include "solver/run_state.hpp"
#include "solver/step.hpp"

namespace rupture {

StepCost measure_step_cost(const Case& c, double budget_seconds, int min_steps, int max_steps) {
  using clock = std::chrono::steady_clock;
  auto seconds = [](clock::time_point a, clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  if (c.solver.threads > 0) omp_set_num_threads(c.solver.threads);
  StepCost cost;
  const auto t0 = clock::now();
  RunState s = make_run_state(c);
  const auto t1 = clock::now();
  cost.setup_seconds = seconds(t0, t1);
  cost.particles = held_particles(s);
  // Per-level time steps (nested levels): a level does its particles' work once per period, so
  // the timed steps are whole cycles of the longest period.
  int cycle = 1;
  if (s.subcycled()) {
    cost.level_periods = s.period;
    for (std::size_t l = 0; l < s.levels.size(); ++l) {
      cycle = std::max(cycle, s.period[l]);
      cost.updates_per_finest_step += double(s.levels[l].particles.size()) / double(s.period[l]);
    }
  }
  min_steps = std::max(min_steps, cycle);
  max_steps = std::max(max_steps, (max_steps + cycle - 1) / cycle * cycle);
  // One warm-up step (first sort, window fit, pages touched), then the timed ones.
  s.dt_cap = c.time.end - s.time;
  step(s);
  const auto t2 = clock::now();
  while (cost.steps < max_steps && s.time < c.time.end) {
    s.dt_cap = c.time.end - s.time;
    step(s);
    ++cost.steps;
    if (cost.steps >= min_steps && cost.steps % cycle == 0 && seconds(t2, clock::now()) >= budget_seconds) break;
  }
  const double stepping = seconds(t2, clock::now());
  cost.step_seconds = cost.steps > 0 ? stepping / cost.steps : 0.0;
  cost.ns_per_particle_update =
      cost.particles > 0 ? 1e9 * cost.step_seconds / double(cost.particles) : 0.0;

  // One snapshot and one set of interface profiles, written as the run writes them.
  namespace fs = std::filesystem;
  const fs::path tmp =
      fs::temp_directory_path() /
      fmt::format("rupture-check-{}-{}", ::getpid(), clock::now().time_since_epoch().count());
  fs::create_directories(tmp / "interface");
  try {
    if (c.output.snapshot_interval > 0) {
      const auto a = clock::now();
      const Particles& all = all_particles(s);
      SnapshotWriter w(tmp.string(), all, c.output.has_snapshot_region ? c.output.snapshot_region : nullptr);
      w.write(all, s.stiffness(), s.time, s.step);
      cost.snapshot_seconds = seconds(a, clock::now());
    }
    if (c.output.interface_interval > 0) {
      const auto a = clock::now();
      for (std::size_t k = 0; k < s.num_interfaces(); ++k)
        write_interface_csv((tmp / "interface" / fmt::format("i{}.csv", k)).string(),
                            s.interface(k), s.time);
      cost.interface_seconds = seconds(a, clock::now());
    }
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw;
  }
  std::error_code ec;
  fs::remove_all(tmp, ec);
  return cost;
}

double predicted_wall_seconds(const StepCost& cost, const Case& c, long steps) {
  // As the driver writes them: at t = 0, at every multiple of the interval, and at the end
  // when the end is not a multiple.
  auto writes = [&](double interval) {
    if (interval <= 0) return 0.0;
    const double n = std::floor(c.time.end / interval * (1.0 + 1e-9));
    return 1.0 + n + (c.time.end > n * interval * (1.0 + 1e-9) ? 1.0 : 0.0);
  };
  return cost.setup_seconds + cost.step_seconds * double(steps) +
         cost.snapshot_seconds * writes(c.output.snapshot_interval) +
         cost.interface_seconds * writes(c.output.interface_interval);
}

}  // namespace rupture
