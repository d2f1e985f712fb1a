// rupture/cohesive/crack_tip.hpp
// Crack-tip tracking on a cohesive interface (theory §4, E10-E11). Positions are arc lengths s
// along the interface's line from its first point (cohesive/polyline.hpp); the files also give
// the (x, y) of each.
//  - tip (E10): the farthest cohesive node from the initial tip (interface start) whose jump
//    magnitude has reached the separation criterion; sampled at a fixed interval; the back tip
//    is the start of the separated stretch that holds it (a crack nucleating inside the line
//    runs both ways);
//  - every separated stretch (run of cracked nodes) is recorded, so a daughter crack ahead of
//    the main tip shows up as a second stretch; the summary counts one as a daughter crack only
//    across an intact ligament of at least one grid cell (the driver's daughter_ligament): two
//    stretches closer than that lie between the same grid nodes, one front split by the order in
//    which its cohesive points reached the criterion;
//  - speed (E11): slope of a least-squares line through 31 consecutive tip positions (centred);
//  - samples are taken at exact multiples of the sampling interval whatever the time step:
//    a node's crack time is interpolated inside the step where its jump crossed the criterion,
//    and the tip at time T is the farthest node cracked by T (so the E11 window is exactly 31
//    intervals);
//  - summary: initiation time; the sustained speed of the steady running phase (see
//    CrackSummary::sustained_speed) and the regime from it (sub-Rayleigh, Rayleigh-to-shear,
//    intersonic, supersonic: theory §6); the least-squares slope over the last 4 us on its own
//    (last_window_speed); arrest (a tip that has not moved for the last microsecond or more of
//    the run) with its time and position; peak speed, first time above c_S, first daughter
//    crack, and the time the tip reached the end of the cohesive line (beyond it the halves are
//    bonded and the crack stops).
// Units: s, m, m/s.
#pragma once
#include <string>
#include <vector>

#include "cohesive/interface.hpp"
#include "cohesive/rupture_front.hpp"
#include "material/elastic.hpp"

namespace rupture {

// Every member must also be written in run/checkpoint.cpp (restart is bitwise).
struct CrackSample {
  double time = 0.0;
  double tip = 0.0;            // tip position s (0, the line's start, if not initiated), m
  double back = 0.0;           // start s of the stretch that holds the tip, m
  double cohesive_zone = 0.0;  // length ahead of the tip past the peak-traction opening, m
  double traction_zone = 0.0;  // length ahead of the tip still carrying >= 10 % of the
                               // peak traction (kTractionZoneFraction), m
  std::vector<double> stretch_begin, stretch_end;  // separated stretches (s), m
};

struct CrackSummary {
  bool initiated = false;
  // A crack that grows off its line (interface.NAME.growth; solver/crack_growth.hpp): then
  // initiated and initiation_time are its first growth step's, and these say how it grew.
  bool grows = false;
  double initial_angle = 0.0;  // degrees, counterclockwise from the crack's direction to its first segment
  int branches = 0;            // how many times a tip split
  double grown_length = 0.0;   // m, the length grown by the end
  // A crack that nucleates at its drawn line (solver/crack_nucleation.hpp): it does, and when
  // (s; -1: it stayed intact).
  bool nucleates = false;
  double nucleation_time = -1.0;
  double initiation_time = -1.0;     // s (first node to crack; -1 if none)
  // m/s: the least-squares slope of the tip positions over the steady running phase, the
  // latest stretch of at least kSteadyMin in which every E11 speed is positive and within
  // +-kSteadyBand of the stretch's midrange (a crack that runs, then arrests, is reported at
  // its running speed; one that jumps to a faster regime late, at the later speed if it ran
  // there long enough). No such stretch: the last-window slope (steady_begin = -1).
  double sustained_speed = 0.0;
  double steady_begin = -1.0, steady_end = -1.0;  // the steady phase's first and last samples, s
  double last_window_speed = 0.0;    // m/s, slope over the last `window` seconds of the run
  bool arrested = false;             // the tip has not moved for kArrestTime or more at the end
  double arrest_time = -1.0;         // when the tip got to where it stopped, s (-1: not arrested)
  double arrest_s = -1.0;            // where it stopped (arc length), m (-1: not arrested)
  double peak_speed = 0.0;           // m/s, max of the E11 speeds
  double intersonic_time = -1.0;     // first time the E11 speed exceeds c_S (-1: never)
  double daughter_time = -1.0;       // first sample with two separated stretches apart by an
                                     // intact ligament >= daughter_ligament (-1: never), s
  double final_tip = 0.0;            // x of the tip at the end, m
  double final_tip_y = 0.0;          // y of the tip at the end, m
  double final_tip_s = 0.0;          // arc length of the tip at the end, m
  double initiation_s = -1.0;        // arc length of the first node to crack, m (-1 if none)
  double back_speed = 0.0;           // m/s, speed of the back tip (> 0 when it runs backwards)
                                     // over the last `window` seconds
  double final_cohesive_zone = 0.0;  // m
  double final_traction_zone = 0.0;  // m
  double end_reached_time = -1.0;    // first sample with the tip within end_tolerance of the
                                     // cohesive line's end, s (-1: never)
  // The shear Mach angle (theory E12) read at the output times (cohesive/mach_angle.hpp, filled
  // by the driver): medians of the readings in the steady phase (-1: none; MachSummary).
  int mach_readings = 0;
  double mach_angle = -1.0;         // both sides, degrees
  double mach_angle_spread = -1.0;  // standard deviation of the readings, degrees
  double mach_angle_left = -1.0;    // left of the running direction (upper for a crack along +x)
  double mach_angle_right = -1.0;   // degrees
  double mach_speed = -1.0;         // c_S / sin(beta), m/s
  // none | sub-Rayleigh (v < c_R) | Rayleigh-to-shear (c_R <= v < c_S: theory §6 says no crack
  // sustains it, so a run showing it says so) | intersonic (c_S <= v < c_D) | supersonic
  std::string regime = "none";
  // A fault's rupture front outside its nucleation patch, from the rupture-time profile
  // (cohesive/rupture_front.hpp; filled by the driver for slip-weakening interfaces only).
  bool fault = false;
  FrontSummary front;
};

class CrackTracker {
 public:
  static constexpr int kWindow = 31;  // E11
  // The steady running phase (CrackSummary::sustained_speed): E11 speeds within +-5 % of their
  // midrange, for at least 1 us (longer than the E11 window, 31 samples of 0.02 us by default,
  // so the phase is more than one speed estimate), each above 5 % of c_R (a moving tip).
  static constexpr double kSteadyBand = 0.05;
  static constexpr double kSteadyMin = 1e-6;     // s
  static constexpr double kMovingFraction = 0.05;  // x c_R
  // Arrest: the tip has not moved over at least this much time before the end of the run.
  static constexpr double kArrestTime = 1e-6;  // s
  // Both durations above are for laboratory runs; a run sampled more coarsely (a fault over
  // seconds) uses 20 sample spacings instead when that is longer: no absolute time scale.
  static constexpr double kMinSamples = 20.0;
  double duration_floor(double lab) const;
  // Two cohesive-zone lengths, both measured from the tip over the contiguous intact nodes
  // ahead of it: `cohesive_zone` ends at the last node past the peak-shear opening
  // (softening: the process zone proper); `traction_zone` goes on past it while the traction
  // is at least this fraction of the peak (|T_t| / tau_max or T_n / sigma_max): the loaded
  // zone a traction profile shows, as in the paper's Fig. 12.
  static constexpr double kTractionZoneFraction = 0.1;
  // What the two lengths are, in words, for run.json and the CLI (docs/validation.md compares
  // them, and the zone of any nonzero traction, with the paper's 7 mm).
  static constexpr const char* kCohesiveZoneDefinition =
      "softening zone: from the tip (jump 5 delta_t, E10) forward to the last node past the "
      "peak-traction opening";
  static constexpr const char* kTractionZoneDefinition =
      "loaded zone: from the tip forward while the traction is at least 10 % of the peak "
      "(sigma_max or tau_max)";

