// rupture/solver/step.hpp
// One explicit GIMP time step (SPEC E4-E6) and its phases, each a free function over the
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
// Throws SimulationError (what, where, when) on a non-finite particle or one leaving the grid.
#pragma once
#include "solver/state.hpp"

namespace rupture {

void step(State& s);

// --- phases (exposed for tests and benchmarks) ---
void build_scatter_plan(State& s);
void particles_to_grid(State& s, bool with_force);  // mass, momentum [, internal force] (E4)
void particles_to_grid_force(State& s);             // internal force only (USF)
void grid_velocity_from_momentum(State& s, double t);  // v_i = p_i/m_i with BCs (USF)
void integrate_grid(State& s);      // p^{n+1} = p^n + dt f, then apply_velocity_bcs
void apply_velocity_bcs(State& s);  // prescribed v at t^{n+1} (E2) and its external work
void update_particle_velocity_and_remap(State& s);  // FLIP/PIC blend + MUSL re-map (scatter)
void remapped_grid_velocity(State& s);              // MUSL: v_i = remapped p_i / m_i, BCs
// Stress update with the velocity in (gvx, gvy) (E5); optionally update velocity (USL) and
// move particles with the t^{n+1} grid velocity.
enum class G2PMode { stress_and_move, stress_velocity_and_move, stress_only, velocity_and_move };
void grid_to_particles(State& s, const double* gvx, const double* gvy, G2PMode mode);

}  // namespace rupture
