// rupture/cohesive/mach_angle.hpp
// The shear Mach angle behind an intersonic crack tip (theory E12), measured on the particles'
// tau_max field (E13): beta, the angle between the crack line and the shear Mach front, and the
// speed it implies, c_S / sin(beta), an independent check of the E11 speed.
//
// Method, per side of the crack (see docs/validation.md, "Shear Mach angle"):
//  1. Frame: xi along the crack in the running direction from the tip, eta away from the crack
//     line on that side. Particles with 2h <= eta <= run/2 and -1.5 run <= xi <= run/2 are
//     averaged into square bins of the grid's cell size h at the tip (2 x 2 particles per bin
//     with the default seeding); run = how far the tip has gone since
//     it passed c_S (the Mach front reaches back to where the crack went intersonic, and a
//     front behind the tip at distance d lies at height d tan(beta) < d).
//  2. Front: the shear wave carries tau_max up as it passes, so the front is an edge where
//     tau_max is larger behind (towards the crack's wake) than ahead. Every straight line
//     xi = xi0 - eta cot(beta) (beta 15..75 deg by 0.5, xi0 by h) is scored by the mean over
//     rows of (mean tau over the width w/2 behind it - mean tau over w/2 ahead), w = 4h: GIMP
//     spreads a jump over about two cells (a particle's support is two cells wide), so each half
//     of the filter must span two cells to see the whole jump. The best line is kept.
//  3. Fit: in every bin row the edge is located on a quarter-bin raster within w of that line
//     (the same two-sided filter), and a least-squares line through those points gives beta and
//     its standard error.
// A side is not measured when fewer than kMinRows rows (run shorter than about 2 kMinRows h) or
// when the front's jump is not positive.
// Units: m, Pa, degrees for angles.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cohesive/crack_tip.hpp"
#include "grid/grid.hpp"
#include "particles/particles.hpp"

namespace rupture {

// Where to look for the front.
struct MachSearch {
  double tip_x = 0.0, tip_y = 0.0;  // the crack tip, m
  double dir_x = 1.0, dir_y = 0.0;  // unit vector along the crack, in the running direction
  double run = 0.0;                 // distance the tip has run since it passed c_S, m
  double spacing = 0.0;             // the grid's cell size h at the tip (bin size), m
};

struct MachLine {
  bool found = false;
  double angle = 0.0;         // beta, degrees between the crack line and the front
  double angle_error = 0.0;   // standard error of the fitted beta, degrees
  double origin = 0.0;        // where the fitted front meets the crack line, xi (m; < 0 behind)
  double jump = 0.0;          // mean tau_max jump across the front, Pa
  int rows = 0;               // bin rows in the fit
  int material = -1;          // most particles' material on this side (for c_S)
};

constexpr int kMinRows = 8;
// The angles searched, degrees: 15 deg is a front at 3.9 c_S (faster than c_D unless
// nu > 0.47), 75 deg one at 1.035 c_S. A fitted angle outside them is not a reading.
constexpr double kMinAngle = 15.0, kMaxAngle = 75.0;

// Distributed runs: sums the n values in place over the ranks (each rank bins its particles;
// the bins' sums and counts, and the material tally, are added before the search, so every
// rank finds the same line from the same bins).
using SumOverRanks = std::function<void(double*, int)>;

// side = +1: to the left of the running direction (the crack's +n side), -1: to the right.
// Particles: positions x, y (m), tau_max (Pa), material id; n of them (this rank's, with
// `sum`).
MachLine find_mach_line(const double* x, const double* y, const double* tau_max,
                        const std::uint8_t* material, std::size_t n, const MachSearch& where,
                        int side, const SumOverRanks* sum = nullptr);

// One measurement at an output time (every member is written in run/checkpoint.cpp).
struct MachReading {
  int interface = 0;                // which interface's crack (input order)
  double time = 0.0;                // s
  double tip_x = 0.0, tip_y = 0.0;  // m
  double dir_x = 1.0, dir_y = 0.0;  // unit vector along the crack, running direction
  double speed = 0.0;               // the latest E11 speed at or before `time`, m/s
  MachLine left, right;             // left (+1) and right (-1) of the running direction
  double c_s_left = 0.0, c_s_right = 0.0;  // shear speed of each side's material, m/s
};

// The readings of a run summarized over those with from <= time <= to (the crack's steady
// phase), or over all when none lies there: medians, so that a reading that locked onto
// another feature (a reflected wave, the oscillations behind the front) does not pull the
// result; each reading's fit error measures its scatter about a line, not which line it is.
struct MachSummary {
  int readings = 0;               // readings with at least one side measured, in the summary
  double angle = -1.0;            // median beta over both sides' readings, degrees (-1: none)
  double angle_spread = -1.0;     // standard deviation of those readings, degrees (-1: < 2)
  double angle_left = -1.0, angle_right = -1.0;  // per side, degrees
  double speed = -1.0;            // median c_S / sin(beta) (each side with its c_S), m/s
};
// Only the readings of `interface` count.
MachSummary summarize_mach(const std::vector<MachReading>& readings, int interface, double from,
                           double to);

// DIR/mach_angle<suffix>.csv, one row per reading of `interface` (rewritten atomically).
void write_mach_angles(const std::string& dir, const std::string& suffix,
                       const std::vector<MachReading>& readings, int interface);

// A reading behind `crack`'s tip at `time` when its latest E11 speed exceeds c_s (the crack
// runs intersonically): run = the distance since its first E11 speed above c_s, the direction
// along the line at the tip, h = the larger width of the grid cell holding the tip, each
// side's c_S from its particles' material (shear_speed per material id). False: not read.
bool read_mach_angle(const CrackTracker& crack, double c_s, const Particles& p, const Grid& grid,
                     const std::vector<double>& shear_speed, double time, MachReading& out,
                     const SumOverRanks* sum = nullptr);

// beta (degrees) for a front behind a tip at speed v in a material of shear speed c_s
// (theory E12: sin(beta) = c_s / v), and the speed c_s / sin(beta) a measured beta implies.
double mach_angle_of_speed(double v, double c_s);
double speed_of_mach_angle(double beta_degrees, double c_s);

}  // namespace rupture
