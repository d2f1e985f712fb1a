// rupture/parallel/halo_nested.cpp
#include "parallel/halo_nested.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/errors.hpp"
#include "parallel/halo.hpp"
#include "solver/energy.hpp"

namespace rupture {

int nested_cut_level(const RunState& n) {
  const Grid& g0 = n.levels[0].grid;
  int k = 0;
  while (std::size_t(k) + 1 < n.levels.size() &&
         (double(g0.x.cells) * double(g0.y.cells)) * double(1L << (2 * (k + 1))) <= double(kCutLatticeCells))
    ++k;
  return k;
}

namespace {

// Adds a particle of level l at (x, y) to the cut lattice's count (nested_cut_count).
struct CutCounter {
  const RunState& n;
  int cols, rows, longest = 1;
  double h;
  std::vector<std::uint32_t> count;
  CutCounter(const RunState& nested, int k, bool dense = true)
      : n(nested), cols(nested.levels[0].grid.x.cells << k), rows(nested.levels[0].grid.y.cells << k),
        h(nested.levels[0].grid.x.h / double(1 << k)) {
    if (dense) count.assign(std::size_t(cols) * std::size_t(rows), 0);
    for (const int p : n.period) longest = std::max(longest, p);
  }
  // Per-level time steps: a level's particle costs 1 / period per finest step.
  std::uint32_t weight(std::size_t l) const { return std::uint32_t(longest / (n.period.empty() ? 1 : n.period[l])); }
  long index(double x, double y) const {  // c + r cols on the cut lattice
    const Grid& g0 = n.levels[0].grid;
    const int c = std::clamp(int(std::floor((x - g0.x.origin) / h)), 0, cols - 1);
    const int r = std::clamp(int(std::floor((y - g0.y.origin) / h)), 0, rows - 1);
    return long(c) + long(r) * long(cols);
  }
  void add(std::uint32_t w, double x, double y) { count[std::size_t(index(x, y))] += w; }
};

}  // namespace

std::vector<std::uint32_t> nested_cut_count(const RunState& n, int k) {
  CutCounter cc(n, k);
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    const Particles& P = n.levels[l].particles;
    const std::uint32_t w = cc.weight(l);
    for (std::size_t p = 0; p < P.size(); ++p) cc.add(w, P.x[p], P.y[p]);
  }
  return cc.count;
}

NestedTally nested_seed_tally(const Case& c, const RunState& n, int k) {
  CutCounter cc(n, k);
  NestedTally t;
  t.min_mass = std::numeric_limits<double>::max();
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    const std::uint32_t w = cc.weight(l);
    std::uint32_t count = 0;
    for_each_level_point(c, n, int(l), [&](double x, double y, double m) {
      cc.add(w, x, y);
      ++count;
      t.min_mass = std::min(t.min_mass, m);
    });
    t.per_level.push_back(count);
  }
  t.cut_count = std::move(cc.count);
  return t;
}

CellBlock level_block(const NestedGrid& g, int l, const CellBlock& cut, int k) {
  const LevelLattice& C = g.levels[0];
  const LevelLattice& L = g.levels[std::size_t(l)];
  const long unit = C.unit >> k;  // the cut lattice's cell, finest units
  // Cut line m lies at C.node0 + m unit finest units; on level l, at or above the level's line
  // below it (floor: the same map for every block, so the blocks tile the level).
  const auto map = [&](int m, int d, int cells) {
    const long u = C.node0[d] + long(m) * unit - L.node0[d];
    const long q = u >= 0 ? u / L.unit : -((-u + L.unit - 1) / L.unit);
    return int(std::clamp(q, 0L, long(cells)));
  };
  return CellBlock{map(cut.c0, 0, L.x.cells), map(cut.c1, 0, L.x.cells), map(cut.r0, 1, L.y.cells),
                   map(cut.r1, 1, L.y.cells)};
}

