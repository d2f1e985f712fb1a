// rupture/run/checkpoint.cpp
// One short list per struct (`fields`) says what a checkpoint holds; the same list writes and
// reads, so the two cannot drift apart. A member added to State, Particles, CohesiveInterface,
// CrackTracker, SnapshotWriter or RunContext that evolves during a run needs one line here.
#include "run/checkpoint.hpp"

#include <fmt/format.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <type_traits>

#include "core/errors.hpp"
#include "core/atomic_file.hpp"
#include "run/checkpoint_access.hpp"
#include "run/checkpoint_archive.hpp"
#include "run/checkpoint_checks.hpp"
#include "solver/run_state.hpp"

namespace rupture {

// The field lists live beside the archive (found by argument-dependent lookup).
namespace checkpoint_detail {


// ---- What a checkpoint holds: one line per member ----

template <class A>
void fields(A& a, Particles& p);
template <class A>
void fields(A& a, ScatterPlan& p);
template <class A>
void fields(A& a, NodeBC& b);
template <class A>
void fields(A& a, StepLimits& l);
template <class A>
void fields(A& a, CohesiveInterface& c);
template <class A>
void fields(A& a, State& s);
template <class A>
void fields(A& a, EnergySample& e);
template <class A>
void fields(A& a, CrackSample& c);
template <class A>
void fields(A& a, CrackTracker& t) {
  CheckpointAccess::fields(a, t);
}
template <class A>
void fields(A& a, SnapshotWriter& w) {
  CheckpointAccess::fields(a, w);
}
template <class A>
void fields(A& a, MachLine& m);
template <class A>
void fields(A& a, MachReading& r);
template <class A>
void fields(A& a, StationSeries& r);
template <class A>
void fields(A& a, TipSeries& r);
template <class A>
void fields(A& a, CrackGrowthRecord& r);
template <class A>
void fields(A& a, Schedule& s);
template <class A>
void fields(A& a, RunContext& c);
template <class A>
void fields(A& a, CaseSource& c);

// Every array of ParticleArrays (particles/particles.hpp), in its order, with viscous_on
// before the first viscous one.
template <class A>
void fields(A& a, Particles& p) {
  bool flag = false;
  for_each_particle_array([&](const auto& e) {
    if (e.kind == ParticleArrayKind::viscous && !flag) a("viscous_on", p.viscous_on), flag = true;
    a(e.name, p.*e.member);
  });
}

// The particle order and the strips it was sorted into fix the summation order: both stored.
// order, bucket, scratch are scratch of the sort; rows_known, row_lo, row_hi, row_height only
// size the strip tiles (false after a restart until the next sort: the tiles then find their
// rows from the particles), so they change no result.
template <class A>
void fields(A& a, ScatterPlan& p) {
  a("strip_cells", p.strip_cells);
  a("sort_interval", p.sort_interval);
  a("num_strips", p.num_strips);
  a("sorted_step", p.sorted_step);
  a("valid", p.valid);
  a("strip_begin", p.strip_begin);
  a("drift", p.drift);  // decides the next re-sort (build_scatter_plan)
  // The rows of the set-up state's sort are not the restored particles': the strip tiles find
  // theirs from the particles until the next sort (solver/strip_tile.cpp).
  if constexpr (A::reading) p.rows_known = false;
}

template <class A>
void fields(A& a, NodeBC& b) {
  a("field", b.field);
  a("node", b.node);
  a("component", b.component);
  a("condition", b.condition);
}

template <class A>
void fields(A& a, StepLimits& l) {
  a("cfl_dt", l.cfl_dt);
  a("bulk_eigen_bound", l.bulk_eigen_bound);
  a("cohesive_dt", l.cohesive_dt);
  a("min_cohesive_dt", l.min_cohesive_dt);
  a("dt", l.dt);
}

// `spec` comes from the case (gp_law, node_law, node_faces_up and node_faces_lo with it: a line
// whose face changes field does not grow), light_face_mass from the case at
// set-up; face_up/face_lo, jump_before, seg_ka/seg_kb are per-step scratch, recomputed before
// they are read.
template <class A>
void fields(A& a, CohesiveInterface& c) {
  // Every array of state InterfaceArrays marks kStored (cohesive/interface.hpp), in its order.
  for_each_interface_array([&](const auto& e) {
    if (e.has(kStored)) a(e.name, c.*e.member);
  });
  a("time", c.time);
  a("work", c.work);
  a("tie_x0", c.tie_x0);  // where its ties are laid (solver/tie_follow.hpp)
  a("tie_y0", c.tie_y0);
  a("tie_ux", c.tie_ux);
  a("tie_uy", c.tie_uy);
}

// Derived and not stored: junctions (rebuilt from bonded at the first tie).
// Rebuilt from the case by make_state() and not stored: grid, stiffness, boundary, absorbing, bonded,
// cohesive_safety, loads (LoadState: particle ids from the t = 0 particles; indices, region
// nodes and forces are rebuilt after the restored sort and in every step; the loads' work is
// in external_work). Set by the driver before every step: dt_cap; tests only: forced_dt.
// Not stored, per-step scratch: fields (every grid array is recomputed in each step).
// Nested per-level time steps (RunState::period, mixed: from the case; hold, substep: 0 at
// every checkpoint, which waits for the levels to end their steps together; sync_by: set by
// the driver before every step).
// A run (solver/run_state.hpp), format 15. On one grid: its level's State as above, entries
// at the run's level. On nested levels: the run's entries (the grid level's lattice size, the
// particle count, the interfaces in input order, the clock, sums and limits; the one-grid
// entries bc_nodes, bc_lines and plan are stored empty, as formats 11 to 15 have them), then
// "nested": every level's State as above (its particle count changes as particles move
// between levels, and its window_drift decides the next move; its interfaces are the run's
// entry), the levels' clock and the migration count. Every level's particles are merged anew
// for the writers (all_particles).

// Lists whose items are another struct's members (read in place: the Reader keeps the items
// there, and the counts are checked before).
struct LevelEntry {
  State* s = nullptr;
};
struct InterfaceEntry {
  CohesiveInterface* c = nullptr;
};
struct NestedEntry {
  RunState* r = nullptr;
};

// A list item past the case's count (the list's own count is checked against it only after).
[[noreturn]] inline void refuse_extra_item(const char* what) {
  throw InputError(fmt::format("checkpoint: its list of {} holds more items than this case has", what));
}

// One State's entries; `level`: one of nested levels.
template <class A>
void state_fields(A& a, State& s, bool level) {
  a.same("grid.nodes_x", s.grid.nodes_x());
  a.same("grid.nodes_y", s.grid.nodes_y());
  a.same("fields", s.fields.num_fields);
  // A distributed run's particles are in part files (run/checkpoint_ranks.hpp).
  a("particle_parts", s.particle_parts);
  if (!level && s.particle_parts == 0) {
    if (s.particles_from_checkpoint) {  // a distributed resume of one process's checkpoint
      std::size_t count = s.particles.size();
      a("particles.count", count);  // read: the file's (its ids are checked after decoding)
    } else {
      a.same("particles.count", s.particles.size());
    }
  }
  // A nested level's interfaces are stored with the run (fields of RunState).
  a.same("interfaces.count", level ? std::size_t(0) : s.interfaces.size());
  if (s.particle_parts == 0) a("particles", s.particles);
  a("bc_nodes", s.bc_nodes);
  a("bc_lines", s.bc_lines);
  a("plan", s.plan);
  if (level) {
    std::vector<CohesiveInterface> none;
    a("interfaces", none);
  } else {
    a("interfaces", s.interfaces);
  }
  a("scheme", s.scheme);
  a("flip", s.flip);
  a("limits", s.limits);
  a("dt", s.dt);
  a("time", s.time);
  a("step", s.step);
  a("mass_floor", s.mass_floor);
  a("cohesive_seconds", s.cohesive_seconds);
  a("external_work", s.external_work);
  a("strain_work", s.strain_work);
  a("viscous_work", s.viscous_work);
  a("initial_energy", s.initial_energy);
  a("tie_drift", s.tie_drift);  // when the ties are measured again (solver/tie_follow.hpp)
  a("travel", s.travel);
  if (level) a("window_drift", s.window_drift);
  a.same("nested", false);
}

template <class A>
void fields(A& a, State& s) {
  state_fields(a, s, false);
}

template <class A>
void fields(A& a, LevelEntry& l) {
  if (!l.s) refuse_extra_item("nested levels");
  state_fields(a, *l.s, true);
}

template <class A>
void fields(A& a, InterfaceEntry& i) {
  if (!i.c) refuse_extra_item("interfaces");
  fields(a, *i.c);
}

template <class A>
void fields(A& a, NestedEntry& e) {
  RunState& r = *e.r;
  std::vector<LevelEntry> levels;
  for (State& l : r.levels) levels.push_back({&l});
  a.same("levels.count", r.levels.size());
  a("levels", levels);
  a("time", r.time);
  a("dt", r.dt);
  a("step", r.step);
  a("migrations", r.migrations);
}

template <class A>
void fields(A& a, RunState& r) {
  if (!r.is_nested()) {  // one grid: its level's entries
    State& s = r.levels[0];
    s.initial_energy = r.initial_energy;  // the run's (distributed: the ranks' sum)
    state_fields(a, s, false);
    if constexpr (A::reading) {
      r.initial_energy = s.initial_energy;
      collect_run_sums(r);
    }
    return;
  }
  const State& g = r.levels[r.grid_level];
  a.same("grid.nodes_x", g.grid.nodes_x());
  a.same("grid.nodes_y", g.grid.nodes_y());
  a.same("fields", 0);  // the run has no fields of its own
  int parts = r.levels[0].particle_parts;
  a("particle_parts", parts);  // every level's (theirs are read below)
  if (parts == 0) {
    if (r.particles_from_checkpoint) {
      std::size_t count = held_particles(r);
      a("particles.count", count);  // read: the file's (its ids are checked after decoding)
    } else {
      a.same("particles.count", held_particles(r));
    }
  }
  a.same("interfaces.count", r.num_interfaces());
  std::vector<NodeBC> no_bc_nodes;  // one grid's entries: empty here
  std::vector<int> no_bc_lines;
  ScatterPlan no_plan;
  a("bc_nodes", no_bc_nodes);
  a("bc_lines", no_bc_lines);
  a("plan", no_plan);
  std::vector<InterfaceEntry> interfaces;
  for (std::size_t k = 0; k < r.num_interfaces(); ++k) interfaces.push_back({&r.interface(k)});
  a("interfaces", interfaces);
  Scheme scheme = r.scheme();
  double flip = r.levels[0].flip, mass_floor = r.levels[0].mass_floor;
  a("scheme", scheme);
  a("flip", flip);
  a("limits", r.limits);
  a("dt", r.dt);
  a("time", r.time);
  a("step", r.step);
  a("mass_floor", mass_floor);
  a("cohesive_seconds", r.cohesive_seconds);
  a("external_work", r.external_work);
  a("strain_work", r.strain_work);
  a("viscous_work", r.viscous_work);
  a("initial_energy", r.initial_energy);
  a.same("nested", true);
  NestedEntry nested{&r};
  a("nested", nested);
  // Read: the run's scheme, flip and mass floor are the levels' copies (each level's own are
  // what steps and are checked), and every level's particles are where the run's are.
  if constexpr (A::reading) {
    for (std::size_t l = 0; l < r.levels.size(); ++l)
      if (r.levels[l].particle_parts != parts)
        throw InputError(fmt::format("checkpoint: run.state.nested.levels[{}].particle_parts = {}: must be the "
                                     "run's, {}",
                                     l, r.levels[l].particle_parts, parts));
    r.merged_step = -1;  // the writers' merged particles anew
  }
}

template <class A>
void fields(A& a, EnergySample& e) {
  a("time", e.time);
  a("kinetic", e.kinetic);
  a("strain", e.strain);
  a("external_work", e.external_work);
  a("initial", e.initial);
  a("cohesive_stored", e.cohesive_stored);
  a("cohesive_dissipated", e.cohesive_dissipated);
  a("viscous_dissipated", e.viscous_dissipated);
}

template <class A>
void fields(A& a, CrackSample& c) {
  a("time", c.time);
  a("tip", c.tip);
  a("back", c.back);
  a("cohesive_zone", c.cohesive_zone);
  a("traction_zone", c.traction_zone);
  a("stretch_begin", c.stretch_begin);
  a("stretch_end", c.stretch_end);
}

template <class A>
void fields(A& a, Schedule& s) {
  a("interval", s.interval);
  a("next", s.next);
  a("count", s.count);
}

template <class A>
void fields(A& a, MachLine& m) {
  a("found", m.found);
  a("angle", m.angle);
  a("angle_error", m.angle_error);
  a("origin", m.origin);
  a("jump", m.jump);
  a("rows", m.rows);
  a("material", m.material);
}

template <class A>
void fields(A& a, StationSeries& r) {
  a("rows", r.rows);
}

template <class A>
void fields(A& a, TipSeries& r) {
  a("rows", r.rows);
}

// A growing crack's record as stored: its rows flat (solver/crack_growth.hpp growth_rows_flat).
struct StoredGrowth {
  std::vector<double> rows;
  double nucleation_time = -1.0;
};

template <class A>
void fields(A& a, StoredGrowth& r) {
  a("rows", r.rows);
  a("nucleation_time", r.nucleation_time);
}

template <class A>
void fields(A& a, MachReading& r) {
  a("interface", r.interface);
  a("time", r.time);
  a("tip_x", r.tip_x);
  a("tip_y", r.tip_y);
  a("dir_x", r.dir_x);
  a("dir_y", r.dir_y);
  a("speed", r.speed);
  a("left", r.left);
  a("right", r.right);
  a("c_s_left", r.c_s_left);
  a("c_s_right", r.c_s_right);
}

template <class A>
void fields(A& a, RunContext& c) {
  // The grown cracks first: a restore lays their segments on the case's interfaces (their
  // geometry, ties and tied nodes) before it reads the state that holds their nodes.
  a.same("growth.count", c.growth.size());
  std::vector<StoredGrowth> growth(c.growth.size());
  if constexpr (!A::reading)
    for (std::size_t k = 0; k < growth.size(); ++k)
      growth[k] = {growth_rows_flat(c.growth[k].rows), c.growth[k].nucleation_time};
  a("growth", growth);
  if constexpr (A::reading) {
    // The grown segments a restore lays again: whole rows, each at an end of its line.
    for (std::size_t k = 0; k < growth.size() && k < c.growth.size(); ++k) {
      c.growth[k].rows =
          growth_rows_from_flat(growth[k].rows, fmt::format("checkpoint '{}': run.growth[{}]", a.origin(), k));
      c.growth[k].nucleation_time = growth[k].nucleation_time;
    }
    if (c.regrow) c.regrow(c.s, c.growth);
  }
  a("state", c.s);
  a("history", c.history.samples);
  a.same("cracks.count", c.cracks.size());
  a("cracks", c.cracks);
  a("mach", c.mach);
  a.same("snapshots", c.snapshots != nullptr);
  if (c.snapshots) a("snapshot_writer", *c.snapshots);
  a("eps", c.eps);
  a("schedule.history", c.hist);
  a("schedule.snapshot", c.snap);
  a("schedule.interface", c.prof);
  a("schedule.crack", c.crack);
  a("schedule.checkpoint", c.checkpoint);
  a("schedule.mach", c.mach_schedule);
  a("stations", c.stations);
  a("schedule.stations", c.station_schedule);
  a("tips", c.tips);
  a("schedule.tips", c.tip_schedule);
  a("interface_files", c.interface_files);
  a("wall_before", c.wall_before);
  a("growth_seconds", c.growth_seconds);
  a("segments", c.segments);
  a("run_id", c.run_id);
}

template <class A>
void fields(A& a, CaseSource& c) {
  a("text", c.text);
  a("origin", c.origin);
  a("overrides", c.overrides);
}

// One rank's particles at a checkpoint of a distributed run.
struct ParticlePart {
  long step = 0;
  int rank = 0, ranks = 1;
  Particles particles;
};

template <class A>
void fields(A& a, ParticlePart& p) {
  a("step", p.step);
  a("rank", p.rank);
  a("ranks", p.ranks);
  a("particles", p.particles);
}

// A checkpoint is a regular file (a symbolic link to one is followed) read whole: its size
// bounds the read (a FIFO or a device would be read without end), and no checkpoint larger
// than this machine's memory can be restored.
std::string read_all(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);  // a FIFO: no wait
  if (fd < 0) {
    if (errno == ENOENT)
      throw InputError(
          fmt::format("no checkpoint at '{}' (a run writes one with "
                      "--checkpoint-interval, or when interrupted by SIGINT/SIGTERM)",
                      path));
    throw_io_error("cannot read", path);
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw_io_error("cannot stat", path);
  if (!S_ISREG(st.st_mode))
    throw InputError(fmt::format("checkpoint '{}' is not a regular file (a {}): rupture writes "
                                 "checkpoints as regular files",
                                 path, S_ISDIR(st.st_mode)    ? "directory"
                                       : S_ISFIFO(st.st_mode) ? "FIFO"
                                       : S_ISCHR(st.st_mode)  ? "character device"
                                       : S_ISBLK(st.st_mode)  ? "block device"
                                       : S_ISSOCK(st.st_mode) ? "socket"
                                                              : "special file"));
  const std::uint64_t size = std::uint64_t(st.st_size);
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  const std::uint64_t memory = pages > 0 && page > 0 ? std::uint64_t(pages) * std::uint64_t(page) : UINT64_MAX;
  if (size > memory)
    throw InputError(fmt::format("checkpoint '{}' is {} bytes, more than this machine's memory ({} bytes): "
                                 "a checkpoint is read whole, so this one cannot be restored here",
                                 path, size, memory));
  std::string bytes(std::size_t(size), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {  // at most the size fstat gave: a file that grows is not followed
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw_io_error("error while reading", path);
    if (n == 0)
      throw IoError(fmt::format("checkpoint '{}' shrank while it was read ({} of {} bytes)", path, got, size));
    got += std::size_t(n);
  }
  return bytes;
}

}  // namespace checkpoint_detail

using namespace checkpoint_detail;

std::string checkpoint_path(const std::string& dir) {
  return dir + "/checkpoint/checkpoint.bin";
}

std::string checkpoint_bytes(const CaseSource& source, const RunContext& ctx) {
  // Per-level time steps hold scatters between the finest steps of a level's step; they are
  // not stored: a checkpoint is written only where every level has ended its step.
  if (!synchronized(ctx.s))
    throw std::logic_error("checkpoint: nested levels between the finest steps of a level's step");
  Writer w;
  w("case", source);
  w("run", ctx);
  return w.finish();
}

void restore_checkpoint_bytes(const std::string& bytes, const std::string& origin,
                              RunContext& ctx) {
  const CheckpointBaseline fresh = checkpoint_baseline(ctx);  // before the checkpoint replaces it
  Reader r(bytes, origin);
  CaseSource source;
  r("case", source);
  r("run", ctx);
  if (!r.at_end()) throw InputError(fmt::format("checkpoint '{}' has data past its end", origin));
  check_restored(ctx, fresh, origin);  // run/checkpoint_checks.hpp
}

void restore_run_checkpoint_bytes(const std::string& bytes, const std::string& origin, RunContext& ctx) {
  restore_checkpoint_bytes(bytes, origin, ctx);
  check_run_records(ctx, origin);
}

CaseSource checkpoint_source_from_bytes(const std::string& bytes, const std::string& origin) {
  Reader r(bytes, origin);
  CaseSource source;
  r("case", source);
  return source;
}

void write_checkpoint(const std::string& dir, const CaseSource& source, const RunContext& ctx) {
  std::error_code ec;
  std::filesystem::create_directories(dir + "/checkpoint", ec);
  if (ec) throw IoError(fmt::format("cannot create '{}/checkpoint': {}", dir, ec.message()));
  write_file_atomic(checkpoint_path(dir), checkpoint_bytes(source, ctx));
}

CaseSource read_checkpoint_source(const std::string& path) {
  return checkpoint_source_from_bytes(read_all(path), path);
}

void read_checkpoint(const std::string& path, RunContext& ctx) {
  restore_run_checkpoint_bytes(read_all(path), path, ctx);
}

}  // namespace rupture

namespace rupture {

using namespace checkpoint_detail;

std::string checkpoint_part_path(const std::string& dir, long step, int rank) {
  return fmt::format("{}/checkpoint/particles_{}_{}.bin", dir, step, rank);
}

void write_checkpoint_part(const std::string& dir, long step, int rank, int ranks,
                           const Particles& particles) {
  std::error_code ec;
  std::filesystem::create_directories(dir + "/checkpoint", ec);
  if (ec) throw IoError(fmt::format("cannot create '{}/checkpoint': {}", dir, ec.message()));
  ParticlePart part{step, rank, ranks, particles};
  Writer w;
  w("part", part);
  write_file_atomic(checkpoint_part_path(dir, step, rank), w.finish());
}

void read_checkpoint_parts(const std::string& dir, long step, int ranks, Particles& out) {
  read_checkpoint_parts(dir, step, 0, ranks, ranks, out);
}

void read_checkpoint_part_bytes(const std::string& bytes, const std::string& origin, long step, int rank,
                                int ranks, Particles& out) {
  Reader in(bytes, origin);
  ParticlePart part;
  in("part", part);
  if (!in.at_end()) throw InputError(fmt::format("checkpoint part '{}' has data past its end", origin));
  if (part.step != step || part.rank != rank || part.ranks != ranks)
    throw InputError(fmt::format("checkpoint part '{}' is of step {}, rank {} of {}; expected "
                                 "step {}, rank {} of {}",
                                 origin, part.step, part.rank, part.ranks, step, rank, ranks));
  check_particle_arrays(part.particles, "part.particles", origin);
  out.append_copy(part.particles);
}

void read_checkpoint_parts(const std::string& dir, long step, int first, int count, int ranks, Particles& out) {
  for (int r = first; r < first + count; ++r) {
    const std::string path = checkpoint_part_path(dir, step, r);
    read_checkpoint_part_bytes(read_all(path), path, step, r, ranks, out);
  }
}

}  // namespace rupture
