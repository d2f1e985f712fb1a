// rupture/solver/crack_nucleation.cpp
// A drawn site held intact by a tie over it until the stress across it reaches the strength
// (solver/crack_nucleation.hpp).
#include "solver/crack_nucleation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/cohesive_step.hpp"
#include "solver/rank_exchange.hpp"

namespace rupture {
namespace {

bool meet(double ax, double ay, double bx, double by, double tol) { return std::hypot(ax - bx, ay - by) <= tol; }

Polyline reversed(Polyline p) {
  std::reverse(p.x.begin(), p.x.end());
  std::reverse(p.y.begin(), p.y.end());
  return p;
}

// `tail` appended to `p`, its first vertex (p's last) dropped.
void append(Polyline& p, const Polyline& tail) {
  p.x.insert(p.x.end(), tail.x.begin() + 1, tail.x.end());
  p.y.insert(p.y.end(), tail.y.begin() + 1, tail.y.end());
}

}  // namespace

std::vector<Polyline> dormant_ties(const InterfaceSpec& is, double tol) {
  Polyline line = is.geometry();
  std::vector<Polyline> rest;
  for (const Polyline& t : is.tie_geometries()) {
    if (t.num_vertices() < 2 || line.closed) {
      rest.push_back(t);
      continue;
    }
    const std::size_t a = t.num_vertices() - 1, b = line.num_vertices() - 1;
    if (meet(t.x[0], t.y[0], line.x[b], line.y[b], tol)) {
      append(line, t);  // the tie runs on from the line's end
    } else if (meet(t.x[a], t.y[a], line.x[b], line.y[b], tol)) {
      append(line, reversed(t));
    } else if (meet(t.x[a], t.y[a], line.x[0], line.y[0], tol)) {
      Polyline joined = t;  // the tie runs into the line's start
      append(joined, line);
      line = joined;
    } else if (meet(t.x[0], t.y[0], line.x[0], line.y[0], tol)) {
      Polyline joined = reversed(t);
      append(joined, line);
      line = joined;
    } else {
      rest.push_back(t);
    }
  }
  rest.insert(rest.begin(), line);
  return rest;
}

InterfaceSpec as_set_up(const InterfaceSpec& is, double tol) {
  if (is.nucleation_strength <= 0.0) return is;
  InterfaceSpec dormant = is;
  dormant.bonded_lines = dormant_ties(is, tol);
  dormant.bonded = true;
  return dormant;
}

double site_stress(const State& L, const CohesiveInterface& in, double reach) {
  const std::size_t segments = in.num_segments();
  // Per segment: the sum of sigma_nn and the count, side by side (one sum over the ranks).
  std::vector<double> sums(2 * segments, 0.0);
  const Particles& P = L.particles;
  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
  for (std::size_t n = 0; n < in.num_nodes(); ++n) {
    lo_x = std::min(lo_x, in.x0[n]), hi_x = std::max(hi_x, in.x0[n]);
    lo_y = std::min(lo_y, in.y0[n]), hi_y = std::max(hi_y, in.y0[n]);
  }
  for (std::size_t q = 0; q < P.size(); ++q) {
    const double px = P.x0[q], py = P.y0[q];
    if (px < lo_x - reach || px > hi_x + reach || py < lo_y - reach || py > hi_y + reach) continue;
    for (std::size_t e = 0; e < segments; ++e) {
      const std::size_t a = e, b = (e + 1) % in.num_nodes();
      const double dx = in.x0[b] - in.x0[a], dy = in.y0[b] - in.y0[a];
      const double len2 = dx * dx + dy * dy;
      const double along = ((px - in.x0[a]) * dx + (py - in.y0[a]) * dy) / len2;
      if (along < 0.0 || along > 1.0) continue;
      const double off = std::abs((px - in.x0[a]) * dy - (py - in.y0[a]) * dx) / std::sqrt(len2);
      if (off > reach) continue;
      const double nx = in.seg_nx[e], ny = in.seg_ny[e];
      double sxx = P.sxx[q], syy = P.syy[q], sxy = P.sxy[q];
      if (P.viscous()) sxx += P.vsxx[q], syy += P.vsyy[q], sxy += P.vsxy[q];
      sums[2 * e] += nx * nx * sxx + 2.0 * nx * ny * sxy + ny * ny * syy;
      sums[2 * e + 1] += 1.0;
    }
  }
  sum_over_ranks(L, sums.data(), sums.size());
  double largest = -std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < segments; ++e)
    if (sums[2 * e + 1] > 0.0) largest = std::max(largest, sums[2 * e] / sums[2 * e + 1]);
  return largest;
}

void release_site(const Case& c, std::size_t k, State& L, std::size_t slot, const std::vector<State*>& others) {
  CohesiveInterface& in = L.interfaces[slot];
  in.spec.bonded_lines = c.interfaces[k].bonded_lines;
  in.spec.bonded = c.interfaces[k].bonded;
  // One grid: the level's ties follow its interfaces (slot); nested levels: every level has one
  // per case interface (k), as crack_segment lays them.
  L.bonded[others.empty() ? slot : k].nodes = bonded_nodes(L.grid, in.spec);
  for (State* S : others) S->bonded[k].nodes = bonded_nodes(S->grid, in.spec);
}

}  // namespace rupture
