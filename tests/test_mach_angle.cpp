// Tests of cohesive/mach_angle: the shear Mach front's angle recovered from synthetic tau_max
// fields with a known front (smeared over two cells as GIMP smears a jump, with noise and an
// unrelated wave front), at several angles, on both sides, for a crack in any direction
// (rotation invariance), and with the front's origin away from the tip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "cohesive/mach_angle.hpp"

using namespace rupture;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Cloud {
  std::vector<double> x, y, tau;
  std::vector<std::uint8_t> material;
};

// Particles at spacing h/2 on a square around the tip (2 x 2 per cell of size h, as the solver
// seeds them). In the crack's frame (xi along dir, eta across): a
// shear front xi = origin - |eta| cot(beta) on each side (angle beta_up for eta > 0, beta_down
// for eta < 0), behind which tau rises by `jump` over a tanh of width h; a circular P front
// centred far behind; uniform noise of +-noise.
Cloud synthetic(double h, double dir_deg, double beta_up, double beta_down, double origin,
                double jump, double noise, unsigned seed) {
  Cloud c;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-noise, noise);
  const double ex = std::cos(dir_deg * kPi / 180), ey = std::sin(dir_deg * kPi / 180);
  const double tip_x = 0.03, tip_y = 0.01, half = 0.03;
  for (double a = -half; a <= half; a += 0.5 * h)
    for (double b = -half; b <= half; b += 0.5 * h) {
      const double xi = a, eta = b;
      const double beta = (eta >= 0 ? beta_up : beta_down) * kPi / 180;
      const double front = origin - std::abs(eta) / std::tan(beta);
      const double dist = (front - xi) * std::sin(beta);  // > 0 behind the front
      const double p_front = std::hypot(xi + 0.05, eta) - 0.06;  // a P wave's arc
      double tau = 5e6 + 0.5 * jump * (1.0 + std::tanh(dist / h)) + (p_front < 0 ? 2e6 : 0.0) + u(rng);
      c.x.push_back(tip_x + xi * ex - eta * ey);
      c.y.push_back(tip_y + xi * ey + eta * ex);
      c.tau.push_back(tau);
      c.material.push_back(eta >= 0 ? 0 : 1);
    }
  return c;
}

MachSearch search(double h, double dir_deg, double run) {
  MachSearch s;
  s.tip_x = 0.03, s.tip_y = 0.01;
  s.dir_x = std::cos(dir_deg * kPi / 180), s.dir_y = std::sin(dir_deg * kPi / 180);
  s.run = run;
  s.spacing = h;
  return s;
}

}  // namespace

TEST(MachAngle, SpeedAndAngleAreInverse) {
  // theory E12 with Homalite's c_S: 2300 m/s -> 32.86 deg; sqrt(2) c_S -> 45 deg exactly.
  EXPECT_NEAR(mach_angle_of_speed(2300.0, 1247.9), std::asin(1247.9 / 2300.0) * 180 / kPi, 1e-12);
  EXPECT_NEAR(mach_angle_of_speed(std::sqrt(2.0) * 1247.9, 1247.9), 45.0, 1e-9);
  EXPECT_NEAR(speed_of_mach_angle(mach_angle_of_speed(2300.0, 1247.9), 1247.9), 2300.0, 1e-9);
  EXPECT_TRUE(std::isnan(mach_angle_of_speed(1000.0, 1247.9)));  // sub-shear: no Mach front
}

TEST(MachAngle, RecoversKnownAnglesOnBothSides) {
  const double h = 0.125e-3;
  for (double beta : {25.0, 33.3, 45.0, 60.0}) {
    const Cloud c = synthetic(h, 0.0, beta, beta, 0.0, 10e6, 2e6, 1);
    for (int side : {+1, -1}) {
      const MachLine m = find_mach_line(c.x.data(), c.y.data(), c.tau.data(), c.material.data(),
                                        c.x.size(), search(h, 0.0, 0.02), side);
      ASSERT_TRUE(m.found) << "beta " << beta << " side " << side;
      EXPECT_NEAR(m.angle, beta, 0.3) << "side " << side << " error estimate " << m.angle_error;
      EXPECT_LT(m.angle_error, 0.3);
      // The filter's response to a tanh edge of width h: the means over 2h either side differ by
      // ln(cosh 2) / 2 = 0.66 of the jump.
      EXPECT_NEAR(m.jump, 10e6 * std::log(std::cosh(2.0)) / 2, 0.5e6);
      EXPECT_NEAR(m.origin, 0.0, 2 * h);
      EXPECT_EQ(m.material, side > 0 ? 0 : 1);
    }
  }
}

