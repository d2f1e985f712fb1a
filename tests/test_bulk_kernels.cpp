// Tests of the dimension-generic kernels of src/bulk/ (dimension.hpp, stencil.hpp,
// particle_kernels.hpp, elastic_update.hpp), each in 2D and 3D: the component table, Hooke's law
// against the full tensor form, plane strain as 3D with no out-of-plane strain, the stencils'
// partition of unity and linear completeness, a linear field gathered exactly with its
// gradient, and a particle's scatter carrying its mass, momentum and -V sigma (the force's first
// moment) to the nodes.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "bulk/dimension.hpp"
#include "bulk/elastic_update.hpp"
#include "bulk/particle_kernels.hpp"
#include "bulk/stencil.hpp"
#include "material/elastic.hpp"

namespace rupture {
namespace {

template <int dim>
void check_component_table() {
  int seen[kSymmetric<dim>] = {};
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) {
      const int c = symmetric_index<dim>(i, j);
      ASSERT_GE(c, 0);
      EXPECT_EQ(c, symmetric_index<dim>(j, i));
      EXPECT_EQ(c < dim, i == j) << "normal components first";
      if (i <= j) ++seen[c];
    }
  for (int c = 0; c < kSymmetric<dim>; ++c) EXPECT_EQ(seen[c], 1) << SymmetricComponents<dim>::name[std::size_t(c)];
  // The stencil's offsets visit each of the 3^dim nodes once.
  std::vector<int> hit(kStencilNodes<dim>, 0);
  for (int n = 0; n < kStencilNodes<dim>; ++n) {
    int flat = 0;
    for (int d = dim - 1; d >= 0; --d) flat = 3 * flat + stencil_offset<dim>(n, d);
    ++hit[std::size_t(flat)];
  }
  for (int h : hit) EXPECT_EQ(h, 1);
}

TEST(BulkKernels, component_table_and_stencil_offsets_are_one_to_one) {
  check_component_table<2>();
  check_component_table<3>();
}

// The full-tensor form of a stored symmetric tensor.
template <int dim>
double full(const double (&t)[kSymmetric<dim>], int i, int j) {
  return t[symmetric_index<dim>(i, j)];
}

TEST(BulkKernels, stress_increment_in_3d_is_hookes_law_and_2d_plane_strain_is_its_plane) {
  const ElasticMaterial m{"m", 5.2e9, 0.34, 1246.0, 0.0};
  const ElasticStiffness C = stiffness(m, PlaneMode::strain);
  const double mu = C.mu, lambda = C.c12;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    double L[3][3], de[6], ds[6];
    for (auto& row : L)
      for (double& x : row) x = u(rng);
    const double dt = 1e-7;
    strain_increment<3>(L, dt, de);
    stress_increment<3>(C.c11, C.c12, C.mu, de, ds);
    const double tr = (L[0][0] + L[1][1] + L[2][2]) * dt;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double eps = 0.5 * (L[i][j] + L[j][i]) * dt;
        EXPECT_NEAR(full<3>(de, i, j), eps, 1e-15 * dt);
        EXPECT_NEAR(full<3>(ds, i, j), lambda * tr * (i == j) + 2.0 * mu * eps, 1e-12 * mu * dt * 4);
      }
    // E14's work: V_mid (sigma + d sigma / 2) : d eps over the full tensor.
    double s[6];
    for (double& x : s) x = 1e6 * u(rng);
    const double V0 = 2e-9, tr_eps = 1e-4;
    double sum = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) sum += (full<3>(s, i, j) + 0.5 * full<3>(ds, i, j)) * full<3>(de, i, j);
    EXPECT_NEAR(stress_work<3>(V0, tr_eps, s, de, ds), V0 * (1.0 + tr_eps + 0.5 * tr) * sum,
                1e-12 * V0 * 1e6 * dt * 9);
    // Plane strain: the 2D law is the 3D one with no out-of-plane strain.
    const double L2[2][2] = {{L[0][0], L[0][1]}, {L[1][0], L[1][1]}};
    double L3[3][3] = {{L[0][0], L[0][1], 0.0}, {L[1][0], L[1][1], 0.0}, {0.0, 0.0, 0.0}};
    double de2[3], ds2[3], ds3[6];
    strain_increment<2>(L2, dt, de2);
    stress_increment<2>(C.c11, C.c12, C.mu, de2, ds2);
    strain_increment<3>(L3, dt, de);
    stress_increment<3>(C.c11, C.c12, C.mu, de, ds3);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) EXPECT_DOUBLE_EQ(full<2>(ds2, i, j), full<3>(ds3, i, j));
    EXPECT_NEAR(ds3[2], stress_zz(C, ds2[0], ds2[1]), 1e-9 * std::fabs(ds3[2]));
  }
}

