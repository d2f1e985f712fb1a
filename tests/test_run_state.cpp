// Tests of solver/run_state (the run: its levels and the transitions): a single grid is one
// level whose run steps bitwise as the level stepped alone, with the run's clock and sums its
// level's; on nested levels each interface stays on its level for the whole run, the writers'
// particles are every level's (each id once), and the run's sums are the levels' sums.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "solver/run_state.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

template <class T>
bool bitwise_equal(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

Case nested_plate() {
  return load_case(std::string(RUPTURE_SOURCE_DIR) + "/examples/rosakis1999.toml",
                   {"grid.min=[0.0,-0.06]", "grid.max=[0.075,0.04]", "bodies.upper.max=[0.075,0.04]",
                    "bodies.lower.min=[0.0,-0.06]", "bodies.lower.max=[0.075,0.0]",
                    "interface.weak_plane.bonded_to=0.075", "grid.refinement=\"nested\"",
                    "time.subcycling=\"none\""});
}

}  // namespace

TEST(RunState, one_grid_is_one_level_and_steps_as_that_level_alone) {
  const Case c = parse_case(test::strip_case_toml());
  RunState r = make_run_state(c);
  State alone = make_state(c);
  ASSERT_FALSE(r.is_nested());
  ASSERT_EQ(r.levels.size(), 1u);
  ASSERT_EQ(r.num_interfaces(), c.interfaces.size());
  for (std::size_t k = 0; k < r.num_interfaces(); ++k) EXPECT_EQ(&r.interface(k), &r.levels[0].interfaces[k]);
  EXPECT_EQ(&all_particles(r), &r.levels[0].particles) << "one grid: no copy for the writers";
  EXPECT_EQ(r.initial_energy, alone.initial_energy);
  r.dt_cap = alone.dt_cap = INFINITY;
  for (int k = 0; k < 30; ++k) {
    step(r);
    step(alone);
  }
  const State& l = r.levels[0];
  EXPECT_TRUE(bitwise_equal(l.particles.x, alone.particles.x));
  EXPECT_TRUE(bitwise_equal(l.particles.vy, alone.particles.vy));
  EXPECT_TRUE(bitwise_equal(l.particles.sxy, alone.particles.sxy));
  // The run's clock and sums are its level's.
  EXPECT_EQ(r.time, l.time);
  EXPECT_EQ(r.step, 30);
  EXPECT_EQ(r.dt, l.dt);
  EXPECT_EQ(r.strain_work, l.strain_work);
  EXPECT_EQ(r.external_work, l.external_work);
  EXPECT_EQ(r.limits.min_cohesive_dt, l.limits.min_cohesive_dt);
}

TEST(RunState, nested_levels_keep_their_interfaces_and_the_run_sums_the_levels) {
  RunState r = make_run_state(nested_plate());
  ASSERT_TRUE(r.is_nested());
  ASSERT_GT(r.levels.size(), 1u);
  ASSERT_EQ(r.num_interfaces(), 1u);
  const CohesiveInterface* home = &r.interface(0);
  const std::size_t level = std::size_t(r.interface_levels[0]);
  EXPECT_EQ(r.grid_level, level) << "the finest level holding an interface";
  std::size_t on_levels = 0;
  for (const State& l : r.levels) on_levels += l.interfaces.size();
  EXPECT_EQ(on_levels, 1u) << "each interface on one level only";
  r.dt_cap = INFINITY;
  for (int k = 0; k < 20; ++k) step(r);
  EXPECT_EQ(&r.interface(0), home) << "no interface moves between steps";
  double strain = 0.0, external = 0.0;
  for (const State& l : r.levels) {
    strain += l.strain_work, external += l.external_work;
    EXPECT_EQ(l.time, r.time) << "one dt for every level";
  }
  EXPECT_EQ(r.strain_work, strain);
  EXPECT_EQ(r.external_work, external);
  // The writers' particles: every level's, each id once, merged once per step.
  const Particles& all = all_particles(r);
  EXPECT_EQ(all.size(), held_particles(r));
  std::vector<std::uint32_t> ids = all.id;
  std::sort(ids.begin(), ids.end());
  EXPECT_TRUE(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
  EXPECT_EQ(&all_particles(r), &all) << "the same merge within a step";
  EXPECT_EQ(r.merged_step, r.step);
  step(r);
  EXPECT_EQ(r.merged_step, -1) << "a step makes the merge stale";
}
