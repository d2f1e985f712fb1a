// rupture/particles/seed.cpp
#include "particles/seed.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace rupture {
namespace {

// Sub-cell centres and sides along one axis covering [lo, hi].
struct Line {
  std::vector<double> centre, side;  // m
};

Line uniform_line(const Axis& a, double domain_min, double lo, double hi, int ppc) {
  const double h = a.h, tol = 1e-9;
  // Start on the box edge when it is a grid line (as seed_rectangle counts), else on the grid
  // line below it. A centre is computed from the grid's origin and its index on the whole
  // lattice, never from the box, so every region (and both axes of a square lattice) gets the
  // same number for the same point: bodies that share an edge split its points exactly
  // (polygon_contains rounds a shared edge alike from both sides).
  const double cells_below = (lo - domain_min) / h;
  const bool on_line = std::fabs(cells_below - std::round(cells_below)) <=
                       tol * std::max(1.0, std::fabs(cells_below));
  const double first = on_line ? std::round(cells_below) : std::floor(cells_below);
  const long cells = std::max(0L, long(std::ceil((hi - domain_min) / h - first - tol)));
  const double side = h / ppc;
  Line l;
  for (long i = 0; i < cells * ppc; ++i) {
    l.centre.push_back(lattice_centre(domain_min, side, long(first) * ppc + i));
    l.side.push_back(side);
  }
  return l;
}

Line graded_line(const Axis& a, double lo, double hi, int ppc) {
  const double tol = 1e-9 * a.h;
  Line l;
  for (int i = 0; i < a.cells; ++i) {
    if (!(a.node(i + 1) > lo + tol && a.node(i) < hi - tol)) continue;
    const double side = a.width(i) / ppc;
    for (int si = 0; si < ppc; ++si) {
      l.centre.push_back(a.node(i) + (si + 0.5) * side);
      l.side.push_back(side);
    }
  }
  return l;
}

void fill(Particles& p, std::size_t k, const SeedPoint& s, const SeedProperties& props) {
  p.x[k] = p.x0[k] = s.x;
  p.y[k] = p.y0[k] = s.y;
  p.vx[k] = props.velocity[0];
  p.vy[k] = props.velocity[1];
  p.volume0[k] = s.lx * s.ly;
  p.mass[k] = props.density * s.lx * s.ly;
  p.half_x[k] = 0.5 * s.lx;
  p.half_y[k] = 0.5 * s.ly;
  p.field[k] = props.field;
  p.material[k] = props.material;
  p.id[k] = std::uint32_t(k);
}

}  // namespace

void for_each_seed_point(const Grid& g, const Region& r, int ppc, const Box& within, const SeedVisit& visit) {
  // The walk covers the region's box (a part of a split body: the side that bounds it) within
  // `within`. The centres come from their indices on the whole lattice, not from the box, so a
  // smaller box visits the same points, in the same order, minus those outside it.
  Box b = region_box(r);
  for (int d = 0; d < 2; ++d) b.min[d] = std::max(b.min[d], within.min[d]), b.max[d] = std::min(b.max[d], within.max[d]);
  if (!(b.min[0] <= b.max[0] && b.min[1] <= b.max[1])) return;
  // On a uniform grid the box is clipped to the grid's extent (a nested level's lattice covers
  // part of the domain; the whole-domain grid holds every body anyway). Its ends are grid
  // lines, so the centres are those of the unclipped box.
  const auto clip_lo = [](const Axis& a, double v) { return std::max(v, a.origin); };
  const auto clip_hi = [](const Axis& a, double v) { return std::min(v, a.node(a.cells)); };
  const Line cols = g.graded() ? graded_line(g.x, b.min[0], b.max[0], ppc)
                               : uniform_line(g.x, g.domain_min[0], clip_lo(g.x, b.min[0]), clip_hi(g.x, b.max[0]), ppc);
  const Line rows = g.graded() ? graded_line(g.y, b.min[1], b.max[1], ppc)
                               : uniform_line(g.y, g.domain_min[1], clip_lo(g.y, b.min[1]), clip_hi(g.y, b.max[1]), ppc);
  for (std::size_t j = 0; j < rows.centre.size(); ++j) {
    if (rows.centre[j] < within.min[1] || rows.centre[j] > within.max[1]) continue;
    for (std::size_t i = 0; i < cols.centre.size(); ++i)
      if (cols.centre[i] >= within.min[0] && cols.centre[i] <= within.max[0] &&
          contains(r, cols.centre[i], rows.centre[j]))
        visit({cols.centre[i], rows.centre[j], cols.side[i], rows.side[j]});
  }
}

