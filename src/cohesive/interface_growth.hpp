// rupture/cohesive/interface_growth.hpp
// Where a pre-crack can grow from, and a new segment at that end (solver/crack_growth.hpp).
// precrack_tips: each end of the interface's current line (InterfaceSpec::line, grown or as
// drawn) that meets one of its bonded stretches (where the crack meets intact material), in
// order start, end; its frame: the end vertex (reference position) and the direction from the
// point `chord` back along the line to it (the crack as a J domain of that radius sees it; the
// end piece's outward tangent where the end piece is longer, or chord = 0). extend_interface: the interface is open; the line becomes one piece per segment (its nodes are the
// vertices), plus the new end node at reference position (x, y), m, with displacement (ux, uy)
// on both faces (the material there is intact: no jump). Every existing node and Gauss point
// keeps its state (displacements, jumps, tractions, law history, crack and rupture times); the
// new segment's Gauss points start separated on a pre-crack (law contact) and intact on a cohesive
// crack (drawn_open or not: the law models the process zone), and
// the new node of a pre-crack counts as cracked at the interface's time. Arc lengths s0 are
// measured from the new start. Distributed runs: the grown interface has no rank ownership
// (every node owned); the caller distributes it again (parallel/halo.hpp).
#pragma once
#include <vector>

#include "cohesive/interface.hpp"
#include "fracture/j_integral.hpp"

namespace rupture {

enum class LineEnd { start, end };

struct CrackTip {
  LineEnd end = LineEnd::end;  // which end of the line
  TipFrame frame;
};

// tol: how close (m) an end must be to a bonded stretch's end to meet it; chord, m.
std::vector<CrackTip> precrack_tips(const InterfaceSpec& is, double tol, double chord = 0.0);

void extend_interface(CohesiveInterface& c, LineEnd at, double x, double y, double ux, double uy);

}  // namespace rupture
