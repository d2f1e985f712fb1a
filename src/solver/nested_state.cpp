// rupture/solver/nested_state.cpp
#include "solver/nested_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include "core/errors.hpp"
#include "particles/seed.hpp"
#include "solver/absorbing_setup.hpp"
#include "solver/case_seeding.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/field_windows.hpp"
#include "solver/grid_update.hpp"
#include "solver/load_step.hpp"
#include "solver/time_step.hpp"
#include "solver/nested_phases.hpp"
#include "solver/rank_exchange.hpp"
#include "solver/transfer.hpp"

namespace rupture {
using namespace detail;
namespace {

// The lattice line of level L that the domain edge of `bc` lies on at t = 0; -1 when L does not
// reach that edge. InputError when the edge is not on one of L's lines. (bc/velocity_bc.hpp
// edge_line is the single grid's: the line nearest the edge at time t, clamped to the grid.)
long level_edge_line(const VelocityBC& bc, const Case& c, const LevelLattice& L) {
  const int d = (bc.edge == Edge::left || bc.edge == Edge::right) ? 0 : 1;
  const bool lo = bc.edge == Edge::left || bc.edge == Edge::bottom;
  if (!(lo ? L.outer_lo[d] : L.outer_hi[d])) return -1;
  const Axis& a = d == 0 ? L.x : L.y;
  const double edge = lo ? c.grid.min[d] : c.grid.max[d];
  const double u = (edge - a.origin) / a.h;
  const long line = std::lround(u);
  if (std::fabs(u - double(line)) > 1e-6)
    throw InputError(fmt::format(
        "boundary.{}: the {} edge ({} = {:g} m) is not on a node line of nested level {} "
        "({:g} m cells, lines at {:g} m + k {:g} m); with nested levels a driven edge must lie "
        "on the lines of every level that reaches it: make the domain's extent a whole number "
        "of coarse cells", bc.name, edge_name(bc.edge), d == 0 ? "x" : "y", edge, L.level, a.h,
        a.origin, a.h));
  return line;
}

// The velocity conditions of the domain edges this level reaches (its outer sides), on the
// level's lattice line of the edge.
void set_level_boundary(State& s, const Case& c, const LevelLattice& L, std::vector<int>& base) {
  for (const VelocityBC& bc : c.boundary) {
    const long line = level_edge_line(bc, c, L);
    if (line < 0) continue;
    s.boundary.push_back(bc);
    base.push_back(int(line));
  }
  s.bc_lines = base;
  s.bc_nodes = resolve_nodes(s.boundary, s.grid, s.fields.num_fields, s.bc_lines);
}

// The level that holds interface `ci` whole: every face node's bilinear stencil (its cell's
// four nodes) made of that level's DOFs, so the cohesive forces land on DOFs and the faces
// read DOF velocities. Throws InputError otherwise.
int owning_level(const NestedGrid& g, const std::vector<double>& x0, const std::vector<double>& y0,
                 const std::string& name) {
  const int l = g.level_of(x0[0], y0[0]);
  const LevelLattice& L = g.levels[std::size_t(l)];
  for (std::size_t k = 0; k < x0.size(); ++k) {
    const double u = (x0[k] - g.min[0]) / g.finest, v = (y0[k] - g.min[1]) / g.finest;
    const double cu = std::floor(u / double(L.unit)) * double(L.unit), cv = std::floor(v / double(L.unit)) * double(L.unit);
    bool dofs = g.level_of(x0[k], y0[k]) == l;
    for (double du : {0.0, double(L.unit)})
      for (double dv : {0.0, double(L.unit)}) {
        const bool finer = std::size_t(l) + 1 < g.levels.size() &&
                           g.levels[std::size_t(l) + 1].owns_units(cu + du, cv + dv);
        dofs = dofs && L.owns_units(cu + du, cv + dv) && !finer;
      }
    if (!dofs)
      throw InputError(fmt::format(
          "interface.{}: its node at (x, y) = ({:g}, {:g}) m is not inside nested level {} with a "
          "cell to spare, where its first node is: on nested levels an interface must lie in one "
          "level's region (one [grid.refine] box and the level it sets), at least one cell from "
          "the region's inner borders", name, x0[k], y0[k], l));
  }
  return l;
}

// Every particle onto the finest level that owns its centre; a particle more than one level
// finer than where it was made breaks the GIMP contract (lp > h/2 of its new lattice).
void migrate(RunState& n) {
  const std::size_t levels = n.levels.size();
  if (levels == 1) return;
  std::vector<Particles> arriving(levels);
  std::vector<unsigned char> mark;
  std::vector<int> dest;
  for (std::size_t l = 0; l < levels; ++l) {
    Particles& P = n.levels[l].particles;
    mark.assign(P.size(), 0);
    bool any = false;
    const long count = long(P.size());
    unsigned char* const away = mark.data();
#pragma omp parallel for schedule(static) reduction(|| : any)
    for (long p = 0; p < count; ++p) {
      const std::size_t i = std::size_t(p);
      away[i] = n.grid.level_of(P.x[i], P.y[i]) != int(l);
      any = any || away[i];
    }
    if (!any) continue;
    Particles leaving;
    n.migrations += long(P.move_marked(mark, leaving));
    n.levels[l].plan.valid = false;
    dest.resize(leaving.size());
    for (std::size_t p = 0; p < leaving.size(); ++p) dest[p] = n.grid.level_of(leaving.x[p], leaving.y[p]);
    for (std::size_t d = 0; d < levels; ++d) {
      mark.assign(leaving.size(), 0);
      bool some = false;
      for (std::size_t p = 0; p < leaving.size(); ++p) some |= (mark[p] = dest[p] == int(d)) != 0;
      if (some) leaving.move_marked(mark, arriving[d]);
    }
  }
  for (std::size_t d = 0; d < levels; ++d) {
    if (arriving[d].size() == 0) continue;
    State& s = n.levels[d];
    const double h = s.grid.x.h;
    for (std::size_t p = 0; p < arriving[d].size(); ++p) {
      const double lp = std::max(arriving[d].half_x[p], arriving[d].half_y[p]);
      if (lp > 0.5 * h * (1 + 1e-9))
        throw SimulationError(fmt::format(
            "GIMP contract broken at step {}, t = {:.6g} s: particle {} (field {}) at (x, y) = "
            "({:.6g}, {:.6g}) m with half-width {:.4g} m entered nested level {} ({:.4g} m "
            "cells): 2 l_p exceeds the cell, so its 3-node stencil (docs/theory.md E3) loses a node. It "
            "was made on a level at least two coarser; widen the boxes between (the nesting "
            "band) so that moving material stays within one level of where it started",
            n.step, n.time, arriving[d].id[p], int(arriving[d].field[p]), arriving[d].x[p],
            arriving[d].y[p], lp, d, h));
    }
    arriving[d].move_marked(std::vector<unsigned char>(arriving[d].size(), 1), s.particles);
    s.plan.valid = false;
  }
}

// migrate, distributed: a broken contract on one rank stops every rank at the end of the step.
void migrate_levels(RunState& n) {
  if (!n.levels[0].halo) return migrate(n);
  try {
    migrate(n);
  } catch (const SimulationError& e) {
    if (n.levels[0].halo->failure.empty()) n.levels[0].halo->failure = e.what();
  }
}

}  // namespace

namespace detail {

Levels levels_of(RunState& n) {
  std::vector<State*>& p = n.level_pointers;
  const bool moved = p.size() != n.levels.size() || (!p.empty() && p[0] != n.levels.data());
  if (moved) {
    p.clear();
    for (State& s : n.levels) p.push_back(&s);
  }
  return Levels{p.data(), p.size(), &n};
}

}  // namespace detail

namespace {

// RunState::coupled of every level with period > 1 (after `mixed` and the transposed terms).
void coupled_nodes(RunState& n) {
  const std::size_t levels = n.levels.size();
  n.coupled.assign(levels, {});
  n.coupled_mask.assign(levels, {});
  // Mixed nodes but the inactive slaves (covered nodes no particle of their level reaches: they
  // stay empty, and condense and distribute skip them), the DOFs with terms, the active slaves.
  std::vector<std::vector<unsigned char>> seed(levels);
  for (std::size_t l = 0; l < levels; ++l) seed[l] = n.mixed[l];
  for (std::size_t k = 0; k < n.slave_level.size(); ++k) seed[n.slave_level[k]][n.slave_node[k]] = 0;
  for (const std::uint32_t k : n.active_slaves) seed[n.slave_level[k]][n.slave_node[k]] = n.mixed[n.slave_level[k]][n.slave_node[k]];
  std::vector<std::vector<unsigned char>> exact(levels);  // DOFs with terms, active slaves
  for (std::size_t l = 0; l < levels; ++l) exact[l].assign(seed[l].size(), 0);
  for (std::size_t d = 0; d < n.dof_level.size(); ++d) exact[n.dof_level[d]][n.dof_node[d]] = 1;
  for (const std::uint32_t k : n.active_slaves) exact[n.slave_level[k]][n.slave_node[k]] = 1;
  for (std::size_t l = 0; l < levels; ++l) {
    if (n.period[l] == 1) continue;
    const State& s = n.levels[l];
    const long nx = s.grid.nodes_x(), ny = s.grid.nodes_y();
    std::vector<unsigned char> near(seed[l].size(), 0);
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i) {
        if (!seed[l][std::size_t(j * nx + i)]) continue;
        for (long b = std::max(0L, j - 2); b <= std::min(ny - 1, j + 2); ++b)
          for (long a = std::max(0L, i - 2); a <= std::min(nx - 1, i + 2); ++a) near[std::size_t(b * nx + a)] = 1;
      }
    for (std::size_t node = 0; node < near.size(); ++node) near[node] = near[node] || exact[l][node];
    for (const BondedTie& t : s.bonded)
      for (const std::size_t node : t.nodes) near[node] = 1;
    // Elements in the whole-lattice layout (field f's node at f x nodes: GridFields::resize),
    // whatever the fields hold now (a distributed rank's are cut to its reach later).
    const std::size_t nodes = s.grid.num_nodes();
    n.coupled_mask[l].assign(std::size_t(s.fields.num_fields) * nodes, 0);
    for (int f = 0; f < s.fields.num_fields; ++f)
      for (std::size_t node = 0; node < near.size(); ++node)
        if (near[node]) {
          const std::size_t e = std::size_t(f) * nodes + node;
          n.coupled[l].push_back(std::uint32_t(e));
          n.coupled_mask[l][e] = 1;
        }
  }
}

}  // namespace

