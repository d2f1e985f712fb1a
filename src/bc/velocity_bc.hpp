// rupture/bc/velocity_bc.hpp
// Prescribed-velocity boundary conditions on grid nodes (SPEC E2). A condition names an edge
// of the physical domain, a coordinate range along it, one velocity component and the velocity
// fields (bodies) it acts on. Everything else is traction-free (nothing to do in MPM).
// resolve_nodes() turns conditions into a flat list of (field, node, component) entries once,
// so the time step applies them with a plain loop.
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
};

struct NodeBC {
  int field;
  std::size_t node;  // node index within the field
  int component;
  int condition;  // index into the VelocityBC list (for the time function)
};

// Nodes on the edge whose coordinate along it lies in [from, to] (with a 1e-9 h tolerance).
std::vector<NodeBC> resolve_nodes(const std::vector<VelocityBC>& bcs, const Grid& grid,
                                  int num_fields);

}  // namespace rupture