// Random particles in a uniform lattice (cell h, ghost margin), their stencils in one batch.
template <int dim>
struct Lattice {
  double h = 0.01;
  std::array<Axis, dim> axis;
  std::ptrdiff_t stride[dim];
  std::size_t nodes = 1;
  std::array<std::vector<double>, dim> x, lp;
  StencilBatch<dim> B;
  int n = kBatch;
  explicit Lattice(unsigned seed) {
    for (int d = 0; d < dim; ++d) {
      axis[std::size_t(d)].origin = -0.03 + 0.001 * d, axis[std::size_t(d)].h = h, axis[std::size_t(d)].cells = 10;
      stride[d] = std::ptrdiff_t(nodes);
      nodes *= 11;
    }
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(0.0, 0.04), half(0.05 * h, 0.5 * h);
    for (int d = 0; d < dim; ++d)
      for (int k = 0; k < n; ++k) x[std::size_t(d)].push_back(pos(rng)), lp[std::size_t(d)].push_back(half(rng));
    const Axis* a[dim];
    const double* px[dim];
    const double* pl[dim];
    for (int d = 0; d < dim; ++d) a[d] = &axis[std::size_t(d)], px[d] = x[std::size_t(d)].data(), pl[d] = lp[std::size_t(d)].data();
    batch_stencils<dim>(a, px, pl, n, B);
  }
  // Coordinate d of the node with this flat index.
  double node_coord(std::ptrdiff_t index, int d) const {
    return axis[std::size_t(d)].origin + h * double((index / stride[d]) % 11);
  }
};

