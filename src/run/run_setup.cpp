// rupture/run/run_setup.cpp
#include "run/run_setup.hpp"

#include <algorithm>

#include <omp.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <memory>
#include <random>

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/fault_injection.hpp"
#include "output/run_json.hpp"
#include "output/snapshot.hpp"
#include "parallel/agreement.hpp"
#include "parallel/halo.hpp"
#include "run/checkpoint.hpp"
#include "run/checkpoint_ranks.hpp"
#include "run/output_dir.hpp"
#include "run/run_io.hpp"
#include "solver/case_seeding.hpp"
#include "solver/run_state.hpp"
#include "solver/tie_follow.hpp"

namespace rupture {
namespace {

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
  const ParticleShare none = ParticleShare::none();
  r.s = !by_rank ? make_run_state(c) : resume ? make_run_state(c, &none) : make_rank_state(c, comm);
  r.history.viscous = std::any_of(c.materials.begin(), c.materials.end(),
                                  [](const ElasticMaterial& m) { return m.kelvin_voigt > 0.0; });
  const double* region = c.output.has_snapshot_region ? c.output.snapshot_region : nullptr;
  std::vector<StationProbe> probes;
  if (by_rank) {
    SnapshotRows rows;
    std::vector<NearestParticle> nearest = station_visitors(c, r.s);
    if (c.output.snapshot_interval > 0 || !c.stations.empty())
      for_each_run_point(c, r.s, [&](double x, double y, std::uint32_t id) {
        if (in_snapshot_region(region, x, y)) rows.add(id);
        for (NearestParticle& n : nearest) n.visit(x, y, id);
      });
    if (c.output.snapshot_interval > 0) r.snapshots = std::make_unique<SnapshotWriter>(dir, std::move(rows), comm);
    probes = make_probes(c, r.s, &nearest);
  } else {
    // Which particles the snapshots hold and the stations read (every particle at t = 0).
    if (c.output.snapshot_interval > 0) r.snapshots = std::make_unique<SnapshotWriter>(dir, all_particles(r.s), region, comm);
    probes = make_probes(c, r.s);
  }
  const RunState& s = r.s;
  const Grid& g = s.run_grid();
  for (std::size_t k = 0; k < s.num_interfaces(); ++k) {
    const CohesiveInterface& ci = s.interface(k);
    // The cell width along the line at node n (the width in the line's direction).
    auto cell_along = [&](std::size_t n) {
      const int i = std::clamp(g.x.cell_of(ci.x0[n]), 0, g.x.cells - 1);
      const int j = std::clamp(g.y.cell_of(ci.y0[n]), 0, g.y.cells - 1);
      return std::fabs(ci.node_ny[n]) * g.x.width(i) + std::fabs(ci.node_nx[n]) * g.y.width(j);
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
  const bool tips = std::any_of(c.interfaces.begin(), c.interfaces.end(),
                                [](const InterfaceSpec& is) { return is.stress_intensity; });
  r.tip_schedule = Schedule(tips ? c.output.crack_sample_interval : 0.0);
  r.tips.assign(c.interfaces.size(), TipSeries{});
  r.growth.assign(c.interfaces.size(), CrackGrowthRecord{});
  r.regrow = [&c](RunState& state, std::vector<CrackGrowthRecord>& grown) { regrow_cracks(c, state, grown); };
  r.rejoin = [&c](RunState& state, const std::vector<CrackGrowthRecord>& grown) {
    rejoin_cracks(c, state, grown);
    lay_followed_ties(state);  // where the checkpoint's ties were laid (solver/tie_follow.hpp)
  };
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

// Replaces the set-up context by the checkpoint in the output directory, split over the ranks by
// where its particles are now (any number of ranks, whatever wrote it); a new segment.
void resume_from_checkpoint(RunContext& ctx, const RunOptions& options) {
  const std::string& dir = options.output_dir;
  const Comm& comm = options.comm;
  const bool writer = comm.rank() == 0;
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
    if (comm.distributed() && ctx.s.levels[0].particle_parts > 0) keys = read_checkpoint_share(dir, ctx, comm);
    if (!comm.distributed()) read_checkpoint_particles(dir, ctx);  // every part, if any
  });
  // Split by where the particles are now (any number of ranks, whatever wrote it).
  if (comm.distributed() && !keys.empty()) {
    split_over_ranks(ctx.s, comm, {false, &keys});  // sends each particle to its rank
  } else if (comm.distributed()) {
    split_over_ranks(ctx.s, comm, {false, nullptr});  // one process's checkpoint: its particles split
  }
  ++ctx.segments;
  if (ctx.rejoin) {
    // The faces and ties the grown cracks' junctions move (derived from the particles): a tie
    // laid again is laid over the whole grid, and each rank keeps its part of it.
    std::vector<InterfaceShapes> before;
    if (comm.distributed())
      for (const State& level : ctx.s.levels) before.push_back(interface_shapes(level));
    agree_on_failure(comm, [&] { ctx.rejoin(ctx.s, ctx.growth); });
    for (std::size_t l = 0; l < before.size(); ++l) follow_grown_interfaces(ctx.s.levels[l], before[l]);
  }
  // The trackers place arc lengths on the grown lines (regrown by the restore), their samples
  // as the checkpoint holds them.
  for (std::size_t k = 0; k < ctx.cracks.size() && k < ctx.growth.size(); ++k)
    if (ctx.growth[k].grown()) ctx.cracks[k].follow(ctx.s.interface(k), false);
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

}  // namespace

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

std::vector<StationProbe> start_run(RunContext& ctx, const Case& c, const CaseSummary& summary,
                                    const RunOptions& options) {
  const Comm& comm = options.comm;
  try {
    std::vector<StationProbe> probes =
        set_up(ctx, c, options.output_dir, options.checkpoint_interval, comm, options.resume);
    if (!options.resume) ctx.run_id = make_run_id(comm);  // a resume takes the checkpoint's
    // Set-up and resume: what one rank cannot do (a checkpoint entry refused, a part file
    // missing, memory) stops every rank with its message (parallel/agreement.hpp), before any
    // collective call that the failed rank would never make.
    agree_on_failure(comm, [&] {
      if (fault_due(FaultSite::setup, 0)) throw IoError("injected set-up failure (RUPTURE_INJECT_FAULT)");
    });
    if (options.resume) resume_from_checkpoint(ctx, options);
    return probes;
  } catch (const std::exception& e) {
    // A new run's directory says how it ended; a resume that could not start leaves the run
    // directory as the last segment left it (resumable once the cause is fixed).
    if (comm.rank() == 0 && !options.resume)
      record_setup_failure(options.output_dir, c, summary, comm.size(), e.what());
    throw;
  }
}

}  // namespace rupture
