// The normal-stress regularization (cohesive/normal_relaxation.hpp) at one Gauss point, alone
// and inside the two fault laws: after a step in the compression the strength follows the
// exponential relaxation of the time form and of the slip form (closed form), a compression
// that ramps converges at first order in the step (the exponential integrator with the
// compression taken at the step's end), a constant compression is seen exactly (the law
// answers bit for bit as without the regularization), and the parameter checks.
#include <gtest/gtest.h>

#include <cmath>

#include "cohesive/law.hpp"

using namespace rupture;

namespace {
constexpr double kSigma0 = 100e6, kSigma1 = 130e6;  // Pa: initial and stepped compression

NormalRelaxation time_form(double T) {
  NormalRelaxation r;
  r.form = RelaxationForm::time, r.time = T;
  return r;
}
NormalRelaxation slip_form(double L, double v_star) {
  NormalRelaxation r;
  r.form = RelaxationForm::slip, r.slip = L, r.rate = v_star;
  return r;
}

SlipWeakening fault(const NormalRelaxation& r) {
  SlipWeakening f;
  f.static_friction = 0.6, f.dynamic_friction = 0.4, f.dc = 0.5, f.cohesion = 1e6;
  f.normal_stiffness = 2e10, f.stick_stiffness = 1e10;
  f.tn0 = -kSigma0, f.tt0 = 80e6;  // above the 61 MPa static strength: it slides
  f.relaxation = r;
  return f;
}
}  // namespace

TEST(NormalRelaxation, time_form_follows_the_exponential_after_a_step) {
  const NormalRelaxation r = time_form(0.02);
  GaussHistory h;
  const double dt = 1e-3;
  for (int n = 1; n <= 100; ++n) {
    const double seen = r.seen(kSigma1, kSigma0, 0.0, dt, h);
    const double exact = kSigma1 + (kSigma0 - kSigma1) * std::exp(-n * dt / 0.02);
    ASSERT_NEAR(seen, exact, 1e-9 * kSigma1) << n;
  }
}

TEST(NormalRelaxation, slip_form_relaxes_over_the_slip_plus_the_reference_rate) {
  const double L = 0.2, v_star = 0.5, V = 3.0, dt = 1e-3;
  const NormalRelaxation r = slip_form(L, v_star);
  GaussHistory h;
  for (int n = 1; n <= 100; ++n) {
    const double seen = r.seen(kSigma1, kSigma0, -V * dt, dt, h);  // |ds|: either direction
    const double exact = kSigma1 + (kSigma0 - kSigma1) * std::exp(-(V + v_star) * n * dt / L);
    ASSERT_NEAR(seen, exact, 1e-9 * kSigma1) << n;
  }
  // Stuck (no slip) with V* = 0: nothing relaxes.
  GaussHistory s;
  EXPECT_EQ(slip_form(L, 0.0).seen(kSigma1, kSigma0, 0.0, dt, s), kSigma0);
}

// sigma(t) = sigma0 + k t: d sigma*/dt = -(sigma* - sigma)/T has sigma* = sigma - k T (1 - e^-t/T).
TEST(NormalRelaxation, a_ramp_converges_at_first_order_in_the_step) {
  const double T = 0.01, k = 5e9, t_end = 0.02;
  const NormalRelaxation r = time_form(T);
  const auto error = [&](int steps) {
    GaussHistory h;
    const double dt = t_end / steps;
    double seen = 0.0;
    for (int n = 1; n <= steps; ++n) seen = r.seen(kSigma0 + k * n * dt, kSigma0, 0.0, dt, h);
    const double exact = kSigma0 + k * t_end - k * T * (1.0 - std::exp(-t_end / T));
    return std::fabs(seen - exact);
  };
  const double e1 = error(50), e2 = error(100), e3 = error(200);
  EXPECT_GT(e1, 0.0);
  EXPECT_NEAR(std::log2(e1 / e2), 1.0, 0.1);
  EXPECT_NEAR(std::log2(e2 / e3), 1.0, 0.05);
}

