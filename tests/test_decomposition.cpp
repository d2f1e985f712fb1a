// Tests for parallel/decomposition.hpp: recursive bisection by particle count. Every cell in
// exactly one block; the particle counts, not the cells, are balanced (to within one slice of
// cells); any number of ranks; a transposed lattice gives the transposed split; the nodes on a
// cut are counted as shared by the blocks on both sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <barrier>
#include <mutex>
#include <random>
#include <thread>
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

// The bisection over ranks (each holding part of the counts, the blocks' slices summed among
// them: three threads standing in for three ranks) gives the split of the summed counts, block
// for block, and the particles per block.
TEST(Decomposition, bisection_over_ranks_equals_the_bisection_of_the_summed_counts) {
  const int cols = 57, rows = 31, holders = 3;
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> amount(0, 40), who(0, holders - 1);
  std::vector<std::uint32_t> count(std::size_t(cols) * std::size_t(rows), 0);
  std::vector<std::vector<std::pair<long, double>>> part(holders);
  for (long cell = 0; cell < long(count.size()); ++cell) {
    const int n = cell % 7 == 0 ? 5 * amount(rng) : amount(rng) / 8;  // uneven: dense stripes
    for (int k = 0; k < n; ++k) part[std::size_t(who(rng))].push_back({cell, 1.0}), ++count[std::size_t(cell)];
  }
  for (int ranks : {1, 2, 3, 5, 8, 13}) {
    const Decomposition serial = bisect_by_particles(count, cols, rows, ranks);
    std::barrier sync(holders);
    std::mutex m;
    std::vector<double> acc;
    std::vector<Decomposition> got(holders);
    std::vector<std::thread> threads;
    for (int h = 0; h < holders; ++h)
      threads.emplace_back([&, h] {
        const auto sum = [&](double* v, int n) {  // as MPI_Allreduce: every holder gets the sum
          {
            std::lock_guard<std::mutex> lock(m);
            if (acc.size() < std::size_t(n)) acc.resize(std::size_t(n), 0.0);
            for (int i = 0; i < n; ++i) acc[std::size_t(i)] += v[i];
          }
          sync.arrive_and_wait();
          for (int i = 0; i < n; ++i) v[i] = acc[std::size_t(i)];
          sync.arrive_and_wait();
          if (h == 0) acc.clear();
          sync.arrive_and_wait();
        };
        got[std::size_t(h)] = bisect_over_ranks(cell_counts(part[std::size_t(h)], cols), cols, rows, ranks, sum);
      });
    for (std::thread& t : threads) t.join();
    for (const Decomposition& d : got) {
      ASSERT_EQ(d.block.size(), serial.block.size());
      for (std::size_t q = 0; q < d.block.size(); ++q) {
        EXPECT_EQ(d.block[q].c0, serial.block[q].c0) << ranks;
        EXPECT_EQ(d.block[q].c1, serial.block[q].c1) << ranks;
        EXPECT_EQ(d.block[q].r0, serial.block[q].r0) << ranks;
        EXPECT_EQ(d.block[q].r1, serial.block[q].r1) << ranks;
      }
      EXPECT_EQ(d.particles, serial.particles) << ranks;
      EXPECT_EQ(d.shared_nodes, serial.shared_nodes) << ranks;
    }
    // The locator finds every cell's block, as a scan of the blocks does.
    const BlockLocator locate(serial.block, rows);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        int scan = -1;
        for (std::size_t q = 0; q < serial.block.size(); ++q) {
          const CellBlock& b = serial.block[q];
          if (c >= b.c0 && c < b.c1 && r >= b.r0 && r < b.r1) scan = int(q);
        }
        ASSERT_EQ(locate.owner(c, r), scan) << c << ", " << r;
      }
  }
}

// cell_counts adds the amounts of one cell and rounds the sum once.
TEST(Decomposition, cell_counts_merge_a_cells_amounts) {
  const std::vector<CellCount> c = cell_counts({{7, 0.4}, {3, 1.0}, {7, 0.4}, {12, 2.0}, {3, 1.0}}, 5);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].c, 3);
  EXPECT_EQ(c[0].r, 0);
  EXPECT_EQ(c[0].count, 2u);
  EXPECT_EQ(c[1].c, 2);
  EXPECT_EQ(c[1].r, 1);
  EXPECT_EQ(c[1].count, 1u);  // 0.8 -> 1
  EXPECT_EQ(c[2].c, 2);
  EXPECT_EQ(c[2].r, 2);
  EXPECT_EQ(c[2].count, 2u);
}
