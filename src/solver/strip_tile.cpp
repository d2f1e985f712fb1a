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

// Node rows per field from the particles: a particle in cell row r touches node rows r-1 ..
// r+2. The cell row is monotonic in y, so the rows of a field's lowest and highest particles
// bound them all (one min/max pass per field present, vectorized, instead of a row per
// particle).
void rows_from_particles(const State& s, std::size_t begin, std::size_t end, TileLayout& T) {
  const Particles& P = s.particles;
  const int fields = s.fields.num_fields;
  const double oy = s.grid.y.origin, inv_hy = 1.0 / s.grid.y.h;
  const bool graded = s.grid.y.graded();
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
}

// Node rows per field from the sort's bounds. A particle's first stencil row moves by at most
// ceil(d / row_height) rows when it moves by d (a row is at least row_height high); one row
// more on each side absorbs the round-off of the summed drift. The window holds every
// particle's stencil (solver/field_windows.hpp), so clipping to it loses none.
void rows_from_plan(const State& s, int strip, TileLayout& T) {
  const ScatterPlan& plan = s.plan;
  const GridFields& G = s.fields;
  const std::size_t fields = std::size_t(G.num_fields);
  const int widen = int(std::ceil(plan.drift / plan.row_height)) + 1;
  T.row0.assign(fields, 0);
  T.rows.assign(fields, 0);
  for (std::size_t f = 0; f < fields; ++f) {
    const std::size_t e = std::size_t(strip) * fields + f;
    if (plan.row_lo[e] > plan.row_hi[e]) continue;  // no particle of this field in the strip
    const int r0 = std::max(plan.row_lo[e] - widen, G.row0[f]);
    const int r1 = std::min(plan.row_hi[e] + 2 + widen, G.row0[f] + G.rows[f] - 1);
    T.row0[f] = r0;
    T.rows[f] = r1 >= r0 ? r1 - r0 + 1 : 0;
  }
}

}  // namespace

void tile_layout(const State& s, int strip, std::size_t begin, std::size_t end, TileLayout& T) {
  tile_columns(s, strip, T);
  if (s.plan.rows_known)
    rows_from_plan(s, strip, T);
  else
    rows_from_particles(s, begin, end, T);
  tile_offsets(T);
}

}  // namespace rupture::detail
