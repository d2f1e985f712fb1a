// rupture/run/checkpoint_checks.cpp
#include "run/checkpoint_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <cfloat>
#include <cmath>

#include "core/errors.hpp"
#include "run/checkpoint_access.hpp"
#include "solver/run_state.hpp"

namespace rupture {
namespace {

// Counters that are incremented (steps, schedule firings) stay where a double counts exactly
// and an increment cannot overflow.
constexpr long kMaxCount = 1L << 53;
// A distributed run's part files: one per rank.
constexpr int kMaxParts = 1 << 20;
// Schedules: a firing costs one loop turn in Schedule::advance; an interval below this
// fraction of the time step, or a count this far behind the time, would spin for ever.
constexpr double kMinIntervalPerStep = 1e-6;
constexpr double kMaxBehind = 1e7;
// The instability watch's streak counter (solver/cohesive_step.cpp) is incremented per step.
constexpr std::int32_t kMaxStreak = 1 << 30;

[[noreturn]] void refuse(const std::string& origin, const std::string& entry, const std::string& value,
                         const std::string& allowed) {
  throw InputError(fmt::format("checkpoint '{}': {} = {}: {}", origin, entry, value, allowed));
}
std::string item(const std::string& entry, std::size_t k) { return fmt::format("{}[{}]", entry, k); }
std::string num(double v) { return fmt::format("{}", v); }

struct Checker {
  const std::string& origin;

