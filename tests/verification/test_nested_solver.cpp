// Verification of the time step on nested levels (solver/nested_state.hpp, theory §5): the
// refinement checks of test_refinement.cpp (a plane wave through coarse -> fine -> coarse
// transitions: < 2 % reflected, arrival within 1 %, energy balance within 1 %) now with the
// real phases of the solver on each level, and a free block translating through transitions
// (particles migrating between levels): mass, momentum and the rigid motion exact to round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "run/checkpoint.hpp"
#include "material/elastic.hpp"
#include "solver/energy.hpp"
#include "solver/nested_state.hpp"
#include "wave_helpers.hpp"

using namespace rupture;

namespace {

double nested_mean_sxx(const RunState& n, double x0, double x1) {
  double sum = 0;
  int count = 0;
  for (const State& s : n.levels)
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      if (s.particles.x[i] >= x0 && s.particles.x[i] <= x1) sum += s.particles.sxx[i], ++count;
  return count ? sum / count : 0.0;
}

double nested_energy(const RunState& n) {
  double e = 0;
  for (const State& s : n.levels) e += kinetic_energy(s.particles) + strain_energy(s.particles, s.stiffness);
  return e;
}

struct PulseRun {
  std::vector<double> probe_a, time;  // probe_a NaN where the levels are between steps
  double arrival_b = NAN, energy_error = 0.0;
  std::size_t particles = 0;
  long migrations = 0;
};

// The strip of test_refinement.cpp (60 mm, plateau 2 us between a rise and a fall of `rise`,
// rollers on top and bottom) of height `height`, refined by `boxes` (level 2: 0.125 mm) on nested levels, or
// uniform at 0.5 mm on the single grid at the same step.
// With per-level time steps (time.subcycling = "levels") a probe is read only when every level
// has ended its step (NaN in between).
PulseRun pulse(double height, double rise, const std::vector<RefineLevel>& boxes,
               Subcycling subcycling = Subcycling::none, int mirror_period = 1) {
  const double end = 30e-6, v = 1.0;
  Case c = test::strip_1d(0.06, height, 0.5e-3, "x", v, end);
  c.time.subcycling = subcycling;
  for (VelocityBC& bc : c.boundary)
    if (bc.name == "drive") bc.velocity = TimeFunction{TimeFunction::Kind::trapezoid, v, rise, 2e-6, rise};
  c.grid.cell_size = 0.125e-3;
  c.grid.coarse_cell_size = 0.5e-3;
  c.grid.refine = boxes;
  PulseRun r;
  const double amplitude = c.materials[0].density * wave_speeds(c.materials[0], c.plane).dilatational * v;
  double prev_t = 0, prev_b = 0;
  const auto record = [&](double t, double a, double b, double energy, double work) {
    r.probe_a.push_back(a);
    r.time.push_back(t);
    if (std::isnan(r.arrival_b) && std::fabs(b) >= 0.5 * amplitude)
      r.arrival_b = prev_t + (-0.5 * amplitude - prev_b) / (b - prev_b) * (t - prev_t);
    prev_t = t, prev_b = b;
    if (t > 2e-6 + 2 * rise) r.energy_error = std::max(r.energy_error, std::fabs(energy - work) / work);
  };
  if (boxes.empty()) {
    c.time.cfl = 0.1;  // the nested run's finest step (its cells are 4x smaller)
    State s = make_state(c);
    r.particles = s.particles.size();
    const double h = s.dt;
    const VelocityBC* drive = nullptr;
    for (const VelocityBC& bc : c.boundary)
      if (bc.name == "drive") drive = &bc;
    while (s.time < end) {
      // mirror_period > 1: the coarse level's step under per-level time steps, mirror_period
      // finest steps, ended early at the first finest step where the drive changes (those are
      // taken one by one: solver/nested_subcycle.cpp).
      if (mirror_period > 1) {
        int k = 0;
        while (k < mirror_period && drive->velocity(s.time + k * h) == drive->velocity(s.time + (k + 1) * h)) ++k;
        s.forced_dt = double(k == mirror_period ? k : k + 1) * h;
      }
      step(s);
      record(s.time, test::mean_over(s.particles, s.particles.sxx, 0.0095, 0.0105),
             test::mean_over(s.particles, s.particles.sxx, 0.0495, 0.0505),
             kinetic_energy(s.particles) + strain_energy(s.particles, s.stiffness), s.external_work);
    }
    return r;
  }
  RunState n = make_nested_state(c);
  r.particles = held_particles(n);
  while (n.time < end || !n.synchronized()) {
    step(n);
    if (!n.synchronized()) {
      r.probe_a.push_back(NAN);
      r.time.push_back(n.time);
      continue;
    }
    record(n.time, nested_mean_sxx(n, 0.0095, 0.0105), nested_mean_sxx(n, 0.0495, 0.0505),
           nested_energy(n), n.external_work);
  }
  r.migrations = n.migrations;
  return r;
}

void check_pulse(const char* what, double height, double rise, const std::vector<RefineLevel>& boxes,
                 Subcycling subcycling = Subcycling::none) {
  // With per-level steps the uniform 0.5 mm strip takes the coarse level's own step (four
  // finest steps, CFL 0.4, and the finest step while the drive changes, as the nested run's
  // coarse level does): the probe at 10 mm lies on the coarse level, and the comparison then
  // measures the transitions, not the coarse level's longer step.
  const int mirror = subcycling == Subcycling::levels ? 4 : 1;
  const PulseRun nested = pulse(height, rise, boxes, subcycling), plain = pulse(height, rise, {}, Subcycling::none, mirror);
  const Case c = test::strip_1d(0.06, height, 0.5e-3, "x", 1.0, 1.0);
  const double cd = wave_speeds(c.materials[0], c.plane).dilatational;
  const double incident = c.materials[0].density * cd * 1.0;
  const double h = 0.4 * 0.125e-3 / cd;
  double reflected = 0, plateau = 0;
  int in_plateau = 0, compared = 0;
  // At x = 10 mm the plateau lasts from 3.9 us + rise to 5.9 us + rise and the tail has passed
  // by 5.9 us + 2 rise; what the transition at 20 mm sends back arrives from 11.8 us.
  const double arrive = 0.01 / cd;
  std::size_t j = 0;  // the nested sample at the uniform one's time
  for (std::size_t k = 0; k < plain.probe_a.size(); ++k) {
    const double t = plain.time[k];
    if (t > arrive + rise + 0.2e-6 && t < arrive + rise + 1.8e-6) plateau += plain.probe_a[k], ++in_plateau;
    while (j < nested.time.size() && nested.time[j] < t - 1e-3 * h) ++j;
    ASSERT_LT(j, nested.time.size());
    ASSERT_NEAR(nested.time[j], t, 1e-3 * h) << "the nested run has a sample at each uniform step";
    ASSERT_FALSE(std::isnan(nested.probe_a[j])) << "the levels end together at every uniform step";
    ++compared;
    if (t > arrive + 2e-6 + 2 * rise + 0.5e-6)
      reflected = std::max(reflected, std::fabs(nested.probe_a[j] - plain.probe_a[k]));
  }
  plateau /= in_plateau;
  const double expected = 0.05 / cd + 0.5 * rise;
  std::printf("%s: %zu particles nested (%ld migrations), %zu uniform; plateau %.4g Pa (rho c_D V = "
              "%.4g), reflected %.3g Pa (%.2f %%); arrival at 50 mm %.4f us (nested), %.4f us "
              "(uniform), analytic %.4f us; energy error %.2e / %.2e\n",
              what, nested.particles, nested.migrations, plain.particles, -plateau, incident,
              reflected, 100 * reflected / incident, 1e6 * nested.arrival_b, 1e6 * plain.arrival_b,
              1e6 * expected, nested.energy_error, plain.energy_error);
  EXPECT_NEAR(-plateau, incident, 0.05 * incident) << "the incident pulse itself";
  EXPECT_LT(reflected, 0.02 * incident);
  EXPECT_NEAR(nested.arrival_b, expected, 0.01 * expected);
  if (subcycling == Subcycling::none) {
    EXPECT_LT(nested.energy_error, 0.01) << "energy balance through the nested levels";
  } else {
    // MUSL's own energy error at the coarse level's step (CFL 0.4 on 0.5 mm cells: 1.3-1.7 %
    // in the uniform strip) is the baseline; the transitions may add a quarter of a percent.
    EXPECT_LT(plain.energy_error, 0.02);
    EXPECT_LT(nested.energy_error, plain.energy_error + 0.0025) << "energy balance through the nested levels";
  }
}

}  // namespace

