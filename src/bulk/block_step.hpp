// rupture/bulk/block_step.hpp
// A block of one linear elastic material on a uniform lattice, stepped by MUSL (theory E3-E6,
// FLIP = 1, lumped mass), for dim = 2 and 3: the bulk of rupture's time step written once over
// the dimension-generic kernels (bulk/stencil.hpp, particle_kernels.hpp, node_update.hpp,
// elastic_update.hpp), explicitly instantiated for both. It is the proof that those kernels
// make a whole step in 3D; the 2D run's step (solver/step.cpp) calls the same kernels through
// its strip and tile loops. No boundary conditions but a velocity component held at zero at
// every node (rollers everywhere: in 3D, fixed = {false, false, true} is plane strain in z);
// the block stays inside the lattice (the caller sizes it). Serial loops: the threaded ones are
// the 2D run's (3D: issue 74). Units: SI (m, s, kg, Pa; volume and mass per unit thickness in 2D).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "bulk/dimension.hpp"
#include "grid/grid.hpp"
#include "material/elastic.hpp"

namespace rupture {

template <int dim>
struct BlockParticles {
  std::array<std::vector<double>, dim> x, v, half;  // position m, velocity m/s, GIMP half-width m
  std::vector<double> mass, volume0;                // kg, m^dim (initial)
  std::array<std::vector<double>, kSymmetric<dim>> stress;  // Cauchy stress, Pa
  std::size_t size() const { return mass.size(); }
};

template <int dim>
struct BlockGrid {
  std::array<Axis, dim> axis;  // uniform axes
  std::vector<double> mass;    // kg
  std::array<std::vector<double>, dim> momentum, force, velocity, dvelocity, remap;
  std::array<std::ptrdiff_t, dim> stride{};
  std::size_t nodes() const { return mass.size(); }
};

// A lattice of cells[d] cells of side h from origin[d] along each axis.
template <int dim>
BlockGrid<dim> make_block_grid(const std::array<double, dim>& origin, double h,
                               const std::array<int, dim>& cells);

// ppc^dim particles per cell filling the box [lo, hi] (whole cells), at rest, stress-free.
template <int dim>
BlockParticles<dim> seed_block(const std::array<double, dim>& lo, const std::array<double, dim>& hi,
                               double h, int ppc, double density);

struct BlockStep {
  ElasticStiffness stiffness;  // dim = 3: c11 = lambda + 2 mu, c12 = lambda (stiffness_3d)
  double dt = 0.0;             // s
  double mass_floor = 0.0;     // kg: lighter nodes are empty
};

// One MUSL step: scatter (E4), node update, FLIP velocity update and re-map, then the stress
// with the re-mapped velocity's gradient (E5) and the move with the t^{n+1} grid velocity.
template <int dim>
void block_step_musl(BlockParticles<dim>& P, BlockGrid<dim>& G, const BlockStep& step,
                     const std::array<bool, dim>& fixed);

// The isotropic 3D stiffness of a material (c11 = lambda + 2 mu, c12 = lambda): in 2D the
// plane-strain stiffness has the same c11, c12, mu (material/elastic.hpp).
ElasticStiffness stiffness_3d(const ElasticMaterial& m);

extern template BlockGrid<2> make_block_grid<2>(const std::array<double, 2>&, double, const std::array<int, 2>&);
extern template BlockGrid<3> make_block_grid<3>(const std::array<double, 3>&, double, const std::array<int, 3>&);
extern template BlockParticles<2> seed_block<2>(const std::array<double, 2>&, const std::array<double, 2>&, double, int, double);
extern template BlockParticles<3> seed_block<3>(const std::array<double, 3>&, const std::array<double, 3>&, double, int, double);
extern template void block_step_musl<2>(BlockParticles<2>&, BlockGrid<2>&, const BlockStep&, const std::array<bool, 2>&);
extern template void block_step_musl<3>(BlockParticles<3>&, BlockGrid<3>&, const BlockStep&, const std::array<bool, 3>&);

}  // namespace rupture