  void length(const std::string& entry, std::size_t n, std::size_t expected, const char* what) const {
    if (n != expected)
      refuse(origin, entry + ".length", std::to_string(n), fmt::format("must be {} ({})", expected, what));
  }
  void at_least(const std::string& entry, double v, double lo) const {
    if (!(v >= lo) || !std::isfinite(v)) refuse(origin, entry, num(v), fmt::format("must be finite and at least {}", lo));
  }
  void positive(const std::string& entry, double v, bool inf_allowed = false) const {
    if (!(v > 0.0) || (!inf_allowed && !(v <= DBL_MAX)))
      refuse(origin, entry, num(v), inf_allowed ? "must be positive" : "must be positive and finite");
  }
  void within(const std::string& entry, double v, double lo, double hi) const {
    if (!(v >= lo && v <= hi)) refuse(origin, entry, num(v), fmt::format("must lie in [{}, {}]", lo, hi));
  }
  void count(const std::string& entry, long v, long lo, long hi, const std::string& what) const {
    if (v < lo || v > hi) refuse(origin, entry, std::to_string(v), fmt::format("must lie in [{}, {}] ({})", lo, hi, what));
  }
};

double widest_cell(const Axis& a) {
  double w = 0.0;
  for (int c = 0; c < a.cells; ++c) w = std::max(w, a.width(c));
  return w;
}

// The extent of the lattice's diagonal: no particle moves further than that and stays inside.
double lattice_extent(const Grid& g) {
  return std::hypot(g.x.node(g.x.cells) - g.x.node(0), g.y.node(g.y.cells) - g.y.node(0));
}

// The cell column of x inside the lattice, as the time step computes it (solver/gather.cpp).
long cell_column(const Axis& a, double x) {
  return a.graded() ? a.cell_of(x) : long(std::floor((x - a.origin) * (1.0 / a.h)));
}

void check_plan(const Checker& ck, const State& s, const std::string& entry, bool holds_particles) {
  const ScatterPlan& p = s.plan;
  const int width = ScatterPlan{}.strip_cells;
  if (p.strip_cells != width)
    refuse(ck.origin, entry + ".strip_cells", std::to_string(p.strip_cells),
           fmt::format("must be {} (the strip width fixes the summation order)", width));
  if (p.sort_interval < 1)
    refuse(ck.origin, entry + ".sort_interval", std::to_string(p.sort_interval), "must be at least 1 (steps between re-sorts)");
  ck.count(entry + ".sorted_step", p.sorted_step, -1, s.step, "-1 (never sorted) up to the step");
  ck.within(entry + ".drift", p.drift, 0.0, lattice_extent(s.grid));
  if (!p.valid || !holds_particles) return;  // re-sorted before the next scatter
  // The strips (solver/state.hpp): every particle of strip k in cell columns k w - 1 .. k w + w,
  // the columns its strip tile holds (solver/strip_tile.cpp).
  const int cx = s.grid.x.cells;
  const long strips = (cx + width - 1) / width;
  ck.count(entry + ".num_strips", p.num_strips, strips, strips, fmt::format("{} cell columns in strips of {}", cx, width));
  const std::size_t n = s.particles.size();
  ck.length(entry + ".strip_begin", p.strip_begin.size(), std::size_t(strips) + 1, "one per strip and one");
  for (std::size_t k = 0; k <= std::size_t(strips); ++k) {  // 0, non-decreasing, ending at n
    const std::size_t b = p.strip_begin[k];
    const std::size_t lo = k == 0 ? 0 : k == std::size_t(strips) ? n : p.strip_begin[k - 1];
    const std::size_t hi = k == 0 ? 0 : n;
    if (b < lo || b > hi)
      refuse(ck.origin, item(entry + ".strip_begin", k), std::to_string(b),
             fmt::format("must lie in [{}, {}] (0 first, non-decreasing, the {} particles last)", lo, hi, n));
  }
  for (long k = 0; k < strips; ++k)
    for (std::size_t q = p.strip_begin[std::size_t(k)]; q < p.strip_begin[std::size_t(k) + 1]; ++q) {
      const long col = cell_column(s.grid.x, s.particles.x[q]);
      if (col < k * width - 1 || col > k * width + width)
        refuse(ck.origin, item(entry.substr(0, entry.size() - 5) + ".particles.x", q), num(s.particles.x[q]),
               fmt::format("the particle is in cell column {}, outside the drift tolerance of its strip {} "
                           "(columns {} to {}) with {}.valid set",
                           col, k, k * width - 1, k * width + width, entry));
    }
}

void check_boundary(const Checker& ck, const State& s, const std::string& entry) {
  const int fields = s.fields.num_fields;
  const std::size_t nodes = s.grid.num_nodes();
  for (std::size_t k = 0; k < s.bc_nodes.size(); ++k) {
    const NodeBC& b = s.bc_nodes[k];
    const std::string e = item(entry + ".bc_nodes", k);
    ck.count(e + ".field", b.field, 0, fields - 1, "a velocity field of the case");
    if (b.node >= nodes) refuse(ck.origin, e + ".node", std::to_string(b.node), fmt::format("must be below the grid's {} nodes", nodes));
    ck.count(e + ".component", b.component, 0, 1, "0: v_x, 1: v_y");
    ck.count(e + ".condition", b.condition, 0, long(s.boundary.size()) - 1, "a velocity condition of the case");
  }
  ck.length(entry + ".bc_lines", s.bc_lines.size(), s.boundary.size(), "one per velocity condition of the case");
  for (std::size_t c = 0; c < s.bc_lines.size(); ++c) {
    const Edge e = s.boundary[c].edge;
    const int lines = e == Edge::left || e == Edge::right ? s.grid.nodes_x() : s.grid.nodes_y();
    ck.count(item(entry + ".bc_lines", c), s.bc_lines[c], 0, lines - 1, "a grid line of the condition's edge");
  }
}

// Interfaces (input order, as stored) and the lattice each lies on.
struct InterfaceOnGrid {
  const CohesiveInterface* c;
  const Grid* g;
  const Grid* whole;  // the lattice over the whole domain (nested: the coarsest), where ties run
};

void check_interfaces(const Checker& ck, const std::vector<InterfaceOnGrid>& all, const std::string& entry) {
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Grid& g = *all[i].g;
    const double xlo = g.x.node(0), xhi = g.x.node(g.x.cells), ylo = g.y.node(0), yhi = g.y.node(g.y.cells);
    const CohesiveInterface& c = *all[i].c;
    const std::string e = item(entry + ".interfaces", i);
    const std::size_t n = c.y0.size(), segs = c.seg_length.size(), gauss = segs * CohesiveInterface::kGauss;
    const auto nodes = [&](const char* name, std::size_t size) { ck.length(e + "." + name, size, n, "the case's nodes of the interface"); };
    const auto points = [&](const char* name, std::size_t size) {
      ck.length(e + "." + name, size, gauss, "the case's Gauss points of the interface");
    };
    nodes("x0", c.x0.size()), nodes("ux_up", c.ux_up.size()), nodes("uy_up", c.uy_up.size());
    nodes("ux_lo", c.ux_lo.size()), nodes("uy_lo", c.uy_lo.size()), nodes("fx_node", c.fx_node.size());
    nodes("fy_node", c.fy_node.size()), nodes("node_crack_time", c.node_crack_time.size());
    nodes("node_rupture_time", c.node_rupture_time.size()), nodes("node_peak_slip_rate", c.node_peak_slip_rate.size());
    nodes("node_slip_path", c.node_slip_path.size()), nodes("node_slip_rate", c.node_slip_rate.size());
    nodes("stiffness_node", c.stiffness_node.size());
    nodes("last_increment_n", c.last_increment_n.size()), nodes("last_increment_t", c.last_increment_t.size());
    nodes("streak_base", c.streak_base.size()), nodes("reversal_streak", c.reversal_streak.size());
    points("gp_dn", c.gp_dn.size()), points("gp_dt", c.gp_dt.size()), points("gp_tn", c.gp_tn.size());
    points("gp_tt", c.gp_tt.size()), points("gp_separated", c.gp_separated.size());
    points("gp_damage", c.gp_damage.size()), points("gp_slip", c.gp_slip.size());
    points("gp_state", c.gp_state.size()), points("gp_rate", c.gp_rate.size());
    points("gp_normal", c.gp_normal.size());
    for (const auto& [name, v] : {std::pair{"seg_fa_x", &c.seg_fa_x}, {"seg_fa_y", &c.seg_fa_y},
                                  {"seg_fb_x", &c.seg_fb_x}, {"seg_fb_y", &c.seg_fb_y}})
      if (v->size() != segs && !v->empty())
        refuse(ck.origin, e + "." + name + ".length", std::to_string(v->size()),
               fmt::format("must be 0 or {} (the case's segments of the interface)", segs));
    // Both faces inside the lattice (solver/cohesive_step.cpp: face_inside).
    for (std::size_t k = 0; k < n; ++k) {
      const double face[4] = {c.x0[k] + c.ux_up[k], c.y0[k] + c.uy_up[k], c.x0[k] + c.ux_lo[k], c.y0[k] + c.uy_lo[k]};
      const char* names[4] = {"ux_up", "uy_up", "ux_lo", "uy_lo"};
      for (int d = 0; d < 4; ++d) {
        const double lo = d % 2 ? ylo : xlo, hi = d % 2 ? yhi : xhi;
        if (!(face[d] >= lo && face[d] <= hi))
          refuse(ck.origin, item(e + "." + names[d], k), num(face[d] - (d % 2 ? c.y0[k] : c.x0[k])),
                 fmt::format("the face would lie at {} m, outside the lattice [{}, {}] m", num(face[d]), num(lo), num(hi)));
      }
    }
    // Where its ties are laid (solver/tie_follow.hpp): points and displacements, one each, inside
    // the lattice; a restore lays them only where they are its tied lines' samples.
    const std::size_t ties = c.tie_x0.size();
    for (const auto& [name, v] : {std::pair{"tie_y0", &c.tie_y0}, {"tie_ux", &c.tie_ux}, {"tie_uy", &c.tie_uy}})
      ck.length(e + "." + name, v->size(), ties, "one per point of tie_x0");
    const Grid& w = *all[i].whole;
    const double wxlo = w.x.node(0), wxhi = w.x.node(w.x.cells), wylo = w.y.node(0), wyhi = w.y.node(w.y.cells);
    for (std::size_t k = 0; k < ties; ++k) {
      ck.within(item(e + ".tie_x0", k), c.tie_x0[k], wxlo, wxhi);
      ck.within(item(e + ".tie_y0", k), c.tie_y0[k], wylo, wyhi);
      ck.within(item(e + ".tie_ux", k), c.tie_ux[k], wxlo - c.tie_x0[k], wxhi - c.tie_x0[k]);
      ck.within(item(e + ".tie_uy", k), c.tie_uy[k], wylo - c.tie_y0[k], wyhi - c.tie_y0[k]);
    }
    for (std::size_t k = 0; k < gauss; ++k)
      if (c.gp_separated[k] > 1) refuse(ck.origin, item(e + ".gp_separated", k), std::to_string(int(c.gp_separated[k])), "must be 0 or 1");
    for (std::size_t k = 0; k < n; ++k)
      ck.count(item(e + ".reversal_streak", k), c.reversal_streak[k], 0, kMaxStreak, "steps in a row");
  }
}

// The limits and clock a State or the run holds.
void check_clock(const Checker& ck, const StepLimits& limits, double dt, double time, long step, double cohesive_seconds,
                 const std::string& entry) {
  ck.count(entry + ".step", step, 0, kMaxCount, "time steps");
  ck.positive(entry + ".limits.cfl_dt", limits.cfl_dt);
  ck.at_least(entry + ".limits.bulk_eigen_bound", limits.bulk_eigen_bound, 0.0);
  ck.positive(entry + ".limits.cohesive_dt", limits.cohesive_dt, true);
  ck.positive(entry + ".limits.min_cohesive_dt", limits.min_cohesive_dt, true);
  ck.positive(entry + ".limits.dt", limits.dt);
  ck.at_least(entry + ".dt", dt, 0.0);
  ck.at_least(entry + ".time", time, 0.0);
  ck.at_least(entry + ".cohesive_seconds", cohesive_seconds, 0.0);
}

// One State: a run's one grid (`level` false: its interfaces are stored with it), or one of
// nested levels (the run's interfaces are checked with the run).
void check_state(const Checker& ck, const State& s, const std::string& entry, bool level) {
  ck.count(entry + ".particle_parts", s.particle_parts, 0, kMaxParts, "0: particles in this file, N: in N part files");
  check_clock(ck, s.limits, s.dt, s.time, s.step, s.cohesive_seconds, entry);  // the plan's bound first
  const bool holds_particles = s.particle_parts == 0;
  if (holds_particles) check_particles(s.particles, s, entry + ".particles", ck.origin);
  check_boundary(ck, s, entry);
  check_plan(ck, s, entry + ".plan", holds_particles);
  if (!level) {
    std::vector<InterfaceOnGrid> all;
    for (const CohesiveInterface& c : s.interfaces) all.push_back({&c, &s.grid, &s.grid});
    check_interfaces(ck, all, entry);
  }
  ck.within(entry + ".flip", s.flip, 0.0, 1.0);
  ck.at_least(entry + ".mass_floor", s.mass_floor, 0.0);
  ck.within(entry + ".tie_drift", s.tie_drift, 0.0, DBL_MAX);
  ck.within(entry + ".travel", s.travel, 0.0, DBL_MAX);
  if (level) ck.within(entry + ".window_drift", s.window_drift, 0.0, lattice_extent(s.grid));
}

void check_run_state(const Checker& ck, const RunState& r, const std::string& entry) {
  if (!r.is_nested()) return check_state(ck, r.levels[0], entry, false);
  check_clock(ck, r.limits, r.dt, r.time, r.step, r.cohesive_seconds, entry);
  std::vector<InterfaceOnGrid> all;  // each on the lattice of its level
  for (std::size_t k = 0; k < r.num_interfaces(); ++k)
    all.push_back({&r.interface(k), &r.levels[std::size_t(r.interface_levels[k])].grid, &r.levels[0].grid});
  check_interfaces(ck, all, entry);
  for (std::size_t l = 0; l < r.levels.size(); ++l) check_state(ck, r.levels[l], item(entry + ".nested.levels", l), true);
  ck.count(entry + ".nested.migrations", r.migrations, 0, kMaxCount, "particles moved");
}

void check_schedule(const Checker& ck, const Schedule& sc, const std::string& entry, const RunState& s) {
  ck.at_least(entry + ".interval", sc.interval, 0.0);
  ck.within(entry + ".next", sc.next, -DBL_MAX, DBL_MAX);
  ck.count(entry + ".count", sc.count, 0, kMaxCount, "firings");
  if (sc.interval == 0.0) return;  // never fires
  if (sc.interval < kMinIntervalPerStep * s.limits.dt)
    refuse(ck.origin, entry + ".interval", num(sc.interval),
           fmt::format("must be 0 (never) or at least {} x the time step, {} s", kMinIntervalPerStep, num(s.limits.dt)));
  const double behind = std::max(s.time, sc.next) / sc.interval - double(sc.count);
  if (behind > kMaxBehind)
    refuse(ck.origin, entry + ".count", std::to_string(sc.count),
           fmt::format("is {:.3g} intervals behind the time {} s (at most {:.0g} allowed)", behind, num(std::max(s.time, sc.next)), kMaxBehind));
}

void check_snapshots(const Checker& ck, const SnapshotWriter& w, const CheckpointBaseline& fresh) {
  const std::string e = "run.snapshot_writer";
  const SnapshotRows& r = CheckpointAccess::rows(w);
  if (!fresh.has_rows || r.first_id != fresh.rows.first_id || r.first_row != fresh.rows.first_row || r.rows != fresh.rows.rows)
    refuse(ck.origin, e + ".rows", fmt::format("{} rows in {} runs", r.rows, r.first_id.size()),
           fmt::format("must be the case's, {} rows in {} runs (the particles at t = 0)", fresh.rows.rows, fresh.rows.first_id.size()));
  if (CheckpointAccess::selected(w) != std::size_t(r.rows))
    refuse(ck.origin, e + ".selected", std::to_string(CheckpointAccess::selected(w)), fmt::format("must be the rows, {}", r.rows));
  const std::vector<std::string>& files = CheckpointAccess::files(w);
  ck.length(e + ".times", CheckpointAccess::times(w).size(), files.size(), "one per file");
  ck.length(e + ".counts", CheckpointAccess::counts(w).size(), files.size(), "one per file");
  for (std::size_t k = 0; k < files.size(); ++k) {
    const std::string want = fmt::format("snapshots/particles_{:06d}.h5", k);
    if (files[k] != want) refuse(ck.origin, item(e + ".files", k), fmt::format("'{}'", files[k]), fmt::format("must be '{}'", want));
  }
}

}  // namespace

