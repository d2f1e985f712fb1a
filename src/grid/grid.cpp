// rupture/grid/grid.cpp
#include "grid/grid.hpp"

#include <algorithm>
#include <cassert>
#include <array>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace rupture {

int ghost_cells(double margin, double w) {
  return 2 + (margin > 0.0 ? int(std::ceil(margin / w - 1e-9)) : 0);
}

Grid make_uniform_grid(const double min[2], const double max[2], double h, double margin) {
  Grid g;
  g.ghost = ghost_cells(margin, h);
  const char* names[2] = {"x", "y"};
  Axis* axes[2] = {&g.x, &g.y};
  for (int d = 0; d < 2; ++d) {
    const double extent = max[d] - min[d];
    const double n = extent / h;
    const long cells = std::lround(n);
    if (cells < 1 || std::fabs(n - double(cells)) > 1e-6 * std::max(1.0, n)) {
      throw InputError(fmt::format(
          "grid.cell_size = {:g}: the domain extent along {} ({:g} m) must be a whole number "
          "(>= 1) of cells; {:g} cells does not qualify",
          h, names[d], extent, n));
    }
    axes[d]->h = h;
    axes[d]->cells = int(cells) + 2 * g.ghost;
    axes[d]->origin = min[d] - g.ghost * h;
    g.domain_min[d] = min[d];
    g.domain_max[d] = max[d];
  }
  return g;
}

double Axis::min_width() const {
  if (!graded()) return h;
  double w = INFINITY;
  for (int c = 0; c < cells; ++c) w = std::min(w, width(c));
  return w;
}

namespace {

// Round-off allowance of the contract test: a box that reaches x_{first+2} within it puts a
// weight of order (1e-9)^2 on a fourth node.
constexpr double kContractTolerance = 1e-9;

}  // namespace

bool stencil_overflows(const Axis& a, double x, double lp) {
  if (!a.graded()) return false;
  const int last = std::min(a.cell_of(x - lp) + 2, a.cells);  // no node beyond the last
  return x + lp > a.node(last) + kContractTolerance * a.h;
}

std::size_t count_stencil_overflows(const Axis& a, const double* x, const double* lp, std::size_t n) {
  if (!a.graded()) return 0;
  // cell_of and node written out over plain arrays, so the loop vectorizes (gathers); the same
  // arithmetic as cell_of, so the count agrees with stencil_overflows to the last bit.
  const double origin = a.origin, h = a.h, tol = kContractTolerance * a.h;
  const double last_unit = double(a.cell_of_unit.size()) - 1.0;
  const int* cell_of_unit = a.cell_of_unit.data();
  const double* coord = a.coord.data();
  const int cells = a.cells;
  std::size_t count = 0;
#pragma omp parallel for simd reduction(+ : count)
  for (std::size_t p = 0; p < n; ++p) {
    const double u = std::clamp(std::floor((x[p] - lp[p] - origin) / h), 0.0, last_unit);
    const int last = std::min(cell_of_unit[std::size_t(u)] + 2, cells);
    count += x[p] + lp[p] > coord[last] + tol ? 1 : 0;
  }
  return count;
}

namespace {

// Cell widths of one graded axis, in units of the finest size (powers of two).
std::vector<long> graded_widths(long units, long coarse, const std::vector<std::array<long, 3>>& boxes) {
  // Size asked for at every unit: the smallest box size covering it, coarse elsewhere.
  std::vector<long> want(std::size_t(units), coarse);
  for (const auto& b : boxes)
    for (long k = std::max(0L, b[0]); k < std::min(units, b[1]); ++k)
      want[std::size_t(k)] = std::min(want[std::size_t(k)], b[2]);
  // Greedy: the largest power-of-two cell aligned to its own size that no finer wish
  // overlaps.
  std::vector<long> w;
  for (long k = 0; k < units;) {
    long size = coarse;
    while (size > 1) {
      bool ok = k % size == 0 && k + size <= units;
      for (long u = k; ok && u < k + size; ++u) ok = want[std::size_t(u)] >= size;
      if (ok) break;
      size /= 2;
    }
    w.push_back(size);
    k += size;
  }
  // Grade: split any cell more than twice as wide as a neighbour (halves stay aligned).
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<long> next;
    for (std::size_t i = 0; i < w.size(); ++i) {
      const long left = i > 0 ? w[i - 1] : w[i], right = i + 1 < w.size() ? w[i + 1] : w[i];
      if (w[i] > 2 * std::min(left, right)) {
        next.push_back(w[i] / 2);
        next.push_back(w[i] / 2);
        changed = true;
      } else {
        next.push_back(w[i]);
      }
    }
    w.swap(next);
  }
  return w;
}

}  // namespace

