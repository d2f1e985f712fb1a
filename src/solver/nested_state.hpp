// rupture/solver/nested_state.hpp
// The time step on nested refinement levels (grid/nested.hpp, SPEC §5): one State per level
// (its uniform lattice, the particles whose centres it owns, every field over the whole
// lattice, the velocity conditions of the domain edges it reaches) and the same phases as the
// single-grid step (solver/step.cpp, SPEC E4-E5) run level by level, with the levels joined
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
// mpirun, interfaces on more than one level: parallel/halo_nested.cpp). The run's State wraps the levels (make_state), so the driver and writers
// run unchanged.
#pragma once
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "grid/nested.hpp"
#include "solver/state.hpp"

namespace rupture {

// Particles move to the level owning their centre once any may have moved this many cells of
// the finest level since the last move (solver/nested_state.cpp).
inline constexpr double kMigrateDrift = 0.25;
// Covered nodes this many cells of their level inside the finer level's rectangle are never
// reached by their level's particles (NestedState::active_slaves).
inline constexpr int kInactiveDepth = 3;
// With per-level time steps particles change level only when every level ends its step
// together; every level ends its step once any may have drifted this fraction of
// kMigrateDrift (a coarse level's step moves its particles by up to its period's worth).
inline constexpr double kSubcycleDrift = 0.5;

// A level's scatter held while its step spans several finest steps, and the velocity
// increments summed over it (per field node of its lattice, as GridFields). Scratch: a step
// that spans several finest steps never spans an output or checkpoint time.
struct LevelHold {
  std::vector<double> mass, mom_x, mom_y, force_x, force_y;  // kg, kg m/s, N
  std::vector<double> inc_x, inc_y;                          // m/s
  double span = 0.0;                                         // the step so far, s
  // The level's particles whose stencil reaches a node of NestedState::mixed (found when its
  // step begins): their re-mapped momentum is needed while the step goes on.
  std::vector<std::uint32_t> band;
};

struct NestedState {
  NestedGrid grid;
  std::vector<State> levels;  // coarsest first
  // The slaves and their terms of grid (same order) as (level, node of that level).
  std::vector<std::uint8_t> slave_level, term_level;
  std::vector<std::uint32_t> slave_node, term_node;
  // The slaves a particle of their level can reach (indices into grid.slaves, ascending):
  // all but covered nodes kInactiveDepth or more cells of their level inside the finer
  // rectangle. The others stay zero (no particle of their level gets within two cells of
  // them: particles change level once they may have drifted a quarter of a finest cell, and a
  // stencil reaches 1.5 cells), so condense and distribute skip them.
  std::vector<std::uint32_t> active_slaves;
  // The terms of the active slaves by DOF (condense): DOF d at (dof_level[d], dof_node[d])
  // takes dof_c[j] times slave dof_slave[j] for j in [dof_start[d], dof_start[d + 1]), slaves
  // ascending.
  std::vector<std::uint8_t> dof_level;
  std::vector<std::uint32_t> dof_node, dof_start, dof_slave;
  std::vector<double> dof_c;
  // Per level, per velocity condition of that level: its edge line at t = 0 (node index).
  std::vector<std::vector<int>> base_lines;
  double time = 0.0;  // s
  double dt = 0.0;    // the last step's, s
  long step = 0;
  long migrations = 0;  // particles moved between levels so far
  // interface_levels[k]: the level of the run's interface k (input order; holds_interfaces).
  // A level holds its interfaces during a step only (step_nested_run lends them); between
  // steps they are the run State's.
  std::vector<int> interface_levels;
  // Per-level time steps (time.subcycling = "levels"): level l takes one step every period[l]
  // finest steps (all 1 without them). substep: finest steps since every level last ended a
  // step together (0: all at one time; checkpoints and outputs only then).
  std::vector<int> period;
  int substep = 0;
  double sync_by = INFINITY;  // every level ends its step at the first finest step ending at or
                              // after this time (the driver's next output), s
  std::vector<LevelHold> hold;  // per level
  // Per level, per lattice node: 1 where the node's DOFs are also reached through a finer
  // level's lattice (its DOFs, or the terms of its active slaves): there a finer level's
  // particles may read the re-mapped velocity while this level's step goes on.
  std::vector<std::vector<unsigned char>> mixed;
  // Per level, per lattice node (i, j): 1 where a 3 x 3 stencil whose first node is (i, j)
  // reaches a mixed node (so finding the band is one lookup per particle).
  std::vector<std::vector<unsigned char>> mixed_reach;
  // Per level with period > 1, the elements (node and field, every field) its arrays must hold
  // up to date at every finest step while its step goes on: the DOFs with condensed terms and
  // the active slaves (what other levels read and write), the nodes within two of a mixed one
  // that is not an inactive slave (the band's stencils), and the bonded stretches' nodes;
  // ascending, and as a mask. Elsewhere nothing changes during its step (held scatter, no other
  // level's terms), so those nodes are updated once, when its step ends, over the whole span
  // (solver/nested_subcycle.cpp).
  std::vector<std::vector<std::uint32_t>> coupled;
  std::vector<std::vector<unsigned char>> coupled_mask;

