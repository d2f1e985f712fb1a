// rupture/solver/strip_tile.cpp
#include "solver/strip_tile.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace rupture::detail {
namespace {

// Tile offsets of each field from T.rows.
void tile_offsets(TileLayout& T) {
  T.start.assign(T.rows.size() + 1, 0);
  for (std::size_t f = 0; f < T.rows.size(); ++f)
    T.start[f + 1] = T.start[f] + std::size_t(T.rows[f]) * std::size_t(T.cols);
}

void tile_columns(const State& s, int strip, TileLayout& T) {
  T.col0 = strip * s.plan.strip_cells - 2;
  T.cols = s.plan.strip_cells + 5;
}

}  // namespace

void tile_layout(const State& s, int strip, std::size_t begin, std::size_t end, TileLayout& T) {
  const Particles& P = s.particles;
  const int fields = s.fields.num_fields;
  const double oy = s.grid.y.origin, inv_hy = 1.0 / s.grid.y.h;
  const bool graded = s.grid.y.graded();
  tile_columns(s, strip, T);
  // Node rows per field: a particle in cell row r touches node rows r-1 .. r+2. The cell row
  // is monotonic in y, so the rows of a field's lowest and highest particles bound them all
  // (one min/max pass per field present, vectorized, instead of a row per particle).
  T.row0.assign(std::size_t(fields), std::numeric_limits<int>::max());
  T.rows.assign(std::size_t(fields), std::numeric_limits<int>::min());  // last row, then count
  const auto row = [&](double y) {
    return graded ? s.grid.y.cell_of(y) : int((y - oy) * inv_hy);  // > 0: trunc = floor
  };
  const double* __restrict y = P.y.data();
  const std::uint8_t* __restrict field = P.field.data();
  // Two fields per pass (two bodies are the common case: one pass over the strip).
  const auto rows_of = [&](std::size_t f, double lo, double hi) {
    if (lo > hi) return;  // no particle of this field in the strip
    T.row0[f] = row(lo) - 1;
    T.rows[f] = row(hi) + 2;
  };
  for (std::size_t f = 0; f < std::size_t(fields); f += 2) {
    double lo0 = INFINITY, hi0 = -INFINITY, lo1 = INFINITY, hi1 = -INFINITY;
    const std::uint8_t f0 = std::uint8_t(f), f1 = std::uint8_t(f + 1);
#pragma omp simd reduction(min : lo0, lo1) reduction(max : hi0, hi1)
    for (std::size_t p = begin; p < end; ++p) {
      lo0 = std::min(lo0, field[p] == f0 ? y[p] : INFINITY);
      hi0 = std::max(hi0, field[p] == f0 ? y[p] : -INFINITY);
      lo1 = std::min(lo1, field[p] == f1 ? y[p] : INFINITY);
      hi1 = std::max(hi1, field[p] == f1 ? y[p] : -INFINITY);
    }
    rows_of(f, lo0, hi0);
    if (f + 1 < std::size_t(fields)) rows_of(f + 1, lo1, hi1);
  }
  for (std::size_t f = 0; f < std::size_t(fields); ++f)
    T.rows[f] = T.rows[f] >= T.row0[f] ? T.rows[f] - T.row0[f] + 1 : 0;
  tile_offsets(T);
}

void keep_tile_rows_sized(State& s) {
  const std::size_t n = std::size_t(s.plan.num_strips) * std::size_t(s.fields.num_fields);
  s.plan.tile_row0.resize(n);
  s.plan.tile_rows.resize(n);
  s.plan.tile_step = s.step;
}
void keep_tile_rows(ScatterPlan& plan, int strip, const TileLayout& T) {
  const std::size_t k = std::size_t(strip) * T.rows.size();  // strips write disjoint parts
  std::copy(T.row0.begin(), T.row0.end(), plan.tile_row0.begin() + std::ptrdiff_t(k));
  std::copy(T.rows.begin(), T.rows.end(), plan.tile_rows.begin() + std::ptrdiff_t(k));
}
void tile_layout_kept(const State& s, int strip, std::size_t begin, std::size_t end, TileLayout& T) {
  const ScatterPlan& plan = s.plan;
  if (plan.tile_step != s.step) return tile_layout(s, strip, begin, end, T);
  const std::size_t fields = std::size_t(s.fields.num_fields), k = std::size_t(strip) * fields;
  tile_columns(s, strip, T);
  T.row0.assign(plan.tile_row0.begin() + std::ptrdiff_t(k), plan.tile_row0.begin() + std::ptrdiff_t(k + fields));
  T.rows.assign(plan.tile_rows.begin() + std::ptrdiff_t(k), plan.tile_rows.begin() + std::ptrdiff_t(k + fields));
  tile_offsets(T);
}

}  // namespace rupture::detail
