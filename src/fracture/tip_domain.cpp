// rupture/fracture/tip_domain.cpp
#include "fracture/tip_domain.hpp"

#include <algorithm>
#include <cmath>

namespace rupture {

namespace {

// A box of grid nodes [i0, i0 + nx) x [j0, j0 + ny) with, per field, the mass-weighted maps.
struct LocalNodes {
  int i0 = 0, j0 = 0, nx = 0, ny = 0, fields = 0;
  std::vector<double> m, ux, uy, vx, vy;  // [field][node]: sums, then values
  bool inside(int i, int j) const { return i >= i0 && i < i0 + nx && j >= j0 && j < j0 + ny; }
  std::size_t at(int f, int i, int j) const {
    return (std::size_t(f) * std::size_t(ny) + std::size_t(j - j0)) * std::size_t(nx) + std::size_t(i - i0);
  }
};

// The distance of (x, y) from the tip.
double tip_distance(const TipFrame& t, double x, double y) { return std::hypot(x - t.x, y - t.y); }

}  // namespace

std::vector<DomainPoint> tip_domain_points(const Grid& g, const GridFields& fields,
                                           const Particles& P,
                                           const std::vector<ElasticStiffness>& stiffness,
                                           const std::vector<TiedFields>& ties,
                                           const TipFrame& tip, double reach, double dt,
                                           const std::vector<InitialStrain>& initial) {
  std::vector<DomainPoint> out;
  tip_domain_points(g, fields, P, stiffness, ties, tip, reach, dt, initial, out);
  return out;
}

void tip_domain_points(const Grid& g, const GridFields& fields, const Particles& P,
                       const std::vector<ElasticStiffness>& stiffness,
                       const std::vector<TiedFields>& ties, const TipFrame& tip, double reach,
                       double dt, const std::vector<InitialStrain>& initial,
                       std::vector<DomainPoint>& out) {
  out.clear();
  const double h = std::max(g.x.h, g.y.h);
  // The points: boxes within reach + a cell. The maps: every particle within two more cells
  // (a node's support is one cell plus a particle half-width).
  const double r_points = reach + h, r_map = reach + 3.0 * h;
  // Every particle is looked at (squared distances: a hypot per particle cost more than the
  // integrals, when growth reads the tips every step).
  std::vector<std::size_t> mapped;
  const double r2 = r_map * r_map, tx = tip.x, ty = tip.y;
  const double* __restrict px = P.x.data();
  const double* __restrict py = P.y.data();
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double dx = px[p] - tx, dy = py[p] - ty;
    if (dx * dx + dy * dy < r2) mapped.push_back(p);
  }
  if (mapped.empty()) return;
  LocalNodes L;
  L.fields = fields.num_fields;
  int imin = g.nodes_x(), imax = -1, jmin = g.nodes_y(), jmax = -1;
  for (std::size_t p : mapped) {
    const int i = stencil_first(g.x, P.x[p], P.half_x[p]), j = stencil_first(g.y, P.y[p], P.half_y[p]);
    imin = std::min(imin, i), imax = std::max(imax, i + 2), jmin = std::min(jmin, j), jmax = std::max(jmax, j + 2);
  }
  L.i0 = imin, L.j0 = jmin, L.nx = imax - imin + 1, L.ny = jmax - jmin + 1;
  const std::size_t size = std::size_t(L.fields) * std::size_t(L.nx) * std::size_t(L.ny);
  for (auto* v : {&L.m, &L.ux, &L.uy, &L.vx, &L.vy}) v->assign(size, 0.0);
  Stencil1D sx, sy;
  for (std::size_t p : mapped) {
    stencil(g.x, P.x[p], P.half_x[p], sx);
    stencil(g.y, P.y[p], P.half_y[p], sy);
    const double ux = P.x[p] - P.x0[p], uy = P.y[p] - P.y0[p];
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) {
        const double w = P.mass[p] * sx.s[a] * sy.s[b];
        const std::size_t k = L.at(P.field[p], sx.first + a, sy.first + b);
        L.m[k] += w, L.ux[k] += w * ux, L.uy[k] += w * uy, L.vx[k] += w * P.vx[p], L.vy[k] += w * P.vy[p];
      }
  }
  // Tied nodes: one body, both fields hold the sums.
  for (const TiedFields& t : ties)
    for (std::size_t n : *t.nodes) {
      const int i = int(n % std::size_t(g.nodes_x())), j = int(n / std::size_t(g.nodes_x()));
      if (!L.inside(i, j)) continue;
      const std::size_t a = L.at(t.upper_field, i, j), b = L.at(t.lower_field, i, j);
      for (auto* v : {&L.m, &L.ux, &L.uy, &L.vx, &L.vy}) (*v)[a] = (*v)[b] = (*v)[a] + (*v)[b];
    }
  for (std::size_t k = 0; k < size; ++k)
    if (L.m[k] > 0.0) {
      const double inv = 1.0 / L.m[k];
      L.ux[k] *= inv, L.uy[k] *= inv, L.vx[k] *= inv, L.vy[k] *= inv;
    }
  std::vector<std::size_t> near;
  for (std::size_t p : mapped)
    if (tip_distance(tip, P.x[p], P.y[p]) < r_points) near.push_back(p);
  out.resize(near.size());
  // Each point's gradients from the maps, side by side (each writes its own point).
  const long n = long(near.size());
#pragma omp parallel for schedule(static) if (n > 256)
  for (long q = 0; q < n; ++q) {
    const std::size_t p = near[std::size_t(q)];
    Stencil1D qx, qy;
    stencil(g.x, P.x[p], P.half_x[p], qx);
    stencil(g.y, P.y[p], P.half_y[p], qy);
    const int f = P.field[p];
    DomainPoint d{};
    d.x = P.x[p], d.y = P.y[p];
    d.id = P.id[p];
    d.vx = P.vx[p], d.vy = P.vy[p];
    const ElasticStiffness& C = stiffness[P.material[p]];
    d.sxx = P.sxx[p], d.syy = P.syy[p], d.sxy = P.sxy[p];
    strain_of(C, d.sxx, d.syy, d.sxy, d.exx, d.eyy, d.exy);
    d.area = P.volume0[p] * (1.0 + strain_trace(C, d.sxx, d.syy));
    d.density = P.mass[p] / P.volume0[p];
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) {
        const int i = qx.first + a, j = qy.first + b;
        const std::size_t k = L.at(f, i, j);
        const double gx = qx.ds[a] * qy.s[b], gy = qx.s[a] * qy.ds[b], w = qx.s[a] * qy.s[b];
        d.ux_x += L.ux[k] * gx, d.ux_y += L.ux[k] * gy, d.uy_x += L.uy[k] * gx, d.uy_y += L.uy[k] * gy;
        d.vx_x += L.vx[k] * gx, d.vx_y += L.vx[k] * gy, d.vy_x += L.vy[k] * gx, d.vy_y += L.vy[k] * gy;
        if (dt > 0.0 && fields.holds(f, i, j)) {
          const std::size_t e = fields.index(f, i, j);
          d.ax += w * fields.dvel_x[e] / dt, d.ay += w * fields.dvel_y[e] / dt;
        }
      }
    if (std::size_t(f) < initial.size()) {
      const InitialStrain& e0 = initial[std::size_t(f)];
      d.ux_x += e0.exx, d.ux_y += e0.exy, d.uy_x += e0.exy, d.uy_y += e0.eyy;
    }
    out[std::size_t(q)] = d;
  }
}

}  // namespace rupture
