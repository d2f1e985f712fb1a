// rupture/solver/energy.cpp
#include "solver/energy.hpp"

namespace rupture {

// Serial sums in particle order: the same to the bit whatever the number of threads (a run may
// change it between steps: run/thread_tuner.hpp), and taken only when a history sample or a
// migration asks (a few ms per million particles).
double kinetic_energy(const Particles& p) {
  const long n = long(p.size());
  double e = 0.0;
  for (long i = 0; i < n; ++i) e += 0.5 * p.mass[i] * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
  return e;
}

double strain_energy(const Particles& p, const std::vector<ElasticStiffness>& stiffness) {
  const long n = long(p.size());
  double e = 0.0;
  for (long i = 0; i < n; ++i)
    e += elastic_energy(p, stiffness[p.material[std::size_t(i)]], std::size_t(i));
  return e;
}

}  // namespace rupture
