// Tests of the interface loop (theory E7-E9: solver/cohesive_step.cpp evaluate_interface and
// add_cohesive_forces, with the laws of cohesive/) on the smallest interface there is: one
// segment (two nodes) between two bodies, with a jump prescribed on its faces. Why: the
// Gauss-point loop (shape functions, weights, the segment frame) and the spread of each node's
// force onto its two fields are where a sign, a factor 2 or a swapped field hides; the
// verification runs (tests/verification/test_cohesive.cpp) see those only through a whole
// dynamic run.
// Checked against values worked out by hand from the laws' formulas (docs/cohesive_laws.md),
// not through the laws' own functions:
//   - a uniform jump: each node's force is -T(jump) x L/2 (the tributary length of a node of
//     a one-segment line), normal opening -> force along -n = -y, tangential slip -> along
//     -t = -x, nothing in the other direction; for Xu-Needleman (Tn = e sigma_max x e^-x,
//     Tt = sqrt(2e) tau_max x e^-x^2 with the default delta_t) and the bilinear law in its
//     elastic part (Tn = sigma_max x / lambda0) and softening part (sigma_max (1 - x) /
//     (1 - lambda0));
//   - a linear jump on the bilinear law's elastic part (T = k jump): the consistent nodal
//     forces of a linear element, F_a = -k L (j_a / 3 + j_b / 6), F_b = -k L (j_a / 6 + j_b / 3);
//   - on the grid: the upper field receives each node's force, the lower one minus it, on the
//     nodes within one cell of the node only (the two nodes' stencils are disjoint); the two
//     fields' sums are equal and opposite and add to zero.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/field_windows.hpp"
#include "solver/state.hpp"
#include "solver/transfer.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

constexpr double kH = 1e-3;                      // cell size, m
constexpr double kStart = 0.002, kEnd = 0.006;   // the interface: one segment, 4 cells long
constexpr double kLength = kEnd - kStart;        // m
const double kE = std::exp(1.0);

// Upper body [0, 8] x [0, 4] mm over lower [0, 8] x [-4, 0] mm, joined along y = 0 from x =
// 2 to 6 mm by `segments` segments (one by default) of `law_lines`; `more`: further input.
State two_bodies(const std::string& law_lines, int segments = 1, const std::string& more = "") {
  return make_state(parse_case(fmt::format(R"({}
[grid]
min = [0.0, -0.004]
max = [0.008, 0.004]
cell_size = {}
particles_per_cell = 2
margin = 0.0
[bodies.upper]
material = "homalite"
min = [0.0, 0.0]
max = [0.008, 0.004]
[bodies.lower]
material = "homalite"
min = [0.0, -0.004]
max = [0.008, 0.0]
[interface.w]
upper_body = "upper"
lower_body = "lower"
y = 0.0
start = {}
end = {}
segments = {}
{}
{}
[time]
end = 1e-6
)",
                                           test::kHomaliteToml, kH, kStart, kEnd, segments, law_lines, more)));
}

const std::string kXuNeedlemanLaw = "sigma_max = 24e6\ntau_max = 18e6\ndelta_n = 0.4e-6";
const std::string kBilinearLaw = "law = \"bilinear\"\nsigma_max = 24e6\ntau_max = 18e6\ndelta_nc = 2e-6\n"
                                 "delta_tc = 3e-6\nlambda0 = 0.1";

// Gives the interface's faces the jumps (jump_x, jump_y) at nodes 0 and 1 (half on each face,
// opposite), scatters the particles' mass, evaluates the interface and spreads its forces onto
// zeroed grid forces: the step's cohesive phases, with the faces put where the test wants them.
void load(State& s, const double jx[2], const double jy[2]) {
  CohesiveInterface& c = s.interfaces.at(0);
  for (std::size_t k = 0; k < 2; ++k) {
    c.ux_up[k] = 0.5 * jx[k], c.ux_lo[k] = -0.5 * jx[k];
    c.uy_up[k] = 0.5 * jy[k], c.uy_lo[k] = -0.5 * jy[k];
  }
  build_scatter_plan(s);
  fit_field_windows(s);
  particles_to_grid(s, false);  // masses for the face stencils
  update_face_stencils(s);
  evaluate_interface(c, 1e-9, 0.0);
  std::fill(s.fields.force_x.begin(), s.fields.force_x.end(), 0.0);
  std::fill(s.fields.force_y.begin(), s.fields.force_y.end(), 0.0);
  add_cohesive_forces(s);
}