// The refined strip of test_refinement.cpp: x in [20, 40] mm at 0.125 mm over the full height
// (two intermediate 0.25 mm bands from the nesting), transitions across the path only.
TEST(NestedSolver, plane_wave_crosses_nested_levels_across_the_path) {
  check_pulse("full-height box", 0.001, 1e-6, {{"fine", {0.02, 0.0}, {0.04, 0.001}, 2}});
}

// A band in the middle of a 4 mm strip: hanging nodes also along the band's top and bottom.
// Most of the path is coarse here, so the pulse rises over 2 us (ten coarse cells): with 1 us
// the uniform 0.5 mm strip itself is 1.2 % late at 50 mm (dispersion), the nested one 1.1 %.
TEST(NestedSolver, plane_wave_crosses_a_nested_band_with_hanging_nodes_along_it) {
  check_pulse("middle band", 0.004, 2e-6,
              {{"band", {0.02, 0.001}, {0.04, 0.003}, 1}, {"core", {0.024, 0.0015}, {0.036, 0.0025}, 2}});
}

// The same two checks with per-level time steps (solver/nested_subcycle.cpp): the coarse
// 0.5 mm strip steps once every 4 finest steps, the 0.25 mm bands every 2.
TEST(NestedSolver, per_level_steps_plane_wave_crosses_nested_levels_across_the_path) {
  check_pulse("full-height box, per-level steps", 0.001, 1e-6, {{"fine", {0.02, 0.0}, {0.04, 0.001}, 2}},
              Subcycling::levels);
}
TEST(NestedSolver, per_level_steps_plane_wave_crosses_a_nested_band_with_hanging_nodes) {
  check_pulse("middle band, per-level steps", 0.004, 2e-6,
              {{"band", {0.02, 0.001}, {0.04, 0.003}, 1}, {"core", {0.024, 0.0015}, {0.036, 0.0025}, 2}},
              Subcycling::levels);
}

