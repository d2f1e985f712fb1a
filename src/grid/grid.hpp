// rupture/grid/grid.hpp
// Background grid geometry and the per-velocity-field nodal arrays (SI: m, kg, kg m/s, N, m/s).
// The grid is a tensor product of two Axis objects; nodes are numbered row by row
// (n = j * nodes_x + i). Ghost cells (two, or more: see make_uniform_grid) surround the physical
// domain so particles on a free
// edge can bulge outward without leaving the grid. Nodal data are stored field-major, each
// field only over its window of nodes (GridFields): memory grows with the fields' extents,
// not with fields x whole grid.
#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include "shape/gimp.hpp"

namespace rupture {

// Nodes along one direction: uniform (spacing h) or graded (theory §5: cell sizes that are
// power-of-two multiples of the finest size h, changing by at most a factor 2 from one cell to
// the next, every cell boundary on a multiple of h from the origin). A graded axis stores its
// node coordinates and, per unit interval of length h, the cell that contains it, so locating
// a point stays O(1).
struct Axis {
  double origin = 0.0;  // coordinate of node 0 (a ghost node), m
  double h = 0.0;       // uniform: the cell size; graded: the finest cell size (the unit), m
  int cells = 0;        // number of cells, ghosts included
  std::vector<double> coord;      // graded only: node coordinates, m (cells + 1)
  std::vector<int> cell_of_unit;  // graded only: cell holding [origin + k h, origin + (k+1) h)
  // graded only: 1 where cells c-1 .. c+2 are equal, so a stencil starting at node c sees a
  // uniform axis and the uniform (SIMD) form of the weights applies
  std::vector<unsigned char> uniform_from;
  std::vector<double> inv_width;  // graded only: 1 / width(c) per cell, 1/m

