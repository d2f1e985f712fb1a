// Tests of fracture/growth_criterion.hpp against the Williams field's hoop stress:
//  - the maximum hoop stress direction is where sigma_thetatheta is largest over all angles
//    (a scan of the exact field) and where the shear tau_rtheta vanishes; K_eq is that maximum;
//  - pure mode II: theta_c = -70.53 degrees and K_eq = (2 / sqrt 3) K_II, the Erdogan-Sih ratio
//    K_IIc / K_Ic = sqrt(3) / 2;
//  - the thresholds of both criteria, the straight direction, and a closed tip that stays;
//  - the kinked crack's intensities are the Williams field's hoop and shear stress intensities
//    on the kink's line; a weak plane ahead: in pure mode II the crack stays on it iff its G_c
//    is below 3/4 of the bulk's (He & Hutchinson's competition with G(theta_c) / G_0 = 4/3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fracture/growth_criterion.hpp"
#include "fracture/j_integral.hpp"

namespace rupture {
namespace {

constexpr double kPi = std::numbers::pi;

// The shear stress intensity tau_rtheta sqrt(2 pi r) of the Williams field (Anderson, Fracture
// Mechanics, Table 2.1 and 2.2, polar components).
double shear_intensity(double KI, double KII, double t) {
  return 0.5 * std::cos(0.5 * t) * (KI * std::sin(t) + KII * (3.0 * std::cos(t) - 1.0));
}

TEST(GrowthCriterion, DirectionIsTheHoopStressMaximumOverEveryAngle) {
  GrowthLaw law;
  law.criterion = GrowthCriterion::max_hoop;
  law.toughness = 1.0;
  for (const double ratio : {0.0, 0.1, 0.5, 1.0, 2.0, 10.0, -0.5, -3.0}) {
    const double KI = 1.0, KII = ratio;
    const GrowthDecision d = decide_growth(law, KI, KII, 1.0);
    double best = -1e300, at = 0.0;
    for (int i = 0; i <= 200000; ++i) {
      const double t = -kPi + 2.0 * kPi * i / 200000.0;
      const double v = hoop_stress_intensity(KI, KII, t);
      if (v > best) best = v, at = t;
    }
    EXPECT_NEAR(d.angle, at, 1e-4) << "K_II/K_I = " << ratio;
    EXPECT_NEAR(d.driving, best, 1e-9 * std::max(1.0, best)) << ratio;
    EXPECT_NEAR(shear_intensity(KI, KII, d.angle), 0.0, 1e-12 * (1.0 + std::fabs(ratio))) << ratio;
  }
}

TEST(GrowthCriterion, PureModeTwoKinksAtMinus70Point5WithTheErdoganSihRatio) {
  GrowthLaw law;
  law.criterion = GrowthCriterion::max_hoop;
  law.toughness = 1.0;
  const double KII = 1.0;
  const GrowthDecision d = decide_growth(law, 1e-12, KII, 1.0);
  EXPECT_NEAR(d.angle * 180.0 / kPi, -70.5288, 1e-3);
  EXPECT_NEAR(d.driving, 2.0 / std::sqrt(3.0) * KII, 1e-9);
  // Mode I: straight ahead, K_eq = K_I, and the threshold is K_Ic.
  EXPECT_FALSE(decide_growth(law, 0.999, 0.0, 1.0).grow);
  const GrowthDecision m1 = decide_growth(law, 1.0, 0.0, 1.0);
  EXPECT_TRUE(m1.grow);
  EXPECT_EQ(m1.angle, 0.0);
  EXPECT_DOUBLE_EQ(m1.driving, 1.0);
  // Pressed shut (K_I < 0): the pure mode II tip's angle and K_eq, whatever the pressure.
  const GrowthDecision closed = decide_growth(law, -0.3, -KII, 1.0);
  EXPECT_TRUE(closed.grow);
  EXPECT_NEAR(closed.angle * 180.0 / kPi, 70.5288, 1e-3);
  EXPECT_NEAR(closed.driving, 2.0 / std::sqrt(3.0) * KII, 1e-9);
  EXPECT_FALSE(decide_growth(law, -0.3, -0.86 * KII, 1.0).grow);  // 2/sqrt3 0.86 = 0.993 < K_Ic
}

TEST(GrowthCriterion, EnergyThresholdStraightDirectionAndClosedTips) {
  GrowthLaw law;
  law.criterion = GrowthCriterion::energy;
  law.fracture_energy = 100.0;  // J/m^2
  const double E = 5e9;
  const double K = std::sqrt(100.0 * E);  // G = K^2 / E' = G_c exactly
  EXPECT_TRUE(decide_growth(law, K * 1.000001, 0.0, E).grow);
  EXPECT_FALSE(decide_growth(law, K * 0.999999, 0.0, E).grow);
  // Mixed mode: G sums both modes; the direction is the hoop stress one unless straight.
  const GrowthDecision m = decide_growth(law, 0.8 * K, 0.6 * K * 1.000001, E);
  EXPECT_TRUE(m.grow);
  EXPECT_LT(m.angle, -0.5);
  law.direction = GrowthDirection::straight;
  EXPECT_EQ(decide_growth(law, 0.8 * K, 0.6 * K, E).angle, 0.0);
  // Faces pressed together (K_I < 0): the closed flaw, read as K_I = 0. Its shear alone decides,
  // and it kinks as in pure mode II (-70.53 degrees for K_II > 0), whatever the pressure.
  law.direction = GrowthDirection::max_hoop;
  for (const double KI : {-0.01 * K, -0.5 * K, -5.0 * K}) {
    const GrowthDecision c = decide_growth(law, KI, K * 1.000001, E);
    EXPECT_TRUE(c.grow) << KI;
    EXPECT_NEAR(c.angle * 180.0 / std::numbers::pi, -70.5288, 1e-3) << KI;
    EXPECT_NEAR(c.driving, K * K * 1.000002 / E, 1e-9 * K * K / E) << KI;
    EXPECT_FALSE(decide_growth(law, KI, K * 0.999999, E).grow) << KI;
  }
  EXPECT_FALSE(decide_growth(law, -10.0 * K, 0.0, E).grow);  // pressed, no shear: nothing drives it
  EXPECT_FALSE(decide_growth(GrowthLaw{}, K * 10.0, 0.0, E).grow);  // no criterion
}

TEST(GrowthCriterion, KinkedIntensitiesAreTheWilliamsFieldOnTheKinksLine) {
  for (const double KII : {0.0, 0.3, 1.0, -2.0})
    for (int i = -17; i <= 17; ++i) {
      const double t = kPi * i / 18.0, KI = 1.0;
      const KinkIntensities k = kinked_intensities(KI, KII, t);
      EXPECT_NEAR(k.k_I, hoop_stress_intensity(KI, KII, t), 1e-12) << KII << " " << t;
      EXPECT_NEAR(k.k_II, shear_intensity(KI, KII, t), 1e-12) << KII << " " << t;
    }
  const KinkIntensities s = kinked_intensities(0.7, -0.2, 0.0);
  EXPECT_DOUBLE_EQ(s.k_I, 0.7);
  EXPECT_DOUBLE_EQ(s.k_II, -0.2);
}

TEST(GrowthCriterion, WeakPlaneInPureModeTwoHoldsTheCrackBelowThreeQuartersOfTheBulkToughness) {
  GrowthLaw law;
  law.criterion = GrowthCriterion::energy;
  law.fracture_energy = 100.0;  // J/m^2, the bulk's
  const double E = 5e9, KII = std::sqrt(110.0 * E);  // G_0 = 110 J/m^2; G(theta_c) = 146.7
  for (const double ratio : {0.5, 0.74, 0.76, 1.0}) {
    law.plane_fracture_energy = ratio * law.fracture_energy;
    const GrowthDecision d = decide_growth(law, 0.0, KII, E, CrackFront::open, true);
    EXPECT_TRUE(d.grow) << ratio;
    if (ratio < 0.75) {
      EXPECT_EQ(d.angle, 0.0) << ratio;
      EXPECT_NEAR(d.driving, 110.0, 1e-9);
      EXPECT_EQ(d.critical, law.plane_fracture_energy);
    } else {
      EXPECT_NEAR(d.angle * 180.0 / kPi, -70.5288, 1e-3) << ratio;
      EXPECT_NEAR(d.driving, 110.0 * 4.0 / 3.0, 1e-9);
      EXPECT_EQ(d.critical, law.fracture_energy);
    }
    // Off the plane, a kink at theta_c reads the G that made it kink and runs straight on; with
    // no kink (phi = 0) it kinks now, with the same G(theta_c).
    const double tc = -70.5288 * kPi / 180.0;
    const GrowthDecision off = decide_growth(law, -0.5 * KII, KII, E, CrackFront::open, false, tc);
    EXPECT_TRUE(off.grow);
    EXPECT_NEAR(off.angle, tc, 1e-5);
    EXPECT_NEAR(off.driving, 110.0 * 4.0 / 3.0, 1e-5);
    EXPECT_EQ(off.critical, 100.0);
    const GrowthDecision straight = decide_growth(law, -0.5 * KII, KII, E, CrackFront::open, false, 0.0);
    EXPECT_NEAR(straight.driving, 110.0 * 4.0 / 3.0, 1e-9);
    EXPECT_NEAR(straight.angle, tc, 1e-5);
  }
  // Below both thresholds: no growth; a shear crack pressed shut (K_I < 0) runs along the plane.
  law.plane_fracture_energy = 50.0;
  EXPECT_FALSE(decide_growth(law, 0.0, std::sqrt(49.0 * E), E, CrackFront::open, true).grow);
  const GrowthDecision closed = decide_growth(law, -0.1 * KII, KII, E, CrackFront::open, true);
  EXPECT_TRUE(closed.grow);
  EXPECT_EQ(closed.angle, 0.0);
  // Pressed shut with a plane as tough as the bulk: the closed flaw kinks as in pure mode II
  // (K_I read as 0; the faces' pressure is not a singular field).
  law.plane_fracture_energy = law.fracture_energy;
  const GrowthDecision wing = decide_growth(law, -3.0 * KII, KII, E, CrackFront::open, true);
  EXPECT_TRUE(wing.grow);
  EXPECT_NEAR(wing.angle * 180.0 / kPi, -70.5288, 1e-3);
  EXPECT_NEAR(wing.driving, 110.0 * 4.0 / 3.0, 1e-9);
  law.plane_fracture_energy = 50.0;
  // Mode I: both ways lie straight ahead; the weaker plane's threshold decides.
  const double KI = std::sqrt(60.0 * E);
  const GrowthDecision m1 = decide_growth(law, KI, 0.0, E, CrackFront::open, true);
  EXPECT_TRUE(m1.grow);
  EXPECT_EQ(m1.angle, 0.0);
  EXPECT_EQ(m1.critical, 50.0);
}

}  // namespace
}  // namespace rupture

