// rupture/solver/step.cpp
// The time step: one function per update scheme, each the method's phases in order with the
// boundary conditions, loads and cohesive phases visible (theory E4-E9), written once over the
// levels of solver/levels.hpp (one grid: one level, whose transitions are no-ops). The phases
// live in solver/transfer (particle <-> grid), solver/grid_update (nodes, velocity BCs,
// absorbing edges), solver/cohesive_step (interfaces), solver/load_step ([loads]),
// solver/time_step (dt, E6), solver/transitions (levels). Distributed runs (State::halo): every
// scatter, and the forces added after it, is summed over the ranks sharing a node right after
// it (parallel/halo.hpp), before the transitions combine the levels.
#include "solver/step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/errors.hpp"
#include "solver/rank_exchange.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/consistent_mass.hpp"
#include "solver/field_windows.hpp"
#include "solver/levels.hpp"
#include "solver/load_step.hpp"
#include "solver/nested_phases.hpp"
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

template <class Phase>
void each(const Levels& L, Phase&& phase) {
  for (State* s : L) phase(*s);
}

// The nodal arrays the scatters add to.
constexpr std::initializer_list<NodalArray> kMassMomentum = {&GridFields::mass, &GridFields::mom_x,
                                                             &GridFields::mom_y};
constexpr std::initializer_list<NodalArray> kForce = {&GridFields::force_x, &GridFields::force_y};
constexpr std::initializer_list<NodalArray> kMassMomentumForce = {
    &GridFields::mass, &GridFields::mom_x, &GridFields::mom_y, &GridFields::force_x, &GridFields::force_y};
constexpr std::initializer_list<NodalArray> kRemapped = {&GridFields::remap_x, &GridFields::remap_y};
constexpr std::initializer_list<NodalArray> kVelocity = {&GridFields::vel_x, &GridFields::vel_y,
                                                         &GridFields::dvel_x, &GridFields::dvel_y};

// Distributed runs: each level's shared nodes summed over the ranks that reach them.
void sum_shared_nodes(const Levels& L, std::initializer_list<NodalArray> arrays) {
  each(L, [&](State& s) { halo_sum(s, arrays); });
}

// One dt for every level and rank: the smallest of their limits (theory E6).
void common_time_step(const Levels& L) {
  double dt = INFINITY;
  each(L, [&](State& s) {
    choose_time_step(s);
    dt = std::min(dt, s.dt);
  });
  dt = min_over_ranks(L.first(), dt);
  each(L, [&](State& s) { s.dt = dt; });
}

// Tractions and body forces ([loads]) after the internal force; distributed: each rank's
// particles' share, summed over the ranks like the scatter. Added before the transitions
// condense the force (levels: a slave's share goes to its DOFs with the rest), and the record
// of them (for their work) condensed alike.
void external_forces(const Levels& L) {
  if (!L.first().loads.has_forces()) return;
  each(L, [](State& s) {
    halo_save(s, kForce);
    add_external_forces(s);
    halo_sum_added(s, kForce);
  });
  condense_to_dofs(L, {&LoadState::ext_fx, &LoadState::ext_fy});
}

// E4's momentum update with the boundary conditions, in this order on each level: the
// absorbing edges' dashpots and the prescribed edge velocities (E2, integrate_grid), the
// [loads] velocity regions (along their direction), then the work of the external forces
// over the step (E14).
void update_grid(const Levels& L) {
  each(L, [](State& s) {
    integrate_grid(s);
    apply_velocity_regions(s);
    external_force_work(s);
  });
}

// solver.mass = "averaged" (solver/consistent_mass.hpp, docs/theory.md §19): the consistent
// mass of this step's stencils, then the velocity at t^n projected with it (v = M_C^-1 p) and
// the acceleration taken with the averaged mass (a = M_A^-1 f), both written back as lumped
// momentum and force for the updates that divide by m. With the lumped mass: nothing.
void averaged_mass(const Levels& L) {
  each(L, [](State& s) {
    if (s.mass_matrix != MassMatrix::averaged) return;
    assemble_consistent_mass(s);
    solve_momentum_and_force(s);
  });
}

// USF: the same two solves, the momentum's before the stress update and the force's after
// the force scatter (the band from the step's stencils: the particles move at its end).
void averaged_mass_momentum(const Levels& L) {
  each(L, [](State& s) {
    if (s.mass_matrix != MassMatrix::averaged) return;
    assemble_consistent_mass(s);
    solve_mass(s, MassSolve::momentum_at_start, s.fields.mom_x.data(), s.fields.mom_y.data());
  });
}
void averaged_mass_force(const Levels& L) {
  each(L, [](State& s) {
    if (s.mass_matrix == MassMatrix::averaged)
      solve_mass(s, MassSolve::force, s.fields.force_x.data(), s.fields.force_y.data());
  });
}

