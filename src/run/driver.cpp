// rupture/run/driver.cpp
#include "run/driver.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <omp.h>

#include "cohesive/crack_tip.hpp"
#include "core/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/history.hpp"
#include "io/interface_csv.hpp"
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
  EnergySample e{s.time, kinetic_energy(s.particles), strain_energy(s.particles), s.external_work,
                 s.initial_energy};
  for (const CohesiveInterface& c : s.interfaces) {
    const double stored = c.stored_energy();
    e.cohesive_stored += stored;
    e.cohesive_dissipated += c.work - stored;  // work on the interface not stored in it (E14)
  }
  return e;
}

// An explicit scheme that goes unstable grows its energy without bound; twice the energy put
// in is far outside any discretization error and catches it long before overflow.
void check_energy(const State& s, const EnergySample& e) {
  const double supplied = e.initial + std::fabs(e.external_work);
  const double mechanical = e.kinetic + e.strain;
  if (mechanical <= 2.0 * supplied || mechanical <= 0.0) return;
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
      s.step, s.time, mechanical, supplied, fastest, P.x[fastest], P.y[fastest], vmax));
}

// Fires at multiples of an interval of simulated time (never when the interval is 0).
struct Schedule {
  double interval, next;
  long count = 1;  // next = count * interval: no round-off accumulates over a long run
  explicit Schedule(double dt) : interval(dt), next(dt) {}
  bool due(double t, double eps) const { return interval > 0 && t >= next - eps; }
  void advance(double t, double eps) {
    while (next <= t + eps) next = double(++count) * interval;
  }
};

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
  if (c.output.snapshot_interval > 0)
    snapshots = std::make_unique<SnapshotWriter>(
        dir, s.particles, c.output.has_snapshot_region ? c.output.snapshot_region : nullptr);
  std::vector<CrackTracker> cracks;
  for (const CohesiveInterface& ci : s.interfaces) {
    const Axis& ax = s.grid.x;
    const int cell = std::clamp(ax.cell_of(ci.spec.end), 0, ax.cells - 1);
    cracks.emplace_back(2.0 * ax.width(cell));  // two cells at the end of the cohesive line
  }
  // Crack speeds are reported against the speeds of the lower body's material.
  std::vector<WaveSpeeds> crack_speeds;  // per interface
  for (const InterfaceSpec& is : c.interfaces)
    crack_speeds.push_back(summary.speeds[std::size_t(c.bodies[is.lower_field].material)]);
  int interface_files = 0;
  auto write_interfaces = [&]() {
    if (s.interfaces.empty()) return;
    fs::create_directories(dir + "/interface");
    for (std::size_t k = 0; k < s.interfaces.size(); ++k)
      write_interface_csv(fmt::format("{}/interface/{}_{:06d}.csv", dir,
                                      k == 0 ? std::string("interface") : c.interface_names[k],
                                      interface_files),
                          s.interfaces[k], s.time);
    ++interface_files;
  };
  auto write_cracks = [&]() {
    if (!cracks.empty()) cracks[0].write(dir, crack_speeds[0].rayleigh, crack_speeds[0].shear);
  };

  history.samples.push_back(sample(s));
  if (snapshots) snapshots->write(s.particles, s.time, s.step);
  if (c.output.interface_interval > 0) write_interfaces();
  for (std::size_t k = 0; k < cracks.size(); ++k) cracks[k].sample(s.interfaces[k], s.time);

  const double eps = 1e-6 * s.dt;  // absorbs round-off in accumulated time
  Schedule hist(c.output.history_interval > 0 ? c.output.history_interval : s.dt);
  Schedule snap(c.output.snapshot_interval), prof(c.output.interface_interval);
  Schedule crack(c.output.crack_sample_interval);

  Progress progress(summary.steps, c.time.end, c.output.progress_interval, options.progress);
  RunResult result;
  try {
    while (s.time < c.time.end - eps) {
      s.dt_cap = c.time.end - s.time;  // land exactly on the end time
      step(s);
      const bool last = s.time >= c.time.end - eps;
      // Crack samples at exact multiples of the interval (E10, E11), however long the step.
      while (crack.due(s.time, eps)) {
        for (std::size_t k = 0; k < cracks.size(); ++k) cracks[k].sample(s.interfaces[k], crack.next);
        crack.advance(crack.next, eps);
      }
      if (last)
        for (std::size_t k = 0; k < cracks.size(); ++k)
          if (cracks[k].samples().back().time < s.time - eps) cracks[k].sample(s.interfaces[k], s.time);
      bool crack_at_end = false;
      if (c.time.stop_at_interface_end)
        for (const CrackTracker& ct : cracks) crack_at_end = crack_at_end || ct.end_reached_time() >= 0.0;
      if (crack_at_end && !last) {
        // Close the record at this time: final samples of every output.
        for (std::size_t k = 0; k < cracks.size(); ++k)
          if (cracks[k].samples().back().time < s.time) cracks[k].sample(s.interfaces[k], s.time);
        history.samples.push_back(sample(s));
        check_energy(s, history.samples.back());
        if (prof.interval > 0) write_interfaces();
        if (snapshots) snapshots->write(s.particles, s.time, s.step);
        record.stop_reason = result.stop_reason = "crack_reached_interface_end";
        break;
      }
      if (hist.due(s.time, eps) || last) {
        history.samples.push_back(sample(s));
        check_energy(s, history.samples.back());
        hist.advance(s.time, eps);
      }
      if (prof.due(s.time, eps) || (last && prof.interval > 0)) {
        write_interfaces();
        prof.advance(s.time, eps);
      }
      if (snapshots && (snap.due(s.time, eps) || last)) {
        snapshots->write(s.particles, s.time, s.step);
        history.write(dir + "/history.csv");
        write_cracks();
        snap.advance(s.time, eps);
      }
      progress.update(s.step, s.time);
    }
    progress.finish(s.step, s.time);
    result.ok = true;
    record.status = "completed";
    if (record.stop_reason.empty()) record.stop_reason = result.stop_reason = "end_time";
  } catch (const SimulationError& e) {
    progress.finish(s.step, s.time);
    result.ok = false;
    result.message = e.what();
    record.status = "failed";
    record.message = e.what();
    record.stop_reason = result.stop_reason = "failed";
  }
  const double wall = progress.elapsed();
  history.write(dir + "/history.csv");
  write_cracks();

  const EnergySample& last = history.samples.back();
  result.steps = s.step;
  result.simulated_time = s.time;
  result.wall_seconds = wall;
  result.particle_updates_per_second =
      wall > 0 ? double(s.particles.size()) * double(s.step) / wall : 0.0;
  result.energy_balance_error = history.max_relative_error(1e-6);
  result.energy_balance_error_final = last.relative_error();
  result.cohesive_seconds = s.cohesive_seconds;
  for (std::size_t k = 0; k < cracks.size(); ++k)
    result.cracks.push_back(cracks[k].summarize(s.interfaces[k], crack_speeds[k]));

  record.steps = s.step;
  record.simulated_time = s.time;
  record.wall_seconds = wall;
  record.particle_updates_per_second = result.particle_updates_per_second;
  record.cohesive_seconds = s.cohesive_seconds;
  record.kinetic_energy = last.kinetic;
  record.strain_energy = last.strain;
  record.external_work = last.external_work;
  record.energy_balance_error = result.energy_balance_error;
  record.energy_balance_error_final = result.energy_balance_error_final;
  record.min_cohesive_dt = s.limits.min_cohesive_dt;
  record.cohesive_stored = last.cohesive_stored;
  record.cohesive_dissipated = last.cohesive_dissipated;
  record.cracks = result.cracks;
  write_file_atomic(dir + "/run.json", run_json(c, summary, record));
  return result;
}

}  // namespace rupture
