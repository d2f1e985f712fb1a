// Tests of grid/nested (theory §5, nested levels with transition nodes): the levels' layout and
// nesting, that every slave node is a partition-of-unity, linear-exact combination of DOFs, the
// GIMP contract (theory E3) of particles anywhere, transitions included, after mapping to DOFs,
// and that condense/distribute conserve mass and momentum and are each other's transpose.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include "core/errors.hpp"
#include "grid/nested.hpp"
#include "solver/nested_state.hpp"

using namespace rupture;

namespace {

// The example's plate and boxes (examples/rosakis1999.toml), finest `h`.
NestedGrid example_levels(double h) {
  const double min[2] = {0.0, -0.15}, max[2] = {0.125, 0.15};
  std::vector<RefineBox> boxes = {{{0.0, -0.06}, {0.09, 0.04}, 1e-3},
                                  {{0.0, -0.03}, {0.08, 0.02}, 0.5e-3},
                                  {{0.01, -0.012}, {0.07, 0.01}, 0.25e-3},
                                  {{0.015, -0.006}, {0.065, 0.005}, 125e-6},
                                  {{0.018, -0.003}, {0.06, 0.0025}, 62.5e-6},
                                  {{0.02, -0.0015}, {0.056, 0.0015}, 31.25e-6}};
  std::vector<RefineBox> kept;
  for (const RefineBox& b : boxes)
    if (b.size >= h * (1 - 1e-9)) kept.push_back(b);
  return make_nested_grid(min, max, 2e-3, h, kept);
}

// A particle's weights mapped to DOFs: dof -> (S, dS/dx, dS/dy).
std::map<std::uint32_t, std::array<double, 3>> dof_weights(const NestedGrid& g,
                                                           const std::vector<std::size_t>& slave_of,
                                                           int l, double x, double y, double lp,
                                                           bool& touched_slave) {
  touched_slave = false;
  const LevelLattice& L = g.levels[std::size_t(l)];
  Stencil1D sx, sy;
  stencil(L.x, x, lp, sx);
  stencil(L.y, y, lp, sy);
  std::map<std::uint32_t, std::array<double, 3>> w;
  for (int b = 0; b < 3; ++b)
    for (int a = 0; a < 3; ++a) {
      const int i = sx.first + a, j = sy.first + b;
      EXPECT_TRUE(i >= 0 && i < L.nodes_x() && j >= 0 && j < L.nodes_y()) << "stencil off level " << l;
      const std::size_t id = g.level_start[std::size_t(l)] + L.node_index(i, j);
      const double s = sx.s[a] * sy.s[b], gx = sx.ds[a] * sy.s[b], gy = sx.s[a] * sy.ds[b];
      if (g.is_dof[id]) {
        auto& e = w[std::uint32_t(id)];
        e[0] += s, e[1] += gx, e[2] += gy;
        continue;
      }
      const std::size_t k = slave_of[id];
      touched_slave = true;
      for (std::uint32_t t = g.term_start[k]; t < g.term_start[k + 1]; ++t) {
        auto& e = w[g.terms[t].dof];
        const double c = g.terms[t].c;
        e[0] += c * s, e[1] += c * gx, e[2] += c * gy;
      }
    }
  return w;
}

}  // namespace

TEST(NestedGrid, levels_nest_properly_and_keep_the_boxes) {
  const NestedGrid g = example_levels(31.25e-6);
  ASSERT_EQ(g.levels.size(), 7u);
  for (std::size_t l = 0; l < g.levels.size(); ++l) {
    const LevelLattice& L = g.levels[l];
    EXPECT_NEAR(L.x.h, 2e-3 / double(1 << l), 1e-15);
    EXPECT_EQ(L.unit, 64L >> l);
    if (l == 0) continue;
    const LevelLattice& P = g.levels[l - 1];
    for (int d = 0; d < 2; ++d) {
      // Inner borders on the parent's nodes, kNestingCells parent cells inside the parent's.
      if (!L.outer_lo[d]) {
        EXPECT_EQ(L.lo[d] % P.unit, 0);
        if (!P.outer_lo[d]) {
          EXPECT_GE(L.lo[d] - P.lo[d], kNestingCells * P.unit);
        }
      } else {
        EXPECT_TRUE(P.outer_lo[d]);
      }
      if (!L.outer_hi[d]) {
        EXPECT_EQ(L.hi[d] % P.unit, 0);
        if (!P.outer_hi[d]) {
          EXPECT_GE(P.hi[d] - L.hi[d], kNestingCells * P.unit);
        }
      } else {
        EXPECT_TRUE(P.outer_hi[d]);
      }
    }
  }
  // The boxes are honoured: level 6 (31.25 um) at the weak plane, level 1 touches the left edge.
  EXPECT_EQ(g.level_of(0.03, 0.0), 6);
  EXPECT_EQ(g.level_of(0.03, 0.002), 5);
  EXPECT_EQ(g.level_of(0.1, 0.1), 0);
  EXPECT_TRUE(g.levels[1].outer_lo[0]);
  EXPECT_FALSE(g.levels[6].outer_lo[0]);
}