// The re-mapped momentum's velocity with the consistent mass (MUSL; the band of this step:
// the particles have not moved yet).
void consistent_remap(const Levels& L) {
  each(L, [](State& s) {
    if (s.mass_matrix == MassMatrix::averaged)
      solve_mass(s, MassSolve::momentum_at_end, s.fields.remap_x.data(), s.fields.remap_y.data());
  });
}

// MUSL: the re-mapped velocity at t^{n+1} (+ E2) and the regions' prescribed component.
void remapped_velocity(const Levels& L) {
  each(L, [](State& s) {
    if (!s.bonded.empty()) {
      CohesiveTimer timer(s);
      tie_bonded_nodes(s, TieWhat::remapped_momentum);
    }
    remapped_grid_velocity(s);  // + E2 velocity BCs at t^{n+1}
    prescribe_region_velocity(s, s.fields.remap_x.data(), s.fields.remap_y.data(), s.time + s.dt);
  });
}

// USF: the grid velocity at t^n (+ E2) and the regions' prescribed component.
void velocity_at_start(const Levels& L) {
  each(L, [](State& s) {
    grid_velocity_from_momentum(s, s.time);
    prescribe_region_velocity(s, s.fields.remap_x.data(), s.fields.remap_y.data(), s.time);
  });
}

// MUSL (modified update stress last): the stress is updated with the grid velocity re-mapped
// from the updated particle velocities.
void step_musl(const Levels& L) {
  particles_to_grid(L.level, L.count, true);  // E4: mass, momentum, internal force per field
  sum_shared_nodes(L, kMassMomentumForce);
  external_forces(L);                         // E4 tractions, body forces ([loads])
  condense_to_dofs(L, kMassMomentumForce);    // levels: slaves onto their DOFs
  detail::tie_and_face_stencils(L);           // bonded stretch, face stencils
  common_time_step(L);                        // dt (E6)
  detail::cohesive_forces_and_ties(L);        // E7-E9, bonded stretch
  averaged_mass(L);                           // solver.mass = "averaged": M_C, M_A (§19)
  update_grid(L);                             // E4 + absorbing edges, E2 velocity BCs, regions
  spread_to_slaves(L, kVelocity);
  update_particle_velocity_and_remap(L.level, L.count);  // FLIP/PIC velocity, re-mapped momentum
  sum_shared_nodes(L, kRemapped);
  condense_to_dofs(L, kRemapped);
  consistent_remap(L);   // "averaged": the re-mapped velocity with M_C
  remapped_velocity(L);  // bonded stretch, v = p / m, E2 at t^{n+1}, regions
  spread_to_slaves(L, kRemapped);
  detail::gather(L, &GridFields::remap_x, &GridFields::remap_y, G2PMode::stress_and_move);  // E5
}

// USL (update stress last): the stress is updated with the t^{n+1} grid velocity.
void step_usl(const Levels& L) {
  particles_to_grid(L.level, L.count, true);
  sum_shared_nodes(L, kMassMomentumForce);
  external_forces(L);
  condense_to_dofs(L, kMassMomentumForce);
  detail::tie_and_face_stencils(L);
  common_time_step(L);
  detail::cohesive_forces_and_ties(L);
  averaged_mass(L);
  update_grid(L);
  spread_to_slaves(L, kVelocity);
  detail::gather(L, &GridFields::vel_x, &GridFields::vel_y, G2PMode::stress_velocity_and_move);  // E5
}

// USF (update stress first): the stress is updated with the t^n grid velocity, before the
// internal force is scattered.
void step_usf(const Levels& L) {
  particles_to_grid(L.level, L.count, false);  // E4: mass, momentum
  sum_shared_nodes(L, kMassMomentum);
  condense_to_dofs(L, kMassMomentum);
  detail::tie_and_face_stencils(L);
  common_time_step(L);
  averaged_mass_momentum(L);  // "averaged": M_C (§19)
  velocity_at_start(L);  // v^n = p / m, E2 at t^n, regions
  spread_to_slaves(L, kRemapped);
  detail::gather(L, &GridFields::remap_x, &GridFields::remap_y, G2PMode::stress_only);  // E5
  each(L, [](State& s) { particles_to_grid_force(s); });
  sum_shared_nodes(L, kForce);
  external_forces(L);
  condense_to_dofs(L, kForce);
  detail::cohesive_forces_and_ties(L);
  averaged_mass_force(L);  // "averaged": M_A (§19)
  update_grid(L);
  spread_to_slaves(L, kVelocity);
  detail::gather(L, &GridFields::vel_x, &GridFields::vel_y, G2PMode::velocity_and_move);
}

}  // namespace

