// rupture/fracture/tip_domain.cpp
#include "fracture/tip_domain.hpp"

#include <algorithm>
#include <cmath>

#include <omp.h>

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

// The squared distance of (x, y) from the tip (a glibc hypot per point cost a tenth of the read).
double tip_distance2(const TipFrame& t, double x, double y) {
  const double dx = x - t.x, dy = y - t.y;
  return dx * dx + dy * dy;
}

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

TipDisplacement tip_domain_points(const Grid& g, const GridFields& fields, const Particles& P,
                       const std::vector<ElasticStiffness>& stiffness,
                       const std::vector<TiedFields>& ties, const TipFrame& tip, double reach,
                       double dt, const std::vector<InitialStrain>& initial,
                       std::vector<DomainPoint>& out, const DomainSums& ranks) {
  out.clear();
  const double h = std::max(g.x.h, g.y.h);
  // The points: boxes within reach + a cell. The maps: every particle within two more cells
  // (a node's support is one cell plus a particle half-width).
  const double r_points = reach + h, r_map = reach + 3.0 * h;
  // Every particle is looked at (squared distances: a hypot per particle cost more than the
  // integrals, when growth reads the tips every step), by contiguous chunks side by side, joined
  // in particle order (the maps' sums below are then the same on any number of threads).
  // Scratch kept by the calling thread between reads (a fresh allocation every step page-faults
  // in), named by references: inside the parallel loops a thread_local name would be each
  // thread's own.
  thread_local std::vector<std::size_t> kept_mapped, kept_near;
  thread_local std::vector<Stencil1D> kept_sx, kept_sy;
  thread_local LocalNodes kept_nodes;
  std::vector<std::size_t>&mapped = kept_mapped, &near = kept_near;
  std::vector<Stencil1D>&msx = kept_sx, &msy = kept_sy;
  LocalNodes& L = kept_nodes;
  mapped.clear(), near.clear();
  const double r2 = r_map * r_map, tx = tip.x, ty = tip.y;
  const double* __restrict px = P.x.data();
  const double* __restrict py = P.y.data();
  const std::size_t np = P.size();
#pragma omp parallel if (np > 16384)
  {
    std::vector<std::size_t> mine;
    const std::size_t threads = std::size_t(omp_get_num_threads()), t = std::size_t(omp_get_thread_num());
    const std::size_t from = np * t / threads, to = np * (t + 1) / threads;
    for (std::size_t p = from; p < to; ++p) {
      const double dx = px[p] - tx, dy = py[p] - ty;
      if (dx * dx + dy * dy < r2) mine.push_back(p);
    }
#pragma omp for ordered schedule(static, 1)
    for (std::size_t k = 0; k < threads; ++k) {
#pragma omp ordered
      mapped.insert(mapped.end(), mine.begin(), mine.end());
    }
  }
  // Distributed: every rank goes on to the sums below, with particles near the tip or not.
  if (mapped.empty() && !ranks.distributed()) return {};
  // Each mapped particle's GIMP stencils, once: the maps and the points' gradients use them.
  const long nm = long(mapped.size());
  msx.resize(mapped.size()), msy.resize(mapped.size());
#pragma omp parallel for schedule(static) if (nm > 512)
  for (long k = 0; k < nm; ++k) {
    const std::size_t p = mapped[std::size_t(k)];
    stencil(g.x, P.x[p], P.half_x[p], msx[std::size_t(k)]);
    stencil(g.y, P.y[p], P.half_y[p], msy[std::size_t(k)]);
  }
  L.fields = fields.num_fields;
  int imin = g.nodes_x(), imax = -1, jmin = g.nodes_y(), jmax = -1;
  for (std::size_t k = 0; k < mapped.size(); ++k) {
    const int i = msx[k].first, j = msy[k].first;
    imin = std::min(imin, i), imax = std::max(imax, i + 2), jmin = std::min(jmin, j), jmax = std::max(jmax, j + 2);
  }
  if (ranks.distributed()) {  // the box of every rank's mapped particles
    double box[4] = {-double(imin), -double(jmin), double(imax), double(jmax)};
    ranks.max(box, 4);
    imin = -int(box[0]), jmin = -int(box[1]), imax = int(box[2]), jmax = int(box[3]);
    if (imax < 0) return {};  // no particle near the tip on any rank
  }
  L.i0 = imin, L.j0 = jmin, L.nx = imax - imin + 1, L.ny = jmax - jmin + 1;
  const std::size_t size = std::size_t(L.fields) * std::size_t(L.nx) * std::size_t(L.ny);
  for (auto* v : {&L.m, &L.ux, &L.uy, &L.vx, &L.vy}) v->assign(size, 0.0);
  for (std::size_t k = 0; k < mapped.size(); ++k) {
    const std::size_t p = mapped[k];
    const Stencil1D &sx = msx[k], &sy = msy[k];
    const double ux = P.x[p] - P.x0[p], uy = P.y[p] - P.y0[p];
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) {
        const double w = P.mass[p] * sx.s[a] * sy.s[b];
        const std::size_t n = L.at(P.field[p], sx.first + a, sy.first + b);
        L.m[n] += w, L.ux[n] += w * ux, L.uy[n] += w * uy, L.vx[n] += w * P.vx[p], L.vy[n] += w * P.vy[p];
      }
  }
  // Distributed: a node's sums over every rank's particles, as one process maps them all.
  if (ranks.distributed()) {  // in one call: the five maps side by side
    thread_local std::vector<double> packed;
    packed.resize(5 * size);
    std::size_t at = 0;
    for (auto* v : {&L.m, &L.ux, &L.uy, &L.vx, &L.vy}) std::copy(v->begin(), v->end(), packed.begin() + long(at)), at += size;
    ranks.sum(packed.data(), packed.size());
    at = 0;
    for (auto* v : {&L.m, &L.ux, &L.uy, &L.vx, &L.vy})
      std::copy(packed.begin() + long(at), packed.begin() + long(at + size), v->begin()), at += size;
  }
  // Tied nodes: one body, both fields hold the sums (where both have mass, as the grid's tie).
  for (const TiedFields& t : ties)
    for (std::size_t n : *t.nodes) {
      const int i = int(n % std::size_t(g.nodes_x())), j = int(n / std::size_t(g.nodes_x()));
      if (!L.inside(i, j)) continue;
      const std::size_t a = L.at(t.upper_field, i, j), b = L.at(t.lower_field, i, j);
      if (!(L.m[a] > 0.0 && L.m[b] > 0.0)) continue;  // one field there: as the grid's tie
      for (auto* v : {&L.m, &L.ux, &L.uy, &L.vx, &L.vy}) (*v)[a] = (*v)[b] = (*v)[a] + (*v)[b];
    }
  for (std::size_t k = 0; k < size; ++k)
    if (L.m[k] > 0.0) {
      const double inv = 1.0 / L.m[k];
      L.ux[k] *= inv, L.uy[k] *= inv, L.vx[k] *= inv, L.vy[k] *= inv;
    }
  // The displacement at the tip: the mean of what the material around it carries (both faces'
  // fields behind it, the tied ones ahead).
  TipDisplacement at_tip;
  {
    const int ci = g.x.cell_of(tx), cj = g.y.cell_of(ty);
    const double fx = (tx - g.x.node(ci)) / g.x.width(ci), fy = (ty - g.y.node(cj)) / g.y.width(cj);
    double mass = 0.0;
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a) {
        if (!L.inside(ci + a, cj + b)) continue;
        const double w = (a ? fx : 1.0 - fx) * (b ? fy : 1.0 - fy);
        for (int f = 0; f < L.fields; ++f) {
          const std::size_t n = L.at(f, ci + a, cj + b);
          mass += w * L.m[n], at_tip.ux += w * L.m[n] * L.ux[n], at_tip.uy += w * L.m[n] * L.uy[n];
        }
      }
    if (mass > 0.0) at_tip.ux /= mass, at_tip.uy /= mass;
  }
  for (std::size_t k = 0; k < mapped.size(); ++k)
    if (tip_distance2(tip, P.x[mapped[k]], P.y[mapped[k]]) < r_points * r_points) near.push_back(k);
  out.resize(near.size());
  // Each point's gradients from the maps, side by side (each writes its own point).
  const long n = long(near.size());
  const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
