// Tests of frictional contact (cohesive/contact.hpp): no tension, a linear penalty, Coulomb
// stick and slip by return mapping, the work of friction, and the energy balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "cohesive/contact.hpp"

using namespace rupture;

namespace {
ContactLaw test_contact() {
  ContactLaw c;
  c.stiffness = 1e15;
  c.friction = 0.4;
  c.tangential_stiffness = 5e14;
  return c;
}
}  // namespace

TEST(Contact, open_faces_carry_no_traction_and_unload_the_stick_spring) {
  const ContactLaw c = test_contact();
  for (const double dn : {0.0, 1e-12, 3e-6})
    for (const double dt : {-2e-6, 0.0, 0.7e-6}) {
      GaussHistory h{0.25, -1e-6};
      const LawResponse r = c.respond(dn, dt, h);
      EXPECT_EQ(r.tn, 0.0) << dn << " " << dt;
      EXPECT_EQ(r.tt, 0.0) << dn << " " << dt;
      EXPECT_EQ(h.slip, dt);      // closing again starts with an unloaded stick spring
      EXPECT_EQ(h.damage, 0.25);  // contact leaves the cohesive law's history alone
      EXPECT_EQ(c.stored_energy(dn, dt, h), 0.0);
      EXPECT_EQ(r.stiffness, std::max(c.stiffness, c.tangential_stiffness));  // may close next step
    }
}

TEST(Contact, penetration_traction_is_linear_in_dn_and_independent_of_dt) {
  const ContactLaw c = test_contact();
  for (const double dn : {-1e-12, -1e-9, -3e-8})
    for (const double dt : {-1e-6, 0.0, 1e-9, 5e-6}) {
      GaussHistory h{0.0, 0.3e-6};
      const LawResponse r = c.respond(dn, dt, h);
      EXPECT_EQ(r.tn, c.stiffness * dn) << dn << " " << dt;
      EXPECT_LT(r.tn, 0.0);  // pushes the faces apart
    }
}

// Stuck below the Coulomb limit (Tt = kt Dt, slip unchanged), sliding at exactly mu |Tn|
// above it, in both directions, with the slip the return mapping leaves.
TEST(Contact, sticks_below_and_slides_at_the_coulomb_limit) {
  const ContactLaw c = test_contact();
  const double dn = -2e-9, limit = c.friction * c.stiffness * 2e-9;  // 0.8 MPa
  const double kt = c.tangential_stiffness;
  for (const double sign : {1.0, -1.0}) {
    GaussHistory h;
    const double stick = sign * 0.9 * limit / kt;
    LawResponse r = c.respond(dn, stick, h);
    EXPECT_NEAR(r.tt, kt * stick, 1e-12 * limit);
    EXPECT_EQ(h.slip, 0.0);
    const double far = sign * 3.0 * limit / kt;
    r = c.respond(dn, far, h);
    EXPECT_NEAR(r.tt, sign * limit, 1e-12 * limit);
    EXPECT_NEAR(h.slip, far - sign * limit / kt, 1e-12 * limit / kt);
    // Back by less than 2 limit / kt: stuck again, on the unloading stick line.
    const double back = far - sign * 1.5 * limit / kt;
    r = c.respond(dn, back, h);
    EXPECT_NEAR(r.tt, sign * (limit - 1.5 * limit), 1e-12 * limit);
    // Pressed harder while sliding: the limit grows with |Tn|.
    GaussHistory s;
    r = c.respond(2 * dn, far * 10, s);
    EXPECT_NEAR(r.tt, sign * 2 * limit, 1e-12 * limit);
  }
  // A point that is open has no friction, however much it slides.
  GaussHistory h;
  EXPECT_EQ(c.respond(1e-9, 1e-3, h).tt, 0.0);
  // Frictionless: never resists sliding.
  ContactLaw smooth = test_contact();
  smooth.friction = 0.0;
  GaussHistory s;
  EXPECT_EQ(smooth.respond(dn, 1e-7, s).tt, 0.0);
  EXPECT_EQ(smooth.respond(dn, 1e-7, s).stiffness, smooth.stiffness);
}

