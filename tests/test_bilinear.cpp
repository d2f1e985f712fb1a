// Tests of the bilinear mixed-mode law (cohesive/bilinear.hpp, docs/cohesive_laws.md): peaks,
// fracture energies in pure and mixed mode, secant unloading, irreversibility, the penalty,
// the closed-form tangent and the stability bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "cohesive/bilinear.hpp"

using namespace rupture;

namespace {
// Mode I and II deliberately different, so a swapped parameter shows.
BilinearLaw test_law(double lambda0 = 0.01) {
  BilinearLaw law;
  law.sigma_max = 24e6;
  law.tau_max = 30e6;
  law.delta_nc = 2e-6;
  law.delta_tc = 3e-6;
  law.lambda0 = lambda0;
  law.penalty = 1.0;
  return law;
}

// Work of the law's tractions along a straight path from (n0, t0) to (n1, t1) in `steps`
// steps (trapezoid in the jump, what the interface computes), updating h; adds to `work`.
struct Walker {
  const BilinearLaw& law;
  GaussHistory h{};
  double dn = 0, dt = 0, tn = 0, tt = 0, work = 0;
  void to(double n1, double t1, int steps, const auto& check) {
    const double n0 = dn, t0 = dt;
    for (int i = 1; i <= steps; ++i) {
      const double s = double(i) / steps;
      const double n = n0 + s * (n1 - n0), t = t0 + s * (t1 - t0);
      const LawResponse r = law.respond(n, t, h);
      work += 0.5 * (tn + r.tn) * (n - dn) + 0.5 * (tt + r.tt) * (t - dt);
      dn = n, dt = t, tn = r.tn, tt = r.tt;
      check(*this);
    }
  }
  void to(double n1, double t1, int steps) {
    to(n1, t1, steps, [](const Walker&) {});
  }
};

// Central-difference tangent at (dn, dt) from history h (each evaluation on a copy of h).
BilinearTangent fd_tangent(const BilinearLaw& law, double dn, double dt, const GaussHistory& h,
                           double e) {
  auto at = [&](double n, double t) {
    GaussHistory c = h;
    return law.respond(n, t, c);
  };
  const LawResponse pn = at(dn + e, dt), mn = at(dn - e, dt), pt = at(dn, dt + e),
                    mt = at(dn, dt - e);
  return {(pn.tn - mn.tn) / (2 * e), (pt.tn - mt.tn) / (2 * e), (pn.tt - mn.tt) / (2 * e),
          (pt.tt - mt.tt) / (2 * e)};
}
}  // namespace

TEST(Bilinear, peak_tractions_are_sigma_max_and_tau_max) {
  for (const double l0 : {0.01, 0.2}) {
    const BilinearLaw law = test_law(l0);
    GaussHistory h;
    EXPECT_NEAR(law.respond(l0 * law.delta_nc, 0, h).tn, law.sigma_max, 1e-9 * law.sigma_max) << l0;
    h = {};
    EXPECT_NEAR(law.respond(0, l0 * law.delta_tc, h).tt, law.tau_max, 1e-9 * law.tau_max) << l0;
    h = {};
    EXPECT_NEAR(law.respond(0, -l0 * law.delta_tc, h).tt, -law.tau_max, 1e-9 * law.tau_max) << l0;
    // No larger traction anywhere along monotone pure-mode paths.
    double best_n = 0, best_t = 0;
    Walker wn{law}, wt{law};
    wn.to(1.2 * law.delta_nc, 0, 24000, [&](const Walker& w) { best_n = std::max(best_n, w.tn); });
    wt.to(0, 1.2 * law.delta_tc, 24000, [&](const Walker& w) { best_t = std::max(best_t, w.tt); });
    EXPECT_LE(best_n, law.sigma_max * (1 + 1e-12)) << l0;
    EXPECT_LE(best_t, law.tau_max * (1 + 1e-12)) << l0;
    EXPECT_NEAR(best_n, law.sigma_max, 1e-9 * law.sigma_max) << l0;  // step 20000 l0 is lambda0
  }
}

