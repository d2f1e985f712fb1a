// rupture/run/run_result.cpp
#include "run/run_result.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <fmt/format.h>
#include <vector>

#include "cohesive/crack_tip.hpp"
#include "cohesive/mach_angle.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "parallel/halo.hpp"

namespace rupture {
namespace {

// A per-rank value in every rank's slot, summed: known to every rank (collective).
std::vector<double> per_rank(const Comm& comm, double mine) {
  std::vector<double> all(std::size_t(comm.size()), 0.0);
  all[std::size_t(comm.rank())] = mine;
  comm.sum(all.data(), int(all.size()));
  return all;
}

// The outcome of a loop that ended without an I/O failure: completed, interrupted (a stop
// with its checkpoint) or unstable.
void settle_outcome(RunIo& io, RunResult& result, const RunEnd& end) {
  RunRecord& record = io.record;
  if (!end.unstable.empty()) {
    result.outcome = Outcome::unstable;
    result.message = record.message = end.unstable;
    record.status = "failed";
    record.stop_reason = "failed";
  } else if (end.io_failure.empty() && record.stop_reason == "interrupted") {
    result.outcome = Outcome::interrupted;
    record.status = "interrupted";
    record.message = result.message = fmt::format(
        "interrupted{} at step {}, t = {:.6e} s; checkpoint written; resume with: rupture "
        "resume {}",
        end.signal ? fmt::format(" by signal {}", end.signal) : std::string(), io.s.step, io.s.time, io.dir);
  } else if (end.io_failure.empty()) {
    result.ok = true;
    result.outcome = Outcome::completed;
    record.status = "completed";
    if (record.stop_reason.empty()) record.stop_reason = "end_time";
  }
}

// The record files once more (rank 0), and the failed write that ends the run, if any.
void write_last_files(RunIo& io, RunResult& result, std::string io_failure) {
  if (io_failure.empty() && !io.pending_write.empty()) io_failure = io.pending_write;  // at the last step
  if (io.writer) {  // after a failed write too: the small files may still fit
    try {
      write_record_files(io);
    } catch (const std::exception& e) {
      if (io_failure.empty()) io_failure = e.what();
    }
  }
  if (io_failure.empty()) return;
  result.ok = false;
  result.outcome = Outcome::io_error;
  result.message = io.record.message = io_failure;
  io.record.status = "failed";
  io.record.stop_reason = "io_error";
}

// Steps, times and rates (as run.json's record has them), and the distributed run's sums.
void add_totals(RunIo& io, RunResult& result, long first_step) {
  const RunState& s = io.s;
  const Comm& comm = io.comm;
  const RunRecord& record = io.record;
  result.status = record.status;
  result.stop_reason = record.stop_reason;
  result.steps = s.step;
  result.simulated_time = s.time;
  result.wall_seconds = record.wall_seconds;
  result.particle_updates_per_second = record.particle_updates_per_second;
  result.energy_balance_error = record.energy_balance_error;
  result.energy_balance_error_final = record.energy_balance_error_final;
  result.cohesive_seconds = s.cohesive_seconds;
  result.growth_seconds = record.growth_seconds;
  if (s.halo) {
    result.migrations = halo_of(s).migrations;
    result.reach_widenings = halo_of(s).widenings;
    const long steps = std::max(1L, s.step - first_step);  // this process's steps
    const ExchangeCost cost = exchange_cost(s);
    result.exchange_bytes_per_step = comm.sum(cost.bytes_sent) / double(comm.size()) / double(steps);
    result.exchange_seconds = comm.max(cost.seconds);
  }
  // Every rank's particles now, and what a split that cannot follow the load became.
  for (const double n : per_rank(comm, double(held_particles(s)))) result.particles_per_rank_end.push_back(long(n));
  const std::string drift = kept_split_drift(s, comm, result.particles_per_rank, result.particles_per_rank_end);
  if (io.writer && !drift.empty()) fmt::print("{}\n", drift);
  rusage use{};
  getrusage(RUSAGE_SELF, &use);
  result.peak_memory_per_rank = per_rank(comm, double(use.ru_maxrss) / 1024.0);  // Linux: KiB
}

// Each interface's crack summary with its Mach-angle readings (distributed: every node from
// its owner first).
void add_crack_summaries(RunIo& io, RunResult& result) {
  RunState& s = io.s;
  collect_interface_state(s);
  const std::vector<CrackTracker>& cracks = io.ctx.cracks;
  for (std::size_t k = 0; k < cracks.size(); ++k) {
    CrackSummary cs = cracks[k].summarize(s.interface(k), io.crack_speeds[k]);
    const MachSummary m = summarize_mach(io.ctx.mach, int(k), cs.steady_begin, cs.steady_end);
    cs.mach_readings = m.readings;
    cs.mach_angle = m.angle;
    cs.mach_angle_spread = m.angle_spread;
    cs.mach_angle_left = m.angle_left;
    cs.mach_angle_right = m.angle_right;
    cs.mach_speed = m.speed;
    if (is_fault(s.interface(k))) {  // the front outside the nucleation patch (faults)
      cs.fault = true;
      const InterfaceSpec& is = io.c.interfaces[k];
      double c_max = 0.0;  // the fastest wave of the two sides
      for (const int b : {is.upper_body, is.lower_body})
        c_max = std::max(c_max, io.summary.speeds[std::size_t(io.c.bodies[std::size_t(b)].material)].dilatational);
      cs.front = summarize_front(s.interface(k), io.c.grid.cell_size, io.summary.dt, c_max,
                                 io.crack_speeds[k]);
    }
    if (io.c.interfaces[k].growth.on() && k < io.ctx.growth.size()) {
      const CrackGrowthRecord& g = io.ctx.growth[k];
      cs.grows = true;
      cs.initiated = g.grown();
      cs.initiation_time = g.initiation_time();
      cs.initial_angle = g.initial_angle();
      cs.branches = g.branches();
      cs.grown_length = g.length();
      cs.nucleates = io.c.interfaces[k].nucleation_strength > 0.0;
      cs.nucleation_time = g.nucleation_time;
    }
    result.cracks.push_back(cs);
  }
}

// run.json as the run ended; when it cannot be written, the run failed (or says so too).
void write_final_run_json(RunIo& io, RunResult& result) {
  try {
    if (io.writer) write_file_atomic(io.dir + "/run.json", run_json(io.c, io.summary, io.record));
  } catch (const IoError& e) {
    if (result.outcome == Outcome::io_error) {
      result.message += fmt::format("; run.json could not be updated either ({})", e.what());
    } else {
      result.ok = false;
      result.outcome = Outcome::io_error;
      result.status = "failed";
      result.stop_reason = "io_error";
      result.message = e.what();
    }
  }
}

}  // namespace

RunResult starting_result(const RunState& s, const Comm& comm) {
  RunResult result;
  result.ranks = comm.size();
  for (const double n : per_rank(comm, double(held_particles(s)))) result.particles_per_rank.push_back(long(n));
  return result;
}

RunResult finish_run(RunIo& io, RunResult result, const RunEnd& end, long first_step) {
  settle_outcome(io, result, end);
  write_last_files(io, result, end.io_failure);
  fill_record(io);
  add_totals(io, result, first_step);
  add_crack_summaries(io, result);
  io.record.cracks = result.cracks;
  write_final_run_json(io, result);
  return result;
}

}  // namespace rupture
