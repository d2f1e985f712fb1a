// rupture/solver/crack_cut.hpp
// The geometry a growing crack's cut is made of, shared by growth and branching
// (solver/crack_growth.cpp, solver/crack_branching.cpp): the body the crack was drawn in, a
// frame around it for the cuts to run out to, and moving a particle to another velocity field
// between sorts. Reference coordinates, m.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>

#include "geometry/shape.hpp"
#include "input/case.hpp"
#include "solver/state.hpp"

namespace rupture {

// The material crack k grows through: the body it was drawn in (its shape and cut-outs, without
// the cuts of lines), less the parts beyond its reach (input/crack_reach.hpp). Their lines are
// then edges of its reach, as an interface between its body and another is: a segment that
// would cross one ends on it, and a tie ends there (solver/crack_junction.hpp).
Region crack_body(const Case& c, std::size_t k);
// The same less the parts other lines have cut off since (InterfaceSpec::reach_cut_off of the
// crack's line `now`, as the run holds it).
Region crack_body(const Case& c, std::size_t k, const InterfaceSpec& now);

// A frame around the body, the line and p with room to spare (more than a tie's lead).
Box cut_frame(const Region& body, const Polyline& line, const Point& p, double h);

inline bool near(const Point& a, double x, double y, double tol) { return std::hypot(a.x - x, a.y - y) <= tol; }

// The unit vector from `from` to `to`.
Point unit(const Point& from, const Point& to);

// The shortest distance from p to the polyline, m.
double distance_to_line(const Polyline& line, const Point& p);

// Where the segment a -> b comes within `tol` (m) of `line`: the point of the line nearest the
// segment and their distance (0 where they cross); nothing when it stays farther.
struct LineMeeting {
  Point at;
  double distance = 0.0;  // m
};
std::optional<LineMeeting> segment_meets_line(const Polyline& line, const Point& a, const Point& b, double tol);

// Whether interface `spec` is drawn inside the body crack k was drawn in (both its faces' bodies
// are parts of that body: the same outer shape), rather than between two bodies.
bool drawn_in_crack_body(const Case& c, std::size_t k, const InterfaceSpec& spec);

// Particle q of level L goes to `field`: the strips' node rows per field (ScatterPlan::row_lo,
// row_hi, from the last sort) take its row in the new field, so the tile keeps its stencil; the
// caller calls measure_windows_again(L) once it has moved them.
void measure_windows_again(State& L);  // the next step measures the fields' windows from the particles
void move_particle_to_field(State& L, std::size_t q, std::uint8_t field);

}  // namespace rupture
