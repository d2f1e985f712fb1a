// Tests of fracture/tip_domain.hpp: the domain points' gradients come from the particles'
// displacement and velocity mapped to the grid.
//  - an affine deformation x = (I + A) X with velocity v = B X (rotation included) gives the
//    spatial gradients grad u = A (I + A)^-1 and grad v = B (I + A)^-1 at every point whose
//    stencil lies in the material, to round-off (mass-weighted GIMP maps of particles on a
//    lattice symmetric about each node reproduce linear fields);
//  - only points within reach (+ a cell) of the tip are returned, with the particle's stress,
//    strain, area, density and id;
//  - two fields that meet along a line hold one body's gradient only where they are tied;
//  - split among ranks (DomainSums), the ranks' points are one process's, with its gradients.
#include <gtest/gtest.h>

#include <algorithm>
#include <barrier>
#include <cmath>
#include <cstdio>
#include <map>
#include <thread>
#include <vector>

#include "fracture/tip_domain.hpp"
#include "grid/grid.hpp"
#include "material/elastic.hpp"
#include "particles/particles.hpp"

namespace rupture {
namespace {

constexpr double kA[2][2] = {{1e-3, -4e-3}, {6e-3, 2e-3}};  // du_i/dX_j (a rotation in it)
constexpr double kB[2][2] = {{3.0, 1.0}, {-2.0, 0.5}};      // dv_i/dX_j, 1/s

// M (I + A)^-1.
void right_inverse(const double M[2][2], double out[2][2]) {
  const double a = 1 + kA[0][0], b = kA[0][1], c = kA[1][0], d = 1 + kA[1][1], det = a * d - b * c;
  const double inv[2][2] = {{d / det, -b / det}, {-c / det, a / det}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) out[i][j] = M[i][0] * inv[0][j] + M[i][1] * inv[1][j];
}

struct Block {
  Grid g;
  GridFields fields;
  Particles P;
  std::vector<ElasticStiffness> C;
};

// A 20 x 20 mm block of 1 mm cells, 2 particles per cell; field 1 below y = `split` (if given).
Block block(double split = -1.0) {
  Block b;
  const double lo[2] = {0.0, 0.0}, hi[2] = {0.02, 0.02}, v[2] = {0.0, 0.0};
  b.g = make_uniform_grid(lo, hi, 1e-3);
  const double origin[2] = {b.g.x.origin, b.g.y.origin};
  seed_rectangle(b.P, lo, hi, 1e-3, 2, 1246.0, 0, 0, v, origin);
  // The particles where they are seeded (a lattice symmetric about every node: the maps then
  // reproduce any linear field exactly) and their reference positions X = (I + A)^-1 x.
  double G[2][2], H[2][2];
  right_inverse(kA, G), right_inverse(kB, H);
  for (std::size_t p = 0; p < b.P.size(); ++p) {
    const double x = b.P.x[p], y = b.P.y[p];
    b.P.x0[p] = x - (G[0][0] * x + G[0][1] * y), b.P.y0[p] = y - (G[1][0] * x + G[1][1] * y);
    b.P.vx[p] = H[0][0] * x + H[0][1] * y, b.P.vy[p] = H[1][0] * x + H[1][1] * y;
    const double Y = b.P.y0[p];
    b.P.sxx[p] = 1e6, b.P.syy[p] = 2e6, b.P.sxy[p] = 3e5;
    if (split >= 0.0 && Y < split) b.P.field[p] = 1;
  }
  b.fields.resize(2, std::size_t(b.g.nodes_x()), std::size_t(b.g.nodes_y()));
  b.C.push_back(stiffness(ElasticMaterial{"homalite", 5.2e9, 0.34, 1246.0}, PlaneMode::strain));
  return b;
}

TEST(TipDomain, affine_fields_give_their_gradients_and_the_particles_state) {
  const Block b = block();
  const TipFrame tip{0.01, 0.01, 1.0, 0.0};
  const std::vector<DomainPoint> pts = tip_domain_points(b.g, b.fields, b.P, b.C, {}, tip, 4e-3, 0.0);
  ASSERT_FALSE(pts.empty());
  double G[2][2], H[2][2];
  right_inverse(kA, G), right_inverse(kB, H);
  for (const DomainPoint& d : pts) {
    EXPECT_LT(std::hypot(d.x - tip.x, d.y - tip.y), 4e-3 + 1e-3);
    EXPECT_NEAR(d.ux_x, G[0][0], 1e-12);
    EXPECT_NEAR(d.ux_y, G[0][1], 1e-12);
    EXPECT_NEAR(d.uy_x, G[1][0], 1e-12);
    EXPECT_NEAR(d.uy_y, G[1][1], 1e-12);
    EXPECT_NEAR(d.vx_x, H[0][0], 1e-9);
    EXPECT_NEAR(d.vy_y, H[1][1], 1e-9);
    EXPECT_NEAR(d.vx_y, H[0][1], 1e-9);
    EXPECT_NEAR(d.vy_x, H[1][0], 1e-9);
    EXPECT_EQ(d.sxy, 3e5);
    EXPECT_NEAR(d.density, 1246.0, 1e-9);
    EXPECT_EQ(d.ax, 0.0);  // dt = 0: no acceleration read
    EXPECT_NEAR(d.ux, G[0][0] * d.x + G[0][1] * d.y, 1e-15);  // u = x - X
    EXPECT_NEAR(d.uy, G[1][0] * d.x + G[1][1] * d.y, 1e-15);
  }
  // The tip's displacement (the loaded faces' J term): the linear field's there, off the lattice
  // of particle centres too.
  for (const TipFrame& t : {tip, TipFrame{0.0103, 0.0087, 1.0, 0.0}}) {
    std::vector<DomainPoint> out;
    const TipDisplacement u = tip_domain_points(b.g, b.fields, b.P, b.C, {}, t, 4e-3, 0.0, {}, out);
    EXPECT_NEAR(u.ux, G[0][0] * t.x + G[0][1] * t.y, 1e-15);
    EXPECT_NEAR(u.uy, G[1][0] * t.x + G[1][1] * t.y, 1e-15);
  }
}

TEST(TipDomain, two_fields_are_one_body_where_tied) {
  // Fields 0 above and 1 below y = 10 mm: untied, the maps of a field see its own particles
  // only, and next to the line the gradient misses the other side; tied everywhere,
  // every point has the one body's gradient again.
  Block b = block(0.01);
  const TipFrame tip{0.01, 0.01, 1.0, 0.0};
  const std::vector<DomainPoint> apart = tip_domain_points(b.g, b.fields, b.P, b.C, {}, tip, 4e-3, 0.0);
  double G[2][2];
  right_inverse(kA, G);
  double worst = 0.0;
  for (const DomainPoint& d : apart) worst = std::max(worst, std::fabs(d.uy_y - G[1][1]));
  EXPECT_GT(worst, 1e-4);  // a free edge's one-sided map
  std::vector<std::size_t> all(b.g.num_nodes());
  for (std::size_t n = 0; n < all.size(); ++n) all[n] = n;
  const std::vector<TiedFields> ties{{0, 1, &all}};
  const std::vector<DomainPoint> tied = tip_domain_points(b.g, b.fields, b.P, b.C, ties, tip, 4e-3, 0.0);
  for (const DomainPoint& d : tied) EXPECT_NEAR(d.uy_y, G[1][1], 1e-12);
}

// Distributed runs: each rank maps its own particles, the maps are summed over the ranks
// (DomainSums), and each rank returns its own particles' points. Two ranks here are two threads
// that split the block's particles by a line through the domain (x = 11.3 mm, 1.3 mm from the
// tip); their sums meet at a barrier and are added in rank order, as Comm::sum_in_rank_order
// adds them. Together they return one process's points, each with one process's gradients (to
// round-off: the maps' sums are added in another order). Two fields meet along y = 10 mm, so a
// field's map near the line is one-sided and must be summed over the ranks per field. Measured:
// 8.9e-15 of the largest gradient summed; 0.64 without the sums (each rank's own half maps).
TEST(TipDomain, ranks_that_split_the_particles_return_one_process_points) {
  const Block b = block(0.01);
  const TipFrame tip{0.01, 0.01, 1.0, 0.0};
  const std::vector<DomainPoint> whole = tip_domain_points(b.g, b.fields, b.P, b.C, {}, tip, 4e-3, 0.0);
  Particles part[2];
  part[0].append_copy(b.P);
  std::vector<unsigned char> right(b.P.size(), 0);
  for (std::size_t p = 0; p < b.P.size(); ++p) right[p] = b.P.x[p] > 0.0113;
  part[0].move_marked(right, part[1]);
  ASSERT_GT(part[0].size(), 0u);
  ASSERT_GT(part[1].size(), 0u);
  std::barrier<> meet(2);
  std::vector<double> slot[2];
  std::vector<double> highest[2];
  TipDisplacement at_tip[2];
  std::vector<DomainPoint> out[2];
  const auto rank = [&](int r, bool summed) {
    DomainSums sums;
    sums.sum = [&, r, summed](double* v, std::size_t n) {
      slot[r].assign(v, v + n);
      meet.arrive_and_wait();
      if (summed)
        for (std::size_t i = 0; i < n; ++i) v[i] = slot[0][i] + slot[1][i];
      meet.arrive_and_wait();
    };
    sums.max = [&, r](double* v, std::size_t n) {
      highest[r].assign(v, v + n);
      meet.arrive_and_wait();
      for (std::size_t i = 0; i < n; ++i) v[i] = std::max(highest[0][i], highest[1][i]);
      meet.arrive_and_wait();
    };
    at_tip[r] = tip_domain_points(b.g, b.fields, part[r], b.C, {}, tip, 4e-3, 0.0, {}, out[r], sums);
  };
  const auto split_read = [&](bool summed) {
    std::thread t0(rank, 0, summed), t1(rank, 1, summed);
    t0.join(), t1.join();
    std::map<std::uint32_t, const DomainPoint*> by_id;
    for (const std::vector<DomainPoint>& o : out)
      for (const DomainPoint& d : o) by_id[d.id] = &d;
    EXPECT_EQ(by_id.size(), whole.size());
    EXPECT_EQ(out[0].size() + out[1].size(), whole.size());
    double worst = 0.0;
    for (const DomainPoint& w : whole) {
      const auto it = by_id.find(w.id);
      if (it == by_id.end()) {
        ADD_FAILURE() << "point " << w.id << " missing";
        continue;
      }
      const DomainPoint& d = *it->second;
      for (const auto& [a, c] : {std::pair{d.ux_x, w.ux_x}, {d.ux_y, w.ux_y}, {d.uy_x, w.uy_x}, {d.uy_y, w.uy_y}})
        worst = std::max(worst, std::fabs(a - c) / 1e-2);  // of the largest gradient, ~1e-2
      for (const auto& [a, c] : {std::pair{d.vx_x, w.vx_x}, {d.vx_y, w.vx_y}, {d.vy_x, w.vy_x}, {d.vy_y, w.vy_y}})
        worst = std::max(worst, std::fabs(a - c) / 3.0);  // of the largest, 3 1/s
    }
    return worst;
  };
  const double summed = split_read(true);
  // The tip's displacement (the loaded faces' J term) from the summed maps: every rank the same
  // bits, one process's to round-off.
  std::vector<DomainPoint> one;
  const TipDisplacement whole_tip = tip_domain_points(b.g, b.fields, b.P, b.C, {}, tip, 4e-3, 0.0, {}, one);
  EXPECT_EQ(at_tip[0].ux, at_tip[1].ux);
  EXPECT_EQ(at_tip[0].uy, at_tip[1].uy);
  EXPECT_GT(std::fabs(whole_tip.ux) + std::fabs(whole_tip.uy), 0.0);
  EXPECT_NEAR(at_tip[0].ux, whole_tip.ux, 1e-12 * (std::fabs(whole_tip.ux) + std::fabs(whole_tip.uy)));
  EXPECT_NEAR(at_tip[0].uy, whole_tip.uy, 1e-12 * (std::fabs(whole_tip.ux) + std::fabs(whole_tip.uy)));
  const double halves = split_read(false);
  std::printf("largest gradient difference from one process: %.2e summed over the ranks, %.2e from each "
              "rank's own map\n", summed, halves);
  EXPECT_LT(summed, 1e-12);
  EXPECT_GT(halves, 1e-3);
}

}  // namespace
}  // namespace rupture

