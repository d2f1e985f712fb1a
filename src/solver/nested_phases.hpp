// rupture/solver/nested_phases.hpp
// What the nested levels' steps share with the update schemes of solver/step.cpp: the
// transitions on a RunState (solver/transitions.cpp), the phases of the schemes that the
// per-level time steps (solver/nested_subcycle.cpp) reuse, and the schemes themselves over a
// Levels view. Internal to solver/.
#pragma once
#include <initializer_list>
#include <vector>

#include "solver/levels.hpp"
#include "solver/nested_state.hpp"
#include "solver/transfer.hpp"

namespace rupture::detail {

using rupture::NodalArray;

// solver/levels.hpp's transitions over every level of n.
void condense_to_dofs(RunState& n, std::initializer_list<NodalArray> arrays);
void condense_to_dofs(RunState& n, std::initializer_list<LoadArray> arrays);
void spread_to_slaves(RunState& n, std::initializer_list<NodalArray> arrays);

// The view over every level of n: it points into n.level_pointers, valid until n.levels is
// resized or moved (a later call on n leaves an earlier view as it is).
Levels levels_of(RunState& n);

// solver/step.cpp's phases (each level in turn):
// after the condensed mass scatter, the bonded stretches tied and the face stencils updated;
void tie_and_face_stencils(const Levels& L);
// E7-E9 on the levels holding interfaces (summed over the ranks), then the bonded ties of the
// forces;
void cohesive_forces_and_ties(const Levels& L);
// E5 over L's levels; distributed, a bad particle's diagnosis waits for the end of the step.
void gather(const Levels& L, NodalArray gx, NodalArray gy, G2PMode mode);

// The beginning of a level's step, on one grid and on each nested level: when `resort` (its
// particles have moved since its last step began) the particles re-sorted when due and each
// field's window fitted to them; a driven edge that has moved onto another grid line takes its
// condition with it (E2: the nearest line to where the edge is, from the lines it started on,
// base_lines); the loads' particles after a sort and region nodes at t^n.
void begin_level_step(State& s, const std::vector<int>& base_lines, bool resort);

// One step of the scheme with one dt (the smallest of the levels' limits, theory E6) for every
// level, then the clock and the interfaces advanced (solver/step.cpp).
void step_levels(const Levels& L, Scheme scheme);
// The end of a step on every level of L: the region particles' velocity, the clock, the
// interfaces advanced with the velocity the scheme strained the bodies with.
void end_step(const Levels& L, Scheme scheme);
// One finest step of the levels stepping at their own dt (time.subcycling = "levels"), MUSL.
void step_subcycled(RunState& n);

}  // namespace rupture::detail
