// rupture/parallel/halo_nested.hpp
// Nested refinement levels (solver/nested_state.hpp) in a distributed run (parallel/halo.hpp).
// Every level shares one split of the plate: a lattice of the cut level's cells over the whole
// plate bisected by the particles of all levels (by their centres), so rank r's block is the
// same rectangle on every level as fine as the cut level, and on coarser ones the rectangle
// with its sides moved down to the level's lines (grid/nested.hpp: a level's lattice lines lie
// at multiples of its cell from the domain's corner). Each level keeps its own Halo (its
// lattice, the block in its cells, its reach), so the transitions between levels stay local:
//  - After each scatter every level's halo sum, then the condense. A DOF's condensed value is
//    the one-process value when every active slave feeding it is fully summed on this rank; a
//    slave's distributed value when every DOF it reads is condensed so. Each rank's reach on
//    each level is the box that holds, for every node its particles may touch
//    (nested_touched_width), the DOFs of the node's slaves and the slaves of those DOFs and of
//    the node itself (nested_reaches). Nodes beyond hold values no particle of this rank reads.
//  - Particles change level when the drift bound over all ranks says so (every rank on the step
//    one process would), then go to the rank owning their cell on the new level; they change
//    rank, on every level at once, once any may have moved kMigrateCells of the finest cell.
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

// The split is made on the lattice of the finest level whose cells over the whole plate number
// at most kCutLatticeCells (a count per cell at set-up): fine enough to divide a refined band
// among many ranks, coarse enough to count.
inline constexpr long kCutLatticeCells = 1L << 22;

struct NestedSplit {
  int cut_level = 0;                            // the lattice cut: level cut_level's lines
  Decomposition cut;                            // its cells over the plate, every level's particles
  std::vector<std::vector<CellBlock>> blocks;   // per level, per rank: the block in its cells
  std::vector<std::vector<NodeBox>> reaches;    // per level, per rank: the nodes it holds summed
};

// The cut level (above), and the particles of every level per cell of its lattice over the
// plate (c + r cols, level 0's extent), by their centres; with per-level time steps each
// weighted by its level's steps per longest period (its work).
int nested_cut_level(const RunState& n);
std::vector<std::uint32_t> nested_cut_count(const RunState& n, int cut_level);
// The same count from the particles the case seeds (solver/nested_state.hpp:
// for_each_level_point), without making them; with each level's particle count (one process's)
// and the lightest particle's mass, kg per unit thickness.
struct NestedTally {
  std::vector<std::uint32_t> cut_count, per_level;
  double min_mass = 0.0;
};
NestedTally nested_seed_tally(const Case& c, const RunState& n, int cut_level);
// The split of this process's particles (at set-up: all of them) among `ranks`, each level's
// blocks and reaches. Throws InputError when the cut lattice has fewer cells than ranks.
NestedSplit split_nested(const RunState& n, int ranks);
// The same from a count on the cut lattice (nested_cut_count, nested_seed_tally).
NestedSplit split_nested(const RunState& n, const std::vector<std::uint32_t>& count, int cut_level, int ranks);
// Level l's cells of a block of the cut lattice: exact on levels at least as fine; on coarser
// ones each cut moves down to the level's line below it (empty where the level does not reach).
CellBlock level_block(const NestedGrid& g, int l, const CellBlock& cut, int cut_level);
// The nodes beyond its block a rank's particles of level l may touch: kHaloNodes on the finest
// level, 1 on coarser ones (a particle strays at most one finest cell, half of their cell),
// kInterfaceHaloNodes on the interfaces' level.
int nested_touched_width(const RunState& n, int l);
// Per level, per rank: the smallest box of nodes that holds what the rank's particles may touch
// (its block and nested_touched_width; nothing on a level without a cell in the block) and
// closes the transitions over it (`blocks`: per level, per rank).
std::vector<std::vector<NodeBox>> nested_reaches(const RunState& n,
                                                 const std::vector<std::vector<CellBlock>>& blocks);

// parallel/halo.hpp's distribute for nested levels: every level split as above and this
// rank's particles kept on each; n.halo is the grid level's halo (RunState::grid_level).
void distribute_nested(RunState& n, const Comm& comm, bool fresh, const NestedSplit* split = nullptr);

// distribute_held (parallel/halo.hpp) for nested levels: each rank holds some of every level's
// particles (a resume: some of the checkpoint's parts) with their keys per level; the cut
// lattice's counts bisected over the ranks, each particle sent to its level's block's rank,
// received ones in key order per level, then distribute_nested with that split.
void distribute_held_nested(RunState& n, const Comm& comm, const std::vector<std::vector<double>>& keys);

// make_rank_state (parallel/halo.hpp) for nested levels: the levels made once without particles
// (the split's lattices and transitions), the case's seed points counted on the cut lattice
// (nested_seed_tally), the split made from that count, and each level's particles in this
// rank's block made with the ids one process gives them; no rank holds the case's particles.
RunState make_nested_rank_state(const Case& c, const Comm& comm);


// The nested step's exchanges (solver/nested_state.cpp's step calls them through
// solver/rank_exchange.hpp on level 0's halo; distributed runs only):
// Halo::migrate_levels_if_due: at the start, once due, every level's particles that left the
// block go to its rank;
// Halo::send_to_level_owners: after particles changed level, each one whose cell on its new
// level is another rank's goes there (on levels coarser than the cut level a block's sides move
// down to the level's lines, so the owner may differ; collective: all ranks);
// Halo::finish_nested_step: at the end, each level's drift bound (from nested_drift_before,
// solver/nested_state.hpp) grows by the largest move over the ranks (so the next level change
// comes on the step one process would take it), the rank-move bound by the largest of them; a
// failure on any rank (kept in its level 0 halo's `failure`) stops all.

}  // namespace rupture