void load_uniform(State& s, double jx, double jy) {
  const double x[2] = {jx, jx}, y[2] = {jy, jy};
  load(s, x, y);
}

// The nodal forces (per unit thickness, N/m) as the grid holds them: per field, the sum over
// the grid nodes within one cell of interface node k (columns i-1 .. i+1 of its node column,
// rows -1 .. +1 of y = 0), and whether any force lies elsewhere.
struct GridForces {
  double fx[2][2] = {}, fy[2][2] = {};  // [field: upper, lower][interface node]
  double total_x[2] = {}, total_y[2] = {}, scale = 0.0;
  bool elsewhere = false;
};

GridForces grid_forces(const State& s) {
  const GridFields& G = s.fields;
  const CohesiveInterface& c = s.interfaces.at(0);
  GridForces out;
  const int fields[2] = {c.spec.upper_field, c.spec.lower_field};
  for (int which = 0; which < 2; ++which) {
    const int f = fields[which];
    for (int j = 0; j < s.grid.nodes_y(); ++j)
      for (int i = 0; i < s.grid.nodes_x(); ++i) {
        if (!G.holds(f, i, j)) continue;
        const std::size_t e = G.index(f, i, j);
        const double fx = G.force_x[e], fy = G.force_y[e];
        if (fx == 0.0 && fy == 0.0) continue;
        out.total_x[which] += fx, out.total_y[which] += fy;
        out.scale += std::fabs(fx) + std::fabs(fy);
        bool near = false;
        for (int k = 0; k < 2; ++k) {
          const double dx = std::fabs(s.grid.x.node(i) - c.x0[std::size_t(k)]);
          const double dy = std::fabs(s.grid.y.node(j) - c.y0[std::size_t(k)]);
          if (dx <= 1.0001 * kH && dy <= 1.0001 * kH) {
            out.fx[which][k] += fx, out.fy[which][k] += fy;
            near = true;
          }
        }
        if (!near) out.elsewhere = true;
      }
  }
  return out;
}

// Node forces fx_node, fy_node against (want_x, want_y) per node, and the grid's version of
// them: the upper field gets them, the lower minus them, nothing elsewhere, sum zero.
void expect_forces(const State& s, const double want_x[2], const double want_y[2], const std::string& what) {
  const CohesiveInterface& c = s.interfaces.at(0);
  ASSERT_EQ(c.num_nodes(), 2u) << what;
  double size = 0.0;
  for (int k = 0; k < 2; ++k) size = std::max({size, std::fabs(want_x[k]), std::fabs(want_y[k])});
  ASSERT_GT(size, 0.0) << what;
  const double tol = 1e-12 * size;
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(c.fx_node[k], want_x[k], tol) << what << ", node " << k;
    EXPECT_NEAR(c.fy_node[k], want_y[k], tol) << what << ", node " << k;
  }
  const GridForces g = grid_forces(s);
  EXPECT_FALSE(g.elsewhere) << what << ": force on a grid node more than a cell from both interface nodes";
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(g.fx[0][k], want_x[k], tol) << what << ": upper field near node " << k;
    EXPECT_NEAR(g.fy[0][k], want_y[k], tol) << what << ": upper field near node " << k;
    EXPECT_NEAR(g.fx[1][k], -want_x[k], tol) << what << ": lower field near node " << k;
    EXPECT_NEAR(g.fy[1][k], -want_y[k], tol) << what << ": lower field near node " << k;
  }
  EXPECT_NEAR(g.total_x[0], want_x[0] + want_x[1], 2 * tol) << what;
  EXPECT_NEAR(g.total_y[0], want_y[0] + want_y[1], 2 * tol) << what;
  EXPECT_NEAR(g.total_x[0] + g.total_x[1], 0.0, 1e-14 * g.scale) << what << ": fields' sums not opposite";
  EXPECT_NEAR(g.total_y[0] + g.total_y[1], 0.0, 1e-14 * g.scale) << what << ": fields' sums not opposite";
}

}  // namespace