void for_each_level_point(const Case& c, const RunState& n, int l,
                          const std::function<void(double, double, double)>& visit) {
  const Grid& lattice = n.levels[std::size_t(l)].grid;
  for (const BodySpec& b : c.bodies) {  // as make_level_state seeds them
    const double density = c.materials[std::size_t(b.material)].density;
    for_each_seed_point(lattice, b.region, c.grid.particles_per_cell, [&](const SeedPoint& p) {
      if (n.grid.level_of(p.x, p.y) == l) visit(p.x, p.y, density * p.lx * p.ly);
    });
  }
}

namespace {

// [loads] on the levels (solver/load_step.hpp): every level lists each load's particles by the
// run's ids, found among every level's particles near the loads at t = 0 (as one process makes
// them, whatever share of them this process holds), so a level acts on the loaded particles it
// holds (LoadState::kAbsent for the others, as for another rank's) and a particle changing
// level keeps its load. A traction patch is found among particles of every size, each with its
// own extent along the segment.
void set_up_level_loads(const Case& c, RunState& n, const std::vector<std::uint32_t>& first_ids) {
  if (c.loads.empty()) return;
  Particles near;
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    const NestedGrid& g = n.grid;
    const PointFilter keep = [&g, l](double x, double y) { return g.level_of(x, y) == int(l); };
    near.append_copy(particles_near_loads(c, n.levels[l].grid, &keep, first_ids[l]));
  }
  for (State& s : n.levels) {
    s.loads = LoadState{};
    set_up_loads(s, c.loads, c.grid.cell_size, &near);
  }
}

}  // namespace

