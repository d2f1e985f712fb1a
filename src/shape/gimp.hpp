// rupture/shape/gimp.hpp
// uGIMP weights and gradients (theory E3, Bardenhagen & Kober 2004): the grid's linear hat
// function N_i averaged over a particle box of half-width lp. Two forms:
//  - gimp_uniform: closed form for a uniform axis of spacing h (the hot path);
//  - gimp_graded: any node with left/right cell sizes hL, hR (graded tensor-product grids).
// Both return S_ip and dS_ip/dx_p for one axis; 2D weights are products (S(dx)S(dy)).
// Contract: lp > 0, lp <= min(h)/2; the partition of unity holds for any such lp. (On a graded
// axis the exact condition for a complete 3-node stencil is in grid/grid.hpp.)
#pragma once
#include <algorithm>
#include <cmath>

namespace rupture {

struct Weight1D {
  double s;   // weight S_ip (dimensionless)
  double ds;  // dS_ip/dx_p (1/m)
};

// theory E3, uniform spacing h, d = x_p - x_i.
inline Weight1D gimp_uniform(double d, double h, double lp) {
  const double a = std::fabs(d);
  const double sgn = d < 0.0 ? -1.0 : 1.0;
  if (a < lp) return {1.0 - (d * d + lp * lp) / (2.0 * h * lp), -d / (h * lp)};
  if (a < h - lp) return {1.0 - a / h, -sgn / h};
  if (a < h + lp) {
    const double g = h + lp - a;
    return {g * g / (4.0 * h * lp), -sgn * g / (2.0 * h * lp)};
  }
  return {0.0, 0.0};
}

// Branch-free uniform stencil, the form used in the hot path (SIMD-friendly). c = (x_p -
// x_mid) / h in [-1/2, 1/2] is the particle's offset from the stencil's middle node (the
// stencil is nodes mid - 1, mid, mid + 1), l = lp / h <= 1/2, inv_4l = 1 / (4 l). The particle
// box [c - l, c + l] then lies between the outer nodes, where the outer hats are linear, so
// each outer weight is the length of the box on its side of the middle node times the hat's
// mean there (theory E3's box average):
//   r_lo = clamp(l - c, 0, 2 l),  S_lo = r_lo (p + p') / (4 l),  dS_lo/dx_p = -r_lo / (2 l h)
//   r_hi = clamp(c + l, 0, 2 l),  S_hi = r_hi (q + q') / (4 l),  dS_hi/dx_p =  r_hi / (2 l h)
// with p = (l - c)+, p' = (-c - l)+, q = (c + l)+, q' = (c - l)+; the middle node takes the
// rest: S_mid = 1 - S_lo - S_hi, dS_mid = -(dS_lo + dS_hi). Where the box misses the middle
// node, r = 2 l exactly, so S_lo = -c and dS_lo = -1/h to a few ulps (the same expression
// as q - q' would lose eps c / l there); where it misses an outer hat, that weight and
// gradient are exactly 0; the middle weight is at least 1/2, so taking it as the rest leaves
// no round-off weight where there should be none. Same values as gimp_uniform to a few ulps
// (tests/test_shape), in about 22 operations instead of 50.
inline void gimp_uniform_three(double c, double l, double inv_4l, double inv_h, double& s0,
                               double& s1, double& s2, double& ds0, double& ds1, double& ds2) {
  // std::min/max, not fmin/fmax: minsd/maxsd instead of libm calls.
  const double p = std::max(l - c, 0.0), pm = std::max(-c - l, 0.0);
  const double q = std::max(c + l, 0.0), qm = std::max(c - l, 0.0);
  const double two_l = 2.0 * l, rp = std::min(p, two_l), rq = std::min(q, two_l);
  s0 = rp * (p + pm) * inv_4l;
  s2 = rq * (q + qm) * inv_4l;
  s1 = (1.0 - s0) - s2;
  const double g = 2.0 * inv_4l * inv_h;  // 1 / (2 l h)
  ds0 = -rp * g;
  ds2 = rq * g;
  ds1 = -(ds0 + ds2);
}

// The three nonzero weights of a particle at u = (x_p - x_first) / h in [0.5, 1.5).
inline void gimp_uniform_stencil(double u, double l, double inv_h, double s[3], double ds[3]) {
  gimp_uniform_three(u - 1.0, l, 0.25 / l, inv_h, s[0], s[1], s[2], ds[0], ds[1], ds[2]);
}

// Linear hat of node i on a graded axis, u = x - x_i (theory E3).
inline double hat_graded(double u, double hL, double hR) {
  if (u <= -hL || u >= hR) return 0.0;
  return u <= 0.0 ? 1.0 + u / hL : 1.0 - u / hR;
}

// Antiderivative F_i of the hat, F_i(-inf) = 0 (theory E3).
inline double hat_integral_graded(double u, double hL, double hR) {
  if (u <= -hL) return 0.0;
  if (u <= 0.0) return (u + hL) * (u + hL) / (2.0 * hL);
  if (u <= hR) return 0.5 * hL + u - u * u / (2.0 * hR);
  return 0.5 * (hL + hR);
}

// theory E3, graded axis: node with left cell hL and right cell hR, u = x_p - x_i.
// The sign convention matches gimp_uniform: ds is the derivative w.r.t. the particle position.
inline Weight1D gimp_graded(double u, double hL, double hR, double lp) {
  const double inv = 1.0 / (2.0 * lp);
  return {(hat_integral_graded(u + lp, hL, hR) - hat_integral_graded(u - lp, hL, hR)) * inv,
          (hat_graded(u + lp, hL, hR) - hat_graded(u - lp, hL, hR)) * inv};
}

// gimp_graded with selects instead of branches (the same operations on every path, so the
// values are those of gimp_graded to the bit), for loops vectorized over particles.
inline double hat_graded_select(double u, double hL, double hR) {
  const double r = u <= 0.0 ? 1.0 + u / hL : 1.0 - u / hR;
  return (u <= -hL || u >= hR) ? 0.0 : r;
}
inline double hat_integral_graded_select(double u, double hL, double hR) {
  const double left = (u + hL) * (u + hL) / (2.0 * hL);
  const double right = 0.5 * hL + u - u * u / (2.0 * hR);
  double r = u <= 0.0 ? left : right;
  r = u > hR ? 0.5 * (hL + hR) : r;
  return u <= -hL ? 0.0 : r;
}
inline void gimp_graded_select(double u, double hL, double hR, double lp, double& s, double& ds) {
  const double inv = 1.0 / (2.0 * lp);
  s = (hat_integral_graded_select(u + lp, hL, hR) - hat_integral_graded_select(u - lp, hL, hR)) * inv;
  ds = (hat_graded_select(u + lp, hL, hR) - hat_graded_select(u - lp, hL, hR)) * inv;
}

}  // namespace rupture
