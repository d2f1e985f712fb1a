// Verification against analytic 1D elastodynamics (theory E1, E4-E6): a plane-strain strip
// hit at one end carries a step wave at c_D (P) or c_S (S) with plateau stress rho c v.
#include <gtest/gtest.h>

#include <cmath>

#include "material/elastic.hpp"
#include "wave_helpers.hpp"

using namespace rupture;

namespace {
const ElasticMaterial kHomalite{"homalite", 5.2e9, 0.34, 1246.0};
}

TEST(Waves, longitudinal_step_wave_arrival_and_plateau_match_analytic) {
  const double h = 0.25e-3, V = 1.0, length = 0.03;
  const double cd = wave_speeds(kHomalite, PlaneMode::strain).dilatational;
  const double plateau = -kHomalite.density * cd * V;  // compressive sigma_xx = -rho c_D V
  State s = make_state(test::strip_1d(length, 4 * h, h, "x", V, 10e-6));
  const double x = 0.015;
  const double t_arrival = test::arrival_time(s, 10e-6, x, 0.25 * h, &Particles::sxx, plateau);
  const double expected = x / cd;
  EXPECT_NEAR(t_arrival, expected, 0.02 * expected) << "P-wave arrival at x = 15 mm";
  while (s.time < 10e-6) step(s);
  const double measured = test::mean_over(s.particles, s.particles.sxx, 0.003, 0.012);
  EXPECT_NEAR(measured, plateau, 0.02 * std::fabs(plateau)) << "plateau sigma_xx = rho c_D V";
  // Uniaxial strain: sigma_yy = sigma_zz = nu/(1-nu) sigma_xx behind the front.
  const double lateral = test::mean_over(s.particles, s.particles.syy, 0.003, 0.012);
  EXPECT_NEAR(lateral, 0.34 / 0.66 * plateau, 0.02 * std::fabs(plateau));
  std::printf("P wave: arrival %.4f us (analytic %.4f us), plateau %.5g Pa (analytic %.5g Pa)\n",
              t_arrival * 1e6, expected * 1e6, measured, plateau);
}

TEST(Waves, measured_p_and_s_wave_speeds_match_spec_E1) {
  const double h = 0.25e-3;
  const WaveSpeeds w = wave_speeds(kHomalite, PlaneMode::strain);
  struct Probe {
    const char* drive;
    const std::vector<double> Particles::*stress;
    double c;
  };
  for (const Probe& pr : {Probe{"x", &Particles::sxx, w.dilatational}, Probe{"y", &Particles::sxy, w.shear}}) {
    const double plateau = -kHomalite.density * pr.c * 1.0;
    const double x1 = 0.005, x2 = 0.012, end = 1.2 * x2 / pr.c + 1e-6;
    State s = make_state(test::strip_1d(0.02, 4 * h, h, pr.drive, 1.0, end));
    const double t1 = test::arrival_time(s, end, x1, 0.25 * h, pr.stress, plateau);
    const double t2 = test::arrival_time(s, end, x2, 0.25 * h, pr.stress, plateau);
    const double speed = (x2 - x1) / (t2 - t1);
    EXPECT_NEAR(speed, pr.c, 0.02 * pr.c) << pr.drive << "-driven wave";
    std::printf("%s wave: measured %.1f m/s, theory E1 %.1f m/s (%.2f %%)\n",
                pr.drive[0] == 'x' ? "P" : "S", speed, pr.c, 100 * (speed - pr.c) / pr.c);
  }
}

TEST(Waves, every_update_scheme_propagates_the_p_wave) {
  const double h = 0.25e-3, V = 1.0;
  const double cd = wave_speeds(kHomalite, PlaneMode::strain).dilatational;
  for (const char* scheme : {"MUSL", "USL", "USF"}) {
    State s = make_state(test::strip_1d(0.02, 4 * h, h, "x", V, 6e-6, scheme));
    const double t = test::arrival_time(s, 6e-6, 0.01, 0.25 * h, &Particles::sxx, -kHomalite.density * cd * V);
    EXPECT_NEAR(t, 0.01 / cd, 0.02 * 0.01 / cd) << scheme;
  }
}

// The driven edge is material: pushed at V it moves by V t, here ten cells. The condition must
// follow it (bc/velocity_bc.hpp) or the nodes of the initial edge line lose their mass after about
// one cell and the pulse stops (the external work then levels off). Analytic for a step push:
// behind the front the material moves at V under sigma_xx = -rho c_D V, and the push does work
// at the rate rho c_D V^2 per unit edge length.
TEST(Waves, driven_edge_keeps_pushing_after_moving_ten_cells) {
  const double h = 0.1e-3, V = 100.0, length = 0.03, height = 4 * h, end = 10e-6;
  const double cd = wave_speeds(kHomalite, PlaneMode::strain).dilatational;
  const double rho = kHomalite.density;
  for (bool follow : {true, false}) {
    Case c = test::strip_1d(length, height, h, "x", V, end);
    for (VelocityBC& bc : c.boundary)
      if (bc.name == "drive") bc.follow_edge = follow;
    State s = make_state(c);
    while (s.time < end) step(s);
    const double work = rho * cd * V * V * height * s.time;  // J per unit thickness
    const double u = V * s.time;                             // edge displacement: 10 cells
    const double front = cd * s.time;
    const double vx = test::mean_over(s.particles, s.particles.vx, u + 2e-3, front - 3e-3);
    const double sxx = test::mean_over(s.particles, s.particles.sxx, u + 2e-3, front - 3e-3);
    std::printf("follow_edge=%d: edge moved %.1f cells; external work %.5g J/m (analytic %.5g), "
                "v_x %.4g m/s, sigma_xx %.5g Pa (analytic %.5g)\n",
                int(follow), u / h, s.external_work, work, vx, sxx, -rho * cd * V);
    if (follow) {
      EXPECT_NEAR(s.external_work, work, 0.02 * work);
      EXPECT_NEAR(vx, V, 0.02 * V);
      EXPECT_NEAR(sxx, -rho * cd * V, 0.02 * rho * cd * V);
    } else {
      // A condition fixed to its initial grid line stops driving: the check above would fail.
      EXPECT_LT(s.external_work, 0.5 * work);
    }
  }
}
