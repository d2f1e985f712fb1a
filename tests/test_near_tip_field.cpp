// Tests of fracture/near_tip_field.hpp: the Williams fields are a consistent elastic solution.
//  - the stress equals C : sym(grad u) (stress and displacement forms agree), both plane modes;
//  - the gradient is that of the displacement (central differences);
//  - equilibrium div sigma = 0 (central differences of the stress);
//  - the crack faces (theta = +-pi) are traction-free and open as the mode says;
//  - the stresses ahead of the tip and around it are Anderson's Table 2.1 forms evaluated with
//    sin and cos of theta / 2 and 3 theta / 2 directly (the code derives the latter by the
//    triple-angle identities, both modes from one sine and cosine).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fracture/near_tip_field.hpp"
#include "material/elastic.hpp"

namespace rupture {
namespace {

constexpr CrackMode kModes[] = {CrackMode::opening, CrackMode::sliding};

TEST(NearTipField, stress_is_stiffness_times_strain_in_both_plane_modes) {
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    const ElasticMaterial mat{"homalite", 5.2e9, 0.34, 1246.0};
    const ElasticStiffness C = stiffness(mat, plane);
    const double kappa = kolosov_kappa(mat.poisson_ratio, plane);
    for (CrackMode mode : kModes)
      for (double th = -3.0; th <= 3.0; th += 0.25) {
        const double r = 1.7e-3;
        const NearTipField f = williams_field(mode, r * std::cos(th), r * std::sin(th), C.mu, kappa);
        const double exx = f.u1_1, eyy = f.u2_2, exy = 0.5 * (f.u1_2 + f.u2_1);
        const double scale = 1.0 / std::sqrt(2.0 * std::numbers::pi * r);
        EXPECT_NEAR(C.c11 * exx + C.c12 * eyy, f.s11, 1e-12 * scale) << th;
        EXPECT_NEAR(C.c12 * exx + C.c11 * eyy, f.s22, 1e-12 * scale) << th;
        EXPECT_NEAR(2.0 * C.mu * exy, f.s12, 1e-12 * scale) << th;
      }
  }
}

TEST(NearTipField, gradient_is_that_of_the_displacement_and_stress_is_in_equilibrium) {
  const double mu = 2e9, kappa = 1.64, h = 1e-7;
  for (CrackMode mode : kModes)
    for (double th = -2.9; th <= 2.9; th += 0.3) {
      const double x = 1e-3 * std::cos(th), y = 1e-3 * std::sin(th);
      const NearTipField f = williams_field(mode, x, y, mu, kappa);
      const NearTipField xp = williams_field(mode, x + h, y, mu, kappa), xm = williams_field(mode, x - h, y, mu, kappa);
      const NearTipField yp = williams_field(mode, x, y + h, mu, kappa), ym = williams_field(mode, x, y - h, mu, kappa);
      const double g = std::fabs(f.u1_1) + std::fabs(f.u2_1) + std::fabs(f.u1_2) + std::fabs(f.u2_2);
      EXPECT_NEAR((xp.u1 - xm.u1) / (2 * h), f.u1_1, 1e-6 * g);
      EXPECT_NEAR((xp.u2 - xm.u2) / (2 * h), f.u2_1, 1e-6 * g);
      EXPECT_NEAR((yp.u1 - ym.u1) / (2 * h), f.u1_2, 1e-6 * g);
      EXPECT_NEAR((yp.u2 - ym.u2) / (2 * h), f.u2_2, 1e-6 * g);
      // div sigma = 0, against the size of one gradient term (|sigma| / r).
      const double sg = (std::fabs(f.s11) + std::fabs(f.s22) + std::fabs(f.s12)) / 1e-3;
      EXPECT_NEAR((xp.s11 - xm.s11) / (2 * h) + (yp.s12 - ym.s12) / (2 * h), 0.0, 1e-6 * sg);
      EXPECT_NEAR((xp.s12 - xm.s12) / (2 * h) + (yp.s22 - ym.s22) / (2 * h), 0.0, 1e-6 * sg);
    }
}

TEST(NearTipField, faces_are_traction_free_and_open_by_the_mode) {
  const double mu = 2e9, kappa = 1.64, r = 1e-3, e = 1e-12;
  for (CrackMode mode : kModes) {
    const NearTipField up = williams_field(mode, -r, e, mu, kappa);
    const NearTipField lo = williams_field(mode, -r, -e, mu, kappa);
    const double scale = 1.0 / std::sqrt(2.0 * std::numbers::pi * r);
    EXPECT_NEAR(up.s22, 0.0, 1e-6 * scale);
    EXPECT_NEAR(up.s12, 0.0, 1e-6 * scale);
    // Face jump: mode I opens (u2 up - u2 down = (kappa + 1) / mu sqrt(r / 2 pi)), mode II slides.
    const double jump = (kappa + 1.0) / mu * std::sqrt(r / (2.0 * std::numbers::pi));
    if (mode == CrackMode::opening) {
      EXPECT_NEAR(up.u2 - lo.u2, jump, 1e-6 * jump);
      EXPECT_NEAR(up.u1 - lo.u1, 0.0, 1e-6 * jump);
    } else {
      EXPECT_NEAR(up.u1 - lo.u1, jump, 1e-6 * jump);
      EXPECT_NEAR(up.u2 - lo.u2, 0.0, 1e-6 * jump);
    }
  }
}

TEST(NearTipField, stresses_are_andersons_table_at_every_angle) {
  const double mu = 2e9, kappa = 1.8, r = 2e-3, pi = std::numbers::pi;
  const double a = 1.0 / std::sqrt(2.0 * pi * r);
  for (int i = -24; i <= 24; ++i) {
    const double th = i == -24 ? -pi + 1e-12 : i * pi / 24.0;
    const double s = std::sin(0.5 * th), c = std::cos(0.5 * th), s3 = std::sin(1.5 * th), c3 = std::cos(1.5 * th);
    NearTipField I, II;
    williams_fields(r * std::cos(th), r * std::sin(th), mu, kappa, I, II);
    EXPECT_NEAR(I.s11, a * c * (1.0 - s * s3), 1e-13 * a) << th;
    EXPECT_NEAR(I.s22, a * c * (1.0 + s * s3), 1e-13 * a) << th;
    EXPECT_NEAR(I.s12, a * s * c * c3, 1e-13 * a) << th;
    EXPECT_NEAR(II.s11, -a * s * (2.0 + c * c3), 1e-13 * a) << th;
    EXPECT_NEAR(II.s22, a * s * c * c3, 1e-13 * a) << th;
    EXPECT_NEAR(II.s12, a * c * (1.0 - s * s3), 1e-13 * a) << th;
    // The one-mode call gives the same numbers.
    const NearTipField one = williams_field(CrackMode::sliding, r * std::cos(th), r * std::sin(th), mu, kappa);
    EXPECT_EQ(one.u1_2, II.u1_2);
    EXPECT_EQ(one.s11, II.s11);
  }
}

}  // namespace
}  // namespace rupture
