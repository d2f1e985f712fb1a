// rupture/solver/absorbing_setup.cpp
#include "solver/absorbing_setup.hpp"

#include <algorithm>
#include <cmath>

#include "material/elastic.hpp"

namespace rupture {

std::vector<AbsorbingNode> absorbing_nodes(const Case& c, const Grid& grid) {
  return absorbing_nodes(c, grid, c.absorbing_edges, nullptr);
}

std::vector<AbsorbingNode> absorbing_nodes(const Case& c, const Grid& grid, const std::vector<Edge>& edges,
                                           const std::function<bool(double, double)>* owns) {
  std::vector<AbsorbingNode> out;
  for (const Edge e : edges) {
    const bool vertical = e == Edge::left || e == Edge::right;
    const Axis& along = vertical ? grid.y : grid.x;
    const Axis& across = vertical ? grid.x : grid.y;
    // The lattice line on the domain edge (a nested level's lattice may reach past the edge by
    // the coarsest level's ghost ring, not its own).
    const int d = vertical ? 0 : 1;
    const bool low = e == Edge::left || e == Edge::bottom;
    const double edge = low ? grid.domain_min[d] : grid.domain_max[d];
    int line = 0;
    for (int k = 1; k < across.nodes(); ++k)
      if (std::fabs(across.node(k) - edge) < std::fabs(across.node(line) - edge)) line = k;
    const double inward = low ? 1.0 : -1.0;
    const double nx = vertical ? -inward : 0.0, ny = vertical ? 0.0 : -inward;
    const double pos = across.node(line);
    // A point a quarter of the adjacent cell inside the domain: which body is there.
    const double probe = pos + inward * 0.25 * across.width(inward > 0 ? line : line - 1);
    for (int k = 0; k < along.nodes(); ++k) {
      for (std::size_t f = 0; f < c.field_names.size(); ++f) {
        // The node's share of the edge: half of each adjacent cell whose middle the field's
        // bodies hold (a body ending along the edge ends the share there).
        double area = 0.0;
        const BodySpec* body = nullptr;
        for (int side = -1; side <= 0; ++side) {
          const int cell = k + side;
          if (cell < 0 || cell >= along.cells) continue;
          const double mid = along.node(cell) + 0.5 * along.width(cell);
          const double x = vertical ? probe : mid, y = vertical ? mid : probe;
          if (owns && !(*owns)(x, y)) continue;  // another level's part of the edge
          for (const BodySpec& b : c.bodies) {
            if (std::size_t(b.field) != f) continue;
            if (!body_contains(b, x, y)) continue;
            area += 0.5 * along.width(cell);
            if (!body) body = &b;
            break;
          }
        }
        if (!body) continue;
        const ElasticMaterial& m = c.materials[std::size_t(body->material)];
        const WaveSpeeds w = wave_speeds(m, c.plane);
        const std::size_t node = vertical ? grid.node_index(line, k) : grid.node_index(k, line);
        out.push_back({int(f), node, nx, ny, m.density * w.dilatational * area,
                       m.density * w.shear * area});
      }
    }
  }
  return out;
}

}  // namespace rupture