CheckpointBaseline checkpoint_baseline(const RunContext& fresh) {
  CheckpointBaseline b;
  for (const State& l : fresh.s.levels) b.ids.insert(b.ids.end(), l.particles.id.begin(), l.particles.id.end());
  std::sort(b.ids.begin(), b.ids.end());
  if (fresh.snapshots) b.has_rows = true, b.rows = CheckpointAccess::rows(*fresh.snapshots);
  return b;
}

void check_particle_arrays(const Particles& p, const std::string& entry, const std::string& origin) {
  const Checker ck{origin};
  const std::size_t n = p.x.size();
  // The Kelvin-Voigt stress: one per particle in a damped run, none otherwise.
  const std::size_t viscous = p.viscous_on ? n : 0;
  for_each_particle_array([&](const auto& a) {
    const std::size_t size = (p.*a.member).size();
    if (a.kind == ParticleArrayKind::every)
      ck.length(entry + "." + a.name, size, n, "the length of x, one per particle");
    else
      ck.length(entry + "." + a.name, size, viscous,
                p.viscous_on ? "the length of x (viscous_on: a damped material)" : "0 (viscous_on is false)");
  });
}

void check_particles(const Particles& p, const State& s, const std::string& entry, const std::string& origin) {
  check_particle_arrays(p, entry, origin);
  const Checker ck{origin};
  const Axis &ax = s.grid.x, &ay = s.grid.y;
  // The bounds of solver/gather.cpp (grid_limits): the whole 3-node stencil inside the lattice.
  const double lim[2][2] = {{ax.node(0) + 0.5 * ax.width(0), ax.node(ax.cells - 1)},
                            {ay.node(0) + 0.5 * ay.width(0), ay.node(ay.cells - 1)}};
  const double widest[2] = {widest_cell(ax), widest_cell(ay)};
  const std::vector<double>* pos[2] = {&p.x, &p.y};
  const std::vector<double>* half[2] = {&p.half_x, &p.half_y};
  const char* pos_name[2] = {".x", ".y"};
  const char* half_name[2] = {".half_x", ".half_y"};
  for (std::size_t q = 0; q < p.size(); ++q) {
    if (p.field[q] >= s.fields.num_fields)
      refuse(origin, item(entry + ".field", q), std::to_string(int(p.field[q])),
             fmt::format("must be below the case's {} velocity fields", s.fields.num_fields));
    if (p.material[q] >= s.stiffness.size())
      refuse(origin, item(entry + ".material", q), std::to_string(int(p.material[q])),
             fmt::format("must be below the case's {} materials", s.stiffness.size()));
    for (int d = 0; d < 2; ++d) {
      const double v = (*pos[d])[q];
      if (!(v > lim[d][0] && v < lim[d][1]))
        refuse(origin, item(entry + pos_name[d], q), num(v),
               fmt::format("must lie inside the lattice, ({}, {}) m", num(lim[d][0]), num(lim[d][1])));
      const double l = (*half[d])[q];
      if (!(l > 0.0 && l <= widest[d]))
        refuse(origin, item(entry + half_name[d], q), num(l),
               fmt::format("must lie in (0, {}] m (the widest cell)", num(widest[d])));
    }
    ck.positive(item(entry + ".mass", q), p.mass[q]);
    ck.positive(item(entry + ".volume0", q), p.volume0[q]);
    // The reference position enters only u = x - X (fracture/): any finite point is a state.
    for (const auto& [name, v] : {std::pair{".x0", p.x0[q]}, {".y0", p.y0[q]}})
      if (!std::isfinite(v)) refuse(origin, item(entry + name, q), num(v), "must be finite (the particle's position at t = 0, m)");
  }
}

