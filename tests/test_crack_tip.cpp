// Tests of cohesive/crack_tip: the E10 tip, separated stretches (a daughter crack), the two
// cohesive-zone lengths, the E11 speed and the sustained speed, on prescribed jump fields
// whose answers are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "cohesive/crack_tip.hpp"
#include "cohesive/interface_growth.hpp"
#include "solver/cohesive_step.hpp"

using namespace rupture;

namespace {

// Homalite's wave speeds (theory §1), m/s.
const WaveSpeeds kHomalite{2534.5, 1247.9, 1165.0, 1164.0};

// `segments` segments on [0, end], tau_max = sigma_max = 24 MPa, delta_t = 1 um.
CohesiveInterface line(double end = 0.01, int segments = 100) {
  InterfaceSpec spec;
  spec.start = 0.0;
  spec.end = end;
  spec.segments = segments;
  XuNeedleman law;
  law.sigma_max = law.tau_max = 24e6;
  law.delta_n = 0.4e-6;
  law.delta_t = 1e-6;
  spec.law = law;
  return make_interface(spec);
}

// Tangential opening at which the shear traction of a pure-shear jump is `fraction` of
// tau_max on the rising branch (T_t is proportional to x exp(-x^2), x = Delta_t / delta_t,
// with the peak at x = 1/sqrt 2). Bisection: a few lines, no tolerance games.
double rising_opening(const XuNeedleman& law, double fraction) {
  double lo = 0.0, hi = law.delta_t / std::sqrt(2.0);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::fabs(law.traction(0.0, mid).tangential) < fraction * law.tau_max ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(CrackTip, tip_stretches_and_zones_of_a_prescribed_jump_field) {
  CohesiveInterface c = line();
  const XuNeedleman& law = std::get<XuNeedleman>(c.spec.law);
  // Nodes 0..30 cracked (tip at 3.0 mm); 31..35 softening (past the peak opening, node 31
  // nearly unloaded, as next to a real tip); 36..45
  // rising but loaded above 10 % of tau_max; 46..49 below 10 %; a daughter crack 60..64.
  const double above = rising_opening(law, 0.2), below = rising_opening(law, 0.05);
  for (std::size_t k = 0; k < c.num_nodes(); ++k) {
    double jump = 0.0;
    if (k <= 30 || (k >= 60 && k <= 64)) c.node_crack_time[k] = 1e-6, jump = 6e-6;
    else if (k == 31) jump = 3e-6;  // far down the softening branch: T_t = 1e-3 tau_max
    else if (k <= 35) jump = 1e-6;  // past delta_t / sqrt 2 (softening; T_t = 0.86 tau_max)
    else if (k <= 45) jump = above;
    else if (k <= 49) jump = below;
    c.ux_up[k] = 0.5 * jump, c.ux_lo[k] = -0.5 * jump;
  }
  CrackTracker tracker(c);
  tracker.sample(c, 2e-6);
  const CrackSample& s = tracker.samples().back();
  EXPECT_NEAR(s.tip, 6.4e-3, 1e-12) << "E10: the farthest cracked node, the daughter's tip";
  ASSERT_EQ(s.stretch_begin.size(), 2u);
  EXPECT_NEAR(s.stretch_end[0], 3.0e-3, 1e-12);
  EXPECT_NEAR(s.stretch_begin[1], 6.0e-3, 1e-12);
  // The zones are measured ahead of the daughter's tip: nothing is loaded there.
  EXPECT_NEAR(s.traction_zone, 0.0, 1e-12);

  // Without the daughter: tip at 3.0 mm, softening zone to 3.5 mm, loaded zone to 4.5 mm.
  for (std::size_t k = 60; k <= 64; ++k) c.node_crack_time[k] = -1.0, c.ux_up[k] = c.ux_lo[k] = 0.0;
  tracker.sample(c, 3e-6);
  const CrackSample& m = tracker.samples().back();
  EXPECT_NEAR(m.tip, 3.0e-3, 1e-12);
  EXPECT_EQ(m.stretch_begin.size(), 1u);
  EXPECT_NEAR(m.cohesive_zone, 0.5e-3, 1e-12);
  EXPECT_NEAR(m.traction_zone, 1.5e-3, 1e-12);
}

// A daughter crack is a second stretch beyond an intact ligament of at least one grid cell
// (the tracker's daughter_ligament): a stretch a few cohesive points ahead of the tip lies
// between the same grid nodes as the tip and is the same front, not a daughter.
TEST(CrackTip, a_daughter_crack_needs_an_intact_ligament_of_one_cell) {
  CohesiveInterface c = line();  // nodes every 0.1 mm
  const double cell = 0.25e-3;
  CrackTracker tracker(c, 0.0, cell);
  auto crack = [&](std::size_t k, double t) {
    c.node_crack_time[k] = t, c.ux_up[k] = 3e-6, c.ux_lo[k] = -3e-6;
  };
  for (std::size_t k = 0; k <= 20; ++k) crack(k, 0.5e-6);  // main crack to 2.0 mm
  tracker.sample(c, 1e-6);
  crack(22, 1.5e-6);  // 2.2 mm: a ligament of one node (0.2 mm < one cell)
  tracker.sample(c, 2e-6);
  ASSERT_EQ(tracker.samples().back().stretch_begin.size(), 2u) << "the raw record keeps both";
  EXPECT_LT(tracker.summarize(c, kHomalite).daughter_time, 0.0)
      << "0.2 mm ahead on a 0.25 mm grid is the main front";
  crack(21, 2.5e-6);  // the gap closes
  crack(30, 2.5e-6);  // 3.0 mm: 0.8 mm of intact interface ahead of the tip at 2.2 mm
  tracker.sample(c, 3e-6);
  const CrackSummary sum = tracker.summarize(c, kHomalite);
  EXPECT_NEAR(sum.daughter_time, 3e-6, 1e-15) << "a daughter 0.8 mm (3.2 cells) ahead";
  // Without a ligament length every second stretch counts, the near one included.
  CrackTracker raw(c, 0.0, 0.0);
  for (std::size_t k = 0; k < c.num_nodes(); ++k) c.node_crack_time[k] = -1.0;
  for (std::size_t k = 0; k <= 20; ++k) crack(k, 0.5e-6);
  crack(22, 1.5e-6);
  raw.sample(c, 2e-6);
  EXPECT_NEAR(raw.summarize(c, kHomalite).daughter_time, 2e-6, 1e-15);
}

TEST(CrackTip, speeds_of_a_tip_moving_at_constant_speed_are_exact) {
  CohesiveInterface c = line();
  CrackTracker tracker(c);
  const double v = 2000.0, dt = 2e-8;
  for (int n = 0; n < 200; ++n) {
    const double t = n * dt;
    // Tip at the node nearest to v t (nodes every 0.1 mm): a staircase whose mean slope is v.
    const long tip = std::lround(v * t / 1e-4);
    for (long k = 0; k <= tip && k < long(c.num_nodes()); ++k)
      if (c.node_crack_time[std::size_t(k)] < 0.0) c.node_crack_time[std::size_t(k)] = t;
    tracker.sample(c, t);
  }
  const std::vector<double> speeds = tracker.speeds();
  double mean = 0.0;
  int count = 0;
  for (double s : speeds)
    if (!std::isnan(s)) mean += s, ++count;
  mean /= count;
  EXPECT_EQ(count, 200 - 30) << "the centred 31-point window fits 170 of 200 samples";
  EXPECT_NEAR(mean, v, 0.02 * v) << "E11 speed of a staircase with mean slope v";
  const CrackSummary sum = tracker.summarize(c, kHomalite, 4e-6);
  EXPECT_NEAR(sum.sustained_speed, v, 0.02 * v);
  EXPECT_EQ(sum.regime, "intersonic");
  EXPECT_NEAR(sum.initiation_time, 0.0, 1e-15);
  EXPECT_GT(sum.intersonic_time, 0.0);
}

// A tip that runs into the end of the cohesive line stops there (the halves are bonded beyond):
// the tracker records when it got there, and a sustained speed over a window after that time
// measures the arrest, which is why time.stop_at_interface_end exists.
TEST(CrackTip, reaching_the_end_of_the_cohesive_line_is_recorded) {
  CohesiveInterface c = line();  // [0, 10 mm]
  CrackTracker tracker(c, 0.25e-3);
  const double v = 2000.0, dt = 2e-8;
  for (int n = 0; n < 400; ++n) {  // 8 us: the tip gets to 10 mm at 5 us
    const double t = n * dt;
    const long tip = std::lround(v * t / 1e-4);
    for (long k = 0; k <= tip && k < long(c.num_nodes()); ++k)
      if (c.node_crack_time[std::size_t(k)] < 0.0) c.node_crack_time[std::size_t(k)] = t;
    tracker.sample(c, t);
  }
  // Tip >= 9.75 mm: node 98 cracks once v t >= 9.75 mm, at t = 4.875 us: the sample at 4.88 us.
  EXPECT_NEAR(tracker.end_reached_time(), 4.88e-6, 1e-12);
  const CrackSummary arrested = tracker.summarize(c, kHomalite, 2e-6);
  EXPECT_NEAR(arrested.end_reached_time, 4.88e-6, 1e-12);
  EXPECT_LT(arrested.last_window_speed, 0.01 * v) << "a window after the arrival sees no motion";
  EXPECT_TRUE(arrested.arrested);
  EXPECT_NEAR(arrested.arrest_s, 0.01, 1e-12) << "stopped at the end of the line";

  // A tip that stops short of the tolerance is never recorded; the same tracker records the
  // sample where it gets within it.
  CohesiveInterface short_of_end = line();
  for (std::size_t k = 0; k <= 97; ++k) short_of_end.node_crack_time[k] = 0.0;  // tip 9.7 mm
  CrackTracker approaching(short_of_end, 0.25e-3);
  approaching.sample(short_of_end, 1e-6);
  EXPECT_LT(approaching.end_reached_time(), 0.0) << "tip 9.7 mm, end 10 mm, tolerance 0.25 mm";
  short_of_end.node_crack_time[98] = 2e-6;  // tip 9.8 mm
  approaching.sample(short_of_end, 2e-6);
  EXPECT_DOUBLE_EQ(approaching.end_reached_time(), 2e-6);
  // An intact line's "tip" is its start: however wide the tolerance, nothing reached the end.
  CrackTracker intact(line(), 0.02);
  intact.sample(line(), 1e-6);
  EXPECT_LT(intact.end_reached_time(), 0.0) << "no crack, so no arrival";
}

// theory §6 bands, with Homalite's speeds: below c_R, between c_R and c_S (the band no crack
// sustains), between c_S and c_D, above c_D; "none" for a crack that does not move.
TEST(CrackTip, regimes_follow_the_wave_speeds) {
  EXPECT_EQ(crack_regime(0.0, kHomalite), "none");
  EXPECT_EQ(crack_regime(1100.0, kHomalite), "sub-Rayleigh");
  EXPECT_EQ(crack_regime(1200.0, kHomalite), "Rayleigh-to-shear");
  EXPECT_EQ(crack_regime(kHomalite.shear, kHomalite), "intersonic");
  EXPECT_EQ(crack_regime(2300.0, kHomalite), "intersonic");
  EXPECT_EQ(crack_regime(3000.0, kHomalite), "supersonic");
}

// E10/E11 do not depend on the time step: a tip whose nodes crack at exact times x / v is
// sampled at exact multiples of an interval shorter than any step a run would take, and only
// nodes cracked by the sample time count, so every E11 window spans exactly 31 intervals and
// the speed is v to within the node spacing's staircase.
TEST(CrackTip, samples_at_exact_times_see_only_nodes_cracked_by_then) {
  CohesiveInterface c = line();  // nodes every 0.1 mm
  const double v = 1200.0, interval = 0.01e-6;
  for (std::size_t k = 0; k < c.num_nodes(); ++k) c.node_crack_time[k] = c.x0[k] / v;  // all known now
  CrackTracker tracker(c);
  for (int n = 0; n <= 600; ++n) tracker.sample(c, n * interval);
  const std::vector<CrackSample>& s = tracker.samples();
  // At t = 3.05 us the tip is the last node with x0 <= v t = 3.66 mm: 3.6 mm.
  EXPECT_NEAR(s[305].tip, 3.6e-3, 1e-12);
  const std::vector<double> speeds = tracker.speeds();
  for (std::size_t n = 15; n + 15 < s.size(); ++n) {
    ASSERT_FALSE(std::isnan(speeds[n]));
    EXPECT_NEAR(speeds[n], v, 0.15 * v) << "window of 31 x 10 ns over 0.1 mm nodes at t = " << s[n].time;
  }
  const CrackSummary sum = tracker.summarize(c, kHomalite, 4e-6);
  EXPECT_NEAR(sum.sustained_speed, v, 0.01 * v);
  EXPECT_EQ(sum.regime, "Rayleigh-to-shear");
}

// A node's crack time is where its jump crossed the criterion inside the step, linearly in
// time: a jump that went from 0.8 to 1.2 x the criterion over [0.9, 1.0] us cracked at 0.95 us.
TEST(CrackTip, node_crack_time_is_interpolated_inside_the_step) {
  CohesiveInterface c = line();
  const double crit = std::get<XuNeedleman>(c.spec.law).crack_threshold(c.spec.separation_factor);
  c.jump_before[7] = 0.8 * crit;
  c.ux_up[7] = 0.6 * crit, c.ux_lo[7] = -0.6 * crit;  // jump 1.2 crit now
  evaluate_interface(c, 1.0e-6, 0.9e-6);
  EXPECT_NEAR(c.node_crack_time[7], 0.95e-6, 1e-15);
  EXPECT_LT(c.node_crack_time[6], 0.0);
}

// A closed line has no start: the crack is followed from the node that cracked first, both
// ways, through node 0 without a jump. Here a square of 16 mm perimeter (64 segments of 0.25 mm,
// node k at s = k/4 mm) cracks from node 12 (s = 3 mm) outwards at v both ways: at time t the
// tip is at s = 3 mm + v t and the back tip at 3 mm - v t (node resolution), continuing past
// node 0 to negative s; a single stretch, whose ends agree with the tips.
// A line that grows (solver/crack_growth.hpp): follow() places arc lengths on the grown line
// (the new end node's position is its own), and moves the recorded samples by the length added
// at the start, so a sample's tip is the same material point before and after; a resumed run's
// samples (already in the grown frame) stay.
TEST(CrackTip, a_grown_line_keeps_its_samples_on_the_same_points) {
  CohesiveInterface c = line(0.01, 10);
  for (std::size_t k = 0; k <= 4; ++k) c.node_crack_time[k] = 0.0;  // cracked from 0 to 4 mm
  CrackTracker t(c);
  t.sample(c, 1e-6);
  ASSERT_NEAR(t.samples()[0].tip, 0.004, 1e-15);
  double x0, y0, x, y;
  t.position(t.samples()[0].tip, x0, y0);
  extend_interface(c, LineEnd::start, -0.0005, 0.0003, 0.0, 0.0);  // 0.583 mm added at the start
  extend_interface(c, LineEnd::end, 0.0105, 0.0, 0.0, 0.0);
  const double added = std::hypot(0.0005, 0.0003);
  t.follow(c, true);
  EXPECT_NEAR(t.samples()[0].tip, 0.004 + added, 1e-15);
  EXPECT_NEAR(t.samples()[0].stretch_begin[0], added, 1e-15);
  t.position(t.samples()[0].tip, x, y);
  EXPECT_NEAR(x, x0, 1e-15);
  EXPECT_NEAR(y, y0, 1e-15);
  t.position(c.s0.back(), x, y);
  EXPECT_EQ(x, 0.0105);
  t.position(0.0, x, y);
  EXPECT_EQ(x, -0.0005);
  EXPECT_EQ(y, 0.0003);
  // Resumed: the samples are the checkpoint's (grown frame); only the nodes are taken again.
  CrackTracker r(line(0.01, 10));
  r.follow(c, false);
  r.position(c.s0.back(), x, y);
  EXPECT_EQ(x, 0.0105);
}

TEST(CrackTip, a_crack_on_a_closed_line_runs_both_ways_through_node_zero) {
  InterfaceSpec spec;
  spec.line.x = {0.0, 0.004, 0.004, 0.0};
  spec.line.y = {0.0, 0.0, 0.004, 0.004};
  spec.line.closed = true;
  spec.segments = 64;
  XuNeedleman law;
  law.sigma_max = law.tau_max = 24e6;
  law.delta_n = 0.4e-6;
  law.delta_t = 1e-6;
  spec.law = law;
  CohesiveInterface c = make_interface(spec);
  ASSERT_EQ(c.num_nodes(), 64u);
  ASSERT_EQ(c.num_segments(), 64u);
  const double v = 1000.0, mm = 1e-3;
  for (std::size_t k = 0; k < 64; ++k) {
    const std::size_t forward = (k + 64 - 12) % 64, backward = (12 + 64 - k) % 64;
    c.node_crack_time[k] = double(std::min(forward, backward)) * 0.25 * mm / v;
  }
  CrackTracker tracker(c);
  const double dt = 0.05e-6;
  for (int n = 0; n <= 140; ++n) tracker.sample(c, n * dt);  // to 7 us: 7 mm each way
  const CrackSample& at5 = tracker.samples()[101];          // 5.05 us: 5 nodes each way
  EXPECT_NEAR(at5.tip, 8 * mm, 1e-12);
  EXPECT_NEAR(at5.back, -2 * mm, 1e-12) << "past node 0: s continues below 0";
  ASSERT_EQ(at5.stretch_begin.size(), 1u) << "one stretch, not split at node 0";
  EXPECT_NEAR(at5.stretch_end[0] - at5.stretch_begin[0], 10 * mm, 1e-12);
  double x, y;
  tracker.position(at5.back, x, y);  // s = -2 mm is s = 14 mm: on the left side, y = 2 mm
  EXPECT_NEAR(x, 0.0, 1e-12);
  EXPECT_NEAR(y, 2 * mm, 1e-12);
  const CrackSummary sum = tracker.summarize(c, kHomalite, 4e-6);
  EXPECT_NEAR(sum.initiation_s, 3 * mm, 1e-12);
  EXPECT_NEAR(sum.sustained_speed, v, 0.05 * v);
  EXPECT_NEAR(sum.back_speed, v, 0.05 * v);
  EXPECT_LT(sum.end_reached_time, 0.0) << "a closed line has no end";
  EXPECT_LT(sum.daughter_time, 0.0);
}

namespace {

CohesiveInterface summary_line;  // the line of the last track(): its crack times

// A line of 4000 segments over 40 mm (10 um nodes) whose nodes crack at the times of a tip
// history s(t) (piecewise linear, given as (t, s) corners; the tip stays at the last corner's s
// after it), sampled every 0.02 us to `end` as a run does. 10 um nodes and 0.02 us samples
// keep the E11 staircase below 1 % at 1000-2000 m/s, well inside the steady band.
CrackTracker track(const std::vector<std::pair<double, double>>& corners, double end) {
  CohesiveInterface c = line(0.04, 4000);
  for (std::size_t k = 0; k < c.num_nodes(); ++k) {
    const double s = c.s0[k];
    for (std::size_t i = 1; i < corners.size(); ++i) {
      const auto [t0, s0] = corners[i - 1];
      const auto [t1, s1] = corners[i];
      if (s1 > s0 && s >= s0 && s <= s1) {
        c.node_crack_time[k] = t0 + (t1 - t0) * (s - s0) / (s1 - s0);
        break;
      }
    }
  }
  CrackTracker tracker(c);
  for (int n = 0; n * 0.02e-6 <= end + 1e-15; ++n) tracker.sample(c, n * 0.02e-6);
  summary_line = c;  // keep the crack times for summarize()
  return tracker;
}

}  // namespace

// The summary describes the running crack (issue "Parameter studies"): one that ran at
// 2000 m/s for 9 us and then stood still for 5 us is reported as arrested, where and when, at
// its running speed and regime; the last-4-us slope, ~0, is kept on its own.
TEST(CrackSummary, an_arrested_crack_is_reported_at_its_running_speed) {
  const CrackTracker t = track({{0.0, 0.0}, {9e-6, 0.018}}, 14e-6);
  const CrackSummary s = t.summarize(summary_line, kHomalite, 4e-6);
  EXPECT_TRUE(s.arrested);
  EXPECT_NEAR(s.arrest_time, 9e-6, 0.02e-6);
  EXPECT_NEAR(s.arrest_s, 0.018, 1e-5);
  EXPECT_NEAR(s.sustained_speed, 2000.0, 0.005 * 2000.0);
  EXPECT_EQ(s.regime, "intersonic");
  EXPECT_NEAR(s.last_window_speed, 0.0, 1e-9);
  EXPECT_GT(s.steady_end, 8e-6);  // the E11 window reaches the stop 0.3 us before it
  EXPECT_LE(s.steady_end, 9e-6);
  EXPECT_LT(s.steady_begin, 1e-6);
}

// A crack at 1100 m/s (sub-Rayleigh) for 10 us that jumps to 2200 m/s: reported at the later
// speed once it has run there for kSteadyMin; a jump too short to be steady (0.6 us before the
// run ends) leaves it sub-Rayleigh.
TEST(CrackSummary, a_late_jump_counts_once_it_is_steady) {
  const double s_jump = 1100.0 * 10e-6;
  const CrackTracker late = track({{0.0, 0.0}, {10e-6, s_jump}, {13e-6, s_jump + 2200.0 * 3e-6}}, 13e-6);
  const CrackSummary a = late.summarize(summary_line, kHomalite, 4e-6);
  EXPECT_NEAR(a.sustained_speed, 2200.0, 0.005 * 2200.0);
  EXPECT_EQ(a.regime, "intersonic");
  EXPECT_GT(a.steady_begin, 10e-6);
  EXPECT_FALSE(a.arrested);
  const CrackTracker brief = track({{0.0, 0.0}, {10e-6, s_jump}, {10.6e-6, s_jump + 2200.0 * 0.6e-6}}, 10.6e-6);
  const CrackSummary b = brief.summarize(summary_line, kHomalite, 4e-6);
  EXPECT_NEAR(b.sustained_speed, 1100.0, 0.005 * 1100.0);
  EXPECT_EQ(b.regime, "sub-Rayleigh");
  EXPECT_LT(b.steady_end, 10e-6);
}

// No node cracks: nothing to describe.
TEST(CrackSummary, a_crack_that_never_starts_is_none) {
  const CrackTracker t = track({}, 10e-6);
  const CrackSummary s = t.summarize(summary_line, kHomalite, 4e-6);
  EXPECT_FALSE(s.initiated);
  EXPECT_FALSE(s.arrested);
  EXPECT_EQ(s.sustained_speed, 0.0);
  EXPECT_EQ(s.last_window_speed, 0.0);
  EXPECT_LT(s.steady_begin, 0.0);
  EXPECT_EQ(s.regime, "none");
}
