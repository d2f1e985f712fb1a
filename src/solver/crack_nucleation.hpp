// rupture/solver/crack_nucleation.hpp
// Cracks that appear where they are drawn once the stress there reaches a strength
// (interface.NAME.nucleation = "strength"; docs/fracture.md, "Nucleation at a drawn site").
// Until then the drawn line is intact material: the tie that holds the line's extension runs on
// over the line itself (dormant_ties), so its two fields share every grid node near it (one
// continuum, solver/cohesive_step.hpp) and its segments' jumps do not change (no traction).
// After every synchronized step, growth (solver/crack_growth.hpp) reads the normal stress across
// each segment of a line not yet loose: the mean of sigma_nn = n . sigma . n over the particles
// whose reference position lies within a cell of the segment (site_stress, summed over the
// ranks). Once one segment's reaches the strength, the tie goes back to the set-up's (the
// extension alone, release_site): the line is the crack drawn (its law's intact segments, or a
// cut with drawn_open) and its tips grow by the crack's criterion from the next step on.
// Units: m, Pa.
#pragma once
#include <cstddef>
#include <vector>

#include "cohesive/interface.hpp"
#include "cohesive/polyline.hpp"
#include "input/case.hpp"
#include "solver/state.hpp"

namespace rupture {

// The ties of a line not yet loose: its set-up ties (the extension beyond each tip), those that
// meet an end of the drawn line joined to it into one polyline (so no grid node near a joint
// counts as beyond a tie's end); ends within `tol` (m) meet.
std::vector<Polyline> dormant_ties(const InterfaceSpec& is, double tol);

// `is` as a run starts with it: a line that nucleates is tied over itself (dormant_ties).
InterfaceSpec as_set_up(const InterfaceSpec& is, double tol);

// The largest, over the segments of `in`'s line, of the mean normal stress across the segment
// over level L's particles whose reference position lies within `reach` (m) of it and projects
// inside it, Pa (distributed: summed over the ranks first, in rank order). -infinity when no
// particle lies near any segment.
double site_stress(const State& L, const CohesiveInterface& in, double reach);

// Case interface k, on level L's interface `slot`, comes loose: its tie is the set-up's again,
// its tied nodes found again on L and on the `others` levels (nested: each ties interface k).
void release_site(const Case& c, std::size_t k, State& L, std::size_t slot, const std::vector<State*>& others);

}  // namespace rupture
