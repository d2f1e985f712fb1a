// rupture/fracture/near_tip_field.cpp
#include "fracture/near_tip_field.hpp"

#include <cmath>
#include <numbers>

namespace rupture {

double kolosov_kappa(double nu, PlaneMode mode) {
  return mode == PlaneMode::strain ? 3.0 - 4.0 * nu : (3.0 - nu) / (1.0 + nu);
}

NearTipField williams_field(CrackMode mode, double x1, double x2, double mu, double kappa) {
  const double pi = std::numbers::pi;
  const double r = std::hypot(x1, x2), th = std::atan2(x2, x1);
  const double s = std::sin(0.5 * th), c = std::cos(0.5 * th);
  const double s3 = std::sin(1.5 * th), c3 = std::cos(1.5 * th);
  const double a = 1.0 / std::sqrt(2.0 * pi * r);         // stress scale
  const double b = std::sqrt(r / (2.0 * pi)) / (2.0 * mu); // displacement scale
  NearTipField f{};
  // g(theta) and g'(theta) of u = b g for each component.
  double g1, g2, dg1, dg2;
  if (mode == CrackMode::opening) {
    f.s11 = a * c * (1.0 - s * s3);
    f.s22 = a * c * (1.0 + s * s3);
    f.s12 = a * c * s * c3;
    g1 = c * (kappa - 1.0 + 2.0 * s * s);
    dg1 = -0.5 * s * (kappa - 1.0 + 2.0 * s * s) + 2.0 * s * c * c;
    g2 = s * (kappa + 1.0 - 2.0 * c * c);
    dg2 = 0.5 * c * (kappa + 1.0 - 2.0 * c * c) + 2.0 * s * s * c;
  } else {
    f.s11 = -a * s * (2.0 + c * c3);
    f.s22 = a * s * c * c3;
    f.s12 = a * c * (1.0 - s * s3);
    g1 = s * (kappa + 1.0 + 2.0 * c * c);
    dg1 = 0.5 * c * (kappa + 1.0 + 2.0 * c * c) - 2.0 * s * s * c;
    g2 = -c * (kappa - 1.0 - 2.0 * s * s);
    dg2 = 0.5 * s * (kappa - 1.0 - 2.0 * s * s) + 2.0 * s * c * c;
  }
  f.u1 = b * g1, f.u2 = b * g2;
  // u = b(r) g(theta), b ~ sqrt(r): du/dr = u / (2 r); d/dx1 = cos th d/dr - sin th / r d/dth,
  // d/dx2 = sin th d/dr + cos th / r d/dth.
  const double ct = std::cos(th), st = std::sin(th), br = b / r;
  f.u1_1 = br * (0.5 * ct * g1 - st * dg1);
  f.u1_2 = br * (0.5 * st * g1 + ct * dg1);
  f.u2_1 = br * (0.5 * ct * g2 - st * dg2);
  f.u2_2 = br * (0.5 * st * g2 + ct * dg2);
  return f;
}

}  // namespace rupture
