// rupture/bc/absorbing.hpp
// Absorbing domain edges (Lysmer & Kuhlemeyer 1969): viscous dashpots on the grid nodes of an
// edge, a traction t = -rho c_P v_n n - rho c_S v_t t on the material there, which takes a plane
// P or S wave arriving along the normal out of the domain without reflection (the dashpot's
// impedance equals the medium's). Obliquely incident waves are absorbed in part (docs/faults.md
// gives the measured reflection at 0, 30 and 60 degrees).
// solver/absorbing_setup.hpp lists, once per run, every (field, node) on an absorbing edge that
// a body of that field reaches, with the dashpot coefficients C = rho c A (A: the node's share
// of the edge, half the adjacent cells' widths inside the body); the time step applies them in
// the trapezoidal form (solver/grid_update.cpp), so no step limit is added. Units: SI; C in kg/(s m) per unit
// thickness (N s/m per metre of thickness).
#pragma once
#include <cstddef>
#include <vector>

#include "bc/velocity_bc.hpp"
#include "grid/grid.hpp"

namespace rupture {

struct AbsorbingNode {
  int field;
  std::size_t node;   // node index within the field
  double nx, ny;      // outward unit normal of the edge
  double c_normal;    // rho c_P A, kg/s per unit thickness
  double c_tangent;   // rho c_S A, kg/s per unit thickness
  double vx = 0.0, vy = 0.0;  // this step's damped velocity (scratch), m/s
};



// "left", "right", "bottom", "top".
const char* edge_name(Edge e);

}  // namespace rupture
