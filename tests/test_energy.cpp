// Tests of solver/energy.hpp: E14's strain energy is the work the stresses have done (theory E14).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "material/elastic.hpp"
#include "solver/energy.hpp"
#include "solver/step.hpp"
#include "verification/wave_helpers.hpp"

using namespace rupture;

namespace {
const ElasticMaterial kHomalite{"homalite", 5.2e9, 0.34, 1246.0};
}

// Uniaxial strain eps_xx from 0 to e in n increments: sigma_xx = c11 eps, sigma_yy = c12 eps and
// V = V0 (1 + eps). The work is int V sigma : d eps = V0 c11 (e^2/2 + e^3/3); the midpoint sum
// is exact for the e^2 term and off by V0 c11 e^3 / (12 n^2) for the other. 1/2 V0 sigma : eps
// (the measure this replaced) gives only V0 c11 e^2 / 2.
TEST(Energy, stress_work_integrates_the_current_volume_times_stress_power) {
  const ElasticStiffness C = stiffness(kHomalite, PlaneMode::strain);
  const double V0 = 2.5e-7, e = -0.04;
  const int n = 400;
  double exx = 0, sxx = 0, syy = 0, W = 0;
  for (int k = 0; k < n; ++k) {
    const double d = e / n, dsxx = C.c11 * d, dsyy = C.c12 * d;
    W += stress_work(V0, exx, sxx, syy, 0.0, d, 0.0, 0.0, dsxx, dsyy, 0.0);
    exx += d, sxx += dsxx, syy += dsyy;
  }
  const double exact = V0 * C.c11 * (e * e / 2 + e * e * e / 3);
  const double half_sigma_eps = 0.5 * V0 * sxx * exx;
  std::printf("uniaxial strain %.2f: accumulated %.10e J/m, exact %.10e, 1/2 V0 sigma:eps %.10e (%+.3f %%)\n",
              e, W, exact, half_sigma_eps, 100 * (half_sigma_eps / exact - 1));
  EXPECT_NEAR(W, exact, 2 * std::fabs(V0 * C.c11 * e * e * e) / (12.0 * n * n));
  EXPECT_GT(std::fabs(half_sigma_eps - exact), 0.02 * exact);  // (2/3)|e| = 2.7 %: the test can tell
  // Shear enters as 2 sigma_xy d eps_xy (tensor components) and does not change the volume.
  double exy = 0, sxy = 0, Ws = 0;
  for (int k = 0; k < n; ++k) {
    const double d = 0.01 / n;
    Ws += stress_work(V0, 0.0, 0.0, 0.0, sxy, 0.0, 0.0, d, 0.0, 0.0, 2 * C.mu * d);
    exy += d, sxy += 2 * C.mu * d;
  }
  EXPECT_NEAR(Ws, V0 * 2 * C.mu * exy * exy, 1e-12 * Ws);
}

// A strip pushed at one end at V = 100 m/s (compression V / c_D = 3.9 %): the push's work goes
// into kinetic and strain energy (half each behind the front). With the strain energy counted
// as 1/2 V0 sigma : eps the balance is off by about (2/3) |eps| of the strain energy, 1.3 % of
// the work; the stress power the forces actually store closes it to the scheme's own error.
TEST(Energy, balance_of_a_strongly_compressed_strip_closes_with_the_stored_stress_work) {
  const double h = 0.1e-3, V = 100.0, length = 0.03, end = 8e-6;
  State s = make_state(test::strip_1d(length, 4 * h, h, "x", V, end));
  while (s.time < end) step(s);
  const Particles& P = s.particles;
  const double half_sigma_eps = strain_energy(P, s.stiffness);
  const double K = kinetic_energy(P), W = s.strain_work, work = s.external_work;
  const double err = (K + W - work) / work, err_old = (K + half_sigma_eps - work) / work;
  std::printf("work %.6e J/m: kinetic %.6e, stored stress work %.6e (balance %+.3f %%), "
              "1/2 V0 sigma:eps %.6e (balance %+.3f %%)\n",
              work, K, W, 100 * err, half_sigma_eps, 100 * err_old);
  // Measured: -0.345 % (the scheme's own error, FLIP's projection of the front) against
  // +1.045 % with 1/2 V0 sigma:eps.
  EXPECT_LT(std::fabs(err), 0.005);
  // The two measures differ by the volume change: (2/3)|eps| of the strain energy for a uniform
  // plateau at eps = -V/c_D (2.63 %; measured 2.80 %: the ringing behind the front makes the
  // mean of eps^3 exceed the cube of the mean).
  const double eps = V / wave_speeds(kHomalite, PlaneMode::strain).dilatational;
  EXPECT_NEAR(half_sigma_eps / W - 1, 2.0 / 3.0 * eps, 0.1 * 2.0 / 3.0 * eps);
}
