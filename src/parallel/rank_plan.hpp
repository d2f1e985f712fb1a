// rupture/parallel/rank_plan.hpp
// A run's split between N processes, from its State at t = 0 (parallel/decomposition.hpp):
// each lattice's cells (the grid's, or each nested level's) bisected by particle count, and
// the work each rank would get. With per-level time steps a level steps once every period[l]
// finest steps, so a rank's work is sum over levels of its particles / period. `rupture check
// --ranks N` prints it.
#pragma once
#include <vector>

#include "parallel/decomposition.hpp"
#include "solver/state.hpp"

namespace rupture {

struct LevelSplit {
  int cols = 0, rows = 0;  // the lattice's cells (ghost cells included)
  int period = 1;          // finest steps per step of this level
  int fields = 1;          // velocity fields of the level
  Decomposition split;
};

// Values a MUSL step exchanges per shared node and velocity field: mass, momentum and force
// summed into the owner after P2G (5), velocity and its increment copied to the others after
// the grid update (4), re-mapped momentum summed (2) and re-mapped velocity copied (2).
inline constexpr int kExchangedValues = 13;

struct RankPlan {
  int ranks = 1;
  std::vector<LevelSplit> levels;  // one for a graded or uniform grid
  std::vector<double> work;        // per rank: particle-updates per finest step
  // Per rank: bytes it sends and receives per finest step, 8 x kExchangedValues per shared
  // node and field (every field counted at every shared node: an upper bound).
  std::vector<double> exchange_bytes;
  double imbalance() const;        // largest work / mean - 1
};

// Throws InputError when a lattice has fewer cells than ranks.
RankPlan plan_ranks(const State& s, int ranks);

}  // namespace rupture