std::vector<std::vector<NodeBox>> nested_reaches(const RunState& n,
                                                 const std::vector<std::vector<CellBlock>>& blocks) {
  const std::size_t levels = n.levels.size(), ranks = blocks[0].size();
  // The DOF index (into RunState::dof_level) of each (level, node) with condensed terms.
  std::vector<std::vector<int>> dof_of(levels);
  for (std::size_t l = 0; l < levels; ++l) dof_of[l].assign(n.levels[l].grid.num_nodes(), -1);
  for (std::size_t d = 0; d < n.dof_level.size(); ++d) dof_of[n.dof_level[d]][n.dof_node[d]] = int(d);
  std::vector<std::vector<NodeBox>> out(levels, std::vector<NodeBox>(ranks));
  for (std::size_t r = 0; r < ranks; ++r) {
    std::vector<NodeBox> touched(levels), need(levels);
    for (std::size_t l = 0; l < levels; ++l)
      if (blocks[l][r].cells() > 0)  // no particle of this rank on a level outside its block
        touched[l] = need[l] = reach_box(blocks[l][r], n.levels[l].grid, nested_touched_width(n, int(l)));
    const auto add = [&](std::size_t l, std::uint32_t node) {
      const int nx = n.levels[l].grid.nodes_x(), i = int(node % std::uint32_t(nx)), j = int(node / std::uint32_t(nx));
      NodeBox& b = need[l];
      if (b.empty()) {
        b = NodeBox{i, i, j, j};
        return;
      }
      b.i0 = std::min(b.i0, i), b.i1 = std::max(b.i1, i), b.j0 = std::min(b.j0, j), b.j1 = std::max(b.j1, j);
    };
    const auto add_slaves_of = [&](std::size_t l, std::uint32_t node) {
      const int d = dof_of[l][node];
      if (d < 0) return;
      for (std::uint32_t j = n.dof_start[std::size_t(d)]; j < n.dof_start[std::size_t(d) + 1]; ++j)
        add(n.slave_level[n.dof_slave[j]], n.slave_node[n.dof_slave[j]]);
    };
    const auto touches = [&](std::size_t l, std::uint32_t node) {
      const int nx = n.levels[l].grid.nodes_x();
      return touched[l].contains(int(node % std::uint32_t(nx)), int(node / std::uint32_t(nx)));
    };
    for (const std::uint32_t k : n.active_slaves) {
      if (!touches(n.slave_level[k], n.slave_node[k])) continue;
      for (std::uint32_t t = n.grid.term_start[k]; t < n.grid.term_start[k + 1]; ++t) {
        add(n.term_level[t], n.term_node[t]);
        add_slaves_of(n.term_level[t], n.term_node[t]);
      }
    }
    for (std::size_t d = 0; d < n.dof_level.size(); ++d)
      if (touches(n.dof_level[d], n.dof_node[d])) add_slaves_of(n.dof_level[d], n.dof_node[d]);
    for (std::size_t l = 0; l < levels; ++l) out[l][r] = need[l];
  }
  return out;
}

int nested_touched_width(const RunState& n, int l) {
  if (n.holds_interfaces(l)) return kInterfaceHaloNodes;  // the faces' stencils, as on one grid
  // A particle is less than kMigrateCells finest cells out of its block (rank moves) and
  // touches nodes closer than h + lp <= 1.5 h: node d of the rim when d < 1.5 + finest / h.
  const double finest = n.levels.back().grid.x.h, h = n.levels[std::size_t(l)].grid.x.h;
  return kMigrateCells * finest <= 0.5 * h ? 1 : kHaloNodes;
}

NestedSplit split_nested(const RunState& n, int ranks) {
  const int k = nested_cut_level(n);
  return split_nested(n, nested_cut_count(n, k), k, ranks);
}

