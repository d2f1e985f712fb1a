// Rate-and-state friction (cohesive/rate_state.hpp) through the whole time step, against an
// independent integration of the 1D problem (examples/rate_state_1d.toml): a fault between two
// half-spaces, creeping in steady state at V_ini, takes a uniform step dtau of its shear load;
// every point slips alike and radiates plane S waves (Z = rho c_S / 2), so
//   tau0 + dtau - Z V = sigma a asinh[V / (2 V0) exp(psi / a)],
// with the state's own ODE (aging: d theta/dt = 1 - V theta / Dc, psi = f0 + b ln(V0 theta/Dc);
// slip: d psi/dt = -(V / Dc)(psi - f0 + b ln(V / V0))). The test integrates that ODE with RK4 and
// a bisection for V (nothing shared with the law's code) and compares the slip rate V(t) the
// fault's friction sees and its slip, every 0.05 s, within 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"

using namespace rupture;

namespace {

constexpr double kRho = 2670.0, kCs = 3464.0, kSigma = 120e6;
constexpr double kA = 0.008, kB = 0.012, kDc = 0.02, kV0 = 1e-6, kF0 = 0.6;
constexpr double kTau0 = 68684277.46608856, kDtau = 5e6, kVi = 1e-3;

// The 1D ODE, in psi, with V from the radiation balance by bisection.
struct Ode {
  bool aging = true;
  double Z = 0.5 * kRho * kCs;
  double friction(double v, double psi) const {
    return kA * std::asinh(v / (2 * kV0) * std::exp(psi / kA));
  }
  double rate(double psi) const {
    double lo = 0.0, hi = (kTau0 + kDtau) / Z;
    for (int i = 0; i < 200; ++i) {
      const double m = 0.5 * (lo + hi);
      (kSigma * friction(m, psi) + Z * m > kTau0 + kDtau ? hi : lo) = m;
    }
    return 0.5 * (lo + hi);
  }
  double dpsi(double psi) const {
    const double v = rate(psi);
    if (aging) return kB * kV0 / kDc * std::exp((kF0 - psi) / kB) - kB * v / kDc;
    return -(v / kDc) * (psi - (kF0 - kB * std::log(v / kV0)));
  }
  // (time, V, slip) every `every` s to t_end, RK4 at step h.
  std::vector<std::array<double, 3>> solve(double t_end, double every, double h = 2e-5) const {
    double psi = kF0 - kB * std::log(kVi / kV0), slip = 0.0, t = 0.0;  // steady at V_ini
    std::vector<std::array<double, 3>> out;
    const long n = std::lround(t_end / h), per = std::lround(every / h);
    for (long i = 0; i <= n; ++i) {
      if (i % per == 0) out.push_back({t, rate(psi), slip});
      if (i == n) break;
      const double v0 = rate(psi);
      const double k1 = dpsi(psi), k2 = dpsi(psi + 0.5 * h * k1), k3 = dpsi(psi + 0.5 * h * k2),
                   k4 = dpsi(psi + h * k3);
      psi += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      slip += 0.5 * h * (v0 + rate(psi));
      t += h;
    }
    return out;
  }
};

struct Measured {
  std::vector<double> time, rate, slip;  // friction's V (mean over the Gauss points), plastic slip
  double at(const std::vector<double>& y, double t) const {
    for (std::size_t i = 1; i < time.size(); ++i)
      if (time[i] >= t) {
        const double f = (t - time[i - 1]) / (time[i] - time[i - 1]);
        return y[i - 1] + f * (y[i] - y[i - 1]);
      }
    return y.back();
  }
};

Measured run(const std::vector<std::string>& set, double t_end) {
  State s = make_state(load_case(RUPTURE_SOURCE_DIR "/examples/rate_state_1d.toml", set));
  const CohesiveInterface& c = s.interfaces.at(0);
  const RateStateFriction& law = std::get<RateStateFriction>(c.spec.law);
  Measured m;
  while (s.time < t_end * (1.0 - 1e-12)) {
    s.dt_cap = t_end - s.time;
    step(s);
    double v = 0.0, slip = 0.0;
    for (std::size_t i = 0; i < c.gp_rate.size(); ++i) v += law.v_init + c.gp_rate[i], slip += c.gp_slip[i];
    m.time.push_back(s.time);
    m.rate.push_back(v / double(c.gp_rate.size()));
    m.slip.push_back(slip / double(c.gp_rate.size()));
  }
  return m;
}

// The largest relative errors of the slip rate and the slip over the ODE's samples.
struct Errors {
  double rate = 0.0, slip = 0.0;
};

Errors compare(const char* name, const Ode& ode, const Measured& m, double t_end, bool check_slip = true) {
  double worst_v = 0.0, worst_s = 0.0;
  for (const auto& [t, v, slip] : ode.solve(t_end, 0.05)) {
    if (t == 0.0) continue;
    const double mv = m.at(m.rate, t), ms = m.at(m.slip, t);
    std::printf("%s t = %.2f s: V %.5f m/s (ODE %.5f, %+.3f %%), slip %.5f m (ODE %.5f, %+.3f %%)\n",
                name, t, mv, v, 100 * (mv / v - 1), ms, slip, 100 * (ms / slip - 1));
    worst_v = std::max(worst_v, std::fabs(mv / v - 1)), worst_s = std::max(worst_s, std::fabs(ms / slip - 1));
    EXPECT_NEAR(mv / v, 1.0, 0.01) << name << ": slip rate at t = " << t;
    if (check_slip) {
      EXPECT_NEAR(ms / slip, 1.0, 0.01) << name << ": slip at t = " << t;
    }
  }
  std::printf("%s: largest error, slip rate %.3f %%, slip %.3f %%\n", name, 100 * worst_v, 100 * worst_s);
  return {worst_v, worst_s};
}

}  // namespace