  bool graded() const { return !coord.empty(); }
  int nodes() const { return cells + 1; }
  double node(int i) const { return graded() ? coord[std::size_t(i)] : origin + h * i; }
  double width(int c) const { return graded() ? coord[std::size_t(c) + 1] - coord[std::size_t(c)] : h; }
  // Index of the cell containing x (floor); points outside give an out-of-range index
  // (uniform) or the nearest end cell (graded).
  int cell_of(double x) const {
    const double u = std::floor((x - origin) / h);
    if (!graded()) return int(u);
    const double last = double(cell_of_unit.size()) - 1.0;
    return cell_of_unit[std::size_t(u < 0.0 ? 0.0 : (u > last ? last : u))];
  }
  double min_width() const;
};

// 3-node stencil of a particle along one axis (uGIMP with lp <= h/2 touches at most 3 nodes).
struct Stencil1D {
  int first;     // index of the first node
  double s[3];   // weights
  double ds[3];  // d weight / d x_p, 1/m
};

// The particle at xp with half-width lp (<= half the width of the cells it overlaps) touches
// nodes first..first+2 (theory E3). Uniform: nodes i0-1..i0+1 if xp lies in the left half of
// cell i0, else i0..i0+2. Graded: first is the cell holding the particle's left edge xp - lp
// (its box overlaps at most two cells; the third weight may be zero).
// The first node of that stencil (the same arithmetic as the transfers' batched stencils,
// solver/stencil_batch.hpp).
// On a uniform lattice, from the particle's lattice coordinate xi = (xp - origin) / h: the
// node below its cell in the cell's lower half, else the cell's own (as a double, so batched
// loops vectorize). xi > 0 for every particle (the ghost cells keep them inside), so
// truncation is floor; unlike std::floor it vectorizes without -ffast-math. The one statement
// of this rule: the transfers (solver/stencil_batch.hpp), the loads and the per-level steps'
// band (solver/nested_subcycle.cpp) call it.
inline double uniform_stencil_first(double xi) {
  const double cell = double(int(xi));
  return xi - cell < 0.5 ? cell - 1.0 : cell;
}
inline int stencil_first(const Axis& a, double xp, double lp) {
  if (a.graded()) return a.cell_of(xp - lp);
  return int(uniform_stencil_first((xp - a.origin) * (1.0 / a.h)));
}
inline void stencil(const Axis& a, double xp, double lp, Stencil1D& st) {
  if (a.graded()) {
    const int first = stencil_first(a, xp, lp);
    st.first = first;
    // Inside a region of equal cells (all but the transitions) the uniform form applies.
    const double h = a.width(first);
    const double tol = 1e-9 * h;  // widths come from node differences: equal to round-off
    if (first > 0 && first + 2 < a.cells && std::fabs(a.width(first - 1) - h) < tol &&
        std::fabs(a.width(first + 1) - h) < tol && std::fabs(a.width(first + 2) - h) < tol) {
      const double inv_h = 1.0 / h;
      gimp_uniform_stencil((xp - a.node(first)) * inv_h, lp * inv_h, inv_h, st.s, st.ds);
      return;
    }
    for (int k = 0; k < 3; ++k) {
      const int i = first + k;
      const double hl = a.width(i > 0 ? i - 1 : 0), hr = a.width(i < a.cells ? i : a.cells - 1);
      const Weight1D w = gimp_graded(xp - a.node(i), hl, hr, lp);
      st.s[k] = w.s;
      st.ds[k] = w.ds;
    }
    return;
  }
  const double inv_h = 1.0 / a.h;
  const int first = stencil_first(a, xp, lp);
  st.first = first;
  gimp_uniform_stencil((xp - a.origin) * inv_h - double(first), lp * inv_h, inv_h, st.s, st.ds);
}

// The GIMP stencil contract along one graded axis (theory E3, graded form). stencil() takes the
// nodes first .. first + 2 with first = the cell holding the box's left edge x - lp, i.e. the
// nodes of cells first and first + 1. The weights are complete (partition of unity, and no
// write past the tile rows and columns that solver/step.cpp reserves) exactly when the box
// [x - lp, x + lp] overlaps at most those two cells:
//     x + lp <= x_{first+2}   <=>   2 lp <= (x_{first+1} - (x - lp)) + w_{first+1},
// that is, no cell lies wholly inside the box. Since 0 < x_{first+1} - (x - lp) <= w_first,
// lp <= w/2 for every cell the box overlaps (theory §2's lp <= h/2) is sufficient wherever the
// particle sits, and 2 lp > w_{first+1} breaks it somewhere in that cell. A uniform axis with
// lp <= h/2 always holds it. On a graded axis particles keep the half-width of the cell they
// were made in (uGIMP), so one that moves from cells of width w into cells narrower than w/2
// (ppc = 2: lp = w/4 against a cell of w/4, a 4x finer region) breaks it.
// Returns how many of the n particles break the contract along this axis (0 on a uniform
// axis); a cheap, vectorizable loop, run at every re-sort.
std::size_t count_stencil_overflows(const Axis& a, const double* x, const double* lp, std::size_t n);
// Whether the particle at x with half-width lp breaks it (the test above, one particle).
bool stencil_overflows(const Axis& a, double x, double lp);

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
  double cell_size() const { return x.h; }  // uniform: h; graded: the finest size
  bool graded() const { return x.graded() || y.graded(); }
};

// Uniform grid over [min, max] with cell size h plus the ghost cells on each side: two, plus
// enough to cover `margin` (m), the distance a free surface may move outward during the run.
// Throws InputError if the extent is not a whole number of cells (within 1e-6 h).
Grid make_uniform_grid(const double min[2], const double max[2], double h, double margin = 0.0);

// Ghost cells of width w that hold a margin: 2 + ceil(margin / w).
int ghost_cells(double margin, double w);

// A refinement box (theory §5): cells inside it along each axis are at most `size` wide.
struct RefineBox {
  double min[2]{}, max[2]{};  // m
  double size = 0.0;          // cell size asked for inside the box, m
};

// Graded tensor-product grid over [min, max]: along each axis, the cell size at a point is
// the smallest size of the boxes whose extent along that axis covers it, `coarse` elsewhere;
// sizes are powers of two times `finest`, aligned to their own size from min, and graded so
// that neighbouring cells differ by at most a factor 2. Ghost cells the size of the edge cells
// on each side, ghost_cells(margin, that size) of them (the largest count over the four edges,
// so Grid::ghost is one number). Throws InputError if an extent is not a whole number of `finest`.
Grid make_graded_grid(const double min[2], const double max[2], double coarse, double finest,
                      const std::vector<RefineBox>& boxes, double margin = 0.0);

