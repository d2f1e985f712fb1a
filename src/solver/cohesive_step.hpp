// rupture/solver/cohesive_step.hpp
// The cohesive phases of the time step (SPEC E7-E9) and the tie of bonded interface stretches.
//   add_cohesive_forces: nodal cohesive forces of every interface onto its two fields' grid
//                        forces (upper face -T^, lower face +T^), before the momentum update;
//   tie_bonded_nodes:    where the halves are bonded, the two fields share mass, momentum and
//                        force on the interface row, which is exactly a single body;
//   advance_interfaces:  face nodes move with their field's t^{n+1} grid velocity; jumps,
//                        tractions, separation and cohesive work are updated.
#pragma once
#include "solver/state.hpp"

namespace rupture {

enum class TieWhat { mass_momentum, force, remapped_momentum };

void add_cohesive_forces(State& s);
void tie_bonded_nodes(State& s, TieWhat what);
void advance_interfaces(State& s);
// Jumps -> Gauss-point tractions, separation, nodal forces and cohesive work at time t.
void evaluate_interface(CohesiveInterface& c, double t);
// Grid nodes on the interface row within the bonded range (computed once at setup).
std::vector<std::size_t> bonded_nodes(const Grid& g, const InterfaceSpec& spec);

}  // namespace rupture
