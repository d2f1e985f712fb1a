// rupture/bc/velocity_bc.hpp
// Prescribed-velocity boundary conditions on grid nodes (theory E2). A condition names an edge
// of the physical domain, a coordinate range along it, one velocity component and the velocity
// fields (bodies) it acts on. Everything else is traction-free (nothing to do in MPM).
//
// The grid is fixed but the material is not: an edge driven along its normal moves by
// u(t) = integral of V, and after u exceeds about one cell the nodes of the initial edge line
// carry no mass and would no longer load anything (the impact pulse would be cut short at fine
// grids). A condition normal to its edge therefore follows the edge (follow_edge, default on):
// it acts on the grid line nearest to the edge's current position and on every line outside it
// (the region a rigid piston pushing the edge occupies; nodes there with mass only see the tails
// of the edge particles). A tangential condition stays on the initial edge line.
// resolve_nodes() turns conditions into a flat list of (field, node, component) entries, so the
// time step applies them with a plain loop; it is rebuilt only when a driven line changes.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "bc/time_function.hpp"
#include "grid/grid.hpp"

namespace rupture {

enum class Edge { left, right, bottom, top };

struct VelocityBC {
  std::string name;
  Edge edge = Edge::left;
  double from = 0.0, to = 0.0;  // range along the edge (y for left/right, x for bottom/top), m
  int component = 0;            // 0: v_x, 1: v_y
  std::vector<int> fields;      // fields it acts on; empty = every field
  TimeFunction velocity;        // m/s
  bool follow_edge = true;      // a normal condition acts where the edge is now (see above)

  bool normal() const {
    return component == ((edge == Edge::left || edge == Edge::right) ? 0 : 1);
  }
  bool moves() const { return follow_edge && normal(); }
};

struct NodeBC {
  int field;
  std::size_t node;  // node index within the field
  int component;
  int condition;  // index into the VelocityBC list (for the time function)
};

// Index of the grid line (a node column for left/right edges, a node row for bottom/top) nearest
// to the edge of condition bc at time t: line `base` (where the edge starts, t = 0), moved by the
// velocity's displacement when bc.moves(). Clamped to the grid. The one rule for the single grid
// (base: initial_lines) and for each nested level (base: the level's own line of the edge,
// solver/nested_state.cpp).
int edge_line(const VelocityBC& bc, const Grid& grid, int base, double t);
// Where every condition's edge starts on the single grid (the domain's edges, inside the ghosts).
std::vector<int> initial_lines(const std::vector<VelocityBC>& bcs, const Grid& grid);
void initial_lines(const std::vector<VelocityBC>& bcs, const Grid& grid, std::vector<int>& lines);  // into lines, reusing it
// The same from the single grid's initial line.
int edge_line(const VelocityBC& bc, const Grid& grid, double t);

// Sets lines[c] = edge_line(bcs[c], grid, base[c], t) for every condition (resizing lines if
// needed); returns true if any entry changed. Without base: from initial_lines.
bool update_edge_lines(const std::vector<VelocityBC>& bcs, const std::vector<int>& base,
                       const Grid& grid, double t, std::vector<int>& lines);
bool update_edge_lines(const std::vector<VelocityBC>& bcs, const Grid& grid, double t,
                       std::vector<int>& lines);

// Nodes of condition c whose coordinate along the edge lies in [from, to] (with a 1e-9 h
// tolerance), on the line lines[c] and, for a condition that moves, every line outside it.
std::vector<NodeBC> resolve_nodes(const std::vector<VelocityBC>& bcs, const Grid& grid,
                                  int num_fields, const std::vector<int>& lines);

// The nodes at time 0 (the initial edge lines).
std::vector<NodeBC> resolve_nodes(const std::vector<VelocityBC>& bcs, const Grid& grid,
                                  int num_fields);

}  // namespace rupture
