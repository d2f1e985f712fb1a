// rupture/solver/field_windows.hpp
// Keeps every velocity field's window of nodes (GridFields, grid/grid.hpp) covering all the
// nodes the time step touches in that field:
//   - its particles: one in cell (c, r) reaches node columns c - 1 .. c + 2 and rows
//     r - 1 .. r + 2 (the 3-node GIMP stencil, theory E3);
//   - the faces of its interfaces: a face point in cell (c, r), nodes c .. c + 1, r .. r + 1
//     (its bilinear stencil, solver/cohesive_step.cpp);
//   - the nodes its bonded stretches tie.
// Windows get kWindowMargin nodes of slack on every side, so they are re-fitted (re-allocated)
// only when something moves that far (out of the window, or more than twice the margin away
// from one of its sides, so a moving field keeps a window of its own size); a re-fit changes storage only, never a value, so results
// are bitwise those of whole-grid fields (State::whole_grid_fields, for tests). Particles are
// measured at every re-sort, and again once any of them may have moved kWindowDrift cells since
// the last measure: the particle move sums the largest |v_x| + |v_y| times dt over the steps
// (State::window_drift), a bound on every particle's displacement, so the per-particle cost is
// one max and no check. A particle's stencil reaches 2 nodes past its cell; a measure keeps
// the window only if it leaves kWindowDrift + 1 nodes beyond every particle's stencil (else it
// re-fits, with the margin of 8), so every stencil stays inside the window at every scatter
// until the next measure. (Not a re-sort: that would change the summation order, hence the round-off.)
#pragma once
#include "geometry/shape.hpp"
#include "solver/state.hpp"

namespace rupture {

inline constexpr int kWindowMargin = 8;  // nodes of slack on each side of what a field needs
inline constexpr double kWindowDrift = 5.0;  // cells (the finest) a particle may move unmeasured

// Fits the windows if needed. Called by make_state() and at the start of every step, after
// the particle sort and before the first scatter. Counts re-fits in State::window_fits.
void fit_field_windows(State& s);


// Nodes of the window a field covering `box` (m) gets at t = 0, margin included: for the
// memory estimate of `rupture check`.
std::size_t window_nodes_estimate(const Grid& g, const Box& box);

}  // namespace rupture
