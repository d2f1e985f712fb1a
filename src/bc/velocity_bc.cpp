// rupture/bc/velocity_bc.cpp
#include "bc/velocity_bc.hpp"

#include <algorithm>
#include <cmath>

namespace rupture {

namespace {
bool vertical(Edge e) { return e == Edge::left || e == Edge::right; }

// The body lies towards larger line indices from a left or bottom edge.
bool inward_is_up(Edge e) { return e == Edge::left || e == Edge::bottom; }

// Index of the initial edge line.
int initial_line(const VelocityBC& bc, const Grid& grid) {
  switch (bc.edge) {
    case Edge::left: return grid.ghost;
    case Edge::right: return grid.x.cells - grid.ghost;
    case Edge::bottom: return grid.ghost;
    case Edge::top: return grid.y.cells - grid.ghost;
  }
  return 0;
}
}  // namespace

int edge_line(const VelocityBC& bc, const Grid& grid, int base, double t) {
  if (!bc.moves()) return base;
  const Axis& across = vertical(bc.edge) ? grid.x : grid.y;
  const double pos = across.node(base) + bc.velocity.displacement(t);
  // Nearest node: the cell holding pos, then whichever of its two nodes is closer.
  int c = across.cell_of(pos);
  c = std::clamp(c, 0, across.cells - 1);
  const int nearest = (pos - across.node(c) <= across.node(c + 1) - pos) ? c : c + 1;
  return std::clamp(nearest, 0, across.nodes() - 1);
}

void initial_lines(const std::vector<VelocityBC>& bcs, const Grid& grid, std::vector<int>& lines) {
  lines.clear();
  for (const VelocityBC& bc : bcs) lines.push_back(initial_line(bc, grid));
}

std::vector<int> initial_lines(const std::vector<VelocityBC>& bcs, const Grid& grid) {
  std::vector<int> lines;
  initial_lines(bcs, grid, lines);
  return lines;
}

int edge_line(const VelocityBC& bc, const Grid& grid, double t) {
  return edge_line(bc, grid, initial_line(bc, grid), t);
}

bool update_edge_lines(const std::vector<VelocityBC>& bcs, const std::vector<int>& base,
                       const Grid& grid, double t, std::vector<int>& lines) {
  bool changed = lines.size() != bcs.size();
  lines.resize(bcs.size(), -1);
  for (std::size_t c = 0; c < bcs.size(); ++c) {
    const int l = edge_line(bcs[c], grid, base[c], t);
    changed = changed || l != lines[c];
    lines[c] = l;
  }
  return changed;
}

bool update_edge_lines(const std::vector<VelocityBC>& bcs, const Grid& grid, double t,
                       std::vector<int>& lines) {
  return update_edge_lines(bcs, initial_lines(bcs, grid), grid, t, lines);
}

std::vector<NodeBC> resolve_nodes(const std::vector<VelocityBC>& bcs, const Grid& grid,
                                  int num_fields, const std::vector<int>& lines) {
  std::vector<NodeBC> out;
  const double tol = 1e-9 * grid.cell_size();
  for (std::size_t c = 0; c < bcs.size(); ++c) {
    const VelocityBC& bc = bcs[c];
    const bool vert = vertical(bc.edge);
    const Axis& along = vert ? grid.y : grid.x;
    const Axis& across = vert ? grid.x : grid.y;
    const int line = lines[c];
    // Lines outside the current edge line lie in the piston's region (moving conditions only).
    const bool up = inward_is_up(bc.edge);
    const int first = !bc.moves() ? line : (up ? 0 : line);
    const int last = !bc.moves() ? line : (up ? line : across.nodes() - 1);
    std::vector<int> fields = bc.fields;
    if (fields.empty())
      for (int f = 0; f < num_fields; ++f) fields.push_back(f);
    for (int l = first; l <= last; ++l)
      for (int k = 0; k < along.nodes(); ++k) {
        const double s = along.node(k);
        if (s < bc.from - tol || s > bc.to + tol) continue;
        const std::size_t node = vert ? grid.node_index(l, k) : grid.node_index(k, l);
        for (int f : fields) out.push_back({f, node, bc.component, int(c)});
      }
  }
  return out;
}

std::vector<NodeBC> resolve_nodes(const std::vector<VelocityBC>& bcs, const Grid& grid,
                                  int num_fields) {
  std::vector<int> lines;
  update_edge_lines(bcs, grid, 0.0, lines);
  return resolve_nodes(bcs, grid, num_fields, lines);
}

}  // namespace rupture
