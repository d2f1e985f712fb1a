// Tests of solver/crack_record.cpp: a growing crack's record gives its grown length, its splits
// and each tip's speed: the path over the window divided by the time since that stretch began
// (exact on steady growth, per tip when the rows of several tips interleave, 0 before the tip
// has grown the window, falling once the tip stops).
#include <gtest/gtest.h>

#include "solver/crack_growth.hpp"

using namespace rupture;

namespace {

void add(CrackGrowthRecord& r, double t, int tip, double end, double x, double length) {
  r.rows.insert(r.rows.end(), {t, double(tip), end, x, 0.0, 0.0, length, 0.0, 0.0});
}

}  // namespace

TEST(CrackRecord, steady_growth_gives_its_speed_per_tip) {
  // The end tip grows 0.25 mm every 0.2 us (1250 m/s); the start tip 0.25 mm every 0.5 us
  // (500 m/s); their rows interleave.
  CrackGrowthRecord r;
  for (int i = 1; i <= 40; ++i) {
    add(r, 0.2e-6 * i, 1, 1.0, 0.01 + 0.25e-3 * i, 0.25e-3);
    if (i % 5 == 0) add(r, 0.5e-6 * (i / 5), 0, 0.0, -0.25e-3 * (i / 5), 0.25e-3);
  }
  const double window = 1e-3;  // four segments
  EXPECT_NEAR(tip_speed(r, 1, LineEnd::end, 8e-6, window), 1250.0, 1e-9);
  // The start tip's rows: at 0.5, 1.0, ... 4.0 us.
  EXPECT_NEAR(tip_speed(r, 0, LineEnd::start, 4.0e-6, window), 500.0, 1e-9);
  // Before four segments, no speed; a tip that stops slows down by the time since.
  CrackGrowthRecord first;
  for (int i = 1; i <= 3; ++i) add(first, 0.2e-6 * i, 1, 1.0, 0.25e-3 * i, 0.25e-3);
  EXPECT_EQ(tip_speed(first, 1, LineEnd::end, 0.6e-6, window), 0.0);
  EXPECT_NEAR(tip_speed(r, 1, LineEnd::end, 9e-6, window), 1e-3 / (9e-6 - 7.2e-6), 1e-9);
  // From the first rows only: the speed when row 10 was made.
  EXPECT_NEAR(tip_speed(r, 1, LineEnd::end, r.rows[9 * kGrowthColumns], window, 10), 1250.0, 1e-9);
}

TEST(CrackRecord, a_split_counts_as_a_branch_and_its_tips_have_their_own_speed) {
  CrackGrowthRecord r;
  for (int i = 1; i <= 8; ++i) add(r, 0.2e-6 * i, 1, 1.0, 0.25e-3 * i, 0.25e-3);
  r.rows.insert(r.rows.end(), {1.8e-6, 1.0, kSplitAtStart + 1.0, 2e-3, 0.0, 10.0, 0.0, 0.0, 0.0});
  for (int i = 1; i <= 8; ++i) {
    add(r, 1.8e-6 + 0.4e-6 * i, 2, 1.0, 2e-3 + 0.25e-3 * i, 0.25e-3);
    add(r, 1.8e-6 + 0.4e-6 * i, 3, 1.0, 2e-3 + 0.25e-3 * i, 0.25e-3);
  }
  EXPECT_EQ(r.branches(), 1);
  EXPECT_NEAR(r.length(), 24 * 0.25e-3, 1e-15);  // the split row adds nothing
  EXPECT_NEAR(tip_speed(r, 2, LineEnd::end, 1.8e-6 + 3.2e-6, 1e-3), 625.0, 1e-9);
  EXPECT_NEAR(tip_speed(r, 3, LineEnd::end, 1.8e-6 + 3.2e-6, 1e-3), 625.0, 1e-9);
  // The crack's own tip (end 1) stopped at the split: its rows are the first eight.
  EXPECT_NEAR(tip_speed(r, 1, LineEnd::end, 1.6e-6, 1e-3), 1250.0, 1e-9);
}