TEST(RateState, one_dimensional_fault_follows_the_ode_aging_law) {
  Ode ode;
  const Measured m = run({}, 0.45);
  compare("aging", ode, m, 0.45);
  // the steady sliding rate: tau0 + dtau - Z V = sigma f_ss(V), f_ss = f0 - (b - a) ln(V/V0)
  double lo = 1e-3, hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    (kSigma * (kF0 - (kB - kA) * std::log(mid / kV0)) + ode.Z * mid > kTau0 + kDtau ? hi : lo) = mid;
  }
  std::printf("steady sliding rate %.5f m/s, closed form %.5f m/s\n", m.rate.back(), lo);
  EXPECT_NEAR(m.rate.back() / lo, 1.0, 0.005);
}

// The slip law weakens faster: V reaches 0.67 m/s by 0.05 s. The slip carries the start-up of
// the load step (the ODE's V jumps at 0+, the grid's over its first steps), an error of first
// order in h: the slip is checked at 5 m, and its error must fall from 10 m to 5 m.
TEST(RateState, one_dimensional_fault_follows_the_ode_slip_law) {
  Ode ode;
  ode.aging = false;
  const std::string slip = "interface.fault.evolution=\"slip\"";
  const Errors coarse = compare("slip, 10 m", ode, run({slip}, 0.45), 0.45, false);
  const Errors fine = compare("slip, 5 m", ode,
                              run({slip, "grid.cell_size=5.0", "interface.fault.segments=8"}, 0.2), 0.2, true);
  EXPECT_LT(fine.slip, coarse.slip) << "the slip's start-up error falls with h";
}

// Bad fault input stops before any work, naming the key, the value and the rule.
TEST(RateState, bad_fault_input_is_named) {
  auto error_of = [](const std::vector<std::string>& set) {
    try {
      load_case(RUPTURE_SOURCE_DIR "/examples/rate_state_1d.toml", set);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const struct {
    std::vector<std::string> set;
    std::vector<std::string> expect;
  } cases[] = {
      {{"interface.fault.a=0"}, {"interface.fault.a", "0", "> 0"}},
      {{"interface.fault.b=-0.01"}, {"interface.fault.b", "-0.01", "> 0"}},
      {{"interface.fault.dc=0"}, {"interface.fault.dc", "0", "> 0"}},
      {{"interface.fault.reference_slip_rate=0"}, {"interface.fault.reference_slip_rate", "> 0"}},
      {{"interface.fault.initial_slip_rate=-1"}, {"interface.fault.initial_slip_rate", "-1", "> 0"}},
      {{"interface.fault.initial_traction=[1e6, 70e6]"},
       {"interface.fault.initial_traction", "compression"}},
      {{"interface.fault.initial_traction=[-120e6, 0.0]"},
       {"interface.fault.initial_traction", "must not be 0"}},
      {{"interface.fault.evolution=\"fast\""}, {"interface.fault.evolution", "aging"}},
      {{"interface.fault.evolution=\"flash_heating\""}, {"interface.fault.weakened_friction", "required"}},
      {{"interface.fault.static_friction=0.6"}, {"interface.fault.static_friction", "rate_state"}},
      {{"interface.fault.nucleation_stress=0", "interface.fault.nucleation_radius=100.0"},
       {"interface.fault.nucleation_radius", "needs nucleation_stress"}},
      {{"interface.fault.nucleation_time=-1"}, {"interface.fault.nucleation_time", ">= 0"}},
      {{"interface.fault.profile={along=\"x\",a=[[0.0,0.01]]}"},
       {"interface.fault.profile.a", "at least two points"}},
      {{"interface.fault.profile={along=\"x\",a=[[0.0,0.01],[0.0,0.02]]}"},
       {"interface.fault.profile.a", "increasing strictly", "row 2"}},
      {{"interface.fault.profile={along=\"x\",b=[[0.0,0.01],[1.0,-0.02]]}"},
       {"interface.fault.profile.b", "values > 0", "row 2"}},
      {{"interface.fault.profile={along=\"z\",a=[[0.0,0.01],[1.0,0.02]]}"},
       {"interface.fault.profile.along", "\"s\""}},
      {{"interface.fault.profile={along=\"x\"}"}, {"interface.fault.profile", "at least one of a"}},
      {{"interface.fault.profile={along=\"x\",weakening_slip_rate=[[0.0,0.1],[1.0,0.2]]}"},
       {"interface.fault.profile.weakening_slip_rate", "flash_heating"}},
      {{"interface.fault.profile={along=\"x\",a=[[0.0,0.01],[1.0,0.02]]}",
        "interface.fault.taper={centre=[0.0,0.0],half_width=10.0,width=10.0,a=0.02}"},
       {"interface.fault.profile.a", "also tapered"}},
      {{"interface.fault.profile={along=\"x\",dc=[[0.0,0.01],[1.0,0.02]]}",
        "interface.fault.stretches=[{from=[0.0,0.0],to=[10.0,0.0],dc=0.5}]"},
       {"interface.fault.stretches[0].dc", "tabulated along the fault"}},
  };
  for (const auto& c : cases) {
    const std::string msg = error_of(c.set);
    EXPECT_FALSE(msg.empty()) << c.set[0];
    for (const std::string& e : c.expect)
      EXPECT_NE(msg.find(e), std::string::npos) << c.set[0] << ": '" << e << "' not in: " << msg;
  }
}