TEST(Bilinear, separation_work_equals_G_in_pure_modes) {
  for (const double l0 : {0.01, 0.2}) {
    const BilinearLaw law = test_law(l0);
    const double Gi = law.sigma_max * law.delta_nc / 2, Gii = law.tau_max * law.delta_tc / 2;
    EXPECT_DOUBLE_EQ(law.fracture_energy_normal(), Gi);
    EXPECT_DOUBLE_EQ(law.fracture_energy_tangential(), Gii);
    Walker wn{law}, wt{law}, wneg{law};
    wn.to(1.3 * law.delta_nc, 0, 100000);
    wt.to(0, 1.3 * law.delta_tc, 100000);
    wneg.to(0, -1.3 * law.delta_tc, 100000);
    EXPECT_NEAR(wn.work, Gi, 1e-4 * Gi) << "lambda0 " << l0;
    EXPECT_NEAR(wt.work, Gii, 1e-4 * Gii) << "lambda0 " << l0;
    EXPECT_NEAR(wneg.work, Gii, 1e-4 * Gii) << "lambda0 " << l0;
    EXPECT_TRUE(law.separated(wn.h));
    EXPECT_TRUE(law.separated(wt.h));
    EXPECT_EQ(wn.tn, 0.0);
    EXPECT_EQ(wt.tt, 0.0);
  }
}

// Along a straight ray (Dn, Dt) = s (cos psi delta_nc, sin psi delta_tc), lambda = s and
// G(psi) = G_Ic cos^2 psi + G_IIc sin^2 psi (docs/cohesive_laws.md).
TEST(Bilinear, radial_path_work_matches_mixed_mode_energy) {
  const BilinearLaw law = test_law(0.05);
  for (const double psi : {0.1, 0.5, 0.785, 1.2, -0.9}) {
    const double c = std::cos(psi), s = std::sin(psi);
    const double expected =
        law.fracture_energy_normal() * c * c + law.fracture_energy_tangential() * s * s;
    EXPECT_NEAR(law.fracture_energy_radial(c * law.delta_nc, s * law.delta_tc), expected,
                1e-12 * expected);
    Walker w{law};
    w.to(1.2 * c * law.delta_nc, 1.2 * s * law.delta_tc, 100000);
    EXPECT_NEAR(w.work, expected, 1e-4 * expected) << "psi " << psi;
    EXPECT_TRUE(law.separated(w.h)) << "psi " << psi;
  }
}

// Load to kappa, unload to the origin, reload to separation. Unloading follows the secant
// g(kappa) exactly and reaches zero traction at zero opening; the work never goes negative;
// the stored energy equals the work minus the dissipation D = G (kappa - lambda0)/(1 - lambda0)
// (docs/cohesive_laws.md); the whole cycle dissipates G and no more.
TEST(Bilinear, unloading_follows_the_secant_and_gains_no_energy) {
  const BilinearLaw law = test_law(0.05);
  for (const double psi : {0.0, 0.6, 1.5707963267948966}) {
    const double c = std::cos(psi), s = std::sin(psi);
    const double G = law.fracture_energy_radial(c * law.delta_nc, s * law.delta_tc);
    const double n1 = c * law.delta_nc, t1 = s * law.delta_tc;  // lambda = 1 on this ray
    const double kappa = 0.5;
    const double D = G * (kappa - law.lambda0) / (1 - law.lambda0);
    Walker w{law};
    w.to(kappa * n1, kappa * t1, 50000);
    EXPECT_NEAR(w.h.damage, kappa, 1e-12);
    const double reached = w.h.damage;
    const double g = law.secant_factor(kappa);
    auto on_secant = [&](const Walker& p) {
      EXPECT_NEAR(p.tn, law.sigma_max * g * p.dn / law.delta_nc, 1e-9 * law.sigma_max);
      EXPECT_NEAR(p.tt, law.tau_max * g * p.dt / law.delta_tc, 1e-9 * law.tau_max);
      EXPECT_GE(p.work, 0.0);
      EXPECT_NEAR(law.stored_energy(p.dn, p.dt, p.h), p.work - D, 1e-6 * G);
      EXPECT_LE(p.h.damage, reached * (1 + 1e-14));  // no damage inside the elastic domain
    };
    on_secant(w);
    w.to(0, 0, 5000, on_secant);
    EXPECT_EQ(w.tn, 0.0);
    EXPECT_EQ(w.tt, 0.0);
    EXPECT_EQ(law.stored_energy(0, 0, w.h), 0.0);
    EXPECT_NEAR(w.work, D, 1e-6 * G) << "psi " << psi;
    w.to(kappa * n1, kappa * t1, 5000, on_secant);
    w.to(1.2 * n1, 1.2 * t1, 50000);
    EXPECT_NEAR(w.work, G, 1e-4 * G) << "psi " << psi;
  }
}

