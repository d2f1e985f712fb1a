// rupture/run/driver.cpp
// run_case: the run's start (run/run_setup.hpp), its time loop, and its end
// (run/run_result.hpp). The loop steps, then asks each output (run/outputs.hpp) whether it is
// due, then agrees with the other ranks on signals and failed writes, then checkpoints or stops.
#include "run/driver.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "parallel/halo.hpp"
#include "run/interrupt.hpp"
#include "run/outputs.hpp"
#include "run/run_io.hpp"
#include "run/run_result.hpp"
#include "run/run_setup.hpp"
#include "run/thread_tuner.hpp"
#include "solver/crack_growth.hpp"
#include "solver/step.hpp"
#include "solver/summary.hpp"
#include "solver/tie_follow.hpp"

namespace rupture {
namespace {

// CPU time of the process (all its threads), s.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Added to the step's agreed signal number when rank 0 failed to write (signals are < 128).
constexpr double kWriteFailed = 1024.0;

// One time step; throws SimulationError when the time did not move (the same on every rank:
// one dt for all).
void step_forward(RunState& s) {
  const double t_before = s.time;
  step(s);
  if (!(s.time > t_before))
    throw SimulationError(fmt::format(
        "time does not advance: step {} took t = {:.17g} s by dt = {:.6g} s to {:.17g} s (the "
        "step is below the round-off of the time); time.end / dt is too large",
        s.step, t_before, s.dt, s.time));
}

// Distributed: says so when the split followed the load in this step.
void note_rebalance(const RunState& r, RunResult& result, bool writer) {
  if (!r.halo || r.is_nested()) return;  // nested levels keep their first split
  const Halo& h = halo_of(r.levels[0]);
  if (h.rebalances == result.rebalances) return;
  result.rebalances = h.rebalances;
  if (writer) fmt::print("{}\n", h.last_rebalance);
}

// The step's agreement: a signal on any rank and a write that failed on rank 0 reach every rank
// here (one reduction), and all stop together. Returns the signal (0: none); throws IoError.
int agree_on_step(const RunIo& io) {
  const int signal = interrupt_signal();
  if (io.comm.distributed()) {
    const double code = io.comm.max(double(signal) + (io.pending_write.empty() ? 0.0 : kWriteFailed));
    if (code >= kWriteFailed) throw IoError(io.comm.broadcast(io.pending_write, 0) + " (rank 0)");
    return int(code);
  }
  if (!io.pending_write.empty()) throw IoError(io.pending_write);
  return signal;
}

}  // namespace

RunResult run_case(const Case& c, const RunOptions& options) {
  prepare_dir(options.output_dir, options);
  if (c.solver.threads > 0) omp_set_num_threads(c.solver.threads);
  const CaseSummary summary = summarize(c);
  RunContext ctx;
  std::vector<StationProbe> probes = start_run(ctx, c, summary, options);  // fresh or resumed
  RunState& s = ctx.s;
  enable_rebalance(s, options.rebalance);
  RunIo io(c, summary, options, ctx, std::move(probes));
  RunResult result = starting_result(s, options.comm);
  const long first_step = s.step;  // 0, or the checkpoint's
  open_record(io);
  if (!options.resume) write_first_record(io);
  const RunOutputs outputs = choose_outputs(io);
  begin_steps(io);

  const double eps = ctx.eps;
  const bool growing = std::any_of(c.interfaces.begin(), c.interfaces.end(),
                                   [](const InterfaceSpec& is) { return is.growth.on(); });
  // solver.threads = 0: the thread count from the step times (run/thread_tuner.hpp).
  ThreadTuner tuner(omp_get_max_threads(), c.solver.threads == 0);
  InterruptGuard interrupt_guard;
  RunEnd end;
  try {
    while (s.time < c.time.end - eps) {
      s.dt_cap = c.time.end - s.time;  // land exactly on the end time
      s.sync_by = sync_by(outputs, c.time.end, eps);  // what reads particles waits for the levels
      const auto step_start = std::chrono::steady_clock::now();
      const double cpu_start = process_cpu_seconds();
      step_forward(s);
      const int threads = tuner.threads();
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - step_start).count();
      if (tuner.after_step(wall, process_cpu_seconds() - cpu_start) != threads) omp_set_num_threads(tuner.threads());
      note_rebalance(s, result, io.writer);
      const bool last = s.time >= c.time.end - eps;
      // Between the finest steps of a coarser level's step (per-level time steps) some particles
      // are behind the run's time: what reads particles waits for a synchronized step.
      const bool synced = synchronized(s);
      // Crack growth (solver/crack_growth.hpp): the tips read, and grown, after the step and
      // before the outputs and the checkpoint see it.
      if (synced && growing) {
        const auto t0 = std::chrono::steady_clock::now();
        // Distributed: every rank reads the same tips (their J domains summed over the ranks,
        // solver/crack_tips.hpp; the cracks' end segments from their owners) and takes the same
        // decisions; before the first segment is laid every rank gathers the whole interface
        // state and notes the shapes, and after growth each keeps its part.
        std::vector<InterfaceShapes> before;
        if (s.halo) collect_crack_fronts(s);
        const auto distribute_grown = [&] {
          for (std::size_t l = 0; l < before.size(); ++l) follow_grown_interfaces(s.levels[l], before[l]);
        };
        try {
          grow_cracks(c, s, ctx.growth, [&] {
            if (!s.halo) return;
            collect_interface_state(s);
            for (const State& level : s.levels) before.push_back(interface_shapes(level));
          });
        } catch (const SimulationError&) {
          // A junction that stops the run after a segment was laid (every rank stops at the same
          // point): each rank keeps its part of the grown interfaces again, so the summaries and
          // outputs of the failed run gather a consistent state.
          distribute_grown();
          throw;
        }
        distribute_grown();
        for (std::size_t k = 0; k < ctx.cracks.size() && k < c.interfaces.size(); ++k)
          if (c.interfaces[k].growth.on()) ctx.cracks[k].follow(s.interface(k), true);
        ctx.growth_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      }
      // Ties that follow the material (solver/tie_follow.hpp): laid again where the material or
      // growth has moved them; distributed, over the whole grid with the interfaces' state
      // gathered first, and each rank keeps its part after.
      if (synced) {
        std::vector<InterfaceShapes> before;
        follow_ties(s, [&] {
          if (!s.halo) return;
          collect_interface_state(s);
          for (const State& level : s.levels) before.push_back(interface_shapes(level));
        });
        for (std::size_t l = 0; l < before.size(); ++l) follow_grown_interfaces(s.levels[l], before[l]);
      }
      for (const std::unique_ptr<Output>& out : outputs.each_step) {
        if ((synced || !out->needs_synchronized_state()) && out->due(s.time, eps, last))
          out->write(s.time, eps, last);
        if (io.closed) break;
      }
      if (io.closed) break;  // time.stop_at_interface_end: the record closed at this step
      end.signal = agree_on_step(io);
      if (last) break;
      const bool stop = end.signal != 0 || (options.stop_after_steps > 0 && s.step >= options.stop_after_steps);
      // A checkpoint holds the particles at one time: a stop waits for the levels' steps to
      // end where they would anyway, so the resumed run is bitwise the uninterrupted one.
      if (!synced) continue;
      if (outputs.checkpoint->due(s.time, eps, last) || stop) outputs.checkpoint->write(s.time, eps, last);
      if (stop) {
        io.record.stop_reason = "interrupted";
        break;
      }
    }
  } catch (const SimulationError& e) {
    end.unstable = e.what();
  } catch (const IoError& e) {
    end.io_failure = e.what();
  } catch (const std::filesystem::filesystem_error& e) {
    end.io_failure = e.what();
  }
  io.progress.finish(s.step, s.time);
  return finish_run(io, std::move(result), end, first_step);
}

}  // namespace rupture