TEST(InterfaceForces, the_interface_is_one_segment_of_two_nodes_on_grid_nodes) {
  const State s = two_bodies(kXuNeedlemanLaw);
  ASSERT_EQ(s.interfaces.size(), 1u);
  const CohesiveInterface& c = s.interfaces[0];
  ASSERT_EQ(c.num_nodes(), 2u);
  ASSERT_EQ(c.num_segments(), 1u);
  EXPECT_DOUBLE_EQ(c.x0[0], kStart);
  EXPECT_DOUBLE_EQ(c.x0[1], kEnd);
  EXPECT_DOUBLE_EQ(c.seg_length[0], kLength);
  EXPECT_EQ(c.seg_nx[0], 0.0);  // a line drawn in +x: n = +y, t = +x
  EXPECT_EQ(c.seg_ny[0], 1.0);
  EXPECT_NE(c.spec.upper_field, c.spec.lower_field);
}

TEST(InterfaceForces, xu_needleman_normal_opening) {
  State s = two_bodies(kXuNeedlemanLaw);
  const double delta_n = 0.4e-6, sigma_max = 24e6;
  for (const double x : {0.3, 1.0, 2.5}) {  // below, at and past the peak (Tn = sigma_max at x = 1)
    State t = s;
    load_uniform(t, 0.0, x * delta_n);
    const double Tn = kE * sigma_max * x * std::exp(-x);  // theory E7 at Dt = 0
    const double want_x[2] = {0.0, 0.0}, want_y[2] = {-Tn * kLength / 2, -Tn * kLength / 2};
    expect_forces(t, want_x, want_y, fmt::format("xu_needleman, Dn = {} delta_n", x));
  }
}

TEST(InterfaceForces, xu_needleman_tangential_slip) {
  State s = two_bodies(kXuNeedlemanLaw);
  // delta_t from q = 1: q e sigma_max delta_n / (sqrt(e/2) tau_max) (docs/input.md).
  const double tau_max = 18e6, delta_t = kE * 24e6 * 0.4e-6 / (std::sqrt(kE / 2) * tau_max);
  ASSERT_NEAR(std::get<XuNeedleman>(s.interfaces[0].spec.law).delta_t, delta_t, 1e-12 * delta_t);
  for (const double x : {0.2, 1.0 / std::sqrt(2.0), 1.5}) {  // the peak, tau_max, at 1/sqrt 2
    for (const double sign : {1.0, -1.0}) {
      State t = s;
      load_uniform(t, sign * x * delta_t, 0.0);
      const double Tt = sign * std::sqrt(2.0 * kE) * tau_max * x * std::exp(-x * x);  // E7 at Dn = 0
      const double want_x[2] = {-Tt * kLength / 2, -Tt * kLength / 2}, want_y[2] = {0.0, 0.0};
      expect_forces(t, want_x, want_y, fmt::format("xu_needleman, Dt = {} delta_t", sign * x));
    }
  }
}

TEST(InterfaceForces, bilinear_normal_opening_elastic_and_softening) {
  State s = two_bodies(kBilinearLaw);
  const double sigma_max = 24e6, delta_nc = 2e-6, lambda0 = 0.1;
  for (const double x : {0.05, 0.1, 0.4, 0.9}) {  // lambda = Dn / delta_nc
    State t = s;
    load_uniform(t, 0.0, x * delta_nc);
    const double Tn = x <= lambda0 ? sigma_max * x / lambda0 : sigma_max * (1.0 - x) / (1.0 - lambda0);
    const double want_x[2] = {0.0, 0.0}, want_y[2] = {-Tn * kLength / 2, -Tn * kLength / 2};
    expect_forces(t, want_x, want_y, fmt::format("bilinear, Dn = {} delta_nc", x));
  }
}

TEST(InterfaceForces, bilinear_tangential_slip_elastic_and_softening) {
  State s = two_bodies(kBilinearLaw);
  const double tau_max = 18e6, delta_tc = 3e-6, lambda0 = 0.1;
  for (const double x : {0.05, 0.5, -0.5}) {  // lambda = |Dt| / delta_tc
    State t = s;
    load_uniform(t, x * delta_tc, 0.0);
    const double a = std::fabs(x);
    const double Tt = std::copysign(a <= lambda0 ? tau_max * a / lambda0 : tau_max * (1.0 - a) / (1.0 - lambda0), x);
    const double want_x[2] = {-Tt * kLength / 2, -Tt * kLength / 2}, want_y[2] = {0.0, 0.0};
    expect_forces(t, want_x, want_y, fmt::format("bilinear, Dt = {} delta_tc", x));
  }
}

