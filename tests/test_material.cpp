// Tests of material/elastic.hpp against theory E1 and E5.
#include <gtest/gtest.h>

#include <cmath>

#include "material/elastic.hpp"

using namespace rupture;

namespace {
ElasticMaterial homalite() { return {"homalite", 5.2e9, 0.34, 1246.0}; }
}  // namespace

TEST(Elastic, homalite_wave_speeds_match_spec_E1) {
  const WaveSpeeds w = wave_speeds(homalite(), PlaneMode::strain);
  EXPECT_NEAR(w.dilatational, 2534.0, 1.0);
  EXPECT_NEAR(w.shear, 1248.0, 1.0);
  EXPECT_NEAR(w.rayleigh_approx, 1164.0, 1.0);
  EXPECT_NEAR(w.rayleigh, 1165.0, 1.0);
}

TEST(Elastic, rayleigh_root_satisfies_rayleigh_equation) {
  for (double nu : {-0.5, 0.0, 0.25, 0.34, 0.49}) {
    ElasticMaterial m{"m", 1e9, nu, 1000.0};
    for (PlaneMode mode : {PlaneMode::strain, PlaneMode::stress}) {
      const WaveSpeeds w = wave_speeds(m, mode);
      const double x2 = std::pow(w.rayleigh / w.shear, 2), k = std::pow(w.shear / w.dilatational, 2);
      const double residual = std::pow(2 - x2, 2) - 4 * std::sqrt(1 - x2 * k) * std::sqrt(1 - x2);
      EXPECT_NEAR(residual, 0.0, 1e-10) << "nu = " << nu;
      EXPECT_LT(w.rayleigh, w.shear);
      // The theory E1 approximation is the plane-strain fit for nu >= 0 (about 1 % accurate).
      if (mode == PlaneMode::strain && nu >= 0.0) {
        EXPECT_NEAR(w.rayleigh, w.rayleigh_approx, 0.015 * w.shear) << "nu = " << nu;
      }
    }
  }
}

TEST(Elastic, plane_strain_keeps_sigma_zz_equal_nu_times_in_plane_sum) {
  const ElasticMaterial m = homalite();
  const ElasticStiffness C = stiffness(m, PlaneMode::strain);
  const double exx = 1e-3, eyy = -4e-4;
  const double sxx = C.c11 * exx + C.c12 * eyy, syy = C.c12 * exx + C.c11 * eyy;
  EXPECT_NEAR(C.cz * (exx + eyy), m.poisson_ratio * (sxx + syy), 1e-6 * std::fabs(sxx));
  // c11 = rho c_D^2 in plane strain (uniaxial strain modulus).
  EXPECT_NEAR(C.c11, m.density * std::pow(wave_speeds(m, PlaneMode::strain).dilatational, 2), 1.0);
}

TEST(Elastic, plane_stress_has_no_sigma_zz_and_zero_lateral_stress_in_uniaxial_stress) {
  const ElasticMaterial m = homalite();
  const ElasticStiffness C = stiffness(m, PlaneMode::stress);
  EXPECT_EQ(C.cz, 0.0);
  const double exx = 1e-3, eyy = -m.poisson_ratio * exx;  // uniaxial stress
  EXPECT_NEAR(C.c12 * exx + C.c11 * eyy, 0.0, 1e-3);
  EXPECT_NEAR(C.c11 * exx + C.c12 * eyy, m.youngs_modulus * exx, 1e-3);
}

// The particles store the stress only: strain, sigma_zz and tr eps are recovered from it
// (strain_of, stress_zz, strain_trace). Each must invert C : eps for any strain, in both plane
// modes and for nu across its range, and agree with the compliance of prestressed_state
// (Hooke's law written in E and nu, an independent form).
TEST(Elastic, strain_and_sigma_zz_recovered_from_the_in_plane_stress_invert_C) {
  for (double nu : {-0.3, 0.0, 0.25, 0.34, 0.49}) {
    const ElasticMaterial m{"m", 3.1e9, nu, 1000.0};
    for (PlaneMode mode : {PlaneMode::strain, PlaneMode::stress}) {
      const ElasticStiffness C = stiffness(m, mode);
      EXPECT_NEAR(C.c11 - C.c12, 2 * C.mu, 1e-9 * C.c11) << nu;  // isotropy
      const double e[3] = {1.3e-3, -7e-4, 4.1e-4};             // exx, eyy, exy
      const double sxx = C.c11 * e[0] + C.c12 * e[1], syy = C.c12 * e[0] + C.c11 * e[1];
      const double sxy = 2 * C.mu * e[2];
      double exx, eyy, exy;
      strain_of(C, sxx, syy, sxy, exx, eyy, exy);
      EXPECT_NEAR(exx, e[0], 1e-15) << nu;
      EXPECT_NEAR(eyy, e[1], 1e-15) << nu;
      EXPECT_NEAR(exy, e[2], 1e-15) << nu;
      EXPECT_NEAR(strain_trace(C, sxx, syy), e[0] + e[1], 1e-15) << nu;
      EXPECT_NEAR(stress_zz(C, sxx, syy), C.cz * (e[0] + e[1]), 1e-9 * std::fabs(sxx)) << nu;
      const ElasticState ps = prestressed_state(m, mode, sxx, syy, sxy);
      EXPECT_NEAR(ps.exx, exx, 1e-15) << nu;
      EXPECT_NEAR(ps.eyy, eyy, 1e-15) << nu;
      EXPECT_NEAR(ps.exy, exy, 1e-15) << nu;
      EXPECT_NEAR(ps.szz, stress_zz(C, sxx, syy), 1e-9 * std::fabs(sxx)) << nu;
    }
  }
}
