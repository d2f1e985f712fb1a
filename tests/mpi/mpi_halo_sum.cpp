// rupture/tests/mpi/mpi_halo_sum.cpp
// halo_sum, halo_save and halo_sum_added (parallel/halo.hpp) under `mpirun -n N` (N = 1..4),
// and the node counts halo_sum records as a side effect (Halo::counts_here, read through
// counts_node). Why: every copy of a shared node must hold the same bits (the grid update
// and the gathers that follow rely on it, with no second exchange), and the node-counted sums
// (external work of prescribed and absorbing edges) must count each node once; a wrong
// order or a wrong count shows up only as round-off or a doubled work on several ranks, which
// no end-to-end run catches reliably.
// The grid's blocks (a layout of N blocks with nodes shared by 2, 3 and 4 ranks) are given to
// the ranks in every permutation (N! of them): the values each block's rank puts on its nodes
// depend on the block only (pseudo-random, magnitudes over 12 decades, a quarter of the
// masses exactly 0, field windows of different extents per block), so the permutations
// change only which rank holds which block. For each one every rank checks, bit for bit,
// against what it computes itself from the blocks:
//   - each node of its windows: the summed arrays are the holders' values added in increasing
//     RANK order starting from 0.0 (halo nodes), its own value elsewhere; arrays not passed
//     are untouched; the same value on every rank's copy (min = max over the ranks);
//   - counts_node(field, node) after the mass sum: true exactly where this rank is the lowest
//     rank whose reach holds the node and that gave it a non-zero mass, or the node is in no
//     other rank's reach; summed over the ranks, a node with mass anywhere is counted once;
//   - a halo_sum whose first array is not the mass leaves the counts as they were;
//   - halo_save + additions + halo_sum_added: saved + (each rank's (saved + a) - saved, in rank
//     order).
// It also checks the test can tell orders apart: on 3 or 4 ranks some sums differ, bit for
// bit, from the same terms added in reverse rank order, and the permutations' results
// agree with each other to round-off (the rank order changes the bits, not the value).
// Prints `halo_sum ok permutations=P nodes_checked=K order_sensitive=S` on rank 0 when all
// hold on every rank; exit 0 then, 1 otherwise.
#include <mpi.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <vector>

#include "input/case_toml.hpp"
#include "parallel/comm.hpp"
#include "parallel/halo.hpp"
#include "solver/state.hpp"

using namespace rupture;

namespace {

// A plate on a 20 x 10 cell grid (1 mm cells, 2 ghost cells each side: 24 x 14 cells,
// 25 x 15 nodes). Its particles play no part: the test writes the nodal arrays itself.
const char* kCase = R"(
title = "halo sum"
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
[grid]
min = [0.0, 0.0]
max = [0.02, 0.01]
cell_size = 1e-3
particles_per_cell = 1
margin = 0.0
[bodies.plate]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.01]
[time]
end = 1e-6
)";

constexpr int kFields = 3;
constexpr int kArrays = 5;  // mass, mom_x, mom_y, force_x, force_y
const NodalArray kArray[kArrays] = {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y,
                                    &GridFields::force_x, &GridFields::force_y};

// The blocks of cells for N ranks (they tile the 24 x 14 cells): 2 ranks side by side; 3 with
// a T junction (3 reaches meet); 4 in a 2 x 2 pattern with an off-centre cut (4 meet).
std::vector<CellBlock> layout(int n) {
  switch (n) {
    case 1: return {{0, 24, 0, 14}};
    case 2: return {{0, 11, 0, 14}, {11, 24, 0, 14}};
    case 3: return {{0, 12, 0, 14}, {12, 24, 0, 6}, {12, 24, 6, 14}};
    case 4: return {{0, 10, 0, 8}, {10, 24, 0, 8}, {0, 13, 8, 14}, {13, 24, 8, 14}};
    default: return {};
  }
}

// A block's reach, computed here (not with reach_box): its nodes and kHaloNodes more on every
// side, clipped to the grid.
NodeBox reach_of(const CellBlock& b, int nx, int ny) {
  return NodeBox{std::max(0, b.c0 - kHaloNodes), std::min(nx - 1, b.c1 + kHaloNodes),
                 std::max(0, b.r0 - kHaloNodes), std::min(ny - 1, b.r1 + kHaloNodes)};
}