TEST(MachAngle, ParticlesSplitAmongRanksGiveTheSameReading) {
  // A distributed run bins each rank's particles and sums the bins over the ranks: two "ranks"
  // (alternate particles, and a cut through the field) give the one-process line. The first
  // rank's bins are kept by its sum; the second's sum adds them (bins, counts, material tally,
  // in that order).
  const double h = 0.125e-3;
  const Cloud c = synthetic(h, 20.0, 33.3, 45.0, -0.002, 10e6, 2e6, 7);
  for (int side : {+1, -1}) {
    const MachSearch where = search(h, 20.0, 0.02);
    const MachLine one = find_mach_line(c.x.data(), c.y.data(), c.tau.data(), c.material.data(), c.x.size(), where, side);
    ASSERT_TRUE(one.found);
    for (int split : {0, 1}) {
      Cloud a, b;
      for (std::size_t p = 0; p < c.x.size(); ++p) {
        Cloud& to = (split == 0 ? p % 2 == 0 : c.x[p] < 0.03) ? a : b;
        to.x.push_back(c.x[p]), to.y.push_back(c.y[p]), to.tau.push_back(c.tau[p]), to.material.push_back(c.material[p]);
      }
      std::vector<std::vector<double>> kept;
      const SumOverRanks keep = [&](double* v, int n) { kept.emplace_back(v, v + n); };
      find_mach_line(b.x.data(), b.y.data(), b.tau.data(), b.material.data(), b.x.size(), where, side, &keep);
      ASSERT_EQ(kept.size(), 3u);
      std::size_t call = 0;
      const SumOverRanks add = [&](double* v, int n) {
        for (int k = 0; k < n; ++k) v[k] += kept[call][std::size_t(k)];
        ++call;
      };
      const MachLine two = find_mach_line(a.x.data(), a.y.data(), a.tau.data(), a.material.data(), a.x.size(), where, side, &add);
      ASSERT_TRUE(two.found) << "split " << split << " side " << side;
      // The bins' sums in another order: the same line to round-off.
      EXPECT_NEAR(two.angle, one.angle, 1e-9) << "split " << split;
      EXPECT_NEAR(two.jump, one.jump, 1e-6 * std::fabs(one.jump));
      EXPECT_EQ(two.rows, one.rows);
      EXPECT_EQ(two.material, one.material);
    }
  }
}

TEST(MachAngle, RotatedCrackGivesTheSameAngles) {
  // Different angles above and below (a bimaterial's two shear speeds), the front starting
  // 1 mm behind the tip; the crack running along 30 and 143 degrees.
  const double h = 0.125e-3;
  for (double dir : {0.0, 30.0, 143.0}) {
    const Cloud c = synthetic(h, dir, 38.0, 31.0, -1e-3, 8e6, 1e6, 7);
    const MachSearch s = search(h, dir, 0.02);
    const MachLine up = find_mach_line(c.x.data(), c.y.data(), c.tau.data(), c.material.data(), c.x.size(), s, +1);
    const MachLine down = find_mach_line(c.x.data(), c.y.data(), c.tau.data(), c.material.data(), c.x.size(), s, -1);
    ASSERT_TRUE(up.found && down.found) << "direction " << dir;
    EXPECT_NEAR(up.angle, 38.0, 0.3) << "direction " << dir;
    EXPECT_NEAR(down.angle, 31.0, 0.3) << "direction " << dir;
    EXPECT_NEAR(up.origin, -1e-3, 2 * h) << "direction " << dir;
    EXPECT_NEAR(down.origin, -1e-3, 2 * h) << "direction " << dir;
  }
}

TEST(MachAngle, TooShortARunIsNotMeasured) {
  // run / 2 - 2h holds fewer than kMinRows rows of bins.
  const double h = 0.125e-3;
  const Cloud c = synthetic(h, 0.0, 33.0, 33.0, 0.0, 10e6, 0.0, 1);
  const MachLine m = find_mach_line(c.x.data(), c.y.data(), c.tau.data(), c.material.data(),
                                    c.x.size(), search(h, 0.0, 2 * (2 + kMinRows - 1) * h), +1);
  EXPECT_FALSE(m.found);
}

TEST(MachAngle, SummaryTakesMediansInsideTheSteadyPhase) {
  auto reading = [](int interface, double t, double left, double right) {
    MachReading r;
    r.interface = interface;
    r.time = t;
    r.left.found = left > 0, r.left.angle = left, r.left.angle_error = 0.1;
    r.right.found = right > 0, r.right.angle = right, r.right.angle_error = 0.1;
    r.c_s_left = 1000.0, r.c_s_right = 2000.0;
    return r;
  };
  const std::vector<MachReading> readings = {
      reading(0, 1.0, 80.0, 40.0),  // before the steady phase: left out
      reading(0, 2.0, 30.0, 32.0),
      reading(0, 2.5, 31.0, -1.0),  // right side not measured
      reading(0, 3.0, 50.0, 33.0),  // an outlier on the left
      reading(1, 2.5, 60.0, 60.0),  // another interface
  };
  const MachSummary m = summarize_mach(readings, 0, 1.5, 3.0);
  EXPECT_EQ(m.readings, 3);
  EXPECT_DOUBLE_EQ(m.angle, 32.0);  // median of 30, 31, 50, 32, 33
  EXPECT_DOUBLE_EQ(m.angle_left, 31.0);
  EXPECT_DOUBLE_EQ(m.angle_right, 32.5);
  const double mean = (30.0 + 31 + 50 + 32 + 33) / 5;
  const double var = ((30 - mean) * (30 - mean) + (31 - mean) * (31 - mean) + (50 - mean) * (50 - mean) +
                      (32 - mean) * (32 - mean) + (33 - mean) * (33 - mean)) / 4;
  EXPECT_NEAR(m.angle_spread, std::sqrt(var), 1e-12);
  // Implied speeds 2000, 1942, 1305, 3774, 3641 m/s (left c_S 1000, right 2000): median 2000.
  EXPECT_NEAR(m.speed, speed_of_mach_angle(30.0, 1000.0), 1e-9);
  // No reading inside the window: all of the interface's readings count.
  EXPECT_EQ(summarize_mach(readings, 0, 5.0, 6.0).readings, 4);
  EXPECT_EQ(summarize_mach(readings, 2, 0.0, 9.0).readings, 0);
  EXPECT_EQ(summarize_mach(readings, 2, 0.0, 9.0).angle, -1.0);
}
