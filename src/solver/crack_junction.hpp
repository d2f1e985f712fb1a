// rupture/solver/crack_junction.hpp
// Where a growing crack meets another line (docs/fracture.md, "Junctions"). Each crack drawn in
// a body splits it into two velocity fields along itself and its tied extension (the tie, to the
// body's edge), and every other interface keeps one field on each of its faces. So
//  - a tip that comes within a cell of another line drawn in its body, or of that line's tie,
//    would cut off pieces that need fields of their own;
//  - a tip that comes within a cell of an interface between its body and another, or a tie that
//    comes to touch another interface (a T-junction: the edge the body shares with another
//    body), would put that interface's face on two fields.
// Neither is modelled: growth (solver/crack_growth.hpp) asks here before each segment is laid
// (stop_at_segment_junction) and after (stop_at_tie_junction), and the run stops with a
// SimulationError naming both lines, the place and the time, and keeps what it wrote, rather
// than grow through material its fields do not hold. Units: m, s.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "cohesive/polyline.hpp"
#include "geometry/shape.hpp"
#include "input/case.hpp"
#include "solver/crack_growth.hpp"
#include "solver/run_state.hpp"

namespace rupture {

// Another line on crack k's level: its geometry, what to call it, and whether it is a tie and
// whether it is drawn inside the crack's body (else it lies between two bodies).
struct OtherLine {
  Polyline line;
  std::string name;  // "interface 'NAME'" or "a branch of interface 'NAME'"
  bool tie = false;
  bool in_body = false;
};

// Every interface on crack k's level other than the crack's own lines (`own`: its slots, its
// branches' included), with their ties.
std::vector<OtherLine> other_lines(const Case& c, const RunState& s, const std::vector<CrackGrowthRecord>& records,
                                   std::size_t k, const std::vector<std::size_t>& own);

// The segment from -> to that a tip of crack k is about to grow comes within h (one cell) of
// another line (drawn in its body, or between its body and another), or of a tie: throws
// SimulationError.
void stop_at_segment_junction(const Case& c, std::size_t k, double time, const std::vector<OtherLine>& others,
                              const Point& from, const Point& to, double h);

// Crack k's ties (after a segment was laid) touch another line (within 1e-6 h): throws
// SimulationError.
void stop_at_tie_junction(const Case& c, std::size_t k, double time, const std::vector<OtherLine>& others,
                          const std::vector<Polyline>& ties, double h);

}  // namespace rupture
