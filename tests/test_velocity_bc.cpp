// Tests of bc/velocity_bc.hpp and the displacement of bc/time_function.hpp (theory E2): a
// condition normal to its edge follows the edge as it moves by the integral of V.
#include <gtest/gtest.h>

#include <cmath>

#include "bc/velocity_bc.hpp"

using namespace rupture;

TEST(TimeFunction, displacement_is_the_integral_of_the_velocity) {
  const TimeFunction f{TimeFunction::Kind::trapezoid, 30.0, 0.1e-6, 15e-6, 1e-6};
  // Midpoint rule with a fine step against the closed form, across every corner.
  const int n = 200000;
  const double T = 17e-6, dt = T / n;
  double u = 0.0;
  for (int k = 0; k < n; ++k) {
    u += f((k + 0.5) * dt) * dt;
    if ((k + 1) % 1000 == 0) {
      ASSERT_NEAR(f.displacement((k + 1) * dt), u, 1e-12) << "t = " << (k + 1) * dt;
    }
  }
  // Closed-form corners: V1 tr/2 after the rise, + V1 tp on the plateau, + V1 ts/2 on the fall.
  EXPECT_NEAR(f.displacement(16.1e-6), 30.0 * (0.05e-6 + 15e-6 + 0.5e-6), 1e-15);
  EXPECT_DOUBLE_EQ(f.displacement(20e-6), f.displacement(16.1e-6));  // at rest afterwards
  EXPECT_EQ(f.displacement(-1.0), 0.0);
  const TimeFunction c{TimeFunction::Kind::constant, -2.0, 0, 0, 0};
  EXPECT_DOUBLE_EQ(c.displacement(3.0), -6.0);
}

namespace {
VelocityBC condition(Edge edge, int component, double v) {
  VelocityBC bc;
  bc.edge = edge;
  bc.from = 0.0;
  bc.to = 1.0;
  bc.component = component;
  bc.velocity = {TimeFunction::Kind::constant, v, 0, 0, 0};
  return bc;
}
}  // namespace

TEST(VelocityBC, a_normal_condition_moves_to_the_nearest_grid_line) {
  const double h = 0.1;
  const double lo[2] = {0.0, 0.0}, hi[2] = {1.0, 1.0};
  const Grid g = make_uniform_grid(lo, hi, h);
  const int left = g.ghost, right = g.x.cells - g.ghost;
  const VelocityBC push = condition(Edge::left, 0, 1.0);  // moves h in 0.1 s
  EXPECT_EQ(edge_line(push, g, 0.0), left);
  EXPECT_EQ(edge_line(push, g, 0.049), left);      // 0.49 h: still nearest to the edge line
  EXPECT_EQ(edge_line(push, g, 0.051), left + 1);  // 0.51 h
  EXPECT_EQ(edge_line(push, g, 0.349), left + 3);
  const VelocityBC pull = condition(Edge::right, 0, -1.0);  // the right edge moving inward
  EXPECT_EQ(edge_line(pull, g, 0.151), right - 2);
  VelocityBC fixed = push;
  fixed.follow_edge = false;
  EXPECT_EQ(edge_line(fixed, g, 0.349), left);
  const VelocityBC slide = condition(Edge::left, 1, 5.0);  // tangential: the edge does not move
  EXPECT_FALSE(slide.moves());
  EXPECT_EQ(edge_line(slide, g, 0.3), left);
  const VelocityBC top = condition(Edge::top, 1, 1.0);  // outward: into the ghost cells
  EXPECT_EQ(edge_line(top, g, 0.151), g.y.cells - g.ghost + 2);
}

// A nested level's edge starts on the level's own line (its base), not on the single grid's
// initial line: the same rule moves it by the same displacement from there.
TEST(VelocityBC, an_edge_moves_from_the_line_it_starts_on) {
  const double h = 0.1;
  const double lo[2] = {0.0, 0.0}, hi[2] = {1.0, 1.0};
  const Grid g = make_uniform_grid(lo, hi, h);
  const VelocityBC push = condition(Edge::left, 0, 1.0);
  const int base = g.ghost + 4;
  EXPECT_EQ(edge_line(push, g, base, 0.0), base);
  EXPECT_EQ(edge_line(push, g, base, 0.049), base);
  EXPECT_EQ(edge_line(push, g, base, 0.251), base + 3);
  EXPECT_EQ(edge_line(push, g, base, 0.251) - base, edge_line(push, g, 0.251) - g.ghost);
  EXPECT_EQ(initial_lines({push}, g), std::vector<int>{g.ghost});
  std::vector<int> lines;
  EXPECT_TRUE(update_edge_lines({push}, {base}, g, 0.151, lines));
  EXPECT_EQ(lines, std::vector<int>{base + 2});
  EXPECT_FALSE(update_edge_lines({push}, {base}, g, 0.16, lines));
}

TEST(VelocityBC, a_moving_condition_drives_its_line_and_every_line_outside_it) {
  const double h = 0.1;
  const double lo[2] = {0.0, 0.0}, hi[2] = {1.0, 1.0};
  const Grid g = make_uniform_grid(lo, hi, h);
  VelocityBC push = condition(Edge::left, 0, 1.0);
  push.from = 0.2;
  push.to = 0.5;  // 4 nodes along the edge
  std::vector<VelocityBC> bcs{push};
  std::vector<int> lines;
  EXPECT_TRUE(update_edge_lines(bcs, g, 0.0, lines));
  EXPECT_FALSE(update_edge_lines(bcs, g, 0.04, lines));
  const std::vector<NodeBC> at0 = resolve_nodes(bcs, g, 1, lines);
  EXPECT_EQ(at0.size(), std::size_t(4 * (g.ghost + 1)));  // the edge line and the ghost lines
  EXPECT_TRUE(update_edge_lines(bcs, g, 0.26, lines));  // 2.6 h: line ghost + 3
  const std::vector<NodeBC> later = resolve_nodes(bcs, g, 1, lines);
  EXPECT_EQ(later.size(), std::size_t(4 * (g.ghost + 4)));
  for (const NodeBC& e : later) {
    const int i = int(e.node % std::size_t(g.nodes_x())), j = int(e.node / std::size_t(g.nodes_x()));
    EXPECT_LE(i, g.ghost + 3);
    EXPECT_GE(g.y.node(j), 0.2 - 1e-12);
    EXPECT_LE(g.y.node(j), 0.5 + 1e-12);
    EXPECT_EQ(e.component, 0);
  }
}
