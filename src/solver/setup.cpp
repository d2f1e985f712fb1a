// rupture/solver/setup.cpp
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <utility>

#include "particles/seed.hpp"
#include "solver/absorbing_setup.hpp"
#include "solver/case_seeding.hpp"
#include "solver/energy.hpp"
#include "solver/field_windows.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/crack_nucleation.hpp"
#include "solver/load_step.hpp"
#include "solver/nested_state.hpp"
#include "solver/run_state.hpp"
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

// Visits body b's points on grid g in the order one process appends them.
void for_each_body_point(const Case& c, const Grid& g, const BodySpec& b, const SeedVisit& visit) {
  const int ppc = c.grid.particles_per_cell;
  if (!b.plain_rectangle())  // point-in-shape of the sub-cell centres (particles/seed.hpp)
    for_each_seed_point(g, b.region, ppc, visit);
  else if (g.graded())
    for_each_graded_rectangle_point(g, b.min, b.max, ppc, visit);
  else
    for_each_rectangle_point(b.min, b.max, c.grid.cell_size, ppc, g.domain_min, visit);
}

SeedProperties seed_properties(const Case& c, const BodySpec& b) {
  const ElasticMaterial& m = c.materials[std::size_t(b.material)];
  return {m.density, std::uint8_t(b.field), std::uint8_t(b.material), {b.velocity[0], b.velocity[1]}};
}

}  // namespace

// Every particle at t = 0 (ids as one process gives them) whose box may meet a traction load's
// segment or be among the nearest to its points (bc/loads.hpp: find_traction_patch looks no
// further than twice a particle's half-diagonal, at most hypot(wx, wy) <= wx + wy for the
// widest cells), or in a velocity region's box, in id order: find_traction_patch and
// region_particles on them find what they find on all.
Particles particles_near_loads(const Case& c, const Grid& g, const PointFilter* keep, std::uint32_t first_id) {
  Particles near;
  if (c.loads.tractions.empty() && c.loads.velocity_regions.empty() && c.loads.point_forces.empty())
    return near;
  double wx = 0.0, wy = 0.0;
  for (int i = 0; i < g.x.cells; ++i) wx = std::max(wx, g.x.width(i));
  for (int j = 0; j < g.y.cells; ++j) wy = std::max(wy, g.y.width(j));
  const double R = wx + wy;
  std::uint32_t id = first_id;
  for (const BodySpec& b : c.bodies) {
    const SeedProperties props = seed_properties(c, b);
    const SeedVisit visit = [&](const SeedPoint& p) {
      if (keep && !(*keep)(p.x, p.y)) return;  // another level's
      for (const VelocityRegion& r : c.loads.velocity_regions)  // bc/loads.cpp: region_particles
        if (p.x >= r.min[0] && p.x <= r.max[0] && p.y >= r.min[1] && p.y <= r.max[1]) {
          append_seed_point(near, p, props, id++);
          return;
        }
      for (const PointForceLoad& f : c.loads.point_forces)  // bc/loads.cpp: find_point_spread
        if (std::fabs(p.x - f.point[0]) < R && std::fabs(p.y - f.point[1]) < R) {
          append_seed_point(near, p, props, id++);
          return;
        }
      for (const TractionLoad& t : c.loads.tractions) {
        const double dx = t.to[0] - t.from[0], dy = t.to[1] - t.from[1], L = std::hypot(dx, dy);
        const double rx = p.x - t.from[0], ry = p.y - t.from[1];
        const double along = (rx * dx + ry * dy) / L, across = (rx * dy - ry * dx) / L;
        if (along > -R && along < L + R && std::fabs(across) < R) {
          append_seed_point(near, p, props, id);
          break;
        }
      }
      ++id;
    };
    if (keep)  // a nested level's: through the region on its lattice (make_state_on)
      for_each_seed_point(g, b.region, c.grid.particles_per_cell, visit);
    else
      for_each_body_point(c, g, b, visit);
  }
  return near;
}

