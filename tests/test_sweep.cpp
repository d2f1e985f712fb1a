// Tests of run/sweep.hpp's pure parts: --vary parsing and run names (the process handling is
// tested end to end by tests/e2e/check_sweep.py).
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "run/sweep.hpp"

using namespace rupture;

TEST(Sweep, vary_splits_values_at_top_level_commas_only) {
  const SweepAxis a = parse_vary("boundary.impact.velocity=5,9.5,30");
  EXPECT_EQ(a.key, "boundary.impact.velocity");
  ASSERT_EQ(a.values.size(), 3u);
  EXPECT_EQ(a.values[1], "9.5");
  const SweepAxis b = parse_vary("grid.max=[0.075,0.04],[0.1,0.05]");
  ASSERT_EQ(b.values.size(), 2u);
  EXPECT_EQ(b.values[0], "[0.075,0.04]");
  const SweepAxis c = parse_vary("solver.scheme=\"MUSL\",\"a,b\"");
  ASSERT_EQ(c.values.size(), 2u);
  EXPECT_EQ(c.values[1], "\"a,b\"");
}

TEST(Sweep, vary_without_values_is_an_input_error_naming_the_argument) {
  for (const char* bad : {"velocity", "=1,2", "boundary.impact.velocity=", "x=1,,2", "x=1,"}) {
    try {
      parse_vary(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
}

TEST(Sweep, run_names_are_built_from_the_values_and_safe_as_directories) {
  const std::vector<SweepAxis> axes{parse_vary("boundary.impact.velocity=9.5,30"),
                                    parse_vary("grid.max=[0.075,0.04]"),
                                    parse_vary("solver.scheme=\"USL\"")};
  EXPECT_EQ(sweep_run_name(axes, {0, 0, 0}), "velocity_9.5__max__0.075_0.04___scheme__USL_");
  EXPECT_EQ(sweep_run_name(axes, {1, 0, 0}), "velocity_30__max__0.075_0.04___scheme__USL_");
}
