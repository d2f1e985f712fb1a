// Slip-weakening friction (cohesive/slip_weakening.hpp) through the whole time step, against
// the closed-form 1D answer (examples/slip_weakening_1d.toml): a fault between two half-spaces
// under a uniform shear prestress tau0 above its static strength slips everywhere at once and
// radiates plane S waves, so tau0 - (rho c_S / 2) V = strength(slip). With linear weakening
// (w = (tau_s - tau_d) / Dc, Z = rho c_S / 2):
//   slip(t) = (tau0 - tau_s) / w (exp(w t / Z) - 1)        until slip = Dc, at
//   t_c     = (Z / w) ln(1 + w Dc / (tau0 - tau_s)),        then V = (tau0 - tau_d) / Z.
// The same case in millimetres and milliseconds (every length and time x 1e-3, stresses and
// speeds unchanged) must give the same answer scaled: no hidden absolute scale.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"

using namespace rupture;

namespace {

constexpr double kRho = 2670.0, kCs = 3464.0;
constexpr double kNormal = 120e6, kMuS = 0.677, kMuD = 0.525, kDc = 0.4, kTau0 = 81.6e6;

struct Analytic {
  double Z = 0.5 * kRho * kCs;
  double tau_s = kMuS * kNormal, tau_d = kMuD * kNormal, w = (tau_s - tau_d) / kDc;
  double slip(double t) const { return (kTau0 - tau_s) / w * std::expm1(w * t / Z); }
  double t_c() const { return Z / w * std::log1p(w * kDc / (kTau0 - tau_s)); }
  double final_rate() const { return (kTau0 - tau_d) / Z; }
};

struct Measured {
  std::vector<double> time, slip;  // mean tangential jump over the fault's nodes, m
  double crack_time = 0.0;         // mean time the nodes' slip reached Dc, s
  double at(double t) const {      // slip at t, linear between steps
    for (std::size_t i = 1; i < time.size(); ++i)
      if (time[i] >= t) {
        const double f = (t - time[i - 1]) / (time[i] - time[i - 1]);
        return slip[i - 1] + f * (slip[i] - slip[i - 1]);
      }
    return slip.back();
  }
};

// Runs the example with every length and time scaled by L (L = 1: metres and seconds).
Measured run(double L) {
  auto num = [](double v) {
    char b[64];
    std::snprintf(b, sizeof b, "%.17g", v);
    return std::string(b);
  };
  auto pair = [&](double a, double b) {
    std::string s = "[";  // appended, not "[" + ...: GCC 12 warns (-Wrestrict) on the latter
    s += num(a);
    s += ',';
    s += num(b);
    s += ']';
    return s;
  };
  std::vector<std::string> set;
  if (L != 1.0)
    set = {"grid.min=" + pair(0.0, -1000.0 * L),     "grid.max=" + pair(40.0 * L, 1000.0 * L),
           "grid.cell_size=" + num(10.0 * L),        "bodies.upper.max=" + pair(40.0 * L, 1000.0 * L),
           "bodies.lower.min=" + pair(0.0, -1000.0 * L), "bodies.lower.max=" + pair(40.0 * L, 0.0),
           "interface.fault.end=" + num(40.0 * L),    "interface.fault.dc=" + num(kDc * L),
           "loads.plane_wave.min=" + pair(0.0, -1000.0 * L),
           "loads.plane_wave.max=" + pair(40.0 * L, 1000.0 * L), "time.end=" + num(0.55 * L),
           "stations.fault_centre.at=" + pair(20.0 * L, 0.0),
           "stations.above_500m.at=" + pair(20.0 * L, 500.0 * L)};
  State s = make_state(load_case(RUPTURE_SOURCE_DIR "/examples/slip_weakening_1d.toml", set));
  Measured m;
  const CohesiveInterface& c = s.interfaces.at(0);
  while (s.time < 0.55 * L * (1.0 - 1e-12)) {
    s.dt_cap = 0.55 * L - s.time;
    step(s);
    double mean = 0.0;
    for (std::size_t k = 0; k < c.num_nodes(); ++k) mean += c.jump_tangential(k);
    m.time.push_back(s.time / L);
    m.slip.push_back(mean / double(c.num_nodes()) / L);
  }
  for (std::size_t k = 0; k < c.num_nodes(); ++k) m.crack_time += c.node_crack_time[k];
  m.crack_time /= double(c.num_nodes()) * L;
  return m;
}

}  // namespace