// Every slave is a combination of DOFs whose coefficients sum to one and reproduce linear
// fields (x and y): the property the GIMP contract at a transition rests on.
TEST(NestedGrid, slaves_are_partition_of_unity_linear_exact_combinations_of_dofs) {
  const NestedGrid g = example_levels(62.5e-6);
  ASSERT_GT(g.slaves.size(), 0u);
  double worst_sum = 0, worst_lin = 0;
  for (std::size_t k = 0; k < g.slaves.size(); ++k) {
    double sum = 0, x = 0, y = 0, xs, ys;
    g.node_position(g.slaves[k], xs, ys);
    for (std::uint32_t t = g.term_start[k]; t < g.term_start[k + 1]; ++t) {
      ASSERT_TRUE(g.is_dof[g.terms[t].dof]) << "slave " << g.slaves[k] << " names a slave";
      double xd, yd;
      g.node_position(g.terms[t].dof, xd, yd);
      sum += g.terms[t].c, x += g.terms[t].c * xd, y += g.terms[t].c * yd;
    }
    worst_sum = std::max(worst_sum, std::fabs(sum - 1.0));
    worst_lin = std::max({worst_lin, std::fabs(x - xs), std::fabs(y - ys)});
  }
  std::printf("%zu slaves of %zu nodes: |sum c - 1| <= %.2e, |sum c x - x| <= %.2e m\n",
              g.slaves.size(), g.num_nodes(), worst_sum, worst_lin);
  EXPECT_LT(worst_sum, 1e-14);
  EXPECT_LT(worst_lin, 1e-15);
}

// theory E3's contract for particles everywhere, densely around the transitions: partition of
// unity, zero gradient sum, and exact linear fields (sum S x = x_p, sum grad S (x) x = I), with
// the particle's own half-width and with those of a particle moved in from the coarser level
// or out from the finer one; on the level owning the point and on every level a particle may
// still be on between migrations (solver/nested_state.hpp: up to kMigrateDrift of the finest
// cells outside its level's region, or anywhere inside a finer one).
TEST(NestedGrid, gimp_contract_holds_through_every_transition) {
  const NestedGrid g = example_levels(0.25e-3);  // levels 0-3: 2 mm .. 0.25 mm
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(-0.002, 0.08), uy(-0.04, 0.03);
  std::vector<std::size_t> slave_of(g.num_nodes(), ~std::size_t(0));
  for (std::size_t k = 0; k < g.slaves.size(); ++k) slave_of[g.slaves[k]] = k;
  double worst[4] = {0, 0, 0, 0};
  int samples = 0, at_transitions = 0;
  for (int n = 0; n < 20000; ++n) {
    const double x = ux(rng), y = uy(rng);
    const double u = (x - g.min[0]) / g.finest, v = (y - g.min[1]) / g.finest;
    for (int l = 0; l < int(g.levels.size()); ++l) {
    const LevelLattice& L = g.levels[std::size_t(l)];
    const double grow = kMigrateDrift * double(g.levels.back().unit), p[2] = {u, v};
    bool reachable = true;
    for (int d = 0; d < 2; ++d)
      reachable = reachable && (L.outer_lo[d] || p[d] > double(L.lo[d]) - grow) &&
                  (L.outer_hi[d] || p[d] < double(L.hi[d]) + grow);
    if (!reachable) continue;
    const double h = L.x.h;
    for (const double lp : {h / 4, h / 8, h / 2}) {  // own, from the finer level, from the coarser
      bool touched = false;
      const auto w = dof_weights(g, slave_of, l, x, y, lp, touched);
      at_transitions += touched;
      double s = 0, gx = 0, gy = 0, sx = 0, sy = 0, gxx = 0, gxy = 0, gyx = 0, gyy = 0;
      for (const auto& [dof, e] : w) {
        double xd, yd;
        g.node_position(dof, xd, yd);
        s += e[0], gx += e[1], gy += e[2];
        sx += e[0] * xd, sy += e[0] * yd;
        gxx += e[1] * xd, gxy += e[1] * yd, gyx += e[2] * xd, gyy += e[2] * yd;
      }
      worst[0] = std::max(worst[0], std::fabs(s - 1));
      worst[1] = std::max(worst[1], (std::fabs(gx) + std::fabs(gy)) * h);
      worst[2] = std::max({worst[2], std::fabs(sx - x) / h, std::fabs(sy - y) / h});
      worst[3] = std::max({worst[3], std::fabs(gxx - 1), std::fabs(gyy - 1), std::fabs(gxy), std::fabs(gyx)});
      ++samples;
    }
    }
  }
  std::printf("%d samples (%d touching slave nodes): |sum S - 1| <= %.2e, |sum grad S| h <= %.2e, |sum S x - x_p| / h <= %.2e, "
              "|sum grad S x - I| <= %.2e\n", samples, at_transitions, worst[0], worst[1], worst[2], worst[3]);
  EXPECT_GT(at_transitions, samples / 20);  // the sample does probe the transitions
  EXPECT_LT(worst[0], 1e-13);
  EXPECT_LT(worst[1], 1e-11);
  EXPECT_LT(worst[2], 1e-9);
  EXPECT_LT(worst[3], 1e-9);
}

