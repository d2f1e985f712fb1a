// rupture/solver/energy.hpp
// Energies of the particle system (SPEC E14), J per unit thickness (J/m in 2D).
//   kinetic = sum 1/2 m_p |v_p|^2,  strain = sum 1/2 V0_p sigma_p : eps_p  (small strain).
#pragma once
#include "particles/particles.hpp"

namespace rupture {

double kinetic_energy(const Particles& p);
double strain_energy(const Particles& p);

}  // namespace rupture
