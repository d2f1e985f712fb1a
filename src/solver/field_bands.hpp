// rupture/solver/field_bands.hpp
// Keeps every velocity field's band of node rows (GridFields, grid/grid.hpp) covering all the
// nodes the time step touches in that field:
//   - its particles: one in cell row r reaches node rows r - 1 .. r + 2 (the 3-node GIMP
//     stencil, SPEC E3);
//   - the faces of its interfaces: a face point in cell row r, rows r and r + 1 (its bilinear
//     stencil, solver/cohesive_step.cpp);
//   - the nodes its bonded stretches tie.
// Bands get kBandMargin rows either side, so they are re-fitted (re-allocated) only when
// something moves that far; a re-fit changes storage only, never a value, so results are
// bitwise those of whole-grid fields. Particles are measured at every re-sort; between sorts
// the particle move (solver/transfer.cpp) asks for a re-sort as soon as one leaves the rows
// its band allows (band_safe_rows), so every particle is inside its band at each scatter.
#pragma once
#include "solver/state.hpp"

namespace rupture {

inline constexpr int kBandMargin = 8;  // rows of slack either side of what a field needs

// Fits the bands if needed. Called by make_state() and at the start of every step, after the
// particle sort and before the first scatter.
void fit_field_bands(State& s);

// The cell rows [lo, hi] a particle of field f may occupy with its whole stencil in the band.
inline void band_safe_rows(const GridFields& G, int f, int& lo, int& hi) {
  lo = G.row0[std::size_t(f)] + 1;
  hi = G.row0[std::size_t(f)] + G.rows[std::size_t(f)] - 3;
}

// Rows of the band a field spanning [ymin, ymax] (m) would get at t = 0: for memory estimates.
std::size_t band_rows_estimate(const Grid& g, double ymin, double ymax);

}  // namespace rupture
