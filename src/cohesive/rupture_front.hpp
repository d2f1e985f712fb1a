// rupture/cohesive/rupture_front.hpp
// A fault's rupture front, from its rupture-time profile (the SCEC definition: the first time
// each node's slip rate exceeded interface.rupture_slip_rate, CohesiveInterface::
// node_rupture_time), as seismologists summarise it: where it started (the nucleation patch:
// the nodes whose initial shear traction exceeds their static strength, or the first node to
// rupture where none does), and on each side of the patch, away from it, how fast the front
// ran. The crack-tip summary (cohesive/crack_tip.hpp: E10, E11) follows the tip of the
// separated stretch in time, which on a fault reads the patch breaking at once as a tip speed
// of tens of km/s; the front's speed here is the inverse of the rupture-time gradient:
//   v(s) = 1 / (dt_r/ds),
// the slope dt_r/ds a least-squares fit of rupture time against distance from the patch over
// the ruptured nodes within a window of kFrontWindowCells cells (docs/faults.md, "The rupture
// front"). Units: m, s, m/s.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "cohesive/interface.hpp"
#include "material/elastic.hpp"

namespace rupture {

// The fitting window, in cells of the fault's grid. A node's rupture time is the end of the
// step in which its slip rate crossed the threshold, so it is late by up to dt = cfl h / c_D;
// over a window of L = 5 h the slowness of a front at v carries an error of at most
// dt / (L / v) = cfl v / (5 c_D): 4 % at cfl 0.4 and v = c_D / 2, less for slower fronts and
// in the median over many windows. Shorter windows resolve a supershear jump more sharply but
// multiply that error; 5 cells is also the width over which a slip-weakening front is resolved
// at the recommended 3-5 cells per cohesive zone (docs/faults.md).
inline constexpr double kFrontWindowCells = 5.0;
// In words, for run.json and the CLI.
inline constexpr const char* kFrontDefinition =
    "rupture front outside the nucleation patch (nodes overstressed at t = 0): speed = 1 / the "
    "least-squares slope of rupture time (slip rate > rupture_slip_rate) against distance from "
    "the patch over windows of 5 cells; per side the median over its windows, the front's the "
    "faster side's";

// The front on one side of the nucleation patch (forward: increasing arc length s).
struct FrontSide {
  int nodes = 0;               // ruptured nodes outside the patch on this side
  double leave_time = -1.0;    // first rupture on this side, outside the patch, s (-1: none)
  double reach_s = -1.0;       // arc length of the farthest ruptured node (-1: none), m
  double speed = 0.0;          // median of the windows' speeds, m/s (0: fewer nodes than a window)
  double peak_speed = 0.0;     // the largest window speed, m/s. A window faster than the
                               // fastest wave (c_D of the faster side: no front outruns the
                               // signal that drives it), whose rupture times do not increase
                               // away from the patch, or whose fit spans less than two time
                               // steps across it, is a patch triggered by a passing wave, not
                               // a front: left out of speed and peak, counted in `triggered`
  int triggered = 0;           // such windows
  double supershear_s = -1.0;  // arc length where the window speed first exceeds c_S and stays
                               // above it to the side's end of rupture (-1: never), m
  double supershear_time = -1.0;  // the rupture time there, s
  std::string regime = "none";    // crack_regime(speed) against the waves given
};

struct FrontSummary {
  bool ruptured = false;
  double nucleation_begin_s = -1.0, nucleation_end_s = -1.0;  // the patch's arc lengths, m
  bool nucleation_overstressed = false;  // the patch is overstressed at t = 0 (else: first node)
  double nucleation_time = -1.0;  // first rupture anywhere, s
  FrontSide forward, backward;
  // The faster side's (a bilateral rupture that turns supershear on one side is supershear):
  double speed = 0.0;       // the larger of the sides' median speeds, m/s
  double peak_speed = 0.0;  // the larger side's peak, m/s
  std::string regime = "none";  // crack_regime(speed) against the waves given
};

// From a profile: arc lengths s (increasing), rupture times (< 0: not ruptured), the
// nucleation nodes (1: in the patch; all 0: the first node to rupture), `window` in m, the
// time step dt (s: rupture times are step ends, so a window whose fit spans less than 2 dt
// is unresolved), the fastest wave speed c_max (m/s: the larger c_D of the two sides). Regimes
// against `w` (a bimaterial fault: the caller's choice, named where reported).
FrontSummary summarize_front(const std::vector<double>& s, const std::vector<double>& rupture_time,
                             const std::vector<unsigned char>& nucleation, double window, double dt,
                             double c_max, const WaveSpeeds& w);

// A fault interface's (spec.law slip weakening, per node with its stretches): the patch from the
// initial tractions, the window kFrontWindowCells x cell_size.
FrontSummary summarize_front(const CohesiveInterface& c, double cell_size, double dt,
                             double c_max, const WaveSpeeds& w);

// Whether an interface is a fault (its front is summarised): slip-weakening friction.
bool is_fault(const CohesiveInterface& c);

}  // namespace rupture