// At fixed pressure, drive Dt from +A to -A and back to +A (a closed cycle in state: the
// sliding point returns to the same traction and slip). Work of the tangential traction over
// the cycle (trapezoid, fine steps) = mu |Tn| x total slip length = mu |Tn| 4 (A - limit/kt).
TEST(Contact, frictional_work_over_a_slip_cycle_is_mu_tn_times_slip_length) {
  const ContactLaw c = test_contact();
  const double dn = -2e-9, limit = c.friction * c.stiffness * 2e-9;
  const double kt = c.tangential_stiffness, A = 10 * limit / kt;
  GaussHistory h;
  double dt = 0.0, tt = 0.0;
  c.respond(dn, 0.0, h);
  auto leg = [&](double to, double& work, double& slip_length, double& dissipated) {
    const int steps = 200000;
    const double from = dt;
    for (int i = 1; i <= steps; ++i) {
      const double next = from + (to - from) * i / steps;
      const double slip_before = h.slip;
      const LawResponse r = c.respond(dn, next, h);
      work += 0.5 * (tt + r.tt) * (next - dt);
      slip_length += std::fabs(h.slip - slip_before);
      dissipated += ContactLaw::dissipated_increment(tt, slip_before, r.tt, h.slip);
      ASSERT_LE(std::fabs(r.tt), limit * (1 + 1e-12));
      dt = next, tt = r.tt;
    }
  };
  double w0 = 0, l0 = 0, d0 = 0;
  leg(A, w0, l0, d0);
  const double slip_at_A = h.slip, energy_at_A = c.stored_energy(dn, dt, h);
  double work = 0, slip_length = 0, dissipated = 0;
  leg(-A, work, slip_length, dissipated);
  leg(A, work, slip_length, dissipated);
  EXPECT_NEAR(h.slip, slip_at_A, 1e-12 * A);
  EXPECT_NEAR(c.stored_energy(dn, dt, h), energy_at_A, 1e-12 * limit * A);
  const double expected = limit * 4 * (A - limit / kt);
  EXPECT_NEAR(slip_length, 4 * (A - limit / kt), 1e-9 * A);
  EXPECT_NEAR(work, expected, 1e-6 * expected);
  EXPECT_NEAR(dissipated, expected, 1e-6 * expected);
}

// Random paths that open, close, stick and slide: |Tt| <= mu |Tn| always, and the trapezoidal
// work of the tractions equals the stored energy plus the friction dissipated (the kink at
// Dn = 0 is a sample point of the path, so the trapezoid is exact for the normal spring).
TEST(Contact, work_equals_stored_plus_dissipated_on_random_paths) {
  for (const double mu : {0.4, 0.0, 1.2}) {
    ContactLaw c = test_contact();
    c.friction = mu;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int path = 0; path < 20; ++path) {
      GaussHistory h;
      double dn = -1e-9, dt = 0.0;
      LawResponse r = c.respond(dn, dt, h);
      const double stored_at_start = c.stored_energy(dn, dt, h);
      double work = 0, dissipated = 0, scale = 0;
      auto visit = [&](double n, double t) {
        const double slip_before = h.slip;
        const LawResponse next = c.respond(n, t, h);
        const double dw = 0.5 * (r.tn + next.tn) * (n - dn) + 0.5 * (r.tt + next.tt) * (t - dt);
        work += dw, scale += std::fabs(dw);
        dissipated += ContactLaw::dissipated_increment(r.tt, slip_before, next.tt, h.slip);
        ASSERT_LE(std::fabs(next.tt), mu * std::fabs(next.tn) * (1 + 1e-12)) << "path " << path;
        ASSERT_LE(next.tn, 0.0);
        dn = n, dt = t, r = next;
      };
      for (int i = 0; i < 2000; ++i) {
        const double n = std::clamp(dn + 0.4e-9 * u(rng) - 0.02e-9, -5e-9, 1e-9);
        const double t = dt + 1e-9 * u(rng);
        if ((dn < 0.0) != (n < 0.0)) {  // sample the kink
          const double f = dn / (dn - n);
          visit(0.0, dt + f * (t - dt));
        }
        visit(n, t);
      }
      const double stored = c.stored_energy(dn, dt, h) - stored_at_start;
      EXPECT_NEAR(work, stored + dissipated, 1e-9 * scale) << "mu " << mu << " path " << path;
      EXPECT_GE(dissipated, 0.0) << "mu " << mu << " path " << path;
      if (mu == 0.0) {
        EXPECT_NEAR(dissipated, 0.0, 1e-12 * scale);
      }
    }
  }
}

TEST(Contact, validate_names_the_parameter_and_range) {
  EXPECT_EQ(test_contact().validate(), "");
  EXPECT_EQ(ContactLaw{}.validate(), "stiffness = 0: must be > 0 and finite (Pa/m)");
  ContactLaw c = test_contact();
  c.friction = -0.1;
  EXPECT_EQ(c.validate(), "friction = -0.1: must be >= 0 and finite (Coulomb coefficient)");
  c = test_contact();
  c.tangential_stiffness = -1;
  EXPECT_EQ(c.validate(),
            "tangential_stiffness = -1: must be >= 0 and finite (Pa/m; 0 = stiffness)");
  // 0 = the normal stiffness, also in aggregate initialisation.
  const ContactLaw same{2e14, 0.3};
  EXPECT_EQ(same.validate(), "");
  EXPECT_EQ(same.stick_stiffness(), 2e14);
}
