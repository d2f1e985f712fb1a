// rupture/solver/crack_junction.hpp
// Where a growing crack meets another line (docs/fracture.md, "Junctions"). Each crack drawn in
// a body splits it into two velocity fields along itself and its tied extension (the tie, to the
// body's edge), and every other interface keeps one field on each of its faces. So
//  - a tip that comes within a cell of another line drawn in its body, or of that line's tie,
//    would cut off pieces that need fields of their own;
//  - a tip that comes within a cell of an interface between its body and another, or of a line
//    in its body on the edge of its reach (input/crack_reach.hpp: the part beyond no growing
//    line changes), or a tie that comes to touch one (a T-junction on the edge of the material
//    the crack grows through), would put that line's face on two fields.
// The first is not modelled: growth (solver/crack_growth.hpp) asks here before each segment is
// laid (stop_at_segment_junction) and after (stop_at_tie_junction), and the run stops with a
// SimulationError naming both lines, the place and the time, and keeps what it wrote, rather
// than grow through material its fields do not hold. The second is: the line's face changes
// field where the crack's tie or end meets it, and its tied stretches join the fields beside
// them (follow_edge_junctions); a crack that reaches it ends there. Units: m, s.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "cohesive/interface.hpp"
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
  // Drawn in the body, between the crack's reach and a part beyond it (solver/crack_cut.hpp
  // crack_body): one face wholly on the crack's fields, the other on a part no growing line
  // changes. An edge of the reach, followed as an interface between two bodies is.
  bool edge = false;
  std::size_t slot = 0;  // the interface on the level
};

// The parts of crack k's body that other lines drawn in it have cut off for good (`own`: the
// crack's lines, its slots on its level): a line with no tie and no tip left (its ends on the
// body's edge: the parts on its sides hold together by its law alone, and no growth moves
// material across it any more), one of whose faces lies wholly on the crack's fields and the
// other wholly on one field that is not the crack's, cuts off the part on that other face's side
// (of its line run on straight out of the body at both ends). A line that has cut the body in
// two is then an edge of the crack's reach (OtherLine::edge): the crack's tie ends on it instead
// of crossing it, and a tip that reaches it ends there (a John-Shah beam broken at its mid-span
// while its notch crack still turns). As Region::minus_parts takes them (InterfaceSpec::
// reach_cut_off, set before each growth step and before each replayed row on a restore).
std::vector<std::vector<Side>> cut_off_parts(const Case& c, const RunState& s, std::size_t k,
                                             const std::vector<std::size_t>& own);

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

// The lines stop_at_segment_junction and stop_at_tie_junction are asked about: those drawn in
// the crack's body and every tie. An interface between the crack's body and another, or a line
// drawn in the body at the edge of the crack's reach (OtherLine::edge), is the edge: growth ends
// a segment on it (the pieces separate there, held only by that interface's law), and
// follow_edge_junctions gives its face the crack's two fields.
std::vector<OtherLine> junction_lines(const std::vector<OtherLine>& others);

// Where crack k (its lines `own`: its ends, its ties' vertices) comes within a cell of an
// interface between its body and another, or of a line in its body on the edge of its reach
// (a T-junction on the edge: a tie that meets it, or runs along it with no particle between, or
// the crack that ends on it), that line's face on the crack's side changes field there
// (InterfaceSpec::upper_faces / lower_faces, and the node faces made from them): each stretch
// between those points on the field of the crack's particles beside its middle (half a cell off
// the line). A tied stretch of that line with the crack's other field beside it (the crack's cut
// runs on along the line into it) gets a pair of fields of its own (BondedTie::of, after the
// interfaces' entries in State::bonded, laid over the whole grid). Where none comes near, a face
// it changed before is set again the same way. Throws SimulationError where that cannot be
// represented: a crack that has branched, a face on neither of the crack's fields, or a stretch
// that needs its own pair on nested levels.
// Distributed: every rank calls it (the particles' fields are read over all ranks). Called after
// every segment laid, and after a restore (the particles then hold the fields the meetings left).
void follow_edge_junctions(const Case& c, RunState& s, std::size_t k, const std::vector<std::size_t>& own,
                           const std::vector<OtherLine>& others, double time, double h);

}  // namespace rupture
