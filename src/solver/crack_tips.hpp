// rupture/solver/crack_tips.hpp
// A crack tip's J, K_I, K_II on a level (fracture/j_integral.hpp; docs/fracture.md), read by
// the stress intensity output and by crack growth (the tips: cohesive/interface_growth.hpp).
//  - read_tip: the tip's domain points from the level's particles and grid (both fields summed
//    at tied nodes; a prestressed body's initial strain added to the displacement gradient), the traction loads on faces inside the domains (the face term), and one
//    TipIntegrals per domain of InterfaceSpec::j_domains (outer radius in cells, inner half).
// The level passed is the one holding the interface; distributed (State::halo), every rank
// reads the whole domain's integrals (its maps and sums over the ranks): every rank calls it.
#pragma once
#include <vector>

#include "cohesive/interface.hpp"
#include "cohesive/interface_growth.hpp"
#include "fracture/j_integral.hpp"
#include "fracture/tip_domain.hpp"
#include "input/case.hpp"
#include "solver/state.hpp"

namespace rupture {

// The material of interface k's tip region (its upper body's).
TipMaterial tip_material(const Case& c, std::size_t k);

// Per velocity field, the uniform strain of its bodies' initial stress (bodies.NAME.stress).
std::vector<InitialStrain> initial_field_strains(const Case& c);

// line: the crack's interface on that level (its faces in contact load the domains: the face
// term of FaceContact); is: its spec, whose j_domains are read (a caller may shrink them).
std::vector<TipIntegrals> read_tip(const State& level, const CohesiveInterface& line, const InterfaceSpec& is,
                                   const TipFrame& tip, const TipMaterial& material, double time,
                                   const std::vector<InitialStrain>& initial);

}  // namespace rupture
