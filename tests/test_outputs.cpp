// Output schedules (run/outputs.hpp): a scheduled output writes at the multiples of its
// interval that the steps reach (once in a step however many it passed) and at the last step,
// never with an interval of 0; the levels synchronize by the earliest next write of what reads
// particles, at the latest the end time.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "run/outputs.hpp"

using namespace rupture;

namespace {

// A scheduled output that notes the times it wrote at.
struct Noted {
  Schedule schedule;
  double now = 0.0;
  std::vector<double> times;
  ScheduledOutput output;
  Noted(double interval, bool synchronized)
      : schedule(interval), output(schedule, synchronized, [this] { times.push_back(now); }) {}
};

// Steps of dt up to `end` (the last one cut to land on it, as the driver's dt_cap does), the
// output asked after each as the driver asks it; returns the times it wrote at.
std::vector<double> run_steps(Noted& n, double dt, double end) {
  const double eps = 1e-6 * dt;
  double t = 0.0;
  while (t < end - eps) {
    t = std::min(t + dt, end);
    const bool last = t >= end - eps;
    n.now = t;
    if (n.output.due(t, eps, last)) n.output.write(t, eps, last);
  }
  return n.times;
}

void expect_times(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t k = 0; k < want.size(); ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << "write " << k;
}

TEST(ScheduledOutput, writes_at_each_multiple_and_at_the_last_step) {
  Noted n(0.1, true);
  expect_times(run_steps(n, 0.025, 0.35), {0.1, 0.2, 0.3, 0.35});
  EXPECT_NEAR(n.schedule.next, 0.4, 1e-12);  // moved past the last write
}

TEST(ScheduledOutput, writes_once_in_a_step_that_passes_several_multiples) {
  Noted n(0.1, true);
  expect_times(run_steps(n, 0.25, 0.5), {0.25, 0.5});
  EXPECT_EQ(n.schedule.count, 6);  // next = 0.6: the multiples passed are not owed
}

TEST(ScheduledOutput, an_end_on_a_multiple_writes_once) {
  Noted n(0.1, false);
  expect_times(run_steps(n, 0.05, 0.3), {0.1, 0.2, 0.3});
}

TEST(ScheduledOutput, never_writes_without_an_interval) {
  Noted n(0.0, true);
  EXPECT_TRUE(run_steps(n, 0.05, 0.3).empty());  // not even at the last step
  EXPECT_EQ(n.output.sync_by(1e-9), INFINITY);
}

TEST(ScheduledOutput, says_whether_it_reads_particles) {
  Noted reads(0.1, true), not_reads(0.1, false);
  EXPECT_TRUE(reads.output.needs_synchronized_state());
  EXPECT_FALSE(not_reads.output.needs_synchronized_state());
}

// The outputs that read particles set the time the levels end their steps together by; the
// others (interface profiles) do not.
TEST(OutputSync, by_the_earliest_next_write_of_what_reads_particles) {
  const double eps = 1e-9;
  Schedule history(0.1), profiles(0.03), snapshots(0.25);
  RunOutputs outputs;
  outputs.each_step.push_back(std::make_unique<ScheduledOutput>(history, true, [] {}));
  outputs.each_step.push_back(std::make_unique<ScheduledOutput>(profiles, false, [] {}));
  outputs.checkpoint = std::make_unique<ScheduledOutput>(snapshots, true, [] {});
  EXPECT_DOUBLE_EQ(sync_by(outputs, 1.0, eps), 0.1 - eps);
  history.advance(0.1, eps);
  EXPECT_DOUBLE_EQ(sync_by(outputs, 1.0, eps), 0.2 - eps);
  history.advance(0.3, eps);
  EXPECT_DOUBLE_EQ(sync_by(outputs, 1.0, eps), 0.25 - eps);
  EXPECT_DOUBLE_EQ(sync_by(outputs, 0.2, eps), 0.2 - eps);  // never past the end time
  EXPECT_DOUBLE_EQ(sync_by(RunOutputs{}, 0.5, eps), 0.5 - eps);
}

}  // namespace
