// rupture/run/driver.cpp
#include "run/driver.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <omp.h>

#include "core/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/history.hpp"
#include "io/run_json.hpp"
#include "io/snapshot.hpp"
#include "run/progress.hpp"
#include "solver/energy.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "solver/summary.hpp"

namespace rupture {
namespace {

EnergySample sample(const State& s) {
  return {s.time, kinetic_energy(s.particles), strain_energy(s.particles), s.external_work,
          s.initial_energy};
}

// An explicit scheme that goes unstable grows its energy without bound; twice the energy put
// in is far outside any discretization error and catches it long before overflow.
void check_energy(const State& s, const EnergySample& e) {
  const double supplied = e.initial + std::fabs(e.external_work);
  if (e.total() <= 2.0 * supplied || e.total() <= 0.0) return;
  const Particles& P = s.particles;
  std::size_t fastest = 0;
  double vmax = -1.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double v = std::hypot(P.vx[p], P.vy[p]);
    if (v > vmax) vmax = v, fastest = p;
  }
  throw SimulationError(fmt::format(
      "unstable: energy blow-up at step {}, t = {:.6g} s: kinetic + strain = {:.6g} J/m exceeds "
      "twice the energy supplied ({:.6g} J/m); fastest particle {} at (x, y) = ({:.6g}, {:.6g}) "
      "m with |v| = {:.6g} m/s; reduce time.cfl",
      s.step, s.time, e.total(), supplied, fastest, P.x[fastest], P.y[fastest], vmax));
}

}  // namespace

RunResult run_case(const Case& c, const RunOptions& options) {
  namespace fs = std::filesystem;
  fs::create_directories(options.output_dir);
  const std::string dir = options.output_dir;
  if (c.solver.threads > 0) omp_set_num_threads(c.solver.threads);

  const CaseSummary summary = summarize(c);
  State s = make_state(c);
  RunRecord record;
  record.threads = omp_get_max_threads();
  write_file_atomic(dir + "/run.json", run_json(c, summary, record));

  History history;
  std::unique_ptr<SnapshotWriter> snapshots;
  if (c.output.snapshot_interval > 0) snapshots = std::make_unique<SnapshotWriter>(dir);

  history.samples.push_back(sample(s));
  if (snapshots) snapshots->write(s.particles, s.time, s.step);
  // Output times are multiples of the interval; a tiny tolerance absorbs round-off in time.
  const double eps = 1e-6 * s.dt;
  double next_history = c.output.history_interval;
  double next_snapshot = c.output.snapshot_interval;

  Progress progress(summary.steps, c.time.end, c.output.progress_interval, options.progress);
  RunResult result;
  try {
    while (s.time < c.time.end - eps) {
      s.dt = std::min(s.limits.dt, c.time.end - s.time);  // land exactly on the end time
      step(s);
      const bool last = s.time >= c.time.end - eps;
      if (s.time >= next_history - eps || last) {
        history.samples.push_back(sample(s));
        check_energy(s, history.samples.back());
        while (next_history <= s.time + eps) next_history += std::max(c.output.history_interval, s.dt);
      }
      if (snapshots && (s.time >= next_snapshot - eps || last)) {
        snapshots->write(s.particles, s.time, s.step);
        history.write(dir + "/history.csv");
        while (next_snapshot <= s.time + eps) next_snapshot += c.output.snapshot_interval;
      }
      progress.update(s.step, s.time);
    }
    progress.finish(s.step, s.time);
    result.ok = true;
    record.status = "completed";
  } catch (const SimulationError& e) {
    progress.finish(s.step, s.time);
    result.ok = false;
    result.message = e.what();
    record.status = "failed";
    record.message = e.what();
  }
  const double wall = progress.elapsed();
  history.write(dir + "/history.csv");

  const EnergySample& last = history.samples.back();
  result.steps = s.step;
  result.simulated_time = s.time;
  result.wall_seconds = wall;
  result.particle_updates_per_second =
      wall > 0 ? double(s.particles.size()) * double(s.step) / wall : 0.0;
  result.energy_balance_error = last.relative_error();

  record.steps = s.step;
  record.simulated_time = s.time;
  record.wall_seconds = wall;
  record.particle_updates_per_second = result.particle_updates_per_second;
  record.kinetic_energy = last.kinetic;
  record.strain_energy = last.strain;
  record.external_work = last.external_work;
  record.energy_balance_error = last.relative_error();
  write_file_atomic(dir + "/run.json", run_json(c, summary, record));
  return result;
}

}  // namespace rupture
