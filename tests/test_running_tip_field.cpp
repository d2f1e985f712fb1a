// Tests of fracture/running_tip_field.hpp: the running tip's fields are the steady elastodynamic
// solution they claim to be, whatever the speed below c_R, in both plane modes.
//  - the gradients are those of the displacement, u_i,11 that of u_i,1 (central differences);
//  - the steady equation of motion div sigma = rho v^2 u_,11 (central differences of the stress);
//  - the faces are traction-free and open (mode I) or slide (mode II) as a positive K says;
//    straight ahead sigma_22 (mode I), sigma_12 (mode II) is 1 / sqrt(2 pi r);
//  - mode I's stress is Freund's eq. 4.3.11 as fracture/branching_criterion.hpp writes it;
//  - as v -> 0 the fields become Williams' (fracture/near_tip_field.hpp);
//  - the contour J of the field (with its kinetic energy, u_dot = -v u_,1) is
//    (A_I K_I^2 + A_II K_II^2) / E' with E' from E and nu (not from the wave speeds).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fracture/branching_criterion.hpp"
#include "fracture/near_tip_field.hpp"
#include "fracture/running_tip_field.hpp"
#include "material/elastic.hpp"

namespace rupture {
namespace {

const ElasticMaterial kHomalite{"homalite", 5.2e9, 0.34, 1246.0};
constexpr double kPi = std::numbers::pi;

struct Both {
  RunningTipField f[2];
};
Both at(double x1, double x2, double v, double mu, const WaveSpeeds& w) {
  Both b;
  running_tip_fields(x1, x2, v, mu, w, b.f[0], b.f[1]);
  return b;
}

TEST(RunningTipField, gradients_and_the_steady_equation_of_motion) {
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    const WaveSpeeds w = wave_speeds(kHomalite, plane);
    const double mu = stiffness(kHomalite, plane).mu, rho = kHomalite.density;
    for (double frac : {0.1, 0.5, 0.9}) {
      const double v = frac * w.rayleigh, h = 1e-7, r = 1e-3;
      double inertia = 0.0;  // the largest |rho v^2 u_,11| against |sigma| / r
      for (double th = -2.9; th <= 2.9; th += 0.3) {
        const double x = r * std::cos(th), y = r * std::sin(th);
        const Both c = at(x, y, v, mu, w), xp = at(x + h, y, v, mu, w), xm = at(x - h, y, v, mu, w),
                   yp = at(x, y + h, v, mu, w), ym = at(x, y - h, v, mu, w);
        for (int k = 0; k < 2; ++k) {
          const NearTipField& f = c.f[k].f;
          const double g = std::fabs(f.u1_1) + std::fabs(f.u2_1) + std::fabs(f.u1_2) + std::fabs(f.u2_2);
          EXPECT_NEAR((xp.f[k].f.u1 - xm.f[k].f.u1) / (2 * h), f.u1_1, 1e-6 * g) << frac << " " << th;
          EXPECT_NEAR((xp.f[k].f.u2 - xm.f[k].f.u2) / (2 * h), f.u2_1, 1e-6 * g);
          EXPECT_NEAR((yp.f[k].f.u1 - ym.f[k].f.u1) / (2 * h), f.u1_2, 1e-6 * g);
          EXPECT_NEAR((yp.f[k].f.u2 - ym.f[k].f.u2) / (2 * h), f.u2_2, 1e-6 * g);
          const double g2 = g / r;
          EXPECT_NEAR((xp.f[k].f.u1_1 - xm.f[k].f.u1_1) / (2 * h), c.f[k].u1_11, 1e-6 * g2);
          EXPECT_NEAR((xp.f[k].f.u2_1 - xm.f[k].f.u2_1) / (2 * h), c.f[k].u2_11, 1e-6 * g2);
          // div sigma = rho v^2 u_,11, against the size of one gradient term (|sigma| / r).
          const double sg = (std::fabs(f.s11) + std::fabs(f.s22) + std::fabs(f.s12)) / r;
          const double div1 = (xp.f[k].f.s11 - xm.f[k].f.s11) / (2 * h) + (yp.f[k].f.s12 - ym.f[k].f.s12) / (2 * h);
          const double div2 = (xp.f[k].f.s12 - xm.f[k].f.s12) / (2 * h) + (yp.f[k].f.s22 - ym.f[k].f.s22) / (2 * h);
          EXPECT_NEAR(div1, rho * v * v * c.f[k].u1_11, 1e-6 * sg) << "mode " << k << " v/cR " << frac;
          EXPECT_NEAR(div2, rho * v * v * c.f[k].u2_11, 1e-6 * sg) << "mode " << k << " v/cR " << frac;
          inertia = std::max(inertia, rho * v * v * (std::fabs(c.f[k].u1_11) + std::fabs(c.f[k].u2_11)) / sg);
        }
      }
      // Not a static balance: at 0.9 c_R the inertia is most of the stress gradient somewhere.
      if (frac == 0.9) {
        EXPECT_GT(inertia, 0.5);
      }
    }
  }
}

TEST(RunningTipField, faces_are_free_and_the_field_ahead_has_unit_intensity) {
  const WaveSpeeds w = wave_speeds(kHomalite, PlaneMode::strain);
  const double mu = stiffness(kHomalite, PlaneMode::strain).mu;
  for (double frac : {0.05, 0.3, 0.6, 0.95}) {
    const double v = frac * w.rayleigh, r = 2e-3, s = 1.0 / std::sqrt(2.0 * kPi * r);
    const Both ahead = at(r, 0.0, v, mu, w);
    EXPECT_NEAR(ahead.f[0].f.s22, s, 1e-12 * s);
    EXPECT_NEAR(ahead.f[0].f.s12, 0.0, 1e-12 * s);
    EXPECT_NEAR(ahead.f[1].f.s12, s, 1e-12 * s);
    EXPECT_NEAR(ahead.f[1].f.s22, 0.0, 1e-12 * s);
    for (double side : {1.0, -1.0}) {
      const Both face = at(-r, side * 1e-15, v, mu, w);
      for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(face.f[k].f.s22, 0.0, 1e-9 * s) << frac;
        EXPECT_NEAR(face.f[k].f.s12, 0.0, 1e-9 * s) << frac;
      }
      EXPECT_GT(side * face.f[0].f.u2, 0.0);  // mode I opens
      EXPECT_NEAR(face.f[0].f.u1, at(-r, -side * 1e-15, v, mu, w).f[0].f.u1, 1e-12 * std::fabs(face.f[0].f.u2));
      EXPECT_GT(side * face.f[1].f.u1, 0.0);  // mode II: the upper face slides ahead
    }
  }
}

