// rupture/shape/gimp.hpp
// uGIMP weights and gradients (SPEC E3, Bardenhagen & Kober 2004): the grid's linear hat
// function N_i averaged over a particle box of half-width lp. Two forms:
//  - gimp_uniform: closed form for a uniform axis of spacing h (the hot path);
//  - gimp_graded: any node with left/right cell sizes hL, hR (graded tensor-product grids).
// Both return S_ip and dS_ip/dx_p for one axis; 2D weights are products (S(dx)S(dy)).
// Contract: lp > 0, lp <= min(h)/2; the partition of unity holds for any such lp.
#pragma once
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

}  // namespace rupture