Grid make_graded_grid(const double min[2], const double max[2], double coarse, double finest,
                      const std::vector<RefineBox>& boxes, double margin) {
  Grid g;
  const char* names[2] = {"x", "y"};
  Axis* axes[2] = {&g.x, &g.y};
  const long coarse_units = std::lround(coarse / finest);
  std::vector<long> widths[2];
  for (int d = 0; d < 2; ++d) {
    const double n = (max[d] - min[d]) / finest;
    const long units = std::lround(n);
    if (units < 1 || std::fabs(n - double(units)) > 1e-6 * std::max(1.0, n))
      throw InputError(fmt::format(
          "grid.cell_size = {:g}: the domain extent along {} ({:g} m) must be a whole number of "
          "finest cells; {:g} does not qualify", finest, names[d], max[d] - min[d], n));
    std::vector<std::array<long, 3>> spans;
    for (const RefineBox& b : boxes) {
      const long size = std::max(1L, std::lround(b.size / finest));
      // The part of the box inside the domain, in finest cells (clamped in floating point, so
      // a box far outside gives an empty span, not a value no long can hold).
      const double from = std::clamp(std::floor((b.min[d] - min[d]) / finest + 1e-9), 0.0, double(units));
      const double to = std::clamp(std::ceil((b.max[d] - min[d]) / finest - 1e-9), 0.0, double(units));
      spans.push_back({long(from), long(to), size});
    }
    widths[d] = graded_widths(units, coarse_units, spans);
    for (long e : {widths[d].front(), widths[d].back()})
      g.ghost = std::max(g.ghost, ghost_cells(margin, double(e) * finest));
  }
  for (int d = 0; d < 2; ++d) {
    std::vector<long>& w = widths[d];
    // Ghost cells as wide as the edge cells.
    const long lo = w.front(), hi = w.back();
    w.insert(w.begin(), std::size_t(g.ghost), lo);
    w.insert(w.end(), std::size_t(g.ghost), hi);
    Axis& a = *axes[d];
    a.h = finest;
    a.cells = int(w.size());
    a.origin = min[d] - double(g.ghost * lo) * finest;
    a.coord.resize(w.size() + 1);
    long unit = 0;
    for (std::size_t c = 0; c < w.size(); ++c) {
      a.coord[c] = a.origin + double(unit) * finest;
      for (long u = 0; u < w[c]; ++u) a.cell_of_unit.push_back(int(c));
      unit += w[c];
    }
    a.coord.back() = a.origin + double(unit) * finest;
    a.inv_width.resize(w.size());
    for (std::size_t c = 0; c < w.size(); ++c) a.inv_width[c] = 1.0 / (a.coord[c + 1] - a.coord[c]);
    a.uniform_from.assign(w.size(), 0);
    for (std::size_t c = 1; c + 2 < w.size(); ++c)
      a.uniform_from[c] = w[c - 1] == w[c] && w[c + 1] == w[c] && w[c + 2] == w[c];
    g.domain_min[d] = min[d];
    g.domain_max[d] = max[d];
  }
  return g;
}

void GridFields::resize(int fields, std::size_t nx, std::size_t ny) {
  const std::size_t n = std::size_t(fields);
  set_windows(nx, ny, std::vector<int>(n, 0), std::vector<int>(n, int(nx)),
              std::vector<int>(n, 0), std::vector<int>(n, int(ny)));
}

void GridFields::set_windows(std::size_t nx, std::size_t ny, const std::vector<int>& c0,
                             const std::vector<int>& nc, const std::vector<int>& r0,
                             const std::vector<int>& nr) {
  num_fields = int(c0.size());
  num_nodes = nx * ny;
  nodes_x = nx;
  col0 = c0, cols = nc, row0 = r0, rows = nr;
  start.assign(c0.size() + 1, 0);
  for (std::size_t f = 0; f < c0.size(); ++f) {
    assert(c0[f] >= 0 && nc[f] > 0 && std::size_t(c0[f] + nc[f]) <= nx);
    assert(r0[f] >= 0 && nr[f] > 0 && std::size_t(r0[f] + nr[f]) <= ny);
    start[f + 1] = start[f] + std::size_t(nc[f]) * std::size_t(nr[f]);
  }
  for_each_field_array([&](std::vector<double> GridFields::*m) {
    std::vector<double>& v = this->*m;
    // A layout much smaller than the memory held (a whole lattice cut to a rank's windows:
    // parallel/halo_nested.hpp) gives the memory back; assign alone would keep it.
    if (v.capacity() > 2 * start.back() + 4096) std::vector<double>().swap(v);
    v.assign(start.back(), 0.0);
  });
}

std::size_t GridFields::bytes() const { return field_array_count() * sizeof(double) * size(); }

}  // namespace rupture
