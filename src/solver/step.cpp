// rupture/solver/step.cpp
// The time step: one function per update scheme, each the method's phases in order with the
// boundary conditions, loads and cohesive phases visible (SPEC E4-E9). The phases live in
// solver/transfer (particle <-> grid), solver/grid_update (nodes, velocity BCs),
// solver/cohesive_step (interfaces), solver/load_step ([loads]), solver/time_step (dt, E6).
#include "solver/step.hpp"

#include <chrono>

#include "core/errors.hpp"
#include "parallel/halo.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/field_windows.hpp"
#include "solver/load_step.hpp"
#include "solver/nested_state.hpp"
#include "solver/time_step.hpp"

namespace rupture {
namespace {
// Wall time of the cohesive phases (forces, ties, interface advance), for the run record.
// Distributed runs count the work only: the exchanges inside (halo increments, interface
// syncs) are the halo's time (Halo::exchange_seconds), not the cohesive phases'.
class CohesiveTimer {
 public:
  explicit CohesiveTimer(State& s)
      : s_(s), t0_(std::chrono::steady_clock::now()), exchanged_(exchange_seconds()) {}
  ~CohesiveTimer() {
    s_.cohesive_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count() -
                           (exchange_seconds() - exchanged_);
  }
  CohesiveTimer(const CohesiveTimer&) = delete;
  CohesiveTimer& operator=(const CohesiveTimer&) = delete;

 private:
  double exchange_seconds() const { return s_.halo ? s_.halo->exchange_seconds : 0.0; }
  State& s_;
  std::chrono::steady_clock::time_point t0_;
  double exchanged_;
};

// After the mass scatter: the bonded stretch becomes one body (shared mass and momentum),
// then the face stencils see this step's masses, and the step follows from them (E6).
void tie_stencils_and_time_step(State& s) {
  if (!s.interfaces.empty()) {
    CohesiveTimer timer(s);
    tie_bonded_nodes(s, TieWhat::mass_momentum);
    update_face_stencils(s);
    check_faces_in_reach(s);  // distributed: faces within this rank's halo
  }
  choose_time_step(s);
  if (s.halo) s.dt = s.halo->comm.min(s.dt);  // distributed: one step for all ranks
}

// A gather that may find a bad particle: on several processes the diagnosis waits for the end
// of the step (every rank takes part in the step's exchanges, then all stop together).
void gather(State& s, NodalArray gx, NodalArray gy, G2PMode mode) {
  if (!s.halo) return grid_to_particles(s, gx, gy, mode);
  try {
    grid_to_particles(s, gx, gy, mode);
  } catch (const SimulationError& e) {
    if (s.halo->failure.empty()) s.halo->failure = e.what();
  }
}

// The nodal arrays each scatter adds to, summed over the ranks that share a node (distributed
// runs; parallel/halo.hpp).
void sum_mass_momentum(State& s) { halo_sum(s, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y}); }
void sum_force(State& s) { halo_sum(s, {&GridFields::force_x, &GridFields::force_y}); }
void sum_remapped(State& s) { halo_sum(s, {&GridFields::remap_x, &GridFields::remap_y}); }
void sum_mass_momentum_force(State& s) {
  halo_sum(s, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y, &GridFields::force_x,
               &GridFields::force_y});
}

// Tractions and body forces ([loads]) after the internal force; distributed: each rank's
// particles' share, summed over the ranks like the scatter.
void external_forces(State& s) {
  if (!s.loads.has_forces()) return;
  halo_save(s, {&GridFields::force_x, &GridFields::force_y});
  add_external_forces(s);
  halo_sum_added(s, {&GridFields::force_x, &GridFields::force_y});
}

void cohesive_forces_and_ties(State& s) {
  if (s.interfaces.empty()) return;
  CohesiveTimer timer(s);
  halo_save(s, {&GridFields::force_x, &GridFields::force_y});
  add_cohesive_forces(s);  // E7-E9 (distributed: each rank its owned faces',
  halo_sum_added(s, {&GridFields::force_x, &GridFields::force_y});  // summed over the ranks)
  tie_bonded_nodes(s, TieWhat::force);
}

