// Tests of interfaces inside one body (interface.NAME.body, input/parse_body_split.cpp): the body
// is split along the line into two bodies in two fields, each end inside the body is tied to
// the body's edge, particles are those of the unsplit body, names that meant the body mean
// all its parts, earlier interfaces follow their faces, and bad input stops with a message
// naming the key, the value and what is allowed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/state.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

// A Homalite plate 20 x 20 mm on a 0.5 mm grid; `bodies` and `rest` (interfaces, boundaries)
// are appended.
std::string plate_case(const std::string& rest, const std::string& bodies = "") {
  return std::string(R"(
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
[grid]
min = [0.0, -0.01]
max = [0.02, 0.01]
cell_size = 0.5e-3
[time]
end = 1e-6
[bodies.plate]
material = "homalite"
min = [0.0, -0.01]
max = [0.02, 0.01]
)") + bodies +
         rest;
}

std::string interface(const std::string& name, const std::string& where, int segments = 40) {
  return "[interface." + name + "]\n" + where + "\nsegments = " + std::to_string(segments) +
         "\nsigma_max = 24e6\ndelta_n = 0.4e-6\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_case(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_message(const std::string& text, const std::vector<std::string>& parts) {
  const std::string e = error_of(text);
  EXPECT_FALSE(e.empty()) << "no error for:\n" << text;
  for (const std::string& p : parts)
    EXPECT_NE(e.find(p), std::string::npos) << "missing '" << p << "' in: " << e;
}

// Particles by position (rounded to 1e-12 m) -> field.
std::map<std::pair<long, long>, int> particle_fields(const State& s) {
  std::map<std::pair<long, long>, int> out;
  for (std::size_t k = 0; k < s.particles.size(); ++k)
    out[{std::lround(s.particles.x[k] * 1e12), std::lround(s.particles.y[k] * 1e12)}] =
        s.particles.field[k];
  return out;
}

}  // namespace

TEST(InsideBody, an_edge_crack_in_one_body_is_the_two_body_case_with_its_bonded_stretch) {
  const Case one = parse_case(
      plate_case(interface("weak", "body = \"plate\"\ny = 0.0\nstart = 0.0\nend = 0.012")));
  const std::string halves = R"(
[bodies.upper]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.01]
[bodies.lower]
material = "homalite"
min = [0.0, -0.01]
max = [0.02, 0.0]
)";
  std::string two_text =
      plate_case(interface("weak",
                           "upper_body = \"upper\"\nlower_body = \"lower\"\n"
                           "y = 0.0\nstart = 0.0\nend = 0.012\nbonded_to = 0.02"),
                 halves);
  two_text.erase(two_text.find("[bodies.plate]"),
                 two_text.find("[bodies.upper]") - two_text.find("[bodies.plate]"));
  const Case two = parse_case(two_text);
  ASSERT_EQ(one.bodies.size(), 2u);
  EXPECT_EQ(one.bodies[0].name, "plate");
  EXPECT_EQ(one.bodies[1].name, "plate.below.weak");
  EXPECT_EQ(one.field_names, (std::vector<std::string>{"plate", "plate.below.weak"}));
  const InterfaceSpec &a = one.interfaces[0], &b = two.interfaces[0];
  EXPECT_EQ(a.upper_body, 0);
  EXPECT_EQ(a.lower_body, 1);
  EXPECT_EQ(a.upper_field, b.upper_field);
  EXPECT_EQ(a.lower_field, b.lower_field);
  // One tied stretch, from the crack's end to the plate's right edge, exactly the two-body one.
  const std::vector<Polyline> ta = a.tie_geometries(), tb = b.tie_geometries();
  ASSERT_EQ(ta.size(), 1u);
  EXPECT_EQ(ta[0].x, tb[0].x);
  EXPECT_EQ(ta[0].y, tb[0].y);
  const State sa = make_state(one), sb = make_state(two);
  EXPECT_EQ(sa.bonded, sb.bonded);
  // The same particles (to round-off: the one body's rows count from its bottom), each in the
  // same field.
  EXPECT_EQ(particle_fields(sa), particle_fields(sb));
  EXPECT_TRUE(one.warnings.empty()) << one.warnings.front();
}

