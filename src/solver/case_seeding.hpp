// rupture/solver/case_seeding.hpp
// A case's particles at t = 0 without storing them: every body's seed points (particles/seed.hpp)
// in the order make_state appends them, each with the id it gets there (0, 1, ... over the
// bodies). A distributed run's ranks walk them to split the grid by particle count, to choose
// the snapshots' rows, the stations' particles and the traction loads' particles as one process
// does, and keep only their own (make_state with a ParticleShare): memory per rank is its particles, never
// the case's; time is one visit of every point per rank.
// Units: m, kg.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "input/case.hpp"
#include "particles/seed.hpp"
#include "solver/run_state.hpp"

namespace rupture {

// One point of body `body` (index into Case::bodies) with its id.
using CasePointVisit = std::function<void(const SeedPoint&, std::size_t body, std::uint32_t id)>;
void for_each_case_point(const Case& c, const Grid& g, const CasePointVisit& visit);

// The particles at t = 0 of the run r was made for (make_run_state: a uniform or graded grid,
// or nested levels, whatever particles r holds), in id order: centre (m) and id.
using RunPointVisit = std::function<void(double, double, std::uint32_t id)>;
void for_each_run_point(const Case& c, const RunState& r, const RunPointVisit& visit);

// A particle centre's test (x, y in m).
using PointFilter = std::function<bool(double, double)>;

// The particles at t = 0 near c.loads (a traction segment's reach, a velocity region's box, a
// point force's neighbourhood) on grid g, with the ids one process gives them from first_id, in
// id order: a distributed rank (or a nested level) finds the loads' particles among them as one
// process finds them among all. With `keep` (a nested level, solver/nested_state.hpp), the points of g's lattice seeded
// through every body's region that `keep` accepts, as make_level_state makes them.
Particles particles_near_loads(const Case& c, const Grid& g, const PointFilter* keep, std::uint32_t first_id);

// What the points add up to: particles per cell of g (cell (c, r) at c + r cols; a centre on
// the lattice's edge counts in the edge cell), how many, and the lightest particle's mass.
struct CaseTally {
  std::vector<std::uint32_t> per_cell;
  std::size_t particles = 0;
  double min_mass = 0.0;  // kg per unit thickness
};
CaseTally tally_case_points(const Case& c, const Grid& g);

// make_state (solver/state.hpp) with a ParticleShare: only the particles the share accepts,
// with the ids one process gives them. Everything else is the whole case's (grid, boundary,
// interfaces, loads: a traction patch is found among every particle near its segment, as one
// process finds it).

}  // namespace rupture