namespace {

// The split's blocks and reaches on every level from the cut lattice's.
NestedSplit split_of(const RunState& n, Decomposition cut, int cut_level) {
  NestedSplit sp;
  sp.cut_level = cut_level;
  sp.cut = std::move(cut);
  const std::size_t levels = n.levels.size();
  sp.blocks.assign(levels, {});
  for (std::size_t l = 0; l < levels; ++l)
    for (const CellBlock& b : sp.cut.block) sp.blocks[l].push_back(level_block(n.grid, int(l), b, sp.cut_level));
  sp.reaches = nested_reaches(n, sp.blocks);
  return sp;
}

[[noreturn]] void cannot_split(int ranks, int cut_level, const std::invalid_argument& e) {
  throw InputError(fmt::format("--ranks {}: nested level {}'s cells over the plate: {}", ranks, cut_level, e.what()));
}

}  // namespace

NestedSplit split_nested(const RunState& n, const std::vector<std::uint32_t>& count, int cut_level, int ranks) {
  const Grid& g0 = n.levels[0].grid;
  try {
    return split_of(n, bisect_by_particles(count, g0.x.cells << cut_level, g0.y.cells << cut_level, ranks), cut_level);
  } catch (const std::invalid_argument& e) {
    cannot_split(ranks, cut_level, e);
  }
}

void distribute_held_nested(RunState& n, const Comm& comm, const std::vector<std::vector<double>>& keys) {
  const int k = nested_cut_level(n);
  // Every rank's particles of every level on the cut lattice (weighted as at t = 0), bisected
  // over the ranks (parallel/decomposition.hpp: no rank holds the lattice's count).
  const CutCounter cc(n, k, false);
  std::vector<std::pair<long, double>> amounts;
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    const Particles& P = n.levels[l].particles;
    const double w = double(cc.weight(l));
    for (std::size_t p = 0; p < P.size(); ++p) amounts.push_back({cc.index(P.x[p], P.y[p]), w});
  }
  Decomposition cut;
  try {
    cut = bisect_over_ranks(cell_counts(std::move(amounts), cc.cols), cc.cols, cc.rows, comm.size(),
                            [&comm](double* v, int m) { comm.sum(v, m); });
  } catch (const std::invalid_argument& e) {
    cannot_split(comm.size(), k, e);
  }
  const NestedSplit sp = split_of(n, std::move(cut), k);
  // Each particle (its level and key before it) to the rank whose block holds its cell on its
  // level; received ones in key order per level (one process's order).
  constexpr std::size_t kRecord = Particles::kPacked + 2;
  std::vector<std::vector<unsigned char>> send(std::size_t(comm.size())), recv;
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    State& L = n.levels[l];
    const BlockLocator locate(sp.blocks[l], L.grid.y.cells);
    Particles& P = L.particles;
    for (std::size_t p = 0; p < P.size(); ++p) {
      const int c = std::clamp(L.grid.x.cell_of(P.x[p]), 0, L.grid.x.cells - 1);
      const int r = std::clamp(L.grid.y.cell_of(P.y[p]), 0, L.grid.y.cells - 1);
      double rec[kRecord];
      rec[0] = double(l), rec[1] = keys[l][p];
      P.pack(p, rec + 2);
      std::vector<unsigned char>& out = send[std::size_t(locate.owner(c, r))];
      out.insert(out.end(), reinterpret_cast<unsigned char*>(rec), reinterpret_cast<unsigned char*>(rec) + sizeof rec);
    }
    P = Particles();
  }
  comm.all_to_all(send, recv);
  send.clear();
  std::vector<std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>>> order(n.levels.size());
  for (std::size_t q = 0; q < recv.size(); ++q)
    for (std::size_t at = 0; at + kRecord * sizeof(double) <= recv[q].size(); at += kRecord * sizeof(double)) {
      double head[2];
      std::memcpy(head, recv[q].data() + at, sizeof head);
      order[std::size_t(head[0])].push_back({head[1], {q, at}});
    }
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    std::sort(order[l].begin(), order[l].end());
    for (const auto& o : order[l]) {
      double rec[Particles::kPacked];
      std::memcpy(rec, recv[o.second.first].data() + o.second.second + 2 * sizeof(double), sizeof rec);
      n.levels[l].particles.push_packed(rec);
    }
  }
  distribute_nested(n, comm, false, &sp);
}

