// rupture/fracture/near_tip_field.cpp
#include "fracture/near_tip_field.hpp"

#include <cmath>
#include <numbers>

namespace rupture {

double kolosov_kappa(double nu, PlaneMode mode) {
  return mode == PlaneMode::strain ? 3.0 - 4.0 * nu : (3.0 - nu) / (1.0 + nu);
}

void williams_fields(double x1, double x2, double mu, double kappa, NearTipField& opening, NearTipField& sliding) {
  const double pi = std::numbers::pi;
  const double r = std::sqrt(x1 * x1 + x2 * x2), th = std::atan2(x2, x1);
  // One sine and cosine, of theta / 2; those of 3 theta / 2 and theta from them (triple and
  // double angle), and the two modes share them: the interaction integral evaluates both modes
  // at every domain point of every tip read, every step.
  const double s = std::sin(0.5 * th), c = std::cos(0.5 * th);
  const double s3 = s * (3.0 - 4.0 * s * s), c3 = c * (4.0 * c * c - 3.0);
  const double ct = c * c - s * s, st = 2.0 * s * c;
  const double a = 1.0 / std::sqrt(2.0 * pi * r);          // stress scale
  const double b = std::sqrt(r / (2.0 * pi)) / (2.0 * mu);  // displacement scale
  const double br = b / r;
  // g(theta) and g'(theta) of u = b g for each component; u = b(r) g(theta), b ~ sqrt(r):
  // du/dr = u / (2 r); d/dx1 = cos th d/dr - sin th / r d/dth, d/dx2 = sin th d/dr + cos th / r d/dth.
  const auto finish = [&](NearTipField& f, double g1, double dg1, double g2, double dg2) {
    f.u1 = b * g1, f.u2 = b * g2;
    f.u1_1 = br * (0.5 * ct * g1 - st * dg1);
    f.u1_2 = br * (0.5 * st * g1 + ct * dg1);
    f.u2_1 = br * (0.5 * ct * g2 - st * dg2);
    f.u2_2 = br * (0.5 * st * g2 + ct * dg2);
  };
  opening.s11 = a * c * (1.0 - s * s3);
  opening.s22 = a * c * (1.0 + s * s3);
  opening.s12 = a * c * s * c3;
  finish(opening, c * (kappa - 1.0 + 2.0 * s * s), -0.5 * s * (kappa - 1.0 + 2.0 * s * s) + 2.0 * s * c * c,
         s * (kappa + 1.0 - 2.0 * c * c), 0.5 * c * (kappa + 1.0 - 2.0 * c * c) + 2.0 * s * s * c);
  sliding.s11 = -a * s * (2.0 + c * c3);
  sliding.s22 = a * s * c * c3;
  sliding.s12 = a * c * (1.0 - s * s3);
  finish(sliding, s * (kappa + 1.0 + 2.0 * c * c), 0.5 * c * (kappa + 1.0 + 2.0 * c * c) - 2.0 * s * s * c,
         -c * (kappa - 1.0 - 2.0 * s * s), 0.5 * s * (kappa - 1.0 - 2.0 * s * s) + 2.0 * s * c * c);
}

NearTipField williams_field(CrackMode mode, double x1, double x2, double mu, double kappa) {
  NearTipField f[2];
  williams_fields(x1, x2, mu, kappa, f[0], f[1]);
  return f[mode == CrackMode::opening ? 0 : 1];
}

}  // namespace rupture