namespace {

// The absorbing edges' dashpots on the levels (bc/absorbing.hpp), so that together they damp
// as one lattice would: each level reaching an absorbing edge gets its lattice nodes there,
// each with rho c times its share of the edge within the bodies and within the level's own
// region; then a slave's coefficients go to its DOFs times its terms, as its mass does
// (condense), so the DOFs' coefficients add up to rho c times the edge's length and each is
// applied with the condensed mass at its node. A slave on the edge has its DOFs on the edge
// (a hanging node: the coarse nodes either side along it; a covered node: the finer node at
// its point).
void set_level_absorbing(const Case& c, RunState& n) {
  if (c.absorbing_edges.empty()) return;
  const std::size_t levels = n.levels.size();
  for (std::size_t l = 0; l < levels; ++l) {
    const LevelLattice& L = n.grid.levels[l];
    std::vector<Edge> reached;
    for (const Edge e : c.absorbing_edges) {
      const int d = (e == Edge::left || e == Edge::right) ? 0 : 1;
      const bool low = e == Edge::left || e == Edge::bottom;
      if (low ? L.outer_lo[d] : L.outer_hi[d]) reached.push_back(e);
    }
    const NestedGrid& g = n.grid;
    const PointFilter owns = [&g, l](double x, double y) { return g.level_of(x, y) == int(l); };
    n.levels[l].absorbing = absorbing_nodes(c, n.levels[l].grid, reached, &owns);
  }
  std::vector<std::vector<long>> slave_at(levels);
  for (std::size_t l = 0; l < levels; ++l) slave_at[l].assign(n.grid.levels[l].num_nodes(), -1);
  for (std::size_t k = 0; k < n.slave_level.size(); ++k) slave_at[n.slave_level[k]][n.slave_node[k]] = long(k);
  struct Moved {
    std::size_t level;
    AbsorbingNode node;
  };
  std::vector<Moved> moved;
  for (std::size_t l = 0; l < levels; ++l) {
    std::vector<AbsorbingNode> kept;
    for (const AbsorbingNode& a : n.levels[l].absorbing) {
      const long k = slave_at[l][a.node];
      if (k < 0) {
        kept.push_back(a);
        continue;
      }
      for (std::uint32_t t = n.grid.term_start[std::size_t(k)]; t < n.grid.term_start[std::size_t(k) + 1]; ++t) {
        const double w = n.grid.terms[t].c;
        moved.push_back({n.term_level[t], {a.field, n.term_node[t], a.nx, a.ny, w * a.c_normal, w * a.c_tangent}});
      }
    }
    n.levels[l].absorbing = std::move(kept);
  }
  for (const Moved& m : moved) {
    std::vector<AbsorbingNode>& list = n.levels[m.level].absorbing;
    const auto same = std::find_if(list.begin(), list.end(), [&](const AbsorbingNode& a) {
      return a.field == m.node.field && a.node == m.node.node && a.nx == m.node.nx && a.ny == m.node.ny;
    });
    if (same == list.end()) {
      list.push_back(m.node);
    } else {
      same->c_normal += m.node.c_normal;
      same->c_tangent += m.node.c_tangent;
    }
  }
}

}  // namespace