namespace {

// A free Homalite block [2, 10] x [2, 8] mm at 40 m/s in a 20 x 10 mm domain of 1 mm cells,
// with one refinement box of the given level (1: 0.5 mm, 2: 0.25 mm).
Case moving_block(const char* box_min, const char* box_max, int level) {
  const std::string grid = fmt::format(R"(
[grid]
min = [0.0, 0.0]
max = [0.02, 0.01]
cell_size = {}
coarse_cell_size = 1e-3
margin = 0.0
[grid.refine.fine]
min = {}
max = {}
level = {}
)", level == 1 ? 0.5e-3 : 0.25e-3, box_min, box_max, level);
  return parse_case(std::string(test::kHomaliteToml) + grid + R"(
[bodies.block]
material = "homalite"
min = [0.002, 0.002]
max = [0.010, 0.008]
velocity = [40.0, 0.0]
[time]
end = 50e-6
)");
}

// Nodal values (mass, momentum, of any field) on the slaves that condense and distribute skip
// (RunState::active_slaves): they must stay zero, else mass would go missing.
std::size_t nonzero_inactive_slaves(const RunState& n) {
  std::vector<unsigned char> active(n.grid.slaves.size(), 0);
  for (const std::uint32_t k : n.active_slaves) active[k] = 1;
  std::size_t bad = 0;
  for (std::size_t k = 0; k < active.size(); ++k) {
    if (active[k]) continue;
    const GridFields& G = n.levels[n.slave_level[k]].fields;
    for (int f = 0; f < G.num_fields; ++f) {
      const std::size_t e = G.start[std::size_t(f)] + n.slave_node[k];
      bad += G.mass[e] != 0.0 || G.mom_x[e] != 0.0 || G.mom_y[e] != 0.0 || G.force_x[e] != 0.0;
    }
  }
  return bad;
}

// The block moves 2 mm in 50 us through a 0.5 mm box [6, 9] x [3, 7] mm: its coarse particles
// enter the box, its fine ones leave it. The motion must stay a rigid translation (no strain,
// every particle at 40 m/s) with mass and momentum kept to round-off.
void check_rigid_translation(Subcycling subcycling) {
  Case c = moving_block("[0.006, 0.003]", "[0.009, 0.007]", 1);
  c.time.subcycling = subcycling;
  RunState n = make_nested_state(c);
  double mass0 = 0, px0 = 0;
  std::size_t count0 = held_particles(n);
  for (const State& s : n.levels)
    for (std::size_t i = 0; i < s.particles.size(); ++i) mass0 += s.particles.mass[i], px0 += s.particles.mass[i] * s.particles.vx[i];
  while (n.time < 50e-6 || !n.synchronized()) step(n);
  double mass = 0, px = 0, py = 0, worst_v = 0, worst_s = 0;
  std::set<std::uint32_t> ids;
  for (const State& s : n.levels) {
    const Particles& P = s.particles;
    for (std::size_t i = 0; i < P.size(); ++i) {
      mass += P.mass[i], px += P.mass[i] * P.vx[i], py += P.mass[i] * P.vy[i];
      worst_v = std::max({worst_v, std::fabs(P.vx[i] - 40.0), std::fabs(P.vy[i])});
      worst_s = std::max({worst_s, std::fabs(P.sxx[i]), std::fabs(P.syy[i]), std::fabs(P.sxy[i])});
      ids.insert(P.id[i]);
    }
  }
  std::printf("%zu particles, %ld migrations over %ld steps; |v - v0| <= %.2e m/s, |sigma| <= %.2e Pa, "
              "mass %.3e (rel. change %.1e), momentum x %.1e, y %.1e\n",
              held_particles(n), n.migrations, n.step, worst_v, worst_s, mass, (mass - mass0) / mass0,
              (px - px0) / px0, py / px0);
  EXPECT_EQ(held_particles(n), count0);
  EXPECT_EQ(ids.size(), count0) << "ids stay unique through migration";
  EXPECT_GT(n.migrations, 100) << "the block does cross the transitions";
  EXPECT_NEAR(mass, mass0, 1e-14 * mass0);
  EXPECT_NEAR(px, px0, 1e-12 * px0);
  EXPECT_LT(std::fabs(py), 1e-12 * px0);
  EXPECT_LT(worst_v, 1e-9);
  EXPECT_LT(worst_s, 1e-3);  // Pa, against a stress scale rho c_D v0 ~ 1e8 Pa
}

}  // namespace

