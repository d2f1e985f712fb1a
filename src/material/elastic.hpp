// rupture/material/elastic.hpp
// Small-strain isotropic linear elasticity in 2D (theory E5) and its wave speeds (theory E1).
// Units: E and stresses in Pa, density in kg/m^3, speeds in m/s.
// Plane strain keeps sigma_zz = nu (sigma_xx + sigma_yy); plane stress has sigma_zz = 0.
#pragma once
#include <string>

namespace rupture {

enum class PlaneMode { strain, stress };

struct ElasticMaterial {
  std::string name;
  double youngs_modulus = 0.0;  // E, Pa
  double poisson_ratio = 0.0;   // nu, -
  double density = 0.0;         // rho, kg/m^3
  // Kelvin-Voigt damping (docs/theory.md §16): sigma = C : (eps + eta eps_dot) with
  // eta = kelvin_voigt x dt, the time step (as SEM2DPACK and PyLith set it, e.g. 0.1). 0: none.
  double kelvin_voigt = 0.0;    // eta / dt, -
};

// In-plane stiffness for the chosen plane mode: sigma = C : eps with
//   sxx = c11 exx + c12 eyy, syy = c12 exx + c11 eyy, sxy = 2 mu exy, szz = cz (exx + eyy).
// Isotropy gives c11 - c12 = 2 mu in both plane modes. tr_per_stress = 1 / (c11 + c12), 1/Pa:
// tr eps = (sxx + syy) tr_per_stress.
struct ElasticStiffness {
  double c11, c12, mu, cz;
  double tr_per_stress;
  double kelvin_voigt = 0.0;  // eta / dt (ElasticMaterial::kelvin_voigt)
};

ElasticStiffness stiffness(const ElasticMaterial& m, PlaneMode mode);

// A uniform elastic state: stress, Pa, and small strain (tensor components), -.
struct ElasticState {
  double sxx, syy, sxy, szz;
  double exx, eyy, exy;
};

// The state of a material prestressed to the in-plane stress (sxx, syy, sxy), Pa: the strain
// is the compliance of the plane mode applied to it, and sigma_zz = nu (sxx + syy) in plane
// strain (eps_zz = 0), 0 in plane stress. So sigma = C : eps, as the incremental stress update
// (theory E5) assumes, and 0.5 sigma:eps is the strain energy density from the start.
ElasticState prestressed_state(const ElasticMaterial& m, PlaneMode mode, double sxx, double syy,
                               double sxy);

// A linear elastic point holds sigma = C : eps at every instant (from the start: see
// prestressed_state; the stress update adds C : d eps), so its strain, sigma_zz and current
// volume follow from the in-plane stress: the particles store the stress only
// (particles/particles.hpp). Each equals the incrementally summed quantity up to round-off.
inline double strain_trace(const ElasticStiffness& C, double sxx, double syy) {
  return (sxx + syy) * C.tr_per_stress;
}
inline double stress_zz(const ElasticStiffness& C, double sxx, double syy) {
  return C.cz * strain_trace(C, sxx, syy);
}
// eps = C^-1 sigma in plane: [c11 c12; c12 c11]^-1 = [c11 -c12; -c12 c11] / ((c11 - c12)(c11 + c12)).
inline void strain_of(const ElasticStiffness& C, double sxx, double syy, double sxy, double& exx,
                      double& eyy, double& exy) {
  const double two_mu = 2.0 * C.mu, det = two_mu / C.tr_per_stress;  // (c11 - c12)(c11 + c12)
  exx = (C.c11 * sxx - C.c12 * syy) / det;
  eyy = (C.c11 * syy - C.c12 * sxx) / det;
  exy = sxy / two_mu;
}

struct WaveSpeeds {
  double dilatational;  // c_D, m/s
  double shear;         // c_S, m/s
  double rayleigh;      // exact root of the Rayleigh equation, m/s
  double rayleigh_approx;  // c_S (0.862 + 1.14 nu)/(1 + nu), theory E1
};

// theory E1, with kappa = 3 - 4 nu (plane strain) or (3 - nu)/(1 + nu) (plane stress).
WaveSpeeds wave_speeds(const ElasticMaterial& m, PlaneMode mode);

}  // namespace rupture
