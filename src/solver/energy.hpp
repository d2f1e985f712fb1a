// rupture/solver/energy.hpp
// Energies of the particle system (SPEC E14), J per unit thickness (J/m in 2D).
//   kinetic = sum 1/2 m_p |v_p|^2,  strain = sum 1/2 V0_p sigma_p : eps_p  (small strain).
#pragma once
#include "particles/particles.hpp"

namespace rupture {

struct State;

double kinetic_energy(const Particles& p);
double strain_energy(const Particles& p);
// The strain energy of the time-stepping scheme after a step, sum 1/2 V0 sigma^{n+1} : eps^n =
// strain_energy(particles) - State::strain_energy_lag. MUSL and USL strain with the velocity
// after the kick (v^{n+1/2} of the central difference), and the central difference conserves
// 1/2 m |v^{n+1/2}|^2 + 1/2 u^n K u^{n+1} exactly for linear elasticity; pairing that kinetic
// energy with 1/2 u^{n+1} K u^{n+1} instead is off by 1/2 dt (dE_strain/dt), an O(dt) error
// of E14 (docs/time_step.md). The energy balance uses this one.
double strain_energy(const State& s);

}  // namespace rupture
