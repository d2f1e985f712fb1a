// Tests of the Xu-Needleman law (SPEC E7, E8) against the SPEC's checks.
#include <gtest/gtest.h>

#include <cmath>

#include "cohesive/xu_needleman.hpp"

using namespace rupture;

namespace {
XuNeedleman spec_law() {
  XuNeedleman law;
  law.sigma_max = 24e6;
  law.tau_max = 24e6;
  law.delta_n = 0.4e-6;
  law.delta_t = std::sqrt(2.0 * std::exp(1.0)) * law.delta_n;
  law.q = 1.0;
  law.r = 0.0;
  return law;
}

// Integral of f over [a, b] by composite Simpson with n (even) panels.
template <class F>
double simpson(F f, double a, double b, int n = 20000) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
  return s * h / 3.0;
}
}  // namespace

TEST(XuNeedleman, spec_parameters_give_the_spec_energies) {
  const XuNeedleman law = spec_law();
  EXPECT_NEAR(law.delta_t, 0.9327e-6, 0.0001e-6);
  EXPECT_NEAR(law.phi_n(), 26.1, 0.05);
  EXPECT_NEAR(law.phi_t(), 26.1, 0.05);
  EXPECT_NEAR(law.phi_t() / law.phi_n(), 1.0, 1e-12);  // q = 1
}

TEST(XuNeedleman, normal_peak_is_sigma_max_at_delta_n) {
  const XuNeedleman law = spec_law();
  double best = 0, at = 0;
  for (double dn = 0; dn < 5 * law.delta_n; dn += 1e-4 * law.delta_n) {
    const double t = law.traction(dn, 0).normal;
    if (t > best) best = t, at = dn;
  }
  EXPECT_NEAR(best, law.sigma_max, 1e-6 * law.sigma_max);
  EXPECT_NEAR(at, law.delta_n, 2e-4 * law.delta_n);
}

TEST(XuNeedleman, tangential_peak_is_tau_max_at_delta_t_over_sqrt2) {
  const XuNeedleman law = spec_law();
  double best = 0, at = 0;
  for (double dt = 0; dt < 5 * law.delta_t; dt += 1e-4 * law.delta_t) {
    const double t = law.traction(0, dt).tangential;
    if (t > best) best = t, at = dt;
  }
  EXPECT_NEAR(best, law.tau_max, 1e-6 * law.tau_max);
  EXPECT_NEAR(at, law.delta_t / std::sqrt(2.0), 2e-4 * law.delta_t);
}

TEST(XuNeedleman, separation_work_equals_phi_in_pure_modes) {
  const XuNeedleman law = spec_law();
  const double wn = simpson([&](double d) { return law.traction(d, 0).normal; }, 0, 60 * law.delta_n);
  const double wt = simpson([&](double d) { return law.traction(0, d).tangential; }, 0, 12 * law.delta_t);
  EXPECT_NEAR(wn, law.phi_n(), 1e-6 * law.phi_n());
  EXPECT_NEAR(wt, law.phi_t(), 1e-6 * law.phi_t());
}

TEST(XuNeedleman, tangential_traction_is_odd_in_tangential_opening) {
  const XuNeedleman law = spec_law();
  for (double dn : {-0.2e-6, 0.0, 0.3e-6, 1e-6})
    for (double dt : {0.1e-6, 0.5e-6, 2e-6}) {
      const CohesiveTraction a = law.traction(dn, dt), b = law.traction(dn, -dt);
      EXPECT_DOUBLE_EQ(a.tangential, -b.tangential);
      EXPECT_DOUBLE_EQ(a.normal, b.normal);
    }
}

TEST(XuNeedleman, penalty_acts_only_in_compression) {
  XuNeedleman with = spec_law(), without = spec_law();
  without.penalty = 0.0;
  for (double dn : {1e-9, 0.2e-6, 1e-6})
    EXPECT_EQ(with.traction(dn, 0.3e-6).normal, without.traction(dn, 0.3e-6).normal);
  const double dn = -0.1e-6;
  const double extra = with.traction(dn, 0.3e-6).normal - without.traction(dn, 0.3e-6).normal;
  EXPECT_NEAR(extra, with.penalty_stiffness() * dn, 1e-9 * std::fabs(extra));
  EXPECT_LT(extra, 0.0);  // resists closing: the normal traction pushes the faces apart
  // Far along the tangential direction the law alone no longer resists closing (q = 1).
  EXPECT_NEAR(without.traction(dn, 5 * with.delta_t).normal, 0.0, 1e-6 * with.sigma_max);
  EXPECT_LT(with.traction(dn, 5 * with.delta_t).normal, -0.2 * with.sigma_max);
}

TEST(XuNeedleman, traction_is_the_gradient_of_the_potential) {
  XuNeedleman law = spec_law();
  for (double q : {1.0, 0.5}) {
    law.q = q;
    law.r = q == 1.0 ? 0.0 : 0.2;
    for (double dn : {-0.1e-6, 0.2e-6, 0.7e-6})
      for (double dt : {-0.4e-6, 0.3e-6, 1.1e-6}) {
        const double e = 1e-12;
        const double gn = (law.potential(dn + e, dt) - law.potential(dn - e, dt)) / (2 * e);
        const double gt = (law.potential(dn, dt + e) - law.potential(dn, dt - e)) / (2 * e);
        const CohesiveTraction T = law.traction(dn, dt);
        EXPECT_NEAR(T.normal, gn, 1e-5 * law.sigma_max) << "q " << q << " dn " << dn << " dt " << dt;
        EXPECT_NEAR(T.tangential, gt, 1e-5 * law.sigma_max) << "q " << q << " dn " << dn << " dt " << dt;
      }
  }
  EXPECT_NEAR(law.potential(0, 0), 0.0, 1e-12);
}