  // end_tolerance: how close to the end of the cohesive line the tip counts as having reached
  // it, m. The last nodes before a bonded grid node cannot open fully, so the driver passes two
  // grid cells there. daughter_ligament: the shortest intact ligament between two separated
  // stretches for the one ahead to count as a daughter crack, m (the driver passes one grid
  // cell). The interface's node positions are kept to place arc lengths in (x, y).
  CrackTracker() = default;
  explicit CrackTracker(const CohesiveInterface& c, double end_tolerance = 0.0,
                        double daughter_ligament = 0.0);

  // Records the crack at time t <= the interface's current time: nodes cracked by t (their
  // interpolated crack times) make the tip and stretches; zone lengths use the current jumps.
  void sample(const CohesiveInterface& c, double t);
  const std::vector<CrackSample>& samples() const { return samples_; }
  double end_reached_time() const { return end_reached_time_; }
  // E11 speed at each sample (NaN where the centred window does not fit).
  std::vector<double> speeds() const;
  CrackSummary summarize(const CohesiveInterface& c, const WaveSpeeds& waves,
                         double window = 4e-6) const;
  // DIR/crack_tip<suffix>.csv and DIR/crack_stretches<suffix>.csv (rewritten atomically).
  void write(const std::string& dir, const std::string& suffix, double c_r, double c_s) const;
  // Position (x, y) of arc length s: a node's own coordinates at a node, else interpolated.
  void position(double s, double& x, double& y) const;
  // The interface's line has grown (solver/crack_growth.hpp): its nodes are taken again to
  // place arc lengths, and, with shift_samples, the recorded ones move by the length the line
  // gained at its start since (arc lengths run from the line's start: a segment added there
  // moves every node along). A resumed run's samples are in the grown line's frame already
  // (shift_samples false).
  void follow(const CohesiveInterface& c, bool shift_samples);

 private:
  friend struct CheckpointAccess;  // every member below must also be written in run/checkpoint.cpp
  std::vector<CrackSample> samples_;
  std::vector<double> x0_, y0_, s0_;  // the interface's nodes (from the case, not stored)
  double daughter_ligament_ = 0.0;    // m (from the case, not stored)
  double length_ = 0.0;               // a closed line's length (0: open), m
  void sample_closed(const CohesiveInterface& c, double t, CrackSample& s);
  // The steady running phase in the E11 speeds v (NaN compares false: excluded): samples
  // [first, last]; false if none lasts kSteadyMin.
  bool steady_phase(const std::vector<double>& v, double moving, std::size_t& first,
                    std::size_t& last) const;
  double end_tolerance_ = 0.0;
  double end_reached_time_ = -1.0;
};

// Regime of a crack running at `speed` (theory §6); "none" below 1e-3 c_S.
std::string crack_regime(double speed, const WaveSpeeds& w);

// DIR/rupture_time<suffix>.csv: when each node of the interface cracked (-1: not yet).
void write_rupture_times(const std::string& dir, const std::string& suffix,
                         const CohesiveInterface& c);

// Least-squares slope of y(t) (E11).
double least_squares_slope(const double* t, const double* y, std::size_t n);

}  // namespace rupture