#pragma omp parallel for schedule(static) if (n > 256)
  for (long q = 0; q < n; ++q) {
    const std::size_t k = near[std::size_t(q)], p = mapped[k];
    const Stencil1D &qx = msx[k], &qy = msy[k];
    const int f = P.field[p];
    DomainPoint d{};
    d.x = P.x[p], d.y = P.y[p];
    d.id = P.id[p];
    d.ux = P.x[p] - P.x0[p], d.uy = P.y[p] - P.y0[p];
    d.vx = P.vx[p], d.vy = P.vy[p];
    const ElasticStiffness& C = stiffness[P.material[p]];
    d.sxx = P.sxx[p], d.syy = P.syy[p], d.sxy = P.sxy[p];
    strain_of(C, d.sxx, d.syy, d.sxy, d.exx, d.eyy, d.exy);
    d.area = P.volume0[p] * (1.0 + strain_trace(C, d.sxx, d.syy));
    d.density = P.mass[p] / P.volume0[p];
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) {
        const int i = qx.first + a, j = qy.first + b;
        const std::size_t e = L.at(f, i, j);
        const double gx = qx.ds[a] * qy.s[b], gy = qx.s[a] * qy.ds[b], w = qx.s[a] * qy.s[b];
        d.ux_x += L.ux[e] * gx, d.ux_y += L.ux[e] * gy, d.uy_x += L.uy[e] * gx, d.uy_y += L.uy[e] * gy;
        d.vx_x += L.vx[e] * gx, d.vx_y += L.vx[e] * gy, d.vy_x += L.vy[e] * gx, d.vy_y += L.vy[e] * gy;
        if (dt > 0.0 && fields.holds(f, i, j)) {
          const std::size_t v = fields.index(f, i, j);
          d.ax += w * fields.dvel_x[v] * inv_dt, d.ay += w * fields.dvel_y[v] * inv_dt;
        }
      }
    if (std::size_t(f) < initial.size()) {
      const InitialStrain& e0 = initial[std::size_t(f)];
      d.ux_x += e0.exx, d.ux_y += e0.exy, d.uy_x += e0.exy, d.uy_y += e0.eyy;
      // and to the displacement, about the tip (only its differences along a face are read)
      const double dx = d.x - tx, dy = d.y - ty;
      d.ux += e0.exx * dx + e0.exy * dy, d.uy += e0.exy * dx + e0.eyy * dy;
    }
    out[std::size_t(q)] = d;
  }
  return at_tip;
}

}  // namespace rupture