TEST(InsideBody, a_centre_crack_is_tied_beyond_both_ends) {
  const Case c = parse_case(
      plate_case(interface("centre", "body = \"plate\"\npoints = [[0.006, 0.0], [0.014, 0.0]]")));
  const std::vector<Polyline> ties = c.interfaces[0].tie_geometries();
  ASSERT_EQ(ties.size(), 2u);
  EXPECT_EQ(ties[0].x, (std::vector<double>{0.0, 0.006}));  // in the line's direction
  EXPECT_EQ(ties[1].x, (std::vector<double>{0.014, 0.02}));
  for (const Polyline& t : ties) EXPECT_EQ(t.y, (std::vector<double>{0.0, 0.0}));
  // The tied grid nodes (docs/theory.md, "Bonded stretches"): on y = 0 and the rows a cell either
  // side (strictly within 2 h of the line), every node from a cell beyond the plate's edges (a
  // free end reaches as far beyond as across) up to the crack's tips, none strictly between them:
  // 14 + 14 nodes a row (x = -0.5 ... 6 mm, 14 ... 20.5 mm on 0.5 mm cells).
  const State s = make_state(c);
  const double h = c.grid.cell_size;
  int rows[3] = {0, 0, 0};
  for (std::size_t n : s.bonded[0].nodes) {
    const int i = int(n % std::size_t(s.grid.nodes_x())),
              j = int(n / std::size_t(s.grid.nodes_x()));
    const double x = s.grid.x.node(i), y = s.grid.y.node(j);
    const int row = int(std::lround(y / h));
    ASSERT_LE(std::abs(row), 1) << "y = " << y;
    EXPECT_NEAR(y, row * h, 1e-12);
    EXPECT_FALSE(x > 0.006 + 1e-12 && x < 0.014 - 1e-12) << "x = " << x << " inside the crack";
    EXPECT_GE(x, -h - 1e-12);
    EXPECT_LE(x, 0.02 + h + 1e-12);
    ++rows[row + 1];
  }
  for (const int r : rows) EXPECT_EQ(r, 28);
  // An inclined crack inside: both ties run along its direction to the plate's edge.
  const Case inclined = parse_case(plate_case(
      interface("tilted", "body = \"plate\"\npoints = [[0.006, -0.002], [0.014, 0.002]]")));
  const std::vector<Polyline> t2 = inclined.interfaces[0].tie_geometries();
  ASSERT_EQ(t2.size(), 2u);
  EXPECT_EQ(t2[0].x[0], 0.0);  // the left edge, exactly
  EXPECT_NEAR(t2[0].y[0], -0.005, 1e-15);
  EXPECT_EQ(t2[1].x[1], 0.02);
  EXPECT_NEAR(t2[1].y[1], 0.005, 1e-15);
}

TEST(InsideBody, an_extension_entering_the_body_again_is_tied_there_too) {
  // A U (two arms 6 mm wide on a 6 mm base) with a crack from the edge into its left arm: the
  // extension leaves the arm at x = 6 mm and crosses the right arm from 14 to 20 mm, which is
  // tied, so the right arm is not cut; the part above the line is the top of both arms.
  const std::string u = R"(
[bodies.u]
material = "homalite"
shape = "polygon"
vertices = [[0, -0.01], [0.02, -0.01], [0.02, 0.01], [0.014, 0.01], [0.014, -0.004],
            [0.006, -0.004], [0.006, 0.01], [0, 0.01]]
)";
  std::string text =
      plate_case(interface("arm", "body = \"u\"\npoints = [[0.0, 0.002], [0.003, 0.002]]"), u);
  text.erase(text.find("[bodies.plate]"), text.find("[bodies.u]") - text.find("[bodies.plate]"));
  const Case c = parse_case(text);
  const std::vector<Polyline> ties = c.interfaces[0].tie_geometries();
  ASSERT_EQ(ties.size(), 2u);
  EXPECT_EQ(ties[0].x, (std::vector<double>{0.003, 0.006}));
  EXPECT_EQ(ties[1].x, (std::vector<double>{0.014, 0.02}));
  const State s = make_state(c);
  long above = 0;
  for (std::size_t k = 0; k < s.particles.size(); ++k) above += s.particles.field[k] == 0;
  EXPECT_EQ(above, 2 * 24 * 32);  // two arms 6 x 8 mm above y = 2 mm, 16 particles per mm^2
}

