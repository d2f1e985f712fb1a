// rupture/solver/load_step.hpp
// The phases of the time step that apply Case::loads (bc/loads.hpp). Each is a no-op without
// loads of its kind, so a case without [loads] runs exactly as before.
//   prepare_loads:          after a particle sort, maps the loads' particle ids to indices; lists
//                           the nodes the velocity regions' particles touch now (t^n).
//   add_external_forces:    f_p = factor(t^n) x (traction x length_p | m_p x acceleration |
//                           F x w_p, a point force's share),
//                           scattered with the GIMP weights S_ip into the nodal force (E4),
//                           after the internal force and before the cohesive forces.
//   apply_velocity_regions: after the momentum update (next to apply_velocity_bcs), every node
//                           a region particle touches (S_ip > 0) gets its velocity component
//                           along d set to V(t^{n+1}); the perpendicular component stays as
//                           integrated. Its work is the constraint impulse m_i (V - v.d) d acting
//                           at the mean prescribed velocity, as for apply_velocity_bcs (E14).
//                           So the region's material moves rigidly along d; material within
//                           one GIMP stencil (about a cell) outside it shares those nodes and is
//                           dragged with it, as next to a driven edge. A node touched by two
//                           regions follows the first in input order. A tied node (the bonded
//                           tie of an interface, solver/cohesive_step.hpp: one continuum) is
//                           prescribed on both its fields' copies when the region reaches either,
//                           its work counted once.
//   prescribe_region_velocity: the same component on a velocity array (MUSL re-mapped, USF t^n).
//   external_force_work:    E14 work of the forces over the step, dt sum_i f_i.(v_i^n+v_i^{n+1})/2,
//                           the kinetic energy the nodal update gives them.
//   set_region_particle_velocity: the region particles' component along d is set to V(t^{n+1})
//                           (FLIP would otherwise keep its drift); the kinetic energy this changes
//                           is counted as external work.
#pragma once
#include "solver/state.hpp"

namespace rupture {

// Setup (make_state): the particles each load acts on, from the particles at t = 0: the
// traction patches and velocity regions from `near` when given (a distributed rank's: every
// particle near the segments and in the regions' boxes, solver/case_seeding.hpp), else from s's.
void set_up_loads(State& s, const Loads& loads, double cell_size, const Particles* near = nullptr);

void prepare_loads(State& s);
void add_external_forces(State& s);
void apply_velocity_regions(State& s);
void prescribe_region_velocity(State& s, double* gvx, double* gvy, double t);
void external_force_work(State& s);
void set_region_particle_velocity(State& s);

}  // namespace rupture
