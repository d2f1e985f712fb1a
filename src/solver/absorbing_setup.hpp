// rupture/solver/absorbing_setup.hpp
// The absorbing edges' dashpots of a case on a grid (bc/absorbing.hpp's AbsorbingNode): every
// (field, node) on an absorbing edge that a body of that field reaches, with C = rho c_P A
// (normal) and rho c_S A (tangential), A the node's share of the edge (half the adjacent cells'
// widths whose middle a body of the field holds). Built once per run from the Case (so here,
// above the case model, not in bc/). Units: SI; C in kg/(s m) per unit thickness.
#pragma once
#include <functional>
#include <vector>

#include "bc/absorbing.hpp"
#include "grid/grid.hpp"
#include "input/case.hpp"

namespace rupture {

std::vector<AbsorbingNode> absorbing_nodes(const Case& c, const Grid& grid);
// The same for `edges` only; with `owns` (a nested level, solver/nested_state.cpp) a node's
// share counts only the adjacent cells whose probe point (the cell's middle along the edge, a
// quarter cell inside) `owns` accepts: the levels' shares then add up to the edge's.
std::vector<AbsorbingNode> absorbing_nodes(const Case& c, const Grid& grid, const std::vector<Edge>& edges,
                                           const std::function<bool(double, double)>* owns);

}  // namespace rupture
