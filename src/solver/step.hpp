// rupture/solver/step.hpp
// One explicit GIMP time step (theory E4-E6) and its phases, each a free function over the
// State's plain arrays. step() runs the phases in the order of the chosen update scheme:
//   MUSL: P2G -> tie, face stencils, dt -> cohesive forces -> integrate + BCs -> G2P (velocity)
//         + re-map -> stress (re-mapped v) and move -> advance interfaces
//   USL : P2G -> tie, stencils, dt -> cohesive -> integrate + BCs -> G2P (velocity, stress from
//         v^{n+1}, move)
//   USF : P2G (mass, momentum) -> tie, stencils, dt -> stress (v^n) -> P2G force -> cohesive
//         -> integrate -> G2P (velocity, move)
// The step dt is chosen inside step() once the nodal masses are known (solver/time_step.hpp),
// never longer than s.dt_cap.
// (cohesive phases: solver/cohesive_step.hpp; [loads] phases: solver/load_step.hpp, external
// forces after the internal force, velocity regions after the velocity BCs)
// The phases: solver/transfer.hpp, solver/grid_update.hpp (both included here for callers).
// Distributed runs (State::halo, parallel/halo.hpp): particles migrate at the start when due,
// and every scatter (and the forces added after it) is summed over the ranks sharing a node
// right after it; the rest of the step is unchanged.
// Throws SimulationError (what, where, when) on a non-finite particle or one leaving the grid
// (distributed: at the end of the step, on every rank, with the failing rank's diagnosis).
#pragma once
#include "solver/grid_update.hpp"
#include "solver/run_state.hpp"
#include "solver/state.hpp"
#include "solver/transfer.hpp"

namespace rupture {

// One grid's time step.
void step(State& s);
// The run's time step on every level (one grid: step(State&)), then its clock and sums.
void step(RunState& r);

}  // namespace rupture
