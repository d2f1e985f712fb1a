// rupture/parallel/rank_state.cpp
// A fresh distributed run's State, made by each rank alone (parallel/halo.hpp: make_rank_state).
// Every rank walks the case's seed points once to count them per cell (solver/case_seeding.hpp;
// no particle stored), bisects the counts as plan_ranks bisects a whole State's (the same
// split), and seeds only the particles whose cell lies in its block, with the ids one process
// gives them. The sums over particles a State holds become the run's by reductions: the mass
// floor from the lightest particle of the case (exact), the initial energy as the ranks' parts
// added (round-off of the one-process sum), the strain work this rank's part (as distribute).
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "core/errors.hpp"
#include "parallel/decomposition.hpp"
#include "parallel/halo.hpp"
#include "solver/case_seeding.hpp"
#include "solver/energy.hpp"

namespace rupture {

State make_rank_state(const Case& c, const Comm& comm) {
  if (c.grid.nested) {  // nested levels: split after a whole set-up
    State s = make_state(c);
    distribute(s, comm);
    return s;
  }
  const Grid g = build_grid(c.grid);
  const int cols = g.x.cells, rows = g.y.cells;
  const CaseTally tally = tally_case_points(c, g);
  Decomposition d;
  try {
    d = bisect_by_particles(tally.per_cell, cols, rows, comm.size());
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("mpirun -n {}: {}", comm.size(), e.what()));
  }
  const CellBlock mine = d.block[std::size_t(comm.rank())];
  State s = make_state_owning(c, [&](double x, double y) {
    const int i = std::clamp(g.x.cell_of(x), 0, cols - 1), j = std::clamp(g.y.cell_of(y), 0, rows - 1);
    return i >= mine.c0 && i < mine.c1 && j >= mine.r0 && j < mine.r1;
  });
  check_distributable(s, comm.size());
  attach_halo(s, comm);
  set_blocks(s, d.block);
  s.mass_floor = 1e-20 * tally.min_mass;  // solver/setup.cpp: the case's lightest particle
  // E14: the strain work starts from this rank's part of the elastic energy (make_state_owning
  // measured it on this rank's particles); the initial energy is the run's.
  s.initial_energy = comm.sum(kinetic_energy(s.particles) + s.strain_work);
  return s;
}

}  // namespace rupture
