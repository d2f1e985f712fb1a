// rupture/solver/grid_update.hpp
// Nodal phases of the time step (SPEC E4) and the prescribed edge velocities (E2), over every
// field's nodes; nodes lighter than State::mass_floor are empty (velocity 0).
#pragma once
#include "solver/state.hpp"

namespace rupture {

void grid_velocity_from_momentum(State& s, double t);  // v_i = p_i/m_i with BCs (USF)
void integrate_grid(State& s);          // p^{n+1} = p^n + dt f, then apply_velocity_bcs
void apply_absorbing_edges(State& s);  // dashpots of the absorbing edges (bc/absorbing.hpp)
void apply_velocity_bcs(State& s);      // prescribed v at t^{n+1} (E2) and its external work
void remapped_grid_velocity(State& s);  // MUSL: v_i = remapped p_i / m_i, BCs

}  // namespace rupture
