// rupture/solver/particle_sort.cpp
// Keeping particles sorted by strips for the race-free scatter (ScatterPlan, solver/state.hpp),
// and the GIMP contract check on graded grids done at every re-sort.
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/errors.hpp"
#include "core/fault_injection.hpp"
#include "solver/rank_exchange.hpp"
#include "solver/stencil_batch.hpp"
#include "solver/transfer.hpp"

namespace rupture {
using namespace detail;
namespace {

// The GIMP contract of grid/grid.hpp (count_stencil_overflows), checked at every re-sort on a
// graded grid: a particle breaking it would silently lose a node of its weights.
// Distributed: the rank goes on with the step (the lost node costs accuracy, never memory) and
// every rank stops at its end (parallel/halo.hpp fail_in_step).
void check_gimp_contract(State& s) {
  if (!s.grid.graded()) return;
  const Particles& P = s.particles;
  const Axis* axes[2] = {&s.grid.x, &s.grid.y};
  const double* pos[2] = {P.x.data(), P.y.data()};
  const double* half[2] = {P.half_x.data(), P.half_y.data()};
  for (int d = 0; d < 2; ++d) {
    const Axis& a = *axes[d];
    const bool injected = d == 0 && P.size() > 0 && fault_due(FaultSite::gimp_contract, s.step);  // tests
    if (!injected && count_stencil_overflows(a, pos[d], half[d], P.size()) == 0) continue;
    std::size_t p = 0;
    while (p < P.size() && !stencil_overflows(a, pos[d][p], half[d][p])) ++p;
    if (p == P.size() && injected) p = 0;
    if (p == P.size()) continue;  // cannot happen: both tests share their arithmetic
    const double lp = half[d][p], lo = pos[d][p] - lp, hi = pos[d][p] + lp;
    int cell = a.cell_of(lo) + 1;  // the narrowest cell wholly inside the box
    for (int c = cell; c + 1 <= a.cells && a.node(c + 1) <= hi; ++c)
      if (a.width(c) < a.width(cell)) cell = c;
    const char* name = d == 0 ? "x" : "y";
    const int col = d == 0 ? cell : s.grid.x.cell_of(P.x[p]);
    const int row = d == 1 ? cell : s.grid.y.cell_of(P.y[p]);
    fail_in_step(s, fmt::format(
        "GIMP contract broken at step {}, t = {:.6g} s: particle {} (field {}) at (x, y) = "
        "({:.6g}, {:.6g}) m with half-widths (l_x, l_y) = ({:.4g}, {:.4g}) m spans, along {}, "
        "[{:.6g}, {:.6g}] m, which holds cell (column {}, row {}) of width {:.4g} m whole: its "
        "3-node stencil (docs/theory.md E3) loses a node: the box may overlap at most two cells, so 2 l_p "
        "must not exceed the width of a cell it reaches. A particle keeps the size of the cell "
        "it was made in (l_p = a quarter of it at 2 x 2 per cell), so this one came from cells "
        "more than twice as wide. Move the refinement-box transition further from moving "
        "material (larger [grid.refine] boxes, so that material stays in cells at most 2x "
        "finer than where it started), or refine where it starts as well",
        s.step, s.time, P.id[p], int(P.field[p]), P.x[p], P.y[p], P.half_x[p], P.half_y[p], name,
        lo, hi, col, row, a.width(cell)));
  }
}

// Per strip and field, the lowest and highest first stencil row of the particles just sorted
// (ScatterPlan::row_lo, row_hi; their keys, by the particles' previous index, hold the row).
void strip_rows(State& s, const std::uint32_t* key, int cy, std::size_t stencil_cols) {
  ScatterPlan& plan = s.plan;
  const Particles& P = s.particles;
  const std::size_t fields = std::size_t(s.fields.num_fields);
  plan.row_lo.assign(std::size_t(plan.num_strips) * fields, std::numeric_limits<int>::max());
  plan.row_hi.assign(std::size_t(plan.num_strips) * fields, std::numeric_limits<int>::min());
  int* const lo = plan.row_lo.data();
  int* const hi = plan.row_hi.data();
  const std::uint32_t* const order = plan.order.data();
  const std::size_t* const begin = plan.strip_begin.data();
#pragma omp parallel for schedule(static)
  for (int k = 0; k < plan.num_strips; ++k) {  // each strip writes its own entries
    for (std::size_t p = begin[k]; p < begin[k + 1]; ++p) {
      const int row = int((key[order[p]] / stencil_cols) % std::uint64_t(cy));
      const std::size_t e = std::size_t(k) * fields + P.field[p];
      lo[e] = std::min(lo[e], row);
      hi[e] = std::max(hi[e], row);
    }
  }
  plan.drift = 0.0;
  plan.row_height = s.grid.y.graded() ? s.grid.y.min_width() : s.grid.y.h;
  plan.rows_known = true;
}

}  // namespace

void sort_particles(State& s) {
  check_gimp_contract(s);
  ScatterPlan& plan = s.plan;
  Particles& P = s.particles;
  const std::size_t n = P.size();
  const int cx = s.grid.x.cells, cy = s.grid.y.cells, width = plan.strip_cells;
  plan.num_strips = (cx + width - 1) / width;
  // Bucket (strip, stencil row, stencil column): strip-major, so every strip is one contiguous
  // particle range; inside a strip, the particles whose 3 x 3 stencils start at the same node
  // (theory E3: grid/grid.hpp stencil_first; about four at 2 x 2 per cell) are adjacent, and the
  // transfers handle such a run with one read of its nine tile nodes (solver/transfer.cpp).
  // The strip is the cell column's; its stencils start at columns strip * width - 1 .. + width.
  const std::size_t stencil_cols = std::size_t(width) + 2;
  auto bucket_of = [&](std::size_t p) {
    const int strip = std::clamp(s.grid.x.cell_of(P.x[p]), 0, cx - 1) / width;
    const int row = std::clamp(stencil_first(s.grid.y, P.y[p], P.half_y[p]), 0, cy - 1);
    const int col = std::clamp(stencil_first(s.grid.x, P.x[p], P.half_x[p]) - strip * width + 1, 0,
                               int(stencil_cols) - 1);
    return (std::size_t(strip) * std::size_t(cy) + std::size_t(row)) * stencil_cols + std::size_t(col);
  };
  // Each particle's bucket once, split over the threads (the cell lookups are most of the
  // sort's work); the counting passes below stay serial, so the order is the same.
  // The lattice-wide key (strip, row, column) of every particle in 4 bytes (the sort's
  // memory is per particle): lattices up to 2^32 of them, about 4e9 cells.
  if (double(plan.num_strips) * double(cy) * double(stencil_cols) >= 4294967296.0)
    throw SimulationError(fmt::format(
        "the grid's {} x {} cells are more than the particle sort can number (2^32 buckets of "
        "a strip, a row and a stencil column); use a coarser grid.cell_size or nested levels",
        cx, cy));
  thread_local std::vector<std::uint32_t> key;  // the calling thread's: reached by pointer
  key.resize(n);
  std::uint32_t* const k_of = key.data();
  int strip_lo = std::numeric_limits<int>::max(), strip_hi = -1, row_lo = std::numeric_limits<int>::max(), row_hi = -1;
#pragma omp parallel for schedule(static) reduction(min : strip_lo, row_lo) reduction(max : strip_hi, row_hi)
  for (long p = 0; p < long(n); ++p) {
    const std::uint32_t k = std::uint32_t(bucket_of(std::size_t(p)));
    k_of[p] = k;
    const int strip = int(k / (std::uint64_t(cy) * stencil_cols)), row = int((k / stencil_cols) % std::uint64_t(cy));
    strip_lo = std::min(strip_lo, strip), strip_hi = std::max(strip_hi, strip);
    row_lo = std::min(row_lo, row), row_hi = std::max(row_hi, row);
  }
  // Buckets for the strips and rows the particles occupy only (a rank of a distributed run
  // holds a block, never counts over the whole lattice); the order is the lattice-wide one.
  const std::uint64_t rows = n > 0 ? std::uint64_t(row_hi - row_lo + 1) : 0;
  const auto relative = [&](std::uint64_t k) {
    const std::uint64_t strip = k / (std::uint64_t(cy) * stencil_cols), row = (k / stencil_cols) % std::uint64_t(cy);
    return ((strip - std::uint64_t(strip_lo)) * rows + (row - std::uint64_t(row_lo))) * stencil_cols + k % stencil_cols;
  };
  const std::size_t buckets = n > 0 ? std::size_t(strip_hi - strip_lo + 1) * std::size_t(rows) * stencil_cols : 0;
  plan.bucket.assign(buckets + 1, 0);
  for (std::size_t p = 0; p < n; ++p) ++plan.bucket[relative(k_of[p]) + 1];
  for (std::size_t k = 0; k < buckets; ++k) plan.bucket[k + 1] += plan.bucket[k];
  plan.strip_begin.resize(std::size_t(plan.num_strips) + 1);
  for (int k = 0; k <= plan.num_strips; ++k)
    plan.strip_begin[std::size_t(k)] =
        n == 0 || k <= strip_lo ? 0
        : k > strip_hi          ? n
                                : plan.bucket[std::size_t(k - strip_lo) * std::size_t(rows) * stencil_cols];
  // Stable counting sort: particles keep their previous relative order inside a bucket.
  plan.order.resize(n);
  for (std::size_t p = 0; p < n; ++p) plan.order[plan.bucket[relative(k_of[p])]++] = std::uint32_t(p);
  P.permute(plan.order, plan.scratch);
  strip_rows(s, k_of, cy, stencil_cols);
  plan.valid = true;
  plan.sorted_step = s.step;
}

void build_scatter_plan(State& s) {
  const ScatterPlan& plan = s.plan;
  // Every sort_interval steps on a graded grid (the re-sort checks the GIMP contract there);
  // on a uniform lattice only once a particle may also have moved half a cell since (the
  // order then still holds the runs of shared stencils and the strip tiles' rows, and a sort
  // costs about 35 particle-updates' time per particle: docs/performance.md, "Choices in the
  // code"). A drift out of the strip's tolerance re-sorts
  // at once (valid false).
  const bool due = s.step - plan.sorted_step >= plan.sort_interval;
  const bool moved = plan.drift >= 0.5 * std::min(s.grid.x.h, s.grid.y.h);  // checkpointed
  if (!plan.valid || (due && (moved || s.grid.graded()))) sort_particles(s);
}

}  // namespace rupture