TEST(Bilinear, damage_never_decreases_and_is_the_largest_opening_reached) {
  const BilinearLaw law = test_law(0.05);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int path = 0; path < 50; ++path) {
    GaussHistory h;
    double largest = 0.0;
    for (int i = 0; i < 200; ++i) {
      const double dn = 0.8 * u(rng) * law.delta_nc, dt = 0.8 * u(rng) * law.delta_tc;
      const double before = h.damage;
      law.respond(dn, dt, h);
      largest = std::max(largest, law.effective_opening(dn, dt));
      ASSERT_GE(h.damage, before) << "path " << path << " step " << i;
      ASSERT_EQ(h.damage, largest) << "path " << path << " step " << i;
    }
  }
}

// theory E8's rule for this law: Tn = k_pen Dn for Dn < 0, k_pen = penalty sigma_max /
// (lambda0 delta_nc), whatever Dt and the damage; no penalty for Dn >= 0.
TEST(Bilinear, penalty_is_independent_of_tangential_opening) {
  BilinearLaw law = test_law(0.05);
  law.penalty = 2.5;
  const double kp = 2.5 * law.sigma_max / (0.05 * law.delta_nc);
  EXPECT_DOUBLE_EQ(law.penalty_stiffness(), kp);
  for (const double damage : {0.0, 0.3, 0.99, 1.5})
    for (const double dt : {0.0, 0.02e-6, -0.5e-6, 2e-6, 10e-6}) {
      GaussHistory h{damage, 0.0};
      const double dn = -0.01e-6;
      EXPECT_DOUBLE_EQ(law.respond(dn, dt, h).tn, kp * dn) << "damage " << damage << " dt " << dt;
      GaussHistory fresh{damage, 0.0};
      EXPECT_GE(law.respond(1e-12, dt, fresh).tn, 0.0) << "no penalty when open";
    }
  // A separated point carries nothing but the penalty.
  GaussHistory gone{1.0, 0.0};
  EXPECT_TRUE(law.separated(gone));
  const LawResponse r = law.respond(0.3e-6, 0.4e-6, gone);
  EXPECT_EQ(r.tn, 0.0);
  EXPECT_EQ(r.tt, 0.0);
  EXPECT_EQ(law.stored_energy(0.3e-6, 0.4e-6, gone), 0.0);
  EXPECT_DOUBLE_EQ(law.stored_energy(-0.1e-6, 0.4e-6, gone), 0.5 * kp * 0.1e-6 * 0.1e-6);
}

// The closed-form tangent against central differences of respond(), on the softening
// (loading) branch from a fresh history, on the elastic branch, and on the unloading branch,
// for both signs of Dt and on the compressed side.
TEST(Bilinear, tangent_matches_finite_differences) {
  const BilinearLaw law = test_law(0.05);
  const double scale = law.initial_stiffness();
  const double e = 1e-7 * law.delta_nc;
  struct Case {
    double xn, xt, damage;
  };
  const Case cases[] = {
      {0.3, 0.2, 0.0},   {0.1, -0.6, 0.0},  {0.7, 0.05, 0.0},  {-0.2, 0.4, 0.0},  // softening
      {0.02, 0.01, 0.0}, {-0.1, 0.02, 0.0},                                       // elastic
      {0.2, 0.3, 0.8},   {0.4, -0.1, 0.6},  {-0.3, -0.2, 0.5},                    // unloading
  };
  for (const Case& c : cases) {
    const double dn = c.xn * law.delta_nc, dt = c.xt * law.delta_tc;
    const GaussHistory h{c.damage, 0.0};
    const BilinearTangent K = law.tangent(dn, dt, h), F = fd_tangent(law, dn, dt, h, e);
    EXPECT_NEAR(K.nn, F.nn, 1e-6 * scale) << c.xn << " " << c.xt << " " << c.damage;
    EXPECT_NEAR(K.nt, F.nt, 1e-6 * scale) << c.xn << " " << c.xt << " " << c.damage;
    EXPECT_NEAR(K.tn, F.tn, 1e-6 * scale) << c.xn << " " << c.xt << " " << c.damage;
    EXPECT_NEAR(K.tt, F.tt, 1e-6 * scale) << c.xn << " " << c.xt << " " << c.damage;
  }
  // Softening really softens: the tangent is not the secant there.
  const BilinearTangent soft = law.tangent(0.3 * law.delta_nc, 0.0, GaussHistory{});
  EXPECT_LT(soft.nn, 0.0);
}

