// rupture/solver/nested_phases.hpp
// The phases of the time step on nested levels (solver/nested_state.hpp), shared by the
// step with one dt for every level (solver/nested_step.cpp) and the step with a dt per level
// (solver/nested_subcycle.cpp). Internal to solver/.
#pragma once
#include <functional>
#include <initializer_list>
#include <vector>

#include "solver/nested_state.hpp"
#include "solver/transfer.hpp"

namespace rupture::detail {

using rupture::NodalArray;

// grid/nested.hpp's condense over the levels' arrays (every field): the active slaves' values
// added to their DOFs times the coefficients, then cleared. Extensive values only.
void condense_fields(NestedState& n, std::initializer_list<NodalArray> arrays);
// grid/nested.hpp's distribute: every active slave takes the combination of its DOFs.
void distribute_fields(NestedState& n, std::initializer_list<NodalArray> arrays);

// Distributed runs (parallel/halo_nested.hpp): each level's shared nodes summed over the ranks
// that reach them (parallel/halo.hpp's halo_sum), before the transitions combine the levels.
void sum_levels(NestedState& n, std::initializer_list<NodalArray> arrays);
// A gather that may find a bad particle; distributed, the diagnosis waits for the end of the
// step (nested_finish_step), as every rank takes part in the step's exchanges.
void gather_levels(NestedState& n, const std::function<void()>& gather);

// Every level's State, for the scatters that run over all levels at once.
std::vector<State*>& level_pointers(NestedState& n);

// After the condensed scatter: bonded stretches tied (on every level they cross) and the face
// stencils of each interface (on its level) with this step's masses.
void tie_and_face_stencils(NestedState& n);
// E7-E9 on the interface's level, then the bonded ties of the forces on every level.
void cohesive_forces_and_ties(NestedState& n);

// One step with one dt (the smallest of the levels' limits) for every level.
void step_musl(NestedState& n);
void step_usl(NestedState& n);
void step_usf(NestedState& n);
// One finest step of the levels stepping at their own dt (time.subcycling = "levels"), MUSL.
void step_subcycled(NestedState& n);

}  // namespace rupture::detail
