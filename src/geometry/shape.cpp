// rupture/geometry/shape.cpp
#include "geometry/shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rupture {
namespace {

// (b - a) x (c - a): > 0 when c lies left of the line a -> b.
double orient(const Point& a, const Point& b, const Point& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// c is collinear with a-b (orient == 0): is it within the segment's box?
bool on_segment(const Point& a, const Point& b, const Point& c) {
  return c.x >= std::min(a.x, b.x) && c.x <= std::max(a.x, b.x) && c.y >= std::min(a.y, b.y) &&
         c.y <= std::max(a.y, b.y);
}

int sign(double v) {
  return (v > 0.0) - (v < 0.0);
}

// The side of a-b that c lies on (+1 left, -1 right), 0 when the three are collinear to
// round-off: |orient| within 1e-12 of the squared extent (the products' rounding, relative to
// their size), as the line checks of cohesive/polyline do. A straight line extended by points
// computed along it (a body split at an angle) is then collinear, not crossing itself.
int side(const Point& a, const Point& b, const Point& c) {
  const double v = orient(a, b, c);
  const double scale = std::max({std::fabs(b.x - a.x), std::fabs(b.y - a.y), std::fabs(c.x - a.x), std::fabs(c.y - a.y)});
  return std::fabs(v) <= 1e-12 * scale * scale ? 0 : sign(v);
}

// Closed segments p1-p2 and q1-q2 share a point (crossing or touching).
bool segments_meet(const Point& p1, const Point& p2, const Point& q1, const Point& q2) {
  const int o1 = side(p1, p2, q1), o2 = side(p1, p2, q2);
  const int o3 = side(q1, q2, p1), o4 = side(q1, q2, p2);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_segment(p1, p2, q1)) || (o2 == 0 && on_segment(p1, p2, q2)) ||
         (o3 == 0 && on_segment(q1, q2, p1)) || (o4 == 0 && on_segment(q1, q2, p2));
}

bool polygon_contains(const std::vector<Point>& v, double x, double y) {
  // Crossing number of a ray towards +x; half-open in y so a vertex is counted once. The
  // crossing is computed from the edge's lower end whichever way the polygon runs, so two
  // polygons sharing an edge round it alike: a point on that edge lies in exactly one of them.
  bool in = false;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const Point &a = v[i].y < v[j].y ? v[i] : v[j], &b = v[i].y < v[j].y ? v[j] : v[i];
    if ((a.y > y) != (b.y > y) && x < a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y)) in = !in;
  }
  return in;
}

}  // namespace

const char* shape_name(ShapeKind k) {
  switch (k) {
    case ShapeKind::rectangle:
      return "rectangle";
    case ShapeKind::polygon:
      return "polygon";
    case ShapeKind::circle:
      return "circle";
    case ShapeKind::ellipse:
      return "ellipse";
  }
  return "?";
}

bool contains(const Shape& s, double x, double y) {
  switch (s.kind) {
    case ShapeKind::rectangle:
      return x > s.min[0] && x < s.max[0] && y > s.min[1] && y < s.max[1];
    case ShapeKind::polygon:
      return polygon_contains(s.vertices, x, y);
    case ShapeKind::circle: {
      const double dx = x - s.center[0], dy = y - s.center[1];
      return dx * dx + dy * dy < s.radii[0] * s.radii[0];
    }
    case ShapeKind::ellipse: {
      // Coordinates along the ellipse's own axes (a-axis at `angle` from +x).
      const double dx = x - s.center[0], dy = y - s.center[1];
      const double c = std::cos(s.angle), sn = std::sin(s.angle);
      const double u = (c * dx + sn * dy) / s.radii[0], w = (-sn * dx + c * dy) / s.radii[1];
      return u * u + w * w < 1.0;
    }
  }
  return false;
}

bool contains(const Region& r, double x, double y) {
  if (!contains(r.outer, x, y)) return false;
  for (const Shape& m : r.minus)
    if (contains(m, x, y)) return false;
  for (const Side& side : r.sides)
    if (contains(side.shape, x, y) != side.inside) return false;
  for (const std::vector<Side>& part : r.minus_parts) {
    bool in_part = true;
    for (const Side& side : part) in_part = in_part && contains(side.shape, x, y) == side.inside;
    if (in_part) return false;
  }
  return true;
}

