// rupture/solver/cohesive_step.cpp
#include "solver/cohesive_step.hpp"

#include <cmath>

namespace rupture {
namespace {

constexpr int kG = CohesiveInterface::kGauss;
// 4-point Gauss-Legendre rule on [-1, 1] (E9).
constexpr double kXi[kG] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                            0.8611363115940526};
constexpr double kW[kG] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                           0.3478548451374538};

// Bilinear hat weights of the point (x, y): nodes (i, j), (i+1, j), (i, j+1), (i+1, j+1).
struct PointStencil {
  std::size_t node;  // index of node (i, j)
  double wx[2], wy[2];
};

inline PointStencil point_stencil(const Grid& g, double x, double y) {
  const double fx = (x - g.x.origin) / g.x.h, fy = (y - g.y.origin) / g.y.h;
  const int i = int(std::floor(fx)), j = int(std::floor(fy));
  const double ax = fx - i, ay = fy - j;
  return {g.node_index(i, j), {1.0 - ax, ax}, {1.0 - ay, ay}};
}

}  // namespace

void evaluate_interface(CohesiveInterface& c, double t) {
  const XuNeedleman& law = c.spec.law;
  const double crit = c.separation_opening();
  const long nseg = long(c.num_segments());
  double work = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : work)
  for (long sl = 0; sl < nseg; ++sl) {
    const std::size_t s = std::size_t(sl);
    const double half = 0.5 * (c.x0[s + 1] - c.x0[s]);
    const double dn_a = c.jump_normal(s), dn_b = c.jump_normal(s + 1);
    const double dt_a = c.jump_tangential(s), dt_b = c.jump_tangential(s + 1);
    double fa_n = 0, fa_t = 0, fb_n = 0, fb_t = 0;
    for (int g = 0; g < kG; ++g) {
      const std::size_t i = s * kG + std::size_t(g);
      const double Na = 0.5 * (1.0 - kXi[g]), Nb = 0.5 * (1.0 + kXi[g]);
      const double dn = Na * dn_a + Nb * dn_b, dt = Na * dt_a + Nb * dt_b;  // linear jump
      double tn = 0.0, tt = 0.0;
      if (!c.gp_separated[i] && std::hypot(dn, dt) >= crit) c.gp_separated[i] = 1;
      if (!c.gp_separated[i]) {
        const CohesiveTraction T = law.traction(dn, dt);
        tn = T.normal;
        tt = T.tangential;
      }
      // Work of the tractions over the step, trapezoidal in time (E14).
      const double jw = kW[g] * half;
      work += jw * (0.5 * (c.gp_tn[i] + tn) * (dn - c.gp_dn[i]) + 0.5 * (c.gp_tt[i] + tt) * (dt - c.gp_dt[i]));
      c.gp_dn[i] = dn, c.gp_dt[i] = dt, c.gp_tn[i] = tn, c.gp_tt[i] = tt;
      fa_n += jw * Na * tn, fa_t += jw * Na * tt;
      fb_n += jw * Nb * tn, fb_t += jw * Nb * tt;
    }
    // Force on the upper face: -T^ (t = +x, n = +y; rotation neglected, SPEC §3).
    c.seg_fa_x[s] = -fa_t, c.seg_fa_y[s] = -fa_n;
    c.seg_fb_x[s] = -fb_t, c.seg_fb_y[s] = -fb_n;
  }
  c.work += work;
  const long nn = long(c.num_nodes());
#pragma omp parallel for schedule(static)
  for (long kl = 0; kl < nn; ++kl) {
    const std::size_t k = std::size_t(kl);
    double fx = 0, fy = 0;
    if (k > 0) fx += c.seg_fb_x[k - 1], fy += c.seg_fb_y[k - 1];
    if (k + 1 < c.num_nodes()) fx += c.seg_fa_x[k], fy += c.seg_fa_y[k];
    c.fx_node[k] = fx, c.fy_node[k] = fy;
    if (c.node_crack_time[k] < 0.0 && std::hypot(c.jump_normal(k), c.jump_tangential(k)) >= crit)
      c.node_crack_time[k] = t;
  }
}