TEST(RunningTipField, mode_one_stress_is_freunds) {
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    const WaveSpeeds w = wave_speeds(kHomalite, plane);
    const double mu = stiffness(kHomalite, plane).mu;
    for (double frac : {0.2, 0.7, 0.9})
      for (double th = -3.0; th <= 3.0; th += 0.25) {
        const double v = frac * w.rayleigh, r = 1.3e-3, s = 1.0 / std::sqrt(2.0 * kPi * r);
        const AngularStress a = running_mode_one(th, v, w);
        const Both b = at(r * std::cos(th), r * std::sin(th), v, mu, w);
        EXPECT_NEAR(b.f[0].f.s11, s * a.xx, 1e-11 * s) << frac << " " << th;
        EXPECT_NEAR(b.f[0].f.s22, s * a.yy, 1e-11 * s) << frac << " " << th;
        EXPECT_NEAR(b.f[0].f.s12, s * a.xy, 1e-11 * s) << frac << " " << th;
      }
  }
}

TEST(RunningTipField, a_slow_tip_has_the_williams_field) {
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    const WaveSpeeds w = wave_speeds(kHomalite, plane);
    const double mu = stiffness(kHomalite, plane).mu, kappa = kolosov_kappa(kHomalite.poisson_ratio, plane);
    const double v = 2.0 * kRunningTipSpeed * w.shear;
    for (double th = -3.0; th <= 3.0; th += 0.2) {
      const double r = 1e-3, x = r * std::cos(th), y = r * std::sin(th);
      const Both b = at(x, y, v, mu, w);
      NearTipField st[2];
      williams_fields(x, y, mu, kappa, st[0], st[1]);
      for (int k = 0; k < 2; ++k) {
        const double s = 1.0 / std::sqrt(2.0 * kPi * r), g = s / mu, u = g * r;
        EXPECT_NEAR(b.f[k].f.s11, st[k].s11, 1e-5 * s) << k << " " << th;
        EXPECT_NEAR(b.f[k].f.s22, st[k].s22, 1e-5 * s);
        EXPECT_NEAR(b.f[k].f.s12, st[k].s12, 1e-5 * s);
        EXPECT_NEAR(b.f[k].f.u1, st[k].u1, 1e-5 * u);
        EXPECT_NEAR(b.f[k].f.u2, st[k].u2, 1e-5 * u);
        EXPECT_NEAR(b.f[k].f.u1_2, st[k].u1_2, 1e-5 * g);
        EXPECT_NEAR(b.f[k].f.u2_1, st[k].u2_1, 1e-5 * g);
      }
    }
    const RunningTipFactors a = running_tip_factors(v, w);
    EXPECT_NEAR(a.A_I, 1.0, 1e-5);
    EXPECT_NEAR(a.A_II, 1.0, 1e-5);
  }
}