// The stiffness respond() reports bounds the largest eigenvalue of the finite-difference
// tangent at random states and histories (including straddling a kink), and is at least the
// penalty; at rest it is the undamaged stiffness or the penalty, whichever is larger.
TEST(Bilinear, stability_stiffness_bounds_the_tangent) {
  for (const double penalty : {1.0, 0.1, 3.0}) {
    BilinearLaw law = test_law(0.05);
    law.penalty = penalty;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0), v(0.0, 1.2);
    for (int i = 0; i < 2000; ++i) {
      const double dn = 0.8 * u(rng) * law.delta_nc, dt = 0.8 * u(rng) * law.delta_tc;
      const GaussHistory h{i % 3 == 0 ? 0.0 : v(rng), 0.0};
      GaussHistory after = h;
      const double k = law.respond(dn, dt, after).stiffness;
      const double fd = fd_tangent(law, dn, dt, h, 1e-7 * law.delta_nc).max_eigenvalue();
      const double closed = law.tangent(dn, dt, h).max_eigenvalue();
      ASSERT_GE(k * (1 + 1e-6), fd) << "dn " << dn << " dt " << dt << " damage " << h.damage;
      ASSERT_GE(k * (1 + 1e-12), closed) << "dn " << dn << " dt " << dt << " damage " << h.damage;
      ASSERT_GE(k, law.penalty_stiffness());
    }
    GaussHistory h;
    EXPECT_DOUBLE_EQ(law.respond(0, 0, h).stiffness,
                     std::max(law.initial_stiffness(), law.penalty_stiffness()));
  }
  const BilinearLaw law = test_law(0.05);
  EXPECT_DOUBLE_EQ(law.initial_stiffness(),
                   law.sigma_max / (0.05 * law.delta_nc));  // mode I stiffer here
}

TEST(Bilinear, validate_names_the_parameter_and_range) {
  EXPECT_EQ(test_law().validate(), "");
  EXPECT_EQ(BilinearLaw{}.validate(), "sigma_max = 0: must be > 0 and finite (Pa)");
  auto message = [](auto edit) {
    BilinearLaw law = test_law();
    edit(law);
    return law.validate();
  };
  EXPECT_EQ(message([](BilinearLaw& l) { l.tau_max = -3; }),
            "tau_max = -3: must be > 0 and finite (Pa)");
  EXPECT_EQ(message([](BilinearLaw& l) { l.delta_nc = 0; }),
            "delta_nc = 0: must be > 0 and finite (m)");
  EXPECT_EQ(message([](BilinearLaw& l) { l.delta_tc = INFINITY; }),
            "delta_tc = inf: must be > 0 and finite (m)");
  EXPECT_EQ(message([](BilinearLaw& l) { l.lambda0 = 1; }),
            "lambda0 = 1: must lie in (0, 1) (elastic fraction of the critical opening)");
  EXPECT_EQ(message([](BilinearLaw& l) { l.lambda0 = 0; }),
            "lambda0 = 0: must lie in (0, 1) (elastic fraction of the critical opening)");
  EXPECT_EQ(message([](BilinearLaw& l) { l.penalty = -1; }),
            "penalty = -1: must be >= 0 and finite (multiple of sigma_max/(lambda0 delta_nc))");
  EXPECT_EQ(message([](BilinearLaw& l) { l.penalty = 0; }), "");
  EXPECT_NE(message([](BilinearLaw& l) { l.sigma_max = NAN; }).find("sigma_max = nan"),
            std::string::npos);
}
