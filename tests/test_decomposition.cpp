// Tests for parallel/decomposition.hpp: recursive bisection by particle count. Every cell in
// exactly one block; the particle counts, not the cells, are balanced (to within one slice of
// cells); any number of ranks; a transposed lattice gives the transposed split; the nodes on a
// cut are counted as shared by the blocks on both sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "parallel/decomposition.hpp"

using namespace rupture;

namespace {

std::vector<std::uint32_t> uniform(int cols, int rows, std::uint32_t per_cell) {
  return std::vector<std::uint32_t>(std::size_t(cols) * std::size_t(rows), per_cell);
}

// Every cell lies in exactly one block.
void expect_partition(const Decomposition& d, int cols, int rows) {
  std::vector<int> owner(std::size_t(cols) * std::size_t(rows), 0);
  for (const CellBlock& b : d.block) {
    ASSERT_LT(b.c0, b.c1);
    ASSERT_LT(b.r0, b.r1);
    for (int r = b.r0; r < b.r1; ++r)
      for (int c = b.c0; c < b.c1; ++c) ++owner[std::size_t(c) + std::size_t(r) * std::size_t(cols)];
  }
  EXPECT_EQ(std::count(owner.begin(), owner.end(), 1), long(owner.size()));
}

}  // namespace

TEST(Decomposition, any_rank_count_partitions_a_uniform_lattice_evenly) {
  const int cols = 64, rows = 64;
  const auto count = uniform(cols, rows, 4);
  for (int ranks = 1; ranks <= 9; ++ranks) {
    const Decomposition d = bisect_by_particles(count, cols, rows, ranks);
    ASSERT_EQ(d.block.size(), std::size_t(ranks));
    expect_partition(d, cols, rows);
    EXPECT_EQ(d.total(), std::size_t(4 * cols * rows));
    // A cut misses its goal by at most half a slice (at most 64 cells of 4 particles here);
    // a rank's count is off its share by its cuts' misses divided among the ranks below each
    // cut: at most 128 (1 + 1/2 + 1/4 + ...) < 256 particles.
    const double mean = double(d.total()) / ranks;
    EXPECT_LE(d.imbalance() * mean, 256.0) << ranks << " ranks";
  }
  EXPECT_EQ(bisect_by_particles(count, cols, rows, 4).imbalance(), 0.0);
}

TEST(Decomposition, balances_particles_not_cells) {
  // Particles only in the left quarter of the lattice (16 x 32 cells): two ranks split that
  // quarter, across its longer side (the cut with fewer particles beside it: 2 rows of 16
  // cells, not 2 columns of 32), though the lattice is wider than tall.
  const int cols = 64, rows = 32;
  std::vector<std::uint32_t> count(std::size_t(cols) * std::size_t(rows), 0);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < 16; ++c) count[std::size_t(c) + std::size_t(r) * cols] = 4;
  const Decomposition d = bisect_by_particles(count, cols, rows, 2);
  expect_partition(d, cols, rows);
  EXPECT_EQ(d.particles[0], d.particles[1]);
  EXPECT_EQ(d.block[0].r1, 16);  // half of the particles, across the quarter's rows
  EXPECT_EQ(d.block[0].c1, cols);
  EXPECT_EQ(d.imbalance(), 0.0);
}

TEST(Decomposition, a_transposed_lattice_gives_the_transposed_split) {
  const int cols = 48, rows = 32;
  std::vector<std::uint32_t> count(std::size_t(cols) * std::size_t(rows)), flipped(count.size());
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      // Uneven counts (no two cuts miss their goals by the same amount: a square block is
      // cut across x on such a tie, which a transposition would not mirror).
      const std::uint32_t n = 1 + ((std::uint32_t(c) * 2654435761u + std::uint32_t(r) * 40503u) >> 7) % 97 +
                              (c > 30 ? 40 : 0);
      count[std::size_t(c) + std::size_t(r) * cols] = n;
      flipped[std::size_t(r) + std::size_t(c) * rows] = n;  // cell (c, r) -> (r, c)
    }
  for (int ranks : {2, 3, 4, 5, 6, 7, 8, 13}) {
    const Decomposition a = bisect_by_particles(count, cols, rows, ranks);
    const Decomposition b = bisect_by_particles(flipped, rows, cols, ranks);
    for (std::size_t k = 0; k < a.block.size(); ++k) {
      EXPECT_EQ(a.block[k].c0, b.block[k].r0);
      EXPECT_EQ(a.block[k].c1, b.block[k].r1);
      EXPECT_EQ(a.block[k].r0, b.block[k].c0);
      EXPECT_EQ(a.block[k].r1, b.block[k].c1);
      EXPECT_EQ(a.particles[k], b.particles[k]);
    }
  }
}

TEST(Decomposition, nodes_on_a_cut_are_shared_by_both_sides) {
  const int cols = 64, rows = 64;
  const Decomposition two = bisect_by_particles(uniform(cols, rows, 4), cols, rows, 2);
  EXPECT_EQ(two.block[0].c1, 32);
  EXPECT_EQ(two.shared_nodes[0], rows + 1);  // the cut's column of nodes
  EXPECT_EQ(two.shared_nodes[1], rows + 1);
  const Decomposition four = bisect_by_particles(uniform(cols, rows, 4), cols, rows, 4);
  for (long n : four.shared_nodes) EXPECT_EQ(n, 2 * 33 - 1);  // two half cuts, one corner
}

TEST(Decomposition, as_many_ranks_as_cells_and_no_more) {
  const auto count = uniform(3, 2, 1);
  const Decomposition d = bisect_by_particles(count, 3, 2, 6);
  expect_partition(d, 3, 2);
  for (const CellBlock& b : d.block) EXPECT_EQ(b.cells(), 1);
  EXPECT_THROW(bisect_by_particles(count, 3, 2, 7), std::invalid_argument);
  EXPECT_THROW(bisect_by_particles(count, 3, 2, 0), std::invalid_argument);
}
