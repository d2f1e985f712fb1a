// The GIMP stencil contract on graded grids (grid/grid.hpp, theory E3 and §5): a particle box
// may overlap at most two cells per axis. The exact test on an axis, and its check at every
// re-sort: a coarse particle driven into a 4x finer region is stopped with a diagnosis naming
// it and the cell; one driven into a 2x finer region is not.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "solver/field_windows.hpp"
#include "solver/state.hpp"
#include "solver/transfer.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

// Cells along x of 1 mm, then 0.5 mm on [7, 8] mm, then 0.25 mm from 8 mm on.
Axis graded_axis() {
  const double min[2] = {0.0, 0.0}, max[2] = {0.016, 0.004};
  const std::vector<RefineBox> boxes = {{{0.008, 0.0}, {0.016, 0.004}, 0.25e-3}};
  return make_graded_grid(min, max, 1e-3, 0.25e-3, boxes).x;
}

// A 2 x 4 mm block of Homalite moving at 200 m/s along x from the 1 mm cells of x < 7 mm
// into a refined box (x >= 8 mm) at `level` (1: 0.5 mm cells, 2: 0.25 mm cells). The grid is
// 0.25 mm along y everywhere (the box spans the height), so only x is graded.
Case moving_block(int level) {
  return parse_case(fmt::format(R"({}
[grid]
min = [0.0, 0.0]
max = [0.016, 0.004]
cell_size = 0.25e-3
coarse_cell_size = 1e-3
refinement = "graded"      # the graded grid's contract (nested levels re-home particles)
margin = 0.0
[grid.refine.fine]
min = [0.008, 0.0]
max = [0.016, 0.004]
level = {}
[bodies.block]
material = "homalite"
min = [0.003, 0.0]
max = [0.005, 0.004]
velocity = [200.0, 0.0]
[time]
end = 25e-6
)",
                                test::kHomaliteToml, level));
}

}  // namespace

TEST(GimpContract, box_may_overlap_two_cells_but_not_three) {
  const Axis a = graded_axis();
  const double x8 = 0.008, lp = 0.25e-3;  // a particle of a 1 mm cell (ppc = 2)
  ASSERT_NEAR(a.width(a.cell_of(0.0075)), 0.5e-3, 1e-15);
  ASSERT_NEAR(a.width(a.cell_of(0.0085)), 0.25e-3, 1e-15);
  // Box [7.75, 8.25] mm: the halves of a 0.5 mm and of a 0.25 mm cell; it reaches x_{first+2}.
  EXPECT_FALSE(stencil_overflows(a, x8, lp));
  // 1 um further the box holds the 0.25 mm cell [8, 8.25] mm whole, and touches a third cell.
  EXPECT_TRUE(stencil_overflows(a, x8 + 1e-6, lp));
  // Aligned with two fine cells it still holds (a box as wide as two cells of 0.25 mm) ...
  EXPECT_FALSE(stencil_overflows(a, 0.0085, lp));
  // ... but anywhere else among them it does not: 2 l_p > w.
  EXPECT_TRUE(stencil_overflows(a, 0.0086, lp));
  // A particle of a 0.5 mm cell (l_p = 0.125 mm) fits anywhere: 2 l_p <= 0.25 mm.
  for (double x = 0.0060; x < 0.0120; x += 0.0137e-3)
    EXPECT_FALSE(stencil_overflows(a, x, 0.125e-3)) << x;
  // The vectorized count agrees with the one-particle test.
  std::vector<double> xs, ls;
  int expected = 0;
  for (double x = 0.0060; x < 0.0120; x += 0.0137e-3) {
    xs.push_back(x), ls.push_back(lp);
    expected += stencil_overflows(a, x, lp);
  }
  EXPECT_GT(expected, 0);
  EXPECT_EQ(count_stencil_overflows(a, xs.data(), ls.data(), xs.size()), std::size_t(expected));
  // Why it matters: the box reaches a fourth node, whose weight (theory E3) the three-node
  // stencil cannot carry, so the particle's mass and force go partly to the wrong nodes.
  Stencil1D st;
  stencil(a, 0.0086, lp, st);
  const int fourth = st.first + 3;
  const double lost = gimp_graded(0.0086 - a.node(fourth), a.width(fourth - 1), a.width(fourth), lp).s;
  EXPECT_GT(lost, 1e-3);
  // A uniform axis is never checked (l_p <= h/2 there by construction).
  Axis u;
  u.h = 1e-3, u.cells = 20;
  EXPECT_EQ(count_stencil_overflows(u, xs.data(), ls.data(), xs.size()), 0u);
}

