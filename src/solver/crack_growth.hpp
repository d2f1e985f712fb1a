// rupture/solver/crack_growth.hpp
// Growth of pre-cracks drawn inside one body (interface.NAME.growth; docs/fracture.md,
// "Growth"). After every synchronized step, each tip of a growing crack (solver/crack_tips.hpp)
// is read (K_I, K_II: the mean over its J domains, in the frame of the crack's chord over the
// outer domain's radius: the crack as the domains see it) and the crack's GrowthLaw decides
// (fracture/growth_criterion.hpp). A tip that grows gets one straight segment of growth.step
// cells in the criterion's direction (reference coordinates, where the cut is a property of the
// material; a tip on its weak plane, plane_fracture_energy, tells the criterion so, and a step
// along the plane is laid on the drawn line's direction exactly), and the body's split follows
// it exactly as the input split it:
//  - the interface gets the segment (cohesive/interface_growth.hpp), its new node displaced as
//    the tip node (the mean of its faces); on a cohesive crack the segment carries the law
//    (intact), and the cohesive criterion reads the end segment's state through it
//    (crack_front: past the law's peak at its far Gauss point, or open);
//  - the tie beyond that tip becomes the new cut's stretches inside the body, and the tied grid
//    nodes are found again (bonded_nodes). The cut: the new segment's straight extension; with
//    several cracks drawn in one body, two cells along the segment's direction and then on in
//    the tie's old direction (the drawn line's), so a turned crack's tie does not cross
//    another crack's (a node two ties reach would join three fields);
//  - the particles of the two parts that lie between the old cut and the new one (by reference
//    position) change field, so each part is again the material on its side of the crack and
//    its cut; the strips' node rows per field take each flipped particle's row, and the
//    windows are re-measured (no re-sort: the order, hence the round-off, stays the last
//    sort's).
// A tip whose segment would leave the body ends on its edge: no tie is left there, the cut is
// through, and the pieces separate. A tip that comes within a cell of the edge cuts through to
// its nearest point the same way (the ligament left is below what the grid resolves). The body
// here is the crack's reach (solver/crack_cut.hpp crack_body): a line drawn in the body on its
// edge, as an interface between the body and another, is an edge the crack ends on. A tip whose
// next segment comes within a cell of another line drawn in its body, or of a tie, or whose tie
// comes to touch one, stops the run with a SimulationError naming both and the place and time (a
// junction the split-body fields cannot follow: solver/crack_junction.hpp). One grid,
// or nested levels with one step for all (the crack read and grown on the level that holds it,
// the others following its cut; input/ refuses the rest); one process or several: every rank
// runs this alike on the whole interface state, each tip's read summed over the ranks, and the
// driver then distributes the grown interfaces and ties again (parallel/halo.hpp).
// Units: m, s, degrees in the records.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "input/case.hpp"
#include "solver/crack_segment.hpp"
#include "solver/crack_tips.hpp"
#include "solver/run_state.hpp"

