// Tests of cohesive/rupture_front: a fault's front speed from its rupture-time profile.
// Profiles with known fronts: a bilateral rupture from an overstressed patch (broken at once, as
// TPV205's is) at 2800 m/s one way and 3000 m/s the other, with a jump to 4500 m/s (supershear,
// above c_S = 3464 m/s) at 8 km on the forward side; the speeds, the patch, the side reaches and
// the transition come back exactly (linear profiles: the least-squares slope is exact), and the
// patch breaking at once does not count as a speed. A front that stops leaves the rest
// unruptured: its reach is where it stopped. Without an overstressed patch the first node to
// rupture is the patch. Why: the crack-tip tracker reads a fault's patch breaking at once as a
// tip speed of tens of km/s; the front summary must read the front.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cohesive/rupture_front.hpp"

using namespace rupture;

namespace {

const WaveSpeeds kRock{6000.0, 3464.1016, 3184.9, 3178.7};  // c_D, c_S, c_R (TPV205's rock)

struct Profile {
  std::vector<double> s, t;
  std::vector<unsigned char> patch;
};

// Nodes every 100 m over [-20, 20] km; patch |x| <= 1.5 km ruptures at t = 0.01 s; outside it
// the front runs at `back` towards -x, and at `fwd` towards +x up to `jump` then at `fast`,
// stopping at `stop` (m) forward.
Profile bilateral(double fwd, double back, double jump, double fast, double stop) {
  Profile p;
  for (int k = 0; k <= 400; ++k) {
    const double x = -20000.0 + 100.0 * k;
    p.s.push_back(x + 20000.0);
    const bool in = std::fabs(x) <= 1500.0;
    p.patch.push_back(in ? 1 : 0);
    double t = 0.01;
    if (x > 1500.0) {
      t += x <= jump ? (x - 1500.0) / fwd : (jump - 1500.0) / fwd + (x - jump) / fast;
      if (x > stop) t = -1.0;
    } else if (x < -1500.0) {
      t += (-1500.0 - x) / back;
    }
    p.t.push_back(t);
  }
  return p;
}

}  // namespace

TEST(RuptureFront, bilateral_front_with_a_supershear_jump) {
  const Profile p = bilateral(2800.0, 3000.0, 8000.0, 4500.0, 1e9);
  const FrontSummary f = summarize_front(p.s, p.t, p.patch, 500.0, 1e-3, 6000.0, kRock);
  ASSERT_TRUE(f.ruptured);
  EXPECT_TRUE(f.nucleation_overstressed);
  EXPECT_DOUBLE_EQ(f.nucleation_begin_s, 18500.0);
  EXPECT_DOUBLE_EQ(f.nucleation_end_s, 21500.0);
  EXPECT_DOUBLE_EQ(f.nucleation_time, 0.01);
  // Backward: one speed everywhere.
  EXPECT_NEAR(f.backward.speed, 3000.0, 1e-6);
  EXPECT_NEAR(f.backward.peak_speed, 3000.0, 1e-6);
  EXPECT_EQ(f.backward.supershear_s, -1.0);
  EXPECT_DOUBLE_EQ(f.backward.reach_s, 0.0);
  EXPECT_NEAR(f.backward.leave_time, 0.01 + 100.0 / 3000.0, 1e-12);
  // Forward: 2800 m/s over 6.5 km, 4500 m/s over 12 km: the median is the longer stretch's,
  // the peak the fast one, and the transition at 8 km (the first window wholly past it
  // starts there), its time the profile's.
  EXPECT_NEAR(f.forward.speed, 4500.0, 1e-6);
  EXPECT_NEAR(f.forward.peak_speed, 4500.0, 1e-6);
  EXPECT_NEAR(f.forward.supershear_s - 20000.0, 8000.0, 500.0);
  const double expect_t = 0.01 + (f.forward.supershear_s - 20000.0 - 1500.0) / 2800.0;
  EXPECT_LE(f.forward.supershear_s - 20000.0, 8000.0 + 1e-9);  // not later than the jump
  EXPECT_GT(f.forward.supershear_time, 0.0);
  EXPECT_NEAR(f.forward.supershear_time, expect_t, 500.0 / 2800.0);
  EXPECT_EQ(f.forward.triggered, 0);  // the patch broke at once, but it is not a window
  EXPECT_EQ(f.forward.regime, "intersonic");
  EXPECT_EQ(f.backward.regime, "sub-Rayleigh");
  EXPECT_NEAR(f.speed, 4500.0, 1e-6);  // the faster side's
  EXPECT_EQ(f.regime, "intersonic");
  EXPECT_DOUBLE_EQ(f.forward.reach_s, 40000.0);
}

