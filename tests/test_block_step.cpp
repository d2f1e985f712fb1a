// Tests of bulk/block_step (the MUSL step of a block written once for dim = 2 and 3 over the
// dimension-generic kernels of bulk/): total momentum conserved to round-off in 3D (and 2D); a
// 3D block held at v_z = 0 is the 2D plane-strain block particle for particle (the z weights sum
// to one); P and S pulses travel at c_D and c_S; an S pulse polarized along z is the one
// polarized along y with the axes swapped (the 3D stress table's xy and xz).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "bulk/block_step.hpp"
#include "bulk/dimension.hpp"
#include "material/elastic.hpp"

namespace rupture {
namespace {

constexpr double kH = 1e-3;  // cell, m
ElasticMaterial homalite() { return {"homalite", 5.2e9, 0.34, 1246.0, 0.0}; }

double dilatational_speed() {
  const ElasticStiffness C = stiffness(homalite(), PlaneMode::strain);
  return std::sqrt(C.c11 / homalite().density);
}

template <int dim>
BlockStep step_of(double cfl) {
  BlockStep s;
  s.stiffness = dim == 3 ? stiffness_3d(homalite()) : stiffness(homalite(), PlaneMode::strain);
  s.dt = cfl * kH / dilatational_speed();
  return s;
}

// A smooth velocity and a self-equilibrium-free stress over the block: every component and
// every shear term of the step is exercised.
template <int dim>
void stir(BlockParticles<dim>& P) {
  for (std::size_t p = 0; p < P.size(); ++p) {
    for (int d = 0; d < dim; ++d) {
      const double a = P.x[0][p] / kH, b = P.x[std::size_t(dim - 1)][p] / kH;
      P.v[std::size_t(d)][p] = 0.7 * std::sin(0.9 * a + 0.4 * d) + 0.3 * std::cos(1.3 * b - d);
    }
    for (int c = 0; c < kSymmetric<dim>; ++c)
      P.stress[std::size_t(c)][p] = 2e6 * std::sin(0.37 * double(p) + 1.1 * c);
  }
}

template <int dim>
std::array<double, dim> momentum(const BlockParticles<dim>& P, double& scale) {
  std::array<double, dim> sum{};
  scale = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p)
    for (int d = 0; d < dim; ++d) {
      sum[std::size_t(d)] += P.mass[p] * P.v[std::size_t(d)][p];
      scale += P.mass[p] * std::fabs(P.v[std::size_t(d)][p]);
    }
  return sum;
}

template <int dim>
void check_momentum_conserved() {
  std::array<double, dim> origin, lo, hi;
  std::array<int, dim> cells;
  for (int d = 0; d < dim; ++d) {
    origin[std::size_t(d)] = -3 * kH, lo[std::size_t(d)] = 0.0;
    hi[std::size_t(d)] = (d == 0 ? 6 : 4) * kH, cells[std::size_t(d)] = (d == 0 ? 12 : 10);
  }
  BlockGrid<dim> G = make_block_grid<dim>(origin, kH, cells);
  BlockParticles<dim> P = seed_block<dim>(lo, hi, kH, 2, homalite().density);
  stir(P);
  double scale = 0.0;
  const std::array<double, dim> before = momentum(P, scale);
  const BlockStep step = step_of<dim>(0.2);
  const std::array<bool, dim> free{};
  const double s0 = P.stress[std::size_t(dim)][0], x0 = P.x[0][0];
  for (int n = 0; n < 30; ++n) block_step_musl<dim>(P, G, step, free);
  double unused = 0.0;
  const std::array<double, dim> after = momentum(P, unused);
  for (int d = 0; d < dim; ++d)
    EXPECT_NEAR(after[std::size_t(d)], before[std::size_t(d)], 1e-13 * scale) << "component " << d;
  // The block did deform: the check is not of a block at rest.
  EXPECT_GT(std::fabs(P.stress[std::size_t(dim)][0] - s0), 1e4);
  EXPECT_GT(std::fabs(P.x[0][0] - x0), 1e-4 * kH);
}

TEST(BlockStep, total_momentum_is_conserved_to_round_off_in_3d_and_2d) {
  check_momentum_conserved<3>();
  check_momentum_conserved<2>();
}

TEST(BlockStep, block_held_at_zero_vz_is_the_plane_strain_2d_block) {
  // 2D: 8 x 5 cells of particles, free edges; 3D: the same x 3 cells along z, v_z = 0 at every
  // node. Particle (i, j) of the 2D block is particle (i, j, l) of the 3D one for every l.
  const int cx = 8, cy = 5, cz = 3, ppc = 2;
  BlockGrid<2> G2 = make_block_grid<2>({-3 * kH, -3 * kH}, kH, {cx + 6, cy + 6});
  BlockGrid<3> G3 = make_block_grid<3>({-3 * kH, -3 * kH, -3 * kH}, kH, {cx + 6, cy + 6, cz + 6});
  BlockParticles<2> P2 = seed_block<2>({0, 0}, {cx * kH, cy * kH}, kH, ppc, homalite().density);
  BlockParticles<3> P3 = seed_block<3>({0, 0, 0}, {cx * kH, cy * kH, cz * kH}, kH, ppc, homalite().density);
  stir(P2);
  const std::size_t layer = P2.size();
  ASSERT_EQ(P3.size(), layer * std::size_t(cz * ppc));
  // The 2D state in every z layer (stress xx, yy, xy of 2D into 3D's xx, yy, xy; zz from
  // plane strain; yz = xz = 0).
  const ElasticStiffness C2 = stiffness(homalite(), PlaneMode::strain);
  for (std::size_t q = 0; q < P3.size(); ++q) {
    const std::size_t p = q % layer;
    P3.v[0][q] = P2.v[0][p], P3.v[1][q] = P2.v[1][p];
    P3.stress[0][q] = P2.stress[0][p], P3.stress[1][q] = P2.stress[1][p];
    P3.stress[std::size_t(symmetric_index<3>(0, 1))][q] = P2.stress[2][p];
    P3.stress[2][q] = stress_zz(C2, P2.stress[0][p], P2.stress[1][p]);
  }
  const std::vector<double> z0 = P3.x[2];
  const BlockStep s2 = step_of<2>(0.3), s3 = step_of<3>(0.3);
  for (int n = 0; n < 40; ++n) {
    block_step_musl<2>(P2, G2, s2, {false, false});
    block_step_musl<3>(P3, G3, s3, {false, false, true});
  }
  double vmax = 0.0, smax = 0.0;
  for (std::size_t p = 0; p < layer; ++p) {
    vmax = std::max({vmax, std::fabs(P2.v[0][p]), std::fabs(P2.v[1][p])});
    smax = std::max({smax, std::fabs(P2.stress[0][p]), std::fabs(P2.stress[1][p]), std::fabs(P2.stress[2][p])});
  }
  double dx = 0.0, dv = 0.0, ds = 0.0, dz = 0.0;
  for (std::size_t q = 0; q < P3.size(); ++q) {
    const std::size_t p = q % layer;
    for (int d = 0; d < 2; ++d) {
      dx = std::max(dx, std::fabs(P3.x[std::size_t(d)][q] - P2.x[std::size_t(d)][p]));
      dv = std::max(dv, std::fabs(P3.v[std::size_t(d)][q] - P2.v[std::size_t(d)][p]));
    }
    ds = std::max({ds, std::fabs(P3.stress[0][q] - P2.stress[0][p]), std::fabs(P3.stress[1][q] - P2.stress[1][p]),
                   std::fabs(P3.stress[std::size_t(symmetric_index<3>(0, 1))][q] - P2.stress[2][p]),
                   std::fabs(P3.stress[2][q] - stress_zz(C2, P2.stress[0][p], P2.stress[1][p])),
                   std::fabs(P3.stress[3][q]), std::fabs(P3.stress[4][q])});
    dz = std::max({dz, std::fabs(P3.v[2][q]), std::fabs(P3.x[2][q] - z0[q])});
  }
  std::printf("3D at v_z = 0 against 2D: |dx| %.3g m, |dv| %.3g m/s (max %.3g), |dsigma| %.3g Pa (max %.3g)\n",
              dx, dv, vmax, ds, smax);
  EXPECT_LT(dx, 1e-12 * kH);
  EXPECT_LT(dv, 1e-11 * vmax);
  EXPECT_LT(ds, 1e-11 * smax);
  EXPECT_EQ(dz, 0.0);
  EXPECT_GT(vmax, 0.1);  // the 2D block moved
}

// A pulse along a bar (x) of 2 x 2 cells' section, every velocity component but `moving` held
// at zero: one-dimensional uniaxial strain. The right-going pulse v(x - c t) with sigma_{moving,x}
// = -rho c v and, for a P pulse, sigma_ii = c12 / c11 sigma_xx across. Returns the bar after
// `steps` steps and the time t.
template <int dim>
BlockParticles<dim> pulse_in_bar(int moving, double c, int steps, double& t) {
  const int length = 80;
  std::array<double, dim> origin, lo, hi;
  std::array<int, dim> cells;
  for (int d = 0; d < dim; ++d) {
    origin[std::size_t(d)] = -3 * kH, lo[std::size_t(d)] = 0.0;
    hi[std::size_t(d)] = (d == 0 ? length : 2) * kH, cells[std::size_t(d)] = (d == 0 ? length : 2) + 6;
  }
  BlockGrid<dim> G = make_block_grid<dim>(origin, kH, cells);
  BlockParticles<dim> P = seed_block<dim>(lo, hi, kH, 2, homalite().density);
  const BlockStep step = step_of<dim>(0.2);
  const double rho = homalite().density, x0 = 25 * kH, w = 5 * kH;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double v = 0.5 * std::exp(-std::pow((P.x[0][p] - x0) / w, 2));
    P.v[std::size_t(moving)][p] = v;
    P.stress[std::size_t(symmetric_index<dim>(moving, 0))][p] = -rho * c * v;
    if (moving == 0)
      for (int d = 1; d < dim; ++d) P.stress[std::size_t(d)][p] = step.stiffness.c12 / step.stiffness.c11 * -rho * c * v;
  }
  std::array<bool, dim> fixed;
  for (int d = 0; d < dim; ++d) fixed[std::size_t(d)] = d != moving;
  for (int n = 0; n < steps; ++n) block_step_musl<dim>(P, G, step, fixed);
  t = steps * step.dt;
  return P;
}