void add_cohesive_forces(State& s) {
  GridFields& G = s.fields;
  const std::size_t nx = std::size_t(s.grid.nodes_x());
  for (CohesiveInterface& c : s.interfaces) {
    const std::size_t up = G.offset(c.spec.upper_field), lo = G.offset(c.spec.lower_field);
    // Serial: ~15 face nodes share each grid node; this loop is O(interface nodes), tiny
    // next to the particle loops, and its fixed order keeps results thread-count independent.
    for (std::size_t k = 0; k < c.num_nodes(); ++k) {
      const double fx = c.fx_node[k], fy = c.fy_node[k];
      if (fx == 0.0 && fy == 0.0) continue;
      const PointStencil a = point_stencil(s.grid, c.x0[k] + c.ux_up[k], c.spec.y + c.uy_up[k]);
      const PointStencil b = point_stencil(s.grid, c.x0[k] + c.ux_lo[k], c.spec.y + c.uy_lo[k]);
      for (int jj = 0; jj < 2; ++jj)
        for (int ii = 0; ii < 2; ++ii) {
          const double wa = a.wx[ii] * a.wy[jj], wb = b.wx[ii] * b.wy[jj];
          const std::size_t na = up + a.node + std::size_t(jj) * nx + std::size_t(ii);
          const std::size_t nb = lo + b.node + std::size_t(jj) * nx + std::size_t(ii);
          G.force_x[na] += wa * fx, G.force_y[na] += wa * fy;  // upper face: -T^
          G.force_x[nb] -= wb * fx, G.force_y[nb] -= wb * fy;  // lower face: +T^
        }
    }
  }
}

std::vector<std::size_t> bonded_nodes(const Grid& g, const InterfaceSpec& spec) {
  std::vector<std::size_t> out;
  if (!spec.bonded) return out;
  const int j = int(std::lround((spec.y - g.y.origin) / g.y.h));
  const double tol = 1e-9 * g.x.h;
  for (int i = 0; i < g.nodes_x(); ++i) {
    const double x = g.x.node(i);
    if (x >= spec.bonded_from - tol && x <= spec.bonded_to + tol) out.push_back(g.node_index(i, j));
  }
  return out;
}

void tie_bonded_nodes(State& s, TieWhat what) {
  GridFields& G = s.fields;
  for (std::size_t c = 0; c < s.interfaces.size(); ++c) {
    const std::size_t up = G.offset(s.interfaces[c].spec.upper_field);
    const std::size_t lo = G.offset(s.interfaces[c].spec.lower_field);
    auto tie = [&](std::vector<double>& v, std::size_t n) { v[up + n] = v[lo + n] = v[up + n] + v[lo + n]; };
    for (std::size_t n : s.bonded[c]) {
      if (what == TieWhat::mass_momentum) {
        for (auto* v : {&G.mass, &G.mom_x, &G.mom_y}) tie(*v, n);
      } else if (what == TieWhat::force) {
        tie(G.force_x, n);
        tie(G.force_y, n);
      } else {
        tie(G.remap_x, n);
        tie(G.remap_y, n);
      }
    }
  }
}

void advance_interfaces(State& s) {
  const GridFields& G = s.fields;
  const std::size_t nx = std::size_t(s.grid.nodes_x());
  const double dt = s.dt;
  for (CohesiveInterface& c : s.interfaces) {
    const std::size_t up = G.offset(c.spec.upper_field), lo = G.offset(c.spec.lower_field);
    const long n = long(c.num_nodes());
#pragma omp parallel for schedule(static)
    for (long kl = 0; kl < n; ++kl) {
      const std::size_t k = std::size_t(kl);
      // Each face moves with its own field's t^{n+1} grid velocity (the particles' velocity).
      const PointStencil a = point_stencil(s.grid, c.x0[k] + c.ux_up[k], c.spec.y + c.uy_up[k]);
      const PointStencil b = point_stencil(s.grid, c.x0[k] + c.ux_lo[k], c.spec.y + c.uy_lo[k]);
      double vax = 0, vay = 0, vbx = 0, vby = 0;
      for (int jj = 0; jj < 2; ++jj)
        for (int ii = 0; ii < 2; ++ii) {
          const double wa = a.wx[ii] * a.wy[jj], wb = b.wx[ii] * b.wy[jj];
          const std::size_t na = up + a.node + std::size_t(jj) * nx + std::size_t(ii);
          const std::size_t nb = lo + b.node + std::size_t(jj) * nx + std::size_t(ii);
          vax += wa * G.vel_x[na], vay += wa * G.vel_y[na];
          vbx += wb * G.vel_x[nb], vby += wb * G.vel_y[nb];
        }
      c.ux_up[k] += dt * vax, c.uy_up[k] += dt * vay;
      c.ux_lo[k] += dt * vbx, c.uy_lo[k] += dt * vby;
    }
    evaluate_interface(c, s.time);
  }
}

}  // namespace rupture
