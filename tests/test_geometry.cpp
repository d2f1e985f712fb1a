// Tests of geometry/ and particles/seed: point-in-shape for every kind, polygon validation,
// seeded mass converging to rho x area, rectangles seeded identically whatever their form,
// initial stress (closed form and a released prestressed square), bodies sharing a velocity
// field behaving as one body, and cutting a region along a line (a body split by a crack).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include "geometry/shape.hpp"
#include "input/case_toml.hpp"
#include "material/elastic.hpp"
#include "particles/seed.hpp"
#include "solver/energy.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

Shape rectangle(double x0, double y0, double x1, double y1) {
  Shape s;
  s.kind = ShapeKind::rectangle;
  s.min[0] = x0, s.min[1] = y0, s.max[0] = x1, s.max[1] = y1;
  return s;
}

Shape polygon(std::vector<Point> v) {
  Shape s;
  s.kind = ShapeKind::polygon;
  s.vertices = std::move(v);
  return s;
}

Shape circle(double cx, double cy, double r) {
  Shape s;
  s.kind = ShapeKind::circle;
  s.center[0] = cx, s.center[1] = cy, s.radii[0] = s.radii[1] = r;
  return s;
}

Shape ellipse(double cx, double cy, double a, double b, double degrees) {
  Shape s;
  s.kind = ShapeKind::ellipse;
  s.center[0] = cx, s.center[1] = cy, s.radii[0] = a, s.radii[1] = b;
  s.angle = degrees * std::numbers::pi / 180.0;
  return s;
}

// An L (concave hexagon), counter-clockwise: the unit square's lower-left 2x2 minus its
// upper-right 1x1 quarter.
std::vector<Point> l_shape() { return {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}; }

// The whole Homalite case with `bodies` (TOML) as its [bodies] tables, on a 10 x 2 mm grid.
std::string case_with_bodies(const std::string& bodies, const std::string& extra = "") {
  std::string s = test::strip_case_toml();
  const std::string strip = "[bodies.strip]\nmaterial = \"homalite\"\nmin = [0.0, 0.0]\nmax = [0.01, 0.002]\n";
  s.replace(s.find(strip), strip.size(), bodies);
  return s + extra;
}

}  // namespace

TEST(Geometry, point_in_shape_for_every_kind) {
  const Shape r = rectangle(0, 0, 2, 1);
  EXPECT_TRUE(contains(r, 1.0, 0.5));
  EXPECT_FALSE(contains(r, 2.1, 0.5));
  EXPECT_FALSE(contains(r, 1.0, -0.1));

  const Shape c = circle(1, 1, 0.5);
  EXPECT_TRUE(contains(c, 1.3, 1.3));   // r = 0.42
  EXPECT_FALSE(contains(c, 1.4, 1.4));  // r = 0.57

  // Rotated ellipse: a = 2 along 30 degrees, b = 0.5. A point 1.9 along the a-axis is in; the
  // same distance along +x is not (it is 0.95 off the a-axis, beyond b).
  const Shape e = ellipse(0, 0, 2, 0.5, 30);
  const double t = std::numbers::pi / 6;
  EXPECT_TRUE(contains(e, 1.9 * std::cos(t), 1.9 * std::sin(t)));
  EXPECT_FALSE(contains(e, 1.9, 0.0));
  EXPECT_TRUE(contains(e, -0.4 * std::sin(t), 0.4 * std::cos(t)));   // 0.4 along the b-axis
  EXPECT_FALSE(contains(e, -0.6 * std::sin(t), 0.6 * std::cos(t)));  // 0.6 along it

  // A concave polygon, in both orientations: the missing quarter is outside.
  std::vector<Point> ccw = l_shape(), cw(ccw.rbegin(), ccw.rend());
  for (const auto& v : {ccw, cw}) {
    const Shape p = polygon(v);
    EXPECT_TRUE(contains(p, 0.5, 0.5));
    EXPECT_TRUE(contains(p, 1.5, 0.5));
    EXPECT_TRUE(contains(p, 0.5, 1.5));
    EXPECT_FALSE(contains(p, 1.5, 1.5)) << "the concave corner's quarter";
    EXPECT_FALSE(contains(p, 2.5, 0.5));
    EXPECT_FALSE(contains(p, -0.1, 1.0));
    EXPECT_DOUBLE_EQ(area(p), 3.0);
  }
  EXPECT_DOUBLE_EQ(signed_area(ccw), 3.0);
  EXPECT_DOUBLE_EQ(signed_area(cw), -3.0);

  // A plate with a circular hole and a notch cut from its edge.
  Region plate{rectangle(0, 0, 4, 2), {circle(2, 1, 0.5), rectangle(-1, 0.95, 1, 1.05)}};
  EXPECT_TRUE(contains(plate, 3.0, 1.0));
  EXPECT_FALSE(contains(plate, 2.2, 1.1)) << "in the hole";
  EXPECT_FALSE(contains(plate, 0.5, 1.0)) << "in the notch";
  EXPECT_TRUE(contains(plate, 0.5, 1.1)) << "beside the notch";
  EXPECT_FALSE(contains(plate, 5.0, 1.0));
}