void check_nested_support(const Case& c) {
  const auto unsupported = [](const char* what) {
    return InputError(fmt::format("input key 'grid.refinement' = \"nested\": {} is not yet supported on "
                                  "nested levels (solver/nested_state.hpp); use grid.refinement = "
                                  "\"graded\"", what));
  };
  // Growth reads and grows the tips only where every level ends its step together, so per-level
  // steps would cap a tip's speed at half a cell per coarse step (the growing disc: 12 mm grown
  // against 13.5 mm with one step for all), and the levels' coupled nodes (RunState::coupled)
  // would need the moved ties (docs/fracture.md, "Growth on nested levels"): not supported.
  for (std::size_t k = 0; k < c.interfaces.size(); ++k)
    if (c.interfaces[k].growth.on() && c.time.subcycling == Subcycling::levels)
      throw InputError(fmt::format(
          "input key 'time.subcycling' = \"levels\": with a growing crack (interface.{}.growth) is not "
          "yet supported on nested levels; use time.subcycling = \"none\" (the default there)",
          c.interface_names[k]));
  // Per-level time steps are verified for MUSL only (docs/performance.md: the long free
  // vibration); USL's dissipation would hide the growth that test looks for.
  if (c.time.subcycling == Subcycling::levels && c.solver.scheme != Scheme::MUSL)
    throw unsupported("time.subcycling = \"levels\" with solver.scheme other than \"MUSL\"");
  // The dashpots act at every level's step end (remapped_grid_velocity keeps their velocity);
  // a level's step spanning several finest steps is not written for them.
  if (!c.absorbing_edges.empty() && c.time.subcycling == Subcycling::levels)
    throw unsupported("time.subcycling = \"levels\" with [absorbing]");
  // Loads are applied at every level's step; a level's step spanning several finest steps
  // would need their impulse held over its span (not written).
  if (!c.loads.empty() && c.time.subcycling == Subcycling::levels)
    throw unsupported("time.subcycling = \"levels\" with [loads]");
  if (!c.grid.refined()) throw unsupported("a grid without [grid.refine] boxes");
  if (c.boundary.empty() && c.interfaces.empty()) return;
  // What the levels' set-up checks, on the levels' lattices alone (no particle, no field).
  const NestedGrid g = make_nested_grid(c.grid.min, c.grid.max, c.grid.coarse_cell_size, c.grid.cell_size,
                                        refine_boxes(c.grid), std::max(0.0, c.grid.margin));
  for (const LevelLattice& L : g.levels)
    for (const VelocityBC& bc : c.boundary) level_edge_line(bc, c, L);
  int level = -1;
  for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
    const LineNodes nodes = discretize(c.interfaces[k].geometry(), c.interfaces[k].segments);
    const int l = owning_level(g, nodes.x, nodes.y, c.interface_names[k]);
    // Per-level steps step the interfaces' level and the finer ones every finest step, the
    // coarser ones at their periods: interfaces on two levels would need a coarser level's
    // cohesive forces held over its period (not written).
    if (level >= 0 && l != level && c.time.subcycling == Subcycling::levels)
      throw InputError(fmt::format(
          "input key 'time.subcycling' = \"levels\": with interfaces on more than one nested level "
          "(levels {} and {}) is not yet supported; use time.subcycling = \"none\" or one "
          "[grid.refine] box around all of them", std::min(level, l), std::max(level, l)));
    level = l;
  }
}

