// rupture/solver/crack_branching.hpp
// A growing crack's tip splits in two (interface.NAME.branching; docs/fracture.md, "Branching";
// the decision: fracture/branching_criterion.hpp). The body around the tip, split so far into
// the part left of the crack (L) and the part right of it (R), tied beyond the tip, becomes
// three parts: L, the wedge W between the two new tips' cuts, and R.
//  - The crack's tie beyond the tip goes: the tip is a junction and grows no more.
//  - Two new cracks (interfaces on the same level, after every other) start at the tip: the
//    left branch between L (upper, left of its direction) and W, the right one between W and
//    R, each with one segment to its first vertex and a tie straight on beyond it (their lines
//    and cuts then grow as any crack's, solver/crack_growth.hpp). Both copy the crack's law and
//    growth; their nodes start with the tip node's displacement on both faces (the material
//    there was intact), their segments separated on a pre-crack and intact on a cohesive crack.
//  - W is the crack's next kept field (InterfaceSpec::branch_fields): the particles of L and R
//    between the two cuts (by reference position) move to it.
// The caller registers the new interfaces in the RunState (interface_levels, interface_slots)
// after the case's, so that they are in the energy balance, the interface files and
// checkpoints; their growth is recorded in the parent crack's CrackGrowthRecord (tip labels
// 2, 3, ...; solver/crack_growth.hpp).
// Units: m.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cohesive/interface_growth.hpp"
#include "fracture/branching_criterion.hpp"
#include "input/case.hpp"
#include "solver/state.hpp"

namespace rupture {

// The wave speeds of the material crack k runs in (plane strain or stress as the case).
WaveSpeeds crack_wave_speeds(const Case& c, std::size_t k);

// Splits `tip` of the interface at `slot` of level L (crack k's or one of its branches): left
// branch (counterclockwise from the running direction) to (left_x, left_y),
// right branch to (right_x, right_y) (reference positions, inside the body), the wedge in
// `wedge_field`; with flip_particles the wedge's particles move to it (a restored run takes
// fields from its checkpoint). Returns the slots of the left and right branches on the level.
// Nested levels: `others` are the run's other levels (their particles of the wedge move with
// L's, and every level lays the ties on its own lattice); ties.parent is the split line's entry
// in every level's State::bonded and ties.first_new where the branches' two go (one grid: the
// defaults, its slot and the level's interface count; nested levels: its index among the run's
// interfaces and their count, RunState::interface_levels).
struct BranchTies {
  std::size_t parent = std::size_t(-1), first_new = std::size_t(-1);
};
std::array<std::size_t, 2> split_crack_tip(const Case& c, std::size_t k, State& L, std::size_t slot,
                                           const CrackTip& tip, double left_x, double left_y, double right_x,
                                           double right_y, int wedge_field, bool flip_particles,
                                           const std::vector<State*>& others = {}, BranchTies ties = {});

}  // namespace rupture
