// Tests of bc/time_function.hpp (theory E2).
#include <gtest/gtest.h>

#include "bc/time_function.hpp"

using namespace rupture;

TEST(TimeFunction, trapezoid_pulse_is_continuous_with_the_spec_corners) {
  TimeFunction f{TimeFunction::Kind::trapezoid, 30.0, 0.1e-6, 15e-6, 1e-6};
  EXPECT_DOUBLE_EQ(f(0.0), 0.0);
  EXPECT_DOUBLE_EQ(f(0.05e-6), 15.0);
  EXPECT_DOUBLE_EQ(f(0.1e-6), 30.0);
  EXPECT_DOUBLE_EQ(f(10e-6), 30.0);
  EXPECT_NEAR(f(15.6e-6), 15.0, 1e-9);  // halfway down the ramp (tr + tp + ts/2)
  EXPECT_DOUBLE_EQ(f(17e-6), 0.0);
  for (double t : {0.1e-6, 15.1e-6, 16.1e-6}) {  // the three corners
    EXPECT_NEAR(f(t - 1e-15), f(t + 1e-15), 1e-6) << "jump at t = " << t;
  }
}

TEST(TimeFunction, constant_is_constant) {
  TimeFunction f{TimeFunction::Kind::constant, -2.5, 0, 0, 0};
  EXPECT_EQ(f(0.0), -2.5);
  EXPECT_EQ(f(1.0), -2.5);
}
