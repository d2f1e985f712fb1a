// rupture/parallel/decomposition.hpp
// How a lattice of cells is split between N processes for a distributed run: recursive
// coordinate bisection weighted by particle count. Each rank gets one rectangular block of
// whole cells; a block with k of the N ranks is cut (across the axis whose cut has fewer
// particles beside it, among those within kSplitTolerance of the share: across the longer side
// of a uniform lattice) where
// the particles on the low side come closest to k_low / k of the block's, with
// k_low = floor(k / 2) (so any N works, not only powers of two). The particle work of a step is
// proportional to the particle count (the grid work is a few percent: docs/performance.md),
// so the largest count over the mean predicts the step's imbalance. A rank owns the nodes of
// its cells; the nodes on a cut are shared with the neighbouring block (its halo: summed
// after a scatter, copied after a gather). Nested levels share one split of level 0's cells
// (parallel/halo_nested.hpp).
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace rupture {

// A cut that misses the ranks' share by at most this fraction of one rank's share counts as
// balanced (the imbalance a run tolerates before it re-splits: kRebalanceImbalance,
// parallel/halo.hpp); among balanced cuts the one with fewer particles beside it is taken.
inline constexpr double kSplitTolerance = 0.05;

// Cells [c0, c1) x [r0, r1) of a lattice (cell (c, r) at column c, row r).
struct CellBlock {
  int c0 = 0, c1 = 0, r0 = 0, r1 = 0;
  long cells() const { return long(c1 - c0) * long(r1 - r0); }
};

struct Decomposition {
  std::vector<CellBlock> block;        // per rank
  std::vector<std::size_t> particles;  // per rank
  std::vector<long> shared_nodes;      // per rank: nodes of its block also in another block
  std::size_t total() const;           // particles in all
  double imbalance() const;            // largest count / mean - 1 (0: perfectly balanced)
};

// Splits a cols x rows lattice among `ranks` (>= 1, at most cols x rows). count[c + r * cols]:
// particles in cell (c, r). Throws std::invalid_argument for a lattice with fewer cells than
// ranks.
Decomposition bisect_by_particles(const std::vector<std::uint32_t>& count, int cols, int rows,
                                  int ranks);
// The same bisection when each of the ranks holds some of the particles: `mine` lists this
// rank's count per cell (each cell once, any order), and each block's slices (its particles per
// column and per row) are summed over the ranks by `sum_over_ranks` (collective: every rank
// calls it for the same blocks in the same order). The split equals bisect_by_particles of the
// counts summed over the ranks, and no rank holds a count of the whole lattice.
struct CellCount {
  int c = 0, r = 0;
  std::uint32_t count = 0;
};
Decomposition bisect_over_ranks(const std::vector<CellCount>& mine, int cols, int rows, int ranks,
                                const std::function<void(double*, int)>& sum_over_ranks);
// This rank's count per cell from amounts (cell index c + r cols, amount): the amounts of one
// cell added, then rounded to a whole count.
std::vector<CellCount> cell_counts(std::vector<std::pair<long, double>> amounts, int cols);

// Which block holds a cell, without a lattice-sized table: per row, the blocks crossing it in
// increasing columns (blocks that tile the lattice).
class BlockLocator {
 public:
  BlockLocator(const std::vector<CellBlock>& blocks, int rows);
  int owner(int c, int r) const;  // -1: no block holds it
 private:
  struct Span {
    int c0, c1, rank;
  };
  std::vector<std::vector<Span>> row_;
};

// The particles and shared nodes of given blocks (a nested level's share of a common split).
Decomposition decomposition_of(std::vector<CellBlock> blocks, const std::vector<std::uint32_t>& count, int cols);

}  // namespace rupture
