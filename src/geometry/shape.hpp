// rupture/geometry/shape.hpp
// Plane regions that bodies are made of (units: m, angles in rad): axis-aligned rectangles,
// simple polygons (either orientation), circles and rotated ellipses, and a Region = one outer
// shape minus any number of cut-outs, on one side of any number of cuts (a body split along a
// line: input/parse_body_split.cpp). contains() answers whether a point lies inside; points
// within round-off of a boundary may go either way (seeding never asks about them for shapes
// on grid lines: sub-cell centres sit half a sub-cell inside). Shapes are validated by input/
// (polygon_self_intersection, signed_area), not here.
#pragma once
#include <optional>
#include <utility>
#include <vector>

namespace rupture {

struct Point {
  double x = 0.0, y = 0.0;  // m
};

struct Box {
  double min[2]{}, max[2]{};  // m
};

enum class ShapeKind { rectangle, polygon, circle, ellipse };

struct Shape {
  ShapeKind kind = ShapeKind::rectangle;
  double min[2]{}, max[2]{};    // rectangle: corners, m
  std::vector<Point> vertices;  // polygon: a simple closed polygon, either orientation, m
  double center[2]{};           // circle, ellipse: m
  double radii[2]{};            // circle: {r, r}; ellipse: semi-axes {a, b}, m
  double angle = 0.0;           // ellipse: rotation of the a-axis from +x, rad
};

// One side of a cut through a region: the points inside `shape` (inside = true) or outside it
// (inside = false). The two sides of one cut test the same shape with the same arithmetic, so
// every point lies on exactly one of them: splitting a body loses or doubles no particle.
struct Side {
  Shape shape;
  bool inside = true;
};

// One outer shape with cut-outs (holes, notches): a point is in the region when it is in the
// outer shape, in none of `minus`, on its side of every cut in `sides`, and in none of
// `minus_parts` (each a part of a split body, cut away: the points on their side of every cut in
// its list; a growing crack's reach, solver/crack_cut.hpp crack_body).
struct Region {
  Shape outer;
  std::vector<Shape> minus;
  std::vector<Side> sides{};  // (defaulted: Region{outer, minus} stays complete)
  std::vector<std::vector<Side>> minus_parts{};
};

const char* shape_name(ShapeKind k);

// The same shape, coordinate for coordinate (the parts of one split body share their outer
// shape and cut-outs).
bool same_shape(const Shape& a, const Shape& b);
// The same outer shape and cut-outs (ignoring the sides that split it into parts).
bool same_drawn_region(const Region& a, const Region& b);  // "rectangle", "polygon", "circle", "ellipse"

bool contains(const Shape& s, double x, double y);
bool contains(const Region& r, double x, double y);

Box bounding_box(const Shape& s);
Box bounding_box(const Region& r);                                 // the outer shape's box
// A box that holds every point of the region, tighter than the outer shape's for a part of a
// split body: the outer box cut down to the box of every side that keeps the inside of its
// shape (min > max along an axis: the region is empty).
Box region_box(const Region& r);
bool boxes_overlap(const Box& a, const Box& b, double gap = 0.0);  // closer than `gap`

// The enclosed area with a sign: > 0 counter-clockwise, < 0 clockwise (shoelace), m^2.
double signed_area(const std::vector<Point>& vertices);
// The exact area of the shape, m^2 (a polygon: |signed_area|).
double area(const Shape& s);
// The length of the shape's boundary, m: exact, but for an ellipse an upper bound,
// pi sqrt(2 (a^2 + b^2)) (at most 11 % above the exact length, at a flat ellipse).
double perimeter_at_most(const Shape& s);

// Edges are numbered by their first vertex: edge i runs from vertex i to vertex i + 1 (mod n).
// Returns the first pair (i < j) of edges that cross or touch, other than adjacent edges
// sharing their common vertex (adjacent edges that fold back over each other do count);
// nothing for a simple polygon. O(n^2).
std::optional<std::pair<int, int>> polygon_self_intersection(const std::vector<Point>& vertices);

// Cutting a region along a line (a crack inside one body, docs/interfaces.md):
// Where the ray from `p` (inside `frame`) along the direction `d` (nonzero) leaves the frame.
Point leave_box(const Box& frame, const Point& p, const Point& d);
// The part of `frame` left of `cut` (the side its normal, the direction turned +90 degrees,
// points to): `cut` is a simple polyline whose first and last points lie on the frame's edge
// and the others inside it. A polygon: the cut, then the frame's corners counter-clockwise
// from the cut's last point back to its first.
Shape left_part(const Box& frame, const std::vector<Point>& cut);
// The stretches of the segment a -> b that lie inside `r`, in order from a. An end where the
// segment crosses an axis-aligned edge takes that edge's coordinate exactly (a stretch that
// ends on a rectangle's side ends on it bitwise); the segment's own ends are a and b exactly.
struct Stretch {
  Point from, to;
};
std::vector<Stretch> inside_stretches(const Region& r, const Point& a, const Point& b);

}  // namespace rupture