Box bounding_box(const Shape& s) {
  Box b;
  switch (s.kind) {
    case ShapeKind::rectangle:
      b = {{s.min[0], s.min[1]}, {s.max[0], s.max[1]}};
      break;
    case ShapeKind::polygon:
      b = {{s.vertices[0].x, s.vertices[0].y}, {s.vertices[0].x, s.vertices[0].y}};
      for (const Point& p : s.vertices) {
        b.min[0] = std::min(b.min[0], p.x), b.max[0] = std::max(b.max[0], p.x);
        b.min[1] = std::min(b.min[1], p.y), b.max[1] = std::max(b.max[1], p.y);
      }
      break;
    case ShapeKind::circle:
    case ShapeKind::ellipse: {
      // Half-extents of the rotated ellipse: sqrt(a^2 cos^2 + b^2 sin^2) along x, and so on.
      const double a = s.radii[0], bb = s.radii[1];
      const double c = std::cos(s.angle), sn = std::sin(s.angle);
      const double wx = s.kind == ShapeKind::circle ? a : std::hypot(a * c, bb * sn);
      const double wy = s.kind == ShapeKind::circle ? a : std::hypot(a * sn, bb * c);
      b = {{s.center[0] - wx, s.center[1] - wy}, {s.center[0] + wx, s.center[1] + wy}};
      break;
    }
  }
  return b;
}

Box bounding_box(const Region& r) {
  return bounding_box(r.outer);
}

bool same_shape(const Shape& a, const Shape& b) {
  if (a.kind != b.kind || a.angle != b.angle || a.vertices.size() != b.vertices.size()) return false;
  for (int d = 0; d < 2; ++d)
    if (a.min[d] != b.min[d] || a.max[d] != b.max[d] || a.center[d] != b.center[d] || a.radii[d] != b.radii[d])
      return false;
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    if (a.vertices[i].x != b.vertices[i].x || a.vertices[i].y != b.vertices[i].y) return false;
  return true;
}

bool same_drawn_region(const Region& a, const Region& b) {
  if (!same_shape(a.outer, b.outer) || a.minus.size() != b.minus.size()) return false;
  for (std::size_t i = 0; i < a.minus.size(); ++i)
    if (!same_shape(a.minus[i], b.minus[i])) return false;
  return true;
}

Box region_box(const Region& r) {
  Box b = bounding_box(r.outer);
  for (const Side& side : r.sides) {
    if (!side.inside) continue;
    const Box s = bounding_box(side.shape);
    for (int d = 0; d < 2; ++d) b.min[d] = std::max(b.min[d], s.min[d]), b.max[d] = std::min(b.max[d], s.max[d]);
  }
  return b;
}

bool boxes_overlap(const Box& a, const Box& b, double gap) {
  return a.min[0] < b.max[0] + gap && b.min[0] < a.max[0] + gap && a.min[1] < b.max[1] + gap &&
         b.min[1] < a.max[1] + gap;
}

double signed_area(const std::vector<Point>& v) {
  double twice = 0.0;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++)
    twice += v[j].x * v[i].y - v[i].x * v[j].y;
  return 0.5 * twice;
}

double area(const Shape& s) {
  switch (s.kind) {
    case ShapeKind::rectangle:
      return (s.max[0] - s.min[0]) * (s.max[1] - s.min[1]);
    case ShapeKind::polygon:
      return std::fabs(signed_area(s.vertices));
    case ShapeKind::circle:
    case ShapeKind::ellipse:
      return std::numbers::pi * s.radii[0] * s.radii[1];
  }
  return 0.0;
}

