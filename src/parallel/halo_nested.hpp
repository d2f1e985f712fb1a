// rupture/parallel/halo_nested.hpp
// Nested refinement levels (solver/nested_state.hpp) in a distributed run (parallel/halo.hpp).
// Every level shares one split of the plate: level 0's cells bisected by the particles of all
// levels (by their centres), so rank r's block is the same rectangle on every level, cut on
// coarse lines, which are lines of every level (grid/nested.hpp: a level's lattice lines lie at
// multiples of its cell from the domain's corner). Each level keeps its own Halo (its lattice,
// the block in its cells, its reach), so a particle that changes level stays on its rank and
// the transitions between levels stay local:
//  - After each scatter every level's halo sum, then the condense. A DOF's condensed value is
//    the one-process value when every active slave feeding it is fully summed on this rank; a
//    slave's distributed value when every DOF it reads is condensed so. Each rank's reach on
//    each level is the box that holds, for every node its particles may touch
//    (nested_touched_width), the DOFs of the node's slaves and the slaves of those DOFs and of
//    the node itself (nested_reaches). Nodes beyond hold values no particle of this rank reads.
//  - Particles change level when the drift bound over all ranks says so (every rank on the step
//    one process would), and change rank, on every level at once, once any may have moved
//    kMigrateCells of the finest cell.
//  - Sums that count a node once count it on the rank whose block holds it.
// Per-level time steps (time.subcycling = "levels"): a level's held scatter is summed when its
// step begins, every level's re-mapped momentum every finest step; particles change rank only
// when every level begins a step.
#pragma once
#include <cstdint>
#include <vector>

#include "parallel/comm.hpp"
#include "parallel/decomposition.hpp"
#include "parallel/halo.hpp"
#include "solver/nested_state.hpp"

namespace rupture {

struct NestedSplit {
  Decomposition coarse;                         // level 0's cells, particles of every level
  std::vector<std::vector<CellBlock>> blocks;   // per level, per rank: the block in its cells
  std::vector<std::vector<NodeBox>> reaches;    // per level, per rank: the nodes it holds summed
};

// Particles of every level per cell of level 0 (c + r cols), by their centres; with per-level
// time steps each weighted by its level's steps per longest period (its work).
std::vector<std::uint32_t> nested_coarse_count(const NestedState& n);
// The split of `count` (nested_coarse_count, summed over the ranks) among `ranks`, each
// level's blocks and reach widths. Throws InputError when level 0 has fewer cells than ranks.
NestedSplit split_nested(const NestedState& n, const std::vector<std::uint32_t>& count, int ranks);
// Level l's cells of a block of level 0's cells (empty where the level does not reach).
CellBlock level_block(const NestedGrid& g, int l, const CellBlock& coarse);
// The nodes beyond its block a rank's particles of level l may touch: kHaloNodes on the finest
// level, 1 on coarser ones (a particle strays at most one finest cell, half of their cell),
// kInterfaceHaloNodes on the interfaces' level.
int nested_touched_width(const NestedState& n, int l);
// Per level, per rank: the smallest box of nodes that holds what the rank's particles may touch
// (its block and nested_touched_width; nothing on a level without a cell in the block) and
// closes the transitions over it (`blocks`: per level, per rank).
std::vector<std::vector<NodeBox>> nested_reaches(const NestedState& n,
                                                 const std::vector<std::vector<CellBlock>>& blocks);

// parallel/halo.hpp's distribute for a nested run State (s.nested): every level split as
// above and this rank's particles kept on each; s.halo is the interfaces' level's halo (the
// finest level's without interfaces).
void distribute_nested(State& s, const Comm& comm, bool fresh);

// In the nested step (solver/nested_state.cpp), distributed runs only (no-ops otherwise):
// at the start, once due, every level's particles that left the block go to its rank;
struct NestedDrift {
  std::vector<double> window_drift;  // per level, before the particle move
};
void nested_migrate_ranks_if_due(NestedState& n);
// before the step's particle move, the levels' drift bounds (the move adds to them; a level
// whose step goes on adds nothing);
NestedDrift nested_drift_before(NestedState& n);
// at the end: each level's drift bound grows by the largest move over the ranks (so the next
// level change comes on the step one process would take it), the rank-move bound by the
// largest of them; a failure on any rank (kept in its level 0 halo's `failure`) stops all.
void nested_finish_step(NestedState& n, const NestedDrift& before);

}  // namespace rupture
