// Tests of fracture/growth_criterion.hpp against the Williams field's hoop stress:
//  - the maximum hoop stress direction is where sigma_thetatheta is largest over all angles
//    (a scan of the exact field) and where the shear tau_rtheta vanishes; K_eq is that maximum;
//  - pure mode II: theta_c = -70.53 degrees and K_eq = (2 / sqrt 3) K_II, the Erdogan-Sih ratio
//    K_IIc / K_Ic = sqrt(3) / 2;
//  - the thresholds of both criteria, the straight direction, and a closed tip that stays.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fracture/growth_criterion.hpp"

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
  // Faces pressed together (K_I < 0) do not grow, however large K_II.
  EXPECT_FALSE(decide_growth(law, -0.1 * K, 10.0 * K, E).grow);
  EXPECT_FALSE(decide_growth(GrowthLaw{}, K * 10.0, 0.0, E).grow);  // no criterion
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