namespace detail {

// The end of every scheme's step on each level: the region particles' component along d at
// t^{n+1}, the clock, and the interfaces' face nodes moved with the velocity the bodies'
// strain was updated with (MUSL: re-mapped, else t^{n+1}), so jumps and strains stay
// consistent; jumps and tractions at t^{n+1}.
void end_step(const Levels& L, Scheme scheme) {
  each(L, [scheme](State& s) {
    set_region_particle_velocity(s);
    s.time += s.dt;
    ++s.step;
    if (s.interfaces.empty()) return;
    CohesiveTimer timer(s);
    const GridFields& G = s.fields;
    const bool musl = scheme == Scheme::MUSL;
    advance_interfaces(s, musl ? G.remap_x.data() : G.vel_x.data(), musl ? G.remap_y.data() : G.vel_y.data());
  });
}

void tie_and_face_stencils(const Levels& L) {
  each(L, [](State& s) {
    if (s.bonded.empty() && s.interfaces.empty()) return;
    CohesiveTimer timer(s);
    tie_bonded_nodes(s, TieWhat::mass_momentum);
    if (s.interfaces.empty()) return;
    update_face_stencils(s);
    check_faces_in_reach(s);  // distributed: faces within this rank's halo
  });
}

void cohesive_forces_and_ties(const Levels& L) {
  each(L, [](State& s) {
    if (s.bonded.empty() && s.interfaces.empty()) return;
    CohesiveTimer timer(s);
    if (!s.interfaces.empty()) {
      halo_save(s, kForce);
      add_cohesive_forces(s);     // E7-E9 (distributed: each rank its owned faces',
      halo_sum_added(s, kForce);  // summed over the ranks)
    }
    tie_bonded_nodes(s, TieWhat::force);
  });
}

// A gather that may find a bad particle: on several processes the diagnosis waits for the end
// of the step (every rank takes part in the step's exchanges, then all stop together).
void gather(const Levels& L, NodalArray gx, NodalArray gy, G2PMode mode) {
  State& first = L.first();
  if (!first.halo) return grid_to_particles(L.level, L.count, gx, gy, mode);
  try {
    grid_to_particles(L.level, L.count, gx, gy, mode);
  } catch (const SimulationError& e) {
    if (first.halo->failure.empty()) first.halo->failure = e.what();
  }
}

void begin_level_step(State& s, const std::vector<int>& base_lines, bool resort) {
  if (resort) {
    build_scatter_plan(s);
    fit_field_windows(s);  // every field's window covers its particles, faces and ties
  }
  if (update_edge_lines(s.boundary, base_lines, s.grid, s.time, s.bc_lines))
    s.bc_nodes = resolve_nodes(s.boundary, s.grid, s.fields.num_fields, s.bc_lines);
  prepare_loads(s);  // loaded particles after a sort, region nodes at t^n
}

void step_levels(const Levels& L, Scheme scheme) {
  switch (scheme) {
    case Scheme::MUSL:
      step_musl(L);
      break;
    case Scheme::USL:
      step_usl(L);
      break;
    case Scheme::USF:
      step_usf(L);
      break;
  }
  end_step(L, scheme);
}

}  // namespace detail

void step(State& s) {
  migrate_if_due(s);  // distributed: particles that left their rank's block move to its owner
  thread_local std::vector<int> base;  // the single grid's edges start on its initial lines
  initial_lines(s.boundary, s.grid, base);  // no allocation once sized
  detail::begin_level_step(s, base, true);
  const double drift_at_start = s.plan.drift;  // the re-sort's (fit_field_windows leaves it)
  State* const one[] = {&s};
  detail::step_levels(Levels{one, 1, nullptr}, s.scheme);
  finish_distributed_step(s, drift_at_start);  // migration bound; a failure on any rank stops all
}

void step(RunState& r) {
  for (State& l : r.levels) l.dt_cap = r.dt_cap, l.forced_dt = r.forced_dt;
  if (!r.is_nested()) {  // one grid: its level is the run
    try {
      step(r.levels[0]);
    } catch (...) {
      collect_run_sums(r);  // what the step did before it stopped (the record reads it)
      throw;
    }
    collect_run_sums(r);
    return;
  }
  step_nested(r);  // the levels and their transitions (solver/nested_state.hpp)
  collect_run_sums(r);
  // The record's limits: the smallest cohesive limits of the levels holding interfaces.
  double cohesive_dt = INFINITY;
  for (const State& l : r.levels) {
    r.limits.min_cohesive_dt = std::min(r.limits.min_cohesive_dt, l.limits.min_cohesive_dt);
    if (!l.interfaces.empty()) cohesive_dt = std::min(cohesive_dt, l.limits.cohesive_dt);
  }
  if (r.num_interfaces() > 0) r.limits.cohesive_dt = cohesive_dt;
}

}  // namespace rupture
