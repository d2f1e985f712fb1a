// rupture/solver/levels.hpp
// The levels one time step runs over. A single grid is one level without transitions; nested
// refinement (solver/nested_state.hpp, theory §5) is several uniform lattices joined at their
// transition nodes. The update schemes (solver/step.cpp) are written once over this view: every
// phase runs level by level, and the transitions' two operations are no-ops on one grid:
//   condense_to_dofs: after a scatter, each slave node's extensive values (mass, momentum,
//                     force) are added to the DOFs it depends on, times its coefficients, and
//                     the slave is cleared (the transpose of spread_to_slaves: what is
//                     scattered is kept, so mass and momentum are conserved);
//   spread_to_slaves: before a gather, each slave takes the combination of its DOFs' values
//                     (velocities), so a particle reading a slave reads its DOFs.
// (Not to be confused with the split over ranks: parallel/, where shared nodes are summed.)
#pragma once
#include <cstddef>
#include <initializer_list>

#include "solver/state.hpp"
#include "solver/transfer.hpp"

namespace rupture {

struct RunState;  // solver/run_state.hpp

struct Levels {
  State* const* level = nullptr;  // coarsest first
  std::size_t count = 0;
  RunState* nested = nullptr;  // the transitions; null: one grid
  State& operator[](std::size_t l) const { return *level[l]; }
  State& first() const { return *level[0]; }
  State* const* begin() const { return level; }
  State* const* end() const { return level + count; }
};

// The transitions over the levels' arrays (every field); no-ops when L.nested is null.
void condense_to_dofs(const Levels& L, std::initializer_list<NodalArray> arrays);
// The loads' nodal forces (LoadState::ext_fx, ext_fy: laid out as the fields), condensed as
// the force is, so their work (E14) is counted at the DOFs the force acts on.
using LoadArray = std::vector<double> LoadState::*;
void condense_to_dofs(const Levels& L, std::initializer_list<LoadArray> arrays);
void spread_to_slaves(const Levels& L, std::initializer_list<NodalArray> arrays);

}  // namespace rupture
