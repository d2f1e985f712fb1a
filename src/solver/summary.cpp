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
  // 11 nodal arrays per field (grid/grid.hpp) + particle arrays + plan (order + strip_of).
  s.memory_bytes = std::size_t(s.nodes) * std::size_t(s.fields) * 11 * sizeof(double) +
                   std::size_t(s.particles) * (Particles::bytes_per_particle() + 8);
  return s;
}

}  // namespace rupture