TEST(SlipWeakening, one_dimensional_fault_slips_as_the_closed_form_answer) {
  const Analytic a;
  const Measured m = run(1.0);
  const double v = (m.at(0.54) - m.at(0.46)) / 0.08;
  std::printf("t_c: measured %.6f s, exact %.6f s (%+.3f %%); final slip rate %.5f m/s, exact "
              "%.5f m/s (%+.3f %%)\n",
              m.crack_time, a.t_c(), 100.0 * (m.crack_time / a.t_c() - 1.0), v, a.final_rate(),
              100.0 * (v / a.final_rate() - 1.0));
  EXPECT_NEAR(m.crack_time / a.t_c(), 1.0, 0.01) << "time to reach Dc within 1 %";
  EXPECT_NEAR(v / a.final_rate(), 1.0, 0.01) << "slip rate after weakening within 1 %";
  // The weakening stage: slip and slip rate on the exponential, where the slip is a sizeable
  // fraction of Dc (the first steps carry the start-up of the sudden stress drop).
  for (double t : {0.2, 0.3, 0.35, 0.39}) {
    const double rate = (m.at(t + 0.005) - m.at(t - 0.005)) / 0.01;
    const double exact_rate = (a.slip(t + 0.005) - a.slip(t - 0.005)) / 0.01;
    std::printf("t = %.3f s: slip %.5f m (exact %.5f, %+.3f %%), rate %.4f m/s (exact %.4f, "
                "%+.3f %%)\n",
                t, m.at(t), a.slip(t), 100.0 * (m.at(t) / a.slip(t) - 1.0), rate, exact_rate,
                100.0 * (rate / exact_rate - 1.0));
    EXPECT_NEAR(rate / exact_rate, 1.0, 0.01) << "slip rate at t = " << t;
    EXPECT_NEAR(m.at(t) / a.slip(t), 1.0, 0.02) << "slip at t = " << t;
  }
  // Millimetres and milliseconds: the same numbers (round-off apart).
  const Measured mm = run(1e-3);
  std::printf("scaled x 1e-3: t_c %.9f s, slip(0.5) %.9f m (metres: %.9f, %.9f)\n",
              mm.crack_time, mm.at(0.5), m.crack_time, m.at(0.5));
  EXPECT_NEAR(mm.crack_time / m.crack_time, 1.0, 1e-6);
  EXPECT_NEAR(mm.at(0.5) / m.at(0.5), 1.0, 1e-6);
}

// Bad fault input stops before any work, naming the key, the value and the rule.
TEST(SlipWeakening, bad_fault_input_is_named) {
  auto error_of = [](const std::vector<std::string>& set) {
    try {
      load_case(RUPTURE_SOURCE_DIR "/examples/slip_weakening_1d.toml", set);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const struct {
    std::vector<std::string> set;
    std::vector<std::string> expect;
  } cases[] = {
      {{"interface.fault.dynamic_friction=0.7"},
       {"interface.fault.dynamic_friction", "0.7", "[0, static_friction = 0.677]"}},
      {{"interface.fault.dc=0"}, {"interface.fault.dc", "0", "> 0"}},
      {{"interface.fault.dc=-1"}, {"interface.fault.dc", "-1", "> 0"}},
      {{"interface.fault.overstressed=false"},
       {"interface.fault.initial_traction", "exceeds the static strength", "everywhere"}},
      {{"interface.fault.friction=0.3"}, {"interface.fault.friction", "slip_weakening"}},
      {{"interface.fault.delta_n=1e-6"}, {"interface.fault.delta_n", "not a parameter"}},
      {{"interface.fault.initial_traction=[1.0]"}, {"interface.fault.initial_traction", "two"}},
      {{"interface.fault.normal_relaxation=\"slip\""},
       {"interface.fault.normal_relaxation_slip", "required with normal_relaxation = \"slip\""}},
      {{"interface.fault.normal_relaxation=\"fast\""}, {"interface.fault.normal_relaxation", "time"}},
      {{"interface.fault.normal_relaxation=\"slip\"", "interface.fault.normal_relaxation_time=0.1"},
       {"interface.fault.normal_relaxation_time", "not a parameter of normal_relaxation = \"slip\""}},
      {{"interface.fault.normal_relaxation=\"time\"", "interface.fault.normal_relaxation_time=-1"},
       {"interface.fault.normal_relaxation_time", "-1", "> 0"}},
      {{"interface.fault.normal_relaxation=\"slip\"", "interface.fault.normal_relaxation_slip=0.1",
        "interface.fault.normal_relaxation_rate=-2"},
       {"interface.fault.normal_relaxation_rate", "-2", ">= 0"}},
      {{"interface.fault.stretches=[{from=[0.0,0.0],to=[10.0,0.0],normal_relaxation=\"time\"}]"},
       {"normal_relaxation"}},
  };
  for (const auto& c : cases) {
    const std::string msg = error_of(c.set);
    EXPECT_FALSE(msg.empty()) << c.set[0];
    for (const std::string& e : c.expect)
      EXPECT_NE(msg.find(e), std::string::npos) << c.set[0] << ": '" << e << "' not in: " << msg;
  }
}
