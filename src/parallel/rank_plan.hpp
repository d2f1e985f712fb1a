// rupture/parallel/rank_plan.hpp
// A run's split between N processes, from its State at t = 0 (parallel/decomposition.hpp):
// the grid's cells bisected by particle count (nested levels: level 0's cells by every level's
// particles, one split for all: parallel/halo_nested.hpp), and the work each rank would get. With per-level time steps a level steps once every period[l]
// finest steps, so a rank's work is sum over levels of its particles / period. `rupture check
// --ranks N` prints it.
#pragma once
#include <vector>

#include "parallel/decomposition.hpp"
#include "parallel/halo.hpp"
#include "solver/state.hpp"

namespace rupture {

struct LevelSplit {
  int cols = 0, rows = 0;  // the lattice's cells (ghost cells included)
  int period = 1;          // finest steps per step of this level
  int fields = 1;          // velocity fields of the level
  std::vector<NodeBox> reach;  // per rank: the nodes it holds summed (parallel/halo.hpp)
  int width() const;           // the largest reach beyond its block, nodes
  Decomposition split;
};

// Values a MUSL step sums over the ranks per halo node and velocity field (parallel/halo.hpp):
// mass, momentum and force after P2G (5), re-mapped momentum (2); a run with cohesive
// interfaces or [loads] forces also sums the forces they add (2 each). The velocities need no
// exchange: every copy of a node holds the same sums and updates them alike. Nested levels at
// their own time steps sum their scatter once per level step, the re-mapped momentum every
// finest step.
inline constexpr int kExchangedValues = 7;

struct RankPlan {
  int ranks = 1;
  std::vector<LevelSplit> levels;  // one for a graded or uniform grid
  int cut_level = 0;               // nested: the level whose lines the split cuts on
  std::vector<double> work;        // per rank: particle-updates per finest step
  // Per rank: bytes it sends per finest step: 8 x the values above per field and node of its
  // reach shared with each neighbour's (every field counted at every node, as the exchange
  // sends them), and 5 values per interface node a neighbour knows (faces, stiffness).
  std::vector<double> exchange_bytes;
  double imbalance() const;        // largest work / mean - 1
};

// Throws InputError when a lattice has fewer cells than ranks.
RankPlan plan_ranks(const State& s, int ranks);  // one grid
RankPlan plan_ranks(const RunState& r, int ranks);

}  // namespace rupture