RunState make_nested_state(const Case& c, const ParticleShare* share) {
  check_nested_support(c);
  RunState n;
  n.grid = make_nested_grid(c.grid.min, c.grid.max, c.grid.coarse_cell_size, c.grid.cell_size,
                            refine_boxes(c.grid), std::max(0.0, c.grid.margin));
  const int levels = int(n.grid.levels.size());
  std::uint32_t next_id = 0;
  std::vector<std::uint32_t> first_ids;  // per level: its first particle's id (as one process)
  double min_mass = INFINITY;
  n.base_lines.resize(std::size_t(levels));
  for (int l = 0; l < levels; ++l) {
    const LevelLattice& L = n.grid.levels[std::size_t(l)];
    const NestedGrid& g = n.grid;
    const std::function<bool(double, double)> own = [share, l](double x, double y) { return share->own_level(l, x, y); };
    n.levels.push_back(make_level_state(c, level_grid(n.grid, l),
                                        [&g, l](double x, double y) { return g.level_of(x, y) == l; },
                                        share ? &own : nullptr));
    State& s = n.levels.back();
    // The case's step limits are the finest cell's (solver/summary.cpp); a level's scale with
    // its cells: the CFL step with h, the bulk eigenvalue bound with 1 / h^2.
    const double scale = L.x.h / c.grid.cell_size;
    s.limits.cfl_dt *= scale;
    s.limits.bulk_eigen_bound /= scale * scale;
    s.whole_grid_fields = true;
    // One process: every level's fields over its whole lattice. A rank's share: the fields stay
    // as make_level_state fitted them until the split makes them windows over the rank's reach
    // (parallel/halo_nested.hpp), so no rank allocates a whole lattice.
    if (!share) fit_field_windows(s);
    set_level_boundary(s, c, L, n.base_lines[std::size_t(l)]);
    // Ids unique over the levels: level l's follow level l - 1's (a rank's share: as one
    // process numbers them).
    const std::uint32_t first = share && std::size_t(l) < share->first_id.size() ? share->first_id[std::size_t(l)] : next_id;
    first_ids.push_back(first);
    for (std::uint32_t& id : s.particles.id) id += first;
    next_id += std::uint32_t(s.particles.size());
    for (double m : s.particles.mass) min_mass = std::min(min_mass, m);
    // Every level ties the bonded stretches on its own lattice (make_state_on); an interface
    // lives on the one level that holds it whole.
    std::vector<CohesiveInterface> kept;
    n.interface_levels.resize(s.interfaces.size());
    n.interface_slots.resize(s.interfaces.size());
    for (std::size_t k = 0; k < s.interfaces.size(); ++k)
      if (owning_level(n.grid, s.interfaces[k].x0, s.interfaces[k].y0, c.interface_names[k]) == l) {
        n.interface_slots[k] = kept.size();
        kept.push_back(std::move(s.interfaces[k]));
        n.interface_levels[k] = l;
      }
    s.interfaces = std::move(kept);
    s.limits.cohesive_dt = s.interfaces.empty() ? INFINITY : s.limits.cohesive_dt;
  }
  for (State& s : n.levels) s.mass_floor = 1e-20 * min_mass;  // one floor (solver/setup.cpp)
  set_up_level_loads(c, n, first_ids);
  const auto locate = [&](std::uint32_t id, std::uint8_t& level, std::uint32_t& node) {
    const auto& st = n.grid.level_start;
    level = std::uint8_t(std::upper_bound(st.begin(), st.end(), std::size_t(id)) - st.begin() - 1);
    node = std::uint32_t(id - st[level]);
  };
  const std::size_t ns = n.grid.slaves.size(), nt = n.grid.terms.size();
  n.slave_level.resize(ns), n.slave_node.resize(ns), n.term_level.resize(nt), n.term_node.resize(nt);
  for (std::size_t k = 0; k < ns; ++k) locate(n.grid.slaves[k], n.slave_level[k], n.slave_node[k]);
  for (std::size_t t = 0; t < nt; ++t) locate(n.grid.terms[t].dof, n.term_level[t], n.term_node[t]);
  // The slaves their level's particles can reach: all but covered nodes kInactiveDepth cells
  // of their level or more inside the finer rectangle (its outer sides do not count).
  for (std::size_t k = 0; k < ns; ++k) {
    const std::size_t l = n.slave_level[k];
    bool deep = l + 1 < n.grid.levels.size();
    if (deep) {
      const LevelLattice& L = n.grid.levels[l];
      const LevelLattice& F = n.grid.levels[l + 1];
      const long node = long(n.slave_node[k]);
      const long u[2] = {L.node0[0] + (node % L.nodes_x()) * L.unit, L.node0[1] + (node / L.nodes_x()) * L.unit};
      const long depth = long(kInactiveDepth) * L.unit;
      for (int d = 0; d < 2; ++d) {
        deep = deep && (F.outer_lo[d] ? u[d] >= F.lo[d] : u[d] - F.lo[d] >= depth);
        deep = deep && (F.outer_hi[d] ? u[d] <= F.hi[d] : F.hi[d] - u[d] >= depth);
      }
    }
    if (!deep) n.active_slaves.push_back(std::uint32_t(k));
  }
  // The active slaves' terms transposed, by DOF (ascending), each DOF's in slave order:
  // condense_to_dofs (solver/transitions.cpp).
  std::vector<std::uint32_t> order, slave_of(nt);
  for (const std::uint32_t k : n.active_slaves)
    for (std::uint32_t t = n.grid.term_start[k]; t < n.grid.term_start[k + 1]; ++t) {
      order.push_back(t);
      slave_of[t] = k;
    }
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return n.grid.terms[a].dof < n.grid.terms[b].dof;
  });
  const std::size_t na = order.size();
  n.dof_slave.resize(na), n.dof_c.resize(na);
  n.dof_start.assign(1, 0);
  for (std::size_t j = 0; j < na; ++j) {
    const std::uint32_t t = order[j];
    if (j == 0 || n.grid.terms[t].dof != n.grid.terms[order[j - 1]].dof) {
      if (j > 0) n.dof_start.push_back(std::uint32_t(j));
      n.dof_level.push_back(n.term_level[t]);
      n.dof_node.push_back(n.term_node[t]);
    }
    n.dof_slave[j] = slave_of[t];
    n.dof_c[j] = n.grid.terms[t].c;
  }
  n.dof_start.push_back(std::uint32_t(na));
  set_level_absorbing(c, n);
  // Per-level time steps: level l at its own CFL step, period 2^(K - l) finest steps, K the
  // interface's level (its cohesive bound is recomputed every finest step: it and the finer
  // levels step every h) or, without interfaces, the finest.
  int reference = levels - 1;
  for (int l = 0; l < levels; ++l)
    if (!n.levels[std::size_t(l)].interfaces.empty()) reference = l;
  n.period.assign(std::size_t(levels), 1);
  if (c.time.subcycling == Subcycling::levels) {
    for (int l = 0; l < reference; ++l) n.period[std::size_t(l)] = 1 << (reference - l);
    // The finest level reaching each DOF through its lattice (the DOF's own, or an active
    // slave's with a term on it), then the nodes of each level whose DOFs a finer one reaches.
    const std::vector<std::size_t>& st = n.grid.level_start;
    std::vector<std::uint8_t> reach(n.grid.num_nodes(), 0);
    for (int l = 0; l < levels; ++l)
      for (std::size_t g = st[std::size_t(l)]; g < st[std::size_t(l) + 1]; ++g) reach[g] = std::uint8_t(l);
    for (const std::uint32_t k : n.active_slaves)
      for (std::uint32_t t = n.grid.term_start[k]; t < n.grid.term_start[k + 1]; ++t)
        reach[n.grid.terms[t].dof] = std::max(reach[n.grid.terms[t].dof], n.slave_level[k]);
    n.mixed.resize(std::size_t(levels));
    std::vector<long> slave_index(n.grid.num_nodes(), -1);
    for (std::size_t k = 0; k < n.grid.slaves.size(); ++k) slave_index[n.grid.slaves[k]] = long(k);
    for (int l = 0; l < levels; ++l) {
      std::vector<unsigned char>& m = n.mixed[std::size_t(l)];
      m.assign(st[std::size_t(l) + 1] - st[std::size_t(l)], 0);
      for (std::size_t node = 0; node < m.size(); ++node) {
        const std::size_t g = st[std::size_t(l)] + node;
        if (slave_index[g] < 0) {
          m[node] = reach[g] > l;
          continue;
        }
        const std::uint32_t k = std::uint32_t(slave_index[g]);
        for (std::uint32_t t = n.grid.term_start[k]; t < n.grid.term_start[k + 1]; ++t)
          m[node] = m[node] || reach[n.grid.terms[t].dof] > l;
      }
    }
    n.mixed_reach.resize(std::size_t(levels));
    for (int l = 0; l < levels; ++l) {
      const std::vector<unsigned char>& m = n.mixed[std::size_t(l)];
      const long nx = n.levels[std::size_t(l)].grid.nodes_x(), ny = n.levels[std::size_t(l)].grid.nodes_y();
      std::vector<unsigned char>& r = n.mixed_reach[std::size_t(l)];
      r.assign(m.size(), 0);
      for (long j = 0; j < ny; ++j)
        for (long i = 0; i < nx; ++i)
          for (long b = j; b < std::min(ny, j + 3); ++b)
            for (long a = i; a < std::min(nx, i + 3); ++a)
              r[std::size_t(j * nx + i)] = r[std::size_t(j * nx + i)] || m[std::size_t(b * nx + a)];
    }
    coupled_nodes(n);
  }
  n.dt = n.levels[0].dt;
  return n;
}

