// Verification of the time-step bound (theory E6, docs/time_step.md): the largest eigenvalue of
// the discrete GIMP operator M^-1 K, found by power iteration on the code's own phases,
// against the analytic bound lambda_bulk = (2 c_D / h)^2 the step uses.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <random>

#include "input/case_toml.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "core/errors.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

// Largest eigenvalue of M^-1 K of the bulk (no cohesive forces): K u is the internal force of
// the stress C : grad u (a G2P stress pass with dt = kScale from zero stress, then a P2G force
// pass, divided by kScale). Rayleigh quotient u.K u / u.M u after `iterations` power steps.
// kScale keeps the strain ~ kScale |u| / h ~ 1e-8 small: the force pass takes the area
// V0 (1 + tr eps) from the stress, so K is linear to that order.
double bulk_max_eigenvalue(State& s, int iterations) {
  particles_to_grid(s, false);
  GridFields& G = s.fields;
  const std::size_t n = G.mass.size();
  std::vector<double> ux(n, 0.0), uy(n, 0.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (std::size_t i = 0; i < n; ++i)
    if (G.mass[i] > s.mass_floor) ux[i] = U(rng), uy[i] = U(rng);
  Particles& P = s.particles;
  const Particles saved = P;
  constexpr double kScale = 1e-12;
  s.dt = kScale;
  double lambda = 0.0;
  for (int it = 0; it < iterations; ++it) {
    for (auto* v : {&P.sxx, &P.syy, &P.sxy}) std::fill(v->begin(), v->end(), 0.0);
    G.remap_x = ux, G.remap_y = uy;  // the grid velocity the stress pass reads
    grid_to_particles(s, &GridFields::remap_x, &GridFields::remap_y, G2PMode::stress_only);
    particles_to_grid_force(s);
    double uKu = 0.0, uMu = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (G.mass[i] <= s.mass_floor) continue;
      uKu -= ux[i] * G.force_x[i] + uy[i] * G.force_y[i];
      uMu += G.mass[i] * (ux[i] * ux[i] + uy[i] * uy[i]);
    }
    lambda = uKu / uMu / kScale;
    for (std::size_t i = 0; i < n; ++i) {
      const double m = G.mass[i];
      ux[i] = m > s.mass_floor ? -G.force_x[i] / m : 0.0;
      uy[i] = m > s.mass_floor ? -G.force_y[i] / m : 0.0;
      norm = std::max(norm, std::max(std::fabs(ux[i]), std::fabs(uy[i])));
    }
    for (std::size_t i = 0; i < n; ++i) ux[i] /= norm, uy[i] /= norm;
  }
  P = saved;
  return lambda;
}

// Two Homalite blocks 8 x 4 mm joined by the paper's Xu-Needleman interface along y = 0,
// the upper one pulled up at its top edge (mode I), at cell size h.
Case pulled_pair(double h, double safety) {
  return parse_case(fmt::format(R"({}
[grid]
min = [0.0, -0.004]
max = [0.008, 0.004]
cell_size = {}
[bodies.upper]
material = "homalite"
min = [0.0, 0.0]
max = [0.008, 0.004]
[bodies.lower]
material = "homalite"
min = [0.0, -0.004]
max = [0.008, 0.0]
[interface.w]
upper_body = "upper"
lower_body = "lower"
y = 0.0
start = 0.0
end = 0.008
segments = 4000
sigma_max = 24e6
delta_n = 0.4e-6
[boundary.pull]
edge = "top"
component = "y"
velocity = 0.5
[time]
end = 10e-6
cohesive_safety = {}
)",
                                test::kHomaliteToml, h, safety));
}

}  // namespace

// Momentum (E9): the cohesive forces put on the two fields sum to zero, node by node of the
// interface and in total, to round-off, also next to a bonded stretch, where the faces' stencils
// include tied nodes (both fields' mass). The halves slide past each other (upper at +1 m/s,
// lower at -1 m/s) for 40 steps, then the cohesive phase of one more step is taken apart.
TEST(TimeStep, cohesive_forces_on_the_two_fields_sum_to_zero_next_to_a_bonded_stretch) {
  Case c = pulled_pair(0.5e-3, 0.9);
  c.interfaces[0].end = 0.006;
  c.interfaces[0].segments = 3000;
  c.interfaces[0].bonded = true;
  c.interfaces[0].bonded_from = 0.006;
  c.interfaces[0].bonded_to = 0.008;
  State s = make_state(c);
  for (std::size_t p = 0; p < s.particles.size(); ++p) s.particles.vx[p] = s.particles.field[p] == 0 ? 1.0 : -1.0;
  for (int n = 0; n < 40; ++n) step(s);
  particles_to_grid(s, true);
  tie_bonded_nodes(s, TieWhat::mass_momentum);
  update_face_stencils(s);
  GridFields& G = s.fields;
  std::fill(G.force_x.begin(), G.force_x.end(), 0.0);
  std::fill(G.force_y.begin(), G.force_y.end(), 0.0);
  add_cohesive_forces(s);
  double sum_x = 0, sum_y = 0, scale = 0;
  for (std::size_t i = 0; i < G.force_x.size(); ++i)
    sum_x += G.force_x[i], sum_y += G.force_y[i], scale += std::fabs(G.force_x[i]) + std::fabs(G.force_y[i]);
  const CohesiveInterface& ci = s.interfaces[0];
  double near_bond = 0;  // cohesive force carried by faces whose stencil reaches a tied node
  for (std::size_t k = 0; k < ci.num_nodes(); ++k)
    if (ci.x0[k] > 0.006 - 0.5e-3) near_bond += std::fabs(ci.fx_node[k]);
  std::printf("cohesive force: sum (%.3e, %.3e) N/m against sum |f| %.3e N/m; %.3e N/m within a cell of the bond\n",
              sum_x, sum_y, scale, near_bond);
  EXPECT_GT(near_bond, 0.0) << "the test must load the faces next to the bonded stretch";
  EXPECT_LT(std::fabs(sum_x), 1e-13 * scale);
  EXPECT_LT(std::fabs(sum_y), 1e-13 * scale);
}

