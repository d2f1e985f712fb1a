// rupture/solver/time_step.cpp
#include "solver/time_step.hpp"

#include <algorithm>
#include <bitset>
#include <cmath>
#include <vector>

#include "shape/gimp.hpp"

namespace rupture {

double bulk_eigen_bound(const ElasticStiffness& C, double density, int ppc, double h) {
  // A free block of n x n cells with nodes -1 .. n + 1 per axis (GIMP tails reach one node
  // past the edge). K_ij = sum_p V_p B_ip^T C B_jp, M_i = sum_p m_p S_ip (E4, E5).
  constexpr int n = 6;
  constexpr int nodes = n + 3;
  const double lp = 0.5 * h / ppc, vp = (h / ppc) * (h / ppc), mp = density * vp;
  constexpr int dofs = 2 * nodes * nodes;
  std::vector<double> mass(nodes * nodes, 0.0), K(std::size_t(dofs) * dofs, 0.0);
  std::vector<double> s(nodes), ds(nodes), t(nodes), dt(nodes);
  for (int cx = 0; cx < n; ++cx)
    for (int cy = 0; cy < n; ++cy)
      for (int a = 0; a < ppc; ++a)
        for (int b = 0; b < ppc; ++b) {
          const double x = (cx + (a + 0.5) / ppc) * h, y = (cy + (b + 0.5) / ppc) * h;
          for (int i = 0; i < nodes; ++i) {
            const Weight1D wx = gimp_uniform(x - (i - 1) * h, h, lp);
            const Weight1D wy = gimp_uniform(y - (i - 1) * h, h, lp);
            s[i] = wx.s, ds[i] = wx.ds, t[i] = wy.s, dt[i] = wy.ds;
          }
          for (int i = 0; i < nodes * nodes; ++i) {
            const int ix = i / nodes, iy = i % nodes;
            const double gxi = ds[ix] * t[iy], gyi = s[ix] * dt[iy];
            mass[i] += mp * s[ix] * t[iy];
            if (gxi == 0.0 && gyi == 0.0) continue;
            for (int j = 0; j < nodes * nodes; ++j) {
              const int jx = j / nodes, jy = j % nodes;
              const double gxj = ds[jx] * t[jy], gyj = s[jx] * dt[jy];
              // 2x2 block B_i^T C B_j of plane elasticity (Voigt: xx, yy, xy).
              const double kxx = C.c11 * gxi * gxj + C.mu * gyi * gyj;
              const double kxy = C.c12 * gxi * gyj + C.mu * gyi * gxj;
              const double kyx = C.c12 * gyi * gxj + C.mu * gxi * gyj;
              const double kyy = C.c11 * gyi * gyj + C.mu * gxi * gxj;
              double* row_x = &K[std::size_t(2 * i) * dofs + std::size_t(2 * j)];
              double* row_y = row_x + dofs;
              row_x[0] += vp * kxx, row_x[1] += vp * kxy;
              row_y[0] += vp * kyx, row_y[1] += vp * kyy;
            }
          }
        }
  double bound = 0.0;
  for (int r = 0; r < dofs; ++r) {
    const double m = mass[std::size_t(r / 2)];
    if (m <= 1e-12 * mp) continue;
    double sum = 0.0;
    for (int j = 0; j < dofs; ++j) sum += std::fabs(K[std::size_t(r) * dofs + std::size_t(j)]);
    bound = std::max(bound, sum / m);
  }
  return bound;
}

double cohesive_eigen_bound(const State& s) {
  // Row i of M^-1 K_coh: K_coh = sum_k k_k B_k^T B_k with B_k = [c_up, -c_lo] (each sums to
  // 1), so sum_j |K_ij| / m_i = (2 / m_i) sum_k k_k c_ki; c_ki / m_i = w_ki / M_k for the
  // mass-weighted stencils. Accumulated per touched grid node in a compact scratch array: one
  // per face when the faces map to different fields (their nodes are different grid elements,
  // each face's a band of two node rows), both together when they share one.
  double bound = 0.0;
  for (const CohesiveInterface& c : s.interfaces) {
    const std::size_t n = c.num_nodes();
    if (c.face_up.size() != n) continue;
    // (Faces whose field changes along the line, T-junctions: shared when any field is on both.)
    bool shared = c.spec.upper_field == c.spec.lower_field;
    if (!c.node_faces_up.empty() || !c.node_faces_lo.empty()) {
      std::bitset<256> up, lo;
      for (std::size_t k = 0; k < n; ++k)
        for (auto [set, f] : {std::pair{&up, c.faces_up(k)}, std::pair{&lo, c.faces_lo(k)}}) {
          set->set(f.a);
          if (f.share < 1.0) set->set(f.b);
        }
      shared = (up & lo).any();
    }
    const std::vector<FaceStencil>* faces[2] = {&c.face_up, &c.face_lo};
    // The two faces' scratch rows are independent: one thread each.
#pragma omp parallel for schedule(static, 1) reduction(max : bound) if (!shared)
    for (int first = 0; first < (shared ? 1 : 2); ++first) {
      thread_local std::vector<double> row;  // scratch, kept between steps (no allocation)
      const int last = shared ? 1 : first;
      std::size_t lo = SIZE_MAX, hi = 0;
      // Distributed: the faces this rank knows; a grid node's sum is complete on its owner
      // (every face touching an owned node is known), partial (smaller) elsewhere, and the
      // step is the minimum over the ranks.
      for (std::size_t k = 0; k < n; ++k)
        for (int side = first; side <= last; ++side) {
          if (!c.knows(k)) continue;
          const FaceStencil& f = (*faces[side])[k];
          for (int q = 0; q < FaceStencil::kSlots; ++q)
            if (f.c[q] > 0.0) lo = std::min(lo, f.node[q]), hi = std::max(hi, f.node[q]);
        }
      if (lo > hi) continue;
      row.assign(hi - lo + 1, 0.0);
      for (std::size_t k = 0; k < n; ++k)
        for (int side = first; side <= last; ++side) {
          if (!c.knows(k)) continue;
          const FaceStencil& f = (*faces[side])[k];
          for (int q = 0; q < FaceStencil::kSlots; ++q)
            if (f.c[q] > 0.0) row[f.node[q] - lo] += 2.0 * c.stiffness_node[k] * f.c[q] / s.fields.mass[f.node[q]];
        }
      for (double r : row) bound = std::max(bound, r);
    }
  }
  return bound;
}

void choose_time_step(State& s) {
  double dt = s.limits.cfl_dt;
  if (!s.interfaces.empty()) {
    const double lambda = s.limits.bulk_eigen_bound + cohesive_eigen_bound(s);
    // MUSL moves the faces with the velocity it keeps (re-mapped): central-difference limit.
    // USL/USF move them with the raw grid velocity v + dv while the next step keeps only
    // v + S dv (S = M_L^-1 M_C, 0 < S <= 1): the limit drops to 2 / sqrt((2 - S) lambda), at
    // worst sqrt(2 / lambda) (docs/time_step.md).
    const double scheme = s.scheme == Scheme::MUSL ? 1.0 : 2.0;
    s.limits.cohesive_dt = 2.0 / std::sqrt(scheme * lambda);
    s.limits.min_cohesive_dt = std::min(s.limits.min_cohesive_dt, s.limits.cohesive_dt);
    dt = std::min(dt, s.cohesive_safety * s.limits.cohesive_dt);
  }
  if (s.forced_dt > 0.0) dt = s.forced_dt;
  s.dt = std::min(dt, s.dt_cap);
}

}  // namespace rupture