TEST(NestedSolver, free_block_translates_rigidly_through_transitions) {
  check_rigid_translation(Subcycling::none);
}
TEST(NestedSolver, per_level_steps_free_block_translates_rigidly_through_transitions) {
  check_rigid_translation(Subcycling::levels);
}

// Condense and distribute skip the covered nodes kInactiveDepth cells inside a finer box. The
// block ([2, 10] x [2, 8] mm) moves 6 mm at 40 m/s through a 12 x 6 mm box: its coarse
// particles migrate in lazily (a stencil reaches 1.5 cells) and its fine ones leave on the
// far side; after every step the skipped nodes must still hold nothing, in any field.
TEST(NestedSolver, covered_nodes_out_of_reach_stay_empty) {
  RunState n = make_nested_state(moving_block("[0.004, 0.002]", "[0.016, 0.008]", 1));
  ASSERT_LT(n.active_slaves.size(), n.grid.slaves.size()) << "some covered nodes are skipped";
  std::size_t touched = 0;
  while (n.time < 150e-6) {
    step(n);
    touched += nonzero_inactive_slaves(n);
  }
  std::printf("%zu of %zu slaves active; %ld migrations\n", n.active_slaves.size(), n.grid.slaves.size(),
              n.migrations);
  // The block's coarse part (x in [2, 4] mm: 2 x 6 cells of 1 mm, 4 particles each) enters.
  EXPECT_EQ(n.migrations, 48) << "every coarse particle crosses into the box";
  EXPECT_EQ(touched, 0u) << "a particle reached a covered node deemed out of its level's reach";
}

TEST(NestedSolver, rejects_what_it_does_not_support_yet) {
  Case c = test::strip_1d(0.06, 0.001, 0.5e-3, "x", 1.0, 1e-6);
  EXPECT_THROW(make_nested_state(c), InputError);  // no boxes
  c.grid.cell_size = 0.125e-3;
  c.grid.coarse_cell_size = 0.5e-3;
  c.grid.refine = {{"fine", {0.02, 0.0}, {0.04, 0.001}, 2}};
  c.absorbing_edges = {Edge::right};
  EXPECT_NO_THROW(make_nested_state(c)) << "absorbing edges on nested levels";
  c.time.subcycling = Subcycling::levels;
  try {
    make_nested_state(c);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("with [absorbing]"), std::string::npos) << e.what();
  }
}

// Interfaces on two nested levels (examples/two_planes.toml: the lower plane in a 0.5 mm box,
// the upper one on the 1 mm level around it): each lies on the level holding it, and stays
// there; the run reaches them in input order (RunState::interface). (Its crack against the uniform grid's: levels_two_planes_match_uniform.)
TEST(NestedSolver, interfaces_on_two_levels_step_each_on_its_own) {
  const Case c = load_case(std::string(RUPTURE_SOURCE_DIR) + "/examples/two_planes.toml",
                           {"grid.coarse_cell_size=2e-3", "grid.refinement=\"nested\"",
                            "grid.refine.a={min=[0.0,-0.06],max=[0.075,0.04],level=1}",
                            "grid.refine.b={min=[0.0,-0.06],max=[0.075,0.004],level=2}"});
  RunState s = make_run_state(c);
  ASSERT_TRUE(s.is_nested());
  EXPECT_TRUE(s.holds_interfaces(1) && s.holds_interfaces(2) && !s.holds_interfaces(0));
  EXPECT_EQ(s.interface_levels, (std::vector<int>{2, 1}));
  ASSERT_EQ(s.num_interfaces(), 2u);
  const double y_lower = s.interface(0).y0[0], y_upper = s.interface(1).y0[0];
  EXPECT_EQ(s.levels[2].interfaces.size(), 1u);
  EXPECT_EQ(s.levels[1].interfaces.size(), 1u);
  EXPECT_TRUE(s.levels[0].interfaces.empty());
  for (int k = 0; k < 20; ++k) step(s);
  ASSERT_EQ(s.num_interfaces(), 2u);
  EXPECT_EQ(&s.interface(0), &s.levels[2].interfaces[0]) << "each stays on its level";
  EXPECT_EQ(&s.interface(1), &s.levels[1].interfaces[0]);
  EXPECT_EQ(s.interface(0).y0[0], y_lower) << "input order kept";
  EXPECT_EQ(s.interface(1).y0[0], y_upper);
  EXPECT_TRUE(std::isfinite(s.limits.cohesive_dt) && s.limits.cohesive_dt > 0.0);
}