namespace rupture {

// One event of a crack's growth: a straight segment laid at a tip, or a tip split in two
// (crack_path_NAME.csv's columns, docs/fracture.md). Units: s, m, degrees, Pa m^1/2.
struct GrowthRow {
  double time = 0.0;  // when the segment was made (or the tip split), s
  // The tip: its index among the crack's tips (as in stress_intensity_NAME.csv); 2 + b: the tip
  // of branch b (solver/crack_branching.hpp).
  int tip = 0;
  LineEnd end = LineEnd::start;  // the end of the line the tip is at (a branch's: its end)
  bool split = false;            // the tip split in two here (its two branches' rows follow)
  // The new vertex, reference position, m; a split: the tip.
  double x = 0.0, y = 0.0;
  // Counterclockwise from the crack's direction at the tip (the chord above) to the new
  // segment; the first row's: from the drawn crack's direction; a split: the half angle
  // between its branches, degrees.
  double angle = 0.0;
  double length = 0.0;           // of the segment (a split: 0), m
  double K_I = 0.0, K_II = 0.0;  // what the criterion read, Pa m^1/2
  // The CSV's and the checkpoint's `end` code: 0, 1 a segment at the line's start, end; 2, 3
  // the tip there split.
  int end_code() const { return (split ? 2 : 0) + (end == LineEnd::end ? 1 : 0); }
  // Whether the row grew the tip (label, end): a branch's tip by its label, the crack's own by
  // its end (its label, the index among its tips, changes when the other stops). A split grows
  // no tip.
  bool grows(int label, LineEnd at) const {
    if (split) return false;
    return label >= 2 ? tip == label : tip < 2 && end == at;
  }
};

// The checkpoint's form of the rows: kGrowthColumns numbers a row (time, tip, end code, x, y,
// angle, length, K_I, K_II: the CSV's order), and back; a row whose tip or end code is not one
// the rows can hold is an InputError naming `where`'s entry, the value and what is allowed.
inline constexpr std::size_t kGrowthColumns = 9;
std::vector<double> growth_rows_flat(const std::vector<GrowthRow>& rows);
std::vector<GrowthRow> growth_rows_from_flat(const std::vector<double>& flat, const std::string& where);

// One interface's growth (checkpointed: the rows); empty rows: it has not grown. A split row is
// followed by its two branches' first segments (tips 2 + b, 3 + b: left, right of the running
// direction).
struct CrackGrowthRecord {
  std::vector<GrowthRow> rows;
  // A crack that nucleates (InterfaceSpec::nucleation_strength): when its drawn line came loose,
  // s; -1 while it is intact (checkpointed).
  double nucleation_time = -1.0;
  bool nucleated() const { return nucleation_time >= 0.0; }
  // The slots of its branches on its level, in tip-label order (derived from the rows: by the
  // splits as they happen, by regrow_cracks on a restore).
  std::vector<std::size_t> branch_slots;
  bool grown() const { return !rows.empty(); }
  double initiation_time() const { return grown() ? rows[0].time : -1.0; }  // s
  double initial_angle() const { return grown() ? rows[0].angle : 0.0; }    // degrees
  double length() const;                                                   // grown length, m (branches too)
  int branches() const;                                                    // how many times a tip split
};

// The speed of a tip (label and end as in the rows), m/s: the path it grew over the last
// `window` (m, at least) divided by the time from that stretch's start to `now`; 0 before it
// has grown that far. From the first `rows` rows only (the speed when the last of them was made).
double tip_speed(const CrackGrowthRecord& record, int label, LineEnd end, double now, double window,
                 std::size_t rows = std::size_t(-1));

// The path a tip (label and end as in the rows) has grown, m.
double tip_grown(const CrackGrowthRecord& record, int label, LineEnd end);

// What interface k's tip (label, end) is read with (solver/crack_tips.hpp, tip_material): with
// running_tip, its speed now (tip_speed over `window`, the outer J domain's radius, m; with
// growth = "prescribed", the prescribed speed once it runs) and the
// wave speeds, so a tip that runs is read with the running tip's fields
// (fracture/j_integral.hpp); without, or before it has grown a window, a stationary tip's.
// The speed of interface k's tip (label, end) now, m/s: the prescribed one once it runs
// (growth = "prescribed"), else tip_speed over `window` (m).
double growing_tip_speed(const Case& c, std::size_t k, const CrackGrowthRecord& record, int label, LineEnd end,
                         double now, double window);
TipMaterial growing_tip_material(const Case& c, std::size_t k, const CrackGrowthRecord& record,
                                 int label, LineEnd end, double now, double window);

// Reads every growing crack's tips and grows those the criterion lets grow (at most one segment
// per tip and call). A crack that nucleates and is still intact is read at its site instead
// (solver/crack_nucleation.hpp: site_stress) and, once that reaches its strength, comes loose
// (release_site, records[k].nucleation_time) and grows from the next call on. records: one per interface (resized). The reads need, of the interface
// state, only the particles and each crack's end segments (crack_front); `before_growth`, when
// given, is called once, before the first segment of the call is laid, and not at all when
// nothing grows (a distributed run gathers the whole interface state there: every rank takes
// the same decisions, so every rank calls it at the same point).
void grow_cracks(const Case& c, RunState& s, std::vector<CrackGrowthRecord>& records,
                 const std::function<void()>& before_growth = {});

// A restored run: lays the recorded segments on the interfaces again (their geometry, the ties
// and the tied nodes; the particles' fields and the interfaces' state come from the
// checkpoint), so the run continues on the grown cracks.
void regrow_cracks(const Case& c, RunState& s, std::vector<CrackGrowthRecord>& records);

// A restored run, once its particles are back (their fields as the checkpoint holds them): the
// faces of the interfaces between bodies that the grown cracks meet follow the cracks' fields
// again (solver/crack_junction.hpp follow_edge_junctions; derived, not stored).
void rejoin_cracks(const Case& c, RunState& s, const std::vector<CrackGrowthRecord>& records);

}  // namespace rupture