namespace rupture {
namespace {

// A prestressed body (bodies.NAME.stress): its particles sit where they were made, u = x - X = 0,
// yet its material is strained by eps0 = C^-1 sigma0; the domain's gradient is that of the
// displacement from the stress-free state, grad u = eps0 (symmetric: no rotation), per field.
TEST(TipDomain, a_fields_initial_strain_is_the_gradient_of_an_undisplaced_prestressed_body) {
  Block b = block(0.01);
  for (std::size_t p = 0; p < b.P.size(); ++p) b.P.x0[p] = b.P.x[p], b.P.y0[p] = b.P.y[p];
  const std::vector<InitialStrain> e0 = {{1e-4, -3e-4, 2e-4}, {-5e-5, 6e-4, 0.0}};
  const TipFrame tip{0.01, 0.015, 1.0, 0.0};  // field 0 around it, field 1 below y = 10 mm
  const std::vector<DomainPoint> pts = tip_domain_points(b.g, b.fields, b.P, b.C, {}, tip, 4e-3, 0.0, e0);
  ASSERT_FALSE(pts.empty());
  for (const DomainPoint& d : pts) {
    EXPECT_NEAR(d.ux_x, 1e-4, 1e-15);
    EXPECT_NEAR(d.uy_y, -3e-4, 1e-15);
    EXPECT_NEAR(d.ux_y, 2e-4, 1e-15);
    EXPECT_NEAR(d.uy_x, 2e-4, 1e-15);
  }
  const TipFrame low{0.01, 0.004, 1.0, 0.0};  // inside field 1
  for (const DomainPoint& d : tip_domain_points(b.g, b.fields, b.P, b.C, {}, low, 3e-3, 0.0, e0)) {
    if (d.y > 0.009) continue;  // the points whose stencils reach field 0's side see its nodes empty
    EXPECT_NEAR(d.ux_x, -5e-5, 1e-15);
    EXPECT_NEAR(d.uy_y, 6e-4, 1e-15);
    EXPECT_NEAR(d.ux_y, 0.0, 1e-15);
  }
}

}  // namespace
}  // namespace rupture
