// rupture/input/crack_reach.hpp
// The material a crack drawn inside one body grows through (docs/fracture.md, "Junctions"). Each
// line drawn in a body splits it into parts, one velocity field each; a crack's two fields are
// the parts on either side of it and its tie. The other parts are beyond its reach when no
// growing line changes their material: their set-up regions then still hold their particles, and
// the lines between them and the crack's parts are edges of the crack's reach, as an interface
// between its body and another body is. Parts that a growing line does change stay within reach
// (a tip that comes near their lines stops the run: solver/crack_junction.hpp).
#pragma once
#include <cstddef>
#include <vector>

#include "input/case.hpp"

namespace rupture {

// The fields of the parts of crack k's body beyond its reach: split off by other lines drawn in
// the body, on neither of the crack's fields, and not a face (or a kept branch field) of any
// growing line.
std::vector<int> fields_beyond_reach(const Case& c, std::size_t k);

// Whether interface `e` (drawn in crack k's body, not growing) lies on the edge of k's reach:
// one face wholly on the crack's two fields, the other wholly beyond its reach.
bool on_edge_of_reach(const Case& c, std::size_t k, const InterfaceSpec& e);

}  // namespace rupture
