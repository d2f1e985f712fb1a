// rupture/solver/energy.cpp
#include "solver/energy.hpp"

namespace rupture {

double kinetic_energy(const Particles& p) {
  const long n = long(p.size());
  double e = 0.0;
#pragma omp parallel for reduction(+ : e) schedule(static)
  for (long i = 0; i < n; ++i) e += 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
  return e;
}

double strain_energy(const Particles& p) {
  const long n = long(p.size());
  double e = 0.0;
  // Plane strain has eps_zz = 0 and plane stress sigma_zz = 0: no out-of-plane term either way.
#pragma omp parallel for reduction(+ : e) schedule(static)
  for (long i = 0; i < n; ++i)
    e += 0.5 * p.volume0[i] *
         (p.sxx[i] * p.exx[i] + p.syy[i] * p.eyy[i] + 2.0 * p.sxy[i] * p.exy[i]);
  return e;
}

}  // namespace rupture
