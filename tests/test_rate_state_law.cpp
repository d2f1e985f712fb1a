// Rate-and-state friction at one Gauss point (cohesive/rate_state.hpp): the regularized
// friction and its derivative, the steady states, the state update against an independent
// integration of each evolution law, the slip-rate solve, the initial state, the response of a
// point (rest, loading, opening, the tangent bound) and the parameter checks.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "cohesive/law.hpp"

using namespace rupture;

namespace {
// TPV101's friction (a = 0.008, b = 0.012, Dc = 0.02 m, V0 = 1e-6 m/s, f0 = 0.6) at 120 MPa;
// TPV103's flash heating (f_w = 0.2, V_w = 0.1 m/s) where asked.
RateStateFriction law(StateEvolution e = StateEvolution::aging) {
  RateStateFriction f;
  f.evolution = e;
  f.a = 0.008, f.b = 0.012, f.dc = 0.02, f.v0 = 1e-6, f.f0 = 0.6;
  if (e == StateEvolution::flash_heating) f.a = 0.01, f.b = 0.014, f.dc = 0.4, f.fw = 0.2, f.vw = 0.1;
  f.v_init = 1e-12;
  f.normal_stiffness = f.stick_stiffness = 1.9e9;  // M / h at 50 m
  f.tn0 = -120e6, f.tt0 = 75e6;
  EXPECT_TRUE(f.initialize_state());
  return f;
}

// RK4 of d psi/dt = rhs(psi) at a constant rate, n steps: an integration that shares nothing
// with the law's closed form.
double integrate(const std::function<double(double)>& rhs, double psi, double t, int n) {
  const double h = t / n;
  for (int i = 0; i < n; ++i) {
    const double k1 = rhs(psi), k2 = rhs(psi + 0.5 * h * k1), k3 = rhs(psi + 0.5 * h * k2),
                 k4 = rhs(psi + h * k3);
    psi += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return psi;
}
}  // namespace

TEST(RateStateLaw, friction_is_the_regularized_form_without_overflow) {
  const RateStateFriction f = law();
  for (double v : {1e-14, 1e-9, 1e-6, 1e-3, 1.0, 10.0})
    for (double psi : {0.3, 0.5, 0.6, 0.75}) {
      const double z = v / (2.0 * f.v0) * std::exp(psi / f.a);
      EXPECT_NEAR(f.friction(v, psi), f.a * std::asinh(z), 1e-13) << v << " " << psi;
      // df/dV against central differences
      const double dv = 1e-6 * v;
      const double fd = (f.friction(v + dv, psi) - f.friction(v - dv, psi)) / (2 * dv);
      EXPECT_NEAR(f.friction_rate_derivative(v, psi) / fd, 1.0, 1e-6);
    }
  // exp(psi / a) = exp(1000) overflows a double; the log form does not.
  const double big = f.friction(1.0, 8.0);
  EXPECT_TRUE(std::isfinite(big));
  EXPECT_NEAR(big, f.a * (std::log(1.0 / (2.0 * f.v0)) + 8.0 / f.a + std::log(2.0)), 1e-12);
}

TEST(RateStateLaw, steady_states_give_the_steady_friction) {
  // Aging and slip: psi_ss = f0 - b ln(V/V0), and f(V, psi_ss) -> f0 - (b - a) ln(V/V0) once
  // z >> 1 (the regularization's difference is a ln(1 + sqrt(1 + 1/z^2)) - a ln 2 ~ a/(4 z^2)).
  const RateStateFriction f = law();
  for (double v : {1e-9, 1e-6, 1e-3, 1.0}) {
    EXPECT_NEAR(f.friction(v, f.steady_state(v)), f.f0 - (f.b - f.a) * std::log(v / f.v0), 1e-12);
    EXPECT_NEAR(f.evolve(f.steady_state(v), v, 10.0), f.steady_state(v), 1e-12) << "stays";
  }
  // Flash heating: f(V, psi_ss) is f_ss exactly (psi_ss is built from it), which falls from
  // f_LV to f_w past V_w.
  const RateStateFriction g = law(StateEvolution::flash_heating);
  for (double v : {1e-9, 1e-3, 0.05, 0.1, 1.0, 10.0})
    EXPECT_NEAR(g.friction(v, g.steady_state(v)), g.steady_friction(v), 1e-12) << v;
  EXPECT_NEAR(g.steady_friction(1e-6), 0.6, 1e-12);
  EXPECT_NEAR(g.steady_friction(1e3), 0.2, 1e-3);
  EXPECT_NEAR(g.steady_friction(0.1), 0.2 + (0.6 - 0.004 * std::log(1e5) - 0.2) / std::pow(2.0, 0.125), 1e-12);
}

TEST(RateStateLaw, state_update_is_exact_at_a_constant_rate) {
  for (StateEvolution e : {StateEvolution::aging, StateEvolution::slip, StateEvolution::flash_heating}) {
    const RateStateFriction f = law(e);
    const double b = f.b, dc = f.dc, v0 = f.v0, f0 = f.f0;
    for (double v : {1e-12, 1e-6, 1e-2, 1.0, 5.0}) {
      std::function<double(double)> rhs;
      if (e == StateEvolution::aging)  // d psi/dt = (b/theta) d theta/dt = (b V0/Dc) e^{(f0-psi)/b} - b V/Dc
        rhs = [=](double p) { return b * v0 / dc * std::exp((f0 - p) / b) - b * v / dc; };
      else
        rhs = [&f, v, dc](double p) { return -(v / dc) * (p - f.steady_state(v)); };
      for (double psi : {0.4, 0.6, 0.8}) {
        const double t = 0.005;
        const double exact = integrate(rhs, psi, t, 20000);
        EXPECT_NEAR(f.evolve(psi, v, t), exact, 1e-10) << evolution_name(e) << " V " << v << " psi " << psi;
        // A step is two half steps (the flow of a constant rate).
        EXPECT_NEAR(f.evolve(f.evolve(psi, v, 0.5 * t), v, 0.5 * t), f.evolve(psi, v, t), 1e-13);
      }
    }
    // Stable for any step: a huge step lands on the steady state, not past it.
    EXPECT_NEAR(f.evolve(0.9, 1.0, 1e3), f.steady_state(1.0), 1e-12);
  }
}

TEST(RateStateLaw, slip_rate_solve_balances_spring_and_friction) {
  const RateStateFriction f = law();
  const double kdt = 1.9e9 * 5e-3;  // kt dt at 50 m
  for (double trial : {60e6, 70e6, 75e6, 80e6, 1e8})
    for (double psi : {0.4, 0.6, 0.75, 0.81})
      for (double sigma : {1e6, 120e6}) {
        const double v = f.solve_slip_rate(trial, sigma, psi, kdt, 1e-12);
        ASSERT_GE(v, 0.0);
        ASSERT_LE(v, trial / kdt);
        const double res = sigma * f.friction(v, psi) + kdt * v - trial;
        EXPECT_LE(std::fabs(res), 1e-9 * trial) << trial << " " << psi << " " << sigma;
        // the same from another start
        EXPECT_NEAR(f.solve_slip_rate(trial, sigma, psi, kdt, 3.0) / v, 1.0, 1e-10);
      }
  EXPECT_EQ(f.solve_slip_rate(0.0, 120e6, 0.6, kdt, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(f.solve_slip_rate(1e6, 0.0, 0.6, kdt, 1.0), 1e6 / kdt);  // no compression
}

TEST(RateStateLaw, initial_state_balances_the_initial_traction) {
  // TPV101: theta = 1.606239e9 s at V_ini = 1e-12 m/s, tau0 = 75 MPa, sigma = 120 MPa (the
  // benchmark's own number, ../shared/validation/tpv101-2d-uguca/README.md).
  const RateStateFriction f = law();
  const double theta = f.dc / f.v0 * std::exp((f.psi_init - f.f0) / f.b);
  EXPECT_NEAR(theta / 1.606239e9, 1.0, 1e-6);
  EXPECT_NEAR(120e6 * f.friction(1e-12, f.psi_init), 75e6, 1e-6);
  RateStateFriction g = f;
  g.tn0 = 0.0;
  EXPECT_FALSE(g.initialize_state());
}

TEST(RateStateLaw, a_point_at_its_initial_balance_stays_there) {
  const RateStateFriction f = law();
  GaussHistory h;
  h.duration = 5e-3;
  for (int step = 1; step <= 100; ++step) {
    h.time = step * 5e-3;
    const LawResponse r = f.respond(0.0, 0.0, h);
    EXPECT_LT(std::fabs(r.tt), 1e-3) << step;  // Pa: V ~ 1e-12 m/s through kt dt
    EXPECT_EQ(r.tn, 0.0);
  }
  EXPECT_NEAR(f.v_init + h.rate, 1e-12, 1e-14);
  EXPECT_LT(h.damage, 1e-12);
}

TEST(RateStateLaw, loading_slides_on_the_friction_law_and_the_tangent_is_bounded_by_kt) {
  const RateStateFriction f = law();
  const double kt = f.stick_stiffness, dt = 5e-3;
  GaussHistory h;
  h.duration = dt;
  double jump = 0.0;
  for (int step = 1; step <= 400; ++step) {
    jump += 2e-3;  // the bulk pulls the faces apart along t at 0.4 m/s
    h.time = step * dt;
    GaussHistory before = h;
    const LawResponse r = f.respond(0.0, jump, h);
    const double T = f.tt0 + r.tt, V = f.v_init + h.rate;
    // the traction is the friction of the step's rate and state, and the spring's
    EXPECT_NEAR(T, 120e6 * f.friction(V, f.psi_init + h.state), 1e-6 * T);
    EXPECT_NEAR(r.tt, kt * (jump - h.slip), 1e-6 * std::fabs(T));
    // tangent dT/dDt by central differences: in [0, kt]
    const double d = 1e-9;
    GaussHistory hp = before, hm = before;
    const double tp = f.respond(0.0, jump + d, hp).tt, tm = f.respond(0.0, jump - d, hm).tt;
    const double tangent = (tp - tm) / (2 * d);
    EXPECT_GE(tangent, -1e-6 * kt);
    EXPECT_LE(tangent, kt * (1 + 1e-6));
  }
  // the point ends near steady sliding at 0.4 m/s
  EXPECT_NEAR(f.v_init + h.rate, 0.4, 0.01);
  EXPECT_NEAR(f.psi_init + h.state, f.steady_state(0.4), 1e-3);
}

TEST(RateStateLaw, open_faces_carry_nothing) {
  const RateStateFriction f = law();
  GaussHistory h;
  h.duration = 1e-3, h.time = 1e-3;
  const double dn = 1.0;  // tn0 + kn dn > 0
  const LawResponse r = f.respond(dn, 0.01, h);
  EXPECT_DOUBLE_EQ(r.tn, -f.tn0);
  EXPECT_DOUBLE_EQ(r.tt, -f.tt0);
  EXPECT_NEAR(h.slip, 0.01 + f.tt0 / f.stick_stiffness, 1e-15);
}

TEST(RateStateLaw, nucleation_stress_shape_and_ramp) {
  RateStateFriction f = law();
  f.nucleation_stress = 25e6, f.nucleation_radius = 3000.0, f.nucleation_time = 1.0;
  EXPECT_DOUBLE_EQ(f.nucleation_shape(0.0, 0.0), std::exp(0.0));
  EXPECT_NEAR(f.nucleation_shape(1500.0, 0.0), std::exp(-1.0 / 3.0), 1e-15);
  EXPECT_EQ(f.nucleation_shape(3000.0, 0.0), 0.0);
  EXPECT_EQ(f.nucleation_ramp(0.0), 0.0);
  EXPECT_NEAR(f.nucleation_ramp(0.5), std::exp(0.25 / (0.5 * -1.5)), 1e-15);
  EXPECT_EQ(f.nucleation_ramp(1.0), 1.0);
  EXPECT_DOUBLE_EQ(f.shear_prestress(0.0, 0.0, 2.0), 100e6);
  f.nucleation_radius = 0.0, f.nucleation_time = 0.0;  // uniform step
  EXPECT_DOUBLE_EQ(f.shear_prestress(1e5, 7.0, 1e-9), 100e6);
  EXPECT_DOUBLE_EQ(f.shear_prestress(1e5, 7.0, 0.0), 75e6);
}

TEST(RateStateLaw, bad_parameters_are_named) {
  const auto message = [](auto edit) {
    RateStateFriction f = law();
    edit(f);
    f.initialize_state();
    return f.validate();
  };
  EXPECT_EQ(message([](RateStateFriction&) {}), "");
  EXPECT_NE(message([](RateStateFriction& f) { f.a = 0; }).find("a = 0: must be > 0"), std::string::npos);
  EXPECT_NE(message([](RateStateFriction& f) { f.b = -1; }).find("b = -1: must be > 0"), std::string::npos);
  EXPECT_NE(message([](RateStateFriction& f) { f.dc = 0; }).find("dc = 0"), std::string::npos);
  EXPECT_NE(message([](RateStateFriction& f) { f.v0 = 0; }).find("reference_slip_rate = 0"), std::string::npos);
  EXPECT_NE(message([](RateStateFriction& f) { f.v_init = 0; }).find("initial_slip_rate = 0"), std::string::npos);
  EXPECT_NE(message([](RateStateFriction& f) { f.tn0 = 1e6; }).find("compression"), std::string::npos);
  EXPECT_NE(message([](RateStateFriction& f) { f.tt0 = 0; }).find("initial_traction = 0"), std::string::npos);
  EXPECT_NE(message([](RateStateFriction& f) {
              f.evolution = StateEvolution::flash_heating, f.vw = 0;
            }).find("weakening_slip_rate"),
            std::string::npos);
}

TEST(RateStateLaw, taper_blends_the_parameters_and_keeps_the_initial_balance) {
  // TPV101: a = 0.008 within 15 km, 0.016 beyond 18 km, B(x) = 0.5 [1 + tanh(w/(x - W - w) +
  // w/(x - W))] between (W = 15 km, w = 3 km).
  RateStateFriction f = law();
  f.taper.on = true, f.taper.half_width = 15e3, f.taper.width = 3e3, f.taper.a = 0.016;
  EXPECT_EQ(f.validate(), "");
  EXPECT_EQ(f.taper.weight(14e3, 0.0), 1.0);
  EXPECT_EQ(f.taper.weight(18e3, 0.0), 0.0);
  EXPECT_NEAR(f.taper.weight(16.5e3, 0.0), 0.5, 1e-15);  // tanh(-2 + 2) = 0
  const double x = 16e3, B = 0.5 * (1.0 + std::tanh(3e3 / (x - 18e3) + 3e3 / (x - 15e3)));
  EXPECT_NEAR(f.taper.weight(-x, 0.0), B, 1e-15);  // symmetric about the centre
  for (double px : {0.0, 15.5e3, 16e3, 17.9e3, 25e3}) {
    const RateStateFriction l = f.at(px, 0.0);
    const double w = f.taper.weight(px, 0.0);
    EXPECT_NEAR(l.a, 0.016 + (0.008 - 0.016) * w, 1e-15) << px;
    EXPECT_EQ(l.b, f.b);  // untapered
    EXPECT_NEAR(120e6 * l.friction(l.v_init, l.psi_init), 75e6, 1e-6) << "balanced at " << px;
    // the response at the point is the local law's
    GaussHistory h1, h2;
    h1.x = h2.x = px, h1.duration = h2.duration = 5e-3;
    EXPECT_EQ(f.respond(0.0, 1e-3, h1).tt, l.respond(0.0, 1e-3, h2).tt);
  }
  f.taper.width = 0.0;
  EXPECT_NE(f.validate().find("taper.width"), std::string::npos);
}