double perimeter_at_most(const Shape& s) {
  switch (s.kind) {
    case ShapeKind::rectangle:
      return 2.0 * ((s.max[0] - s.min[0]) + (s.max[1] - s.min[1]));
    case ShapeKind::polygon: {
      double p = 0.0;
      for (std::size_t i = 0; i < s.vertices.size(); ++i) {
        const Point &a = s.vertices[i], &b = s.vertices[(i + 1) % s.vertices.size()];
        p += std::hypot(b.x - a.x, b.y - a.y);
      }
      return p;
    }
    case ShapeKind::circle:
      return 2.0 * std::numbers::pi * s.radii[0];
    case ShapeKind::ellipse:
      // The root mean square radius bounds the mean radius (Cauchy-Schwarz on the length's integral).
      return std::numbers::pi * std::sqrt(2.0 * (s.radii[0] * s.radii[0] + s.radii[1] * s.radii[1]));
  }
  return 0.0;
}

std::optional<std::pair<int, int>> polygon_self_intersection(const std::vector<Point>& v) {
  const int n = int(v.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const Point &a0 = v[std::size_t(i)], &a1 = v[std::size_t((i + 1) % n)];
      const Point &b0 = v[std::size_t(j)], &b1 = v[std::size_t((j + 1) % n)];
      const bool next = j == i + 1, wrap = i == 0 && j == n - 1;
      if (next || wrap) {
        // Adjacent edges share one vertex: they meet elsewhere only by folding back over each
        // other (collinear, pointing the same way from the shared vertex).
        const Point& s = next ? a1 : a0;  // the shared vertex
        const Point& p = next ? a0 : a1;  // the other end of edge i
        const Point& q = next ? b1 : b0;  // the other end of edge j
        if (side(p, s, q) == 0 && (p.x - s.x) * (q.x - s.x) + (p.y - s.y) * (q.y - s.y) > 0.0)
          return std::make_pair(i, j);
        continue;
      }
      if (segments_meet(a0, a1, b0, b1)) return std::make_pair(i, j);
    }
  return std::nullopt;
}

Point leave_box(const Box& frame, const Point& p, const Point& d) {
  // The nearest of the frame's sides ahead of p along d.
  double t = INFINITY;
  for (int k = 0; k < 2; ++k) {
    const double dk = k == 0 ? d.x : d.y, pk = k == 0 ? p.x : p.y;
    if (dk > 0.0) t = std::min(t, (frame.max[k] - pk) / dk);
    if (dk < 0.0) t = std::min(t, (frame.min[k] - pk) / dk);
  }
  return {p.x + t * d.x, p.y + t * d.y};
}

namespace {

// Position along the frame's edge, counter-clockwise from the lower-left corner: the corners
// are at 0, 1, 2, 3 (lower-left, lower-right, upper-right, upper-left), each side spans 1.
double perimeter_position(const Box& f, const Point& p) {
  const double w = f.max[0] - f.min[0], h = f.max[1] - f.min[1];
  const double gap[4] = {std::fabs(p.y - f.min[1]) / h, std::fabs(p.x - f.max[0]) / w,
                         std::fabs(p.y - f.max[1]) / h, std::fabs(p.x - f.min[0]) / w};
  const int side = int(std::min_element(gap, gap + 4) - gap);
  switch (side) {
    case 0:
      return (p.x - f.min[0]) / w;
    case 1:
      return 1.0 + (p.y - f.min[1]) / h;
    case 2:
      return 2.0 + (f.max[0] - p.x) / w;
    default:
      return std::fmod(3.0 + (f.max[1] - p.y) / h, 4.0);
  }
}

// Where segment a -> b crosses segment p -> q: the parameter t along a -> b in (0, 1), or
// nothing (parallel segments never count: a ray along an edge is decided by the midpoints).
struct Crossing {
  double t;
  Point at;
};
void edge_crossing(const Point& a, const Point& b, const Point& p, const Point& q,
                   std::vector<Crossing>& out) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = q.x - p.x, vy = q.y - p.y;
  const double den = ux * vy - uy * vx;
  if (den == 0.0) return;
  const double wx = p.x - a.x, wy = p.y - a.y;
  const double t = (wx * vy - wy * vx) / den, s = (wx * uy - wy * ux) / den;
  if (!(t > 0.0 && t < 1.0 && s >= 0.0 && s <= 1.0)) return;
  Point at{a.x + t * ux, a.y + t * uy};
  if (p.x == q.x) at.x = p.x;  // an axis-aligned edge: its coordinate exactly
  if (p.y == q.y) at.y = p.y;
  out.push_back({t, at});
}