NestedDrift nested_drift_before(RunState& n) {
  NestedDrift d;
  for (State& s : n.levels) {
    d.window_drift.push_back(s.window_drift);
    s.last_move = 0.0;  // a level whose step goes on does not move its particles
  }
  return d;
}


void step_nested(RunState& n) {
  // Every particle onto the level owning its centre, once any may have moved kMigrateDrift
  // finest cells since the last time (the particle move sums max |v| dt into window_drift,
  // which whole-lattice fields leave alone). Until then a particle may stand a little outside
  // its level's region (its stencil stays on the lattice: the ghost ring is kGhostRing cells,
  // the stencil reaches 1.5) or inside a finer one (its nodes there are covered slaves): the
  // GIMP contract holds either way (tests/test_nested_grid.cpp), and each migration costs a
  // re-sort of the levels it touches.
  // With per-level time steps (solver/nested_subcycle.cpp) particles change level only when
  // every level begins a step, and sooner (kSubcycleDrift): a level's step may not end before.
  const bool subcycled = n.subcycled();
  const bool all_begin = !subcycled || n.substep == 0;
  double drift = 0.0;
  for (const State& s : n.levels) drift = std::max(drift, s.window_drift);
  const double due = (subcycled ? kSubcycleDrift : 1.0) * kMigrateDrift * n.levels.back().grid.x.h;
  if (all_begin && (n.step == 0 || drift >= due)) {
    migrate_levels(n);
    if (RankExchange* x = n.levels[0].halo.get()) x->send_to_level_owners(n);  // distributed: each to
    // the rank owning its cell on its level
    for (State& s : n.levels) s.window_drift = 0.0;
  }
  if (RankExchange* x = n.levels[0].halo.get()) x->migrate_levels_if_due(n);  // distributed: particles
  // that left the rank's block
  for (std::size_t l = 0; l < n.levels.size(); ++l)  // resorted where the particles have moved since
    detail::begin_level_step(n.levels[l], n.base_lines[l], !subcycled || n.substep % n.period[l] == 0);
  const NestedDrift before = nested_drift_before(n);
  const Levels all = detail::levels_of(n);
  const Scheme scheme = n.levels[0].scheme;
  if (subcycled) {
    detail::step_subcycled(n);
    detail::end_step(all, scheme);
  } else {
    detail::step_levels(all, scheme);
    n.dt = n.levels[0].dt;
  }
  n.time += n.dt;
  ++n.step;
  if (RankExchange* x = n.levels[0].halo.get()) x->finish_nested_step(n, before);  // distributed: drift
  // bounds over the ranks; a failure on any rank stops all
}

}  // namespace rupture
