// Tests of the Xu-Needleman law (theory E7, E8) against the paper's checks.
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

// The closed-form tangent (used by the E6 step bound) is the derivative of the traction:
// central differences agree to 1e-6 of the stiffness scale, on both sides of the penalty kink,
// for q = 1 and for a q != 1, r != 0 law (every term of E7).
TEST(XuNeedleman, tangent_matches_finite_differences_of_the_traction) {
  for (const double q : {1.0, 0.5}) {
    XuNeedleman law = spec_law();
    law.q = q;
    law.r = q == 1.0 ? 0.0 : 0.3;
    const double scale = law.initial_stiffness();
    for (const double xn : {-1.5, -0.2, 0.3, 1.0, 2.5})
      for (const double xt : {-1.2, 0.0, 0.4, 0.9, 2.0}) {
        const double dn = xn * law.delta_n, dt = xt * law.delta_t;
        const double e = 1e-6 * law.delta_n;
        const CohesiveTangent K = law.tangent(dn, dt);
        const CohesiveTraction pn = law.traction(dn + e, dt), mn = law.traction(dn - e, dt);
        const CohesiveTraction pt = law.traction(dn, dt + e), mt = law.traction(dn, dt - e);
        EXPECT_NEAR(K.nn, (pn.normal - mn.normal) / (2 * e), 1e-6 * scale) << xn << " " << xt;
        EXPECT_NEAR(K.nt, (pt.normal - mt.normal) / (2 * e), 1e-6 * scale) << xn << " " << xt;
        EXPECT_NEAR(K.nt, (pn.tangential - mn.tangential) / (2 * e), 1e-6 * scale) << "symmetry";
        EXPECT_NEAR(K.tt, (pt.tangential - mt.tangential) / (2 * e), 1e-6 * scale) << xn << " " << xt;
      }
  }
}

// theory E6 and E8: at zero opening the normal stiffness is e sigma_max / delta_n on the open
// side and twice that on the compressed side (law + penalty, k_pen = 1); the tangential one is
// 2 phi_t / delta_t^2 = tau_max / delta_n for the paper's q = 1 parameters. The step bound takes
// the compressed side for a face at rest.
TEST(XuNeedleman, stiffness_at_rest_includes_the_penalty) {
  const XuNeedleman law = spec_law();
  const double k0 = std::exp(1.0) * law.sigma_max / law.delta_n;
  EXPECT_NEAR(law.tangent(0.0, 0.0).nn, k0, 1e-9 * k0);
  EXPECT_NEAR(law.tangent(-1e-15, 0.0).nn, 2.0 * k0, 1e-6 * k0);
  EXPECT_NEAR(law.tangent(0.0, 0.0).tt, law.tau_max / law.delta_n, 1e-9 * k0);
  EXPECT_NEAR(law.stability_stiffness(0.0, 0.0), 2.0 * k0, 1e-6 * k0);
  // Compression stiffens the exponential law: (1 - xn) e^{-xn} + k_pen at xn = -1.
  EXPECT_NEAR(law.stability_stiffness(-law.delta_n, 0.0), k0 * (2.0 * std::exp(1.0) + 1.0), 1e-6 * k0);
  // Opening in shear lowers it: at Dt = delta_t the normal stiffness is k0 e^{-1}, the shear
  // one negative (softening), the coupling zero at Dn = 0.
  const CohesiveTangent soft = law.tangent(0.0, law.delta_t);
  EXPECT_LT(soft.tt, 0.0);
  EXPECT_NEAR(soft.max_eigenvalue(), k0 * std::exp(-1.0), 1e-9 * k0);
}