void check_particle_ids(std::vector<std::uint32_t> ids, const std::vector<std::uint32_t>& expected,
                        const std::string& entry, const std::string& origin) {
  if (ids.size() != expected.size())
    refuse(origin, entry + ".length", std::to_string(ids.size()), fmt::format("must be the case's {} particles", expected.size()));
  std::sort(ids.begin(), ids.end());
  const auto bad = std::mismatch(ids.begin(), ids.end(), expected.begin());
  if (bad.first != ids.end())
    refuse(origin, entry, fmt::format("{} (sorted, at {})", *bad.first, bad.first - ids.begin()),
           fmt::format("must be the case's particle ids, each once ({} there)", *bad.second));
}

void check_ids_below(const Particles& p, std::uint64_t count, const std::string& entry, const std::string& origin) {
  for (std::size_t q = 0; q < p.size(); ++q)
    if (p.id[q] >= count)
      refuse(origin, item(entry, q), std::to_string(p.id[q]), fmt::format("must be below the run's {} particles", count));
}

void check_restored(const RunContext& ctx, const CheckpointBaseline& fresh, const std::string& origin) {
  const Checker ck{origin};
  const RunState& s = ctx.s;
  check_run_state(ck, s, "run.state");
  if (s.levels[0].particle_parts == 0) {  // the particles are in this file: exactly the case's
    std::vector<std::uint32_t> ids;
    for (const State& l : s.levels) ids.insert(ids.end(), l.particles.id.begin(), l.particles.id.end());
    // A distributed resume of one process's checkpoint made no particle to compare with: the
    // ids must be 0 .. n - 1, each once, as one process numbers the case's particles.
    std::vector<std::uint32_t> expected = fresh.ids;
    if (s.particles_from_checkpoint) {
      expected.resize(ids.size());
      std::iota(expected.begin(), expected.end(), 0u);
    }
    check_particle_ids(std::move(ids), expected,
                       s.is_nested() ? "run.state.nested.levels[*].particles.id" : "run.state.particles.id", origin);
  }
  for (std::size_t k = 0; k < ctx.cracks.size(); ++k) {
    const CrackTracker& t = ctx.cracks[k];
    const std::string e = item("run.cracks", k);
    for (std::size_t j = 0; j < t.samples().size(); ++j) {
      const CrackSample& c = t.samples()[j];
      ck.length(item(e + ".samples", j) + ".stretch_end", c.stretch_end.size(), c.stretch_begin.size(),
                "one per stretch_begin");
    }
    ck.at_least(e + ".end_tolerance", CheckpointAccess::end_tolerance(t), 0.0);
  }
  for (std::size_t k = 0; k < ctx.mach.size(); ++k) {
    const MachReading& m = ctx.mach[k];
    const std::string e = item("run.mach", k);
    ck.count(e + ".interface", m.interface, 0, long(s.num_interfaces()) - 1, "an interface of the case");
    for (const auto& [side, line] : {std::pair{".left", &m.left}, {".right", &m.right}}) {
      ck.count(e + side + ".rows", line->rows, 0, 1L << 30, "bin rows");
      ck.count(e + side + ".material", line->material, -1, 255, "-1 (none) or a material id");
    }
  }
  if (ctx.snapshots) check_snapshots(ck, *ctx.snapshots, fresh);
  const std::pair<const char*, const Schedule*> schedules[] = {
      {"run.schedule.history", &ctx.hist},         {"run.schedule.snapshot", &ctx.snap},
      {"run.schedule.interface", &ctx.prof},       {"run.schedule.crack", &ctx.crack},
      {"run.schedule.checkpoint", &ctx.checkpoint}, {"run.schedule.mach", &ctx.mach_schedule},
      {"run.schedule.stations", &ctx.station_schedule}, {"run.schedule.tips", &ctx.tip_schedule}};
  for (const auto& [name, sc] : schedules) check_schedule(ck, *sc, name, s);
  for (std::size_t k = 0; k < ctx.tips.size(); ++k)
    if (ctx.tips[k].rows.size() % kTipColumns != 0)
      ck.length(fmt::format("run.tips[{}].rows", k), ctx.tips[k].rows.size(),
                ctx.tips[k].rows.size() / kTipColumns * kTipColumns,
                fmt::format("a multiple of {} (the columns of a row)", kTipColumns).c_str());
  ck.at_least("run.eps", ctx.eps, 0.0);
  ck.count("run.interface_files", ctx.interface_files, 0, 1L << 30, "files written");
  ck.at_least("run.wall_before", ctx.wall_before, 0.0);
  ck.at_least("run.growth_seconds", ctx.growth_seconds, 0.0);
  ck.count("run.segments", ctx.segments, 1, 1L << 30, "1 + resumptions");
}

void check_run_records(const RunContext& ctx, const std::string& origin) {
  if (ctx.history.samples.empty())
    refuse(origin, "run.history.length", "0", "must be at least 1 (a run records the energies at t = 0)");
  for (std::size_t k = 0; k < ctx.cracks.size(); ++k)
    if (ctx.cracks[k].samples().empty())
      refuse(origin, item("run.cracks", k) + ".samples.length", "0",
             "must be at least 1 (a run samples every crack at t = 0)");
}

}  // namespace rupture