namespace rupture {
namespace {

// The cohesive criterion reads the end segment through its law: a cohesive end grows once past
// the peak, never before, whatever K; a cut (no cohesion at the end) grows once pulled open.
TEST(GrowthCriterion, CohesiveGrowsPastThePeakOrFromAPulledCut) {
  GrowthLaw law;
  law.criterion = GrowthCriterion::cohesive;
  EXPECT_TRUE(decide_growth(law, 0.0, 0.0, 1.0, CrackFront::softening).grow);
  EXPECT_TRUE(decide_growth(law, -1e6, 0.0, 1.0, CrackFront::softening).grow);  // the law decides
  EXPECT_FALSE(decide_growth(law, 1e9, 1e9, 1.0, CrackFront::loading).grow);
  EXPECT_TRUE(decide_growth(law, 1.0, 0.0, 1.0, CrackFront::open).grow);
  EXPECT_FALSE(decide_growth(law, -1.0, 5.0, 1.0, CrackFront::open).grow);  // a closed cut
  EXPECT_FALSE(decide_growth(law, 0.0, 5.0, 1.0, CrackFront::open).grow);
  // The direction is the crack's rule as for the other criteria.
  const GrowthDecision d = decide_growth(law, 1e-12, 1.0, 1.0, CrackFront::softening);
  EXPECT_NEAR(d.angle * 180.0 / std::numbers::pi, -70.5288, 1e-3);
  law.direction = GrowthDirection::straight;
  EXPECT_EQ(decide_growth(law, 1e-12, 1.0, 1.0, CrackFront::softening).angle, 0.0);
}

}  // namespace
}  // namespace rupture