TEST(InterfaceForces, linear_jump_gives_the_consistent_nodal_forces) {
  // The bilinear law's elastic part is linear, T = k Delta with k = sigma_max / (lambda0
  // delta_nc) (normal) and tau_max / (lambda0 delta_tc) (tangential), and the 4-point Gauss
  // rule integrates N_a k (N_a j_a + N_b j_b) exactly: F_a = -k L (j_a/3 + j_b/6).
  State s = two_bodies(kBilinearLaw);
  const double kn = 24e6 / (0.1 * 2e-6), kt = 18e6 / (0.1 * 3e-6);
  const double jn[2] = {0.02 * 2e-6, 0.08 * 2e-6};   // both in the elastic part (lambda < 0.1)
  const double jt[2] = {-0.03 * 3e-6, 0.05 * 3e-6};
  {
    State t = s;
    const double zero[2] = {0.0, 0.0};
    load(t, zero, jn);
    const double want_y[2] = {-kn * kLength * (jn[0] / 3 + jn[1] / 6), -kn * kLength * (jn[0] / 6 + jn[1] / 3)};
    expect_forces(t, zero, want_y, "bilinear, linear normal jump");
  }
  {
    State t = s;
    const double zero[2] = {0.0, 0.0};
    load(t, jt, zero);
    const double want_x[2] = {-kt * kLength * (jt[0] / 3 + jt[1] / 6), -kt * kLength * (jt[0] / 6 + jt[1] / 3)};
    expect_forces(t, want_x, zero, "bilinear, linear tangential jump");
  }
}

// Contact on light faces (docs/fracture.md): a pre-crack pressed shut (jump -1e-8 m) with its
// faces of normal mass takes the full penalty, Tn = kn Dn, each node -Tn L / 2; with its upper
// field's nodal masses scaled down (a face hanging on nodes its field barely reaches) the penalty
// is scaled by the face's mass over light_face_mass (a quarter of rho h^2 / 2), so each node's
// force and stiffness (the step bound's term) drop by that ratio; a face of normal mass is above
// the threshold.
TEST(InterfaceForces, a_light_face_meets_the_contact_penalty_in_proportion_to_its_mass) {
  const double kn = 1e14;
  State s = two_bodies(fmt::format("law = \"contact\"\ncontact = true\ncontact_stiffness = {}", kn));
  CohesiveInterface& c0 = s.interfaces.at(0);
  EXPECT_NEAR(c0.light_face_mass, 0.25 * 0.5 * 1246.0 * kH * kH, 1e-15) << "a quarter of rho h^2 / 2";
  const double dn = -1e-8;
  auto pressed = [&](double mass_factor, double& force, double& stiffness, double& face_mass) {
    State t = s;
    CohesiveInterface& c = t.interfaces.at(0);
    for (std::size_t k = 0; k < 2; ++k) c.uy_up[k] = 0.5 * dn, c.uy_lo[k] = -0.5 * dn;
    build_scatter_plan(t);
    fit_field_windows(t);
    particles_to_grid(t, false);
    const int up = c.spec.upper_field;
    for (int j = 0; j < t.grid.nodes_y(); ++j)
      for (int i = 0; i < t.grid.nodes_x(); ++i)
        if (t.fields.holds(up, i, j)) t.fields.mass[t.fields.index(up, i, j)] *= mass_factor;
    update_face_stencils(t);
    evaluate_interface(c, 1e-9, 0.0);
    force = c.fy_node[0], stiffness = c.stiffness_node[0];
    face_mass = std::min(c.face_up[0].mass, c.face_lo[0].mass);
  };
  double f1, k1, m1, f2, k2, m2;
  pressed(1.0, f1, k1, m1);
  EXPECT_GT(m1, c0.light_face_mass) << "a face of normal mass is above the threshold";
  EXPECT_NEAR(f1, -kn * dn * 0.5 * kLength, 1e-12 * std::fabs(f1)) << "full penalty";
  pressed(1e-3, f2, k2, m2);
  ASSERT_LT(m2, c0.light_face_mass);
  const double ratio = m2 / c0.light_face_mass;
  EXPECT_NEAR(f2, ratio * f1, 1e-12 * std::fabs(f1)) << "force scaled by M / light_face_mass";
  EXPECT_NEAR(k2, ratio * k1, 1e-12 * k1) << "stiffness (the step bound's term) scaled alike";
  // The step bound's term 2 k w / M of the light face is at most that of a face at the threshold.
  EXPECT_LE(2.0 * k2 / m2, 2.0 * k1 / c0.light_face_mass * (1 + 1e-12));
  std::printf("light face: M = %.3g kg/m (normal %.3g, threshold %.3g), force %.4g -> %.4g N/m\n", m2, m1,
              c0.light_face_mass, f1, f2);
}