TEST(GimpContract, coarse_particle_driven_into_4x_finer_region_stops_with_a_diagnosis) {
  State s = make_state(moving_block(2));
  long first_breach = -1;
  std::string message;
  try {
    while (s.time < 25e-6) {
      // Records when a particle first breaks the contract (the check only runs at re-sorts).
      if (first_breach < 0)
        for (std::size_t p = 0; p < s.particles.size(); ++p)
          if (stencil_overflows(s.grid.x, s.particles.x[p], s.particles.half_x[p]))
            first_breach = s.step;
      step(s);
    }
  } catch (const SimulationError& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "no SimulationError by t = " << s.time;
  ASSERT_GE(first_breach, 0);
  std::printf("first breach at step %ld, stopped at step %ld:\n%s\n", first_breach, s.step,
              message.c_str());
  EXPECT_LE(s.step - first_breach, s.plan.sort_interval) << "detected at the next re-sort";
  // The sort threw before permuting: the first breaking particle is still in place.
  std::size_t p = 0;
  while (!stencil_overflows(s.grid.x, s.particles.x[p], s.particles.half_x[p])) ++p;
  const int cell = s.grid.x.cell_of(s.particles.x[p] - s.particles.half_x[p]) + 1;
  EXPECT_NE(message.find(fmt::format("particle {} ", s.particles.id[p])), std::string::npos);
  EXPECT_NE(message.find(fmt::format("cell (column {}, row", cell)), std::string::npos);
  EXPECT_NE(message.find("of width 0.00025 m"), std::string::npos);
  EXPECT_NE(message.find("half-widths (l_x, l_y) = (0.00025, 6.25e-05) m"), std::string::npos);
  EXPECT_NE(message.find(fmt::format("step {},", s.step)), std::string::npos);
  EXPECT_NE(message.find("[grid.refine]"), std::string::npos) << "advice";
}

TEST(GimpContract, coarse_particle_driven_into_2x_finer_region_runs) {
  // l_p = 1 mm / 4 = half a 0.5 mm cell: the box never overlaps more than two cells.
  State s = make_state(moving_block(1));
  while (s.time < 25e-6) step(s);
  double lead = 0.0;
  for (double x : s.particles.x) lead = std::max(lead, x);
  EXPECT_GT(lead, 0.0095) << "the block got well into the refined region (from 8 mm)";
}

// Debug builds (NDEBUG undefined) check every stencil against its tile: a particle far too
// wide for its cells, here bypassing the re-sort check, stops at an assertion instead of
// writing outside the tile. Release builds carry no such check (and skip this test).
// A stencil starts at the cell of x - l_p, and a strip's tile reaches two node columns left of
// the strip, so the particle must lie in a strip's first column with l_p over three cells
// (strip 0's tile reaches the grid's first column: no stencil starts left of it). Strips as
// wide as the block's first cell column (>= 5, the block moved 2 mm right) put particles in
// the first column of strip 1.
TEST(GimpContractDeathTest, debug_build_stops_a_stencil_outside_its_tile) {
#ifdef NDEBUG
  GTEST_SKIP() << "assertions are compiled out (NDEBUG)";
#else
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  State s = make_state(moving_block(2));
  const Axis& ax = s.grid.x;
  int first_column = ax.cells;
  for (double& x : s.particles.x) {
    x += 2e-3;  // the block over [5, 7] mm
    first_column = std::min(first_column, ax.cell_of(x));
  }
  ASSERT_GE(first_column, 5);
  s.plan.strip_cells = first_column;  // strip 1 starts at the block's first column
  s.plan.valid = false;
  build_scatter_plan(s);
  fit_field_windows(s);
  std::size_t wide = s.particles.size();
  for (std::size_t p = 0; p < s.particles.size() && wide == s.particles.size(); ++p)
    if (ax.cell_of(s.particles.x[p]) == first_column) wide = p;
  ASSERT_LT(wide, s.particles.size()) << "no particle in the first column of strip 1";
  // x - l_p in the cell three left of the strip: the stencil starts a column left of its tile.
  const double x = s.particles.x[wide];
  s.particles.half_x[wide] = x - 0.5 * (ax.node(first_column - 3) + ax.node(first_column - 2));
  ASSERT_EQ(ax.cell_of(x - s.particles.half_x[wide]), first_column - 3);
  EXPECT_DEATH(particles_to_grid(s, true), "outside the tile");
#endif
}