// J = integral over a circle of [(W + T) n_1 - sigma_ij n_j u_i,1] ds, T = rho v^2 u_i,1 u_i,1 / 2.
double contour_J(double KI, double KII, double v, double mu, double rho, const WaveSpeeds& w, double r) {
  const int n = 20000;
  double J = 0.0;
  for (int i = 0; i < n; ++i) {
    const double th = -kPi + (i + 0.5) * 2.0 * kPi / n, n1 = std::cos(th), n2 = std::sin(th);
    const Both b = at(r * n1, r * n2, v, mu, w);
    const NearTipField &a = b.f[0].f, &c = b.f[1].f;
    const double s11 = KI * a.s11 + KII * c.s11, s22 = KI * a.s22 + KII * c.s22, s12 = KI * a.s12 + KII * c.s12;
    const double u11 = KI * a.u1_1 + KII * c.u1_1, u12 = KI * a.u1_2 + KII * c.u1_2;
    const double u21 = KI * a.u2_1 + KII * c.u2_1, u22 = KI * a.u2_2 + KII * c.u2_2;
    const double W = 0.5 * (s11 * u11 + s22 * u22 + s12 * (u12 + u21));
    const double T = 0.5 * rho * v * v * (u11 * u11 + u21 * u21);
    J += ((W + T) * n1 - (s11 * n1 + s12 * n2) * u11 - (s12 * n1 + s22 * n2) * u21) * r * 2.0 * kPi / n;
  }
  return J;
}

TEST(RunningTipField, energy_release_rate_is_freunds) {
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    const WaveSpeeds w = wave_speeds(kHomalite, plane);
    const double mu = stiffness(kHomalite, plane).mu, rho = kHomalite.density, nu = kHomalite.poisson_ratio;
    const double Ep = plane == PlaneMode::strain ? kHomalite.youngs_modulus / (1.0 - nu * nu) : kHomalite.youngs_modulus;
    for (double frac : {0.1, 0.4, 0.7, 0.9}) {
      const double v = frac * w.rayleigh;
      const RunningTipFactors A = running_tip_factors(v, w);
      EXPECT_GT(A.A_I, 1.0);  // a running tip releases more per K^2 than a stationary one
      EXPECT_GT(A.A_II, 1.0);
      for (double r : {1e-3, 7e-3}) {
        const double KI = 1e6, KII = 0.6e6;
        const double J = contour_J(KI, KII, v, mu, rho, w, r);
        EXPECT_NEAR(J, (A.A_I * KI * KI + A.A_II * KII * KII) / Ep, 2e-4 * J) << frac << " " << r;
        EXPECT_NEAR(contour_J(KI, 0.0, v, mu, rho, w, r), A.A_I * KI * KI / Ep, 2e-4 * J);
      }
    }
  }
}

}  // namespace
}  // namespace rupture
