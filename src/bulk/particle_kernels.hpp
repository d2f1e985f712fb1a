// rupture/bulk/particle_kernels.hpp
// The per-particle bodies of the particle <-> grid transfers, for any dimension (theory E4,
// E5), over raw arrays: a particle's stencil (bulk/stencil.hpp: batch B, index k) and the grid
// as one pointer per nodal array with the strides of its axes (node (i, j[, l]) at
// i stride[0] + j stride[1] [+ l stride[2]]). Nothing here knows a State, a vector or a run:
// the loops that call them (bulk/block_step.cpp) own the arrays and the order of the particles.
// Units: kg, m/s, Pa, m^dim, N, s.
#pragma once
#include <cstddef>

#include "bulk/dimension.hpp"
#include "bulk/stencil.hpp"

namespace rupture {

// Node n of particle k's stencil: its index and its weight S with the gradient dS/dx_d.
template <int dim>
struct StencilNode {
  std::ptrdiff_t index;
  double S;
  double grad[dim];
};
template <int dim>
inline StencilNode<dim> stencil_node(const StencilBatch<dim>& B, int k, int n,
                                     const std::ptrdiff_t (&stride)[dim]) {
  StencilNode<dim> out{0, 1.0, {}};
  for (int d = 0; d < dim; ++d) {
    const int o = stencil_offset<dim>(n, d);
    out.index += std::ptrdiff_t(B.first[d][k] + o) * stride[d];
    out.S *= B.w[d][o][k];
  }
  for (int d = 0; d < dim; ++d) {
    double g = B.dw[d][stencil_offset<dim>(n, d)][k];
    for (int e = 0; e < dim; ++e)
      if (e != d) g *= B.w[e][stencil_offset<dim>(n, e)][k];
    out.grad[d] = g;
  }
  return out;
}

// E4's scatter of one particle: mass m S, momentum m v S and internal force -V sigma . grad S
// added to its 3^dim nodes (minus_v_sigma: -V sigma in bulk/dimension.hpp's component order).
// kMomentumOnly: the momentum alone (MUSL's re-map; mass and force are not read).
template <int dim>
struct ScatterArrays {
  double* mass;
  double* momentum[dim];
  double* force[dim];
  std::ptrdiff_t stride[dim];
};
template <int dim, bool kMomentumOnly = false>
inline void scatter_particle(const StencilBatch<dim>& B, int k, double m, const double (&v)[dim],
                             const double (&minus_v_sigma)[kSymmetric<dim>],
                             const ScatterArrays<dim>& g) {
  for (int n = 0; n < kStencilNodes<dim>; ++n) {
    const StencilNode<dim> node = stencil_node<dim>(B, k, n, g.stride);
    for (int d = 0; d < dim; ++d) g.momentum[d][node.index] += m * v[d] * node.S;
    if constexpr (kMomentumOnly) continue;
    g.mass[node.index] += m * node.S;
    for (int i = 0; i < dim; ++i) {
      double f = 0.0;
      for (int j = 0; j < dim; ++j) f += minus_v_sigma[symmetric_index<dim>(i, j)] * node.grad[j];
      g.force[i][node.index] += f;
    }
  }
}

// The grid field u (dim components per node) at particle k: sum S u_i, and, with L, its
// gradient L_ij = du_i/dx_j = sum u_i dS/dx_j.
template <int dim>
inline void gather_particle(const StencilBatch<dim>& B, int k, const double* const (&u)[dim],
                            const std::ptrdiff_t (&stride)[dim], double (&value)[dim],
                            double (*L)[dim]) {
  for (int d = 0; d < dim; ++d) value[d] = 0.0;
  if (L)
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) L[i][j] = 0.0;
  for (int n = 0; n < kStencilNodes<dim>; ++n) {
    const StencilNode<dim> node = stencil_node<dim>(B, k, n, stride);
    for (int i = 0; i < dim; ++i) {
      const double ui = u[i][node.index];
      value[i] += node.S * ui;
      if (L)
        for (int j = 0; j < dim; ++j) L[i][j] += ui * node.grad[j];
    }
  }
}

}  // namespace rupture
