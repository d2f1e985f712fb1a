// Shared helpers for tests that step a State: the energy balance (theory E14) and a run to a time.
#pragma once
#include <cmath>

#include "solver/energy.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"

namespace rupture::test {

// |E0 + W_ext - (K + U)| / (E0 + |W_ext|): the particles' kinetic and strain energy against the
// initial energy and the external work.
inline double energy_error(const State& s) {
  const double total = kinetic_energy(s.particles) + strain_energy(s.particles, s.stiffness);
  return std::fabs(s.initial_energy + s.external_work - total) /
         (s.initial_energy + std::fabs(s.external_work));
}

// Steps until `end` (s), the last step shortened to land on it.
inline void run_to(State& s, double end) {
  while (s.time < end - 1e-6 * s.dt) {
    s.dt_cap = end - s.time;
    step(s);
  }
}

}  // namespace rupture::test