TEST(NormalRelaxation, slip_weakening_strength_uses_the_relaxed_compression) {
  const double T = 0.01, dt = 1e-4;
  const SlipWeakening f = fault(time_form(T));
  GaussHistory h;
  const double dn = -(kSigma1 - kSigma0) / f.normal_stiffness;  // the compression steps to 130 MPa
  double jump = 0.0;
  for (int n = 1; n <= 300; ++n) {
    jump += 1e-4;  // sliding: the jump outruns the stick spring
    h.duration = dt;
    const LawResponse resp = f.respond(dn, jump, h);
    h.jump_t = jump;
    const double seen = kSigma1 + (kSigma0 - kSigma1) * std::exp(-n * dt / T);
    ASSERT_NEAR(f.total_normal(resp), -kSigma1, 1e-6);  // the penalty's traction: the actual one
    ASSERT_NEAR(f.total_shear(resp), f.cohesion + f.friction(h.damage) * seen, 1e-6 * kSigma1) << n;
  }
}

TEST(NormalRelaxation, rate_state_strength_uses_the_relaxed_compression) {
  RateStateFriction f;
  f.a = 0.008, f.b = 0.012, f.dc = 0.02, f.v0 = 1e-6, f.f0 = 0.6, f.v_init = 1e-12;
  f.normal_stiffness = f.stick_stiffness = 1.9e9;
  f.tn0 = -kSigma0, f.tt0 = 62e6;
  ASSERT_TRUE(f.initialize_state());
  const double T = 0.005, dt = 1e-4;
  f.relaxation = time_form(T);
  GaussHistory h;
  const double dn = -(kSigma1 - kSigma0) / f.normal_stiffness;
  double jump = 0.0;
  for (int n = 1; n <= 200; ++n) {
    jump += 2e-4;  // 2 m/s imposed jump rate: the point slides
    h.duration = dt;
    h.time = n * dt;
    const LawResponse resp = f.respond(dn, jump, h);
    h.jump_t = jump;
    const double seen = kSigma1 + (kSigma0 - kSigma1) * std::exp(-n * dt / T);
    const double v = std::fabs(f.v_init + h.rate), psi = f.psi_init + h.state;
    ASSERT_NEAR(f.tt0 + resp.tt, seen * f.friction(v, psi), 1e-6 * kSigma1) << n;
  }
}

TEST(NormalRelaxation, a_constant_compression_is_seen_exactly) {
  // The regularized law answers bit for bit as the plain one while the compression stays put.
  const SlipWeakening plain = fault(NormalRelaxation{}), relaxed = fault(slip_form(0.1, 1.0));
  GaussHistory a, b;
  for (int n = 1; n <= 50; ++n) {
    a.duration = b.duration = 1e-3;
    const double jump = 2e-4 * n;
    const LawResponse ra = plain.respond(0.0, jump, a), rb = relaxed.respond(0.0, jump, b);
    a.jump_t = b.jump_t = jump;
    ASSERT_EQ(ra.tn, rb.tn);
    ASSERT_EQ(ra.tt, rb.tt);
    ASSERT_EQ(a.damage, b.damage);
    ASSERT_EQ(b.normal_seen, 0.0);
  }
}

TEST(NormalRelaxation, parameter_ranges_are_named) {
  EXPECT_EQ(NormalRelaxation{}.validate(), "");
  EXPECT_EQ(time_form(0.1).validate(), "");
  EXPECT_EQ(slip_form(0.1, 0.0).validate(), "");
  EXPECT_NE(time_form(0.0).validate().find("normal_relaxation_time = 0"), std::string::npos);
  EXPECT_NE(time_form(-1.0).validate().find("> 0"), std::string::npos);
  EXPECT_NE(slip_form(0.0, 1.0).validate().find("normal_relaxation_slip = 0"), std::string::npos);
  EXPECT_NE(slip_form(0.1, -1.0).validate().find("normal_relaxation_rate = -1"), std::string::npos);
  EXPECT_NE(slip_form(NAN, 1.0).validate().find("finite"), std::string::npos);
}
