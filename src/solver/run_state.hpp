// rupture/solver/run_state.hpp
// The state of a run, whatever its grid: its levels and, between them, the transitions. A
// uniform or graded grid is one level without transitions; grid.refinement = "nested"
// (grid/nested.hpp, theory §5) is several uniform lattices, coarsest first, joined at their
// transition nodes. Each level is a State (solver/state.hpp: its lattice, particles, fields,
// boundary nodes and the interfaces that lie on it); this struct adds the run's clock and
// sums, which interface is where, and the transitions' tables (empty on one grid).
// make_run_state (solver/setup.cpp) builds it; step(RunState&) (solver/step.hpp) advances it.
// The driver, the writers and the checkpoint read the run through it only. SI units.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "grid/nested.hpp"
#include "solver/state.hpp"

namespace rupture {

// A level's scatter held while its step spans several finest steps, and the velocity
// increments summed over it (per field node of its lattice, as GridFields). Scratch: a step
// that spans several finest steps never spans an output or checkpoint time.
struct LevelHold {
  std::vector<double> mass, mom_x, mom_y, force_x, force_y;  // kg, kg m/s, N
  std::vector<double> inc_x, inc_y;                          // m/s
  double span = 0.0;                                         // the step so far, s
  // The level's particles whose stencil reaches a node of RunState::mixed (found when its
  // step begins): their re-mapped momentum is needed while the step goes on.
  std::vector<std::uint32_t> band;
};

// Every member must also be written in run/checkpoint.cpp, or be listed there as rebuilt from
// the case or per-step scratch.
struct RunState {
  std::vector<State> levels;  // coarsest first; one grid: one level

  // ---- The run: its clock and what the records read.
  double time = 0.0;  // s
  double dt = 0.0;    // the last step's, s
  long step = 0;
  double dt_cap = INFINITY;  // no step goes past this much time (the driver: time to the end), s
  double sync_by = INFINITY;  // per-level steps: every level ends its step at the first finest step
                              // ending at or after this time (the driver: its next output), s
  double forced_dt = 0.0;     // > 0: a fixed step that bypasses E6 (tests of instability only), s
  // The run's step limits as the record reports them: on one grid its level's; on nested
  // levels the coarsest's CFL step, the smallest cohesive limits of the levels holding
  // interfaces.
  StepLimits limits;
  double initial_energy = 0.0;    // kinetic + strain energy at t = 0, J (per unit thickness)
  double strain_work = 0.0;       // E14 (solver/energy.hpp), summed over the levels, J
  double viscous_work = 0.0;      // Kelvin-Voigt dissipation, summed over the levels, J
  double external_work = 0.0;     // work of the prescribed velocities and loads, J
  double cohesive_seconds = 0.0;  // wall time in the cohesive phases so far, s
  // interface_levels[k], interface_slots[k]: the level of the case's interface k (input
  // order) and its index among that level's interfaces (each level's in input order).
  std::vector<int> interface_levels;
  std::vector<std::size_t> interface_slots;
  // The finest level holding an interface (without: the finest): the lattice of what reads
  // one grid (crack trackers' cell widths, checkpoint checks), and whose exchange with the
  // other ranks gathers the interfaces' state.
  std::size_t grid_level = 0;
  // Distributed (MPI): the grid level's exchange (parallel/halo.hpp); null on one process.
  std::shared_ptr<RankExchange> halo;
  // Made without particles for a distributed resume (ParticleShare::none()): the checkpoint
  // brings them, so their count is the file's (derived, not written).
  bool particles_from_checkpoint = false;

  // ---- The transitions between nested levels (grid/nested.hpp); empty on one grid.
  NestedGrid grid;
  // The slaves and their terms of grid (same order) as (level, node of that level).
  std::vector<std::uint8_t> slave_level, term_level;
  std::vector<std::uint32_t> slave_node, term_node;
  // The slaves a particle of their level can reach (indices into grid.slaves, ascending):
  // all but covered nodes kInactiveDepth or more cells of their level inside the finer
  // rectangle. The others stay zero (no particle of their level gets within two cells of
  // them: particles change level once they may have drifted a quarter of a finest cell, and a
  // stencil reaches 1.5 cells), so condense and spread skip them.
  std::vector<std::uint32_t> active_slaves;
  // The terms of the active slaves by DOF (condense): DOF d at (dof_level[d], dof_node[d])
  // takes dof_c[j] times slave dof_slave[j] for j in [dof_start[d], dof_start[d + 1]), slaves
  // ascending.
  std::vector<std::uint8_t> dof_level;
  std::vector<std::uint32_t> dof_node, dof_start, dof_slave;
  std::vector<double> dof_c;
  // Per level, per velocity condition of that level: its edge line at t = 0 (node index).
  std::vector<std::vector<int>> base_lines;
  long migrations = 0;  // particles moved between levels so far
  // Per-level time steps (time.subcycling = "levels"): level l takes one step every period[l]
  // finest steps (all 1 without them). substep: finest steps since every level last ended a
  // step together (0: all at one time; checkpoints and outputs only then).
  std::vector<int> period;
  int substep = 0;
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

  // ---- What the writers read of nested levels: every level's particles in one array, as of
  // step merged_step (all_particles; scratch, not checkpointed).
  Particles merged;
  long merged_step = -1;
  // &levels[l] for every level: what detail::levels_of's views point into (scratch, laid again
  // only when the levels have moved, so a view stays valid while another is taken).
  std::vector<State*> level_pointers;

  bool is_nested() const { return !grid.levels.empty(); }  // nested levels (else one grid)
  bool subcycled() const;
  bool synchronized() const { return substep == 0; }
  bool holds_interfaces(int level) const;  // some interface lies on this level

  std::size_t num_interfaces() const { return interface_levels.size(); }
  CohesiveInterface& interface(std::size_t k) {
    return levels[std::size_t(interface_levels[k])].interfaces[interface_slots[k]];
  }
  const CohesiveInterface& interface(std::size_t k) const {
    return levels[std::size_t(interface_levels[k])].interfaces[interface_slots[k]];
  }
  const Grid& run_grid() const { return levels[grid_level].grid; }
  const std::vector<ElasticStiffness>& stiffness() const { return levels[0].stiffness; }
  Scheme scheme() const { return levels[0].scheme; }
};

// Every particle of the run, in level order (one grid: its level's; nested levels: merged
// once per step into r.merged).
const Particles& all_particles(RunState& r);
// This process's particles, on every level.
std::size_t held_particles(const RunState& r);
// Whether every particle of the run is at the run's time (always, but between the finest steps
// of a coarser level's step with per-level time steps): outputs and checkpoints wait for it.
inline bool synchronized(const RunState& r) { return r.synchronized(); }
// The run's clock, sums and limits from its levels (after a step, a split or a restore).
void collect_run_sums(RunState& r);

// The set-up, for every grid (uniform, graded, nested levels): the levels (each with its
// particles: every one, or `share`'s; stiffnesses, boundary nodes, interfaces, loads, time
// step) and the transitions, from a validated case. The one entry point for one process and
// (with a share: parallel/halo.hpp, make_rank_state) for a rank of a distributed run.
RunState make_run_state(const Case& c, const ParticleShare* share = nullptr);

}  // namespace rupture
