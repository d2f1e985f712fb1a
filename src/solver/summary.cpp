// rupture/solver/summary.cpp
#include "solver/summary.hpp"

#include <algorithm>
#include <cmath>

#include "grid/grid.hpp"
#include "particles/particles.hpp"

namespace rupture {

CaseSummary summarize(const Case& c) {
  CaseSummary s;
  double max_cd = 0.0;
  for (const ElasticMaterial& m : c.materials) {
    s.speeds.push_back(wave_speeds(m, c.plane));
    max_cd = std::max(max_cd, s.speeds.back().dilatational);
  }
  const double h = c.grid.cell_size;
  s.dt_cfl = c.time.cfl * h / max_cd;
  s.dt = s.dt_cfl;
  // SPEC E6: two face nodes of mass m = rho h^2/2 (interface row, per field) joined by a
  // spring k = K h, K the law's initial stiffness or the penalty if larger: dt < 2/sqrt(2k/m).
  for (const InterfaceSpec& is : c.interfaces) {
    const double rho = std::min(c.materials[c.bodies[is.upper_field].material].density,
                                c.materials[c.bodies[is.lower_field].material].density);
    const double k = std::max(is.law.initial_stiffness(), is.law.penalty_stiffness()) * h;
    const double m = 0.5 * rho * h * h;
    const double limit = 2.0 / std::sqrt(2.0 * k / m);
    s.dt_cohesive = s.dt_cohesive > 0 ? std::min(s.dt_cohesive, limit) : limit;
  }
  if (s.dt_cohesive > 0) s.dt = std::min(s.dt, c.time.cohesive_safety * s.dt_cohesive);
  s.steps = long(std::ceil(c.time.end / s.dt - 1e-9));
  const long cx = std::lround((c.grid.max[0] - c.grid.min[0]) / h);
  const long cy = std::lround((c.grid.max[1] - c.grid.min[1]) / h);
  s.cells = cx * cy;
  const long ghost = Grid{}.ghost;
  s.nodes = (cx + 2 * ghost + 1) * (cy + 2 * ghost + 1);
  const long ppc = c.grid.particles_per_cell;
  for (const BodySpec& b : c.bodies) {
    const long n = std::lround((b.max[0] - b.min[0]) / h) * std::lround((b.max[1] - b.min[1]) / h) *
                   ppc * ppc;
    s.particles_per_body.push_back(n);
    s.particles += n;
  }
  s.fields = int(c.bodies.size());
  // 11 nodal arrays per field (grid/grid.hpp) + particle arrays + sort scratch (order, one
  // double array for the permutation).
  std::size_t interface_bytes = 0;
  for (const InterfaceSpec& is : c.interfaces)
    interface_bytes += std::size_t(is.segments) * (4 * 4 * sizeof(double) + 4 + 4 * sizeof(double)) +
                       std::size_t(is.segments + 1) * 8 * sizeof(double);
  s.memory_bytes = interface_bytes + std::size_t(s.nodes) * std::size_t(s.fields) * 11 * sizeof(double) +
                   std::size_t(s.particles) * (Particles::bytes_per_particle() + 12);
  return s;
}

}  // namespace rupture
