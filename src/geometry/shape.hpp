// rupture/geometry/shape.hpp
// Plane regions that bodies are made of (units: m, angles in rad): axis-aligned rectangles,
// simple polygons (either orientation), circles and rotated ellipses, and a Region = one outer
// shape minus any number of cut-outs. contains() answers whether a point lies inside; points
// within round-off of a boundary may go either way (seeding never asks about them for shapes
// on grid lines: sub-cell centres sit half a sub-cell inside). Shapes are validated by io/
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

// One outer shape with cut-outs (holes, notches): a point is in the region when it is in the
// outer shape and in none of `minus`.
struct Region {
  Shape outer;
  std::vector<Shape> minus;
};

const char* shape_name(ShapeKind k);  // "rectangle", "polygon", "circle", "ellipse"

bool contains(const Shape& s, double x, double y);
bool contains(const Region& r, double x, double y);

Box bounding_box(const Shape& s);
Box bounding_box(const Region& r);                                 // the outer shape's box
bool boxes_overlap(const Box& a, const Box& b, double gap = 0.0);  // closer than `gap`

// The enclosed area with a sign: > 0 counter-clockwise, < 0 clockwise (shoelace), m^2.
double signed_area(const std::vector<Point>& vertices);
// The exact area of the shape, m^2 (a polygon: |signed_area|).
double area(const Shape& s);

// Edges are numbered by their first vertex: edge i runs from vertex i to vertex i + 1 (mod n).
// Returns the first pair (i < j) of edges that cross or touch, other than adjacent edges
// sharing their common vertex (adjacent edges that fold back over each other do count);
// nothing for a simple polygon. O(n^2).
std::optional<std::pair<int, int>> polygon_self_intersection(const std::vector<Point>& vertices);

}  // namespace rupture
