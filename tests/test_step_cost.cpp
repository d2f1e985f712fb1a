// Tests of run/step_cost (rupture check's predicted run time): the output count behind the
// prediction is the driver's, the measurement times what it says, and it leaves nothing behind.
// No timing is asserted (speed is measured in bench/, never in a unit test).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <cstdlib>

#include <filesystem>
#include <string>

#include "input/case_toml.hpp"
#include "run/driver.hpp"
#include "run/step_cost.hpp"

using namespace rupture;
namespace fs = std::filesystem;

namespace {
Case small_case(double snapshot_interval, double interface_interval) {
  const std::string path = std::string(RUPTURE_SOURCE_DIR) + "/examples/rosakis1999.toml";
  // One dt for every cell (the graded realization): per-level steps time whole cycles.
  return load_case(path, {"time.end=1.1e-6", "grid.refinement=\"graded\"",
                          fmt::format("output.snapshot_interval={}", snapshot_interval),
                          fmt::format("output.interface_interval={}", interface_interval),
                          "solver.threads=1"});
}

long files_in(const fs::path& dir, const std::string& ext) {
  long n = 0;
  if (fs::exists(dir))
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == ext;
  return n;
}
}  // namespace

TEST(StepCost, output_counts_are_the_files_a_run_writes) {
  // A snapshot at t = 0, one per interval and one at the end (1.1 us is no multiple); the same for
  // interface profiles. The two unit costs differ by a power of ten so the sum tells them apart.
  const Case c = small_case(0.25e-6, 0.3e-6);
  const fs::path dir = fs::temp_directory_path() / "rupture_test_step_cost";
  RunOptions o;
  o.output_dir = dir.string();
  o.overwrite = true;
  o.progress = false;
  run_case(c, o);
  const long snapshots = files_in(dir / "snapshots", ".h5");
  long profiles = 0;
  for (const auto& e : fs::directory_iterator(dir / "interface"))
    profiles += e.path().filename().string().rfind("interface_", 0) == 0;
  fs::remove_all(dir);
  StepCost cost;
  cost.snapshot_seconds = 1.0;
  cost.interface_seconds = 100.0;
  const double predicted = predicted_wall_seconds(cost, c, 7);
  std::printf("run wrote %ld snapshots and %ld interface profiles; predicted %g\n", snapshots,
              profiles, predicted);
  EXPECT_EQ(snapshots, 6);  // 0, 0.25, 0.5, 0.75, 1.0, 1.1 us
  EXPECT_EQ(profiles, 5);   // 0, 0.3, 0.6, 0.9, 1.1 us
  EXPECT_DOUBLE_EQ(predicted, double(snapshots) * 1.0 + double(profiles) * 100.0);
}

TEST(StepCost, measures_the_steps_it_says_and_leaves_no_files) {
  // A temporary folder of this process's own: `rupture check` runs of other tests, side by
  // side under ctest, make and remove theirs in the shared one.
  const fs::path own = fs::temp_directory_path() / ("rupture_step_cost_" + std::to_string(::getpid()));
  fs::create_directories(own);
  ::setenv("TMPDIR", own.c_str(), 1);
  const Case c = small_case(0.25e-6, 0.3e-6);
  auto leftovers = [] {
    long n = 0;
    for (const auto& e : fs::directory_iterator(fs::temp_directory_path()))
      n += e.path().filename().string().rfind("rupture-check-", 0) == 0;
    return n;
  };
  const long before = leftovers();
  const StepCost cost = measure_step_cost(c, 0.0, 3, 5);
  EXPECT_EQ(cost.steps, 3) << "a zero budget stops at the minimum";
  EXPECT_GT(cost.particles, 0u);
  EXPECT_GT(cost.step_seconds, 0.0);
  EXPECT_DOUBLE_EQ(cost.ns_per_particle_update, 1e9 * cost.step_seconds / double(cost.particles));
  EXPECT_GT(cost.snapshot_seconds, 0.0);
  EXPECT_GT(cost.interface_seconds, 0.0);
  EXPECT_EQ(leftovers(), before) << "the timed output's temporary directory is removed";
  // Steps, set-up and output add up.
  EXPECT_DOUBLE_EQ(predicted_wall_seconds(cost, c, 10),
                   cost.setup_seconds + 10 * cost.step_seconds + 6 * cost.snapshot_seconds +
                       5 * cost.interface_seconds);
  ::unsetenv("TMPDIR");
  fs::remove_all(own);
}

// Per-level time steps (nested levels): the timed steps are whole cycles of the longest period
// whatever the minimum says, and the particle-updates per finest step follow the periods.
TEST(StepCost, times_whole_cycles_of_per_level_steps) {
  Case c = small_case(0.0, 0.0);
  c.grid.nested = true;
  c.time.subcycling = Subcycling::levels;
  const StepCost cost = measure_step_cost(c, 0.0, 3, 5);
  // The example at 0.5 mm: levels 0-2, the interface on level 2.
  ASSERT_EQ(cost.level_periods, (std::vector<int>{4, 2, 1}));
  EXPECT_EQ(cost.steps, 4) << "one cycle of the longest period";
  EXPECT_LT(cost.updates_per_finest_step, double(cost.particles));
  EXPECT_GT(cost.updates_per_finest_step, double(cost.particles) / 4.0);
}
