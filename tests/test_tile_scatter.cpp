// Tests of the particle -> grid scatter (theory E4: solver/transfer.cpp particles_to_grid, which
// sums through per-strip tiles, solver/strip_tile.hpp, and batched SIMD stencils,
// solver/stencil_batch.hpp) against a naive scatter written here: for every particle and every
// node, the GIMP weights of shape/gimp.hpp (gimp_uniform on a uniform axis, gimp_graded on a
// graded one, the closed forms, not the solver's branch-free stencils) and their products,
// added straight into whole-grid arrays per field. Why: the tiles, the runs of particles that
// share a stencil, the field windows and the two-colour strip loop are each a place where a
// contribution can land on the wrong node or field, be lost at a strip's edge or be added
// twice, and the solver's conservation tests (sums over all nodes) would not see a
// contribution moved to a neighbour.
// The particles are put at random positions (each field over half the domain's width, random
// half-widths up to half the finest cell, masses, velocities, stresses and materials), on a
// uniform grid and on a graded one refined in x and y, with three fields, with the default
// strips and narrow ones (5 cells: many strips, tile edges everywhere).
// At every node of every field, mass, momentum and internal force agree with the naive sum to
// 1e-12 of the size of what reaches the node (sum over its particles of |m|, |m v|, or
// |V sigma| / h_min: the round-off of a weight or gradient is relative to 1 or 1/h, not to
// a tail weight), and nodes outside a field's window get nothing in the naive sum either.
// The results are bitwise the same with 1 and 2 OpenMP threads (the summation order is set by
// the sort, ScatterPlan), and the several-States form equals one call per State bit for bit.
#include <gtest/gtest.h>
#include <omp.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "shape/gimp.hpp"
#include "solver/field_windows.hpp"
#include "solver/state.hpp"
#include "solver/transfer.hpp"

using namespace rupture;

namespace {

// Three bodies (three fields) of two materials on [0, 80] x [0, 12] mm, 1 mm cells (84 x 16
// cells with the ghosts: three strips of 32 columns). `grid_extra`: lines for [grid].
std::string three_bodies(const std::string& grid_extra) {
  return fmt::format(R"(
title = "tile scatter"
[materials.homalite]
youngs_modulus = 5.2e9
poisson_ratio = 0.34
density = 1246.0
[materials.steel]
youngs_modulus = 200e9
poisson_ratio = 0.29
density = 7850.0
[grid]
min = [0.0, 0.0]
max = [0.08, 0.012]
cell_size = {}
particles_per_cell = 2
margin = 0.0
{}
[bodies.a]
material = "homalite"
min = [0.0, 0.0]
max = [0.03, 0.012]
[bodies.b]
material = "steel"
min = [0.036, 0.0]
max = [0.06, 0.012]
[bodies.c]
material = "homalite"
min = [0.064, 0.0]
max = [0.08, 0.012]
[time]
end = 1e-6
)",
                     grid_extra.empty() ? "1e-3" : "0.5e-3", grid_extra);
}

const std::string kUniform = three_bodies("");
// Finest 0.5 mm inside the box, 2 mm elsewhere (transitions 2 -> 1 -> 0.5 mm along x and y).
const std::string kGraded = three_bodies(R"(coarse_cell_size = 2e-3
refinement = "graded"
[grid.refine.middle]
min = [0.024, 0.004]
max = [0.048, 0.008]
level = 2)");

