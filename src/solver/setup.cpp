// rupture/solver/setup.cpp
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

#include "particles/seed.hpp"
#include "solver/energy.hpp"
#include "solver/field_windows.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/load_step.hpp"
#include "solver/nested_state.hpp"
#include "solver/summary.hpp"

namespace rupture {
namespace {

// The body's uniform initial stress (bodies.NAME.stress) on its particles [first, last).
void prestress(Particles& P, std::size_t first, std::size_t last, const BodySpec& b,
               const ElasticMaterial& m, PlaneMode plane) {
  if (b.stress[0] == 0.0 && b.stress[1] == 0.0 && b.stress[2] == 0.0) return;
  const ElasticState e = prestressed_state(m, plane, b.stress[0], b.stress[1], b.stress[2]);
  for (std::size_t p = first; p < last; ++p) {
    P.sxx[p] = e.sxx, P.syy[p] = e.syy, P.sxy[p] = e.sxy;  // strain, sigma_zz: derived
  }
}

// Drops the particles [first, size) that `keep` rejects (by centre).
void keep_only(Particles& P, std::size_t first, const std::function<bool(double, double)>& keep) {
  std::vector<unsigned char> drop(P.size(), 0);
  for (std::size_t p = first; p < P.size(); ++p) drop[p] = !keep(P.x[p], P.y[p]);
  Particles dropped;
  P.move_marked(drop, dropped);
}

// make_state on a given grid. With `keep` (a nested level, solver/nested_state.hpp) every body
// is seeded through its region on this lattice, only the particles `keep` accepts stay, ids
// are their indices, and the boundary conditions are left to the caller.
State make_state_on(const Case& c, Grid grid, const std::function<bool(double, double)>* keep) {
  State s;
  s.grid = std::move(grid);
  const int num_fields = int(c.field_names.size());  // bodies sharing a field share its arrays
  // Whole-grid fields until the particles exist; fitted to windows below (solver/field_windows.hpp).
  s.fields.resize(num_fields, std::size_t(s.grid.nodes_x()), std::size_t(s.grid.nodes_y()));

  for (const ElasticMaterial& m : c.materials) s.stiffness.push_back(stiffness(m, c.plane));
  const int ppc = c.grid.particles_per_cell;
  for (const BodySpec& b : c.bodies) {
    const ElasticMaterial& m = c.materials[std::size_t(b.material)];
    const SeedProperties props{m.density, std::uint8_t(b.field), std::uint8_t(b.material),
                               {b.velocity[0], b.velocity[1]}};
    const std::size_t first = s.particles.size();
    if (keep) {
      seed_region(s.particles, s.grid, b.region, ppc, props);
      keep_only(s.particles, first, *keep);
    } else if (!b.plain_rectangle())  // point-in-shape of the sub-cell centres (particles/seed.hpp)
      seed_region(s.particles, s.grid, b.region, ppc, props);
    else if (s.grid.graded())
      seed_graded_rectangle(s.particles, s.grid, b.min, b.max, ppc, props);
    else
      seed_rectangle(s.particles, b.min, b.max, c.grid.cell_size, ppc, m.density,
                     std::uint8_t(b.field), std::uint8_t(b.material), b.velocity,
                     s.grid.domain_min);
    prestress(s.particles, first, s.particles.size(), b, m, c.plane);
  }
  if (keep) {
    for (std::size_t p = 0; p < s.particles.size(); ++p) s.particles.id[p] = std::uint32_t(p);
  } else {
    s.boundary = c.boundary;
    update_edge_lines(s.boundary, s.grid, 0.0, s.bc_lines);
    s.bc_nodes = resolve_nodes(s.boundary, s.grid, num_fields, s.bc_lines);
    s.absorbing = absorbing_nodes(c, s.grid);
  }

  const CaseSummary summary = summarize(c);
  s.limits.cfl_dt = summary.dt_cfl;
  s.limits.bulk_eigen_bound = summary.bulk_eigen_bound;
  s.limits.cohesive_dt = summary.dt_cohesive > 0 ? summary.dt_cohesive : INFINITY;
  s.limits.dt = summary.dt;
  s.dt = s.limits.dt;
  s.cohesive_safety = c.time.cohesive_safety;

  for (const InterfaceSpec& is : c.interfaces) {
    s.interfaces.push_back(make_interface(is));
    evaluate_interface(s.interfaces.back(), 0.0, 0.0);  // tractions and stiffnesses at rest
    s.bonded.push_back({is.upper_field, is.lower_field, bonded_nodes(s.grid, is)});
  }
  s.scheme = c.solver.scheme;
  s.flip = c.solver.flip;
  double min_mass = std::numeric_limits<double>::max();
  for (double m : s.particles.mass) min_mass = std::min(min_mass, m);
  // Only nodes touched by nothing but the extreme tail of a particle (weight < 1e-20) are
  // treated as empty. A higher floor zeroes the velocity of lightly touched nodes whose weight
  // gradient is not small (dS ~ sqrt(S)), which breaks rigid-body motion at the 1e-9 level.
  s.mass_floor = 1e-20 * min_mass;
  s.strain_work = strain_energy(s.particles, s.stiffness);  // the elastic energy at t = 0 (prestress)
  s.initial_energy = kinetic_energy(s.particles) + s.strain_work;
  // Sorted from the start, so particle indices are stable until the first re-sort.
  build_scatter_plan(s);
  fit_field_windows(s);
  s.windows_checked_step = -2;  // the first step measures again
  set_up_loads(s, c.loads, c.grid.cell_size);
  return s;
}

}  // namespace

State make_state(const Case& c) {
  if (c.grid.nested) return make_nested_run_state(c);  // solver/nested_state.hpp
  return make_state_on(c, build_grid(c.grid), nullptr);
}

State make_level_state(const Case& c, Grid lattice, const std::function<bool(double, double)>& keep) {
  return make_state_on(c, std::move(lattice), &keep);
}

}  // namespace rupture