namespace {

// Each level's fields over this rank's reach only, every field the same window (a level it
// does not reach: one node), so its grid work and memory are its reach's; the transitions'
// lists keep the elements in the windows, by their place in the window.
void window_levels(RunState& n) {
  const std::size_t levels = n.levels.size();
  std::vector<std::vector<long>> local(levels);  // per level, lattice node -> its place, or -1
  std::vector<std::size_t> whole(levels);        // the lattice's nodes (the old layout's field size)
  for (std::size_t l = 0; l < levels; ++l) {
    State& s = n.levels[l];
    const NodeBox b = halo_of(s).reach.empty() ? NodeBox{0, 0, 0, 0} : halo_of(s).reach;
    const int F = s.fields.num_fields, nx = s.grid.nodes_x(), ny = s.grid.nodes_y(), w = b.i1 - b.i0 + 1;
    whole[l] = s.grid.num_nodes();
    s.fields.set_windows(std::size_t(nx), std::size_t(ny), std::vector<int>(std::size_t(F), b.i0),
                         std::vector<int>(std::size_t(F), w), std::vector<int>(std::size_t(F), b.j0),
                         std::vector<int>(std::size_t(F), b.j1 - b.j0 + 1));
    local[l].assign(whole[l], -1);
    for (int j = b.j0; j <= b.j1; ++j)
      for (int i = b.i0; i <= b.i1; ++i)
        local[l][std::size_t(j) * std::size_t(nx) + std::size_t(i)] = long(j - b.j0) * w + long(i - b.i0);
  }
  const auto in = [&](std::size_t l, std::uint32_t node) { return local[l][node] >= 0; };
  // Condense: the DOFs in the window, each with its slaves in the window (all of them where the
  // rank's particles read it: nested_reaches).
  std::vector<std::uint8_t> dof_level;
  std::vector<std::uint32_t> dof_node, dof_start{0}, dof_slave;
  std::vector<double> dof_c;
  for (std::size_t d = 0; d < n.dof_level.size(); ++d) {
    if (!in(n.dof_level[d], n.dof_node[d])) continue;
    for (std::uint32_t j = n.dof_start[d]; j < n.dof_start[d + 1]; ++j) {
      const std::uint32_t k = n.dof_slave[j];
      if (!in(n.slave_level[k], n.slave_node[k])) continue;
      dof_slave.push_back(k), dof_c.push_back(n.dof_c[j]);
    }
    dof_level.push_back(n.dof_level[d]);
    dof_node.push_back(std::uint32_t(local[n.dof_level[d]][n.dof_node[d]]));
    dof_start.push_back(std::uint32_t(dof_slave.size()));
  }
  n.dof_level.swap(dof_level), n.dof_node.swap(dof_node), n.dof_start.swap(dof_start);
  n.dof_slave.swap(dof_slave), n.dof_c.swap(dof_c);
  // Distribute (and the condense's clearing): the slaves in the window with every term in it
  // (the others are not read by this rank's particles).
  std::vector<std::uint32_t> active;
  for (const std::uint32_t k : n.active_slaves) {
    bool all = in(n.slave_level[k], n.slave_node[k]);
    for (std::uint32_t t = n.grid.term_start[k]; all && t < n.grid.term_start[k + 1]; ++t)
      all = in(n.term_level[t], n.term_node[t]);
    if (all) active.push_back(k);
  }
  n.active_slaves.swap(active);
  for (std::size_t k = 0; k < n.slave_node.size(); ++k)
    if (in(n.slave_level[k], n.slave_node[k])) n.slave_node[k] = std::uint32_t(local[n.slave_level[k]][n.slave_node[k]]);
  for (std::size_t t = 0; t < n.term_node.size(); ++t)
    if (in(n.term_level[t], n.term_node[t])) n.term_node[t] = std::uint32_t(local[n.term_level[t]][n.term_node[t]]);
  // Per-level time steps: the coupled elements (whole-lattice layout: field f's node at
  // f x nodes) in the window.
  for (std::size_t l = 0; l < n.coupled.size(); ++l) {
    if (n.coupled[l].empty()) continue;
    const GridFields& G = n.levels[l].fields;
    std::vector<std::uint32_t> kept;
    for (const std::uint32_t e : n.coupled[l]) {
      const std::size_t f = e / whole[l], node = e % whole[l];
      if (local[l][node] >= 0) kept.push_back(std::uint32_t(G.start[f] + std::size_t(local[l][node])));
    }
    n.coupled[l].swap(kept);
    n.coupled_mask[l].assign(G.size(), 0);
    for (const std::uint32_t e : n.coupled[l]) n.coupled_mask[l][e] = 1;
  }
}

}  // namespace