// Randomizes every particle: position anywhere in its field's part of the domain, half-widths in
// [0.1, 0.5] x the finest cell (the GIMP contract holds on any cell), mass, volume,
// velocity, stress, field and material.
void scramble(State& s, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Particles& P = s.particles;
  const double hmin = std::min(s.grid.x.min_width(), s.grid.y.min_width());
  const int fields = s.fields.num_fields;
  for (std::size_t p = 0; p < P.size(); ++p) {
    // Field f over its own part of the domain along x (they overlap), so its window is not
    // the whole grid: [0, 0.5], [0.25, 0.75], [0.5, 1] of the width for three fields.
    P.field[p] = std::uint8_t(std::min(fields - 1, int(u(rng) * fields)));
    const double lo = 0.25 * P.field[p], width = s.grid.domain_max[0] - s.grid.domain_min[0];
    P.x[p] = s.grid.domain_min[0] + (lo + 0.5 * u(rng)) * width;
    P.y[p] = s.grid.domain_min[1] + u(rng) * (s.grid.domain_max[1] - s.grid.domain_min[1]);
    P.half_x[p] = (0.1 + 0.4 * u(rng)) * hmin;
    P.half_y[p] = (0.1 + 0.4 * u(rng)) * hmin;
    P.mass[p] = (0.5 + u(rng)) * 1e-3;
    P.volume0[p] = (0.5 + u(rng)) * 1e-6;
    P.vx[p] = 20.0 * (u(rng) - 0.5);
    P.vy[p] = 20.0 * (u(rng) - 0.5);
    P.sxx[p] = 1e7 * (u(rng) - 0.5);
    P.syy[p] = 1e7 * (u(rng) - 0.5);
    P.sxy[p] = 1e7 * (u(rng) - 0.5);
    P.material[p] = std::uint8_t(u(rng) < 0.5 ? 0 : 1);
  }
}

// The state made from `toml`, scrambled, sorted (with strips of `strip_cells`) and with its
// windows fitted, as step() has it before the scatter.
State prepared(const std::string& toml, unsigned seed, int strip_cells) {
  State s = make_state(parse_case(toml));
  scramble(s, seed);
  s.plan.strip_cells = strip_cells;
  s.plan.valid = false;
  build_scatter_plan(s);
  fit_field_windows(s);
  return s;
}

// 1 / (c11 + c12) of a plane-strain isotropic material from E and nu (tr eps per unit
// sxx + syy): c11 = lambda + 2 mu, c12 = lambda.
double trace_per_stress(double E, double nu) {
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = E / (2.0 * (1.0 + nu));
  return 1.0 / (2.0 * lambda + 2.0 * mu);
}

// One axis: weight and derivative of every node for a particle at x with half-width lp, from
// the closed forms of shape/gimp.hpp (0 where the hat's support misses the box).
void axis_weights(const Axis& a, double x, double lp, std::vector<double>& w, std::vector<double>& dw) {
  w.assign(std::size_t(a.nodes()), 0.0);
  dw.assign(std::size_t(a.nodes()), 0.0);
  for (int i = 1; i < a.cells; ++i) {  // the particles never reach the outermost ghost nodes
    const Weight1D g = a.graded() ? gimp_graded(x - a.node(i), a.width(i - 1), a.width(i), lp)
                                  : gimp_uniform(x - a.node(i), a.h, lp);
    w[std::size_t(i)] = g.s;
    dw[std::size_t(i)] = g.ds;
  }
}

// Whole-grid arrays per field (f * nodes + node) and the size of what reaches each node.
struct Naive {
  std::vector<double> v[5];      // mass, mom_x, mom_y, force_x, force_y
  std::vector<double> scale[5];  // sum of |m|, |m vx|, |m vy|, |V sigma| / h_min
};

