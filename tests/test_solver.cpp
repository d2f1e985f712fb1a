// Tests of solver/: conservation properties of single phases and the instability diagnoses.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <cstdio>
#include <sstream>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "run/driver.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {
State strip_state(const std::vector<std::string>& overrides = {}) {
  return make_state(parse_case(test::strip_case_toml(), overrides));
}
// The diagnosis message m reports a finite region "x in [x0, x1], y in [y0, y1]" that holds
// (x, y) and spans less than 3 mm along x (local to where the run went bad).
void expect_local_region_holding(const std::string& m, double x, double y) {
  double x0, x1, y0, y1;
  const auto pos = m.find("x in [");
  ASSERT_NE(pos, std::string::npos) << m;
  ASSERT_EQ(std::sscanf(m.c_str() + pos, "x in [%lf, %lf], y in [%lf, %lf]", &x0, &x1, &y0, &y1), 4) << m;
  EXPECT_TRUE(x >= x0 && x <= x1 && y >= y0 && y <= y1) << m;
  EXPECT_LT(x1 - x0, 0.003) << "region should be local: " << m;
}
}  // namespace

TEST(Solver, particle_to_grid_conserves_mass_and_momentum) {
  State s = strip_state();
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    s.particles.vx[p] = 1.0 + 0.1 * std::sin(double(p));
    s.particles.vy[p] = -0.5 + 0.2 * std::cos(double(p));
  }
  build_scatter_plan(s);
  particles_to_grid(s, true);
  double pm = 0, px = 0, py = 0, gm = 0, gx = 0, gy = 0, fx = 0, fy = 0;
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    pm += s.particles.mass[p];
    px += s.particles.mass[p] * s.particles.vx[p];
    py += s.particles.mass[p] * s.particles.vy[p];
  }
  for (std::size_t i = 0; i < s.fields.mass.size(); ++i) {
    gm += s.fields.mass[i];
    gx += s.fields.mom_x[i];
    gy += s.fields.mom_y[i];
    fx += s.fields.force_x[i];
    fy += s.fields.force_y[i];
  }
  EXPECT_NEAR(gm, pm, 1e-13 * pm);
  EXPECT_NEAR(gx, px, 1e-13 * std::fabs(px));
  EXPECT_NEAR(gy, py, 1e-13 * std::fabs(py));
  EXPECT_EQ(fx, 0.0);  // stress-free body
  EXPECT_EQ(fy, 0.0);
}

TEST(Solver, internal_forces_sum_to_zero_for_any_stress_field) {
  State s = strip_state();
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    s.particles.sxx[p] = 1e6 * std::sin(0.3 * double(p));
    s.particles.syy[p] = 2e5 * std::cos(0.7 * double(p));
    s.particles.sxy[p] = -3e5 * std::sin(1.1 * double(p));
  }
  build_scatter_plan(s);
  particles_to_grid(s, true);
  double fx = 0, fy = 0, scale = 0;
  for (std::size_t i = 0; i < s.fields.mass.size(); ++i) {
    fx += s.fields.force_x[i];
    fy += s.fields.force_y[i];
    scale += std::fabs(s.fields.force_x[i]);
  }
  // Newton's third law in discrete form: gradients of a partition of unity sum to zero.
  EXPECT_NEAR(fx, 0.0, 1e-12 * scale);
  EXPECT_NEAR(fy, 0.0, 1e-12 * scale);
}

TEST(Solver, rigid_translation_is_exact_and_stress_free) {
  State s = strip_state({"boundary.push.velocity=0", "boundary.push.edge=\"right\""});
  s.boundary.clear();
  s.bc_nodes.clear();
  for (std::size_t p = 0; p < s.particles.size(); ++p) s.particles.vx[p] = 2.0, s.particles.vy[p] = -1.0;
  const std::vector<double> x0 = s.particles.x;
  for (int k = 0; k < 20; ++k) step(s);
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    EXPECT_NEAR(s.particles.vx[p], 2.0, 1e-9);  // round-off only
    EXPECT_NEAR(s.particles.x[p] - x0[p], 2.0 * s.time, 1e-12);
    EXPECT_NEAR(s.particles.sxx[p], 0.0, 1e-3);
  }
}

// MUSL's stress pass does not read the particle velocity: a non-finite one (NaN, or infinite,
// whose S = 0 terms are NaN) reaches the momentum of all its nodes, hence the stress of its
// neighbours and its own in the same step, which the pass checks.
TEST(Solver, non_finite_velocity_is_caught_in_the_same_musl_step) {
  for (const double bad : {double(NAN), double(INFINITY)}) {
    State s = strip_state();
    ASSERT_EQ(s.scheme, Scheme::MUSL);
    std::size_t seed = 0;
    while (s.particles.id[seed] != 41) ++seed;
    s.particles.vy[seed] = bad;
    const double x = s.particles.x[seed], y = s.particles.y[seed];
    try {
      step(s);
      FAIL() << "no SimulationError for v_y = " << bad;
    } catch (const SimulationError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("unstable: non-finite"), std::string::npos) << m;
      EXPECT_NE(m.find("velocity"), std::string::npos) << m;
      EXPECT_NE(m.find("step 0, t = 0 s"), std::string::npos) << m;
      // The particles the bad velocity reached are not moved with it: the reported region is
      // finite, local, and holds where it started.
      expect_local_region_holding(m, x, y);
    }
  }
}

TEST(Solver, non_finite_state_is_diagnosed_with_particle_and_time) {
  State s = strip_state();
  // The particle created 41st (the solver sorts particles, so look it up by id).
  std::size_t seed = 0;
  while (s.particles.id[seed] != 41) ++seed;
  s.particles.sxx[seed] = NAN;
  const double x = s.particles.x[seed], y = s.particles.y[seed];
  try {
    step(s);
    FAIL() << "no SimulationError";
  } catch (const SimulationError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("non-finite"), std::string::npos) << m;
    EXPECT_NE(m.find("step 0, t = 0 s"), std::string::npos) << m;
    // The reported region must contain the particle that went bad.
    expect_local_region_holding(m, x, y);
  }
}

TEST(Solver, particle_leaving_the_grid_is_diagnosed) {
  State s = strip_state();
  s.particles.vy[7] = 1e6;
  try {
    for (int k = 0; k < 3; ++k) step(s);
    FAIL() << "no SimulationError";
  } catch (const SimulationError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("left the grid"), std::string::npos) << m;
    EXPECT_NE(m.find("step 0"), std::string::npos) << m;
  }
}

TEST(Driver, unstable_run_fails_with_diagnosis_and_keeps_complete_files) {
  const std::string dir = (std::filesystem::temp_directory_path() / "rupture_test_unstable").string();
  std::filesystem::remove_all(dir);
  const Case c = parse_case(test::strip_case_toml(), {"boundary.push.velocity=1e6"});
  RunOptions options;
  options.output_dir = dir;
  options.progress = false;
  const RunResult r = run_case(c, options);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("left the grid"), std::string::npos) << r.message;
  std::ifstream json(dir + "/run.json");
  std::stringstream js;
  js << json.rdbuf();
  EXPECT_NE(js.str().find("\"status\" : \"failed\""), std::string::npos) << js.str();
  std::ifstream hist(dir + "/history.csv");
  std::string header;
  std::getline(hist, header);
  EXPECT_EQ(header.rfind("time,kinetic_energy", 0), 0u);
  EXPECT_FALSE(std::filesystem::exists(dir + "/history.csv.tmp"));
}
