// Tests of cohesive/polyline: node placement, projection, crossings.
#include <gtest/gtest.h>

#include <cmath>

#include "cohesive/polyline.hpp"

using namespace rupture;

namespace {
Polyline line(std::vector<double> x, std::vector<double> y, bool closed = false) {
  Polyline p;
  p.x = std::move(x), p.y = std::move(y), p.closed = closed;
  return p;
}
}  // namespace

// One straight piece: node k is exactly x0 + (x1 - x0) k / N (the original horizontal form,
// so the reference problem's nodes are bitwise those of earlier versions).
TEST(Polyline, straight_line_nodes_are_the_original_formula) {
  const Polyline p = line({0.025, 0.05}, {0.0, 0.0});
  const LineNodes n = discretize(p, 12000);
  ASSERT_EQ(n.x.size(), 12001u);
  for (std::size_t k = 0; k <= 12000; k += 997) {
    EXPECT_EQ(n.x[k], 0.025 + (0.05 - 0.025) * double(k) / 12000.0);
    EXPECT_EQ(n.y[k], 0.0);
  }
  EXPECT_DOUBLE_EQ(n.s.back(), 0.025);
}

// A vertex is always a node; segments go to pieces in proportion to their length.
TEST(Polyline, pieces_get_segments_in_proportion_and_vertices_are_nodes) {
  const Polyline p = line({0.0, 3.0, 3.0}, {0.0, 0.0, 1.0});  // lengths 3 and 1
  const LineNodes n = discretize(p, 8);
  ASSERT_EQ(n.x.size(), 9u);
  EXPECT_DOUBLE_EQ(n.x[6], 3.0);  // 6 segments on the first piece, 2 on the second
  EXPECT_DOUBLE_EQ(n.y[6], 0.0);
  EXPECT_DOUBLE_EQ(n.s[6], 3.0);
  EXPECT_DOUBLE_EQ(n.y[8], 1.0);
  EXPECT_DOUBLE_EQ(n.s[8], 4.0);
  // Closed: as many nodes as segments, the last segment ends on node 0.
  const LineNodes ring = discretize(line({0, 1, 1, 0}, {0, 0, 1, 1}, true), 8);
  EXPECT_EQ(ring.x.size(), 8u);
  EXPECT_DOUBLE_EQ(ring.s[4], 2.0);
}

TEST(Polyline, projection_gives_distance_arc_length_normal_and_overshoot) {
  const Polyline p = line({0.0, 2.0}, {0.0, 2.0});  // 45 degrees, normal (-1, 1)/sqrt 2
  const LineProjection a = project(p, 0.0, 2.0);
  EXPECT_NEAR(a.distance, std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(a.s, std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(a.nx, -1.0 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(a.ny, 1.0 / std::sqrt(2.0), 1e-15);
  EXPECT_DOUBLE_EQ(a.beyond, 0.0);
  const LineProjection b = project(p, 3.0, 3.0);  // beyond the end by sqrt 2 along the line
  EXPECT_NEAR(b.beyond, std::sqrt(2.0), 1e-15);
  double x, y;
  point_at(p, std::sqrt(2.0), x, y);
  EXPECT_NEAR(x, 1.0, 1e-15);
  EXPECT_NEAR(y, 1.0, 1e-15);
}

// Crossing: strictly through each other. Meeting at an end (a kinked crack made of two
// interfaces) or touching is not crossing; a bow-tie line crosses itself.
TEST(Polyline, crossings_are_told_from_touching) {
  EXPECT_TRUE(segments_cross(0, 0, 2, 2, 0, 2, 2, 0));
  EXPECT_FALSE(segments_cross(0, 0, 1, 1, 1, 1, 2, 0)) << "shared end point";
  EXPECT_FALSE(segments_cross(0, 0, 2, 0, 1, 0, 1, 1)) << "one ends on the other";
  EXPECT_TRUE(segments_intersect(0, 0, 2, 0, 1, 0, 1, 1)) << "but they do touch";
  EXPECT_FALSE(segments_cross(0, 0, 1, 0, 2, 0, 3, 0)) << "collinear, apart";
  const PieceCrossing bow = first_self_crossing(line({0, 1, 1, 0}, {0, 1, 0, 1}, true));
  EXPECT_EQ(bow.i, 0);
  EXPECT_EQ(bow.j, 2);
  EXPECT_EQ(first_self_crossing(line({0, 1, 1, 0}, {0, 0, 1, 1}, true)).i, -1)
      << "a square is simple";
}