Naive naive_scatter(const State& s) {
  const Particles& P = s.particles;
  const Grid& g = s.grid;
  const std::size_t nx = std::size_t(g.nodes_x()), nodes = g.num_nodes();
  const std::size_t size = std::size_t(s.fields.num_fields) * nodes;
  Naive out;
  for (int a = 0; a < 5; ++a) out.v[a].assign(size, 0.0), out.scale[a].assign(size, 0.0);
  const double tr[2] = {trace_per_stress(5.2e9, 0.34), trace_per_stress(200e9, 0.29)};
  const double inv_h = 1.0 / std::min(g.x.min_width(), g.y.min_width());
  std::vector<double> wx, dwx, wy, dwy;
  for (std::size_t p = 0; p < P.size(); ++p) {
    axis_weights(g.x, P.x[p], P.half_x[p], wx, dwx);
    axis_weights(g.y, P.y[p], P.half_y[p], wy, dwy);
    const double m = P.mass[p];
    // theory E4: f_i = -sum_p V_p sigma_p . grad S_ip, V_p the current area V0 (1 + tr eps).
    const double V = P.volume0[p] * (1.0 + (P.sxx[p] + P.syy[p]) * tr[P.material[p]]);
    const double fxx = -V * P.sxx[p], fyy = -V * P.syy[p], fxy = -V * P.sxy[p];
    const double q[3] = {m, m * P.vx[p], m * P.vy[p]};
    const double fscale = (std::fabs(fxx) + std::fabs(fyy) + 2.0 * std::fabs(fxy)) * inv_h;
    for (std::size_t j = 0; j < wy.size(); ++j) {
      if (wy[j] == 0.0 && dwy[j] == 0.0) continue;
      for (std::size_t i = 0; i < nx; ++i) {
        if (wx[i] == 0.0 && dwx[i] == 0.0) continue;
        const std::size_t e = std::size_t(P.field[p]) * nodes + j * nx + i;
        const double S = wx[i] * wy[j], gx = dwx[i] * wy[j], gy = wx[i] * dwy[j];
        for (int a = 0; a < 3; ++a) {
          out.v[a][e] += S * q[a];
          out.scale[a][e] += std::fabs(q[a]);
        }
        out.v[3][e] += fxx * gx + fxy * gy;
        out.v[4][e] += fxy * gx + fyy * gy;
        out.scale[3][e] += fscale;
        out.scale[4][e] += fscale;
      }
    }
  }
  return out;
}

const NodalArray kArrays[5] = {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y, &GridFields::force_x,
                               &GridFields::force_y};
const char* const kNames[5] = {"mass", "mom_x", "mom_y", "force_x", "force_y"};

// The library's arrays (windows) against the naive sum at every node of every field, arrays
// [first, last).
void expect_matches_naive(const State& s, const Naive& n, const std::string& what, int first = 0, int last = 5) {
  const GridFields& G = s.fields;
  const std::size_t nx = std::size_t(s.grid.nodes_x()), nodes = s.grid.num_nodes();
  long compared = 0, outside = 0, bad = 0;
  std::size_t nonzero[5] = {};
  for (int f = 0; f < G.num_fields; ++f)
    for (std::size_t node = 0; node < nodes; ++node) {
      const int i = int(node % nx), j = int(node / nx);
      const std::size_t e = std::size_t(f) * nodes + node;
      for (int a = first; a < last; ++a) {
        if (n.v[a][e] != 0.0) ++nonzero[a];
        if (!G.holds(f, i, j)) {
          ++outside;
          if (n.scale[a][e] != 0.0 && bad++ < 10)
            ADD_FAILURE() << what << ": field " << f << " node (" << i << ", " << j << ") " << kNames[a]
                          << " is reached by particles but lies outside the field's window";
          continue;
        }
        const double got = (G.*kArrays[a])[G.index(f, i, j)];
        ++compared;
        if (!(std::fabs(got - n.v[a][e]) <= 1e-12 * n.scale[a][e]) && bad++ < 10)
          ADD_FAILURE() << what << ": field " << f << " node (" << i << ", " << j << ") " << kNames[a] << " = "
                        << got << ", naive " << n.v[a][e] << " (scale " << n.scale[a][e] << ")";
      }
    }
  EXPECT_EQ(bad, 0) << what;
  EXPECT_GT(compared, 0) << what;
  EXPECT_GT(outside, 0) << what << ": every window is the whole grid, the windows are not exercised";
  for (int a = first; a < last; ++a) EXPECT_GT(nonzero[a], 100u) << what << ": " << kNames[a];
}

bool bitwise_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

struct Threads {  // restores the thread count a test changed
  int saved = omp_get_max_threads();
  ~Threads() { omp_set_num_threads(saved); }
};

}  // namespace