// Per-field nodal arrays, field-major. Field f holds only its window of nodes: columns
// [col0[f], col0[f] + cols[f]) x rows [row0[f], row0[f] + rows[f]), row by row, contiguous
// from start[f]. The window covers what its particles' stencils, its interface faces and its
// tied nodes reach, plus a margin; the solver keeps it fitted (solver/field_windows.hpp). A
// local field (an inclusion, one of several strips or blocks) therefore costs its own nodes,
// and the arrays hold sum_f cols[f] x rows[f] nodes, not fields x whole grid. Grid node (i, j)
// of field f is element index(f, i, j), valid only inside the window (holds(f, i, j)).
// See solver/ for when each array is valid.
struct GridFields {
  int num_fields = 0;
  std::size_t num_nodes = 0;  // nodes of the whole grid
  std::size_t nodes_x = 0;    // nodes per grid row (a grid node n is i + j nodes_x)
  std::vector<int> col0, cols, row0, rows;  // per field: its window
  std::vector<std::size_t> start;           // per field: first element; start[num_fields] = size()
  std::vector<double> mass;          // lumped nodal mass m_i, kg
  std::vector<double> mom_x, mom_y;  // momentum p_i at t^n, kg m/s
  std::vector<double> force_x, force_y;  // total nodal force f_i, N (per unit thickness)
  std::vector<double> vel_x, vel_y;      // velocity at t^{n+1}, m/s
  std::vector<double> dvel_x, dvel_y;    // velocity increment over the step (dt * a_i), m/s
  std::vector<double> remap_x, remap_y;  // MUSL re-mapped momentum, then velocity

  // Every field over the whole grid.
  void resize(int fields, std::size_t nodes_x, std::size_t nodes_y);
  // Windows (non-empty, inside the grid). The arrays are re-allocated and zeroed: they hold no
  // state from one time step to the next.
  void set_windows(std::size_t nodes_x, std::size_t nodes_y, const std::vector<int>& col0,
                   const std::vector<int>& cols, const std::vector<int>& row0,
                   const std::vector<int>& rows);
  bool holds(int f, int i, int j) const {
    const std::size_t k = std::size_t(f);
    return i >= col0[k] && i < col0[k] + cols[k] && j >= row0[k] && j < row0[k] + rows[k];
  }
  bool holds(int f, std::size_t node) const {
    return holds(f, int(node % nodes_x), int(node / nodes_x));
  }
  std::size_t index(int f, int i, int j) const {
    const std::size_t k = std::size_t(f);
    return start[k] + std::size_t(j - row0[k]) * std::size_t(cols[k]) + std::size_t(i - col0[k]);
  }
  std::size_t index(int f, std::size_t node) const {
    return index(f, int(node % nodes_x), int(node / nodes_x));
  }
  std::size_t stride(int f) const { return std::size_t(cols[std::size_t(f)]); }  // one row up
  std::size_t size() const { return mass.size(); }
  std::size_t bytes() const;
};

// The nodal arrays of GridFields, each listed once: f(member) for each. set_windows sizes and
// zeroes them, bytes() and the memory estimates (solver/summary.cpp, input/case_checks.cpp)
// count them, so an array added here is carried by all.
template <class F>
constexpr void for_each_field_array(F&& f) {
  for (std::vector<double> GridFields::*m :
       {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y, &GridFields::force_x, &GridFields::force_y,
        &GridFields::vel_x, &GridFields::vel_y, &GridFields::dvel_x, &GridFields::dvel_y, &GridFields::remap_x,
        &GridFields::remap_y})
    f(m);
}

// How many nodal arrays a field node holds (11).
constexpr std::size_t field_array_count() {
  std::size_t n = 0;
  for_each_field_array([&](auto) { ++n; });
  return n;
}

}  // namespace rupture
