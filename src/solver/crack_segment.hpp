// rupture/solver/crack_segment.hpp
// One grown segment of a crack drawn inside one body (solver/crack_growth.hpp decides where):
// the interface gets the segment, the tie beyond the tip becomes the new cut's stretches inside
// the body (the segment's straight extension; with several cracks in the body, two cells along
// it and on in the tie's old direction, so ties drawn apart stay apart), and the particles
// between the old cut and the new one change field on every level. Units: m.
#pragma once
#include <cstddef>
#include <vector>

#include "cohesive/interface_growth.hpp"
#include "input/case.hpp"
#include "solver/state.hpp"

namespace rupture {

// One segment on level L's interface `slot` at `tip`, ending at (x, y) (reference position):
// the interface, the tie and, with flip_particles, the wedge's particles. `tip` as
// precrack_tips gives it with chord 0: its direction is the end piece's, along which the old
// extension runs. Returns whether the tip reached the body's edge (no tie left there). For
// tests, grow_cracks and regrow_cracks (solver/crack_growth.hpp). On nested levels `others` are the run's other levels: their
// particles change sides with L's, and their tie of the interface follows the new one (every
// level ties every interface's bonded stretches on its own lattice, in the run's order).
// `tie`: the interface's entry in every level's State::bonded; kCaseTie: its slot on one grid,
// the case's interface k on nested levels (a branch's is its index among the run's interfaces,
// RunState::interface_levels).
constexpr std::size_t kCaseTie = std::size_t(-1);
bool add_crack_segment(const Case& c, std::size_t k, State& L, std::size_t slot,
                       const CrackTip& tip, double x, double y, bool flip_particles,
                       const std::vector<State*>& others = {}, std::size_t tie = kCaseTie);

}  // namespace rupture
