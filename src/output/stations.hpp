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
// t = 0 (read = "interpolated": a linear least-squares fit of its body's particles within a
// cell, at the point): where it is, its velocity and its displacement since t = 0 (ux, uy, m:
// its position less the first sample's, which is taken at t = 0). Written to DIR/stations/NAME.csv
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
  // An interpolated body station (read = "interpolated"): its particles, their weights (the
  // fit's value at the point is sum_k w_k q_k) and slots; empty: the one particle above.
  std::vector<std::uint32_t> fit_ids;
  std::vector<double> fit_weights;
  std::vector<std::size_t> fit_slots;
};

// Columns of a sample (the rows stored); a body station's file adds ux, uy (from x, y).
inline constexpr std::size_t kFaultColumns = 8;  // time, slip, slip_rate, opening, shear, normal,
                                                 // jump_rate, state (written on rate-and-state
                                                 // faults only)
inline constexpr std::size_t kBodyColumns = 5;   // time, x, y, vx, vy

// The id of the particle nearest (x, y) in a sequence visited one by one: the lowest among
// equally near ones.
// With radius > 0 it also keeps every point within radius (an interpolated station's
// candidates).
struct NearestParticle {
  NearestParticle(double px, double py, double r = 0.0) : x(px), y(py), radius(r) {}
  double x = 0.0, y = 0.0;
  double radius = 0.0;  // m
  double best = std::numeric_limits<double>::infinity();
  std::uint32_t id = 0;
  double best_x = 0.0, best_y = 0.0;
  struct Point {
    double x, y;
    std::uint32_t id;
  };
  std::vector<Point> near;
  void visit(double px, double py, std::uint32_t pid);
};

// The weights w_k of a linear least-squares fit a + b (x - x0) + c (y - y0) of values at
// `points`, evaluated at (x0, y0): a = sum_k w_k q_k. Exact for a linear field; empty when the
// points do not span the plane (fewer than three, or on one line).
std::vector<double> linear_fit_weights(const std::vector<NearestParticle::Point>& points, double x0,
                                       double y0);

// What each station visits at t = 0: the point, and for an interpolated station the radius
// (one cell of the run's grid at the point, the larger width).
std::vector<NearestParticle> station_visitors(const Case& c, const RunState& s);
// A body station reads the particle nearest its point at t = 0, the lowest id among equally
// near ones (so the choice does not depend on the particles' order): among s's particles, or
// when `visited` is given, its entry for the station (a distributed run's visit of every
// particle the case seeds, solver/case_seeding.hpp; entries of fault stations unused).
std::vector<StationProbe> make_probes(const Case& c, RunState& s,
                                      const std::vector<NearestParticle>* visited = nullptr);
// Appends one row per station at the state's time.
void sample_stations(RunState& s, std::vector<StationProbe>& probes,
                     std::vector<StationSeries>& series);
void write_stations(const std::string& dir, const std::vector<StationSpec>& specs,
                    const std::vector<StationProbe>& probes,
                    const std::vector<StationSeries>& series);

}  // namespace rupture
