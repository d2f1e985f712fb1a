// rupture/grid/nested.hpp
// Nested refinement levels (theory §5: the paper's Fig. 6; transition nodes after Ma, Lu &
// Komanduri, CMES 2006), the alternative to the graded tensor-product grid of grid/grid.hpp
// that refines only inside each box instead of along whole rows and columns.
//
// Level l is a uniform lattice of square cells s_l = coarse / 2^l over its own rectangle R_l
// plus a ring of ghost cells. A particle belongs to the finest level whose rectangle holds its
// centre and takes its GIMP weights (theory E3, uniform form) on that level's lattice. Every
// lattice node is either a degree of freedom (DOF) or a slave, a fixed combination of DOFs:
//  - outside R_l or on its inner border: the bilinear interpolant of level l-1 at the node
//    (coefficients 1, 1/2 or 1/4 at the nodes of the coarse cell holding it): the hanging
//    nodes of a transition and the ghost ring;
//  - strictly inside R_{l+1}: level l+1's node at the same point (injection).
// Chains (a slave whose master is a slave) are resolved once, so every slave's terms name DOFs.
// Each slave's coefficients sum to one and reproduce linear fields, so a particle's weights,
// mapped to DOFs, keep the partition of unity and linear completeness at every transition (the
// GIMP contract); the scatter's condense_to_dofs (slaves' mass, momentum and force added to their DOFs
// with the coefficients) is the transpose of the gather's spread_to_slaves (slaves' velocity from
// their DOFs), so mass and momentum are conserved and the transfers do no work.
//
// Geometry is kept in integer units of the finest cell size from the domain's lower corner,
// so alignment is exact. Rectangles are proper-nested: R_l lies inside R_{l-1} with at least
// kNestingCells cells of level l-1 between them (R_{l-1} grows where the boxes ask for less),
// so a ghost node's coarse masters are DOFs. A side of R_l on a domain edge is an outer side:
// no transition there; the lattice reaches the common outer extent (the coarsest level's
// ghost ring), and particles that bulge out of the edge stay on their level.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "grid/grid.hpp"

namespace rupture {

inline constexpr int kNestingCells = 2;  // cells of level l-1 between R_l and R_{l-1}'s border
inline constexpr int kGhostRing = 2;     // ghost cells of a level beyond an inner border

// One nested level's lattice (its geometry; solver/levels.hpp Levels is the view of the levels'
// States the step works on). Units: m; `lo`, `hi` and node coordinates also in finest units (integers).
struct LevelLattice {
  int level = 0;
  Axis x, y;                    // uniform lattice axes (Axis::h = s_l); nodes row by row
  long unit = 1;                // s_l in finest units
  long lo[2]{}, hi[2]{};        // R_l in finest units from the domain's lower corner
  bool outer_lo[2]{}, outer_hi[2]{};  // side on the domain's edge (no transition)
  long node0[2]{};              // finest-unit coordinate of lattice node (0, 0)
  int nodes_x() const { return x.nodes(); }
  int nodes_y() const { return y.nodes(); }
  std::size_t num_nodes() const { return std::size_t(nodes_x()) * std::size_t(nodes_y()); }
  std::size_t node_index(int i, int j) const { return std::size_t(j) * std::size_t(nodes_x()) + std::size_t(i); }
  // Whether the point (finest units) is in R_l: inner borders excluded, outer sides open.
  bool owns_units(double u, double v) const;
};

struct SlaveTerm {
  std::uint32_t dof;  // global node id of a DOF
  double c;           // coefficient
};

struct NestedGrid {
  double finest = 0.0;           // finest cell size, m (the unit)
  double min[2]{}, max[2]{};     // physical domain, m
  std::vector<LevelLattice> levels;     // coarsest first
  // Global node ids: level l's node n is level_start[l] + n; level_start.back() = total.
  std::vector<std::size_t> level_start;
  std::vector<unsigned char> is_dof;  // per global node
  // Slaves and their terms (CSR): slave k is node slaves[k], terms [term_start[k], term_start[k+1]).
  std::vector<std::uint32_t> slaves;
  std::vector<std::uint32_t> term_start;
  std::vector<SlaveTerm> terms;

  std::size_t num_nodes() const { return level_start.back(); }
  // The finest level whose rectangle holds the point (m).
  int level_of(double x, double y) const;
  // Global node position (m).
  void node_position(std::size_t id, double& x, double& y) const;
};

// Level l's lattice as a uniform Grid over the physical domain [g.min, g.max] (the ghost count
// is nominal: a level's rings differ by side).
Grid level_grid(const NestedGrid& g, int l);

// Builds the levels from the refinement boxes (sizes powers of two times `finest`, at most
// `coarse`), over [min, max] (a whole number of finest cells along each axis) with the
// coarsest level's ghost ring holding `margin` (m, as make_graded_grid). Throws InputError
// naming the box and value when a box's size is not coarse / 2^l.
NestedGrid make_nested_grid(const double min[2], const double max[2], double coarse, double finest,
                            const std::vector<RefineBox>& boxes, double margin = 0.0);

// Extensive nodal values (mass, momentum, force) over all global nodes: every slave's value is
// added to its DOFs times the coefficients, then set to zero. Total mass and momentum unchanged.
void condense_to_dofs(const NestedGrid& g, double* values);
// Intensive nodal values (velocity): every slave takes the combination of its DOFs. The
// transpose of condense_to_dofs: sum a . spread_to_slaves(b) = sum condense_to_dofs(a) . b over DOFs.
void spread_to_slaves(const NestedGrid& g, double* values);

// Cells of each level that no finer level covers (its share of the plate), and the particles
// ppc x ppc per such cell inside [bmin, bmax] (m) would hold: for estimates and reports.
struct LevelCount {
  std::size_t cells = 0, particles = 0;
};
std::vector<LevelCount> count_level_cells(const NestedGrid& g, const double bmin[2],
                                          const double bmax[2], int ppc);

}  // namespace rupture
