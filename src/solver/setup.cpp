// rupture/solver/setup.cpp
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/energy.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/load_step.hpp"
#include "solver/summary.hpp"

namespace rupture {
namespace {

// SPEC §5: on a refined grid every cell the body covers gets ppc x ppc particles of the
// cell's own size (rectangular where the cell is), in rows of particles across the body.
void seed_graded(Particles& P, const Grid& g, const BodySpec& b, int ppc, double density) {
  const double tol = 1e-9 * g.x.h;
  std::vector<int> cols, rows;
  for (int i = 0; i < g.x.cells; ++i) {
    const double xc = g.x.node(i) + 0.5 * g.x.width(i);
    if (xc > b.min[0] - tol && xc < b.max[0] + tol) cols.push_back(i);
  }
  for (int j = 0; j < g.y.cells; ++j) {
    const double yc = g.y.node(j) + 0.5 * g.y.width(j);
    if (yc > b.min[1] - tol && yc < b.max[1] + tol) rows.push_back(j);
  }
  std::size_t k = P.size();
  P.resize(k + cols.size() * rows.size() * std::size_t(ppc * ppc));
  for (int j : rows)
    for (int sj = 0; sj < ppc; ++sj)
      for (int i : cols)
        for (int si = 0; si < ppc; ++si, ++k) {
          const double lx = g.x.width(i) / ppc, ly = g.y.width(j) / ppc;
          P.x[k] = g.x.node(i) + (si + 0.5) * lx;
          P.y[k] = g.y.node(j) + (sj + 0.5) * ly;
          P.vx[k] = b.velocity[0];
          P.vy[k] = b.velocity[1];
          P.volume0[k] = P.volume[k] = lx * ly;
          P.mass[k] = density * lx * ly;
          P.half_x[k] = 0.5 * lx;
          P.half_y[k] = 0.5 * ly;
          P.field[k] = std::uint8_t(b.field);
          P.material[k] = std::uint8_t(b.material);
          P.id[k] = std::uint32_t(k);
        }
}

}  // namespace

State make_state(const Case& c) {
  State s;
  s.grid = build_grid(c.grid);
  const int num_fields = int(c.bodies.size());
  s.fields.resize(num_fields, s.grid.num_nodes());

  for (const ElasticMaterial& m : c.materials) s.stiffness.push_back(stiffness(m, c.plane));
  for (const BodySpec& b : c.bodies) {
    if (s.grid.graded())
      seed_graded(s.particles, s.grid, b, c.grid.particles_per_cell, c.materials[b.material].density);
    else
      seed_rectangle(s.particles, b.min, b.max, c.grid.cell_size, c.grid.particles_per_cell,
                     c.materials[b.material].density, std::uint8_t(b.field),
                     std::uint8_t(b.material), b.velocity);
  }
  s.boundary = c.boundary;
  update_edge_lines(s.boundary, s.grid, 0.0, s.bc_lines);
  s.bc_nodes = resolve_nodes(s.boundary, s.grid, num_fields, s.bc_lines);

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
  set_up_loads(s, c.loads, c.grid.cell_size);
  return s;
}

}  // namespace rupture
