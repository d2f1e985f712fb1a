// Tests of shape/gimp.hpp and grid stencils (theory E3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "grid/grid.hpp"
#include "shape/gimp.hpp"

using namespace rupture;

namespace {

// Reference: hat function averaged over the particle box by composite Gauss quadrature,
// splitting at the hat's kinks so each piece is integrated exactly.
double quadrature_weight(double u, double hL, double hR, double lp) {
  const double a = u - lp, b = u + lp;
  std::vector<double> cuts = {a, b};
  for (double k : {-hL, 0.0, hR})
    if (k > a && k < b) cuts.push_back(k);
  std::sort(cuts.begin(), cuts.end());
  const double g[2] = {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double m = 0.5 * (cuts[k] + cuts[k + 1]), r = 0.5 * (cuts[k + 1] - cuts[k]);
    for (double gi : g) sum += r * hat_graded(m + r * gi, hL, hR);
  }
  return sum / (2.0 * lp);
}

}  // namespace

TEST(Shape, uniform_matches_quadrature_of_hat_over_particle_box) {
  const double h = 1.0;
  for (double lp : {0.25, 0.125, 0.5}) {
    for (double d = -1.6; d <= 1.6; d += 0.0137) {
      const double expected = quadrature_weight(d, h, h, lp);
      EXPECT_NEAR(gimp_uniform(d, h, lp).s, expected, 1e-13) << "d = " << d << ", lp = " << lp;
    }
  }
}

TEST(Shape, graded_matches_quadrature_and_uniform) {
  for (double hL : {1.0, 0.5, 2.0})
    for (double hR : {1.0, 0.5, 2.0})
      for (double u = -2.4; u <= 2.4; u += 0.0113) {
        const double lp = 0.25 * std::min(hL, hR);
        EXPECT_NEAR(gimp_graded(u, hL, hR, lp).s, quadrature_weight(u, hL, hR, lp), 1e-13)
            << "u = " << u << " hL = " << hL << " hR = " << hR;
      }
  for (double u = -1.3; u <= 1.3; u += 0.01) {
    const Weight1D a = gimp_uniform(u, 1.0, 0.25), b = gimp_graded(u, 1.0, 1.0, 0.25);
    EXPECT_NEAR(a.s, b.s, 1e-14);
    EXPECT_NEAR(a.ds, b.ds, 1e-12);
  }
}

TEST(Shape, gradient_is_derivative_of_weight) {
  const double h = 2e-3, lp = h / 4, eps = 1e-9;
  for (double d = -1.2 * h; d <= 1.2 * h; d += 0.01 * h) {
    const double fd = (gimp_uniform(d + eps, h, lp).s - gimp_uniform(d - eps, h, lp).s) / (2 * eps);
    EXPECT_NEAR(gimp_uniform(d, h, lp).ds, fd, 1e-5 / h) << "d/h = " << d / h;
  }
}

TEST(Shape, weights_are_continuous_across_cell_boundaries) {
  const double h = 1.0, lp = 0.25;
  // Kinks of the weight function: |d| = lp, h - lp, h + lp (and their mirror images).
  for (double k : {0.25, 0.75, 1.25}) {
    for (double sgn : {-1.0, 1.0}) {
      const double d = sgn * k;
      const double below = gimp_uniform(d - 1e-12, h, lp).s, above = gimp_uniform(d + 1e-12, h, lp).s;
      EXPECT_NEAR(below, above, 1e-10) << "weight jumps at d = " << d;
      const Weight1D lo = gimp_uniform(d - 1e-9, h, lp), hi = gimp_uniform(d + 1e-9, h, lp);
      EXPECT_NEAR(lo.ds, hi.ds, 1e-6) << "gradient jumps at d = " << d;  // uGIMP is C1
    }
  }
}

TEST(Shape, stencil_partition_of_unity_and_zero_gradient_sum) {
  Axis a;
  a.origin = -0.01;
  a.h = 0.5e-3;
  a.cells = 60;
  for (double lp : {a.h / 4, a.h / 2, a.h / 8}) {
    for (double x = a.node(1) + 1e-7; x < a.node(a.cells - 1); x += 0.0371 * a.h) {
      Stencil1D st;
      stencil(a, x, lp, st);
      double s = 0, ds = 0;
      for (int k = 0; k < 3; ++k) s += st.s[k], ds += st.ds[k];
      EXPECT_NEAR(s, 1.0, 1e-14) << "x = " << x;
      EXPECT_NEAR(ds, 0.0, 1e-9 / a.h) << "x = " << x;
      // Nodes outside the 3-node stencil carry no weight.
      EXPECT_EQ(gimp_uniform(x - a.node(st.first - 1), a.h, lp).s, 0.0);
      EXPECT_EQ(gimp_uniform(x - a.node(st.first + 3), a.h, lp).s, 0.0);
    }
  }
}

