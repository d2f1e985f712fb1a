// rupture/grid/grid.hpp
// Background grid geometry and the per-velocity-field nodal arrays (SI: m, kg, kg m/s, N, m/s).
// The grid is a tensor product of two Axis objects; nodes are numbered row by row
// (n = j * nodes_x + i). Two ghost cells surround the physical domain so particles on a free
// edge can bulge outward without leaving the grid. Nodal data are stored field-major: the
// arrays of field f occupy [f * num_nodes, (f + 1) * num_nodes), contiguous per field.
#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include "shape/gimp.hpp"

namespace rupture {

// Nodes along one direction. Only uniform spacing is wired into the time step now; the
// node coordinates are explicit so a graded axis can replace it (SPEC §5).
struct Axis {
  double origin = 0.0;  // coordinate of node 0 (a ghost node), m
  double h = 0.0;       // cell size, m
  int cells = 0;        // number of cells, ghosts included

  int nodes() const { return cells + 1; }
  double node(int i) const { return origin + h * i; }
};

// 3-node stencil of a particle along one axis (uGIMP with lp <= h/2 touches at most 3 nodes).
struct Stencil1D {
  int first;     // index of the first node
  double s[3];   // weights
  double ds[3];  // d weight / d x_p, 1/m
};

// The particle at xp with half-width lp (<= h/2) touches nodes first..first+2 (SPEC E3).
// Nodes i0-1..i0+1 if xp lies in the left half of cell i0, else i0..i0+2.
inline void stencil(const Axis& a, double xp, double lp, Stencil1D& st) {
  const double inv_h = 1.0 / a.h;
  const double xi = (xp - a.origin) * inv_h;
  const double cell = std::floor(xi);
  const int first = int(cell) - (xi - cell < 0.5 ? 1 : 0);
  st.first = first;
  gimp_uniform_stencil(xi - double(first), lp * inv_h, inv_h, st.s, st.ds);
}

struct Grid {
  Axis x, y;
  int ghost = 2;           // ghost cells on each side
  double domain_min[2]{};  // physical domain (without ghosts), m
  double domain_max[2]{};

  int nodes_x() const { return x.nodes(); }
  int nodes_y() const { return y.nodes(); }
  std::size_t num_nodes() const { return std::size_t(nodes_x()) * std::size_t(nodes_y()); }
  std::size_t node_index(int i, int j) const { return std::size_t(j) * nodes_x() + i; }
  int physical_cells_x() const { return x.cells - 2 * ghost; }
  int physical_cells_y() const { return y.cells - 2 * ghost; }
  double cell_size() const { return x.h; }
};

// Uniform grid over [min, max] with cell size h plus the ghost cells on each side.
// Throws InputError if the extent is not a whole number of cells (within 1e-6 h).
Grid make_uniform_grid(const double min[2], const double max[2], double h);

// Per-field nodal arrays, field-major. See solver/ for when each array is valid.
struct GridFields {
  int num_fields = 0;
  std::size_t num_nodes = 0;
  std::vector<double> mass;          // lumped nodal mass m_i, kg
  std::vector<double> mom_x, mom_y;  // momentum p_i at t^n, kg m/s
  std::vector<double> force_x, force_y;  // total nodal force f_i, N (per unit thickness)
  std::vector<double> vel_x, vel_y;      // velocity at t^{n+1}, m/s
  std::vector<double> dvel_x, dvel_y;    // velocity increment over the step (dt * a_i), m/s
  std::vector<double> remap_x, remap_y;  // MUSL re-mapped momentum, then velocity

  void resize(int fields, std::size_t nodes);
  std::size_t offset(int field) const { return std::size_t(field) * num_nodes; }
  std::size_t bytes() const;
};

}  // namespace rupture