// A face that changes field along the line (a T-junction, cohesive/interface.hpp FaceFields): a
// crack drawn in the upper body from the interface's middle node up to 3 mm splits that body in
// two, and the interface's upper face lies on both parts. Under a uniform opening (Xu-Needleman,
// 2 segments) the end nodes' forces go to their own part's field and the middle node's, half to
// each; the lower field gets minus the sum, so the three fields' forces add to zero; the two
// upper parts, mirror images about the crack, get equal totals.
TEST(InterfaceForces, a_face_on_a_t_junction_loads_both_parts_by_their_shares) {
  State s = two_bodies(kXuNeedlemanLaw, 2, R"([interface.crack]
body = "upper"
points = [[0.004, 0.0], [0.004, 0.003]]
segments = 3
law = "contact")");
  CohesiveInterface& c = s.interfaces.at(0);
  ASSERT_EQ(c.num_nodes(), 3u);
  const int left = c.faces_up(0).a, right = c.faces_up(2).a, lower = c.spec.lower_field;
  ASSERT_NE(left, right);
  EXPECT_EQ(c.faces_up(1).a, left);
  EXPECT_EQ(c.faces_up(1).b, right);
  EXPECT_NEAR(c.faces_up(1).share, 0.5, 1e-12);
  const double dn = 0.5 * 0.4e-6;  // a uniform opening of half delta_n
  for (std::size_t k = 0; k < 3; ++k) c.uy_up[k] = 0.5 * dn, c.uy_lo[k] = -0.5 * dn;
  build_scatter_plan(s);
  fit_field_windows(s);
  particles_to_grid(s, false);
  update_face_stencils(s);
  for (std::size_t k = 0; k < 3; ++k) {
    const FaceStencil& f = c.face_up[k];
    double on[2] = {0.0, 0.0};  // weight on the left and the right part's nodes
    for (int q = 0; q < FaceStencil::kSlots; ++q) on[q < 4 ? 0 : 1] += f.c[q];
    EXPECT_NEAR(on[0] + on[1], 1.0, 1e-14) << k;
    EXPECT_NEAR(on[1], k == 1 ? 0.5 : 0.0, 1e-12) << k;
  }
  evaluate_interface(c, 1e-9, 0.0);
  std::fill(s.fields.force_x.begin(), s.fields.force_x.end(), 0.0);
  std::fill(s.fields.force_y.begin(), s.fields.force_y.end(), 0.0);
  add_cohesive_forces(s);
  const GridFields& G = s.fields;
  auto total = [&](int f) {
    double fy = 0.0;
    for (int j = 0; j < s.grid.nodes_y(); ++j)
      for (int i = 0; i < s.grid.nodes_x(); ++i)
        if (G.holds(f, i, j)) fy += G.force_y[G.index(f, i, j)];
    return fy;
  };
  const double fl = total(left), fr = total(right), fo = total(lower);
  EXPECT_LT(c.fy_node[1], 0.0);  // an opening: the upper face pulled back down
  EXPECT_NEAR(fl, c.fy_node[0] + 0.5 * c.fy_node[1], 1e-12 * std::fabs(c.fy_node[1]));
  EXPECT_NEAR(fr, c.fy_node[2] + 0.5 * c.fy_node[1], 1e-12 * std::fabs(c.fy_node[1]));
  EXPECT_NEAR(fl, fr, 1e-12 * std::fabs(fl));
  EXPECT_NEAR(fl + fr + fo, 0.0, 1e-12 * std::fabs(fo));
}
