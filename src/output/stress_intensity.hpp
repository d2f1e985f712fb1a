// rupture/output/stress_intensity.hpp
// J, K_I and K_II at the crack tips of the interfaces with stress_intensity = true, over time
// (fracture/j_integral.hpp; docs/fracture.md). The tips of an interface:
//  - a pre-crack (no cohesion): each end of its current line (as drawn, or grown) that meets one
//    of its bonded stretches (solver/crack_tips.hpp: where the crack meets intact material), the
//    crack direction the line's outward tangent there;
//  - a cohesive line: the running tip of its crack tracker (cohesive/crack_tip.hpp: the
//    farthest separated node, the line's start before initiation), direction along the line.
// Per sample and tip, one row per J domain: time (s), tip (0, 1: which of the tips), x, y (m),
// domain (its outer radius, m), J (J/m^2), K_I, K_II (Pa m^1/2), points (in the domain), speed
// (m/s: a growing crack's tip's, growing_tip_speed; 0 for a crack that does not grow; K is read
// at it with running_tip = true, below 0.95 c_R).
// Written to DIR/stress_intensity_NAME.csv atomically at every flush; the rows are
// checkpointed. On nested levels the level holding the interface; distributed, every rank
// reads the whole domain (solver/crack_tips.hpp) and rank 0 writes.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "cohesive/crack_tip.hpp"
#include "fracture/j_integral.hpp"
#include "input/case.hpp"
#include "solver/crack_growth.hpp"

namespace rupture {

struct RunState;

inline constexpr std::size_t kTipColumns = 10;

// One interface's rows (checkpointed), kTipColumns per row; empty for interfaces without
// stress_intensity.
struct TipSeries {
  std::vector<double> rows;
};

// The tips of interface k now (see above): frames in the global frame.
std::vector<TipFrame> crack_tips(const Case& c, const RunState& s, std::size_t k,
                                 const CrackTracker& tracker);

// Appends the rows of every interface with stress_intensity at the state's time.
// A growing crack with running_tip reads each tip at its speed (growing_tip_material).
void sample_stress_intensity(const Case& c, RunState& s, const std::vector<CrackTracker>& trackers,
                             const std::vector<CrackGrowthRecord>& growth, std::vector<TipSeries>& series);
void write_stress_intensity(const std::string& dir, const Case& c,
                            const std::vector<TipSeries>& series);
// DIR/crack_path_NAME.csv of every growing crack (solver/crack_growth.hpp: one row per grown
// segment, its new vertex, or split; the path is the drawn line with these vertices added at
// its ends), with the tip's speed then in a last column, speed (m/s, tip_speed).
void write_crack_paths(const std::string& dir, const Case& c,
                       const std::vector<CrackGrowthRecord>& growth);

}  // namespace rupture