// Condense keeps the totals (mass, momentum) and is the transpose of distribute.
TEST(NestedGrid, condense_conserves_totals_and_is_the_transpose_of_distribute) {
  const NestedGrid g = example_levels(0.125e-3);
  const std::size_t n = g.num_nodes();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> a(n), b(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = u(rng), b[i] = u(rng);
  double total = 0;
  for (double v : a) total += v;
  std::vector<double> ca = a, db = b;
  condense_to_dofs(g, ca.data());
  spread_to_slaves(g, db.data());
  double total_after = 0, lhs = 0, rhs = 0, scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    total_after += ca[i];
    if (g.is_dof[i]) {
      EXPECT_EQ(db[i], b[i]);
    } else {
      EXPECT_EQ(ca[i], 0.0);
    }
    lhs += a[i] * db[i];
    if (g.is_dof[i]) rhs += ca[i] * b[i];
    scale += std::fabs(a[i] * db[i]);
  }
  EXPECT_NEAR(total_after, total, 1e-12 * double(n));
  EXPECT_NEAR(lhs, rhs, 1e-13 * scale);
}

TEST(NestedGrid, counts_particles_per_level) {
  const NestedGrid g = example_levels(62.5e-6);
  const double bmin[2] = {0.0, -0.15}, bmax[2] = {0.125, 0.15};
  const auto counts = count_level_cells(g, bmin, bmax, 2);
  std::size_t total = 0;
  double area = 0;
  for (std::size_t l = 0; l < counts.size(); ++l) {
    const double h = g.levels[l].x.h;
    std::printf("level %zu (%.4g mm): %zu cells, %zu particles\n", l, h * 1e3, counts[l].cells, counts[l].particles);
    total += counts[l].particles;
    area += double(counts[l].particles) * h * h / 4;
  }
  std::printf("total %zu particles\n", total);
  // The particles tile the plate exactly once (its right edge, 62.5 coarse cells out, is on the
  // particles' lattice).
  EXPECT_NEAR(area, 0.125 * 0.3, 1e-12);
}

TEST(NestedGrid, rejects_box_sizes_that_are_not_a_level) {
  const double min[2] = {0, 0}, max[2] = {0.01, 0.01};
  try {
    make_nested_grid(min, max, 1e-3, 0.25e-3, {{{0.002, 0.002}, {0.006, 0.006}, 0.3e-3}});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("box 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.0003"), std::string::npos) << e.what();
  }
}
