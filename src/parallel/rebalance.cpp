// rupture/parallel/rebalance.cpp
// Load drift (parallel/halo.hpp): a crack running into one block, a body flying across the
// grid. The load of a rank is its particles plus its owned interface nodes, each node weighted
// by w = (cost of an interface node-update) / (cost of a particle-update), both measured over
// the run so far on all ranks (cohesive phases' wall time per owned node-update; the rest of the
// steps' wall time, exchanges excluded, per particle-update): no tuned weight, and 0 until
// there is a measurement. Checked at every migration and every ScatterPlan::sort_interval
// steps. With the largest load more than kRebalanceImbalance above the mean, every rank adds
// its load per cell, the same bisection as at t = 0 splits the load summed over the ranks
// (parallel/decomposition.hpp: bisect_over_ranks, the blocks' slices summed, never the whole
// lattice), and each particle goes to its new block's rank.
// Why 5 %: a rebalance costs about one step (a count over the cells, an all-to-all of the
// particles that change rank, a re-sort: measured in docs/parallel.md), and the checks come
// tens of steps apart, so an imbalance of 5 % kept until the next check costs more. The new
// split is kept only if it is better by 5 % of the mean too (whole cells cannot always divide
// the load: an interface along one row of cells).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

#include "parallel/decomposition.hpp"
#include "parallel/halo.hpp"

namespace rupture {
namespace {

// Interface node-update cost over particle-update cost, measured on all ranks (0: no data yet).
double node_weight(const State& s) {
  const Halo& h = halo_of(s);
  double m[4] = {s.cohesive_seconds, h.step_seconds - h.exchange_seconds, h.particle_steps, h.node_steps};
  h.comm.sum(m, 4);
  const double particle_seconds = m[1] - m[0];
  if (m[3] <= 0.0 || m[2] <= 0.0 || particle_seconds <= 0.0 || m[0] <= 0.0) return 0.0;
  return (m[0] / m[3]) / (particle_seconds / m[2]);
}

// Load units per particle in the lattice count (integers: the bisection counts uint32).
constexpr double kUnits = 16.0;

}  // namespace

void rebalance_if_needed(State& s) {
  Halo& h = halo_of(s);
  const Comm& comm = h.comm;
  if (!comm.distributed() || !h.rebalance) return;
  Particles& P = s.particles;
  const double w = node_weight(s);
  const double mine = double(P.size()) + w * h.owned_nodes;  // particle-updates per step
  const double largest = comm.max(mine), mean = comm.sum(mine) / double(comm.size());
  const double before = mean > 0.0 ? largest / mean - 1.0 : 0.0;
  if (before <= kRebalanceImbalance) return;
  const auto t0 = std::chrono::steady_clock::now();
  // This rank's load per cell, and the bisection of the load summed over the ranks slice by
  // slice (no rank holds the whole lattice's count; parallel/decomposition.hpp).
  const int cols = s.grid.x.cells, rows = s.grid.y.cells;
  auto cell_of = [&](double x, double y) {
    return std::clamp(s.grid.x.cell_of(x), 0, cols - 1) + std::clamp(s.grid.y.cell_of(y), 0, rows - 1) * cols;
  };
  std::vector<std::pair<long, double>> load;
  std::vector<int> cell(P.size());
  for (std::size_t p = 0; p < P.size(); ++p) {
    cell[p] = cell_of(P.x[p], P.y[p]);
    load.push_back({cell[p], kUnits});
  }
  for (const CohesiveInterface& c : s.interfaces)
    for (std::size_t k = 0; k < c.num_nodes(); ++k)
      if (c.owns(k)) load.push_back({cell_of(c.x0[k], c.y0[k]), kUnits * w});
  const Decomposition d = bisect_over_ranks(cell_counts(std::move(load), cols), cols, rows, comm.size(),
                                            [&comm](double* v, int n) { comm.sum(v, n); });
  // Only a split that gains: load concentrated in one row of cells (an interface along a cut
  // direction) may not be divisible further by whole cells.
  if (before - d.imbalance() <= kRebalanceImbalance) return;
  collect_interface_state(s);  // the new owners of interface nodes need their whole state
  // Each particle to the rank of the block holding its cell.
  const BlockLocator locate(d.block, rows);
  std::vector<std::vector<unsigned char>> send(std::size_t(comm.size())), recv;
  std::vector<unsigned char> leaving(P.size(), 0);
  for (std::size_t p = 0; p < P.size(); ++p) {
    const int q = locate.owner(cell[p] % cols, cell[p] / cols);
    if (q == comm.rank()) continue;
    leaving[p] = 1;
    std::vector<unsigned char>& out = send[std::size_t(q)];
    const std::size_t at = out.size();
    out.resize(at + Particles::kPacked * sizeof(double));
    double rec[Particles::kPacked];
    P.pack(p, rec);
    std::memcpy(out.data() + at, rec, sizeof rec);
  }
  Particles gone;
  const std::size_t moved = P.move_marked(leaving, gone);
  comm.all_to_all(send, recv);
  for (const std::vector<unsigned char>& in : recv)  // in rank order
    for (std::size_t at = 0; at + Particles::kPacked * sizeof(double) <= in.size();
         at += Particles::kPacked * sizeof(double)) {
      double rec[Particles::kPacked];
      std::memcpy(rec, in.data() + at, sizeof rec);
      P.push_packed(rec);
    }
  set_blocks(s, d.block);
  h.drift = 0.0;  // every particle is inside its new block
  ++h.rebalances;
  const double seconds = comm.max(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  const double moved_all = comm.sum(double(moved));
  h.last_rebalance = fmt::format(
      "rebalanced at step {}, t = {:.6e} s: load per rank {:.0f} at most against a mean of {:.0f} "
      "particle-updates per step ({:.1f} % over; an interface node counts {:.2f}, measured); new "
      "split {:.1f} % over, {:.0f} particles moved in {:.3g} s (the re-sort follows)",
      s.step, s.time, largest, mean, 100.0 * before, w, 100.0 * d.imbalance(), moved_all, seconds);
}

void enable_rebalance(RunState& r, bool on) {
  if (r.halo && !r.is_nested()) halo_of(r.levels[0]).rebalance = on;  // nested levels: one split (halo_nested.cpp)
}

std::string kept_split_drift(const RunState& r, const Comm& comm, const std::vector<long>& start,
                             const std::vector<long>& end) {
  if (!r.is_nested() || !comm.distributed()) return {};  // other splits follow the load, or none is made
  // The most particles on a rank over the mean, minus 1.
  const auto over = [](const std::vector<long>& v) {
    double most = 0.0, all = 0.0;
    for (const long n : v) most = std::max(most, double(n)), all += double(n);
    return all > 0.0 ? most / (all / double(v.size())) - 1.0 : 0.0;
  };
  const double before = over(start), after = over(end);
  if (!(after - before > kRebalanceImbalance)) return {};
  return fmt::format("nested levels keep their first split: the most particles on a rank went from {:.1f} % "
                     "to {:.1f} % over the mean",
                     100.0 * before, 100.0 * after);
}

}  // namespace rupture
