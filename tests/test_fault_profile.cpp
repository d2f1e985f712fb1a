// Rate-and-state parameters tabulated along a fault (cohesive/fault_profile.hpp) and the point
// laws the interface resolves from them and from the taper (cohesive/interface.hpp): the
// interpolation, the re-balanced initial state, every Gauss point's law against the table at
// its position, and the taper's point laws against RateStateFriction::at.
#include <gtest/gtest.h>

#include <cmath>

#include "cohesive/interface.hpp"

using namespace rupture;

namespace {
RateStateFriction tpv101() {
  RateStateFriction f;
  f.a = 0.008, f.b = 0.012, f.dc = 0.02, f.v0 = 1e-6, f.f0 = 0.6, f.v_init = 1e-12;
  f.normal_stiffness = f.stick_stiffness = 1.9e9;
  f.tn0 = -120e6, f.tt0 = 75e6;
  EXPECT_TRUE(f.initialize_state());
  return f;
}
ProfileTable table(std::vector<double> at, std::vector<double> value) {
  ProfileTable t;
  t.at = std::move(at), t.value = std::move(value);
  return t;
}
InterfaceSpec fault(const RateStateFriction& law) {
  InterfaceSpec is;
  is.y = 0.0, is.start = -20000.0, is.end = 20000.0, is.segments = 40;
  is.law = law;
  return is;
}
}  // namespace

TEST(FaultProfile, interpolates_linearly_and_holds_the_ends) {
  const ProfileTable t = table({-1000.0, 0.0, 2000.0}, {0.02, 0.01, 0.03});
  EXPECT_DOUBLE_EQ(t(-5000.0), 0.02);
  EXPECT_DOUBLE_EQ(t(-1000.0), 0.02);
  EXPECT_DOUBLE_EQ(t(-500.0), 0.015);
  EXPECT_DOUBLE_EQ(t(0.0), 0.01);
  EXPECT_DOUBLE_EQ(t(500.0), 0.015);
  EXPECT_DOUBLE_EQ(t(2000.0), 0.03);
  EXPECT_DOUBLE_EQ(t(9000.0), 0.03);
}

TEST(FaultProfile, the_law_at_a_point_balances_the_initial_traction) {
  RateStateProfile p;
  p.along = ProfileAxis::x;
  p.a = table({0.0, 10000.0}, {0.008, 0.016});
  p.dc = table({0.0, 10000.0}, {0.02, 0.04});
  const RateStateFriction base = tpv101();
  const RateStateFriction l = p.apply(base, 2500.0, 0.0, 12345.0);
  EXPECT_DOUBLE_EQ(l.a, 0.010);
  EXPECT_DOUBLE_EQ(l.dc, 0.025);
  EXPECT_EQ(l.b, base.b);  // untabulated: kept
  EXPECT_NEAR(-l.tn0 * l.friction(l.v_init, l.psi_init), l.tt0, 1e-6);
  EXPECT_NE(l.psi_init, base.psi_init);  // re-balanced with the new a
  // along s and y take those coordinates.
  p.along = ProfileAxis::s;
  EXPECT_DOUBLE_EQ(p.apply(base, 2500.0, 0.0, 5000.0).a, 0.012);
  p.along = ProfileAxis::y;
  EXPECT_DOUBLE_EQ(p.apply(base, 2500.0, 7500.0, 0.0).a, 0.014);
}

TEST(FaultProfile, every_gauss_point_gets_the_table_at_its_position) {
  InterfaceSpec is = fault(tpv101());
  is.profile.along = ProfileAxis::x;
  is.profile.a = table({-20000.0, 20000.0}, {0.004, 0.020});
  const CohesiveInterface c = make_interface(is);
  ASSERT_EQ(c.gp_point_law.size(), c.num_segments() * CohesiveInterface::kGauss);
  ASSERT_EQ(c.node_point_law.size(), c.num_nodes());
  const auto& base = std::get<RateStateFriction>(is.law);
  for (std::size_t s = 0; s < c.num_segments(); ++s)
    for (int q = 0; q < CohesiveInterface::kGauss; ++q) {
      const double xi = CohesiveInterface::kGaussXi[q];
      const double x = 0.5 * (1.0 - xi) * c.x0[s] + 0.5 * (1.0 + xi) * c.x0[s + 1];
      const std::size_t i = s * CohesiveInterface::kGauss + std::size_t(q);
      const double a = gauss_point_law(c, base, i).a;
      ASSERT_NEAR(a, 0.012 + 0.008 * x / 20000.0, 1e-15) << s << " " << q;
    }
  for (std::size_t k = 0; k < c.num_nodes(); ++k)
    ASSERT_NEAR(node_law_of(c, base, k).a, 0.012 + 0.008 * c.x0[k] / 20000.0, 1e-15);
}

TEST(FaultProfile, taper_point_laws_are_the_law_at_each_point) {
  RateStateFriction law = tpv101();
  law.taper.on = true;
  law.taper.half_width = 8000.0, law.taper.width = 4000.0, law.taper.a = 0.016;
  const InterfaceSpec is = fault(law);
  const CohesiveInterface c = make_interface(is);
  ASSERT_FALSE(c.gp_point_law.empty());
  for (std::size_t s = 0; s < c.num_segments(); ++s)
    for (int q = 0; q < CohesiveInterface::kGauss; ++q) {
      const double xi = CohesiveInterface::kGaussXi[q];
      const double Na = 0.5 * (1.0 - xi), Nb = 0.5 * (1.0 + xi);
      const double x = Na * c.x0[s] + Nb * c.x0[s + 1], y = Na * c.y0[s] + Nb * c.y0[s + 1];
      const RateStateFriction& p = gauss_point_law(c, law, s * CohesiveInterface::kGauss + std::size_t(q));
      const RateStateFriction want = law.at(x, y);
      // The same position as the step's: equal to round-off (this file may be compiled with
      // other flags than the library's, where a*b+c contracts to an FMA or not: 4 ulps).
      ASSERT_DOUBLE_EQ(p.a, want.a);
      ASSERT_DOUBLE_EQ(p.psi_init, want.psi_init);
      ASSERT_FALSE(p.taper.on);
    }
  // Without taper or profile no point laws: the interface's own (or its stretches').
  EXPECT_TRUE(make_interface(fault(tpv101())).gp_point_law.empty());
}
