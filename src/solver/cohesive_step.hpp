// rupture/solver/cohesive_step.hpp
// The cohesive phases of the time step (theory E7-E9) and the tie of bonded interface stretches.
//   update_face_stencils: each face node's stencil on its field (after the bonded tie, with
//                        this step's nodal masses), used by both phases below;
//   add_cohesive_forces: nodal cohesive forces of every interface onto its two fields' grid
//                        forces (upper face -T^, lower face +T^), before the momentum update;
//   tie_bonded_nodes:    where the halves are bonded, the two fields share mass, momentum and
//                        force on every grid node both reach across the bonded line, which
//                        is exactly a single body;
//   advance_interfaces:  face nodes move with their field's t^{n+1} grid velocity (MUSL: the
//                        re-mapped one its strain uses, solver/time_step.hpp); jumps,
//                        tractions, separation and cohesive work are updated.
#pragma once
#include "solver/state.hpp"

namespace rupture {

enum class TieWhat { mass_momentum, force, remapped_momentum };

void update_face_stencils(State& s);
void add_cohesive_forces(State& s);
void tie_bonded_nodes(State& s, TieWhat what);
void advance_interfaces(State& s, const double* vel_x, const double* vel_y);
// Jumps -> Gauss-point tractions, separation, nodal forces and cohesive work at time t; the
// step began at t_before (node crack times are interpolated in [t_before, t] from
// c.jump_before).
void evaluate_interface(CohesiveInterface& c, double t, double t_before);
// Grid nodes tied along the interface's bonded stretches: those closer to one of them than a
// particle within half a cell of it reaches (2 (|n_x| h_x + |n_y| h_y)), and as far beyond an end
// unless that end lies on the crack's line (a tip), where the tie stops exactly; each node once,
// in increasing order.
std::vector<std::size_t> bonded_nodes(const Grid& g, const InterfaceSpec& spec);
// The same for some of its tied lines (InterfaceSpec::tie_geometries); `crack` its line
// (InterfaceSpec::geometry): a tie's end on it is a tip.
std::vector<std::size_t> bonded_nodes(const Grid& g, const std::vector<Polyline>& ties,
                                      const Polyline& crack);
// The same with each tie laid where the material has carried it (`laid[i]`: ties[i] moved with the
// material, its first and last points ties[i]'s ends moved; solver/tie_follow.hpp): whether an
// end is a tip is read on the drawn lines, the band is laid about the moved one.
std::vector<std::size_t> bonded_nodes(const Grid& g, const std::vector<Polyline>& ties,
                                      const Polyline& crack, const std::vector<Polyline>& laid);

}  // namespace rupture