void distribute_nested(RunState& n, const Comm& comm, bool fresh, const NestedSplit* given) {
  const NestedSplit sp = given ? *given : split_nested(n, comm.size());
  // Each level's split sees its own interfaces (their faces' owners and links).
  const double finest = n.levels.back().grid.x.h;
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    State& L = n.levels[l];
    auto h = std::make_shared<Halo>();
    h->comm = comm;
    h->cell = finest;  // particles change level on the spot: one drift bound for all levels
    h->reaches = sp.reaches[l];
    h->all_bonded = L.bonded;
    h->count_by_block = true;
    h->rebalance = false;  // the levels share one split (a rebalance would move all of them)
    L.halo = h;
    set_blocks(L, sp.blocks[l]);
    keep_own_particles(L);  // every rank made or read the same state
    const Particles& P = L.particles;
    // E14 as in distribute: this rank's parts of the run's sums.
    if (fresh)
      L.strain_work = strain_energy(P, L.stiffness);
    else if (comm.rank() > 0)
      L.strain_work = L.external_work = L.viscous_work = 0.0;
    if (!fresh && comm.rank() > 0)  // the run's sums stay on rank 0
      for (CohesiveInterface& c : L.interfaces) c.work = 0.0;
  }
  window_levels(n);
  // The run's sums over the ranks need the communicator only: the grid level's exchange.
  n.halo = n.levels[n.grid_level].halo;
  collect_run_sums(n);  // this rank's parts
}

void Halo::send_to_level_owners(RunState& n) {
  const Comm& world = halo_of(n.levels[0]).comm;
  constexpr std::size_t kRecord = (Particles::kPacked + 1) * sizeof(double);  // level, particle
  std::vector<std::vector<unsigned char>> send(std::size_t(world.size())), recv;
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    State& s = n.levels[l];
    Halo& h = halo_of(s);
    Particles& P = s.particles;
    std::vector<unsigned char> leaving(P.size(), 0);
    bool any = false;
    for (std::size_t p = 0; p < P.size(); ++p) {
      const int c = std::clamp(s.grid.x.cell_of(P.x[p]), 0, s.grid.x.cells - 1);
      const int r = std::clamp(s.grid.y.cell_of(P.y[p]), 0, s.grid.y.cells - 1);
      if (h.owns_cell(c, r)) continue;
      std::size_t q = 0;
      while (q < h.blocks.size() && !(c >= h.blocks[q].c0 && c < h.blocks[q].c1 && r >= h.blocks[q].r0 && r < h.blocks[q].r1)) ++q;
      if (q == h.blocks.size()) continue;  // cannot happen: the blocks tile the level
      leaving[p] = 1, any = true;
      double rec[Particles::kPacked + 1];
      rec[0] = double(l);
      P.pack(p, rec + 1);
      std::vector<unsigned char>& out = send[q];
      out.insert(out.end(), reinterpret_cast<unsigned char*>(rec), reinterpret_cast<unsigned char*>(rec) + kRecord);
    }
    if (!any) continue;
    Particles gone;
    P.move_marked(leaving, gone);
    s.plan.valid = false;
  }
  world.all_to_all(send, recv);
  for (const std::vector<unsigned char>& in : recv)  // in rank order
    for (std::size_t at = 0; at + kRecord <= in.size(); at += kRecord) {
      double rec[Particles::kPacked + 1];
      std::memcpy(rec, in.data() + at, kRecord);
      State& s = n.levels[std::size_t(rec[0])];
      s.particles.push_packed(rec + 1);
      s.plan.valid = false;
    }
}

