// Tests of the per-field node windows (grid/grid.hpp GridFields, solver/field_windows.hpp): the
// storage of a field covers what touches it, results do not depend on the storage, and a local
// field costs its own nodes, not the whole grid.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>

#include "input/case_toml.hpp"
#include "solver/field_windows.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

TEST(FieldWindows, every_window_node_has_its_own_element) {
  GridFields G;
  const std::size_t nx = 20, ny = 12;
  G.set_windows(nx, ny, {0, 5, 17}, {20, 4, 3}, {0, 7, 2}, {12, 5, 1});
  EXPECT_EQ(G.size(), 20u * 12u + 4u * 5u + 3u * 1u);
  std::set<std::size_t> seen;
  for (int f = 0; f < 3; ++f)
    for (int j = 0; j < int(ny); ++j)
      for (int i = 0; i < int(nx); ++i) {
        const bool in = i >= G.col0[std::size_t(f)] && i < G.col0[std::size_t(f)] + G.cols[std::size_t(f)] &&
                        j >= G.row0[std::size_t(f)] && j < G.row0[std::size_t(f)] + G.rows[std::size_t(f)];
        ASSERT_EQ(G.holds(f, i, j), in) << f << " " << i << " " << j;
        ASSERT_EQ(G.holds(f, std::size_t(j) * nx + std::size_t(i)), in);
        if (!in) continue;
        const std::size_t e = G.index(f, i, j);
        ASSERT_LT(e, G.size());
        ASSERT_TRUE(seen.insert(e).second) << "element used twice";
        ASSERT_EQ(G.index(f, std::size_t(j) * nx + std::size_t(i)), e);
        if (G.holds(f, i, j + 1)) {
          ASSERT_EQ(G.index(f, i, j + 1), e + G.stride(f));
        }
      }
  EXPECT_EQ(seen.size(), G.size());
}

namespace {

// Runs `steps` steps of the case with windowed and with whole-grid fields and checks the two
// give the same particles and interfaces, bit for bit. Returns the windowed state.
State run_both_ways(const Case& c, int steps) {
  State a = make_state(c), b = make_state(c);
  b.whole_grid_fields = true;
  for (int n = 0; n < steps; ++n) step(a), step(b);
  EXPECT_EQ(b.fields.size(), b.fields.num_nodes * std::size_t(b.fields.num_fields));
  const Particles &P = a.particles, &Q = b.particles;
  for (std::size_t p = 0; p < P.size(); ++p) {
    EXPECT_EQ(P.x[p], Q.x[p]);
    EXPECT_EQ(P.y[p], Q.y[p]);
    EXPECT_EQ(P.vx[p], Q.vx[p]);
    EXPECT_EQ(P.vy[p], Q.vy[p]);
    EXPECT_EQ(P.sxy[p], Q.sxy[p]);
    if (::testing::Test::HasFailure()) break;
  }
  for (std::size_t k = 0; k < a.interfaces.size(); ++k) {
    EXPECT_EQ(a.interfaces[k].ux_up, b.interfaces[k].ux_up);
    EXPECT_EQ(a.interfaces[k].uy_lo, b.interfaces[k].uy_lo);
  }
  EXPECT_EQ(a.time, b.time);
  return a;
}

}  // namespace

// examples/inclusion.toml: a stiff disc (its own field, a closed cohesive interface) in a plate
// under tension. The disc's window is its box plus stencil and margin.
TEST(FieldWindows, inclusion_gives_the_same_answer_with_a_fraction_of_the_memory) {
  const Case c = load_case(std::string(RUPTURE_SOURCE_DIR) + "/examples/inclusion.toml");
  const State s = run_both_ways(c, 150);
  const GridFields& G = s.fields;
  ASSERT_EQ(G.num_fields, 2);
  const double whole = double(G.num_nodes);
  std::printf("inclusion: plate window %d x %d, disc window %d x %d nodes; fields hold %.3f x the "
              "grid (whole-grid fields: 2.000 x), %ld re-fits\n",
              G.cols[0], G.rows[0], G.cols[1], G.rows[1], double(G.size()) / whole, s.window_fits);
  EXPECT_LT(double(G.cols[1] * G.rows[1]), 0.25 * whole);  // the disc: a local field
  EXPECT_LT(double(G.size()), 1.3 * whole);
}

namespace {

// A block flying diagonally at 400 m/s past a block at rest.
Case flying_block_case() {
  return parse_case(std::string(test::kHomaliteToml) + R"(
[grid]
min = [0.0, 0.0]
max = [0.03, 0.03]
cell_size = 0.5e-3
[bodies.still]
material = "homalite"
min = [0.02, 0.0]
max = [0.03, 0.01]
[bodies.flying]
material = "homalite"
min = [0.002, 0.002]
max = [0.006, 0.006]
velocity = [400.0, 400.0]
[time]
end = 40e-6
)");
}

}  // namespace

// A block flying diagonally at 400 m/s past a block at rest: its window follows it (re-fits),
// always covering it, with results equal to whole-grid fields; at the end the window no longer
// holds where the block started, so the field stays local as it moves.
TEST(FieldWindows, window_follows_a_moving_body) {
  const Case c = flying_block_case();
  const State s = run_both_ways(c, 300);
  const GridFields& G = s.fields;
  std::printf("flying block after %.2f us: moved %.2f mm; window columns %d..%d, rows %d..%d; "
              "%ld re-fits\n",
              s.time * 1e6, 400.0 * s.time * 1e3, G.col0[1], G.col0[1] + G.cols[1] - 1, G.row0[1],
              G.row0[1] + G.rows[1] - 1, s.window_fits);
  EXPECT_GE(s.window_fits, 2);  // the fit at t = 0 and at least one as it moved
  const int start_node = int(0.002 / 0.5e-3) + s.grid.ghost;
  EXPECT_FALSE(G.holds(1, start_node, start_node));
  EXPECT_LT(double(G.cols[1] * G.rows[1]), 0.2 * double(G.num_nodes));
}

// After a measure that finds the window just big enough, the particles may still move
// kWindowDrift cells before the next: the window must keep that much to spare. A block flying
// at 400 m/s with strips so wide that it is re-sorted (and measured) only every 25 steps: after
// every step every particle's stencil (node columns and rows c - 1 .. c + 2) lies in its
// field's window, and the result equals whole-grid fields. (Failed at step 286 before the
// slack rule, with 16-column strips.)
TEST(FieldWindows, measured_window_keeps_room_for_the_drift_until_the_next_measure) {
  const Case c = flying_block_case();
  State a = make_state(c), b = make_state(c);
  b.whole_grid_fields = true;
  a.plan.strip_cells = b.plan.strip_cells = 64;
  a.plan.valid = b.plan.valid = false;
  long outside = 0;
  for (int n = 0; n < 300; ++n) {
    step(a), step(b);
    const Particles& P = a.particles;
    for (std::size_t p = 0; p < P.size(); ++p) {
      const int f = P.field[p], i = a.grid.x.cell_of(P.x[p]), j = a.grid.y.cell_of(P.y[p]);
      outside += !(a.fields.holds(f, i - 1, j - 1) && a.fields.holds(f, i + 2, j + 2));
    }
  }
  EXPECT_EQ(outside, 0);
  EXPECT_GE(a.window_fits, 3);
  for (std::size_t p = 0; p < a.particles.size(); ++p) {
    ASSERT_EQ(a.particles.x[p], b.particles.x[p]);
    ASSERT_EQ(a.particles.vx[p], b.particles.vx[p]);
    ASSERT_EQ(a.particles.sxy[p], b.particles.sxy[p]);
  }
}