TEST(TileScatter, the_stiffness_the_naive_force_uses_is_the_solvers) {
  // The naive force recomputes tr eps per stress from E and nu; a mismatch here would make
  // the force comparisons below fail for the wrong reason.
  const State s = make_state(parse_case(kUniform));
  ASSERT_EQ(s.stiffness.size(), 2u);
  EXPECT_NEAR(s.stiffness[0].tr_per_stress, trace_per_stress(5.2e9, 0.34), 1e-15 * s.stiffness[0].tr_per_stress);
  EXPECT_NEAR(s.stiffness[1].tr_per_stress, trace_per_stress(200e9, 0.29), 1e-15 * s.stiffness[1].tr_per_stress);
  EXPECT_EQ(s.fields.num_fields, 3);
  EXPECT_FALSE(s.grid.graded());
  const State g = make_state(parse_case(kGraded));
  EXPECT_TRUE(g.grid.x.graded() && g.grid.y.graded());
  EXPECT_NEAR(g.grid.x.min_width(), 0.5e-3, 1e-12 * 0.5e-3);
}

TEST(TileScatter, uniform_grid_matches_the_naive_scatter) {
  for (const int strip : {32, 5}) {
    State s = prepared(kUniform, 11, strip);
    ASSERT_GE(s.plan.num_strips, 3);
    particles_to_grid(s, true);
    expect_matches_naive(s, naive_scatter(s), fmt::format("uniform, strips of {}", strip));
  }
}

TEST(TileScatter, graded_grid_matches_the_naive_scatter) {
  for (const int strip : {32, 5}) {
    State s = prepared(kGraded, 12, strip);
    particles_to_grid(s, true);
    expect_matches_naive(s, naive_scatter(s), fmt::format("graded, strips of {}", strip));
  }
}

TEST(TileScatter, without_force_and_force_only_match_the_naive_scatter) {
  for (const std::string* toml : {&kUniform, &kGraded}) {
    State s = prepared(*toml, 13, 32);
    const Naive n = naive_scatter(s);
    particles_to_grid(s, false);
    expect_matches_naive(s, n, "mass and momentum only", 0, 3);
    for (const double f : s.fields.force_x) ASSERT_EQ(f, 0.0);  // zeroed, not left from before
    particles_to_grid_force(s);  // USF: the force alone, straight into the grid arrays
    expect_matches_naive(s, n, "force only", 3, 5);
  }
}

TEST(TileScatter, the_same_bits_with_one_and_two_threads) {
  Threads restore;
  for (const std::string* toml : {&kUniform, &kGraded})
    for (const int strip : {32, 5}) {
      const State base = prepared(*toml, 14, strip);
      ASSERT_GE(base.plan.num_strips, 3);  // both colours have strips to share out
      State one = base, two = base;
      omp_set_num_threads(1);
      particles_to_grid(one, true);
      omp_set_num_threads(2);
      particles_to_grid(two, true);
      for (int a = 0; a < 5; ++a)
        EXPECT_TRUE(bitwise_equal(one.fields.*kArrays[a], two.fields.*kArrays[a]))
            << kNames[a] << ", strips of " << strip << (toml == &kGraded ? ", graded" : ", uniform");
      // And a second call gives the same bits again (the tiles and buffers keep no state).
      particles_to_grid(two, true);
      EXPECT_TRUE(bitwise_equal(one.fields.mass, two.fields.mass));
      EXPECT_TRUE(bitwise_equal(one.fields.force_y, two.fields.force_y));
    }
}

TEST(TileScatter, several_states_at_once_equal_one_call_each) {
  Threads restore;
  omp_set_num_threads(2);
  State a = prepared(kUniform, 15, 32), b = prepared(kGraded, 16, 5);
  State a1 = a, b1 = b;
  particles_to_grid(a1, true);
  particles_to_grid(b1, true);
  State* both[2] = {&a, &b};
  particles_to_grid(both, 2, true);
  for (int k = 0; k < 5; ++k) {
    EXPECT_TRUE(bitwise_equal(a.fields.*kArrays[k], a1.fields.*kArrays[k])) << kNames[k];
    EXPECT_TRUE(bitwise_equal(b.fields.*kArrays[k], b1.fields.*kArrays[k])) << kNames[k];
  }
}
