// rupture/bulk/node_update.hpp
// The nodal momentum update of the time step at one node, for any dimension (theory E4):
// dv = dt f / m and v(t^{n+1}) = p / m + dv where the node holds more than the mass floor;
// velocity and increment 0 at an empty node. A plain function over raw nodal arrays (one
// pointer per component), called by the loops over nodes (solver/grid_update.hpp in 2D,
// bulk/block_step.cpp in 2D and 3D). Units: kg, kg m/s, N, s, m/s.
#pragma once
#include <cstddef>

namespace rupture {

template <int dim>
struct NodeArrays {
  const double* mass;
  const double* momentum[dim];
  const double* force[dim];
  double* velocity[dim];
  double* dvelocity[dim];
};

template <int dim>
inline void integrate_node(const NodeArrays<dim>& g, std::size_t i, double dt, double floor) {
  const double m = g.mass[i];
  if (m > floor) {
    const double inv_m = 1.0 / m;
    for (int d = 0; d < dim; ++d) g.dvelocity[d][i] = dt * g.force[d][i] * inv_m;
    for (int d = 0; d < dim; ++d) g.velocity[d][i] = g.momentum[d][i] * inv_m + g.dvelocity[d][i];
  } else {
    for (int d = 0; d < dim; ++d) g.dvelocity[d][i] = g.velocity[d][i] = 0.0;
  }
}

}  // namespace rupture
