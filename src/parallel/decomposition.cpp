// rupture/parallel/decomposition.cpp
#include "parallel/decomposition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace rupture {
namespace {

struct Lattice {
  const std::vector<std::uint32_t>& count;
  int cols, rows;
};

// Particles in the block's slices along one axis: per column (along_x) or per row.
std::vector<std::size_t> slices(const Lattice& L, const CellBlock& b, bool along_x) {
  std::vector<std::size_t> s(std::size_t(along_x ? b.c1 - b.c0 : b.r1 - b.r0), 0);
  for (int r = b.r0; r < b.r1; ++r)
    for (int c = b.c0; c < b.c1; ++c)
      s[std::size_t(along_x ? c - b.c0 : r - b.r0)] += L.count[std::size_t(c) + std::size_t(r) * std::size_t(L.cols)];
  return s;
}

void split(const Lattice& L, const CellBlock& b, int first_rank, int ranks, Decomposition& d) {
  if (ranks == 1) {
    d.block[std::size_t(first_rank)] = b;
    return;
  }
  const int low_ranks = ranks / 2, high_ranks = ranks - low_ranks;
  const int width = b.c1 - b.c0, height = b.r1 - b.r0;
  // Cuts k (slices on the low side) that leave each side at least a cell per rank.
  const auto cut_range = [&](bool along_x, int& k_min, int& k_max) {
    const long n = along_x ? width : height, across = along_x ? height : width;
    k_min = int((long(low_ranks) + across - 1) / across);
    k_max = int(n - (long(high_ranks) + across - 1) / across);
    return k_min <= k_max;
  };
  // The best cut across one axis: slices on the low side, how far its particles miss the
  // ranks' share (-1 when no cut leaves each side a cell per rank), and the particles in the
  // two slices beside it (contact).
  const auto best_cut = [&](bool along_x, double& miss, double& contact) {
    int k_min = 0, k_max = 0;
    miss = -1.0;
    contact = 0.0;
    if (!cut_range(along_x, k_min, k_max)) return 0;
    const std::vector<std::size_t> s = slices(L, b, along_x);
    const int n = int(s.size());
    const double total = double(std::accumulate(s.begin(), s.end(), std::size_t(0)));
    const double goal = total * double(low_ranks) / double(ranks);
    // Without particles, the cut that splits the cells in the ranks' proportion.
    int best = std::clamp(int(std::lround(double(n) * double(low_ranks) / double(ranks))), k_min, k_max);
    double prefix = 0.0;
    miss = total > 0.0 ? INFINITY : 0.0;
    for (int k = 1; k < n; ++k) {
      prefix += double(s[std::size_t(k - 1)]);
      if (k < k_min || k > k_max) continue;
      const double m = std::fabs(prefix - goal);
      if (m < miss) miss = m, best = k;  // the first of equal misses: deterministic
    }
    if (n > 1) contact = double(s[std::size_t(std::max(best - 1, 0))] + s[std::size_t(std::min(best, n - 1))]);
    return best;
  };
  // Of the axes whose cut comes within kSplitTolerance of a rank's share, across the one whose
  // cut has fewer particles beside it (the halo's work: on a uniform lattice, across the longer
  // side; with refinement, across a refined band rather than along it), the longer side on a
  // tie; if neither comes that close, the closer cut (x on a tie); the other axis when no cut
  // fits.
  double miss_x = -1.0, miss_y = -1.0, contact_x = 0.0, contact_y = 0.0;
  const int cut_x = best_cut(true, miss_x, contact_x);
  const int cut_y = best_cut(false, miss_y, contact_y);
  double total = 0.0;
  for (int r = b.r0; r < b.r1; ++r)
    for (int c = b.c0; c < b.c1; ++c) total += double(L.count[std::size_t(c) + std::size_t(r) * std::size_t(L.cols)]);
  const double tolerance = kSplitTolerance * total / double(ranks);
  const bool fits_x = miss_x >= 0.0, fits_y = miss_y >= 0.0;
  const bool near_x = fits_x && miss_x <= tolerance, near_y = fits_y && miss_y <= tolerance;
  bool along_x = fits_x && (!fits_y || miss_x <= miss_y);  // the closer cut
  if (near_x && near_y)
    along_x = contact_x < contact_y || (contact_x == contact_y && width >= height);
  else if (near_x || near_y)
    along_x = near_x;
  int best = along_x ? cut_x : cut_y;
  if ((along_x ? miss_x : miss_y) < 0.0) {  // no cut across the preferred axis fits
    along_x = !along_x;
    double miss = -1.0, contact = 0.0;
    best = best_cut(along_x, miss, contact);
    if (miss < 0.0)
      throw std::invalid_argument(fmt::format(
          "cannot split a block of {} x {} cells into {} blocks of whole cells", width, height, ranks));
  }
  CellBlock lo = b, hi = b;
  if (along_x)
    lo.c1 = hi.c0 = b.c0 + best;
  else
    lo.r1 = hi.r0 = b.r0 + best;
  split(L, lo, first_rank, low_ranks, d);
  split(L, hi, first_rank + low_ranks, ranks - low_ranks, d);
}

// Nodes of block a that are also nodes of block b (their node rectangles overlap).
long common_nodes(const CellBlock& a, const CellBlock& b) {
  const int x0 = std::max(a.c0, b.c0), x1 = std::min(a.c1, b.c1);
  const int y0 = std::max(a.r0, b.r0), y1 = std::min(a.r1, b.r1);
  if (x0 > x1 || y0 > y1) return 0;
  return long(x1 - x0 + 1) * long(y1 - y0 + 1);
}

}  // namespace

