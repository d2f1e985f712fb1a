// rupture/input/parse_shape.cpp
// One shape of a body or of a cut-out (geometry/shape.hpp) from its table: `shape` picks the
// kind (rectangle by default) and only that kind's keys may be given. Polygons must be simple.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "input/case_parse.hpp"
#include "input/input_schema.hpp"

namespace rupture {
namespace {

// The keys of one kind of shape: those documented "only with shape = <kind>".
std::vector<std::string> keys_of(ShapeKind k) {
  return variant_keys("bodies.*.minus[]", "shape", shape_name(k));
}

std::string point(const Point& p) {
  return fmt::format("({:g}, {:g})", p.x, p.y);
}

std::vector<Point> parse_vertices(Section& s) {
  const std::string key = s.key("vertices");
  const toml::node* n = s.node("vertices");
  if (!n) fail(key, "(missing)", "required, an array of at least 3 points [[x, y], ...] (m)");
  const toml::array* a = n->as_array();
  if (!a || a->size() < 3)
    fail(key, show(*n), "must be an array of at least 3 points [[x, y], ...] (m)");
  std::vector<Point> v;
  for (const toml::node& e : *a) {
    const toml::array* xy = e.as_array();
    std::optional<double> x, y;
    if (xy && xy->size() == 2) x = (*xy)[0].value<double>(), y = (*xy)[1].value<double>();
    if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y))
      fail(key, show(*n),
           fmt::format("vertex {} is {}: every vertex must be an array of two finite numbers "
                       "[x, y] (m)",
                       v.size(), show(e)));
    v.push_back({*x, *y});
  }
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j)
      if (v[i].x == v[j].x && v[i].y == v[j].y)
        fail(key, show(*n),
             fmt::format("vertices {} and {} are the same point {}: each vertex must appear once "
                         "(counting from 0)",
                         i, j, point(v[i])));
  // Collinear vertices first: their edges fold back over each other, which the crossing test
  // would report less clearly (and, within round-off, either way). Collinear: every vertex
  // within round-off of the line through vertex 0 and the vertex farthest from it.
  const Box b = bounding_box(Shape{ShapeKind::polygon, {}, {}, v, {}, {}, 0.0});
  const double extent = std::max(b.max[0] - b.min[0], b.max[1] - b.min[1]);
  {
    std::size_t far = 0;
    for (std::size_t i = 1; i < v.size(); ++i)
      if (std::hypot(v[i].x - v[0].x, v[i].y - v[0].y) >
          std::hypot(v[far].x - v[0].x, v[far].y - v[0].y))
        far = i;
    const double dx = v[far].x - v[0].x, dy = v[far].y - v[0].y, len = std::hypot(dx, dy);
    double off = 0.0;
    for (const Point& q : v)
      off = std::max(off, std::fabs((q.x - v[0].x) * dy - (q.y - v[0].y) * dx) / len);
    if (!(off > 1e-9 * extent))
      fail(key, show(*n), "the polygon encloses no area (its vertices are collinear)");
  }
  if (const auto cross = polygon_self_intersection(v)) {
    const auto [i, j] = *cross;
    const std::size_t n_v = v.size();
    fail(key, show(*n),
         fmt::format("the polygon intersects itself: edge {} from {} to {} meets edge {} from {} "
                     "to {} (edge k runs from vertex k to vertex k + 1, counting from 0); the "
                     "polygon must be simple, its edges meeting only at shared vertices",
                     i, point(v[std::size_t(i)]), point(v[std::size_t(i + 1) % n_v]), j,
                     point(v[std::size_t(j)]), point(v[std::size_t(j + 1) % n_v])));
  }
  if (!(std::fabs(signed_area(v)) > 1e-12 * extent * extent))
    fail(key, show(*n), "the polygon encloses no area");
  return v;
}

}  // namespace

Shape parse_shape(Section& s, const char* what) {
  Shape shape;
  const std::string kind =
      s.string("shape", "rectangle", {"rectangle", "polygon", "circle", "ellipse"});
  shape.kind = kind == "rectangle" ? ShapeKind::rectangle
               : kind == "polygon" ? ShapeKind::polygon
               : kind == "circle"  ? ShapeKind::circle
                                   : ShapeKind::ellipse;
  const std::vector<std::string> own = keys_of(shape.kind);
  for (const ShapeKind other :
       {ShapeKind::rectangle, ShapeKind::polygon, ShapeKind::circle, ShapeKind::ellipse})
    for (const std::string& k : keys_of(other))
      if (s.has(k) && std::find(own.begin(), own.end(), k) == own.end())
        fail(s.key(k), show(*s.node(k)),
             fmt::format("not a key of shape = \"{}\" (it takes {}); {} belongs to shape = \"{}\"",
                         kind, Section::join(own), k, shape_name(other)));
  switch (shape.kind) {
    case ShapeKind::rectangle:
      s.pair("min", shape.min, true);
      s.pair("max", shape.max, true);
      for (int d = 0; d < 2; ++d)
        if (!(shape.max[d] > shape.min[d]))
          fail(s.key("max"), fmt::format("[{:g}, {:g}]", shape.max[0], shape.max[1]),
               fmt::format("the {} is empty: must exceed {} = [{:g}, {:g}] in both components",
                           what, s.key("min"), shape.min[0], shape.min[1]));
      break;
    case ShapeKind::polygon:
      shape.vertices = parse_vertices(s);
      break;
    case ShapeKind::circle: {
      s.pair("center", shape.center, true);
      const double r = s.number("radius");
      if (!(r > 0)) fail(s.key("radius"), r, "must be > 0 (m)");
      shape.radii[0] = shape.radii[1] = r;
      break;
    }
    case ShapeKind::ellipse:
      s.pair("center", shape.center, true);
      if (!s.has("radii"))
        fail(s.key("radii"), "(missing)", "required, the semi-axes [a, b] (m), both > 0");
      s.pair("radii", shape.radii, true);
      if (!(shape.radii[0] > 0 && shape.radii[1] > 0))
        fail(s.key("radii"), fmt::format("[{:g}, {:g}]", shape.radii[0], shape.radii[1]),
             "both semi-axes [a, b] must be > 0 (m)");
      shape.angle = s.number("angle", 0.0) * std::numbers::pi / 180.0;  // degrees in the input
      break;
  }
  return shape;
}

std::string describe_extent(const Box& b) {
  return fmt::format("[{:g}, {:g}]..[{:g}, {:g}]", b.min[0], b.min[1], b.max[0], b.max[1]);
}

}  // namespace rupture
