// rupture/run/driver.cpp
#include "run/driver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <random>
#include <omp.h>
#include <sys/resource.h>

#include "cohesive/crack_tip.hpp"
#include "cohesive/mach_angle.hpp"
#include "core/errors.hpp"
#include "core/fault_injection.hpp"
#include "core/atomic_file.hpp"
#include "run/checkpoint.hpp"
#include "run/checkpoint_ranks.hpp"
#include "io/csv_units.hpp"
#include "io/history.hpp"
#include "io/interface_csv.hpp"
#include "io/run_json.hpp"
#include "io/snapshot.hpp"
#include "parallel/agreement.hpp"
#include "parallel/halo.hpp"
#include "run/interrupt.hpp"
#include "run/output_dir.hpp"
#include "run/progress.hpp"
#include "solver/energy.hpp"
#include "solver/case_seeding.hpp"
#include "solver/nested_state.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "solver/summary.hpp"

namespace rupture {
namespace {

// Added to the step's agreed signal number when rank 0 failed to write (signals are < 128).
constexpr double kWriteFailed = 1024.0;

EnergySample sample(State& s) {
  // Distributed: the sums over particles and owned nodes, added over the ranks; every
  // interface node's state from its owner.
  double part[3] = {kinetic_energy(s.particles), s.strain_work, s.external_work};
  if (s.halo) s.halo->comm.sum(part, 3);
  gather_interface_state(s);
  EnergySample e{s.time, part[0], part[1], part[2], s.initial_energy};
  for (std::size_t k = 0; k < s.interfaces.size(); ++k) {
    const double stored = s.interfaces[k].stored_energy();
    e.cohesive_stored += stored;
    e.cohesive_dissipated += interface_work(s, k) - stored;  // work not stored in it (E14)
  }
  return e;
}

// An explicit scheme that goes unstable grows its energy without bound; twice the energy put
// in is far outside any discretization error and catches it long before overflow. The energy
// put in by the loads is the most their work has been so far (`peak_work`, J/m, updated
// here): absorbing edges take it out again (negative work), and what is left in the bodies
// (a reflection's worth) must not read as a blow-up.
void check_energy(const State& s, const EnergySample& e, double& peak_work) {
  // A prestressed fault (traction-offset form) releases energy into the bulk: its work on the
  // bodies, -work > 0, is supplied too.
  double released = 0.0;
  for (std::size_t k = 0; k < s.interfaces.size(); ++k) released += std::max(0.0, -interface_work(s, k));
  peak_work = std::max(peak_work, std::fabs(e.external_work));
  const double supplied = e.initial + peak_work + released;
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

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void stamp_heartbeat(RunRecord& r) {
  const auto now = std::chrono::system_clock::now();
  r.heartbeat_unix = std::chrono::duration<double>(now.time_since_epoch()).count();
  const std::time_t t = std::chrono::system_clock::to_time_t(now);
  std::tm utc{};
  gmtime_r(&t, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  r.heartbeat = buf;
}

// Sets up a run's context from the case: the initial state, one crack tracker per interface,
// the snapshot writer and the output schedules; returns where the stations read. A fresh run
// starts from it; a resumed one overwrites it with the checkpoint. Distributed, each rank makes
// its own particles only (parallel/halo.hpp: make_rank_state) and chooses the snapshot rows and
// the stations' particles among every particle the case seeds (solver/case_seeding.hpp), as
// one process chooses them.
std::vector<StationProbe> set_up(RunContext& r, const Case& c, const std::string& dir,
                                 double checkpoint_interval, const Comm& comm, bool resume) {
  const bool by_rank = comm.distributed();
  // A distributed resume builds no particle: the checkpoint brings them and their sums.
  r.s = !by_rank ? make_state(c) : resume ? make_state_without_particles(c) : make_rank_state(c, comm);
  const double* region = c.output.has_snapshot_region ? c.output.snapshot_region : nullptr;
  std::vector<StationProbe> probes;
  if (by_rank) {
    SnapshotRows rows;
    std::vector<NearestParticle> nearest;
    for (const StationSpec& st : c.stations) nearest.push_back({st.x, st.y});
    if (c.output.snapshot_interval > 0 || !c.stations.empty())
      for_each_run_point(c, r.s, [&](double x, double y, std::uint32_t id) {
        if (in_snapshot_region(region, x, y)) rows.add(id);
        for (NearestParticle& n : nearest) n.visit(x, y, id);
      });
    if (c.output.snapshot_interval > 0) r.snapshots = std::make_unique<SnapshotWriter>(dir, std::move(rows), comm);
    std::vector<std::uint32_t> ids;
    for (const NearestParticle& n : nearest) ids.push_back(n.id);
    probes = make_probes(c.stations, r.s, &ids);
  } else {
    // Which particles the snapshots hold and the stations read (every particle at t = 0).
    if (c.output.snapshot_interval > 0) r.snapshots = std::make_unique<SnapshotWriter>(dir, r.s.particles, region, comm);
    probes = make_probes(c.stations, r.s);
  }
  const State& s = r.s;
  for (const CohesiveInterface& ci : s.interfaces) {
    // The cell width along the line at node k (the width in the line's direction).
    auto cell_along = [&](std::size_t k) {
      const int i = std::clamp(s.grid.x.cell_of(ci.x0[k]), 0, s.grid.x.cells - 1);
      const int j = std::clamp(s.grid.y.cell_of(ci.y0[k]), 0, s.grid.y.cells - 1);
      return std::fabs(ci.node_ny[k]) * s.grid.x.width(i) + std::fabs(ci.node_nx[k]) * s.grid.y.width(j);
    };
    // Two cells at the end of the cohesive line; a daughter crack needs an intact ligament of
    // one cell (the smaller at the line's two ends) between it and the main crack.
    const double w_end = cell_along(ci.x0.size() - 1);
    r.cracks.emplace_back(ci, 2.0 * w_end, std::min(cell_along(0), w_end));
  }
  r.eps = 1e-6 * s.dt;  // absorbs round-off in accumulated time
  r.hist = Schedule(c.output.history_interval > 0 ? c.output.history_interval : s.dt);
  r.snap = Schedule(c.output.snapshot_interval);
  r.prof = Schedule(c.output.interface_interval);
  r.crack = Schedule(c.output.crack_sample_interval);
  r.checkpoint = Schedule(checkpoint_interval);
  r.mach_schedule = Schedule(c.output.mach_interval);
  r.station_schedule = Schedule(c.output.station_interval);
  return probes;
}

// A new run's identity: 64 random bits in hex (rank 0's, sent to every rank). Checkpoints keep
// it, and a resume refuses a checkpoint whose identity is not the run directory's.
std::string make_run_id(const Comm& comm) {
  std::string id;
  if (comm.rank() == 0) {
    std::random_device rd;
    const std::uint64_t bits = (std::uint64_t(rd()) << 32) ^ std::uint64_t(rd()) ^
                               std::uint64_t(std::chrono::system_clock::now().time_since_epoch().count());
    id = fmt::format("{:016x}", bits);
  }
  return comm.broadcast(id, 0);
}

// FNV-1a of the case text and its overrides, in hex: which input a run started from.
std::string case_hash(const CaseSource& source) {
  std::uint64_t h = 1469598103934665603ull;
  auto add = [&](const std::string& text) {
    for (const unsigned char ch : text) h = (h ^ ch) * 1099511628211ull;
    h = (h ^ 0xffu) * 1099511628211ull;  // a separator no text byte can fake alone
  };
  add(source.text);
  for (const std::string& o : source.overrides) add(o);
  return fmt::format("{:016x}", h);
}

// run.json of a run that failed before its first step (best effort: the error is reported
// either way).
void record_setup_failure(const std::string& dir, const Case& c, const CaseSummary& summary, int ranks,
                          const std::string& message) {
  RunRecord r;
  r.status = "failed";
  r.stop_reason = "error";
  r.message = message;
  r.ranks = ranks;
  r.threads = omp_get_max_threads();
  stamp_heartbeat(r);
  try {
    write_file_atomic(dir + "/run.json", run_json(c, summary, r));
  } catch (const std::exception&) {
  }
}

// Rank 0 prepares the directory; every rank learns whether it could (InputError on all).
void prepare_dir(const std::string& dir, const RunOptions& o) {
  std::string error;
  if (o.comm.rank() == 0) {
    try {
      if (o.resume)
        std::filesystem::create_directories(dir);
      else
        prepare_output_dir(dir, o.overwrite);
    } catch (const std::exception& e) {
      error = e.what();
      if (!o.comm.distributed()) throw;
    }
  }
  error = o.comm.broadcast(error, 0);
  if (!error.empty()) throw InputError(error);
}

}  // namespace

RunResult run_case(const Case& c, const RunOptions& options) {
  namespace fs = std::filesystem;
  const std::string dir = options.output_dir;
  const Comm& comm = options.comm;
  const bool writer = comm.rank() == 0;  // the rank that writes the run directory
  prepare_dir(dir, options);
  if (c.solver.threads > 0) omp_set_num_threads(c.solver.threads);

  const CaseSummary summary = summarize(c);
  RunContext ctx;
  // Where the stations read, from the state at t = 0 (a body station follows the particle
  // nearest its point then), before a checkpoint replaces the state.
  std::vector<StationProbe> probes;
  try {
  probes = set_up(ctx, c, dir, options.checkpoint_interval, comm, options.resume);
  if (!options.resume) ctx.run_id = make_run_id(comm);  // a resume takes the checkpoint's
  // Set-up and resume: what one rank cannot do (a checkpoint entry refused, a part file
  // missing, memory) stops every rank with its message (parallel/agreement.hpp), before any
  // collective call that the failed rank would never make.
  agree_on_failure(comm, [&] {
    if (fault_due(FaultSite::setup, 0)) throw IoError("injected set-up failure (RUPTURE_INJECT_FAULT)");
  });
  if (options.resume) {
    std::vector<std::vector<double>> keys;
    agree_on_failure(comm, [&] {
      read_checkpoint(checkpoint_path(dir), ctx);
      // A checkpoint copied in from another run would replace this run's history.
      const std::string here = recorded_run_id(dir);
      if (!here.empty() && here != ctx.run_id)
        throw InputError(fmt::format(
            "checkpoint '{}' belongs to run {}, but the run directory's run.json is run {}: it was "
            "copied from another run; resume that run's own directory",
            checkpoint_path(dir), ctx.run_id.empty() ? "(none recorded)" : ctx.run_id, here));
      // Distributed: each rank reads some of the parts (a distributed run's checkpoint), or
      // every particle from checkpoint.bin (one process wrote it).
      if (comm.distributed() && ctx.s.particle_parts > 0) keys = read_checkpoint_share(dir, ctx, comm);
      if (!comm.distributed()) read_checkpoint_particles(dir, ctx);  // every part, if any
    });
    // Split by where the particles are now (any number of ranks, whatever wrote it).
    if (comm.distributed() && !keys.empty()) {
      split_held_particles(ctx.s, comm, keys);  // sends each particle to its rank
    } else if (comm.distributed()) {
      distribute(ctx.s, comm, false);  // one process's checkpoint: its particles split
    }
    ++ctx.segments;
    if (ctx.snapshots) {  // snapshot files deleted since: particles.xdmf names only what exists
      const std::vector<std::string> gone = ctx.snapshots->drop_missing_files();
      if (!gone.empty() && writer)
        fmt::print(stderr, "warning: {} snapshot file(s) of this run are missing ({}{}): left out of "
                           "particles.xdmf\n",
                   gone.size(), gone.front(), gone.size() > 1 ? ", ..." : "");
    }
    Schedule& ck = ctx.checkpoint;
    if (options.checkpoint_interval > 0 && options.checkpoint_interval != ck.interval) {
      ck.interval = options.checkpoint_interval;
      ck.next = (std::floor(ctx.s.time / ck.interval) + 1.0) * ck.interval;
    }
  }
  } catch (const std::exception& e) {
    // A new run's directory says how it ended; a resume that could not start leaves the run
    // directory as the last segment left it (resumable once the cause is fixed).
    if (writer && !options.resume) record_setup_failure(dir, c, summary, comm.size(), e.what());
    throw;
  }
  State& s = ctx.s;
  enable_rebalance(s, options.rebalance);
  const long total_particles = sum_over_ranks(s, long(s.particles.size()));
  const long first_step = s.step;  // 0, or the checkpoint's
  RunResult result;
  result.ranks = comm.size();
  {  // every rank's count in its slot, summed: the split, known to every rank
    std::vector<double> count(std::size_t(comm.size()), 0.0);
    count[std::size_t(comm.rank())] = double(s.particles.size());
    comm.sum(count.data(), int(count.size()));
    for (const double n : count) result.particles_per_rank.push_back(long(n));
  }
  History& history = ctx.history;
  std::unique_ptr<SnapshotWriter>& snapshots = ctx.snapshots;
  std::vector<CrackTracker>& cracks = ctx.cracks;
  RunRecord record;
  record.threads = omp_get_max_threads();
  record.ranks = comm.size();
  record.segments = ctx.segments;
  record.run_id = ctx.run_id;
  record.case_hash = case_hash(options.source);
  if (options.resume) record.checkpoint_time = s.time, record.checkpoint_step = s.step;
  stamp_heartbeat(record);
  if (writer) {
    write_file_atomic(dir + "/run.json", run_json(c, summary, record));
    write_csv_units(dir);  // what every CSV column holds, in which unit
  }

  // Crack speeds are reported against the speeds of the lower body's material.
  std::vector<WaveSpeeds> crack_speeds;  // per interface
  for (const InterfaceSpec& is : c.interfaces)
    crack_speeds.push_back(summary.speeds[std::size_t(c.bodies[is.lower_body].material)]);
  int& interface_files = ctx.interface_files;
  // Distributed: a file rank 0 alone writes that fails is kept here, and the run goes on to
  // the step's agreement (below), where every rank learns it and stops with it; one process
  // stops at once. Nothing rank 0 alone writes is attempted after one failed.
  std::string pending_write;
  auto writer_only = [&](auto&& write) {
    if (!writer) return;
    if (!comm.distributed()) return write();
    if (!pending_write.empty()) return;
    try {
      write();
    } catch (const std::exception& e) {
      pending_write = e.what();
    }
  };
  auto write_interfaces = [&]() {
    if (s.interfaces.empty()) return;
    gather_interface_state(s);  // distributed: every node from its owner
    writer_only([&] {
    fs::create_directories(dir + "/interface");
    for (std::size_t k = 0; k < s.interfaces.size(); ++k) {
      const std::string named =
          fmt::format("{}/interface/{}_{:06d}.csv", dir, c.interface_names[k], interface_files);
      if (k > 0 || c.interface_names[0] == "interface") {
        write_interface_csv(named, s.interfaces[k], s.time);
        continue;
      }
      // The first interface keeps its original name, interface_NNNNNN.csv; the file named after
      // it is a hard link to the same data (a copy where links are not possible).
      const std::string first = fmt::format("{}/interface/interface_{:06d}.csv", dir, interface_files);
      write_interface_csv(first, s.interfaces[0], s.time);
      std::error_code ec;
      fs::remove(named, ec);
      fs::create_hard_link(first, named, ec);
      if (ec) fs::copy_file(first, named, fs::copy_options::overwrite_existing);
    }
    ++interface_files;
    });
  };
  // SPEC E12 (output.mach_interval): the shear Mach front behind each crack running above c_S.
  std::vector<double> shear_speed;  // per material
  for (const WaveSpeeds& w : summary.speeds) shear_speed.push_back(w.shear);
  // Distributed: each rank bins its particles, the bins summed over the ranks (collective).
  const SumOverRanks sum_bins = [&comm](double* v, int n) { comm.sum(v, n); };
  auto read_mach_angles = [&]() {
    gather_particles(s);
    for (std::size_t k = 0; k < cracks.size(); ++k) {
      MachReading m;
      if (read_mach_angle(cracks[k], crack_speeds[k].shear, s.particles, s.grid, shear_speed, s.time, m,
                          comm.distributed() ? &sum_bins : nullptr)) {
        m.interface = int(k);
        ctx.mach.push_back(m);
      }
    }
  };
  auto write_cracks = [&]() {
    // The first interface keeps the original names (crack_tip.csv); every interface also gets
    // files named after it.
    for (std::size_t k = 0; k < cracks.size(); ++k) {
      if (k == 0) cracks[0].write(dir, "", crack_speeds[0].rayleigh, crack_speeds[0].shear);
      cracks[k].write(dir, "_" + c.interface_names[k], crack_speeds[k].rayleigh, crack_speeds[k].shear);
      write_rupture_times(dir, "_" + c.interface_names[k], s.interfaces[k]);
      if (c.output.mach_interval > 0) {
        if (k == 0) write_mach_angles(dir, "", ctx.mach, 0);
        write_mach_angles(dir, "_" + c.interface_names[k], ctx.mach, int(k));
      }
    }
  };

  auto sample_stations_now = [&]() {
    gather_particles(s);
    sample_stations(s, probes, ctx.stations);
  };
  if (!options.resume) {
    if (!c.stations.empty()) sample_stations_now();
    history.samples.push_back(sample(s));
    if (snapshots) snapshots->write(s.particles, s.stiffness, s.time, s.step);
    if (c.output.interface_interval > 0) write_interfaces();
    for (std::size_t k = 0; k < cracks.size(); ++k) cracks[k].sample(s.interfaces[k], s.time);
  }

  double peak_work = 0.0;  // check_energy: the most the loads' work has been (a resume: so far)
  for (const EnergySample& e : history.samples) peak_work = std::max(peak_work, std::fabs(e.external_work));
  const double eps = ctx.eps;
  Schedule &hist = ctx.hist, &snap = ctx.snap, &prof = ctx.prof, &crack = ctx.crack;

  // The record files (history, crack tip, run.json "running" + heartbeat), every kFlushSeconds
  // of wall time and at every snapshot; and checkpoints.
  Progress progress(summary.steps, c.time.end, c.output.progress_interval, options.progress && writer);
  auto fill_record = [&](RunRecord& r) {
    const EnergySample& e = history.samples.back();
    r.steps = s.step;
    r.simulated_time = s.time;
    r.wall_seconds = ctx.wall_before + progress.elapsed();
    r.particle_updates_per_second =
        r.wall_seconds > 0 ? double(total_particles) * double(s.step) / r.wall_seconds : 0.0;
    r.cohesive_seconds = s.cohesive_seconds;
    r.kinetic_energy = e.kinetic;
    r.strain_energy = e.strain;
    r.external_work = e.external_work;
    // After the start-up: 1 us in the laboratory, 5 % of the run when that is longer.
    r.energy_balance_error = history.max_relative_error(std::max(1e-6, 0.05 * c.time.end));
    r.energy_balance_error_final = e.relative_error();
    r.min_cohesive_dt = s.limits.min_cohesive_dt;
    r.cohesive_stored = e.cohesive_stored;
    r.cohesive_dissipated = e.cohesive_dissipated;
    stamp_heartbeat(r);
  };
  auto last_flush = std::chrono::steady_clock::now();
  auto flush = [&]() {
    writer_only([&] {
      if (fault_due(FaultSite::record_write, s.step))  // tests
        throw IoError(fmt::format("error while writing '{}/history.csv': No space left on device "
                                  "(injected: RUPTURE_INJECT_FAULT)", dir));
      history.write(dir + "/history.csv");
      write_cracks();
      write_stations(dir, c.stations, probes, ctx.stations);
      fill_record(record);
      write_file_atomic(dir + "/run.json", run_json(c, summary, record));
      last_flush = std::chrono::steady_clock::now();
    });
  };
  auto checkpoint = [&]() {
    const double wall_before = ctx.wall_before;
    ctx.wall_before += progress.elapsed();  // the checkpoint holds the wall time up to here
    if (comm.distributed())
      write_checkpoint_ranks(dir, options.source, ctx, comm);  // particle parts per rank
    else
      write_checkpoint(dir, options.source, ctx);
    ctx.wall_before = wall_before;
    record.checkpoint_time = s.time;
    record.checkpoint_step = s.step;
  };
  InterruptGuard interrupt_guard;
  std::string io_failure;  // what failed to be written (then the run stops)
  int caught_signal = 0;
  try {
    while (s.time < c.time.end - eps) {
      s.dt_cap = c.time.end - s.time;  // land exactly on the end time
      // Nested per-level time steps: every level ends its step together by the next time an
      // output needs the particles (solver/nested_state.hpp).
      s.sync_by = c.time.end - eps;
      for (const Schedule* due : {&hist, &snap, &ctx.station_schedule, &ctx.mach_schedule, &ctx.checkpoint})
        if (due->interval > 0) s.sync_by = std::min(s.sync_by, due->next - eps);
      if (!c.stations.empty() && ctx.station_schedule.interval <= 0) s.sync_by = -INFINITY;  // every step
      const double t_before = s.time;
      step(s);
      if (!(s.time > t_before))  // the same on every rank: one dt for all
        throw SimulationError(fmt::format(
            "time does not advance: step {} took t = {:.17g} s by dt = {:.6g} s to {:.17g} s (the "
            "step is below the round-off of the time); time.end / dt is too large",
            s.step, t_before, s.dt, s.time));
      if (s.halo && s.halo->rebalances != result.rebalances) {  // the split followed the load
        result.rebalances = s.halo->rebalances;
        if (writer) fmt::print("{}\n", s.halo->last_rebalance);
      }
      const bool last = s.time >= c.time.end - eps;
      // Between the finest steps of a coarser level's step (per-level time steps) some particles
      // are behind the run's time: what reads particles waits for the levels to end together.
      const bool synced = synchronized(s);
      // Crack samples at exact multiples of the interval (E10, E11), however long the step.
      // Distributed: crack and rupture times, faces from their owners (the crack files too).
      if (crack.due(s.time, eps) || last || c.time.stop_at_interface_end) gather_crack_times(s);
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
      if (crack_at_end && !last && synced) {
        // Close the record at this time: final samples of every output.
        for (std::size_t k = 0; k < cracks.size(); ++k)
          if (cracks[k].samples().back().time < s.time) cracks[k].sample(s.interfaces[k], s.time);
        gather_particles(s);  // nested levels: every level's particles, merged
        history.samples.push_back(sample(s));
        check_energy(s, history.samples.back(), peak_work);
        if (prof.interval > 0) write_interfaces();
        if (snapshots) snapshots->write(s.particles, s.stiffness, s.time, s.step);  // gathered above
        if (ctx.mach_schedule.interval > 0) read_mach_angles();
        record.stop_reason = result.stop_reason = "crack_reached_interface_end";
        break;
      }
      Schedule& st = ctx.station_schedule;
      if (!c.stations.empty() && synced && (st.interval <= 0 || st.due(s.time, eps) || last)) {
        sample_stations_now();
        st.advance(s.time, eps);
      }
      if (synced && (hist.due(s.time, eps) || last)) {
        gather_particles(s);  // nested levels: every level's particles, merged
        history.samples.push_back(sample(s));
        check_energy(s, history.samples.back(), peak_work);
        hist.advance(s.time, eps);
      }
      if (prof.due(s.time, eps) || (last && prof.interval > 0)) {
        write_interfaces();
        prof.advance(s.time, eps);
      }
      if (synced && (ctx.mach_schedule.due(s.time, eps) || (last && ctx.mach_schedule.interval > 0))) {
        read_mach_angles();
        ctx.mach_schedule.advance(s.time, eps);
      }
      bool flushed = false;
      if (snapshots && synced && (snap.due(s.time, eps) || last)) {
        gather_particles(s);
        flush();  // the small record files first: they say what happened if the disk fills
        snapshots->write(s.particles, s.stiffness, s.time, s.step);
        flushed = true;
        snap.advance(s.time, eps);
      }
      progress.update(s.step, s.time);
      // Durable runs: record files, checkpoints, interruption (after the step's outputs).
      if (!last && !flushed && seconds_since(last_flush) >= kFlushSeconds) flush();
      // The step's agreement: a signal on any rank and a write that failed on rank 0 reach
      // every rank here (one reduction), and all stop together.
      caught_signal = interrupt_signal();
      if (comm.distributed()) {
        const double code = comm.max(double(caught_signal) + (pending_write.empty() ? 0.0 : kWriteFailed));
        if (code >= kWriteFailed) throw IoError(comm.broadcast(pending_write, 0) + " (rank 0)");
        caught_signal = int(code);
      } else if (!pending_write.empty()) {
        throw IoError(pending_write);
      }
      if (last) break;
      const bool stop = caught_signal != 0 ||
                        (options.stop_after_steps > 0 && s.step >= options.stop_after_steps);
      // A checkpoint holds the particles at one time: a stop waits for the levels' steps to
      // end where they would anyway, so the resumed run is bitwise the uninterrupted one.
      if (!synced) continue;
      if (ctx.checkpoint.due(s.time, eps) || stop) {
        ctx.checkpoint.advance(s.time, eps);
        checkpoint();
      }
      if (stop) {
        record.stop_reason = result.stop_reason = "interrupted";
        break;
      }
    }
    progress.finish(s.step, s.time);
    if (result.stop_reason == "interrupted") {
      result.outcome = Outcome::interrupted;
      record.status = "interrupted";
      record.message = result.message = fmt::format(
          "interrupted{} at step {}, t = {:.6e} s; checkpoint written; resume with: rupture "
          "resume {}",
          caught_signal ? fmt::format(" by signal {}", caught_signal) : std::string(), s.step,
          s.time, dir);
    } else {
      result.ok = true;
      result.outcome = Outcome::completed;
      record.status = "completed";
      if (record.stop_reason.empty()) record.stop_reason = result.stop_reason = "end_time";
    }
  } catch (const SimulationError& e) {
    progress.finish(s.step, s.time);
    result.outcome = Outcome::unstable;
    result.message = e.what();
    record.status = "failed";
    record.message = e.what();
    record.stop_reason = result.stop_reason = "failed";
  } catch (const IoError& e) {
    progress.finish(s.step, s.time);
    io_failure = e.what();
  } catch (const fs::filesystem_error& e) {
    progress.finish(s.step, s.time);
    io_failure = e.what();
  }
  if (io_failure.empty() && !pending_write.empty()) io_failure = pending_write;  // at the last step
  if (writer) {  // after a failed write too: the small files may still fit
    try {
      history.write(dir + "/history.csv");
      write_cracks();
      write_stations(dir, c.stations, probes, ctx.stations);
    } catch (const std::exception& e) {
      if (io_failure.empty()) io_failure = e.what();
    }
  }
  if (!io_failure.empty()) {
    result.ok = false;
    result.outcome = Outcome::io_error;
    result.message = record.message = io_failure;
    record.status = "failed";
    record.stop_reason = result.stop_reason = "io_error";
  }

  fill_record(record);
  const double wall = record.wall_seconds;
  result.status = record.status;
  result.steps = s.step;
  result.simulated_time = s.time;
  result.wall_seconds = wall;
  result.particle_updates_per_second = record.particle_updates_per_second;
  result.energy_balance_error = record.energy_balance_error;
  result.energy_balance_error_final = record.energy_balance_error_final;
  result.cohesive_seconds = s.cohesive_seconds;
  if (s.halo) {
    result.migrations = s.halo->migrations;
    const long steps = std::max(1L, s.step - first_step);  // this process's steps
    const ExchangeCost cost = exchange_cost(s);
    result.exchange_bytes_per_step = comm.sum(cost.bytes_sent) / double(comm.size()) / double(steps);
    result.exchange_seconds = comm.max(cost.seconds);
  }
  {  // every rank's particles now, and what a kept split became
    std::vector<double> count(std::size_t(comm.size()), 0.0);
    count[std::size_t(comm.rank())] = double(held_particles(s));
    comm.sum(count.data(), int(count.size()));
    for (const double n : count) result.particles_per_rank_end.push_back(long(n));
    const std::string drift = kept_split_drift(s, comm, result.particles_per_rank, result.particles_per_rank_end);
    if (writer && !drift.empty()) fmt::print("{}\n", drift);
  }
  {  // every rank's peak resident memory in its slot, summed: known to every rank
    rusage use{};
    getrusage(RUSAGE_SELF, &use);
    std::vector<double> peak(std::size_t(comm.size()), 0.0);
    peak[std::size_t(comm.rank())] = double(use.ru_maxrss) / 1024.0;  // Linux: KiB
    comm.sum(peak.data(), int(peak.size()));
    result.peak_memory_per_rank = peak;
  }
  gather_interface_state(s);  // distributed: every node from its owner
  for (std::size_t k = 0; k < cracks.size(); ++k) {
    CrackSummary cs = cracks[k].summarize(s.interfaces[k], crack_speeds[k]);
    const MachSummary m = summarize_mach(ctx.mach, int(k), cs.steady_begin, cs.steady_end);
    cs.mach_readings = m.readings;
    cs.mach_angle = m.angle;
    cs.mach_angle_spread = m.angle_spread;
    cs.mach_angle_left = m.angle_left;
    cs.mach_angle_right = m.angle_right;
    cs.mach_speed = m.speed;
    result.cracks.push_back(cs);
  }
  record.cracks = result.cracks;
  try {
    if (writer) write_file_atomic(dir + "/run.json", run_json(c, summary, record));
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
  return result;
}

}  // namespace rupture