namespace rupture {
namespace {

// growth = "prescribed": a tip grows whenever its path plus one step is due by speed (t - start),
// so N calls at the step's interval grow N steps (a tip that runs at the speed), none before start.
TEST(GrowthCriterion, prescribed_tip_runs_at_its_speed) {
  GrowthLaw law;
  law.criterion = GrowthCriterion::prescribed;
  law.direction = GrowthDirection::straight;
  law.speed = 500.0, law.start = 1e-6;
  const double step = 0.1e-3, dt = 0.03e-6;  // a step every 0.2 us; 6.67 calls per step
  double grown = 0.0;
  for (double t = 0.0; t <= 5e-6 + 1e-12; t += dt) {
    const GrowthDecision d = decide_prescribed(law, 1e6, 0.3e6, grown, step, t);
    if (t < 1e-6) {
      EXPECT_FALSE(d.grow);
    }
    EXPECT_EQ(d.angle, 0.0);
    if (d.grow) grown += step;
    EXPECT_LE(grown, law.speed * std::max(t - law.start, 0.0) + 1e-15);    // never ahead of the schedule
    EXPECT_GT(grown + step, law.speed * std::max(t - law.start, 0.0) - dt * law.speed);  // nor a step behind
  }
  EXPECT_NEAR(grown, 2.0e-3, step);
  law.direction = GrowthDirection::max_hoop;
  EXPECT_NEAR(decide_prescribed(law, 1e6, 0.3e6, 0.0, step, 2e-6).angle, hoop_stress_angle(1e6, 0.3e6), 1e-15);
  EXPECT_FALSE(decide_growth(law, 1e9, 0.0, 1e9).grow);  // K does not move a prescribed tip
}

// The energy criterion of a running tip: G = (A_I K_I^2 + A_II K_II^2) / E' (Freund eq. 5.3.10).
TEST(GrowthCriterion, energy_of_a_running_tip_takes_the_speed_factors) {
  GrowthLaw law;
  law.criterion = GrowthCriterion::energy;
  law.fracture_energy = 100.0;
  const double Ep = 5e9, KI = 0.6e6, KII = 0.2e6;
  const RunningTipFactors A{1.5, 1.2};
  const GrowthDecision still = decide_growth(law, KI, KII, Ep);
  const GrowthDecision run = decide_growth(law, KI, KII, Ep, CrackFront::open, false, 0.0, A);
  EXPECT_DOUBLE_EQ(still.driving, (KI * KI + KII * KII) / Ep);
  EXPECT_DOUBLE_EQ(run.driving, (1.5 * KI * KI + 1.2 * KII * KII) / Ep);
  EXPECT_FALSE(still.grow);  // 80 J/m^2
  EXPECT_TRUE(run.grow);     // 113.6 J/m^2
}

}  // namespace
}  // namespace rupture