TEST(InsideBody, a_closed_line_makes_its_inside_a_new_body) {
  for (const bool ccw : {true, false}) {
    const std::string square =
        ccw ? "[[0.006, -0.004], [0.014, -0.004], [0.014, 0.004], [0.006, 0.004]]"
            : "[[0.006, -0.004], [0.006, 0.004], [0.014, 0.004], [0.014, -0.004]]";
    const Case c = parse_case(
        plate_case(interface("rim", "body = \"plate\"\nclosed = true\npoints = " + square)));
    ASSERT_EQ(c.bodies.size(), 2u);
    EXPECT_EQ(c.bodies[1].name, "plate.inside.rim");
    // The normal (direction turned +90 degrees) points inside for a counter-clockwise line.
    EXPECT_EQ(c.interfaces[0].upper_body, ccw ? 1 : 0);
    EXPECT_TRUE(c.interfaces[0].tie_geometries().empty());
    const State s = make_state(c);
    long inside = 0;
    for (std::size_t k = 0; k < s.particles.size(); ++k) inside += s.particles.field[k] == 1;
    EXPECT_EQ(inside, 32 * 32);  // 8 x 8 mm at 0.25 mm particle spacing
  }
  const Case circle = parse_case(
      plate_case(interface("disc", "body = \"plate\"\ncenter = [0.01, 0.0]\nradius = 0.004", 64)));
  EXPECT_EQ(circle.bodies[1].name, "plate.inside.disc");
  EXPECT_EQ(circle.bodies[1].region.sides[0].shape.kind, ShapeKind::circle);
  EXPECT_EQ(circle.interfaces[0].upper_body, 1);
}

TEST(InsideBody, lines_split_in_turn_and_names_mean_all_their_parts) {
  // Two full-width planes in one plate, the upper one given first: the second lies in the part
  // below the first, and the first plane's lower face moves to the part below the second.
  const std::string rest =
      interface("top", "body = \"plate\"\ny = 0.004\nstart = 0.0\nend = 0.02") +
      interface("bottom", "body = \"plate\"\ny = -0.002\nstart = 0.0\nend = 0.02") + R"(
[boundary.all]
edge = "left"
component = "x"
bodies = ["plate"]
velocity = 1.0
[boundary.middle]
edge = "right"
component = "x"
bodies = ["plate.below.top.above.bottom"]
velocity = 1.0
)";
  const Case c = parse_case(plate_case(rest));
  std::vector<std::string> names;
  for (const BodySpec& b : c.bodies) names.push_back(b.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"plate", "plate.below.top", "plate.below.top.below.bottom"}));
  EXPECT_EQ(c.field_names, names);  // numbered in the bodies' order
  EXPECT_EQ(c.interfaces[0].upper_body, 0);
  EXPECT_EQ(c.interfaces[0].lower_body, 1);
  EXPECT_EQ(c.interfaces[1].upper_body, 1);
  EXPECT_EQ(c.interfaces[1].lower_body, 2);
  std::vector<int> all = c.boundary[0].fields;
  std::sort(all.begin(), all.end());
  EXPECT_EQ(all, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(c.boundary[1].fields, (std::vector<int>{1}));
  // Given the other way round, the first plane's upper face moves to the new middle part.
  const Case d = parse_case(
      plate_case(interface("bottom", "body = \"plate\"\ny = -0.002\nstart = 0.0\nend = 0.02") +
                 interface("top", "body = \"plate\"\ny = 0.004\nstart = 0.0\nend = 0.02")));
  names.clear();
  for (const BodySpec& b : d.bodies) names.push_back(b.name);
  EXPECT_EQ(names, (std::vector<std::string>{"plate", "plate.below.top", "plate.below.bottom"}));
  EXPECT_EQ(d.interfaces[0].upper_body, 1);  // bottom: middle part above it
  EXPECT_EQ(d.interfaces[0].lower_body, 2);
  EXPECT_EQ(d.interfaces[0].upper_field, 1);
  EXPECT_EQ(d.interfaces[1].upper_body, 0);
  EXPECT_EQ(d.interfaces[1].lower_body, 1);
}

