// rupture/cohesive/polyline.hpp
// The line a cohesive interface or a bonded tie lies on: straight pieces through a list of
// vertices, open or closed. Arc length s runs from the first vertex along the pieces. The
// normal of a piece is its direction turned by +90 degrees, n = (-t_y, t_x): for a line drawn
// in +x it points to +y. The "upper" body of an interface is the one n points into.
// discretize() puts a node on every vertex and splits each piece into segments of nearly equal
// length; project() gives the nearest point of the line. Units: m.
#pragma once
#include <cstddef>
#include <vector>

namespace rupture {

struct Polyline {
  std::vector<double> x, y;  // vertices, m
  bool closed = false;       // the last vertex joins the first

  std::size_t num_vertices() const { return x.size(); }
  std::size_t num_pieces() const { return closed ? x.size() : x.size() - 1; }
  double piece_length(std::size_t i) const;
  double length() const;
  // Piece i goes from vertex i to vertex (i + 1) mod n.
  std::size_t piece_end(std::size_t i) const { return (i + 1) % x.size(); }
};

// Nodes of `segments` segments along the line: every vertex is a node, and piece i gets
// n_i >= 1 segments of equal length, n_i proportional to its length (largest remainders),
// with sum n_i = segments (validated: segments >= number of pieces). A closed line has as many
// nodes as segments (the last segment ends on node 0); an open one has one more.
// On a single straight piece, node k is exactly x0 + (x1 - x0) k / segments.
struct LineNodes {
  std::vector<double> x, y, s;  // node positions and arc length, m
};
LineNodes discretize(const Polyline& line, int segments);

// The nearest point of the line to (px, py): its distance, arc length and the unit normal of
// the piece it lies on. `beyond` is how far the orthogonal projection falls outside the line's
// ends, measured along it (0 if it falls on the line; always 0 for a closed line).
struct LineProjection {
  double distance = 0.0, s = 0.0, beyond = 0.0;
  double nx = 0.0, ny = 0.0;
};
LineProjection project(const Polyline& line, double px, double py);

// Position at arc length s (clamped to the line), m.
void point_at(const Polyline& line, double s, double& x, double& y);

// Index pair (i, j) of two non-adjacent pieces that cross, or {-1, -1} if the line is simple.
struct PieceCrossing {
  int i = -1, j = -1;
};
PieceCrossing first_self_crossing(const Polyline& line);

// Whether two segments cross properly: each one's ends lie strictly on both sides of the
// other (touching at an end, or overlapping along a line, does not count).
bool segments_cross(double ax0, double ay0, double ax1, double ay1, double bx0, double by0,
                    double bx1, double by1);

// Whether two segments [a0, a1] and [b0, b1] intersect (touching counts).
bool segments_intersect(double ax0, double ay0, double ax1, double ay1, double bx0, double by0,
                        double bx1, double by1);

}  // namespace rupture
