// rupture/bulk/elastic_update.hpp
// Small-strain isotropic elasticity at one point, for any dimension (theory E5): the strain
// increment of a velocity gradient, the stress increment C : d eps, the stress work of the
// increment (E14) and the Kelvin-Voigt viscous stress (docs/theory.md §16). Plain functions over
// a point's components (bulk/dimension.hpp's order: normal components first), called inside the
// loops over particles (solver/gather.cpp in 2D, bulk/block_step.cpp in 2D and 3D); they
// inline to straight-line code the loops vectorize.
// Stiffness: c11 = d sigma_ii / d eps_ii, c12 = d sigma_ii / d eps_jj (j != i), mu the shear
// modulus (material/elastic.hpp's ElasticStiffness: its plane mode in 2D; in 3D c11 = lambda +
// 2 mu, c12 = lambda). Units: Pa, 1/s, s, m^dim, J.
// In 2D every expression is the one the 2D code always had, term for term and in the same
// order, so its answers are bitwise what they were (tests/e2e/same_answers.py).
#pragma once
#include "bulk/dimension.hpp"

namespace rupture {

// d eps = sym(L) dt with L_ij = dv_i / dx_j: the tensor components (d eps_xy, not the
// engineering shear 2 d eps_xy).
template <int dim>
inline void strain_increment(const double (&L)[dim][dim], double dt, double (&de)[kSymmetric<dim>]) {
  using C = SymmetricComponents<dim>;
  for (int c = 0; c < kSymmetric<dim>; ++c) {
    const int i = C::row[std::size_t(c)], j = C::col[std::size_t(c)];
    de[c] = c < dim ? L[i][i] * dt : 0.5 * (L[i][j] + L[j][i]) * dt;
  }
}

// Row i of the normal block of C times the normal strains, summed in component order
// (c_ij d eps_jj, c_ii = c11, c_ij = c12): the order the 2D code always summed in.
template <int dim>
inline double normal_row(double c11, double c12, const double (&de)[kSymmetric<dim>], int i) {
  double sum = (i == 0 ? c11 : c12) * de[0];
  for (int j = 1; j < dim; ++j) sum += (i == j ? c11 : c12) * de[j];
  return sum;
}

// d sigma = C : d eps.
template <int dim>
inline void stress_increment(double c11, double c12, double mu, const double (&de)[kSymmetric<dim>],
                             double (&ds)[kSymmetric<dim>]) {
  for (int c = 0; c < kSymmetric<dim>; ++c)
    ds[c] = c < dim ? normal_row<dim>(c11, c12, de, c) : 2.0 * mu * de[c];
}

// sigma : d eps (each shear component twice).
template <int dim>
inline double contract(const double (&s)[kSymmetric<dim>], const double (&de)[kSymmetric<dim>]) {
  double sum = s[0] * de[0];
  for (int c = 1; c < kSymmetric<dim>; ++c) sum += c < dim ? s[c] * de[c] : 2.0 * s[c] * de[c];
  return sum;
}

// E14's stress work of the increment: the midpoint stress on the midpoint volume,
// V0 (1 + tr eps + tr d eps / 2) (sigma + d sigma / 2) : d eps. tr_eps before the increment.
template <int dim>
inline double stress_work(double volume0, double tr_eps, const double (&s)[kSymmetric<dim>],
                          const double (&de)[kSymmetric<dim>], const double (&ds)[kSymmetric<dim>]) {
  double tr_de = de[0];
  for (int c = 1; c < dim; ++c) tr_de += de[c];
  const double v_mid = volume0 * (1.0 + tr_eps + 0.5 * tr_de);
  double mid[kSymmetric<dim>];
  for (int c = 0; c < kSymmetric<dim>; ++c) mid[c] = s[c] + 0.5 * ds[c];
  return v_mid * contract<dim>(mid, de);
}

// Kelvin-Voigt: the viscous stress eta C : eps_dot = kv C : d eps (kv = eta / dt, the
// material's kelvin_voigt).
template <int dim>
inline void viscous_stress(double kv, double c11, double c12, double mu,
                           const double (&de)[kSymmetric<dim>], double (&vs)[kSymmetric<dim>]) {
  for (int c = 0; c < kSymmetric<dim>; ++c)
    vs[c] = c < dim ? kv * normal_row<dim>(c11, c12, de, c) : kv * 2.0 * mu * de[c];
}

// tr sigma: the sum of the normal components.
template <int dim>
inline double trace(const double (&s)[kSymmetric<dim>]) {
  double sum = s[0];
  for (int c = 1; c < dim; ++c) sum += s[c];
  return sum;
}

}  // namespace rupture
