// rupture/output/stations.hpp
// Stations: named points whose time series the run records (the SCEC benchmarks' receivers).
// A fault station (`interface` given) lies on that interface's line and records, interpolated
// between the two nodes around it: slip (tangential jump, m), slip rate (m/s, the rate friction
// sees: on a fault the slip path's over the last step, sliding only, CohesiveInterface::
// node_slip_rate; elsewhere the jump's), opening (normal jump, m), the total shear and normal
// tractions (Pa, prestress included; normal tension positive) and jump_rate (m/s, the last
// step's tangential jump increment over dt: on a fault it includes the stick spring's elastic
// jump, which passing waves load), and on a rate-and-state fault the state psi
// (dimensionless, the law's psi: f = a asinh[V/(2 V0) exp(psi/a)]). A body station records the particle nearest its point at
// t = 0: where it is, its velocity and its displacement since t = 0 (ux, uy, m: its position
// less the first sample's, which is taken at t = 0). Written to DIR/stations/NAME.csv
// atomically at every flush and at the end; the samples are checkpointed.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "input/case.hpp"

namespace rupture {

struct RunState;

// One station's recorded rows (checkpointed), kFaultColumns or kBodyColumns per row.
struct StationSeries {
  std::vector<double> rows;
};

// Where each station reads, derived once from the case and the state at t = 0 (not state).
struct StationProbe {
  int interface = -1;
  std::size_t a = 0, b = 0;  // fault: the nodes around the station
  double f = 0.0;            //        weight of node b (linear in arc length)
  bool state = false;        //        a rate-and-state fault: its file has the state column
  std::uint32_t particle_id = 0;  // body: the particle read
  std::size_t slot = 0;           //       its index at the last read (re-found after sorts)
};

// Columns of a sample (the rows stored); a body station's file adds ux, uy (from x, y).
inline constexpr std::size_t kFaultColumns = 8;  // time, slip, slip_rate, opening, shear, normal,
                                                 // jump_rate, state (written on rate-and-state
                                                 // faults only)
inline constexpr std::size_t kBodyColumns = 5;   // time, x, y, vx, vy

// A body station reads the particle nearest its point at t = 0, the lowest id among equally
// near ones (so the choice does not depend on the particles' order): among s's particles, or
// when `nearest` is given, its entry for the station (a distributed run's choice among every
// particle the case seeds, solver/case_seeding.hpp; entries of fault stations unused).
std::vector<StationProbe> make_probes(const std::vector<StationSpec>& specs, RunState& s,
                                      const std::vector<std::uint32_t>* nearest = nullptr);
// The id of the particle nearest (x, y) in a sequence visited one by one: the lowest among
// equally near ones.
struct NearestParticle {
  double x = 0.0, y = 0.0;
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t id = 0;
  void visit(double px, double py, std::uint32_t pid);
};
// Appends one row per station at the state's time.
void sample_stations(RunState& s, std::vector<StationProbe>& probes,
                     std::vector<StationSeries>& series);
void write_stations(const std::string& dir, const std::vector<StationSpec>& specs,
                    const std::vector<StationProbe>& probes,
                    const std::vector<StationSeries>& series);

}  // namespace rupture