// The absorbing edge's dashpots on nested levels (set_level_absorbing): an edge on three levels
// with four transitions crossing it. Each dashpot sits on a DOF (a slave's coefficient went to
// its DOFs), and together they are rho c_P and rho c_S times the edge's length, as on one
// lattice (bc/absorbing.hpp), so no part of the edge is damped twice or not at all.
TEST(NestedSolver, absorbing_edge_dashpots_add_up_to_the_edge_over_the_levels) {
  const Case c = load_case(std::string(RUPTURE_SOURCE_DIR) + "/tests/inputs/absorbing_on_levels.toml");
  const RunState n = make_nested_state(c);
  ASSERT_EQ(n.levels.size(), 3u);
  std::vector<std::vector<char>> slave(n.levels.size());
  for (std::size_t l = 0; l < n.levels.size(); ++l) slave[l].assign(n.grid.levels[l].num_nodes(), 0);
  for (std::size_t k = 0; k < n.slave_level.size(); ++k) slave[n.slave_level[k]][n.slave_node[k]] = 1;
  double cn = 0.0, ct = 0.0;
  int on_levels = 0;
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    on_levels += !n.levels[l].absorbing.empty();
    const Grid& g = n.levels[l].grid;
    for (const AbsorbingNode& a : n.levels[l].absorbing) {
      EXPECT_FALSE(slave[l][a.node]) << "level " << l << " node " << a.node << " is a slave";
      EXPECT_NEAR(g.x.node(int(a.node % std::size_t(g.nodes_x()))), 0.08, 1e-12) << "on the right edge";
      EXPECT_EQ(a.nx, 1.0);
      cn += a.c_normal, ct += a.c_tangent;
    }
  }
  EXPECT_EQ(on_levels, 3);
  const WaveSpeeds w = wave_speeds(c.materials[0], c.plane);
  const double rho = c.materials[0].density, length = 0.02;
  EXPECT_NEAR(cn, rho * w.dilatational * length, 1e-12 * rho * w.dilatational * length);
  EXPECT_NEAR(ct, rho * w.shear * length, 1e-12 * rho * w.shear * length);
}

// A particle made on level 0 (1 mm cells) that reaches level 2 (0.25 mm) through a band of
// level 1 only two cells wide breaks the GIMP contract: the run stops and says so.
TEST(NestedSolver, a_particle_two_levels_too_coarse_stops_the_run_with_a_diagnosis) {
  RunState n = make_nested_state(moving_block("[0.008, 0.003]", "[0.016, 0.007]", 2));
  try {
    while (n.time < 50e-6) step(n);
    FAIL() << "no error";
  } catch (const SimulationError& e) {
    const std::string what = e.what();
    std::printf("%s\n", e.what());
    EXPECT_NE(what.find("GIMP contract broken"), std::string::npos);
    EXPECT_NE(what.find("level 2"), std::string::npos);
  }
}