TEST(Geometry, bounding_box_of_a_rotated_ellipse_is_tight) {
  const Shape e = ellipse(1, 2, 3, 1, 40);
  const Box b = bounding_box(e);
  double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
  for (int k = 0; k < 100000; ++k) {
    const double t = 2 * std::numbers::pi * k / 100000, c = std::cos(e.angle), s = std::sin(e.angle);
    const double u = 3 * std::cos(t), w = std::sin(t);
    const double x = 1 + c * u - s * w, y = 2 + s * u + c * w;
    lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x), lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
  }
  for (int d = 0; d < 2; ++d) {
    EXPECT_NEAR(b.min[d], lo[d], 1e-8);
    EXPECT_NEAR(b.max[d], hi[d], 1e-8);
  }
}

TEST(Geometry, self_intersections_are_found_and_simple_polygons_pass) {
  // Bow-tie: edge 0 (0,0)-(1,1) crosses edge 2 (1,0)-(0,1).
  const auto bow = polygon_self_intersection({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  ASSERT_TRUE(bow.has_value());
  EXPECT_EQ(bow->first, 0);
  EXPECT_EQ(bow->second, 2);
  // Concave but simple, both orientations; a triangle; a comb with deep teeth.
  std::vector<Point> l = l_shape();
  EXPECT_FALSE(polygon_self_intersection(l).has_value());
  EXPECT_FALSE(polygon_self_intersection({l.rbegin(), l.rend()}).has_value());
  EXPECT_FALSE(polygon_self_intersection({{0, 0}, {1, 0}, {0, 1}}).has_value());
  EXPECT_FALSE(polygon_self_intersection({{0, 0}, {3, 0}, {3, 2}, {2.5, 2}, {2.5, 0.1}, {2, 0.1},
                                          {2, 2}, {0, 2}})
                   .has_value());
  // A vertex touching another edge (edges 1 and 3 meet at (1, 0.5)).
  const auto touch = polygon_self_intersection({{0, 0}, {2, 0}, {1, 0.5}, {2, 1}, {0, 1}, {1, 0.5}});
  EXPECT_TRUE(touch.has_value());
  // Adjacent edges folding back over each other: (0,0)->(2,0)->(1,0).
  const auto fold = polygon_self_intersection({{0, 0}, {2, 0}, {1, 0}, {1, 1}});
  ASSERT_TRUE(fold.has_value());
  EXPECT_EQ(fold->first, 0);
  EXPECT_EQ(fold->second, 1);
}

// theory §2: the seeded mass of a curved or slanted body is rho x (area of the sub-cells whose
// centres lie inside). Only sub-cells the boundary crosses can be wrong, each by at most its
// area s^2 (s = h / ppc), and a boundary of length P crosses at most about sqrt(2) P / s + 4 of
// them: |error| <= (sqrt(2) P / s + 4) s^2, first order in h. Midpoint sampling cancels most of
// it, so the errors are far below the bound; we check the bound at every h and that halving h
// three times gains at least a factor 4 (first order: 8).
TEST(Geometry, seeded_mass_converges_to_rho_times_area) {
  const double rho = 1246.0, L = 0.04;
  const double dmin[2] = {0.0, 0.0}, dmax[2] = {L, L};
  struct Case {
    const char* name;
    Region region;
    double area, perimeter;  // exact, m^2 and m
  };
  const double a = 0.015, b = 0.007;
  // Ramanujan's perimeter of an ellipse (relative error ~1e-5 here: ample for a bound).
  const double h3 = (a - b) * (a - b) / ((a + b) * (a + b));
  const double ellipse_perimeter = std::numbers::pi * (a + b) * (1 + 3 * h3 / (10 + std::sqrt(4 - 3 * h3)));
  const std::vector<Point> pentagon = {{0.004, 0.005}, {0.033, 0.003}, {0.036, 0.021}, {0.02, 0.036}, {0.012, 0.02}};
  double pent_perimeter = 0;
  for (std::size_t i = 0; i < pentagon.size(); ++i) {
    const Point &p = pentagon[i], &q = pentagon[(i + 1) % pentagon.size()];
    pent_perimeter += std::hypot(q.x - p.x, q.y - p.y);
  }
  const Shape hole = ellipse(0.021, 0.017, 0.006, 0.003, -20);
  const std::vector<Case> cases = {
      {"circle", {circle(0.0203, 0.0197, 0.0131), {}}, std::numbers::pi * 0.0131 * 0.0131,
       2 * std::numbers::pi * 0.0131},
      {"ellipse", {ellipse(0.021, 0.019, a, b, 25), {}}, std::numbers::pi * a * b, ellipse_perimeter},
      {"polygon with a hole", {polygon(pentagon), {hole}}, std::fabs(signed_area(pentagon)) - area(hole),
       pent_perimeter + 2 * std::numbers::pi * std::sqrt(0.5 * (0.006 * 0.006 + 0.003 * 0.003))},
  };
  const int ppc = 2;
  for (const Case& c : cases) {
    std::vector<double> errors;
    for (int cells : {20, 40, 80, 160}) {
      const double h = L / cells, s = h / ppc;
      const Grid g = make_uniform_grid(dmin, dmax, h);
      Particles p;
      seed_region(p, g, c.region, ppc, {rho, 0, 0, {0.0, 0.0}});
      double mass = 0;
      for (double m : p.mass) mass += m;
      const double error = std::fabs(mass - rho * c.area), bound = rho * (std::sqrt(2.0) * c.perimeter / s + 4) * s * s;
      std::printf("%-20s h = %6.3f mm: %7zu particles, |mass - rho A| / (rho A) = %.3e (bound %.3e)\n", c.name,
                  1e3 * h, p.size(), error / (rho * c.area), bound / (rho * c.area));
      EXPECT_LT(error, bound) << c.name << " at h = " << h;
      errors.push_back(error);
    }
    EXPECT_LT(errors.back(), errors.front() / 4) << c.name << ": no first-order convergence";
  }
}

TEST(Geometry, a_rectangle_as_a_polygon_seeds_the_same_particles) {
  // Uniform 0.5 mm grid, and a graded one (1 mm coarse, 0.5 mm in a box) with the body's edges
  // crossing both levels; the body is part of the plate so its edges are not the grid's.
  const std::string rect = "[bodies.strip]\nmaterial = \"homalite\"\nmin = [0.002, 0.0005]\nmax = [0.009, 0.002]\n";
  const std::string poly =
      "[bodies.strip]\nmaterial = \"homalite\"\nshape = \"polygon\"\n"
      "vertices = [[0.009, 0.0005], [0.009, 0.002], [0.002, 0.002], [0.002, 0.0005]]\n";
  const std::vector<std::string> graded = {"grid.coarse_cell_size=1e-3", "grid.refinement=\"graded\"", "grid.refine.fine.min=[0.004, 0.0]",
                                           "grid.refine.fine.max=[0.008, 0.002]", "grid.refine.fine.level=1",
                                           "bodies.strip.min=[0.002, 0.0]"};
  for (const bool refined : {false, true}) {
    std::vector<std::string> set;
    if (refined) set.assign(graded.begin(), graded.end() - 1);
    std::string r = rect, q = poly;
    if (refined) {  // on the coarse level the body must start on a 1 mm line
      r.replace(r.find("0.0005]"), 7, "0.0]");
      q = "[bodies.strip]\nmaterial = \"homalite\"\nshape = \"polygon\"\n"
          "vertices = [[0.009, 0.0], [0.009, 0.002], [0.002, 0.002], [0.002, 0.0]]\n";
    }
    const State a = make_state(parse_case(case_with_bodies(r), set));
    const State b = make_state(parse_case(case_with_bodies(q), set));
    ASSERT_EQ(a.grid.graded(), refined);
    ASSERT_EQ(a.particles.size(), b.particles.size()) << (refined ? "graded" : "uniform");
    ASSERT_GT(a.particles.size(), 0u);
    // make_state sorts particles for the scatter; compare by creation id.
    std::map<std::uint32_t, std::size_t> at;
    for (std::size_t k = 0; k < b.particles.size(); ++k) at[b.particles.id[k]] = k;
    std::size_t differ = 0;
    for (std::size_t k = 0; k < a.particles.size(); ++k) {
      const std::size_t m = at.at(a.particles.id[k]);
      const Particles &P = a.particles, &Q = b.particles;
      differ += P.x[k] != Q.x[m] || P.y[k] != Q.y[m] || P.volume0[k] != Q.volume0[m] || P.mass[k] != Q.mass[m] ||
                P.half_x[k] != Q.half_x[m] || P.half_y[k] != Q.half_y[m];
    }
    EXPECT_EQ(differ, 0u) << (refined ? "graded" : "uniform") << " grid: particles differ bitwise";
    std::printf("%s grid: %zu particles, identical\n", refined ? "graded" : "uniform", a.particles.size());
  }
}

// A body split along a line keeps the side of the cut its normal points to (left_part); the
// extensions of a line beyond its ends are tied where they run through material
// (inside_stretches), and their ends on a rectangle's side are that side bitwise.
TEST(Geometry, left_part_of_a_cut_is_the_side_its_normal_points_to) {
  const Box frame{{0.0, 0.0}, {10.0, 10.0}};
  const Shape up = left_part(frame, {{0, 5}, {10, 5}});
  EXPECT_TRUE(contains(up, 5, 7));
  EXPECT_FALSE(contains(up, 5, 3));
  EXPECT_DOUBLE_EQ(signed_area(up.vertices), 50.0);  // counter-clockwise, the upper half
  const Shape down = left_part(frame, {{10, 5}, {0, 5}});
  EXPECT_TRUE(contains(down, 5, 3));
  EXPECT_DOUBLE_EQ(signed_area(down.vertices), 50.0);
  // A bent cut (area below it: two trapezoids of 17.5), and one leaving through corners.
  const Shape bent = left_part(frame, {{0, 2}, {5, 5}, {10, 2}});
  EXPECT_DOUBLE_EQ(signed_area(bent.vertices), 65.0);
  EXPECT_TRUE(contains(bent, 5, 5.5));
  EXPECT_FALSE(contains(bent, 1, 2.5));  // the cut is at y = 2.6 there
  EXPECT_FALSE(polygon_self_intersection(bent.vertices));
  const Shape diagonal = left_part(frame, {{0, 0}, {10, 10}});
  EXPECT_DOUBLE_EQ(signed_area(diagonal.vertices), 50.0);
  EXPECT_TRUE(contains(diagonal, 2, 8));
  const Point exit = leave_box(frame, {5, 5}, {2, 1});
  EXPECT_DOUBLE_EQ(exit.x, 10.0);
  EXPECT_DOUBLE_EQ(exit.y, 7.5);
}

TEST(Geometry, inside_stretches_of_a_segment_through_a_region) {
  const Region holed{rectangle(0, 0, 10, 10), {circle(5, 5, 2)}};
  const std::vector<Stretch> across = inside_stretches(holed, {-1, 5}, {11, 5});
  ASSERT_EQ(across.size(), 2u);
  EXPECT_EQ(across[0].from.x, 0.0);  // on the rectangle's side exactly
  EXPECT_NEAR(across[0].to.x, 3.0, 1e-12);
  EXPECT_NEAR(across[1].from.x, 7.0, 1e-12);
  EXPECT_EQ(across[1].to.x, 10.0);
  EXPECT_EQ(across[1].to.y, 5.0);
  const std::vector<Stretch> from_inside = inside_stretches(holed, {5, 8.5}, {15.3, 8.5});
  ASSERT_EQ(from_inside.size(), 1u);
  EXPECT_EQ(from_inside[0].from.x, 5.0);  // the segment's own end, exactly
  EXPECT_EQ(from_inside[0].to.x, 10.0);
  EXPECT_TRUE(inside_stretches(holed, {5, 11}, {15, 11}).empty());
  // One side of a cut at y = 2 (the part above it): a vertical segment is inside from the cut
  // (its coordinate exactly) to the top, less the hole.
  Region above = holed;
  above.sides.push_back({left_part({{-1, -1}, {11, 11}}, {{-1, 2}, {11, 2}}), true});
  const std::vector<Stretch> up = inside_stretches(above, {4, -0.5}, {4, 10.5});
  ASSERT_EQ(up.size(), 2u);
  EXPECT_EQ(up[0].from.y, 2.0);
  EXPECT_NEAR(up[0].to.y, 5.0 - std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(up[1].from.y, 5.0 + std::sqrt(3.0), 1e-12);
  EXPECT_EQ(up[1].to.y, 10.0);
}


// A part of a split body cut away (Region::minus_parts): the points on its side of every cut in
// its list are out. A square split at y = 5 into halves, the lower half split again at x = 6:
// the region without the lower-right quarter is the upper half and the lower-left quarter, and
// a segment through it stops on the quarter's two cuts.
TEST(Geometry, a_part_cut_away_from_a_region) {
  const Box frame{{-1, -1}, {11, 11}};
  const Shape below = left_part(frame, {{11, 5}, {-1, 5}});    // y < 5
  const Shape right = left_part(frame, {{6, 11}, {6, -1}});    // x > 6
  Region reach{rectangle(0, 0, 10, 10), {}};
  reach.minus_parts.push_back({{below, true}, {right, true}});  // the lower-right quarter
  EXPECT_TRUE(contains(reach, 8, 7));
  EXPECT_TRUE(contains(reach, 3, 2));
  EXPECT_FALSE(contains(reach, 8, 2));
  EXPECT_FALSE(contains(reach, 11, 7));
  // Across the lower half: in from x = 0 to the quarter's cut at x = 6 exactly.
  const std::vector<Stretch> low = inside_stretches(reach, {-1, 2}, {11, 2});
  ASSERT_EQ(low.size(), 1u);
  EXPECT_EQ(low[0].from.x, 0.0);
  EXPECT_NEAR(low[0].to.x, 6.0, 1e-12);
  // Down at x = 8: from the top to the cut at y = 5; at x = 3 the whole height.
  const std::vector<Stretch> down = inside_stretches(reach, {8, 10.5}, {8, -0.5});
  ASSERT_EQ(down.size(), 1u);
  EXPECT_EQ(down[0].from.y, 10.0);
  EXPECT_NEAR(down[0].to.y, 5.0, 1e-12);
  const std::vector<Stretch> whole = inside_stretches(reach, {3, 10.5}, {3, -0.5});
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_EQ(whole[0].to.y, 0.0);
}
TEST(Geometry, the_two_sides_of_a_cut_seed_the_body_once) {
  // An ellipse with a hole, cut by a bent line: each sub-cell centre of the whole region lies
  // in exactly one side, at the same position (the lattice is the region's, not the side's).
  const double lo[2] = {0.0, 0.0}, hi[2] = {0.04, 0.03};
  const Grid g = make_uniform_grid(lo, hi, 0.5e-3);
  const Region whole{ellipse(0.02, 0.015, 0.018, 0.012, 20), {circle(0.025, 0.015, 0.003)}};
  const Shape cut = left_part({{-0.01, -0.01}, {0.05, 0.04}},
                              {{-0.01, 0.012}, {0.021, 0.0147}, {0.05, 0.02}});
  Region a = whole, b = whole;
  a.sides.push_back({cut, true});
  b.sides.push_back({cut, false});
  std::map<std::pair<double, double>, int> seen;
  for_each_seed_point(g, whole, 2, [&](const SeedPoint& s) { seen[{s.x, s.y}] += 1; });
  for (const Region* r : {&a, &b})
    for_each_seed_point(g, *r, 2, [&](const SeedPoint& s) { seen[{s.x, s.y}] += 10; });
  const long total = count_seed_points(g, whole, 2);
  long once = 0;
  for (const auto& [xy, n] : seen) once += n == 11;
  std::printf("%ld particles: %ld above the cut, %ld below\n", total, count_seed_points(g, a, 2),
              count_seed_points(g, b, 2));
  EXPECT_EQ(once, total) << "every particle of the body in exactly one side, none elsewhere";
  EXPECT_EQ(long(seen.size()), total);
  EXPECT_GT(count_seed_points(g, a, 2), total / 4);
  EXPECT_GT(count_seed_points(g, b, 2), total / 4);
}

// A part walks only its side's box (geometry/shape.hpp region_box), and a check only the box it
// asks for: the points are those of the whole region's walk that the part (and the box) holds,
// at the same positions and in the same order, so seeding is unchanged.
TEST(Geometry, a_part_walks_its_side_box_and_visits_the_points_of_the_whole_walk) {
  const double lo[2] = {0.0, 0.0}, hi[2] = {0.04, 0.03};
  const Grid g = make_uniform_grid(lo, hi, 0.5e-3);
  const Region whole{ellipse(0.02, 0.015, 0.018, 0.012, 20), {circle(0.025, 0.015, 0.003)}};
  const Shape cut = left_part({{-0.01, -0.01}, {0.05, 0.04}}, {{0.017, -0.01}, {0.019, 0.016}, {0.021, 0.04}});
  Region a = whole, b = whole;
  a.sides.push_back({cut, true});
  b.sides.push_back({cut, false});
  const Box ba = region_box(a), bb = region_box(b);
  EXPECT_LT(ba.max[0], 0.0215) << "the part left of the cut is walked over its side's box";
  EXPECT_EQ(bb.max[0], bounding_box(whole).max[0]) << "an outside side keeps the outer box";
  const Box within{{0.012, 0.004}, {0.026, 0.02}};
  for (const Region* part : {&a, &b}) {
    std::vector<SeedPoint> expected, expected_within, got, got_within;
    for_each_seed_point(g, whole, 2, [&](const SeedPoint& s) {
      if (!contains(*part, s.x, s.y)) return;
      expected.push_back(s);
      if (s.x >= within.min[0] && s.x <= within.max[0] && s.y >= within.min[1] && s.y <= within.max[1])
        expected_within.push_back(s);
    });
    for_each_seed_point(g, *part, 2, [&](const SeedPoint& s) { got.push_back(s); });
    for_each_seed_point(g, *part, 2, within, [&](const SeedPoint& s) { got_within.push_back(s); });
    ASSERT_EQ(got.size(), expected.size());
    ASSERT_EQ(got_within.size(), expected_within.size());
    EXPECT_GT(got_within.size(), 100u);
    for (std::size_t i = 0; i < got.size(); ++i)
      ASSERT_TRUE(got[i].x == expected[i].x && got[i].y == expected[i].y && got[i].lx == expected[i].lx) << i;
    for (std::size_t i = 0; i < got_within.size(); ++i)
      ASSERT_TRUE(got_within[i].x == expected_within[i].x && got_within[i].y == expected_within[i].y) << i;
  }
}

// theory E5 with a prestress: sigma_zz = nu (sxx + syy) in plane strain, eps from the compliance,
// and the strain energy 0.5 sigma:eps x area from t = 0.
TEST(Geometry, initial_stress_sets_szz_strain_and_strain_energy) {
  const double s = -8e6, E = 5.2e9, nu = 0.34;
  const std::string body = "[bodies.strip]\nmaterial = \"homalite\"\nmin = [0.0, 0.0]\nmax = [0.01, 0.002]\n"
                           "stress = [-8e6, -8e6, 0.0]\n";
  for (const char* plane : {"strain", "stress"}) {
    const State st = make_state(parse_case(case_with_bodies(body), {std::string("model.plane=\"") + plane + "\""}));
    const bool strain = std::string(plane) == "strain";
    // Equal biaxial stress: eps = (1 + nu)(1 - 2 nu) s / E (plane strain), (1 - nu) s / E (stress).
    const double e = strain ? (1 + nu) * (1 - 2 * nu) * s / E : (1 - nu) * s / E;
    const double szz = strain ? 2 * nu * s : 0.0;
    const Particles& P = st.particles;
    for (std::size_t p = 0; p < P.size(); ++p) {
      ASSERT_DOUBLE_EQ(P.sxx[p], s);
      ASSERT_DOUBLE_EQ(P.syy[p], s);
      ASSERT_EQ(P.sxy[p], 0.0);
      const ElasticStiffness& C = st.stiffness[P.material[p]];
      double exx, eyy, exy;
      strain_of(C, P.sxx[p], P.syy[p], P.sxy[p], exx, eyy, exy);
      ASSERT_NEAR(stress_zz(C, P.sxx[p], P.syy[p]), szz, 1e-12 * std::fabs(s));
      ASSERT_NEAR(exx, e, 1e-14);
      ASSERT_NEAR(eyy, e, 1e-14);
      ASSERT_EQ(exy, 0.0);
    }
    const double expected = 0.01 * 0.002 * 0.5 * (2 * s * e);  // area x 0.5 sigma:eps, J/m
    EXPECT_NEAR(strain_energy(P, st.stiffness), expected, 1e-12 * std::fabs(expected)) << plane;
    EXPECT_NEAR(st.initial_energy, expected, 1e-12 * std::fabs(expected)) << plane;
    std::printf("plane %s: eps = %.6e, szz = %.4g Pa, strain energy %.6e J/m (closed form %.6e)\n", plane, e,
                stress_zz(st.stiffness[P.material[0]], P.sxx[0], P.syy[0]),
                strain_energy(P, st.stiffness), expected);
  }
  // Shear: eps_xy = sxy / (2 mu).
  const State sh = make_state(parse_case(case_with_bodies(
      "[bodies.strip]\nmaterial = \"homalite\"\nmin = [0.0, 0.0]\nmax = [0.01, 0.002]\nstress = [0.0, 0.0, 3e6]\n")));
  double exx, eyy, exy;
  strain_of(sh.stiffness[0], sh.particles.sxx[0], sh.particles.syy[0], sh.particles.sxy[0], exx,
            eyy, exy);
  EXPECT_NEAR(exy, 3e6 * (1 + nu) / E, 1e-15);
}

// A free square prestressed in equal biaxial compression s, released at t = 0 (no loads, no
// supports). At the middle of each edge the release is a plane wave (uniaxial strain) until
// waves from the corners arrive, (L/2 - y)/c_D later at distance y from the middle: the edge
// moves outward at v = -s / (rho c_D) (momentum jump across a front moving at c_D). With no
// external work, kinetic + strain energy keeps its initial value: the step release excites
// the shortest waves, and the error of the explicit step oscillates about zero with an
// amplitude first order in dt (measured: 2.4 % at cfl 0.4, 1.0 % at 0.2, 0.55 % at 0.1,
// 0.29 % at 0.05). A wrong initial strain energy would be an offset that no dt removes.
struct ReleasedSquare {
  double edge_velocity, plane_wave_velocity, worst_energy_error, initial_energy;
};

ReleasedSquare release_prestressed_square(double cfl) {
  const double L = 0.02, s = -10e6;
  const Case c = parse_case(std::string(test::kHomaliteToml) + R"(
[grid]
min = [0.0, 0.0]
max = [0.02, 0.02]
cell_size = 0.5e-3
[bodies.square]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.02]
stress = [-10e6, -10e6, 0.0]
[time]
end = 8e-6
)", {"time.cfl=" + std::to_string(cfl)});
  State st = make_state(c);
  const ElasticMaterial& m = c.materials[0];
  const double cD = wave_speeds(m, PlaneMode::strain).dilatational;
  ReleasedSquare r{0.0, -s / (m.density * cD), 0.0, st.initial_energy};
  // Outward normal velocity of the outer particle column/row of each edge, within L/6 of the
  // edge's middle, averaged over 1 us .. 2.4 us (the corner waves reach it at 2.6 us).
  const double edge = 0.25e-3;  // the outer particles sit 0.125 mm in (displacements ~ 10 um)
  double sum = 0.0;
  long samples = 0;
  while (st.time < c.time.end) {
    step(st);
    const Particles& P = st.particles;
    const double E = kinetic_energy(P) + strain_energy(P, st.stiffness);
    r.worst_energy_error = std::max(r.worst_energy_error, std::fabs(E - r.initial_energy) / r.initial_energy);
    if (st.time < 1e-6 || st.time > 2.4e-6) continue;
    for (std::size_t p = 0; p < P.size(); ++p) {
      const double x = P.x[p], y = P.y[p], mid = 0.5 * L, band = L / 6;
      if (std::fabs(y - mid) < band && (x < edge || x > L - edge)) sum += x < mid ? -P.vx[p] : P.vx[p], ++samples;
      if (std::fabs(x - mid) < band && (y < edge || y > L - edge)) sum += y < mid ? -P.vy[p] : P.vy[p], ++samples;
    }
  }
  EXPECT_GT(samples, 0);
  r.edge_velocity = sum / double(std::max(samples, 1L));
  std::printf("cfl %.2f: edge velocity %.4f m/s, plane wave -s/(rho c_D) = %.4f m/s (%+.2f %%); "
              "|kinetic + strain - initial| <= %.3e x %.4e J/m\n",
              cfl, r.edge_velocity, r.plane_wave_velocity, 100 * (r.edge_velocity / r.plane_wave_velocity - 1),
              r.worst_energy_error, r.initial_energy);
  return r;
}

TEST(Geometry, released_prestressed_square_expands_at_the_plane_wave_velocity) {
  const ReleasedSquare coarse = release_prestressed_square(0.2), fine = release_prestressed_square(0.1);
  // 10 MPa over 20 x 20 mm: 0.5 s:eps x area = 3.30 J/m.
  EXPECT_NEAR(fine.initial_energy, 0.02 * 0.02 * 10e6 * 10e6 * (1 + 0.34) * (1 - 2 * 0.34) / 5.2e9, 1e-9);
  EXPECT_NEAR(fine.edge_velocity, fine.plane_wave_velocity, 0.03 * fine.plane_wave_velocity);
  EXPECT_LT(fine.worst_energy_error, 0.01);
  EXPECT_LT(fine.worst_energy_error, 0.7 * coarse.worst_energy_error) << "the energy error must shrink with dt";
}

// Bodies sharing a field are one continuum: the strip split in two rectangles of one field
// gives the one-body result to round-off (seeded positions can differ in the last bit), while
// the same split as two fields does not (the wave stops at the cut).
TEST(Geometry, bodies_sharing_a_field_behave_as_one_body) {
  const std::string one = "[bodies.strip]\nmaterial = \"homalite\"\nmin = [0.0, 0.0]\nmax = [0.01, 0.002]\n";
  auto split = [](bool vertical, const std::string& field) {
    const std::string cut = vertical ? "[0.005, 0.002]" : "[0.01, 0.001]";
    const std::string start = vertical ? "[0.005, 0.0]" : "[0.0, 0.001]";
    return "[bodies.a]\nmaterial = \"homalite\"\nmin = [0.0, 0.0]\nmax = " + cut + "\n" + field +
           "[bodies.b]\nmaterial = \"homalite\"\nmin = " + start + "\nmax = [0.01, 0.002]\n" + field;
  };
  // Compare states after 40 steps (the P wave from the pushed left edge travels 8 mm), matching
  // particles by their initial position.
  auto run = [](const std::string& bodies) {
    State s = make_state(parse_case(case_with_bodies(bodies)));
    std::map<std::uint32_t, std::pair<long, long>> start;
    for (std::size_t p = 0; p < s.particles.size(); ++p)
      start[s.particles.id[p]] = {std::lround(s.particles.x[p] / 1e-7), std::lround(s.particles.y[p] / 1e-7)};
    for (int k = 0; k < 40; ++k) step(s);
    std::map<std::pair<long, long>, std::vector<double>> out;
    const Particles& P = s.particles;
    for (std::size_t p = 0; p < P.size(); ++p)
      out[start[P.id[p]]] = {P.x[p], P.y[p], P.vx[p], P.vy[p], P.sxx[p], P.syy[p], P.sxy[p]};
    return out;
  };
  const auto reference = run(one);
  // Largest difference of each quantity relative to its largest magnitude.
  auto difference = [&](const std::map<std::pair<long, long>, std::vector<double>>& other) {
    EXPECT_EQ(other.size(), reference.size());
    std::vector<double> dmax(7, 0.0), vmax(7, 0.0);
    for (const auto& [key, a] : reference) {
      const auto& b = other.at(key);
      for (int q = 0; q < 7; ++q) dmax[q] = std::max(dmax[q], std::fabs(a[q] - b[q])), vmax[q] = std::max(vmax[q], std::fabs(a[q]));
    }
    double worst = 0.0;
    for (int q = 2; q < 7; ++q) worst = std::max(worst, dmax[q] / vmax[q]);
    return std::max(worst, std::max(dmax[0], dmax[1]) / 0.01);  // positions relative to the strip length
  };
  const double horizontal = difference(run(split(false, "field = \"plate\"\n")));
  const double vertical = difference(run(split(true, "field = \"plate\"\n")));
  // Two fields meeting with (practically) no interaction: a contact interface of negligible
  // stiffness (1 Pa/m) along the cut, so that the input is valid (touching fields need one).
  const std::string loose =
      "[interface.cut]\nupper_body = \"a\"\nlower_body = \"b\"\npoints = [[0.005, 0.0], [0.005, 0.002]]\n"
      "segments = 8\nlaw = \"contact\"\ncontact_stiffness = 1.0\n";
  const double two_fields = difference(run(split(true, "") + loose));
  std::printf("relative difference to one body: shared field cut along y %.2e, along x %.2e; two fields %.2e\n",
              horizontal, vertical, two_fields);
  EXPECT_LT(horizontal, 1e-12);
  EXPECT_LT(vertical, 1e-12);
  EXPECT_GT(two_fields, 0.1);  // the test can tell
}

TEST(Geometry, polygons_sharing_an_edge_through_seed_points_own_each_point_once) {
  // Two squares rotated by 45 degrees about a node share their diagonal edge y = x, which
  // passes exactly through sub-cell centres (h/4 + k h/2 on both axes). Each polygon lists
  // the shared edge in its own direction, so an edge test that depends on the traversal
  // rounds differently in the two and a point on the edge lands in both or in neither. Every
  // seed point of the union must lie in exactly one of them.
  const double h = 0.5e-3, c = std::sqrt(0.5), L = 0.07;
  const double lo[2] = {-0.06, -0.06}, hi[2] = {0.1, 0.1};  // one lattice on both axes
  const Grid g = make_uniform_grid(lo, hi, h);
  const Shape upper =
      polygon({{0, 0}, {c * L, c * L}, {c * L - c * 0.03, c * L + c * 0.03}, {-c * 0.03, c * 0.03}});
  const Shape lower = polygon(
      {{c * 0.055, -c * 0.055}, {c * L + c * 0.055, c * L - c * 0.055}, {c * L, c * L}, {0, 0}});
  std::map<std::pair<double, double>, int> seen;
  long on_edge = 0;
  for (const Shape* s : {&upper, &lower})
    for_each_seed_point(g, Region{*s, {}}, 2, [&](const SeedPoint& p) {
      seen[{p.x, p.y}] += 1;
      on_edge += p.x == p.y;
    });
  long twice = 0;
  for (const auto& [xy, n] : seen) twice += n > 1;
  std::printf("%zu points, %ld on the shared edge, %ld in both\n", seen.size(), on_edge, twice);
  EXPECT_GT(on_edge, 100) << "the shared edge passes through seed points";
  EXPECT_EQ(twice, 0) << "a point on the shared edge belongs to one polygon only";
  // and to at least one:
  long expected_on_edge = 0;
  for (int k = 0; h / 4 + k * h / 2 < c * L; ++k) expected_on_edge += h / 4 + k * h / 2 > 0;
  EXPECT_EQ(on_edge, expected_on_edge);
}

// The walk-free lower bound on a region's particles (particles/seed.hpp) holds for every kind of
// shape, with cut-outs and off the grid lines, and closes on the count as the cells shrink (its
// deficit is the boundary's strip, first order in s).
TEST(Geometry, seed_points_at_least_bounds_the_walked_count_from_below) {
  const double L = 0.04;
  const double dmin[2] = {0.0, 0.0}, dmax[2] = {L, L};
  const std::vector<Point> pentagon = {{0.004, 0.005}, {0.033, 0.003}, {0.036, 0.021}, {0.02, 0.036}, {0.012, 0.02}};
  const std::vector<std::pair<const char*, Region>> regions = {
      {"rectangle off the grid lines", {rectangle(0.0031, 0.0027, 0.0347, 0.0219), {}}},
      {"circle", {circle(0.0203, 0.0197, 0.0131), {}}},
      {"flat ellipse", {ellipse(0.021, 0.019, 0.017, 0.002, 25), {}}},
      {"polygon with a hole", {polygon(pentagon), {ellipse(0.021, 0.017, 0.006, 0.003, -20)}}},
      {"rectangle with a notch and a hole",
       {rectangle(0.002, 0.002, 0.038, 0.03), {rectangle(0.019, 0.0, 0.0213, 0.008), circle(0.01, 0.02, 0.004)}}},
  };
  for (const auto& [name, region] : regions) {
    double deficit_before = 0.0;
    for (int cells : {20, 40, 80, 160, 320}) {
      const double h = L / cells;
      const Grid g = make_uniform_grid(dmin, dmax, h);
      const double walked = double(count_seed_points(g, region, 2));
      const double bound = seed_points_at_least(region, h / 2);
      std::printf("%-34s h = %6.3f mm: %8.0f particles, at least %8.0f\n", name, 1e3 * h, walked, bound);
      EXPECT_LE(bound, walked) << name << " at h = " << h;
      const double deficit = (walked - bound) / walked;
      if (cells == 320) {
        EXPECT_GT(bound, 0.75 * walked) << name << ": the bound does not close on the count";
        // First order: halving h halves the deficit (0.5, and the strip's curvature terms).
        EXPECT_LT(deficit, 0.6 * deficit_before) << name << ": the deficit does not fall as h";
      }
      deficit_before = deficit;
    }
  }
  Region cut{rectangle(0.0, 0.0, 0.01, 0.01), {}};
  cut.sides.push_back({circle(0.0, 0.0, 0.005), true});
  EXPECT_EQ(seed_points_at_least(cut, 1e-4), 0.0);  // cut by a line: no bound claimed
}