// The pulse's centre: the mean of x weighted by m v.
template <int dim>
double pulse_centre(const BlockParticles<dim>& P, int moving) {
  double num = 0.0, den = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const double mv = P.mass[p] * P.v[std::size_t(moving)][p];
    num += mv * P.x[0][p], den += mv;
  }
  return num / den;
}

TEST(BlockStep, p_and_s_pulses_travel_at_the_dilatational_and_shear_speeds) {
  const ElasticStiffness C = stiffness_3d(homalite());
  const double rho = homalite().density, cd = std::sqrt(C.c11 / rho), cs = std::sqrt(C.mu / rho);
  const int steps = 100;
  double t = 0.0;
  // 3D: P along x; S polarized along y.
  const double p_speed = (pulse_centre(pulse_in_bar<3>(0, cd, steps, t), 0) - 25 * kH) / t;
  EXPECT_NEAR(p_speed / cd, 1.0, 0.005) << "P: " << p_speed << " against c_D " << cd;
  const BlockParticles<3> Sy = pulse_in_bar<3>(1, cs, steps, t);
  const double s_speed = (pulse_centre(Sy, 1) - 25 * kH) / t;
  EXPECT_NEAR(s_speed / cs, 1.0, 0.005) << "S: " << s_speed << " against c_S " << cs;
  // 2D: the same pulses, the same speeds.
  const double p2 = (pulse_centre(pulse_in_bar<2>(0, cd, steps, t), 0) - 25 * kH) / t;
  EXPECT_NEAR(p2 / cd, 1.0, 0.005);
  const double s2 = (pulse_centre(pulse_in_bar<2>(1, cs, steps, t), 1) - 25 * kH) / t;
  EXPECT_NEAR(s2 / cs, 1.0, 0.005);
  // The S pulse polarized along z is the one along y: v_z and sigma_xz of one are v_y and
  // sigma_xy of the other (the bar's section is symmetric under y <-> z; particles seeded x
  // fastest, so particle (i, j, l) of one is (i, l, j) of the other).
  const BlockParticles<3> Sz = pulse_in_bar<3>(2, cs, steps, t);
  const int nx = 160, ny = 4;
  double dv = 0.0, dsig = 0.0, vmax = 0.0, smax = 0.0;
  for (std::size_t q = 0; q < Sy.size(); ++q) {
    const std::size_t i = q % nx, j = (q / nx) % ny, l = q / (nx * ny);
    const std::size_t r = i + nx * (l + ny * j);
    dv = std::max(dv, std::fabs(Sz.v[2][r] - Sy.v[1][q]));
    dsig = std::max(dsig, std::fabs(Sz.stress[4][r] - Sy.stress[5][q]));
    vmax = std::max(vmax, std::fabs(Sy.v[1][q]));
    smax = std::max(smax, std::fabs(Sy.stress[5][q]));
  }
  std::printf("speeds: P %.6g (c_D %.6g), S %.6g (c_S %.6g), 2D P %.6g, S %.6g; S along z vs y: |dv| %.3g, |dsigma| %.3g\n",
              p_speed, cd, s_speed, cs, p2, s2, dv, dsig);
  EXPECT_LT(dv, 1e-12 * vmax);
  EXPECT_LT(dsig, 1e-12 * smax);
}

}  // namespace
}  // namespace rupture
