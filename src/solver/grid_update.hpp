// rupture/solver/grid_update.hpp
// Nodal phases of the time step (theory E4) and the prescribed edge velocities (E2), over every
// field's nodes; nodes lighter than State::mass_floor are empty (velocity 0).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bulk/node_update.hpp"
#include "solver/state.hpp"

namespace rupture {

void grid_velocity_from_momentum(State& s, double t);  // v_i = p_i/m_i with BCs (USF)
void integrate_grid(State& s);          // p^{n+1} = p^n + dt f, then apply_velocity_bcs
void apply_absorbing_edges(State& s);  // dashpots of the absorbing edges (bc/absorbing.hpp)
// Prescribed v at t^{n+1} (E2) and its external work; with `only`, at the nodes whose element
// has only[e] != 0.
void apply_velocity_bcs(State& s, const std::vector<unsigned char>* only = nullptr);
void remapped_grid_velocity(State& s);  // MUSL: v_i = remapped p_i / m_i, BCs
// The same at the elements listed in `nodes` only (nested levels between their steps' ends:
// solver/nested_subcycle.cpp); `only` marks the same elements.
void remapped_grid_velocity(State& s, const std::vector<std::uint32_t>& nodes,
                            const std::vector<unsigned char>& only);

// E4 at element i: p^{n+1} = p^n + dt f stored as velocity and increment (zero where the node is
// empty). The loops of integrate_grid and of the nested levels' partial updates.
inline void integrate_node(GridFields& G, std::size_t i, double dt, double floor) {
  const NodeArrays<2> g{G.mass.data(), {G.mom_x.data(), G.mom_y.data()}, {G.force_x.data(), G.force_y.data()},
                        {G.vel_x.data(), G.vel_y.data()}, {G.dvel_x.data(), G.dvel_y.data()}};
  integrate_node<2>(g, i, dt, floor);  // bulk/node_update.hpp
}

}  // namespace rupture