void for_each_seed_point(const Grid& g, const Region& r, int ppc, const SeedVisit& visit) {
  for_each_seed_point(g, r, ppc, Box{{-INFINITY, -INFINITY}, {INFINITY, INFINITY}}, visit);
}

long count_seed_points(const Grid& g, const Region& r, int ppc) {
  long n = 0;
  for_each_seed_point(g, r, ppc, [&n](const SeedPoint&) { ++n; });
  return n;
}

double seed_points_at_least(const Region& r, double s) {
  if (!r.sides.empty() || !(s > 0.0)) return 0.0;
  const double pi = std::numbers::pi, root2 = std::numbers::sqrt2;
  double covered = area(r.outer) - 2.0 * root2 * s * perimeter_at_most(r.outer) - 2.0 * pi * s * s;
  for (const Shape& c : r.minus) covered -= area(c) + root2 * s * perimeter_at_most(c) + 0.5 * pi * s * s;
  return std::max(0.0, std::floor(covered / (s * s)));
}

std::size_t seed_region(Particles& p, const Grid& g, const Region& r, int ppc,
                        const SeedProperties& props) {
  std::vector<SeedPoint> points;
  for_each_seed_point(g, r, ppc, [&](const SeedPoint& s) { points.push_back(s); });
  std::size_t k = p.size();
  p.resize(k + points.size());
  for (const SeedPoint& s : points) fill(p, k++, s, props);
  return points.size();
}

// theory §5: on a refined grid every cell the body covers gets ppc x ppc particles of the
// cell's own size (rectangular where the cell is), in rows of particles across the body.
void for_each_graded_rectangle_point(const Grid& g, const double min[2], const double max[2], int ppc,
                                     const SeedVisit& visit) {
  const double tol = 1e-9 * g.x.h;
  std::vector<int> cols, rows;
  for (int i = 0; i < g.x.cells; ++i) {
    const double xc = g.x.node(i) + 0.5 * g.x.width(i);
    if (xc > min[0] - tol && xc < max[0] + tol) cols.push_back(i);
  }
  for (int j = 0; j < g.y.cells; ++j) {
    const double yc = g.y.node(j) + 0.5 * g.y.width(j);
    if (yc > min[1] - tol && yc < max[1] + tol) rows.push_back(j);
  }
  for (int j : rows)
    for (int sj = 0; sj < ppc; ++sj)
      for (int i : cols)
        for (int si = 0; si < ppc; ++si) {
          const double lx = g.x.width(i) / ppc, ly = g.y.width(j) / ppc;
          visit({g.x.node(i) + (si + 0.5) * lx, g.y.node(j) + (sj + 0.5) * ly, lx, ly});
        }
}

void seed_graded_rectangle(Particles& P, const Grid& g, const double min[2], const double max[2],
                           int ppc, const SeedProperties& props) {
  std::vector<SeedPoint> points;
  for_each_graded_rectangle_point(g, min, max, ppc, [&](const SeedPoint& s) { points.push_back(s); });
  std::size_t k = P.size();
  P.resize(k + points.size());
  for (const SeedPoint& s : points) fill(P, k++, s, props);
}

void for_each_rectangle_point(const double min[2], const double max[2], double h, int ppc,
                              const double origin[2], const SeedVisit& visit) {
  // The arithmetic of seed_rectangle (particles/particles.cpp), point for point.
  const long cx = std::lround((max[0] - min[0]) / h);
  const long cy = std::lround((max[1] - min[1]) / h);
  const double side = h / ppc;
  const long ix = std::lround((min[0] - origin[0]) / h) * ppc;
  const long iy = std::lround((min[1] - origin[1]) / h) * ppc;
  for (long j = 0; j < cy * ppc; ++j)
    for (long i = 0; i < cx * ppc; ++i)
      visit({lattice_centre(origin[0], side, ix + i), lattice_centre(origin[1], side, iy + j), side, side});
}

void append_seed_point(Particles& p, const SeedPoint& s, const SeedProperties& props, std::uint32_t id) {
  const std::size_t k = p.size();
  p.resize(k + 1);
  fill(p, k, s, props);
  p.id[k] = id;
}

}  // namespace rupture