std::size_t Decomposition::total() const {
  return std::accumulate(particles.begin(), particles.end(), std::size_t(0));
}

double Decomposition::imbalance() const {
  if (particles.empty() || total() == 0) return 0.0;
  const double mean = double(total()) / double(particles.size());
  return double(*std::max_element(particles.begin(), particles.end())) / mean - 1.0;
}

Decomposition bisect_by_particles(const std::vector<std::uint32_t>& count, int cols, int rows,
                                  int ranks) {
  if (ranks < 1 || long(ranks) > long(cols) * long(rows))
    throw std::invalid_argument(fmt::format(
        "cannot split a lattice of {} x {} cells among {} ranks (1 to {} allowed)", cols, rows,
        ranks, long(cols) * long(rows)));
  if (count.size() != std::size_t(cols) * std::size_t(rows))
    throw std::invalid_argument("particle counts do not match the lattice");
  Decomposition d;
  d.block.resize(std::size_t(ranks));
  split(Lattice{count, cols, rows}, CellBlock{0, cols, 0, rows}, 0, ranks, d);
  return decomposition_of(std::move(d.block), count, cols);
}

Decomposition decomposition_of(std::vector<CellBlock> blocks, const std::vector<std::uint32_t>& count, int cols) {
  Decomposition d;
  d.block = std::move(blocks);
  const std::size_t ranks = d.block.size();
  d.particles.assign(std::size_t(ranks), 0);
  d.shared_nodes.assign(std::size_t(ranks), 0);
  for (std::size_t k = 0; k < d.block.size(); ++k) {
    const CellBlock& b = d.block[k];
    for (int r = b.r0; r < b.r1; ++r)
      for (int c = b.c0; c < b.c1; ++c)
        d.particles[k] += count[std::size_t(c) + std::size_t(r) * std::size_t(cols)];
  }
  // A node is shared when it lies in another block as well (on a cut or at a cut's corner).
  for (std::size_t k = 0; k < d.block.size(); ++k) {
    const CellBlock& b = d.block[k];
    if (b.cells() <= 0) continue;  // no cell (a nested level outside the block)
    std::vector<unsigned char> shared(std::size_t(b.c1 - b.c0 + 1) * std::size_t(b.r1 - b.r0 + 1), 0);
    for (std::size_t j = 0; j < d.block.size(); ++j) {
      if (j == k || d.block[j].cells() <= 0 || common_nodes(b, d.block[j]) == 0) continue;
      const CellBlock& o = d.block[j];
      for (int y = std::max(b.r0, o.r0); y <= std::min(b.r1, o.r1); ++y)
        for (int x = std::max(b.c0, o.c0); x <= std::min(b.c1, o.c1); ++x)
          shared[std::size_t(x - b.c0) + std::size_t(y - b.r0) * std::size_t(b.c1 - b.c0 + 1)] = 1;
    }
    d.shared_nodes[k] = long(std::count(shared.begin(), shared.end(), 1));
  }
  return d;
}

}  // namespace rupture
