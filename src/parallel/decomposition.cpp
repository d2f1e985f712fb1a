// rupture/parallel/decomposition.cpp
#include "parallel/decomposition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <stdexcept>

namespace rupture {
namespace {

// The particles in a block's slices (double: sums of whole counts, exact below 2^53).
using Slices = std::function<std::vector<double>(const CellBlock&, bool along_x)>;

// Particles in the block's slices along one axis, per column (along_x) or per row, from a
// lattice count.
std::vector<double> lattice_slices(const std::vector<std::uint32_t>& count, int cols, const CellBlock& b,
                                   bool along_x) {
  std::vector<double> s(std::size_t(along_x ? b.c1 - b.c0 : b.r1 - b.r0), 0.0);
  for (int r = b.r0; r < b.r1; ++r)
    for (int c = b.c0; c < b.c1; ++c)
      s[std::size_t(along_x ? c - b.c0 : r - b.r0)] += double(count[std::size_t(c) + std::size_t(r) * std::size_t(cols)]);
  return s;
}

// Splits block b (holding `total` particles) among ranks [first_rank, first_rank + ranks).
void split(const Slices& slices, const CellBlock& b, double total, int first_rank, int ranks, Decomposition& d) {
  if (ranks == 1) {
    d.block[std::size_t(first_rank)] = b;
    d.particles[std::size_t(first_rank)] = std::size_t(total);
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
  // The slices across both axes (every rank of a distributed bisection asks for the same ones
  // in the same order: bisect_over_ranks sums them over the ranks).
  const std::vector<double> slices_x = slices(b, true), slices_y = slices(b, false);
  double low_total = 0.0;  // the particles on the low side of the chosen cut
  const auto best_cut = [&](bool along_x, double& miss, double& contact) {
    int k_min = 0, k_max = 0;
    miss = -1.0;
    contact = 0.0;
    if (!cut_range(along_x, k_min, k_max)) return 0;
    const std::vector<double>& s = along_x ? slices_x : slices_y;
    const int n = int(s.size());
    const double goal = total * double(low_ranks) / double(ranks);
    // Without particles, the cut that splits the cells in the ranks' proportion.
    int best = std::clamp(int(std::lround(double(n) * double(low_ranks) / double(ranks))), k_min, k_max);
    double prefix = 0.0;
    miss = total > 0.0 ? INFINITY : 0.0;
    for (int k = 1; k < n; ++k) {
      prefix += s[std::size_t(k - 1)];
      if (k < k_min || k > k_max) continue;
      const double m = std::fabs(prefix - goal);
      if (m < miss) miss = m, best = k;  // the first of equal misses: deterministic
    }
    if (n > 1) contact = s[std::size_t(std::max(best - 1, 0))] + s[std::size_t(std::min(best, n - 1))];
    return best;
  };
  // The particles in slices [0, k) across one axis.
  const auto below = [&](bool along_x, int k) {
    const std::vector<double>& s = along_x ? slices_x : slices_y;
    double sum = 0.0;
    for (int i = 0; i < k; ++i) sum += s[std::size_t(i)];
    return sum;
  };
  // Of the axes whose cut comes within kSplitTolerance of a rank's share, across the one whose
  // cut has fewer particles beside it (the halo's work: on a uniform lattice, across the longer
  // side; with refinement, across a refined band rather than along it), the longer side on a
  // tie; if neither comes that close, the closer cut (x on a tie); the other axis when no cut
  // fits.
  double miss_x = -1.0, miss_y = -1.0, contact_x = 0.0, contact_y = 0.0;
  const int cut_x = best_cut(true, miss_x, contact_x);
  const int cut_y = best_cut(false, miss_y, contact_y);
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
  low_total = below(along_x, best);
  split(slices, lo, low_total, first_rank, low_ranks, d);
  split(slices, hi, total - low_total, first_rank + low_ranks, ranks - low_ranks, d);
}

// Fills d.shared_nodes from d.block.
void count_shared_nodes(Decomposition& d);

// Nodes of block a that are also nodes of block b (their node rectangles overlap).
long common_nodes(const CellBlock& a, const CellBlock& b) {
  const int x0 = std::max(a.c0, b.c0), x1 = std::min(a.c1, b.c1);
  const int y0 = std::max(a.r0, b.r0), y1 = std::min(a.r1, b.r1);
  if (x0 > x1 || y0 > y1) return 0;
  return long(x1 - x0 + 1) * long(y1 - y0 + 1);
}

// A node is shared when it lies in another block as well (on a cut or at a cut's corner).
void count_shared_nodes(Decomposition& d) {
  d.shared_nodes.assign(d.block.size(), 0);
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

namespace {

Decomposition bisect(const Slices& slices, int cols, int rows, int ranks) {
  if (ranks < 1 || long(ranks) > long(cols) * long(rows))
    throw std::invalid_argument(fmt::format(
        "cannot split a lattice of {} x {} cells among {} ranks (1 to {} allowed)", cols, rows,
        ranks, long(cols) * long(rows)));
  Decomposition d;
  d.block.resize(std::size_t(ranks));
  d.particles.assign(std::size_t(ranks), 0);
  const CellBlock all{0, cols, 0, rows};
  double total = 0.0;
  for (const double v : slices(all, true)) total += v;
  split(slices, all, total, 0, ranks, d);
  count_shared_nodes(d);
  return d;
}

}  // namespace

Decomposition bisect_by_particles(const std::vector<std::uint32_t>& count, int cols, int rows,
                                  int ranks) {
  if (count.size() != std::size_t(cols) * std::size_t(rows))
    throw std::invalid_argument("particle counts do not match the lattice");
  return bisect([&](const CellBlock& b, bool along_x) { return lattice_slices(count, cols, b, along_x); },
                cols, rows, ranks);
}

Decomposition bisect_over_ranks(const std::vector<CellCount>& mine, int cols, int rows, int ranks,
                                const std::function<void(double*, int)>& sum_over_ranks) {
  return bisect(
      [&](const CellBlock& b, bool along_x) {
        std::vector<double> s(std::size_t(along_x ? b.c1 - b.c0 : b.r1 - b.r0), 0.0);
        for (const CellCount& e : mine)
          if (e.c >= b.c0 && e.c < b.c1 && e.r >= b.r0 && e.r < b.r1)
            s[std::size_t(along_x ? e.c - b.c0 : e.r - b.r0)] += double(e.count);
        sum_over_ranks(s.data(), int(s.size()));
        return s;
      },
      cols, rows, ranks);
}

std::vector<CellCount> cell_counts(std::vector<std::pair<long, double>> amounts, int cols) {
  std::sort(amounts.begin(), amounts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<CellCount> out;
  for (std::size_t k = 0; k < amounts.size();) {
    const long cell = amounts[k].first;
    double sum = 0.0;
    for (; k < amounts.size() && amounts[k].first == cell; ++k) sum += amounts[k].second;
    out.push_back({int(cell % cols), int(cell / cols), std::uint32_t(std::lround(sum))});
  }
  return out;
}

BlockLocator::BlockLocator(const std::vector<CellBlock>& blocks, int rows) : row_(std::size_t(std::max(rows, 0))) {
  for (std::size_t q = 0; q < blocks.size(); ++q)
    for (int r = std::max(blocks[q].r0, 0); r < std::min(blocks[q].r1, rows); ++r)
      if (blocks[q].c1 > blocks[q].c0) row_[std::size_t(r)].push_back({blocks[q].c0, blocks[q].c1, int(q)});
  for (auto& spans : row_)
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.c0 < b.c0; });
}

int BlockLocator::owner(int c, int r) const {
  if (r < 0 || r >= int(row_.size())) return -1;
  const std::vector<Span>& spans = row_[std::size_t(r)];
  auto it = std::upper_bound(spans.begin(), spans.end(), c, [](int v, const Span& s) { return v < s.c0; });
  if (it == spans.begin()) return -1;
  --it;
  return c < it->c1 ? it->rank : -1;
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
  count_shared_nodes(d);
  return d;
}

}  // namespace rupture