TEST(RuptureFront, a_front_that_stops_and_a_sub_rayleigh_one) {
  const Profile p = bilateral(2800.0, 2800.0, 1e9, 0.0, 10000.0);
  const FrontSummary f = summarize_front(p.s, p.t, p.patch, 500.0, 1e-3, 6000.0, kRock);
  EXPECT_NEAR(f.speed, 2800.0, 1e-6);
  EXPECT_NEAR(f.peak_speed, 2800.0, 1e-6);
  EXPECT_EQ(f.regime, "sub-Rayleigh");
  EXPECT_DOUBLE_EQ(f.forward.reach_s, 30000.0);  // x = 10 km
  EXPECT_EQ(f.forward.supershear_s, -1.0);
  EXPECT_EQ(f.forward.nodes, 85);  // (1.5, 10] km every 100 m
}

TEST(RuptureFront, no_overstressed_patch_starts_at_the_first_node) {
  Profile p = bilateral(2000.0, 2000.0, 1e9, 0.0, 1e9);
  for (auto& v : p.patch) v = 0;
  // Inside the old patch the front now runs too: from the centre node at 2000 m/s.
  for (std::size_t k = 0; k < p.s.size(); ++k) {
    const double x = p.s[k] - 20000.0;
    if (std::fabs(x) <= 1500.0) p.t[k] = 0.01 + std::fabs(x) / 2000.0 - 1500.0 / 2000.0 + 1500.0 / 2000.0;
  }
  const FrontSummary f = summarize_front(p.s, p.t, p.patch, 500.0, 1e-3, 6000.0, kRock);
  EXPECT_FALSE(f.nucleation_overstressed);
  EXPECT_DOUBLE_EQ(f.nucleation_begin_s, 20000.0);
  EXPECT_DOUBLE_EQ(f.nucleation_end_s, 20000.0);
  EXPECT_NEAR(f.speed, 2000.0, 1e-6);
}

TEST(RuptureFront, triggered_rupture_is_counted_not_averaged) {
  // Every node outside a patch ruptures at the same time (a fault overstressed everywhere but
  // its centre): no speed, every window triggered.
  Profile p = bilateral(3000.0, 3000.0, 1e9, 0.0, 1e9);
  for (std::size_t k = 0; k < p.s.size(); ++k)
    if (!p.patch[k]) p.t[k] = 0.5;
  const FrontSummary f = summarize_front(p.s, p.t, p.patch, 500.0, 1e-3, 6000.0, kRock);
  EXPECT_EQ(f.speed, 0.0);
  EXPECT_GT(f.forward.triggered, 100);
  EXPECT_EQ(f.regime, "none");
}

TEST(RuptureFront, a_patch_triggered_at_once_is_not_a_speed) {
  // At 2800 m/s both ways, but the nodes of x in [6, 7] km rupture within one step of 0.01 s
  // (a patch set off by a passing wave): the windows over it span less than two steps, so the
  // peak stays the front's and those windows count as triggered.
  Profile p = bilateral(2800.0, 2800.0, 1e9, 0.0, 1e9);
  for (std::size_t k = 0; k < p.s.size(); ++k) {
    const double x = p.s[k] - 20000.0;
    if (x >= 6000.0 && x <= 7000.0) p.t[k] = 0.01 + 4500.0 / 2800.0 + 1e-4 * (x - 6000.0) / 1000.0;
  }
  const FrontSummary f = summarize_front(p.s, p.t, p.patch, 500.0, 0.01, 6000.0, kRock);
  EXPECT_GT(f.forward.triggered, 0);
  EXPECT_LT(f.forward.peak_speed, 500.0 / (2 * 0.01));  // below the resolvable bound
  EXPECT_NEAR(f.backward.peak_speed, 2800.0, 1e-6);
  EXPECT_NEAR(f.forward.speed, 2800.0, 1.0);  // the median is the front's
}

TEST(RuptureFront, a_window_faster_than_c_D_is_triggered_not_a_front) {
  // x in [6, 6.5] km ruptures at 20 km/s (resolved by the steps, but faster than any wave):
  // not a front, so not the peak.
  Profile p = bilateral(2800.0, 2800.0, 1e9, 0.0, 1e9);
  for (std::size_t k = 0; k < p.s.size(); ++k) {
    const double x = p.s[k] - 20000.0;
    if (x > 6000.0) p.t[k] = x <= 6500.0 ? 0.01 + 4500.0 / 2800.0 + (x - 6000.0) / 20000.0
                                         : 0.01 + 4500.0 / 2800.0 + 500.0 / 20000.0 + (x - 6500.0) / 2800.0;
  }
  const FrontSummary f = summarize_front(p.s, p.t, p.patch, 500.0, 1e-4, 6000.0, kRock);
  EXPECT_GT(f.forward.triggered, 0);
  EXPECT_LE(f.forward.peak_speed, 6000.0);
  EXPECT_NEAR(f.forward.speed, 2800.0, 1.0);
}

TEST(RuptureFront, nothing_ruptured) {
  const std::vector<double> s{0.0, 1.0, 2.0}, t{-1.0, -1.0, -1.0};
  const std::vector<unsigned char> patch{0, 0, 0};
  const FrontSummary f = summarize_front(s, t, patch, 1.0, 1e-3, 6000.0, kRock);
  EXPECT_FALSE(f.ruptured);
  EXPECT_EQ(f.nucleation_time, -1.0);
}