void Halo::migrate_levels_if_due(RunState& n) {
  const Halo& h = halo_of(n.levels[0]);
  // Per-level time steps: only when every level begins a step (no scatter held), and at half
  // the bound: until the next such step the particles move at most the levels' sync drift
  // (kSubcycleDrift x kMigrateDrift of a finest cell) and one level step more.
  if (n.subcycled() && n.substep != 0) return;
  const double bound = (n.subcycled() ? 0.5 : 1.0) * kMigrateCells * h.cell;
  if (h.drift < bound) return;  // the same bound on every rank and level
  for (State& s : n.levels) migrate_particles(s);
}

void Halo::finish_nested_step(RunState& n, const NestedDrift& before) {
  const Comm& world = halo_of(n.levels[0]).comm;
  std::vector<double> move;
  for (const State& s : n.levels) move.push_back(s.last_move);
  world.max(move.data(), int(move.size()));
  double largest = 0.0;
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    n.levels[l].window_drift = before.window_drift[l] + move[l];
    largest = std::max(largest, move[l]);
  }
  std::string found;
  for (State& s : n.levels) {
    halo_of(s).drift += largest;
    if (found.empty()) found = halo_of(s).failure;
    halo_of(s).failure.clear();
  }
  // The reaches hold a particle's stencil while it stays within a cell of its block; with
  // per-level time steps rank moves wait for the levels to begin a step together (above), so
  // the bound is checked: past it a scatter would miss the halo. (One dt for every level: the
  // next step begins with the move, as on one grid.)
  const Halo& h = halo_of(n.levels[0]);
  if (found.empty() && n.subcycled() && h.drift > kMigrateCells * h.cell)
    found = fmt::format("step {}, t = {:.6g} s: particles may have moved {:.3g} finest cells since they last "
                        "changed rank (the halo holds 1): the per-level time steps kept the levels "
                        "apart too long; run without time.subcycling",
                        n.step, n.time, h.drift / h.cell);
  const int failed = world.first_with(!found.empty());
  if (failed < 0) return;
  const std::string what = world.broadcast(found, failed);
  throw SimulationError(world.size() > 1 ? fmt::format("{} (rank {})", what, failed) : what);
}

RunState make_nested_rank_state(const Case& c, const Comm& comm) {
  // The levels without particles: the lattices, transitions and periods the split needs.
  const ParticleShare none = ParticleShare::none();
  std::vector<Grid> lattices;
  NestedSplit sp;
  NestedTally tally;
  {
    const RunState n = make_run_state(c, &none);
    for (const State& l : n.levels) lattices.push_back(l.grid);
    const int k = nested_cut_level(n);
    tally = nested_seed_tally(c, n, k);
    sp = split_nested(n, tally.cut_count, k, comm.size());
  }
  // This rank's particles: on each level, those whose cell is in its block there.
  const std::size_t me = std::size_t(comm.rank());
  ParticleShare share;
  share.own_level = [&](int l, double x, double y) {
    const Grid& g = lattices[std::size_t(l)];
    const CellBlock& b = sp.blocks[std::size_t(l)][me];
    const int i = std::clamp(g.x.cell_of(x), 0, g.x.cells - 1), j = std::clamp(g.y.cell_of(y), 0, g.y.cells - 1);
    return i >= b.c0 && i < b.c1 && j >= b.r0 && j < b.r1;
  };
  std::uint32_t first = 0;
  for (const std::uint32_t count : tally.per_level) share.first_id.push_back(first), first += count;
  RunState r = make_run_state(c, &share);
  distribute_nested(r, comm, true, &sp);
  // The case's sums: one mass floor from its lightest particle (solver/setup.cpp), the initial
  // energy the ranks' parts added.
  for (State& l : r.levels) l.mass_floor = 1e-20 * tally.min_mass;
  r.initial_energy = comm.sum(r.initial_energy);
  return r;
}

}  // namespace rupture
