// Tests of run/thread_tuner: with every thread on its own core (CPU time = threads x wall) all
// threads are kept without timing 1; where they are not, the faster of 1 and all is chosen (1
// only when faster by the margin); a window's mean weighs the whole cycle of per-level steps;
// the period doubles while the choice holds and starts again when the load changes; a fixed
// count (solver.threads, or a machine of one core) is never touched.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "run/thread_tuner.hpp"

namespace rupture {
namespace {

// n steps that take many_s(k) on all (2) threads and one_s on 1; `contended`: the 2 threads got
// 1.2 cores between them (another process holds the rest), else 2. Returns the counts used.
template <class Many>
std::vector<int> feed(ThreadTuner& t, Many many_s, double one_s, long n, bool contended) {
  std::vector<int> used;
  for (long k = 0; k < n; ++k) {
    used.push_back(t.threads());
    if (t.threads() == 1) {
      t.after_step(one_s, one_s);
    } else {
      const double wall = many_s(k);
      t.after_step(wall, (contended ? 1.2 : 2.0) * wall);
    }
  }
  return used;
}
std::vector<int> feed(ThreadTuner& t, double many_s, double one_s, long n, bool contended) {
  return feed(t, [many_s](long) { return many_s; }, one_s, n, contended);
}

long count(const std::vector<int>& v, int x) { return long(std::count(v.begin(), v.end(), x)); }

TEST(ThreadTuner, a_fixed_count_or_one_core_is_never_changed) {
  ThreadTuner fixed(2, false), single(1, true);
  EXPECT_EQ(count(feed(fixed, 1.0, 0.1, 5000, true), 2), 5000);
  EXPECT_EQ(count(feed(single, 1.0, 0.1, 5000, true), 1), 5000);
  EXPECT_FALSE(fixed.probing());
}

TEST(ThreadTuner, threads_on_their_own_cores_are_kept_without_timing_one) {
  ThreadTuner idle(2, true);
  const std::vector<int> used = feed(idle, 0.6, 1.0, 20000, false);
  EXPECT_EQ(count(used, 1), 0);
  EXPECT_GE(idle.decisions(), 4);
  EXPECT_EQ(idle.chose_one(), 0);
}

TEST(ThreadTuner, contended_threads_give_way_to_one_where_one_is_faster) {
  const int W = ThreadTuner::kWindow;
  // Busy: 2 threads take 1.5 s a step, 1 thread 1.0 s.
  ThreadTuner busy(2, true);
  std::vector<int> used = feed(busy, 1.5, 1.0, 2 * W + ThreadTuner::kFirstPeriod, true);
  EXPECT_EQ(count(used, 2), W) << "one window on all threads, then 1 thread";
  EXPECT_EQ(busy.threads(), 2) << "the period over: measuring again, all threads first";
  EXPECT_EQ(busy.chose_one(), 1);
  // Contended but still faster on 2 (0.6 against 1.0 s): one window on 1 thread per period.
  ThreadTuner still(2, true);
  used = feed(still, 0.6, 1.0, 2 * W + ThreadTuner::kFirstPeriod, true);
  EXPECT_EQ(count(used, 1), W);
  EXPECT_EQ(still.chose_one(), 0);
  // A tie (within the margin) keeps all threads.
  ThreadTuner tie(2, true);
  feed(tie, 1.0, 0.99, 2 * W, true);
  EXPECT_EQ(tie.threads(), 2);
}

TEST(ThreadTuner, a_window_weighs_the_whole_cycle_of_per_level_steps) {
  // All threads: a coarse level's step every 4th finest step, 0.5 0.5 0.5 2.5 (mean 1.0 s, median
  // 0.5 s); 1 thread: 0.9 s a step. The mean is the cost per unit of simulated time: 1 thread.
  const int W = ThreadTuner::kWindow;
  ThreadTuner t(2, true);
  feed(t, [](long k) { return k % 4 == 3 ? 2.5 : 0.5; }, 0.9, 2 * W, true);
  EXPECT_EQ(t.threads(), 1);
}

TEST(ThreadTuner, periods_double_while_the_choice_holds_and_restart_when_the_load_changes) {
  const int W = ThreadTuner::kWindow;
  const long P = ThreadTuner::kFirstPeriod;
  ThreadTuner t(2, true);
  // Contended but faster on 2 for three periods: P, 2P, 4P steps between the measurements.
  std::vector<int> used = feed(t, 0.5, 1.0, 3 * 2 * W + P + 2 * P + 4 * P, true);
  EXPECT_EQ(t.decisions(), 3);
  EXPECT_EQ(count(used, 1), 3 * W);
  // Then a busier machine: the next measurement (after the 4P period) picks 1 thread...
  used = feed(t, 1.5, 1.0, 2 * W, true);
  EXPECT_EQ(t.threads(), 1);
  EXPECT_EQ(t.chose_one(), 1);
  // ...and measures again after the first period, not the longest.
  used = feed(t, 1.5, 1.0, P, true);
  EXPECT_EQ(count(used, 1), P);
  EXPECT_TRUE(t.probing());
}

}  // namespace
}  // namespace rupture
