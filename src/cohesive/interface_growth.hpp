// rupture/cohesive/interface_growth.hpp
// A crack tip that grew (solver/crack_growth.hpp) adds a segment to its interface at that end.
// Contract: the interface is open; the line becomes one piece per segment (its nodes are the
// vertices), plus the new end node at reference position (x, y), m, with displacement (ux, uy)
// on both faces (the material there is intact: no jump). Every existing node and Gauss point
// keeps its state (displacements, jumps, tractions, law history, crack and rupture times); the
// new segment's Gauss points start as make_interface makes them (separated on a pre-crack), and
// the new node of a pre-crack counts as cracked at the interface's time. Arc lengths s0 are
// measured from the new start. One process (no rank ownership).
#pragma once
#include "cohesive/interface.hpp"

namespace rupture {

enum class LineEnd { start, end };

void extend_interface(CohesiveInterface& c, LineEnd at, double x, double y, double ux, double uy);

}  // namespace rupture
