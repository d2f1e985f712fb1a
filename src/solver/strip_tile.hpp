// rupture/solver/strip_tile.hpp
// Strip tiles of the particle loops (solver/transfer.cpp, solver/gather.cpp). Each particle
// loop works on one strip of ScatterPlan at a time through a small node-major tile that holds,
// per node, the few values the loop needs packed in one vector (Lane2/Lane4/Lane8): a
// particle-node pair is then one to three vector FMAs instead of several scalar loads or
// read-modify-writes on separate arrays, and the grid arrays are walked once per strip, row
// by row, instead of once per particle. Gathers pack the tile from the grid arrays first;
// scatters add the tile to the grid arrays after. A tile spans the strip's node columns (with
// the one-column drift tolerance of ScatterPlan) and, per field, the node rows its particles
// touch. Internal to solver/.
#pragma once
#include <algorithm>
#include <cassert>
#include <cstddef>
#include <vector>

#include "solver/state.hpp"

namespace rupture::detail {

using Lane8 = double __attribute__((vector_size(64)));
using Lane4 = double __attribute__((vector_size(32)));
using Lane2 = double __attribute__((vector_size(16)));

struct TileLayout {
  int col0 = 0, cols = 0;          // first node column, number of columns
  std::vector<int> row0, rows;     // per field: first node row, number of rows (0: absent)
  std::vector<std::size_t> start;  // per field: offset of its first node in the tile
  std::size_t size() const { return start.back(); }
  // Tile index of grid node (gx, gy) of field f: the first node of a particle's 3 x 3 stencil.
  // Debug builds check that the whole stencil lies in the tile; a particle breaking the GIMP
  // contract (grid/grid.hpp) could write outside it.
  std::size_t index(std::size_t f, int gx, int gy) const {
    assert(f < rows.size());
    assert(gy >= row0[f] && gy + 2 < row0[f] + rows[f] && "stencil rows outside the tile");
    assert(gx >= col0 && gx + 2 < col0 + cols && "stencil columns outside the tile");
    const std::size_t t =
        start[f] + std::size_t(gy - row0[f]) * std::size_t(cols) + std::size_t(gx - col0);
    assert(t + 2 * std::size_t(cols) + 2 < size());
    return t;
  }
};

// The strip's tile. Its node rows per field: those the strip's particles reached at the last
// sort, widened by their drift since and clipped to the field's window (ScatterPlan::row_lo,
// row_hi, drift); after a restart, until the next sort, found from the particles
// [begin, end) themselves (one pass over them, which the sort's bounds save: docs/
// performance.md, "Choices in the code").
void tile_layout(const State& s, int strip, std::size_t begin, std::size_t end, TileLayout& T);

// Calls visit(tile_index, element, count) for every row of tile nodes that lie inside their
// field's window (the window lies inside the grid; the particles' nodes lie inside it): count
// nodes from tile_index on in the tile and from element on in the grid arrays.
template <class Visit>
void for_each_tile_row(const State& s, const TileLayout& T, Visit&& visit) {
  const GridFields& G = s.fields;
  for (std::size_t f = 0; f < T.rows.size(); ++f) {
    const int fi = int(f);
    const int r_lo = std::max(T.row0[f], G.row0[f]), r_hi = std::min(T.row0[f] + T.rows[f], G.row0[f] + G.rows[f]);
    const int c_lo = std::max(T.col0, G.col0[f]), c_hi = std::min(T.col0 + T.cols, G.col0[f] + G.cols[f]);
    if (c_hi <= c_lo) continue;
    for (int gy = r_lo; gy < r_hi; ++gy) {
      const std::size_t t = T.start[f] + std::size_t(gy - T.row0[f]) * std::size_t(T.cols) +
                            std::size_t(c_lo - T.col0);
      visit(t, G.index(fi, c_lo, gy), c_hi - c_lo);
    }
  }
}

// One tile row and the grid arrays: tile[c] = {in[0][e + c], .., in[kLanes-1][e + c], 0, ..}
// (pack_tile_row), or out[lane][e + c] += tile[c][lane] (add_tile_row), c < count. The array
// pointers are copied in first: reached through the GridFields vectors node by node, they
// were reloaded for every node (docs/performance.md, "Choices in the code").
template <int kLanes, class Lane>
inline void pack_tile_row(Lane* __restrict tile, int count, const double* const* in, std::size_t e) {
  const double* src[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) src[lane] = in[lane] + e;
  for (int c = 0; c < count; ++c) {
    Lane v = {};
    for (int lane = 0; lane < kLanes; ++lane) v[lane] = src[lane][c];
    tile[c] = v;
  }
}
template <int kLanes, class Lane>
inline void add_tile_row(const Lane* __restrict tile, int count, double* const* out, std::size_t e) {
  double* dst[kLanes];
  for (int lane = 0; lane < kLanes; ++lane) dst[lane] = out[lane] + e;
  for (int c = 0; c < count; ++c) {
    const Lane v = tile[c];
    for (int lane = 0; lane < kLanes; ++lane) dst[lane][c] += v[lane];
  }
}

template <class Lane>
Lane* tile_buffer(std::vector<Lane>& buffer, std::size_t size, bool zero) {
  if (buffer.size() < size) buffer.resize(size);
  if (zero) std::fill(buffer.begin(), buffer.begin() + std::ptrdiff_t(size), Lane{});
  return buffer.data();
}

}  // namespace rupture::detail
