// rupture/shape/gimp.hpp
// uGIMP weights and gradients (SPEC E3, Bardenhagen & Kober 2004): the grid's linear hat
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

// SPEC E3, uniform spacing h, d = x_p - x_i.
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

// Branch-free uniform weight of one node, the form used in the hot path (SIMD-friendly).
// d = (x_p - x_i) / h, l = lp / h <= 1/2, inv_2l = 1 / (2 l). Same values as gimp_uniform
// (to round-off), written as the box average of SPEC E3: S = [F(d + l) - F(d - l)] / (2 l),
// with the hat's antiderivative F(c) = 1/2 + c - c|c|/2 on c = clamp(d, -1, 1), and
// dS/dx_p = [N(d + l) - N(d - l)] / (2 l h) with N(u) = max(0, 1 - |u|).
inline void gimp_uniform_node(double d, double l, double inv_2l, double inv_h, double& s,
                              double& ds) {
  // std::min/max, not fmin/fmax: these compile to minsd/maxsd instead of libm calls.
  const double a = std::min(1.0, std::max(-1.0, d + l));
  const double b = std::min(1.0, std::max(-1.0, d - l));
  s = ((a - b) - 0.5 * (a * std::fabs(a) - b * std::fabs(b))) * inv_2l;
  ds = (std::fabs(b) - std::fabs(a)) * inv_2l * inv_h;
}

// The three nonzero weights of a particle at u = (x_p - x_first) / h in [0.5, 1.5).
inline void gimp_uniform_stencil(double u, double l, double inv_h, double s[3], double ds[3]) {
  const double inv_2l = 0.5 / l;
  for (int k = 0; k < 3; ++k) gimp_uniform_node(u - double(k), l, inv_2l, inv_h, s[k], ds[k]);
}

// Linear hat of node i on a graded axis, u = x - x_i (SPEC E3).
inline double hat_graded(double u, double hL, double hR) {
  if (u <= -hL || u >= hR) return 0.0;
  return u <= 0.0 ? 1.0 + u / hL : 1.0 - u / hR;
}

// Antiderivative F_i of the hat, F_i(-inf) = 0 (SPEC E3).
inline double hat_integral_graded(double u, double hL, double hR) {
  if (u <= -hL) return 0.0;
  if (u <= 0.0) return (u + hL) * (u + hL) / (2.0 * hL);
  if (u <= hR) return 0.5 * hL + u - u * u / (2.0 * hR);
  return 0.5 * (hL + hR);
}

// SPEC E3, graded axis: node with left cell hL and right cell hR, u = x_p - x_i.
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
