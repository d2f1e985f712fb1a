// rupture/solver/crack_cut.cpp
#include "solver/crack_cut.hpp"

#include <algorithm>
#include <cmath>

#include "grid/grid.hpp"

namespace rupture {

Region crack_body(const Case& c, std::size_t k) {
  const Region& r = c.bodies[std::size_t(c.interfaces[k].upper_body)].region;
  return Region{r.outer, r.minus};
}

Box cut_frame(const Region& body, const Polyline& line, const Point& p, double h) {
  Box f = bounding_box(body);
  auto take = [&](double x, double y) {
    f.min[0] = std::min(f.min[0], x), f.max[0] = std::max(f.max[0], x);
    f.min[1] = std::min(f.min[1], y), f.max[1] = std::max(f.max[1], y);
  };
  for (std::size_t i = 0; i < line.num_vertices(); ++i) take(line.x[i], line.y[i]);
  take(p.x, p.y);
  const double pad = 3.0 * h + 0.01 * std::max(f.max[0] - f.min[0], f.max[1] - f.min[1]);  // > the tie's lead
  for (int d = 0; d < 2; ++d) f.min[d] -= pad, f.max[d] += pad;
  return f;
}

Point unit(const Point& from, const Point& to) {
  const double l = std::hypot(to.x - from.x, to.y - from.y);
  return {(to.x - from.x) / l, (to.y - from.y) / l};
}

double distance_to_line(const Polyline& line, const Point& p) {
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < line.num_vertices(); ++i) {
    const double ax = line.x[i], ay = line.y[i], bx = line.x[i + 1] - ax, by = line.y[i + 1] - ay;
    const double l2 = bx * bx + by * by;
    const double u = l2 > 0.0 ? std::clamp(((p.x - ax) * bx + (p.y - ay) * by) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(p.x - ax - u * bx, p.y - ay - u * by));
  }
  return best;
}

void move_particle_to_field(State& L, std::size_t q, std::uint8_t field) {
  Particles& P = L.particles;
  P.field[q] = field;
  // The drift since the sort widens the rows from there on, as it does for the rows the sort
  // found.
  ScatterPlan& plan = L.plan;
  if (!plan.rows_known) return;
  const auto at = std::upper_bound(plan.strip_begin.begin(), plan.strip_begin.end(), q);
  const std::size_t strip = std::size_t(at - plan.strip_begin.begin()) - 1;
  const int row = std::clamp(stencil_first(L.grid.y, P.y[q], P.half_y[q]), 0, L.grid.y.cells - 1);
  const std::size_t e = strip * std::size_t(L.fields.num_fields) + field;
  plan.row_lo[e] = std::min(plan.row_lo[e], row);
  plan.row_hi[e] = std::max(plan.row_hi[e], row);
}

// A fresh or restored state's mark (solver/field_windows.cpp measures when the last check was not
// the previous step): not a drift, so nothing checkpointed reads it, and nested levels' particles
// are not moved between levels for it.
void measure_windows_again(State& L) { L.windows_checked_step = -2; }

}  // namespace rupture
