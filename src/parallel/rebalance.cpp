// rupture/parallel/rebalance.cpp
// Load drift (parallel/halo.hpp): a crack running into one block, a body flying across the
// grid. Checked at every migration (when particles may have crossed a block's border): with
// the largest particle count over the ranks more than kRebalanceImbalance above the mean,
// every rank adds its particles per cell into one lattice count, the same bisection as at
// t = 0 (parallel/decomposition.hpp) splits it anew, and each particle goes to its new block's
// rank. Why 5 %: a rebalance costs about one step (a count over the cells, an all-to-all of
// the particles that change rank, a re-sort: measured in docs/parallel.md), and the
// migrations that check it come tens of steps apart (a cell of drift), so an imbalance of 5 %
// held until the next check already costs more than the rebalance.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstring>

#include "parallel/decomposition.hpp"
#include "parallel/halo.hpp"

namespace rupture {

void rebalance_if_needed(State& s) {
  Halo& h = *s.halo;
  const Comm& comm = h.comm;
  if (!comm.distributed()) return;
  Particles& P = s.particles;
  const double mine = double(P.size());
  const double largest = comm.max(mine), mean = comm.sum(mine) / double(comm.size());
  const double before = mean > 0.0 ? largest / mean - 1.0 : 0.0;
  if (before <= kRebalanceImbalance) return;
  const auto t0 = std::chrono::steady_clock::now();
  // The particles per cell of the whole lattice (the split's input, as at t = 0).
  const int cols = s.grid.x.cells, rows = s.grid.y.cells;
  std::vector<double> count(std::size_t(cols) * std::size_t(rows), 0.0);
  std::vector<int> cell(P.size());
  for (std::size_t p = 0; p < P.size(); ++p) {
    const int c = std::clamp(s.grid.x.cell_of(P.x[p]), 0, cols - 1);
    const int r = std::clamp(s.grid.y.cell_of(P.y[p]), 0, rows - 1);
    cell[p] = c + r * cols;
    count[std::size_t(cell[p])] += 1.0;
  }
  comm.sum(count.data(), int(count.size()));
  std::vector<std::uint32_t> whole(count.size());
  for (std::size_t k = 0; k < count.size(); ++k) whole[k] = std::uint32_t(count[k]);
  const Decomposition d = bisect_by_particles(whole, cols, rows, comm.size());
  // Each particle to the rank of the block holding its cell.
  std::vector<int> owner(count.size(), 0);
  for (std::size_t q = 0; q < d.block.size(); ++q) {
    const CellBlock& b = d.block[q];
    for (int r = b.r0; r < b.r1; ++r)
      for (int c = b.c0; c < b.c1; ++c) owner[std::size_t(c + r * cols)] = int(q);
  }
  std::vector<std::vector<unsigned char>> send(std::size_t(comm.size())), recv;
  std::vector<unsigned char> leaving(P.size(), 0);
  for (std::size_t p = 0; p < P.size(); ++p) {
    const int q = owner[std::size_t(cell[p])];
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
  ++h.rebalances;
  const double seconds = comm.max(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  const double moved_all = comm.sum(double(moved));
  h.last_rebalance = fmt::format(
      "rebalanced at step {}, t = {:.6e} s: particles per rank {:.0f} at most against a mean of "
      "{:.0f} ({:.1f} % over); new split {:.1f} % over, {:.0f} particles moved in {:.3g} s (the "
      "re-sort follows)",
      s.step, s.time, largest, mean, 100.0 * before, 100.0 * d.imbalance(), moved_all, seconds);
}

}  // namespace rupture