namespace {

// make_state on a given grid. With `keep` (a nested level, solver/nested_state.hpp) every body
// is seeded through its region on this lattice, only the particles `keep` accepts stay, ids
// are their indices among those, and the boundary conditions are left to the caller. With `own`
// (a rank of a distributed run, solver/case_seeding.hpp) only the particles `own` accepts are
// made, with the ids they get without it.
State make_state_on(const Case& c, Grid grid, const PointFilter* keep, const PointFilter* own) {
  State s;
  s.grid = std::move(grid);
  const int num_fields = int(c.field_names.size());  // bodies sharing a field share its arrays
  // Whole-grid fields until the particles exist; fitted to windows below (solver/field_windows.hpp).
  // A rank's start with one node each: it never holds the whole grid.
  if (own) {
    const std::vector<int> zero(std::size_t(num_fields), 0), one(std::size_t(num_fields), 1);
    s.fields.set_windows(std::size_t(s.grid.nodes_x()), std::size_t(s.grid.nodes_y()), zero, one, zero, one);
  } else {
    s.fields.resize(num_fields, std::size_t(s.grid.nodes_x()), std::size_t(s.grid.nodes_y()));
  }

  for (const ElasticMaterial& m : c.materials) s.stiffness.push_back(stiffness(m, c.plane));
  const int ppc = c.grid.particles_per_cell;
  std::uint32_t next_id = 0;  // the id one process gives the next point
  for (const BodySpec& b : c.bodies) {
    const SeedProperties props = seed_properties(c, b);
    const std::size_t first = s.particles.size();
    if (keep) {  // through the region on this lattice; ids: the index among the kept
      for_each_seed_point(s.grid, b.region, ppc, [&](const SeedPoint& p) {
        if (!(*keep)(p.x, p.y)) return;
        if (!own || (*own)(p.x, p.y)) append_seed_point(s.particles, p, props, next_id);
        ++next_id;
      });
    } else {
      for_each_body_point(c, s.grid, b, [&](const SeedPoint& p) {
        if (!own || (*own)(p.x, p.y)) append_seed_point(s.particles, p, props, next_id);
        ++next_id;
      });
    }
    prestress(s.particles, first, s.particles.size(), b, c.materials[std::size_t(b.material)], c.plane);
  }
  // Kelvin-Voigt damping: the particles carry their viscous stress (particles/particles.hpp).
  for (const ElasticMaterial& m : c.materials)
    if (m.kelvin_voigt > 0.0) s.particles.enable_viscous();
  if (!keep) {
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

  for (const InterfaceSpec& drawn : c.interfaces) {
    // A line that nucleates starts tied over itself (solver/crack_nucleation.hpp).
    const InterfaceSpec is = as_set_up(drawn, 1e-6 * c.grid.cell_size);
    s.interfaces.push_back(make_interface(is));
    if (is.contact) {  // a quarter of the face mass the set-up's step bound assumes (summarize)
      const double rho = std::min(c.materials[std::size_t(c.bodies[std::size_t(is.upper_body)].material)].density,
                                  c.materials[std::size_t(c.bodies[std::size_t(is.lower_body)].material)].density);
      const double h = std::min(s.grid.x.min_width(), s.grid.y.min_width());
      s.interfaces.back().light_face_mass = 0.25 * 0.5 * rho * h * h;
    }
    evaluate_interface(s.interfaces.back(), 0.0, 0.0);  // tractions and stiffnesses at rest
    s.bonded.push_back({is.upper_field, is.lower_field, bonded_nodes(s.grid, is)});
  }
  s.scheme = c.solver.scheme;
  s.flip = c.solver.flip;
  s.mass_matrix = c.solver.mass;
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
  if (keep) return s;  // a nested level: its loads by the run's ids (make_nested_state)
  if (own) {  // a traction patch: found among every particle near its segment
    const Particles near = particles_near_loads(c, s.grid, nullptr, 0);
    set_up_loads(s, c.loads, c.grid.cell_size, &near);
  } else {
    set_up_loads(s, c.loads, c.grid.cell_size);
  }
  return s;
}

}  // namespace

void for_each_case_point(const Case& c, const Grid& g, const CasePointVisit& visit) {
  std::uint32_t id = 0;
  for (std::size_t k = 0; k < c.bodies.size(); ++k)
    for_each_body_point(c, g, c.bodies[k], [&](const SeedPoint& p) { visit(p, k, id++); });
}

void for_each_run_point(const Case& c, const RunState& r, const RunPointVisit& visit) {
  if (!r.is_nested()) {
    for_each_case_point(c, r.levels[0].grid, [&](const SeedPoint& p, std::size_t, std::uint32_t id) { visit(p.x, p.y, id); });
    return;
  }
  std::uint32_t id = 0;  // level l's ids follow level l - 1's (solver/nested_state.cpp)
  for (std::size_t l = 0; l < r.levels.size(); ++l)
    for_each_level_point(c, r, int(l), [&](double x, double y, double) { visit(x, y, id++); });
}

CaseTally tally_case_points(const Case& c, const Grid& g) {
  CaseTally t;
  const int cols = g.x.cells, rows = g.y.cells;
  t.per_cell.assign(std::size_t(cols) * std::size_t(rows), 0);
  t.min_mass = std::numeric_limits<double>::max();
  for_each_case_point(c, g, [&](const SeedPoint& p, std::size_t body, std::uint32_t) {
    const int i = std::clamp(g.x.cell_of(p.x), 0, cols - 1), j = std::clamp(g.y.cell_of(p.y), 0, rows - 1);
    ++t.per_cell[std::size_t(i) + std::size_t(j) * std::size_t(cols)];
    ++t.particles;
    // The mass append_seed_point gives it (particles/seed.cpp: density * lx * ly).
    const double m = c.materials[std::size_t(c.bodies[body].material)].density * p.lx * p.ly;
    t.min_mass = std::min(t.min_mass, m);
  });
  return t;
}

ParticleShare ParticleShare::none() {
  ParticleShare s;
  s.own = [](double, double) { return false; };
  s.own_level = [](int, double, double) { return false; };
  s.from_checkpoint = true;
  return s;
}

State make_state(const Case& c, const ParticleShare* share) {
  if (c.grid.nested) throw std::logic_error("make_state: nested levels are a RunState (make_run_state)");
  State s = make_state_on(c, build_grid(c.grid), nullptr, share ? &share->own : nullptr);
  s.particles_from_checkpoint = share && share->from_checkpoint;
  return s;
}

RunState make_run_state(const Case& c, const ParticleShare* share) {
  RunState r;
  if (c.grid.nested) {
    r = make_nested_state(c, share);  // the levels, their interfaces and the transitions
    // The run's limits and step at t = 0 are the coarsest level's (as its clock: every level
    // starts with the common dt), the energies the levels' sums.
    r.limits = r.levels[0].limits;
    for (const State& l : r.levels) r.initial_energy += l.initial_energy;
    r.grid_level = r.levels.size() - 1;
    if (!r.interface_levels.empty())
      r.grid_level = std::size_t(*std::max_element(r.interface_levels.begin(), r.interface_levels.end()));
  } else {
    r.levels.push_back(make_state(c, share));
    for (std::size_t k = 0; k < r.levels[0].interfaces.size(); ++k)
      r.interface_levels.push_back(0), r.interface_slots.push_back(k);
    r.initial_energy = r.levels[0].initial_energy;
  }
  r.particles_from_checkpoint = share && share->from_checkpoint;
  collect_run_sums(r);
  return r;
}

State make_level_state(const Case& c, Grid lattice, const std::function<bool(double, double)>& keep,
                       const std::function<bool(double, double)>* own) {
  return make_state_on(c, std::move(lattice), &keep, own);
}

}  // namespace rupture
