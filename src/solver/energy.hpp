// rupture/solver/energy.hpp
// Energies of the particle system (theory E14), J per unit thickness (J/m in 2D).
//   kinetic = sum 1/2 m_p |v_p|^2
//   strain (E14, the balance) = State::strain_work: the elastic energy at t = 0 plus the work
//             the stresses have done since, accumulated by the stress update (solver/transfer)
//             as sum_p V sigma : d eps with V and sigma at the middle of each step;
//   elastic = sum 1/2 V0_p sigma_p : eps_p, the energy of the current state at the initial
//             volume (the same at t = 0).
// Why the stored work for the balance: the internal forces use the current volume
// V = V0 (1 + tr eps) (theory E4), so the energy they store is sum int V sigma : d eps; the elastic
// sum misses the (2/3)|eps| part of it, which drifted the balance by -8 J/m (0.37 %) under the
// reference impact's 1.2 % compression by 19.2 us (docs/validation.md). For linear elasticity
// with V = V0 the midpoint sum equals 1/2 V0 sigma : eps exactly (C is symmetric), so the two
// differ only by that drift.
#pragma once
#include <cstddef>

#include <vector>

#include "bulk/elastic_update.hpp"
#include "material/elastic.hpp"
#include "particles/particles.hpp"

namespace rupture {

double kinetic_energy(const Particles& p);
// The elastic sum, 1/2 V0 sigma : eps; stiffness: the run's table, indexed by P.material.
double strain_energy(const Particles& p, const std::vector<ElasticStiffness>& stiffness);
// 1/2 V0 sigma : eps of particle p with eps = C^-1 sigma (plane strain: eps_zz = 0; plane
// stress: sigma_zz = 0, so no out-of-plane term either way), J/m.
inline double elastic_energy(const Particles& P, const ElasticStiffness& C, std::size_t p) {
  double exx, eyy, exy;
  strain_of(C, P.sxx[p], P.syy[p], P.sxy[p], exx, eyy, exy);
  return 0.5 * P.volume0[p] * (P.sxx[p] * exx + P.syy[p] * eyy + 2.0 * P.sxy[p] * exy);
}
// The work V sigma : d eps of one strain increment d eps (d exy: tensor component) that takes
// the stress from (sxx, syy, sxy) by (dsxx, dsyy, dsxy), with tr eps = tr_eps before it; both
// V and sigma at the middle of the increment, J/m.
inline double stress_work(double volume0, double tr_eps, double sxx, double syy, double sxy,
                          double dexx, double deyy, double dexy, double dsxx, double dsyy,
                          double dsxy) {
  const double s[3] = {sxx, syy, sxy}, de[3] = {dexx, deyy, dexy}, ds[3] = {dsxx, dsyy, dsxy};
  return stress_work<2>(volume0, tr_eps, s, de, ds);  // bulk/elastic_update.hpp
}

}  // namespace rupture