// grid.refinement: "nested" (the default with boxes) or "graded"; nested needs refinement boxes;
// a bad value names the key, the value and the choices. time.subcycling defaults to "levels"
// where per-level steps are verified (MUSL, no [loads], no [absorbing], interfaces on one
// level) and to "none" elsewhere; given, "levels" keeps its refusals.
TEST(NestedSolver, input_chooses_the_realization_and_rejects_bad_values) {
  const std::string base = std::string(test::kHomaliteToml) + R"(
[bodies.block]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.01]
[time]
end = 1e-6
[grid]
min = [0.0, 0.0]
max = [0.02, 0.01]
cell_size = 0.25e-3
)";
  // base with one more line in its [time] table
  const auto with_time_key = [&base](const std::string& line) {
    const std::string key = "end = 1e-6\n";
    std::string text = base;
    return text.insert(text.find(key) + key.size(), line + "\n");
  };
  const std::string boxes = "coarse_cell_size = 1e-3\n[grid.refine.fine]\nmin = [0.008, 0.004]\nmax = [0.012, 0.006]\nlevel = 2\n";
  EXPECT_FALSE(parse_case(base).grid.nested);  // no boxes: nothing to nest
  EXPECT_FALSE(parse_case(base + "refinement = \"graded\"\n" + boxes).grid.nested);
  EXPECT_EQ(parse_case(base + "refinement = \"graded\"\n" + boxes).time.subcycling, Subcycling::none);
  const Case by_default = parse_case(base + boxes);
  EXPECT_TRUE(by_default.grid.nested);
  EXPECT_EQ(by_default.time.subcycling, Subcycling::levels);
  EXPECT_FALSE(by_default.time.subcycling_given);
  const Case nested = parse_case(base + "refinement = \"nested\"\n" + boxes);
  EXPECT_TRUE(nested.grid.nested);
  EXPECT_EQ(nested.time.subcycling, Subcycling::levels);
  // Where per-level steps are not verified the default is one dt for every level.
  const std::string usl = "[solver]\nscheme = \"USL\"\n";
  EXPECT_EQ(parse_case(base + boxes + usl).time.subcycling, Subcycling::none);
  const std::string load = "[loads.pull]\ntype = \"body_force\"\nacceleration = [0.0, -9.81]\n";
  EXPECT_EQ(parse_case(base + boxes + load).time.subcycling, Subcycling::none);
  const std::string edge = "[absorbing]\nedges = [\"right\"]\n";
  EXPECT_EQ(parse_case(base + boxes + edge).time.subcycling, Subcycling::none);
  // Asked for explicitly there, it is refused by name.
  for (const std::string& extra : {usl, load, edge}) {
    const std::string text = with_time_key("subcycling = \"levels\"") + boxes + extra;
    try {
      const Case c = parse_case(text);
      (void)make_state(c);
      ADD_FAILURE() << "no error for " << extra;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("time.subcycling"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(parse_case(with_time_key("subcycling = \"none\"") + boxes).time.subcycling, Subcycling::none);
  for (const Scheme other : {Scheme::USL, Scheme::USF}) {
    Case c = nested;
    c.solver.scheme = other;
    c.time.subcycling = Subcycling::levels;
    EXPECT_THROW(make_nested_state(c), InputError) << "per-level time steps: MUSL only";
  }
  // make_run_state gives the nested run: every level's particles (merged for the writers),
  // the levels stepping; make_state is one grid's.
  RunState s = make_run_state(nested);
  ASSERT_TRUE(s.is_nested());
  EXPECT_EQ(all_particles(s).size(), held_particles(s));
  EXPECT_EQ(s.levels.size(), 3u);
  EXPECT_THROW((void)make_state(nested), std::logic_error);
  step(s);
  EXPECT_EQ(s.step, 1);
  for (const State& l : s.levels) EXPECT_EQ(s.time, l.time);
  for (const auto& [text, words] :
       std::vector<std::pair<std::string, std::vector<std::string>>>{
           {base + "refinement = \"nested\"\n", {"grid.refinement", "nested", "needs grid.coarse_cell_size"}},
           {base + "refinement = \"octree\"\n" + boxes, {"grid.refinement", "octree", "graded", "nested"}},
           // per-level time steps step nested levels; "none" and "levels" only
           {with_time_key("subcycling = \"levels\"") + "refinement = \"graded\"\n" + boxes,
            {"time.subcycling", "levels", "nested"}},
           {with_time_key("subcycling = \"always\"") +
                "refinement = \"nested\"\n" + boxes,
            {"time.subcycling", "always", "none", "levels"}}}) {
    try {
      parse_case(text);
      ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
      for (const std::string& w : words) EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << e.what();
    }
  }
}

// Checkpoints of a nested run (run/checkpoint.cpp): written after particles have moved between
// levels (the block of free_block_translates_rigidly_through_transitions) and re-read into a
// fresh run, they write the same bytes, and the run continues bitwise as the uninterrupted one.
// The reference problem's crop (0.5 mm, levels 1-2) checks the same with its interface.
void check_nested_checkpoint(const Case& c, int before, int after, bool expect_migrations) {
  const CaseSource source{"title = \"x\"\n", "case.toml", {}};
  RunContext a;
  a.s = make_run_state(c);
  ASSERT_TRUE(a.s.is_nested());
  for (int k = 0; k < before || !synchronized(a.s); ++k) step(a.s);  // a checkpoint's time
  const long moved = a.s.migrations;
  const std::string bytes = checkpoint_bytes(source, a);
  RunContext b;
  b.s = make_run_state(c);
  restore_checkpoint_bytes(bytes, "test", b);
  EXPECT_EQ(checkpoint_bytes(source, b), bytes) << "re-written checkpoint differs";
  for (int k = 0; k < after; ++k) step(a.s), step(b.s);
  const Particles &pa = all_particles(a.s), &pb = all_particles(b.s);
  ASSERT_EQ(pa.size(), pb.size());
  const auto same = [](const auto& u, const auto& v) {
    return u.size() == v.size() && std::memcmp(u.data(), v.data(), u.size() * sizeof(u[0])) == 0;
  };
  std::printf("%ld migrations before the checkpoint, %ld after %d more steps\n", moved,
              a.s.migrations, after);
  if (expect_migrations) {
    EXPECT_GT(moved, 0) << "particles have changed level before the checkpoint";
    EXPECT_GT(a.s.migrations, moved) << "and after it";
  }
  EXPECT_TRUE(same(pa.id, pb.id) && same(pa.x, pb.x) && same(pa.vy, pb.vy) && same(pa.sxy, pb.sxy));
  for (std::size_t l = 0; l < a.s.levels.size(); ++l)
    EXPECT_EQ(a.s.levels[l].particles.size(), b.s.levels[l].particles.size());
  EXPECT_EQ(a.s.migrations, b.s.migrations);
  for (std::size_t k = 0; k < a.s.num_interfaces(); ++k)
    EXPECT_TRUE(same(a.s.interface(k).ux_up, b.s.interface(k).ux_up));
  EXPECT_EQ(a.s.time, b.s.time);
  EXPECT_EQ(a.s.external_work, b.s.external_work);
}

TEST(NestedSolver, checkpoint_round_trip_and_continuation_are_bitwise) {
  Case block = moving_block("[0.006, 0.003]", "[0.009, 0.007]", 1);
  block.grid.nested = true;
  check_nested_checkpoint(block, 300, 300, true);
  const Case crop = load_case(std::string(RUPTURE_SOURCE_DIR) + "/examples/rosakis1999.toml",
                              {"grid.min=[0.0,-0.06]", "grid.max=[0.075,0.04]", "bodies.upper.max=[0.075,0.04]",
                               "bodies.lower.min=[0.0,-0.06]", "bodies.lower.max=[0.075,0.0]",
                               "interface.weak_plane.bonded_to=0.075", "grid.refinement=\"nested\""});
  check_nested_checkpoint(crop, 15, 10, false);
  block.time.subcycling = Subcycling::levels;  // per-level time steps: at a step all levels end
  check_nested_checkpoint(block, 301, 301, true);
}

namespace {

// One body of two blocks in one velocity field, [2, 6] and [6, 14] x [2, 8] mm, moving against
// each other along x with zero total momentum and angular momentum (20 and -10 m/s), the right
// one prestressed: waves run through the 0.5 mm box [6, 9] x [3, 7] mm and its transitions for
// as long as the run lasts (a free body: nothing leaves, nothing is added).
Case colliding_blocks(Subcycling subcycling) {
  Case c = parse_case(std::string(test::kHomaliteToml) + R"(
[grid]
min = [0.0, 0.0]
max = [0.02, 0.01]
cell_size = 0.5e-3
coarse_cell_size = 1e-3
margin = 0.0
refinement = "nested"
[grid.refine.fine]
min = [0.006, 0.003]
max = [0.009, 0.007]
level = 1
[bodies.left]
material = "homalite"
min = [0.002, 0.002]
max = [0.006, 0.008]
velocity = [20.0, 0.0]
field = "solid"
[bodies.right]
material = "homalite"
min = [0.006, 0.002]
max = [0.014, 0.008]
velocity = [-10.0, 0.0]
stress = [2e6, -1e6, 5e5]
field = "solid"
[time]
end = 1.0
)");
  c.time.subcycling = subcycling;
  return c;
}

struct Totals {
  double px = 0, py = 0, scale = 0, energy = 0;
};
Totals totals(const RunState& n) {
  Totals t;
  for (const State& s : n.levels) {
    const Particles& P = s.particles;
    for (std::size_t i = 0; i < P.size(); ++i) {
      t.px += P.mass[i] * P.vx[i], t.py += P.mass[i] * P.vy[i];
      t.scale += P.mass[i] * std::hypot(P.vx[i], P.vy[i]);
    }
    t.energy += kinetic_energy(P) + strain_energy(P, s.stiffness);
  }
  return t;
}

// Total momentum (zero) after every step where the levels end together, relative to sum m |v|
// at the start, and the energy relative to the start (no external work): its extremes, and its
// largest value over the first and the last tenth of the run.
struct FreeRun {
  double momentum = 0, energy_lo = 0, energy_hi = 0, early_hi = -INFINITY, late_hi = -INFINITY;
  long steps = 0;
};
FreeRun free_run(Subcycling subcycling, long steps) {
  RunState n = make_nested_state(colliding_blocks(subcycling));
  const Totals t0 = totals(n);
  FreeRun r;
  while (n.step < steps || !n.synchronized()) {
    step(n);
    if (!n.synchronized()) continue;
    const Totals t = totals(n);
    r.momentum = std::max(r.momentum, std::hypot(t.px - t0.px, t.py - t0.py) / t0.scale);
    const double e = t.energy / t0.energy - 1.0;
    r.energy_lo = std::min(r.energy_lo, e), r.energy_hi = std::max(r.energy_hi, e);
    if (n.step <= steps / 10) r.early_hi = std::max(r.early_hi, e);
    if (n.step >= steps - steps / 10) r.late_hi = std::max(r.late_hi, e);
  }
  r.steps = n.step;
  return r;
}

}  // namespace

// The known failure of multi-time-step schemes is a slow growth at the interface between
// step sizes. 20 000 finest steps (the 1 mm level steps every 2): momentum stays zero to
// round-off and the energy does not grow (its largest value over the last tenth of the run
// stays below that over the first tenth; the one-dt run for comparison). With the held
// momentum as the re-mapped one on the band where the levels meet (instead of
// solver/nested_subcycle.cpp's band_remap) the energy doubles by the end (+106 %).
// RUPTURE_LONG_STEPS=100000 runs it longer.
TEST(NestedSolver, per_level_steps_keep_momentum_and_energy_over_a_long_free_vibration) {
  const long steps = std::getenv("RUPTURE_LONG_STEPS") ? std::atol(std::getenv("RUPTURE_LONG_STEPS")) : 20000;
  for (const Subcycling sc : {Subcycling::none, Subcycling::levels}) {
    const FreeRun r = free_run(sc, steps);
    std::printf("%s: %ld steps; momentum %.2e of sum m|v|; energy %+.3e .. %+.3e of E0, largest over "
                "the first tenth %+.3e, the last %+.3e\n",
                sc == Subcycling::none ? "one dt" : "per-level dt", r.steps, r.momentum, r.energy_lo,
                r.energy_hi, r.early_hi, r.late_hi);
    EXPECT_LT(r.momentum, 1e-13);
    EXPECT_LT(r.late_hi, r.early_hi) << "the energy grows";
    EXPECT_LT(r.energy_hi, 0.05);
    EXPECT_GT(r.energy_lo, -0.05);
  }
}

// Four blocks in four velocity fields (20 field arrays in a transition pass: more than one
// pass of kMaxColumns, solver/transitions.cpp) translate rigidly through the level transitions
// (3 mm at 120 m/s: two blocks enter the fine box, two leave it) as one block does: every particle keeps its velocity, no stress arises, mass and momentum
// are kept to round-off.
TEST(NestedSolver, four_fields_translate_rigidly_through_transitions) {
  Case c = parse_case(std::string(test::kHomaliteToml) + R"(
[grid]
min = [0.0, 0.0]
max = [0.02, 0.01]
cell_size = 0.5e-3
coarse_cell_size = 1e-3
margin = 0.0
refinement = "nested"
[grid.refine.fine]
min = [0.006, 0.003]
max = [0.012, 0.007]
level = 1
[bodies.a]
material = "homalite"
min = [0.002, 0.002]
max = [0.005, 0.004]
velocity = [120.0, 0.0]
[bodies.b]
material = "homalite"
min = [0.007, 0.002]
max = [0.010, 0.004]
velocity = [120.0, 0.0]
[bodies.c]
material = "homalite"
min = [0.002, 0.006]
max = [0.005, 0.008]
velocity = [120.0, 0.0]
[bodies.d]
material = "homalite"
min = [0.007, 0.006]
max = [0.010, 0.008]
velocity = [120.0, 0.0]
[time]
end = 25e-6
)");
  ASSERT_EQ(c.field_names.size(), 4u);
  RunState n = make_nested_state(c);
  double mass0 = 0, px0 = 0;
  for (const State& s : n.levels)
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      mass0 += s.particles.mass[i], px0 += s.particles.mass[i] * s.particles.vx[i];
  while (n.time < 25e-6) step(n);
  double mass = 0, px = 0, worst_v = 0, worst_s = 0;
  for (const State& s : n.levels) {
    const Particles& P = s.particles;
    for (std::size_t i = 0; i < P.size(); ++i) {
      mass += P.mass[i], px += P.mass[i] * P.vx[i];
      worst_v = std::max({worst_v, std::fabs(P.vx[i] - 120.0), std::fabs(P.vy[i])});
      worst_s = std::max({worst_s, std::fabs(P.sxx[i]), std::fabs(P.syy[i]), std::fabs(P.sxy[i])});
    }
  }
  std::printf("four fields: %ld steps, %ld migrations, |v - v0| <= %.2e m/s, |sigma| <= %.2e Pa\n", n.step,
              n.migrations, worst_v, worst_s);
  EXPECT_GT(n.migrations, 10) << "blocks cross the transitions";
  EXPECT_NEAR(mass, mass0, 1e-14 * mass0);
  EXPECT_NEAR(px, px0, 1e-12 * px0);
  EXPECT_LT(worst_v, 1e-9);
  EXPECT_LT(worst_s, 1e-3);  // Pa, against rho c_D v0 ~ 4e8 Pa
}
