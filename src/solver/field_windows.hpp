// rupture/solver/field_windows.hpp
// Keeps every velocity field's window of nodes (GridFields, grid/grid.hpp) covering all the
// nodes the time step touches in that field:
//   - its particles: one in cell (c, r) reaches node columns c - 1 .. c + 2 and rows
//     r - 1 .. r + 2 (the 3-node GIMP stencil, SPEC E3);
//   - the faces of its interfaces: a face point in cell (c, r), nodes c .. c + 1, r .. r + 1
//     (its bilinear stencil, solver/cohesive_step.cpp);
//   - the nodes its bonded stretches tie.
// Windows get kWindowMargin nodes of slack on every side, so they are re-fitted (re-allocated)
// only when something moves that far (out of the window, or more than twice the margin away
// from one of its sides, so a moving field keeps a window of its own size); a re-fit changes storage only, never a value, so results
// are bitwise those of whole-grid fields (State::whole_grid_fields, for tests). Particles are
// measured at every re-sort, and between sorts in the step after one leaves the cells its
// window allows (window_safe_cells; the particle move checks it and sets
// State::windows_stale), so at every scatter each particle's stencil lies in its field's
// window. (Not a re-sort: that would change the summation order, hence the round-off.)
#pragma once
#include "geometry/shape.hpp"
#include "solver/state.hpp"

namespace rupture {

inline constexpr int kWindowMargin = 8;  // nodes of slack on each side of what a field needs

// Fits the windows if needed. Called by make_state() and at the start of every step, after
// the particle sort and before the first scatter. Counts re-fits in State::window_fits.
void fit_field_windows(State& s);

// The cells a particle of field f may occupy with its whole stencil in the window:
// columns [lo[0], hi[0]], rows [lo[1], hi[1]].
inline void window_safe_cells(const GridFields& G, int f, int lo[2], int hi[2]) {
  const std::size_t k = std::size_t(f);
  lo[0] = G.col0[k] + 1, hi[0] = G.col0[k] + G.cols[k] - 3;
  lo[1] = G.row0[k] + 1, hi[1] = G.row0[k] + G.rows[k] - 3;
}

// Nodes of the window a field covering `box` (m) gets at t = 0, margin included: for the
// memory estimate of `rupture check`.
std::size_t window_nodes_estimate(const Grid& g, const Box& box);

}  // namespace rupture
