// rupture/solver/nested_state.hpp
// The time step on nested refinement levels (grid/nested.hpp, theory §5): one State per level
// (its uniform lattice, the particles whose centres it owns, every field over the whole
// lattice, the velocity conditions of the domain edges it reaches) and the same phases as the
// single-grid step (solver/step.cpp, theory E4-E5) run level by level, with the levels joined
// at the transition nodes: after every scatter the slaves' mass, momentum and force are
// condensed onto their DOFs, before every gather the slaves take their DOFs' velocities.
// Every level steps with the same dt (the smallest of the levels' limits), or, with
// time.subcycling = "levels", each at its own (solver/nested_subcycle.cpp). Particles whose
// centre crosses into another level's region move there at the start of a step (batched:
// kMigrateDrift), keeping their size (uGIMP); one from two or more levels coarser would break
// the GIMP contract and stops the run with a diagnosis.
// Each cohesive interface lies on one level (the finest holding it whole; different
// interfaces may lie on different levels); bonded stretches are tied on every level. [loads] act on every level (each lists the loaded particles by the run's
// ids; forces added before the transitions condense them). Absorbing edges damp on every level
// reaching them, their slaves' dashpots moved to their DOFs (as their mass). Not yet supported
// here (make_nested_state throws InputError naming them): per-level steps with [loads],
// [absorbing], USL/USF or interfaces on more than one level, a grid without boxes (and, under
// mpirun, interfaces on more than one level: parallel/halo_nested.cpp). The levels and the
// transitions are a RunState (solver/run_state.hpp), as one grid is, so the driver and the
// writers run unchanged.
#pragma once
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "grid/nested.hpp"
#include "solver/run_state.hpp"

namespace rupture {

// Particles move to the level owning their centre once any may have moved this many cells of
// the finest level since the last move (solver/nested_state.cpp).
inline constexpr double kMigrateDrift = 0.25;
// Covered nodes this many cells of their level inside the finer level's rectangle are never
// reached by their level's particles (RunState::active_slaves).
inline constexpr int kInactiveDepth = 3;
// With per-level time steps particles change level only when every level ends its step
// together; every level ends its step once any may have drifted this fraction of
// kMigrateDrift (a coarse level's step moves its particles by up to its period's worth).
inline constexpr double kSubcycleDrift = 0.5;

// make_state (solver/state.hpp) on a level's lattice: every body seeded through its region on
// `lattice`, keeping the particles whose centre `keep` accepts, ids their index among those;
// no boundary conditions. With `own`, only the kept particles `own` accepts are made (ids as
// without it).
State make_level_state(const Case& c, Grid lattice, const std::function<bool(double, double)>& keep,
                       const std::function<bool(double, double)>* own = nullptr);

// InputError naming grid.refinement when the case holds what nested levels do not support yet
// (rupture check and rupture run refuse it at input: input/case_checks).
void check_nested_support(const Case& c);

// The levels of c.grid's boxes, their states and the transitions (make_run_state's nested
// branch; each interface on the level holding it, RunState::interface_levels) (with `share`, each level's share of its
// particles, ParticleShare::own_level; the sums over particles, mass floor included, are then this process's). Throws
// InputError for what the nested step does not support yet, and for a velocity condition on an
// edge that is not on a lattice line of a level reaching it.
RunState make_nested_state(const Case& c, const ParticleShare* share = nullptr);

// Visits level l's particles at t = 0 as make_nested_state seeds them, in their order (their
// centres, m, and masses, kg per unit thickness), without making them.
void for_each_level_point(const Case& c, const RunState& n, int l,
                          const std::function<void(double, double, double)>& visit);

// One time step (c.solver.scheme) on every level of nested levels (step(RunState&) calls it).
void step_nested(RunState& n);

// Before the step's particle move, the levels' drift bounds (the move adds to them; a level
// whose step goes on adds nothing): what a distributed step's end grows by the largest move
// over the ranks (RankExchange::finish_nested_step).
struct NestedDrift {
  std::vector<double> window_drift;  // per level, before the particle move, m
};
NestedDrift nested_drift_before(RunState& n);

}  // namespace rupture
