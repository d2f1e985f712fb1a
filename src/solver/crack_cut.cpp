// rupture/solver/crack_cut.cpp
#include "solver/crack_cut.hpp"

#include <algorithm>
#include <cmath>

#include "grid/grid.hpp"
#include "input/crack_reach.hpp"

namespace rupture {

Region crack_body(const Case& c, std::size_t k) {
  const Region& r = c.bodies[std::size_t(c.interfaces[k].upper_body)].region;
  Region reach{r.outer, r.minus};
  const std::vector<int> beyond = fields_beyond_reach(c, k);
  for (const BodySpec& b : c.bodies)
    if (same_drawn_region(b.region, r) && std::find(beyond.begin(), beyond.end(), b.field) != beyond.end())
      reach.minus_parts.push_back(b.region.sides);
  return reach;
}

Region crack_body(const Case& c, std::size_t k, const InterfaceSpec& now) {
  Region reach = crack_body(c, k);
  reach.minus_parts.insert(reach.minus_parts.end(), now.reach_cut_off.begin(), now.reach_cut_off.end());
  return reach;
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

namespace {

// The point of segment p -> q nearest x, and its distance.
std::pair<Point, double> nearest_on_segment(const Point& p, const Point& q, const Point& x) {
  const double bx = q.x - p.x, by = q.y - p.y, l2 = bx * bx + by * by;
  const double u = l2 > 0.0 ? std::clamp(((x.x - p.x) * bx + (x.y - p.y) * by) / l2, 0.0, 1.0) : 0.0;
  const Point at{p.x + u * bx, p.y + u * by};
  return {at, std::hypot(x.x - at.x, x.y - at.y)};
}

}  // namespace

std::optional<LineMeeting> segment_meets_line(const Polyline& line, const Point& a, const Point& b, double tol) {
  std::optional<LineMeeting> best;
  for (std::size_t i = 0; i + 1 < line.num_vertices(); ++i) {
    const Point p{line.x[i], line.y[i]}, q{line.x[i + 1], line.y[i + 1]};
    LineMeeting m;
    // Crossing: a and b on opposite sides of p -> q and p, q on opposite sides of a -> b.
    const auto side = [](const Point& o, const Point& d, const Point& x) {
      return (d.x - o.x) * (x.y - o.y) - (d.y - o.y) * (x.x - o.x);
    };
    const double sa = side(p, q, a), sb = side(p, q, b), sp = side(a, b, p), sq = side(a, b, q);
    if (((sa < 0.0 && sb > 0.0) || (sa > 0.0 && sb < 0.0)) && ((sp < 0.0 && sq > 0.0) || (sp > 0.0 && sq < 0.0))) {
      const double u = sa / (sa - sb);
      m.at = {a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)}, m.distance = 0.0;
    } else {
      // Apart: the nearest pair has an end of one of the two segments.
      const auto [pa, da] = nearest_on_segment(p, q, a);
      const auto [pb, db] = nearest_on_segment(p, q, b);
      const double dp = nearest_on_segment(a, b, p).second, dq = nearest_on_segment(a, b, q).second;
      m.at = pa, m.distance = da;
      if (db < m.distance) m.at = pb, m.distance = db;
      if (dp < m.distance) m.at = p, m.distance = dp;
      if (dq < m.distance) m.at = q, m.distance = dq;
    }
    if (m.distance < tol && (!best || m.distance < best->distance)) best = m;
  }
  return best;
}

bool drawn_in_crack_body(const Case& c, std::size_t k, const InterfaceSpec& spec) {
  const Shape& outer = c.bodies[std::size_t(c.interfaces[k].upper_body)].region.outer;
  return same_shape(c.bodies[std::size_t(spec.upper_body)].region.outer, outer) &&
         same_shape(c.bodies[std::size_t(spec.lower_body)].region.outer, outer);
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