// The hot path's three-node form (gimp_uniform_three: outer weights from the box's overlap,
// the middle node the rest) gives theory E3's weights node by node: the branchy closed form and
// the quadrature agree with it to a few ulps for every box size the contract allows, the
// gradients sum to zero, and an outer node the box does not reach gets exactly zero.
// (Offsets c in units of h, h = 1, so the nodes' offsets c + 1, c, c - 1 carry no rounding
// of their own: through an axis, the offset from the first node rounds at eps x / h.)
TEST(Shape, three_node_form_matches_closed_form_and_quadrature) {
  double worst_s = 0.0, worst_ds = 0.0;
  for (double l : {0.5, 0.25, 1.0 / 6.0, 0.125, 1e-3}) {
    for (double c = -0.5; c <= 0.5; c += 0.000731) {
      double s[3], ds[3];
      gimp_uniform_three(c, l, 0.25 / l, 1.0, s[0], s[1], s[2], ds[0], ds[1], ds[2]);
      for (int k = 0; k < 3; ++k) {
        const double d = c - double(k - 1);
        const Weight1D ref = gimp_uniform(d, 1.0, l);
        worst_s = std::max(worst_s, std::fabs(s[k] - ref.s));
        worst_ds = std::max(worst_ds, std::fabs(ds[k] - ref.ds));
        EXPECT_NEAR(s[k], quadrature_weight(d, 1.0, 1.0, l), 1e-13) << "c = " << c << ", l = " << l;
        if (k != 1 && ref.s == 0.0) {
          EXPECT_EQ(s[k], 0.0) << "c = " << c << ", node " << k;
        }
        if (k != 1 && ref.ds == 0.0) {
          EXPECT_EQ(ds[k], 0.0) << "c = " << c << ", node " << k;
        }
      }
      EXPECT_EQ(ds[0] + ds[2] + ds[1], 0.0) << "c = " << c;
    }
  }
  EXPECT_LT(worst_s, 1e-15);
  EXPECT_LT(worst_ds, 1e-15 / 1e-3);  // the gradient's scale: 1 / (2 l h)
}

TEST(Shape, graded_axis_partition_of_unity_across_size_jumps) {
  // Nodes 0..6 with cells 1, 1, 0.5, 0.5, 1, 2: every kind of size change.
  const std::vector<double> xs = {0, 1, 2, 2.5, 3, 4, 6};
  for (double x = 1.5; x <= 4.0; x += 0.01) {
    const double lp = 0.125;
    double s = 0, ds = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const double hL = i > 0 ? xs[i] - xs[i - 1] : 1.0, hR = i + 1 < xs.size() ? xs[i + 1] - xs[i] : 1.0;
      const Weight1D w = gimp_graded(x - xs[i], hL, hR, lp);
      s += w.s;
      ds += w.ds;
    }
    EXPECT_NEAR(s, 1.0, 1e-14) << "x = " << x;
    EXPECT_NEAR(ds, 0.0, 1e-12) << "x = " << x;
  }
}

// The select (branch-free) form the batched stencils vectorize is gimp_graded to the bit, on
// every branch: outside the support, left cell, right cell, beyond, and exactly on the kinks.
TEST(Shape, graded_select_form_equals_graded_form_bitwise) {
  const double widths[][2] = {{1.0, 1.0}, {1.0, 2.0}, {2.0, 1.0}, {0.5, 2.0}, {3e-5, 6e-5}};
  for (const auto& w : widths) {
    const double hL = w[0], hR = w[1];
    for (const double lp : {0.25 * std::min(hL, hR), 0.5 * std::min(hL, hR), 0.1 * hL}) {
      std::vector<double> us;
      for (int i = -400; i <= 400; ++i) us.push_back(double(i) / 400.0 * 1.6 * std::max(hL, hR));
      for (const double kink : {-hL, 0.0, hR}) us.insert(us.end(), {kink - lp, kink + lp, kink});
      for (const double u : us) {
        const Weight1D a = gimp_graded(u, hL, hR, lp);
        double s = -1.0, ds = -1.0;
        gimp_graded_select(u, hL, hR, lp, s, ds);
        EXPECT_EQ(a.s, s) << "u " << u << " hL " << hL << " hR " << hR << " lp " << lp;
        EXPECT_EQ(a.ds, ds) << "u " << u << " hL " << hL << " hR " << hR << " lp " << lp;
      }
    }
  }
}