// theory E6 at rest: the per-step bound from the face stencils and masses equals the lumped
// estimate `rupture check` prints (faces on their node row, row mass rho h^2 / 2, stiffness
// 2 e sigma_max / delta_n with the penalty), and the step is safety x that.
TEST(TimeStep, per_step_cohesive_bound_at_rest_matches_the_lumped_estimate) {
  // The lumped estimate holds in the interior; the node next to the interface's free end is
  // loaded harder, because there the mass-weighted stencils of the faces in the end cell lean
  // on it (the end node has half the mass): its row sum is (2 k h / m) [1/2 + int_0^1 2u/(1+u)
  // du] = (2 k h / m) [1/2 + 2 (1 - ln 2)] = 1.1137 x the interior one.
  State s = make_state(pulled_pair(0.5e-3, 0.9));
  const double lambda_b = s.limits.bulk_eigen_bound;
  const double lambda_lumped = 4.0 / (s.limits.cohesive_dt * s.limits.cohesive_dt) - lambda_b;
  step(s);
  const double lambda = 4.0 / (s.limits.cohesive_dt * s.limits.cohesive_dt) - lambda_b;
  const double edge = 0.5 + 2.0 * (1.0 - std::log(2.0));
  std::printf("cohesive lambda at rest: %.6e (lumped interior %.6e, ratio %.5f; edge factor %.5f)\n", lambda,
              lambda_lumped, lambda / lambda_lumped, edge);
  EXPECT_NEAR(lambda / lambda_lumped, edge, 2e-3);
  EXPECT_NEAR(s.dt, 0.9 * s.limits.cohesive_dt, 1e-12 * s.dt);
}

// Driven past the bound on purpose (a fixed step 2.5 x the limit), the interface must be
// reported unstable by the oscillation watch before a single node has cracked; at safety 1
// (on the bound) the same case runs to 5 us, past the arrival of the pull at the interface
// (1.6 us), without a report.
TEST(TimeStep, a_step_past_the_cohesive_limit_is_diagnosed_before_anything_cracks) {
  State bad = make_state(pulled_pair(0.5e-3, 0.9));
  bad.forced_dt = 2.5 * bad.limits.cohesive_dt;
  bool caught = false;
  try {
    while (bad.time < 5e-6) step(bad);
  } catch (const SimulationError& e) {
    caught = true;
    const std::string what = e.what();
    std::printf("diagnosis at step %ld: %s\n", bad.step, what.c_str());
    EXPECT_NE(what.find("oscillates at node"), std::string::npos) << what;
  }
  EXPECT_TRUE(caught) << "a step 2.5 x the cohesive limit ran to 5 us unreported";
  for (double t : bad.interfaces[0].node_crack_time) ASSERT_LT(t, 0.0) << "cracked before the diagnosis";

  State good = make_state(pulled_pair(0.5e-3, 1.0));
  EXPECT_NO_THROW(while (good.time < 5e-6) step(good));
}

// The power iteration on the code's operator lands between the interior P mode's exact
// eigenvalue (2 c_D / h)^2 (von Neumann analysis of uGIMP with 2 x 2 particles: the mode
// (-1)^i along x gives eps_xx = 2/h at every particle) and the Gershgorin bound the step uses.
// The two 16 x 8-cell blocks are separate fields. (An independent dense eigensolver of a free
// 10 x 10-cell block gives 1.0291 (2 c_D/h)^2 for nu = 0.34: free edges raise it a little above
// the interior value.)
TEST(TimeStep, bulk_eigenvalue_lies_between_the_interior_P_mode_and_the_gershgorin_bound) {
  const double h = 0.5e-3;
  Case c = pulled_pair(h, 0.9);  // the two blocks, as bulk only
  c.interfaces.clear();
  c.interface_names.clear();
  c.boundary.clear();
  State s = make_state(c);
  const double lambda = bulk_max_eigenvalue(s, 300);
  const double E = 5.2e9, nu = 0.34, rho = 1246.0;
  const double cD = std::sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho));
  const double interior = std::pow(2.0 * cD / h, 2);
  const double bound = s.limits.bulk_eigen_bound;
  std::printf("bulk lambda_max = %.6e 1/s^2 = %.4f (2 c_D/h)^2; Gershgorin bound %.4f (2 c_D/h)^2\n",
              lambda, lambda / interior, bound / interior);
  EXPECT_GE(lambda, interior * (1.0 - 1e-3));
  EXPECT_LE(lambda, bound);
}
