// rupture/parallel/rank_plan.cpp
#include "parallel/rank_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "core/errors.hpp"
#include "parallel/halo.hpp"
#include "parallel/halo_nested.hpp"
#include "solver/nested_state.hpp"

namespace rupture {
namespace {

// Particles per cell of s's grid (cell (c, r) at c + r cols), positions at their cells.
std::vector<std::uint32_t> particles_per_cell(const State& s) {
  const int cols = s.grid.x.cells, rows = s.grid.y.cells;
  std::vector<std::uint32_t> count(std::size_t(cols) * std::size_t(rows), 0);
  const Particles& P = s.particles;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const int c = std::clamp(s.grid.x.cell_of(P.x[p]), 0, cols - 1);
    const int r = std::clamp(s.grid.y.cell_of(P.y[p]), 0, rows - 1);
    ++count[std::size_t(c) + std::size_t(r) * std::size_t(cols)];
  }
  return count;
}

LevelSplit split_level(const State& s, int period, int ranks) {
  LevelSplit l;
  l.cols = s.grid.x.cells;
  l.rows = s.grid.y.cells;
  l.period = period;
  l.fields = s.fields.num_fields;
  try {
    l.split = bisect_by_particles(particles_per_cell(s), l.cols, l.rows, ranks);
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("--ranks {}: {}", ranks, e.what()));
  }
  return l;
}

}  // namespace

int LevelSplit::width() const {
  int w = 0;
  for (std::size_t r = 0; r < reach.size(); ++r) {
    const CellBlock& b = split.block[r];
    const NodeBox& e = reach[r];
    if (b.cells() > 0 && !e.empty()) w = std::max({w, b.c0 - e.i0, e.i1 - b.c1, b.r0 - e.j0, e.j1 - b.r1});
  }
  return w;
}

double RankPlan::imbalance() const {
  if (work.empty()) return 0.0;
  const double sum = std::accumulate(work.begin(), work.end(), 0.0);
  if (sum <= 0.0) return 0.0;
  return *std::max_element(work.begin(), work.end()) / (sum / double(work.size())) - 1.0;
}

namespace {

// The plan of one grid s (levels null), or of nested levels (s: its grid level, whose interfaces
// are the run's: distributed interfaces lie on one level).
RankPlan plan_of(const RunState* levels, const State& s, int ranks) {
  if (ranks < 1) throw InputError(fmt::format("--ranks {}: at least 1", ranks));
  RankPlan plan;
  plan.ranks = ranks;
  const bool cohesive = levels ? levels->num_interfaces() > 0 : !s.interfaces.empty();
  std::vector<bool> interface_levels;  // per lattice: it holds interfaces (one grid: the grid)
  // [loads] forces are summed after each scatter (every level lists the loads: its first's).
  const bool loads_forces = (levels ? levels->levels[0] : s).loads.has_forces();
  if (levels) {
    const RunState& n = *levels;
    // One split for every level (parallel/halo_nested.hpp).
    const NestedSplit sp = split_nested(n, ranks);
    plan.cut_level = sp.cut_level;
    for (std::size_t l = 0; l < n.levels.size(); ++l) {
      const State& ls = n.levels[l];
      LevelSplit L;
      L.cols = ls.grid.x.cells, L.rows = ls.grid.y.cells;
      L.period = n.period.empty() ? 1 : n.period[l];
      L.fields = ls.fields.num_fields;
      L.reach = sp.reaches[l];
      L.split = decomposition_of(sp.blocks[l], particles_per_cell(ls), L.cols);
      plan.levels.push_back(std::move(L));
    }
    for (std::size_t l = 0; l < n.levels.size(); ++l) interface_levels.push_back(n.holds_interfaces(int(l)));
  } else {
    plan.levels.push_back(split_level(s, 1, ranks));
    for (const CellBlock& b : plan.levels.back().split.block)
      plan.levels.back().reach.push_back(reach_box(b, s.grid, cohesive ? kInterfaceHaloNodes : kHaloNodes));
  }
  plan.work.assign(std::size_t(ranks), 0.0);
  plan.exchange_bytes.assign(std::size_t(ranks), 0.0);
  for (std::size_t l = 0; l < plan.levels.size(); ++l) {
    const LevelSplit& L = plan.levels[l];
    const bool here = cohesive && (l < interface_levels.size() ? bool(interface_levels[l]) : l == 0);  // the cohesive forces' sum
    // Per finest step: the scatter's sums once per level step (mass, momentum, force; [loads]
    // forces), the re-mapped momentum every finest step, the cohesive forces on their level.
    const double values = double(kExchangedValues - 2 + (loads_forces ? 2 : 0)) / double(L.period) +
                          2.0 + (here ? 2.0 : 0.0);
    for (std::size_t r = 0; r < std::size_t(ranks); ++r) {
      plan.work[r] += double(L.split.particles[r]) / double(L.period);
      const NodeBox& mine = L.reach[r];
      long halo = 0;  // nodes of this rank's reach in each neighbour's, summed over neighbours
      for (std::size_t q = 0; q < std::size_t(ranks); ++q)
        if (q != r) halo += overlap(mine, L.reach[q]).count();
      plan.exchange_bytes[r] += 8.0 * values * double(halo) * double(L.fields);
      // Interface nodes: each step the owners send the faces (4 values) and the stiffness (1)
      // of the nodes their neighbours know.
      if (here) plan.exchange_bytes[r] += 8.0 * 5.0 * double(interface_nodes_sent(s, L.split.block, int(r)));
    }
  }
  return plan;
}

}  // namespace

RankPlan plan_ranks(const State& s, int ranks) { return plan_of(nullptr, s, ranks); }

RankPlan plan_ranks(const RunState& r, int ranks) {
  return r.is_nested() ? plan_of(&r, r.levels[r.grid_level], ranks) : plan_of(nullptr, r.levels[0], ranks);
}

}  // namespace rupture
