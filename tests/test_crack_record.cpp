// Tests of solver/crack_record.cpp: a growing crack's record gives its grown length, its splits
// and each tip's speed: the path over the window divided by the time since that stretch began
// (exact on steady growth, per tip when the rows of several tips interleave, 0 before the tip
// has grown the window, falling once the tip stops).
#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "solver/crack_growth.hpp"

using namespace rupture;

namespace {

void add(CrackGrowthRecord& r, double t, int tip, double end, double x, double length) {
  r.rows.push_back({t, tip, end == 0.0 ? LineEnd::start : LineEnd::end, false, x, 0.0, 0.0, length, 0.0, 0.0});
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
  EXPECT_NEAR(tip_speed(r, 1, LineEnd::end, r.rows[9].time, window, 10), 1250.0, 1e-9);
}

TEST(CrackRecord, a_split_counts_as_a_branch_and_its_tips_have_their_own_speed) {
  CrackGrowthRecord r;
  for (int i = 1; i <= 8; ++i) add(r, 0.2e-6 * i, 1, 1.0, 0.25e-3 * i, 0.25e-3);
  r.rows.push_back({1.8e-6, 1, LineEnd::end, true, 2e-3, 0.0, 10.0, 0.0, 0.0, 0.0});
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

TEST(CrackRecord, rows_go_to_the_checkpoint_form_and_back_unchanged) {
  // Every end code (segments at either end, splits at either end) and a branch's row survive
  // the flat form the checkpoint stores, number for number, in the CSV's column order.
  CrackGrowthRecord r;
  r.rows.push_back({1e-6, 0, LineEnd::start, false, -1e-3, 2e-4, -12.5, 5e-4, 1.1e6, -2e5});
  r.rows.push_back({2e-6, 1, LineEnd::end, false, 3e-3, -1e-4, 7.25, 4e-4, 9e5, 3e5});
  r.rows.push_back({3e-6, 1, LineEnd::end, true, 3e-3, -1e-4, 15.0, 0.0, 8e5, 0.0});
  r.rows.push_back({3e-6, 2, LineEnd::end, false, 3.4e-3, 0.0, 15.0, 4e-4, 8e5, 0.0});
  r.rows.push_back({3e-6, 3, LineEnd::end, false, 3.4e-3, -2e-4, -15.0, 4e-4, 8e5, 0.0});
  r.rows.push_back({4e-6, 0, LineEnd::start, true, -1e-3, 2e-4, 20.0, 0.0, 7e5, 1e5});
  const std::vector<double> flat = growth_rows_flat(r.rows);
  ASSERT_EQ(flat.size(), r.rows.size() * kGrowthColumns);
  const double codes[] = {0.0, 1.0, 3.0, 1.0, 1.0, 2.0};
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    EXPECT_EQ(flat[i * kGrowthColumns + 0], r.rows[i].time);
    EXPECT_EQ(flat[i * kGrowthColumns + 1], double(r.rows[i].tip));
    EXPECT_EQ(flat[i * kGrowthColumns + 2], codes[i]);
    EXPECT_EQ(flat[i * kGrowthColumns + 5], r.rows[i].angle);
    EXPECT_EQ(flat[i * kGrowthColumns + 8], r.rows[i].K_II);
  }
  const std::vector<GrowthRow> back = growth_rows_from_flat(flat, "test");
  ASSERT_EQ(back.size(), r.rows.size());
  EXPECT_EQ(growth_rows_flat(back), flat);
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].end, r.rows[i].end);
    EXPECT_EQ(back[i].split, r.rows[i].split);
  }
  EXPECT_EQ(r.branches(), 2);
}

TEST(CrackRecord, a_bad_stored_row_is_refused_naming_the_entry) {
  std::vector<double> flat = {1e-6, 0.0, 1.0, 0.0, 0.0, 0.0, 1e-3, 0.0, 0.0};
  flat[2] = 4.0;  // no such end code
  try {
    growth_rows_from_flat(flat, "checkpoint 'x': run.growth[0]");
    FAIL() << "end code 4 was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.growth[0].rows[2] = 4: must be 0 or 1"), std::string::npos) << e.what();
  }
  flat[2] = 1.0, flat[1] = 0.5;  // a tip between two
  EXPECT_THROW(growth_rows_from_flat(flat, "w"), InputError);
  flat[1] = 0.0;
  flat.pop_back();  // not whole rows
  EXPECT_THROW(growth_rows_from_flat(flat, "w"), InputError);
}