template <int dim>
void check_stencils_and_linear_gather() {
  Lattice<dim> Lt(7 + dim);
  // A linear field u_i = A_ij x_j + b_i on the nodes.
  double A[dim][dim], b[dim];
  for (int i = 0; i < dim; ++i) {
    b[i] = 0.3 * i - 0.1;
    for (int j = 0; j < dim; ++j) A[i][j] = 1.0 + i - 0.7 * j + 0.2 * i * j;
  }
  std::array<std::vector<double>, dim> field;
  for (int i = 0; i < dim; ++i) {
    field[std::size_t(i)].assign(Lt.nodes, 0.0);
    for (std::size_t q = 0; q < Lt.nodes; ++q) {
      double v = b[i];
      for (int j = 0; j < dim; ++j) v += A[i][j] * Lt.node_coord(std::ptrdiff_t(q), j);
      field[std::size_t(i)][q] = v;
    }
  }
  const double* u[dim];
  for (int i = 0; i < dim; ++i) u[i] = field[std::size_t(i)].data();
  for (int k = 0; k < Lt.n; ++k) {
    // Partition of unity and linear completeness of the weights.
    double sum = 0.0, grad[dim] = {}, moment[dim] = {}, grad_moment[dim][dim] = {};
    for (int n = 0; n < kStencilNodes<dim>; ++n) {
      const StencilNode<dim> node = stencil_node<dim>(Lt.B, k, n, Lt.stride);
      sum += node.S;
      for (int d = 0; d < dim; ++d) {
        grad[d] += node.grad[d];
        moment[d] += node.S * Lt.node_coord(node.index, d);
        for (int e = 0; e < dim; ++e) grad_moment[d][e] += node.grad[d] * Lt.node_coord(node.index, e);
      }
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    for (int d = 0; d < dim; ++d) {
      EXPECT_NEAR(grad[d], 0.0, 1e-11 / Lt.h);
      EXPECT_NEAR(moment[d], Lt.x[std::size_t(d)][std::size_t(k)], 1e-14);
      for (int e = 0; e < dim; ++e) EXPECT_NEAR(grad_moment[d][e], d == e ? 1.0 : 0.0, 1e-12);
    }
    // The linear field and its gradient, gathered exactly (to round-off).
    double value[dim], L[dim][dim];
    gather_particle<dim>(Lt.B, k, u, Lt.stride, value, L);
    for (int i = 0; i < dim; ++i) {
      double exact = b[i];
      for (int j = 0; j < dim; ++j) exact += A[i][j] * Lt.x[std::size_t(j)][std::size_t(k)];
      EXPECT_NEAR(value[i], exact, 1e-13);
      for (int j = 0; j < dim; ++j) EXPECT_NEAR(L[i][j], A[i][j], 1e-11);
    }
  }
}

TEST(BulkKernels, stencils_are_a_partition_of_unity_and_gather_a_linear_field_exactly) {
  check_stencils_and_linear_gather<2>();
  check_stencils_and_linear_gather<3>();
}

template <int dim>
void check_scatter_moments() {
  Lattice<dim> Lt(11 + dim);
  std::vector<double> mass(Lt.nodes, 0.0);
  std::array<std::vector<double>, dim> mom, force;
  ScatterArrays<dim> g{mass.data(), {}, {}, {}};
  for (int d = 0; d < dim; ++d) {
    mom[std::size_t(d)].assign(Lt.nodes, 0.0), force[std::size_t(d)].assign(Lt.nodes, 0.0);
    g.momentum[d] = mom[std::size_t(d)].data(), g.force[d] = force[std::size_t(d)].data(), g.stride[d] = Lt.stride[d];
  }
  const int k = 5;
  const double m = 0.25, v[3] = {1.5, -2.0, 0.75};
  double minus_v_sigma[kSymmetric<dim>], vd[dim];
  for (int c = 0; c < kSymmetric<dim>; ++c) minus_v_sigma[c] = 100.0 * (c + 1) * (c % 2 ? -1 : 1);
  for (int d = 0; d < dim; ++d) vd[d] = v[d];
  scatter_particle<dim>(Lt.B, k, m, vd, minus_v_sigma, g);
  double M = 0.0, P[dim] = {}, F[dim] = {}, moment[dim][dim] = {};
  for (std::size_t q = 0; q < Lt.nodes; ++q) {
    M += mass[q];
    for (int i = 0; i < dim; ++i) {
      P[i] += mom[std::size_t(i)][q];
      F[i] += force[std::size_t(i)][q];
      for (int j = 0; j < dim; ++j) moment[i][j] += force[std::size_t(i)][q] * Lt.node_coord(std::ptrdiff_t(q), j);
    }
  }
  EXPECT_NEAR(M, m, 1e-15);
  for (int i = 0; i < dim; ++i) {
    EXPECT_NEAR(P[i], m * v[i], 1e-14);
    EXPECT_NEAR(F[i], 0.0, 1e-9) << "internal forces sum to zero";
    // sum_n f_i x_j = sum_k (-V sigma)_ik sum_n dS/dx_k x_j = (-V sigma)_ij.
    for (int j = 0; j < dim; ++j) EXPECT_NEAR(moment[i][j], minus_v_sigma[symmetric_index<dim>(i, j)], 1e-9);
  }
}

TEST(BulkKernels, a_particles_scatter_carries_its_mass_momentum_and_stress_to_the_nodes) {
  check_scatter_moments<2>();
  check_scatter_moments<3>();
}

}  // namespace
}  // namespace rupture