// Field f's window on the rank holding block `slot` (inside its reach, different per slot
// and field, so some shared nodes are in one rank's window and not the other's).
NodeBox window_of(int slot, int f, const NodeBox& r) {
  NodeBox w = r;
  if (f == 1) {
    if (slot % 2 == 1) w.i0 += 1;
    if (slot % 2 == 0) w.j1 -= 2;
  } else if (f == 2) {
    w.i1 = std::clamp((w.i0 + w.i1) / 2 + slot, w.i0, w.i1);  // the left part
    w.j0 = std::min(w.j1, w.j0 + 1);
  }
  return w;
}

std::uint64_t mix(std::uint64_t z) {  // splitmix64
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
double unit(std::uint64_t& state) { return double((state = mix(state)) >> 11) * 0x1.0p-53; }

// What the rank holding block `slot` puts on node (i, j) of field f, array a (salt: 0 for the
// scatter, 1 for the additions before halo_sum_added); 0 outside its window.
double value(int slot, int f, int a, int i, int j, int salt, const NodeBox& window) {
  if (!window.contains(i, j)) return 0.0;
  std::uint64_t st = (std::uint64_t(slot) << 48) ^ (std::uint64_t(f) << 40) ^ (std::uint64_t(a) << 32) ^
                     (std::uint64_t(i) << 16) ^ std::uint64_t(j) ^ (std::uint64_t(salt) << 56);
  const double u0 = unit(st), u1 = unit(st), u2 = unit(st), u3 = unit(st);
  const double magnitude = (0.5 + u1) * std::pow(10.0, std::floor(u2 * 12.0) - 6.0);
  if (a == 0) return salt == 0 && u0 < 0.25 ? 0.0 : magnitude;  // masses: a quarter exactly 0
  return u3 < 0.5 ? -magnitude : magnitude;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const Comm world = Comm::world();
  const int n = world.size(), me = world.rank();
  const std::vector<CellBlock> slots = layout(n);
  if (slots.empty()) {
    if (me == 0) fmt::print("mpi_halo_sum: runs on 1 to 4 ranks, not {}\n", n);
    MPI_Finalize();
    return 1;
  }
  State s = make_state(parse_case(kCase));
  const int nx = s.grid.nodes_x(), ny = s.grid.nodes_y();
  if (s.grid.x.cells != 24 || s.grid.y.cells != 14) {
    if (me == 0) fmt::print("mpi_halo_sum: grid of {} x {} cells, expected 24 x 14\n", s.grid.x.cells, s.grid.y.cells);
    MPI_Finalize();
    return 1;
  }
  attach_halo(s, world);
  long bad = 0, checked = 0, order_sensitive = 0, permutations = 0;
  const auto report = [&](const std::string& what) {
    if (bad < 20) fmt::print("rank {}: {}\n", me, what);
    ++bad;
  };
  std::vector<int> perm(static_cast<std::size_t>(n));
  std::iota(perm.begin(), perm.end(), 0);
  // Per permutation, every node's summed arrays (field-major, whole grid) on this rank's
  // copies, to compare the permutations (NaN where this rank holds no copy).
  const std::size_t whole = std::size_t(kFields) * std::size_t(nx) * std::size_t(ny);
  std::vector<std::vector<double>> results;
  do {
    ++permutations;
    std::vector<CellBlock> blocks(static_cast<std::size_t>(n));
    for (int r = 0; r < n; ++r) blocks[std::size_t(r)] = slots[std::size_t(perm[std::size_t(r)])];
    set_blocks(s, blocks);
    const Halo& h = halo_of(s);
    std::vector<NodeBox> reach(static_cast<std::size_t>(n));
    for (int r = 0; r < n; ++r) reach[std::size_t(r)] = reach_of(blocks[std::size_t(r)], nx, ny);
    const NodeBox& mine = reach[std::size_t(me)];
    if (h.reach.i0 != mine.i0 || h.reach.i1 != mine.i1 || h.reach.j0 != mine.j0 || h.reach.j1 != mine.j1)
      report(fmt::format("reach [{}, {}] x [{}, {}], expected [{}, {}] x [{}, {}]", h.reach.i0, h.reach.i1,
                         h.reach.j0, h.reach.j1, mine.i0, mine.i1, mine.j0, mine.j1));
    const auto window = [&](int r, int f) { return window_of(perm[std::size_t(r)], f, reach[std::size_t(r)]); };
    // Each rank's value (by rank r: the block it holds now).
    const auto v = [&](int r, int f, int a, int i, int j, int salt) {
      return value(perm[std::size_t(r)], f, a, i, j, salt, window(r, f));
    };
    const auto shared = [&](int i, int j) {
      for (int r = 0; r < n; ++r)
        if (r != me && reach[std::size_t(r)].contains(i, j)) return true;
      return false;
    };
    // The sum in rank order from 0.0, as every copy must hold it (or the reverse order).
    const auto rank_sum = [&](int f, int a, int i, int j, bool reverse) {
      double sum = 0.0;
      for (int k = 0; k < n; ++k) {
        const int r = reverse ? n - 1 - k : k;
        if (reach[std::size_t(r)].contains(i, j)) sum += v(r, f, a, i, j, 0);
      }
      return sum;
    };
    // This rank's windows and values.
    std::vector<int> c0, nc, r0, nr;
    for (int f = 0; f < kFields; ++f) {
      const NodeBox w = window(me, f);
      c0.push_back(w.i0), nc.push_back(w.i1 - w.i0 + 1), r0.push_back(w.j0), nr.push_back(w.j1 - w.j0 + 1);
    }
    GridFields& G = s.fields;
    G.set_windows(std::size_t(nx), std::size_t(ny), c0, nc, r0, nr);
    const auto each_held = [&](auto&& body) {
      for (int f = 0; f < kFields; ++f)
        for (int j = 0; j < ny; ++j)
          for (int i = 0; i < nx; ++i)
            if (G.holds(f, i, j)) body(f, i, j, G.index(f, i, j));
    };
    each_held([&](int f, int i, int j, std::size_t e) {
      for (int a = 0; a < kArrays; ++a) (G.*kArray[a])[e] = v(me, f, a, i, j, 0);
    });

    // 1. Mass and momentum: summed in rank order; the forces untouched.
    halo_sum(s, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y});
    // (Comm has an element-wise max only: the smallest is minus the largest of the negated.)
    std::vector<double> copy_neg_min(whole * 3, -INFINITY), copy_max(whole * 3, -INFINITY);
    std::vector<double> result(whole, std::numeric_limits<double>::quiet_NaN());
    each_held([&](int f, int i, int j, std::size_t e) {
      const bool halo = shared(i, j);
      for (int a = 0; a < kArrays; ++a) {
        const double got = (G.*kArray[a])[e];
        const double want = a < 3 && halo ? rank_sum(f, a, i, j, false) : v(me, f, a, i, j, 0);
        ++checked;
        if (!same_bits(got, want))
          report(fmt::format("field {} node ({}, {}) array {}: {:.17g}, expected {:.17g} ({})", f, i, j, a, got,
                             want, a < 3 ? "rank-order sum" : "not summed"));
        if (a < 3 && halo && n >= 3 && !same_bits(want, rank_sum(f, a, i, j, true))) ++order_sensitive;
        if (a < 3) {
          const std::size_t k = (std::size_t(a) * std::size_t(kFields) + std::size_t(f)) * std::size_t(nx * ny) +
                                std::size_t(j) * std::size_t(nx) + std::size_t(i);
          copy_neg_min[k] = std::max(copy_neg_min[k], -got), copy_max[k] = std::max(copy_max[k], got);
        }
      }
      result[(std::size_t(f) * std::size_t(ny) + std::size_t(j)) * std::size_t(nx) + std::size_t(i)] = G.mass[e];
    });
    results.push_back(result);
    // Every copy the same value: the smallest and largest over the ranks agree.
    world.max(copy_neg_min.data(), int(copy_neg_min.size()));
    world.max(copy_max.data(), int(copy_max.size()));
    for (std::size_t k = 0; k < copy_max.size(); ++k)
      if (copy_max[k] != -INFINITY && -copy_neg_min[k] != copy_max[k])
        report(fmt::format("entry {}: copies differ over the ranks ({:.17g} .. {:.17g})", k, -copy_neg_min[k],
                           copy_max[k]));

    // 2. The counts recorded by that mass sum.
    std::vector<double> counted(std::size_t(kFields) * std::size_t(nx * ny), 0.0), gave(counted.size(), 0.0);
    std::vector<unsigned char> counts_after_mass(counted.size(), 0);
    for (int f = 0; f < kFields; ++f)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const std::size_t node = std::size_t(j) * std::size_t(nx) + std::size_t(i);
          const std::size_t k = std::size_t(f) * std::size_t(nx * ny) + node;
          bool want = false;
          if (mine.contains(i, j)) {
            if (!shared(i, j)) {
              want = true;
            } else {
              int lowest = -1;
              for (int r = 0; r < n && lowest < 0; ++r)
                if (reach[std::size_t(r)].contains(i, j) && v(r, f, 0, i, j, 0) != 0.0) lowest = r;
              want = lowest == me;
            }
          }
          const bool got = counts_node(s, f, node);
          counts_after_mass[k] = got;
          if (got != want)
            report(fmt::format("counts_node(field {}, node ({}, {})) = {}, expected {}", f, i, j, got, want));
          counted[k] = got ? 1.0 : 0.0;
          if (mine.contains(i, j) && v(me, f, 0, i, j, 0) != 0.0) gave[k] = 1.0;
        }
    world.sum(counted.data(), int(counted.size()));
    world.sum(gave.data(), int(gave.size()));
    for (std::size_t k = 0; k < counted.size(); ++k)
      if (gave[k] > 0.0 && counted[k] != 1.0)
        report(fmt::format("entry {} (mass from {} ranks) counted by {} ranks", k, gave[k], counted[k]));

    // 3. The forces: summed in rank order, the counts left as the mass sum recorded them.
    halo_sum(s, {&GridFields::force_x, &GridFields::force_y});
    each_held([&](int f, int i, int j, std::size_t e) {
      for (int a = 3; a < kArrays; ++a) {
        const double want = shared(i, j) ? rank_sum(f, a, i, j, false) : v(me, f, a, i, j, 0);
        ++checked;
        if (!same_bits((G.*kArray[a])[e], want))
          report(fmt::format("field {} node ({}, {}) array {}: {:.17g}, expected {:.17g}", f, i, j, a,
                             (G.*kArray[a])[e], want));
      }
    });
    for (int f = 0; f < kFields; ++f)
      for (std::size_t node = 0; node < std::size_t(nx * ny); ++node)
        if (counts_node(s, f, node) != bool(counts_after_mass[std::size_t(f) * std::size_t(nx * ny) + node]))
          report(fmt::format("counts_node(field {}, node {}) changed by a sum without the mass", f, node));

    // 4. halo_save, each rank adds to its copies, halo_sum_added.
    halo_save(s, {&GridFields::force_x, &GridFields::force_y});
    std::vector<double> saved(G.size() * 2);
    each_held([&](int, int, int, std::size_t e) { saved[2 * e] = G.force_x[e], saved[2 * e + 1] = G.force_y[e]; });
    each_held([&](int f, int i, int j, std::size_t e) {
      G.force_x[e] += v(me, f, 3, i, j, 1);
      G.force_y[e] += v(me, f, 4, i, j, 1);
    });
    halo_sum_added(s, {&GridFields::force_x, &GridFields::force_y});
    each_held([&](int f, int i, int j, std::size_t e) {
      for (int a = 3; a < kArrays; ++a) {
        const double S = saved[2 * e + std::size_t(a - 3)];  // the summed value: alike on every copy
        double want = S + v(me, f, a, i, j, 1);
        if (shared(i, j)) {
          double sum = 0.0;
          for (int r = 0; r < n; ++r)
            if (reach[std::size_t(r)].contains(i, j) && window(r, f).contains(i, j))
              sum += (S + v(r, f, a, i, j, 1)) - S;  // what rank r added, as it measures it
          want = S + sum;
        }
        ++checked;
        if (!same_bits((G.*kArray[a])[e], want))
          report(fmt::format("halo_sum_added: field {} node ({}, {}) array {}: {:.17g}, expected {:.17g}", f, i, j,
                             a, (G.*kArray[a])[e], want));
      }
    });
  } while (std::next_permutation(perm.begin(), perm.end()));

  // The permutations agree to round-off: the same terms, another order (each mass sum has at
  // most 4 positive terms: a few ulps).
  for (std::size_t p = 1; p < results.size(); ++p)
    for (std::size_t k = 0; k < whole; ++k) {
      const double a = results[0][k], b = results[p][k];
      if (std::isnan(a) || std::isnan(b)) continue;  // a copy in one permutation only
      if (std::fabs(a - b) > 8.0 * std::numeric_limits<double>::epsilon() * std::fabs(a))
        report(fmt::format("permutation {}: mass entry {} = {:.17g}, permutation 0: {:.17g}", p, k, b, a));
    }
  bad = world.sum(bad);
  checked = world.sum(checked);
  order_sensitive = world.sum(order_sensitive);
  if (n >= 3 && order_sensitive == 0) {
    if (me == 0) fmt::print("no sum depends on the order of its terms: the test cannot tell orders apart\n");
    ++bad;
  }
  if (me == 0 && bad == 0)
    fmt::print("halo_sum ok permutations={} nodes_checked={} order_sensitive={}\n", permutations, checked,
               order_sensitive);
  if (me == 0 && bad != 0) fmt::print("halo_sum FAILED: {} problems\n", bad);
  MPI_Finalize();
  return bad == 0 ? 0 : 1;
}
