// rupture/material/elastic.cpp
#include "material/elastic.hpp"

#include <cmath>

namespace rupture {

ElasticStiffness stiffness(const ElasticMaterial& m, PlaneMode mode) {
  const double E = m.youngs_modulus, nu = m.poisson_ratio;
  const double mu = E / (2.0 * (1.0 + nu));
  if (mode == PlaneMode::strain) {
    const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    return {lambda + 2.0 * mu, lambda, mu, lambda, 1.0 / (2.0 * (lambda + mu)), m.kelvin_voigt};
  }
  const double c = E / (1.0 - nu * nu);
  return {c, c * nu, mu, 0.0, 1.0 / (c * (1.0 + nu)), m.kelvin_voigt};
}

ElasticState prestressed_state(const ElasticMaterial& m, PlaneMode mode, double sxx, double syy,
                               double sxy) {
  const double E = m.youngs_modulus, nu = m.poisson_ratio;
  ElasticState s{sxx, syy, sxy, 0.0, 0.0, 0.0, 0.0};
  if (mode == PlaneMode::strain) {
    // eps = ((1 + nu) / E) (sigma - nu tr(sigma) I) with sigma_zz = nu (sxx + syy).
    s.szz = nu * (sxx + syy);
    s.exx = (1.0 + nu) / E * ((1.0 - nu) * sxx - nu * syy);
    s.eyy = (1.0 + nu) / E * ((1.0 - nu) * syy - nu * sxx);
  } else {
    s.exx = (sxx - nu * syy) / E;
    s.eyy = (syy - nu * sxx) / E;
  }
  s.exy = (1.0 + nu) / E * sxy;  // sxy / (2 mu)
  return s;
}

WaveSpeeds wave_speeds(const ElasticMaterial& m, PlaneMode mode) {
  const double nu = m.poisson_ratio;
  const double mu = m.youngs_modulus / (2.0 * (1.0 + nu));
  const double kappa = mode == PlaneMode::strain ? 3.0 - 4.0 * nu : (3.0 - nu) / (1.0 + nu);
  WaveSpeeds w{};
  w.shear = std::sqrt(mu / m.density);
  w.dilatational = std::sqrt((kappa + 1.0) / (kappa - 1.0) * mu / m.density);
  w.rayleigh_approx = w.shear * (0.862 + 1.14 * nu) / (1.0 + nu);
  // Rayleigh equation in xi = c/c_S: (2 - xi^2)^2 - 4 sqrt(1 - xi^2 k) sqrt(1 - xi^2) = 0,
  // k = (c_S/c_D)^2. The root in (0, 1) is unique; bisection is robust and cheap.
  const double k = (w.shear / w.dilatational) * (w.shear / w.dilatational);
  auto f = [k](double xi) {
    const double x2 = xi * xi;
    return (2.0 - x2) * (2.0 - x2) - 4.0 * std::sqrt(1.0 - x2 * k) * std::sqrt(1.0 - x2);
  };
  // f ~ 2 (k - 1) xi^2 < 0 near 0 and f(1) = 1 > 0 for every nu in (-1, 0.5).
  double lo = 0.1, hi = 1.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  w.rayleigh = 0.5 * (lo + hi) * w.shear;
  return w;
}

}  // namespace rupture
