// Tests of fracture/branching_criterion.hpp (Yoffe's criterion from Freund's running-tip field):
//  - at v -> 0 the angular functions are Williams' mode-I field (to O(v^2));
//  - at every speed: Sigma_yy(0) = 1 (K_I's definition) and the faces (theta = pi) are free;
//  - the Rayleigh speed of a Poisson solid (nu = 1/4) is 0.9194 c_s (the classical root);
//  - Yoffe's speed: the largest hoop stress leaves the axis near 0.6 c_s (Yoffe 1951, as Freund
//    1990 §4.3 quotes it) and the off-axis angle grows with the speed, below it the decision
//    is "straight on"; the angle is where the hoop stress is largest over a fine scan.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fracture/branching_criterion.hpp"

namespace rupture {
namespace {

constexpr double kPi = std::numbers::pi;

WaveSpeeds plane_strain(double nu) {
  WaveSpeeds w{};
  w.dilatational = std::sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu)), w.shear = 1.0;
  return w;
}

TEST(BranchingCriterion, SlowTipIsTheWilliamsField) {
  const WaveSpeeds w = plane_strain(0.25);
  for (double t = -3.0; t <= 3.0; t += 0.25) {
    const AngularStress a = running_mode_one(t, 1e-3, w);
    const double c = std::cos(0.5 * t), s = std::sin(0.5 * t), s3 = std::sin(1.5 * t), c3 = std::cos(1.5 * t);
    EXPECT_NEAR(a.xx, c * (1.0 - s * s3), 1e-5) << t;
    EXPECT_NEAR(a.yy, c * (1.0 + s * s3), 1e-5) << t;
    EXPECT_NEAR(a.xy, c * s * c3, 1e-5) << t;
  }
}

TEST(BranchingCriterion, NormalisedAndFreeFacesAtEverySpeed) {
  const WaveSpeeds w = plane_strain(0.2);
  const double cR = rayleigh_speed(w);
  for (const double f : {0.1, 0.4, 0.7, 0.9}) {
    const double v = f * cR;
    EXPECT_NEAR(running_mode_one(0.0, v, w).yy, 1.0, 1e-12) << f;
    EXPECT_NEAR(running_mode_one(0.0, v, w).xy, 0.0, 1e-12) << f;
    const AngularStress face = running_mode_one(kPi - 1e-9, v, w);
    EXPECT_NEAR(face.yy, 0.0, 1e-8) << f;
    EXPECT_NEAR(face.xy, 0.0, 1e-8) << f;
    // The field is even in theta for sigma_xx, sigma_yy and odd for sigma_xy (mode I).
    EXPECT_NEAR(running_mode_one(0.8, v, w).xx, running_mode_one(-0.8, v, w).xx, 1e-12);
    EXPECT_NEAR(running_mode_one(0.8, v, w).xy, -running_mode_one(-0.8, v, w).xy, 1e-12);
  }
}

TEST(BranchingCriterion, RayleighSpeedOfAPoissonSolid) {
  EXPECT_NEAR(rayleigh_speed(plane_strain(0.25)), 0.91940, 1e-4);
}

TEST(BranchingCriterion, YoffeSpeedAndTheOffAxisMaximum) {
  const WaveSpeeds w = plane_strain(0.25);
  const double vY = yoffe_speed(w), cR = rayleigh_speed(w);
  EXPECT_GT(vY, 0.58);  // "about 0.6 c_s"
  EXPECT_LT(vY, 0.66);
  EXPECT_FALSE(decide_branching(0.98 * vY, w).branch);
  EXPECT_EQ(largest_hoop_angle(0.98 * vY, w), 0.0);
  double last = 0.0;
  for (const double f : {1.02, 1.1, 1.2, 1.3}) {
    const double v = f * vY;
    ASSERT_LT(v, cR);
    const BranchDecision d = decide_branching(v, w);
    ASSERT_TRUE(d.branch) << f;
    EXPECT_GT(d.angle, last) << f;
    last = d.angle;
    // The angle is the hoop stress maximum over a fine scan of [0, pi).
    double best = -1e300, at = 0.0;
    for (int i = 0; i <= 100000; ++i) {
      const double t = kPi * i / 100000.0;
      const double s = running_hoop(t, v, w);
      if (s > best) best = s, at = t;
    }
    EXPECT_NEAR(d.angle, at, 1e-4) << f;
    EXPECT_GT(running_hoop(d.angle, v, w), running_hoop(0.0, v, w));
  }
  EXPECT_FALSE(decide_branching(cR, w).branch);  // at and above c_R the field is not a crack's
}

}  // namespace
}  // namespace rupture