TEST(InsideBody, every_bad_input_is_reported_with_key_value_and_rule) {
  const std::string edge = "y = 0.0\nstart = 0.0\nend = 0.012";
  expect_message(plate_case(interface("w", "body = \"plate\"\nupper_body = \"plate\"\n" + edge)),
                 {"interface.w.upper_body", "\"plate\"", "either interface.w.body", "not both"});
  expect_message(plate_case(interface("w", "body = \"plate\"\nbonded_to = 0.02\n" + edge)),
                 {"interface.w.bonded_to", "0.02", "not allowed with interface.w.body",
                  "tied there automatically"});
  expect_message(plate_case(interface("w", "body = \"plates\"\n" + edge)),
                 {"interface.w.body", "\"plates\"", "must name a body among \"plate\"",
                  "did you mean \"plate\"?"});
  expect_message(plate_case(interface("w", "body = \"plate\"\nclosed = true\n" + edge)),
                 {"interface.w.closed", "true", "only allowed with points"});
  expect_message(plate_case(interface("w", "body = \"plate\"\ny = 0.0\nstart = 0.01\nend = 0.004")),
                 {"interface.w.end", "0.004", "must be > start = 0.01 m"});
  expect_message(plate_case(interface("w", "lower_body = \"plate\"\n" + edge)),
                 {"interface.w.upper_body", "(missing)", "upper_body and lower_body",
                  "interface.w.body alone"});
  // A line leaving the body's material (through a hole).
  expect_message(
      plate_case(
          interface("w", "body = \"plate\"\npoints = [[0.004, 0.0], [0.016, 0.0]]"),
          "[[bodies.plate.minus]]\nshape = \"circle\"\ncenter = [0.01, 0.0]\nradius = 0.002\n"),
      {"interface.w.points", "[[0.004, 0], [0.016, 0]]", "must lie inside bodies.plate",
       "is outside it"});
  // Through two parts made by an earlier line, and a T-junction.
  const std::string first = interface("a", "body = \"plate\"\ny = 0.0\nstart = 0.0\nend = 0.02");
  expect_message(
      plate_case(first +
                 interface("b", "body = \"plate\"\npoints = [[0.01, -0.004], [0.01, 0.004]]")),
      {"interface.b.points", "runs through two parts of bodies.plate", "bodies.plate.below.a"});
  // Ending on another line's tied extension (a T-junction on a tie).
  expect_message(
      plate_case(interface("a", "body = \"plate\"\ny = 0.0\nstart = 0.0\nend = 0.012") +
                 interface("b", "body = \"plate\"\npoints = [[0.016, 0.004], [0.016, 0.0]]")),
      {"interface.b.points", "splits bodies.plate across the upper face of interface.a",
       "may not end on another line's tied extension"});
  // Ending on a line that grows.
  expect_message(
      plate_case(interface("a", "body = \"plate\"\ny = 0.0\nstart = 0.0\nend = 0.012") +
                 "growth = \"energy\"\nfracture_energy = 26.0\n" +
                 interface("b", "body = \"plate\"\npoints = [[0.006, 0.004], [0.006, 0.0]]")),
      {"interface.b.points", "ends on interface.a", "a line that grows"});
  // A growing line whose tied extension ends on another: allowed where that line is on the edge
  // of its reach (the part beyond it no growing line changes: input/crack_reach.hpp; followed as
  // it grows), refused where a growing line (c) changes the part beyond.
  const std::string grows_onto_a =
      interface("a", "body = \"plate\"\ny = 0.0\nstart = 0.0\nend = 0.02") +
      interface("b", "body = \"plate\"\npoints = [[0.012, 0.002], [0.012, 0.006]]") +
      "growth = \"energy\"\nfracture_energy = 26.0\n";
  EXPECT_EQ(error_of(plate_case(grows_onto_a)), "") << "the part below a is beyond b's reach";
  expect_message(plate_case(grows_onto_a + interface("c", "body = \"plate\"\npoints = [[0.004, -0.006], [0.004, -0.004]]") +
                            "growth = \"energy\"\nfracture_energy = 26.0\n"),
                 {"interface.b.growth", "\"energy\"", "tied extension ends on interface.a",
                  "may have its extension end on another line in its body only where"});
  // A line whose extensions come back across it.
  expect_message(plate_case(interface("w",
                                      "body = \"plate\"\npoints = [[0.006, 0.0], [0.014, 0.0], "
                                      "[0.014, 0.004], [0.01, 0.004], [0.01, 0.002]]")),
                 {"interface.w.points", "crosses itself", "does not cut bodies.plate in two"});
  // An interface between two bodies naming a split body: it must name a part.
  expect_message(
      plate_case(first + interface("c",
                                   "upper_body = \"plate\"\nlower_body = \"plate.below.a\"\n"
                                   "y = 0.0\nstart = 0.0\nend = 0.02")),
      {"interface.c.upper_body", "\"plate\"", "has been split", "\"plate\", \"plate.below.a\""});
}

