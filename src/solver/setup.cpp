// rupture/solver/setup.cpp
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/energy.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/summary.hpp"

namespace rupture {

State make_state(const Case& c) {
  State s;
  s.grid = make_uniform_grid(c.grid.min, c.grid.max, c.grid.cell_size);
  const int num_fields = int(c.bodies.size());
  s.fields.resize(num_fields, s.grid.num_nodes());

  for (const ElasticMaterial& m : c.materials) s.stiffness.push_back(stiffness(m, c.plane));
  for (const BodySpec& b : c.bodies) {
    seed_rectangle(s.particles, b.min, b.max, c.grid.cell_size, c.grid.particles_per_cell,
                   c.materials[b.material].density, std::uint8_t(b.field),
                   std::uint8_t(b.material), b.velocity);
  }
  s.boundary = c.boundary;
  s.bc_nodes = resolve_nodes(s.boundary, s.grid, num_fields);

  const CaseSummary summary = summarize(c);
  s.limits.cfl_dt = summary.dt_cfl;
  s.limits.cohesive_dt = summary.dt_cohesive > 0 ? summary.dt_cohesive : INFINITY;
  s.limits.dt = summary.dt;
  s.dt = s.limits.dt;

  for (const InterfaceSpec& is : c.interfaces) {
    s.interfaces.push_back(make_interface(is));
    s.bonded.push_back(bonded_nodes(s.grid, is));
  }
  s.scheme = c.solver.scheme;
  s.flip = c.solver.flip;
  double min_mass = std::numeric_limits<double>::max();
  for (double m : s.particles.mass) min_mass = std::min(min_mass, m);
  // Only nodes touched by nothing but the extreme tail of a particle (weight < 1e-20) are
  // treated as empty. A higher floor zeroes the velocity of lightly touched nodes whose weight
  // gradient is not small (dS ~ sqrt(S)), which breaks rigid-body motion at the 1e-9 level.
  s.mass_floor = 1e-20 * min_mass;
  s.initial_energy = kinetic_energy(s.particles) + strain_energy(s.particles);
  // Sorted from the start, so particle indices are stable until the first re-sort.
  build_scatter_plan(s);
  return s;
}

}  // namespace rupture
