// rupture/bulk/block_step.cpp
// The MUSL step of bulk/block_step.hpp: loops over particles in batches of kBatch (their
// stencils SIMD over the batch) and over nodes, each body a kernel of this folder.
#include "bulk/block_step.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bulk/elastic_update.hpp"
#include "bulk/node_update.hpp"
#include "bulk/particle_kernels.hpp"
#include "bulk/stencil.hpp"
#include "particles/particles.hpp"

namespace rupture {
namespace {

template <int dim>
void zero(std::array<std::vector<double>, dim>& a) {
  for (std::vector<double>& v : a) std::fill(v.begin(), v.end(), 0.0);
}

// Runs body(p, k, B) over every particle, batch by batch (k: index in the batch B).
template <int dim, class Body>
void for_each_particle(const BlockParticles<dim>& P, const BlockGrid<dim>& G, Body&& body) {
  StencilBatch<dim> B;
  const Axis* axis[dim];
  for (int d = 0; d < dim; ++d) axis[d] = &G.axis[std::size_t(d)];
  for (std::size_t p0 = 0; p0 < P.size(); p0 += kBatch) {
    const int n = int(std::min<std::size_t>(kBatch, P.size() - p0));
    const double* x[dim];
    const double* lp[dim];
    for (int d = 0; d < dim; ++d) x[d] = P.x[std::size_t(d)].data() + p0, lp[d] = P.half[std::size_t(d)].data() + p0;
    batch_stencils<dim>(axis, x, lp, n, B);
    for (int k = 0; k < n; ++k) body(p0 + std::size_t(k), k, B);
  }
}

// The particle's stencil lies inside the lattice (every node of it exists).
template <int dim>
void check_inside(const StencilBatch<dim>& B, int k, const BlockGrid<dim>& G, std::size_t p) {
  for (int d = 0; d < dim; ++d)
    if (B.first[d][k] < 0 || B.first[d][k] + 2 > G.axis[std::size_t(d)].cells)
      throw std::runtime_error("block_step_musl: particle " + std::to_string(p) +
                               " reaches past the lattice along axis " + std::to_string(d));
}

}  // namespace

template <int dim>
BlockGrid<dim> make_block_grid(const std::array<double, dim>& origin, double h,
                               const std::array<int, dim>& cells) {
  BlockGrid<dim> G;
  std::size_t nodes = 1;
  for (int d = 0; d < dim; ++d) {
    Axis& a = G.axis[std::size_t(d)];
    a.origin = origin[std::size_t(d)], a.h = h, a.cells = cells[std::size_t(d)];
    G.stride[std::size_t(d)] = std::ptrdiff_t(nodes);
    nodes *= std::size_t(a.nodes());
  }
  G.mass.assign(nodes, 0.0);
  for (auto* a : {&G.momentum, &G.force, &G.velocity, &G.dvelocity, &G.remap})
    for (std::vector<double>& v : *a) v.assign(nodes, 0.0);
  return G;
}

template <int dim>
BlockParticles<dim> seed_block(const std::array<double, dim>& lo, const std::array<double, dim>& hi,
                               double h, int ppc, double density) {
  BlockParticles<dim> P;
  const double side = h / ppc;
  std::array<long, dim> count{};
  std::size_t total = 1;
  for (int d = 0; d < dim; ++d) {
    count[std::size_t(d)] = std::lround((hi[std::size_t(d)] - lo[std::size_t(d)]) / side);
    total *= std::size_t(count[std::size_t(d)]);
  }
  const double volume = std::pow(side, dim);
  for (std::size_t q = 0; q < total; ++q) {
    std::size_t rest = q;
    for (int d = 0; d < dim; ++d) {
      const long i = long(rest % std::size_t(count[std::size_t(d)]));
      rest /= std::size_t(count[std::size_t(d)]);
      P.x[std::size_t(d)].push_back(lattice_centre(lo[std::size_t(d)], side, i));
      P.v[std::size_t(d)].push_back(0.0);
      P.half[std::size_t(d)].push_back(0.5 * side);
    }
    P.mass.push_back(density * volume);
    P.volume0.push_back(volume);
    for (std::vector<double>& s : P.stress) s.push_back(0.0);
  }
  return P;
}

template <int dim>
void block_step_musl(BlockParticles<dim>& P, BlockGrid<dim>& G, const BlockStep& step,
                     const std::array<bool, dim>& fixed) {
  constexpr int S = kSymmetric<dim>;
  const ElasticStiffness& C = step.stiffness;
  const double dt = step.dt;
  std::ptrdiff_t stride[dim];
  for (int d = 0; d < dim; ++d) stride[d] = G.stride[std::size_t(d)];
  // E4: mass, momentum and internal force.
  std::fill(G.mass.begin(), G.mass.end(), 0.0);
  zero<dim>(G.momentum), zero<dim>(G.force);
  ScatterArrays<dim> out{G.mass.data(), {}, {}, {}};
  for (int d = 0; d < dim; ++d) {
    out.momentum[d] = G.momentum[std::size_t(d)].data();
    out.force[d] = G.force[std::size_t(d)].data();
    out.stride[d] = stride[d];
  }
  for_each_particle<dim>(P, G, [&](std::size_t p, int k, const StencilBatch<dim>& B) {
    check_inside<dim>(B, k, G, p);
    double s[S], v[dim], f[S];
    for (int c = 0; c < S; ++c) s[c] = P.stress[std::size_t(c)][p];
    for (int d = 0; d < dim; ++d) v[d] = P.v[std::size_t(d)][p];
    const double V = P.volume0[p] * (1.0 + trace<dim>(s) * C.tr_per_stress);
    for (int c = 0; c < S; ++c) f[c] = -V * s[c];
    scatter_particle<dim>(B, k, P.mass[p], v, f, out);
  });
  // E4 at the nodes; the held components.
  NodeArrays<dim> nodes{G.mass.data(), {}, {}, {}, {}};
  for (int d = 0; d < dim; ++d) {
    nodes.momentum[d] = G.momentum[std::size_t(d)].data();
    nodes.force[d] = G.force[std::size_t(d)].data();
    nodes.velocity[d] = G.velocity[std::size_t(d)].data();
    nodes.dvelocity[d] = G.dvelocity[std::size_t(d)].data();
  }
  for (std::size_t i = 0; i < G.nodes(); ++i) {
    integrate_node<dim>(nodes, i, dt, step.mass_floor);
    for (int d = 0; d < dim; ++d)
      if (fixed[std::size_t(d)]) nodes.velocity[d][i] = nodes.dvelocity[d][i] = 0.0;
  }
  // FLIP velocity update and the re-mapped momentum (MUSL).
  zero<dim>(G.remap);
  const double* dv[dim];
  for (int d = 0; d < dim; ++d) dv[d] = G.dvelocity[std::size_t(d)].data();
  ScatterArrays<dim> remap{nullptr, {}, {}, {}};
  for (int d = 0; d < dim; ++d) {
    remap.momentum[d] = G.remap[std::size_t(d)].data();
    remap.stride[d] = stride[d];
  }
  const double no_stress[S] = {};
  for_each_particle<dim>(P, G, [&](std::size_t p, int k, const StencilBatch<dim>& B) {
    double inc[dim], v[dim];
    gather_particle<dim>(B, k, dv, stride, inc, nullptr);
    for (int d = 0; d < dim; ++d) v[d] = P.v[std::size_t(d)][p] += inc[d];
    scatter_particle<dim, true>(B, k, P.mass[p], v, no_stress, remap);
  });
  for (std::size_t i = 0; i < G.nodes(); ++i) {
    const double m = G.mass[i];
    for (int d = 0; d < dim; ++d) {
      double& u = G.remap[std::size_t(d)][i];
      u = (m > step.mass_floor && !fixed[std::size_t(d)]) ? u / m : 0.0;
    }
  }
  // E5: the stress with the re-mapped velocity's gradient; the move with v(t^{n+1}).
  const double* vr[dim];
  const double* vn[dim];
  for (int d = 0; d < dim; ++d) vr[d] = G.remap[std::size_t(d)].data(), vn[d] = G.velocity[std::size_t(d)].data();
  for_each_particle<dim>(P, G, [&](std::size_t p, int k, const StencilBatch<dim>& B) {
    double vm[dim], L[dim][dim], move[dim], de[S], ds[S], s[S];
    gather_particle<dim>(B, k, vr, stride, vm, L);
    gather_particle<dim>(B, k, vn, stride, move, nullptr);
    strain_increment<dim>(L, dt, de);
    stress_increment<dim>(C.c11, C.c12, C.mu, de, ds);
    for (int c = 0; c < S; ++c) s[c] = P.stress[std::size_t(c)][p] + ds[c];
    for (int c = 0; c < S; ++c) P.stress[std::size_t(c)][p] = s[c];
    for (int d = 0; d < dim; ++d) P.x[std::size_t(d)][p] += dt * move[d];
  });
}

ElasticStiffness stiffness_3d(const ElasticMaterial& m) {
  // Plane strain keeps eps_zz = 0, where sigma_ii = (lambda + 2 mu) eps_ii + lambda eps_jj:
  // the 3D law's c11, c12 and mu (tr_per_stress is the 3D one: tr eps = tr sigma / (3 lambda + 2 mu)).
  ElasticStiffness C = stiffness(m, PlaneMode::strain);
  const double lambda = C.c12, mu = C.mu;
  C.tr_per_stress = 1.0 / (3.0 * lambda + 2.0 * mu);
  C.cz = 0.0;
  return C;
}

template BlockGrid<2> make_block_grid<2>(const std::array<double, 2>&, double, const std::array<int, 2>&);
template BlockGrid<3> make_block_grid<3>(const std::array<double, 3>&, double, const std::array<int, 3>&);
template BlockParticles<2> seed_block<2>(const std::array<double, 2>&, const std::array<double, 2>&, double, int, double);
template BlockParticles<3> seed_block<3>(const std::array<double, 3>&, const std::array<double, 3>&, double, int, double);
template void block_step_musl<2>(BlockParticles<2>&, BlockGrid<2>&, const BlockStep&, const std::array<bool, 2>&);
template void block_step_musl<3>(BlockParticles<3>&, BlockGrid<3>&, const BlockStep&, const std::array<bool, 3>&);

}  // namespace rupture