void shape_crossings(const Shape& s, const Point& a, const Point& b, std::vector<Crossing>& out) {
  switch (s.kind) {
    case ShapeKind::rectangle: {
      const Point c[4] = {
          {s.min[0], s.min[1]}, {s.max[0], s.min[1]}, {s.max[0], s.max[1]}, {s.min[0], s.max[1]}};
      for (int k = 0; k < 4; ++k) edge_crossing(a, b, c[k], c[(k + 1) % 4], out);
      return;
    }
    case ShapeKind::polygon:
      for (std::size_t i = 0, j = s.vertices.size() - 1; i < s.vertices.size(); j = i++)
        edge_crossing(a, b, s.vertices[j], s.vertices[i], out);
      return;
    case ShapeKind::circle:
    case ShapeKind::ellipse: {
      // In the ellipse's own axes, scaled to the unit circle: |u0 + t u1|^2 = 1.
      const double c = std::cos(s.angle), sn = std::sin(s.angle);
      auto frame = [&](double x, double y, double& u, double& w) {
        u = (c * x + sn * y) / s.radii[0];
        w = (-sn * x + c * y) / s.radii[1];
      };
      double u0, w0, u1, w1;
      frame(a.x - s.center[0], a.y - s.center[1], u0, w0);
      frame(b.x - a.x, b.y - a.y, u1, w1);
      const double qa = u1 * u1 + w1 * w1, qb = u0 * u1 + w0 * w1, qc = u0 * u0 + w0 * w0 - 1.0;
      const double disc = qb * qb - qa * qc;
      if (qa == 0.0 || disc <= 0.0) return;
      for (const double t : {(-qb - std::sqrt(disc)) / qa, (-qb + std::sqrt(disc)) / qa})
        if (t > 0.0 && t < 1.0) out.push_back({t, {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}});
      return;
    }
  }
}

}  // namespace

Shape left_part(const Box& frame, const std::vector<Point>& cut) {
  Shape s;
  s.kind = ShapeKind::polygon;
  s.vertices = cut;
  const double last = perimeter_position(frame, cut.back());
  double first = perimeter_position(frame, cut.front());
  if (first <= last) first += 4.0;
  const Point corner[4] = {{frame.min[0], frame.min[1]},
                           {frame.max[0], frame.min[1]},
                           {frame.max[0], frame.max[1]},
                           {frame.min[0], frame.max[1]}};
  // Counter-clockwise along the frame from the cut's end back to its start: with the cut
  // walked forwards, what lies on its left is enclosed.
  for (int k = int(std::floor(last)) + 1; double(k) < first; ++k) {
    if (std::fabs(double(k) - last) < 1e-12 || std::fabs(double(k) - first) < 1e-12) continue;
    s.vertices.push_back(corner[k % 4]);
  }
  return s;
}

std::vector<Stretch> inside_stretches(const Region& r, const Point& a, const Point& b) {
  std::vector<Crossing> x{{0.0, a}, {1.0, b}};
  shape_crossings(r.outer, a, b, x);
  for (const Shape& m : r.minus) shape_crossings(m, a, b, x);
  for (const Side& side : r.sides) shape_crossings(side.shape, a, b, x);
  for (const std::vector<Side>& part : r.minus_parts)
    for (const Side& side : part) shape_crossings(side.shape, a, b, x);
  std::sort(x.begin(), x.end(), [](const Crossing& u, const Crossing& v) { return u.t < v.t; });
  // Between consecutive crossings the segment is wholly in or out: its midpoint says which.
  std::vector<Stretch> out;
  bool open = false;
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    if (x[k + 1].t - x[k].t <= 1e-12) continue;
    const double tm = 0.5 * (x[k].t + x[k + 1].t);
    const bool in = contains(r, a.x + tm * (b.x - a.x), a.y + tm * (b.y - a.y));
    if (in && open) out.back().to = x[k + 1].at;
    if (in && !open) out.push_back({x[k].at, x[k + 1].at});
    open = in;
  }
  return out;
}

}  // namespace rupture