  bool subcycled() const;
  bool synchronized() const { return substep == 0; }
  bool holds_interfaces(int level) const;  // some interface lies on this level

  std::size_t num_particles() const;
  double external_work() const;  // J per unit thickness, summed over the levels
};

// make_state (solver/state.hpp) on a level's lattice: every body seeded through its region on
// `lattice`, keeping the particles whose centre `keep` accepts, ids their index among those;
// no boundary conditions. With `own`, only the kept particles `own` accepts are made (ids as
// without it).
State make_level_state(const Case& c, Grid lattice, const std::function<bool(double, double)>& keep,
                       const std::function<bool(double, double)>* own = nullptr);

// The run's interfaces (s.interfaces, input order) to the levels holding them, each level's in
// input order, and back: a level's step and its share of a split see its own interfaces only.
void lend_interfaces(State& s);
void return_interfaces(State& s);

// InputError naming grid.refinement when the case holds what nested levels do not support yet
// (rupture check and rupture run refuse it at input: input/case_checks).
void check_nested_support(const Case& c);

// The levels of c.grid's boxes and their states (with `share`, each level's share of its
// particles, ParticleShare::own_level; the sums over particles, mass floor included, are then this process's). Throws
// InputError for what the nested step does not support yet, and for a velocity condition on an
// edge that is not on a lattice line of a level reaching it.
NestedState make_nested_state(const Case& c, const ParticleShare* share = nullptr);

// Visits level l's particles at t = 0 as make_nested_state seeds them, in their order (their
// centres, m, and masses, kg per unit thickness), without making them.
void for_each_level_point(const Case& c, const NestedState& n, int l,
                          const std::function<void(double, double, double)>& visit);

// One time step (c.solver.scheme) on every level.
void step(NestedState& n);

// Before the step's particle move, the levels' drift bounds (the move adds to them; a level
// whose step goes on adds nothing): what a distributed step's end grows by the largest move
// over the ranks (RankExchange::finish_nested_step).
struct NestedDrift {
  std::vector<double> window_drift;  // per level, before the particle move, m
};
NestedDrift nested_drift_before(NestedState& n);

// One step of s.nested (step(State&) calls it), then the clock, energies and limits of s.
void step_nested_run(State& s);
// Whether every particle of the run is at the run's time (always, but between the finest steps
// of a coarser level's step with per-level time steps): outputs and checkpoints wait for it.
bool synchronized(const State& s);
// Merges every level's particles into s.particles, once per step (a no-op for other runs).
void merge_level_particles(State& s);
// This process's particles (a nested run's: on every level, whether gathered or not).
std::size_t held_particles(const State& s);

}  // namespace rupture