// A line that ends on another (a T-junction): the face it ends on changes field at the end, each
// node's face on the part holding the middle of its share of the line.
TEST(InsideBody, a_line_ending_on_another_divides_that_face_at_its_end) {
  // A full-width plane at y = 0, then a crack from it up to (10, 4) mm: the plane's upper face
  // lies on the crack's lower part (x > 10 mm: the crack runs up, its normal points to -x, so
  // the left part keeps the name) up to s = 10 mm, then on the kept part.
  const std::string plane = interface("a", "body = \"plate\"\ny = 0.0\nstart = 0.0\nend = 0.02");
  const Case c = parse_case(
      plate_case(plane + interface("b", "body = \"plate\"\npoints = [[0.01, 0.0], [0.01, 0.004]]", 8)));
  std::vector<std::string> names;
  for (const BodySpec& b : c.bodies) names.push_back(b.name);
  EXPECT_EQ(names, (std::vector<std::string>{"plate", "plate.below.b", "plate.below.a"}));
  const InterfaceSpec& a = c.interfaces[0];
  ASSERT_EQ(a.upper_faces.size(), 2u);
  EXPECT_TRUE(a.lower_faces.empty());
  EXPECT_EQ(a.upper_faces[0].from, 0.0);
  EXPECT_EQ(c.bodies[std::size_t(a.upper_faces[0].body)].name, "plate");
  EXPECT_NEAR(a.upper_faces[1].from, 0.01, 1e-15);
  EXPECT_EQ(c.bodies[std::size_t(a.upper_faces[1].body)].name, "plate.below.b");
  EXPECT_EQ(a.upper_field, c.bodies[0].field);  // the first stretch's, for the material
  EXPECT_TRUE(c.interfaces[1].bonded_lines.size() == 1);  // tied above only: its foot is on a
  // Node fields: 40 segments of 0.5 mm; the node at x = 10 mm (the junction) moves half with
  // each part, every other node with the part holding it.
  const CohesiveInterface ci = make_interface(a);
  ASSERT_EQ(ci.node_faces_up.size(), 41u);
  EXPECT_TRUE(ci.node_faces_lo.empty());
  for (std::size_t k = 0; k < 41; ++k) {
    const FaceFields f = ci.faces_up(k);
    EXPECT_EQ(int(f.a), k <= 20 ? c.bodies[0].field : c.bodies[1].field) << k;
    EXPECT_NEAR(f.share, k == 20 ? 0.5 : 1.0, 1e-12) << k;
    if (k == 20) EXPECT_EQ(int(f.b), c.bodies[1].field);
  }
  for (std::size_t k = 0; k < 41; ++k) EXPECT_EQ(int(ci.faces_lo(k).a), c.bodies[2].field);
  // With the junction at a quarter of a segment, the node before it has 3/4 of its part there.
  InterfaceSpec moved = a;
  moved.upper_faces[1].from = 0.010125;
  const CohesiveInterface cm = make_interface(moved);
  EXPECT_NEAR(cm.faces_up(20).share, 0.75, 1e-12);
  EXPECT_EQ(cm.faces_up(21).share, 1.0);
  EXPECT_EQ(int(cm.faces_up(21).a), c.bodies[1].field);
  // The same with the crack's tie ending on the plane instead (its foot 2 mm above it): the face
  // changes where the tie ends.
  const Case d = parse_case(
      plate_case(plane + interface("b", "body = \"plate\"\npoints = [[0.012, 0.002], [0.012, 0.006]]", 8)));
  ASSERT_EQ(d.interfaces[0].upper_faces.size(), 2u);
  EXPECT_NEAR(d.interfaces[0].upper_faces[1].from, 0.012, 1e-15);
  EXPECT_EQ(d.interfaces[1].bonded_lines.size(), 2u);
  // A line ending on the plane from below divides its lower face.
  const Case e = parse_case(
      plate_case(plane + interface("b", "body = \"plate\"\npoints = [[0.004, -0.006], [0.004, 0.0]]", 8)));
  EXPECT_TRUE(e.interfaces[0].upper_faces.empty());
  ASSERT_EQ(e.interfaces[0].lower_faces.size(), 2u);
  EXPECT_NEAR(e.interfaces[0].lower_faces[1].from, 0.004, 1e-15);
}