// MUSL (modified update stress last): the stress is updated with the grid velocity re-mapped
// from the updated particle velocities.
void step_musl(State& s) {
  GridFields& G = s.fields;
  particles_to_grid(s, true);             // E4: mass, momentum, internal force per field
  sum_mass_momentum_force(s);             // distributed: shared nodes summed over ranks
  tie_stencils_and_time_step(s);          // bonded stretch, face stencils, dt (E6)
  external_forces(s);                     // E4 tractions, body forces ([loads])
  cohesive_forces_and_ties(s);            // E7-E9, bonded stretch
  integrate_grid(s);                      // E4 momentum update + E2 velocity BCs
  apply_velocity_regions(s);              // [loads] velocity regions, along d
  external_force_work(s);                 // E14
  update_particle_velocity_and_remap(s);  // FLIP/PIC velocity, re-mapped momentum
  sum_remapped(s);
  if (!s.interfaces.empty()) {
    CohesiveTimer timer(s);
    tie_bonded_nodes(s, TieWhat::remapped_momentum);
  }
  remapped_grid_velocity(s);  // + E2 velocity BCs at t^{n+1}
  prescribe_region_velocity(s, G.remap_x.data(), G.remap_y.data(), s.time + s.dt);
  gather(s, &GridFields::remap_x, &GridFields::remap_y, G2PMode::stress_and_move);  // E5
}

// USL (update stress last): the stress is updated with the t^{n+1} grid velocity.
void step_usl(State& s) {
  particles_to_grid(s, true);
  sum_mass_momentum_force(s);
  tie_stencils_and_time_step(s);
  external_forces(s);
  cohesive_forces_and_ties(s);
  integrate_grid(s);
  apply_velocity_regions(s);
  external_force_work(s);
  gather(s, &GridFields::vel_x, &GridFields::vel_y, G2PMode::stress_velocity_and_move);  // E5
}

// USF (update stress first): the stress is updated with the t^n grid velocity, before the
// internal force is scattered.
void step_usf(State& s) {
  GridFields& G = s.fields;
  particles_to_grid(s, false);  // E4: mass, momentum
  sum_mass_momentum(s);
  tie_stencils_and_time_step(s);
  grid_velocity_from_momentum(s, s.time);  // + E2 velocity BCs at t^n
  prescribe_region_velocity(s, G.remap_x.data(), G.remap_y.data(), s.time);
  gather(s, &GridFields::remap_x, &GridFields::remap_y, G2PMode::stress_only);  // E5
  particles_to_grid_force(s);
  sum_force(s);
  external_forces(s);
  cohesive_forces_and_ties(s);
  integrate_grid(s);
  apply_velocity_regions(s);
  external_force_work(s);
  gather(s, &GridFields::vel_x, &GridFields::vel_y, G2PMode::velocity_and_move);
}

}  // namespace

void step(State& s) {
  if (s.nested) {  // grid.refinement = "nested": the levels step (solver/nested_state.hpp)
    step_nested_run(s);
    return;
  }
  migrate_if_due(s);  // distributed: particles that left their rank's block move to its owner
  build_scatter_plan(s);
  const double drift_at_start = s.plan.drift;
  fit_field_windows(s);  // every field's window covers its particles, faces and ties
  // A driven edge that has moved onto another grid line takes its condition with it (E2).
  if (update_edge_lines(s.boundary, s.grid, s.time, s.bc_lines))
    s.bc_nodes = resolve_nodes(s.boundary, s.grid, s.fields.num_fields, s.bc_lines);
  prepare_loads(s);  // loaded particles after a sort, region nodes at t^n
  switch (s.scheme) {
    case Scheme::MUSL:
      step_musl(s);
      break;
    case Scheme::USL:
      step_usl(s);
      break;
    case Scheme::USF:
      step_usf(s);
      break;
  }
  set_region_particle_velocity(s);  // region particles: component along d at t^{n+1}
  s.time += s.dt;
  ++s.step;
  if (!s.interfaces.empty()) {
    CohesiveTimer timer(s);
    // Face nodes follow their fields with the velocity the bodies' strain is updated with (MUSL:
    // re-mapped), so jumps and strains stay consistent; jumps and tractions at t^{n+1}.
    const GridFields& G = s.fields;
    const bool musl = s.scheme == Scheme::MUSL;
    advance_interfaces(s, musl ? G.remap_x.data() : G.vel_x.data(),
                       musl ? G.remap_y.data() : G.vel_y.data());
  }
  finish_distributed_step(s, drift_at_start);  // migration bound; a failure on any rank stops all
}

}  // namespace rupture
