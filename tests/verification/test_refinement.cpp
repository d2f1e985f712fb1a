// Verification of the graded (refined) grid, theory §2 (E3) and §5: weights across every kind
// of cell boundary, a plane wave crossing coarse -> fine -> coarse transitions (reflection,
// arrival time) and the energy balance of an impact through refined regions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "solver/energy.hpp"
#include "wave_helpers.hpp"

using namespace rupture;

namespace {

// Hat function of node i on a graded axis, integrated over the particle box by the midpoint
// rule: the definition of the GIMP weight (theory E3), independent of the closed form.
double quadrature_weight(const Axis& a, int i, double xp, double lp) {
  const int n = 4000;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double x = xp - lp + (k + 0.5) * (2.0 * lp / n);
    const double xi = a.node(i);
    if (x < xi && i > 0) sum += std::max(0.0, 1.0 - (xi - x) / (xi - a.node(i - 1)));
    if (x >= xi && i < a.cells) sum += std::max(0.0, 1.0 - (x - xi) / (a.node(i + 1) - xi));
  }
  return sum / n;
}

Grid two_level_boxes() {
  const double min[2] = {0.0, 0.0}, max[2] = {0.04, 0.01};
  const std::vector<RefineBox> boxes = {{{0.01, 0.002}, {0.03, 0.008}, 0.5e-3},
                                        {{0.015, 0.004}, {0.025, 0.006}, 0.25e-3}};
  return make_graded_grid(min, max, 2e-3, 0.25e-3, boxes);
}

}  // namespace

TEST(Refinement, graded_axes_are_aligned_powers_of_two_graded_by_two) {
  const Grid g = two_level_boxes();
  for (int d = 0; d < 2; ++d) {
    const Axis* a = d == 0 ? &g.x : &g.y;
    EXPECT_TRUE(a->graded());
    for (int c = g.ghost; c < a->cells - g.ghost; ++c) {
      const double w = a->width(c) / a->h;
      const long units = std::lround(w);
      EXPECT_NEAR(w, double(units), 1e-9);
      EXPECT_EQ(units & (units - 1), 0) << "cell " << c << " is " << w << " finest cells";
      const double offset = std::fmod((a->node(c) - g.domain_min[d]) / a->h + 1e-6, double(units));
      EXPECT_LT(offset, 1e-5) << "cell " << c << " not aligned to its own size from grid.min";
      if (c > 0) {
        const double r = a->width(c) / a->width(c - 1);
        EXPECT_TRUE(std::fabs(r - 0.5) < 1e-9 || std::fabs(r - 1.0) < 1e-9 || std::fabs(r - 2.0) < 1e-9)
            << "ratio " << r << " at cell " << c;
      }
    }
  }
  // The boxes are honoured: 0.25 mm cells across x in [15, 25] mm, 2 mm far from them.
  EXPECT_NEAR(g.x.width(g.x.cell_of(0.02)), 0.25e-3, 1e-12);
  EXPECT_NEAR(g.x.width(g.x.cell_of(0.012)), 0.5e-3, 1e-12);
  EXPECT_NEAR(g.x.width(g.x.cell_of(0.001)), 2e-3, 1e-12);
  EXPECT_NEAR(g.y.width(g.y.cell_of(0.005)), 0.25e-3, 1e-12);
}

// Ghost cells, as wide as the edge cells, hold the margin beyond the two every grid has: here
// the x edges are 2 mm cells and the y edges 1 mm (graded down towards the box), so a 4.5 mm
// margin needs 2 + ceil(4.5 / 1) = 7 ghost cells (one count for the whole grid).
TEST(Refinement, ghost_cells_hold_the_margin) {
  const double min[2] = {0.0, 0.0}, max[2] = {0.04, 0.01};
  const std::vector<RefineBox> boxes = {{{0.01, 0.002}, {0.03, 0.008}, 0.5e-3}};
  const Grid plain = make_graded_grid(min, max, 2e-3, 0.5e-3, boxes);
  const Grid wide = make_graded_grid(min, max, 2e-3, 0.5e-3, boxes, 4.5e-3);
  EXPECT_EQ(plain.ghost, 2);
  EXPECT_NEAR(wide.x.width(wide.ghost), 2e-3, 1e-15);
  EXPECT_NEAR(wide.y.width(wide.ghost), 1e-3, 1e-15);
  EXPECT_EQ(wide.ghost, 7);
  for (const Grid* g : {&plain, &wide})
    for (const Axis* a : {&g->x, &g->y}) {
      const int first = g->ghost, last = a->cells - g->ghost;  // physical edge nodes
      EXPECT_NEAR(a->node(first), 0.0, 1e-15);
      EXPECT_NEAR(a->node(last), a == &g->x ? 0.04 : 0.01, 1e-15);
      for (int c = 0; c < g->ghost; ++c) {  // ghosts as wide as the edge cells
        EXPECT_NEAR(a->width(c), a->width(first), 1e-15);
        EXPECT_NEAR(a->width(last + c), a->width(last - 1), 1e-15);
      }
      if (g == &wide) {
        EXPECT_GE(a->node(first) - a->node(0), 4.5e-3 + 2 * a->width(first) - 1e-12);
      }
    }
}

TEST(Refinement, weights_partition_unity_and_match_quadrature_across_every_transition) {
  const Grid g = two_level_boxes();
  const Axis& a = g.x;
  double worst_sum = 0, worst_grad = 0, worst_quad = 0;
  int samples = 0;
  for (int c = g.ghost; c < a.cells - g.ghost; ++c) {
    for (const double ppc : {1.0, 2.0}) {
      const double lp = 0.5 * a.width(c) / ppc;  // a particle of the cell it starts in
      for (int k = 0; k < 7; ++k) {
        const double xp = a.node(c) + (k + 0.5) / 7.0 * a.width(c);
        Stencil1D st;
        stencil(a, xp, lp, st);
        double sum = 0, grad = 0;
        for (int j = 0; j < 3; ++j) {
          sum += st.s[j];
          grad += st.ds[j];
          worst_quad = std::max(worst_quad, std::fabs(st.s[j] - quadrature_weight(a, st.first + j, xp, lp)));
        }
        // Nodes outside the stencil carry no weight.
        for (int i : {st.first - 1, st.first + 3})
          if (i >= 0 && i <= a.cells) worst_quad = std::max(worst_quad, quadrature_weight(a, i, xp, lp));
        worst_sum = std::max(worst_sum, std::fabs(sum - 1.0));
        worst_grad = std::max(worst_grad, std::fabs(grad) * a.width(c));
        ++samples;
      }
    }
  }
  std::printf("%d samples: |sum S - 1| <= %.2e, |sum dS| h <= %.2e, |S - quadrature| <= %.2e\n",
              samples, worst_sum, worst_grad, worst_quad);
  EXPECT_LT(worst_sum, 1e-13);
  EXPECT_LT(worst_grad, 1e-12);
  EXPECT_LT(worst_quad, 1e-6);  // midpoint rule with 4000 points on a piecewise-linear hat
}

namespace {

// A 1D P-wave pulse along a strip 60 mm long and 1 mm high, rollers on top and bottom. With
// `refined`, cells are 0.5 mm (x) outside and 0.125 mm inside x in [20, 40] mm.
struct PulseRun {
  std::vector<double> t, probe_a;  // time, mean sigma_xx at x = 10 mm (before the transitions)
  double arrival_b = NAN;          // half-amplitude arrival of the pulse front at x = 50 mm
  double energy_error = 0.0;       // worst |E_kin + E_strain - W_ext| / W_ext after the loading
  double amplitude = 0.0;          // incident plateau rho c_D V, Pa
};

PulseRun pulse(bool refined) {
  const double end = 30e-6, v = 1.0;
  Case c = test::strip_1d(0.06, 0.001, 0.5e-3, "x", v, end);
  // A pulse resolved by the coarse cells: rise 1 us (2.5 mm, five 0.5 mm cells), plateau 2 us,
  // fall 1 us; 10 mm long, it has passed x = 10 mm by 8 us.
  for (VelocityBC& bc : c.boundary)
    if (bc.name == "drive") bc.velocity = TimeFunction{TimeFunction::Kind::trapezoid, v, 1e-6, 2e-6, 1e-6};
  if (refined) {
    c.grid.cell_size = 0.125e-3;
    c.grid.coarse_cell_size = 0.5e-3;
    c.grid.refine.push_back({"fine", {0.02, 0.0}, {0.04, 0.001}, 2});
  } else {
    c.grid.cell_size = 0.125e-3;       // no boxes: every cell 0.5 mm ...
    c.grid.coarse_cell_size = 0.5e-3;
    c.time.cfl = 0.1;                  // ... and the refined strip's time step
  }
  State s = make_state(c);
  const WaveSpeeds w = wave_speeds(c.materials[0], c.plane);
  PulseRun r;
  r.amplitude = c.materials[0].density * w.dilatational * v;
  double prev_t = 0, prev_b = 0;
  while (s.time < end) {
    step(s);
    r.t.push_back(s.time);
    r.probe_a.push_back(test::mean_over(s.particles, s.particles.sxx, 0.0095, 0.0105));
    const double b = test::mean_over(s.particles, s.particles.sxx, 0.0495, 0.0505);
    if (std::isnan(r.arrival_b) && std::fabs(b) >= 0.5 * r.amplitude)
      r.arrival_b = prev_t + (-0.5 * r.amplitude - prev_b) / (b - prev_b) * (s.time - prev_t);
    prev_t = s.time, prev_b = b;
    if (s.time > 4e-6) {  // after the loading: W_ext is final
      const double e = kinetic_energy(s.particles) + strain_energy(s.particles, s.stiffness);
      r.energy_error = std::max(r.energy_error, std::fabs(e - s.external_work) / s.external_work);
    }
  }
  return r;
}

}  // namespace

TEST(Refinement, plane_wave_crosses_coarse_fine_coarse_without_reflection) {
  const PulseRun fine = pulse(true), plain = pulse(false);
  ASSERT_EQ(fine.t.size(), plain.t.size());
  // Anything the refined strip shows at x = 10 mm that the uniform one does not came back
  // from the transitions (at 20 mm: back at 10 mm from about 11.8 us; at 40 mm: 27.6 us).
  // Incident amplitude: rho c_D V, which the uniform strip's plateau at 10 mm reproduces.
  const double incident = fine.amplitude;
  double reflected = 0, plateau = 0;
  int in_plateau = 0;
  for (std::size_t k = 0; k < fine.t.size(); ++k) {
    if (fine.t[k] > 5.2e-6 && fine.t[k] < 6.8e-6) plateau += plain.probe_a[k], ++in_plateau;
    if (fine.t[k] > 9e-6) reflected = std::max(reflected, std::fabs(fine.probe_a[k] - plain.probe_a[k]));
  }
  plateau /= in_plateau;
  const WaveSpeeds w = wave_speeds(test::strip_1d(0.06, 0.001, 0.5e-3, "x", 1, 1).materials[0], PlaneMode::strain);
  const double expected = 0.05 / w.dilatational + 0.5e-6;  // mid-rise of the front at 50 mm
  std::printf("plateau at 10 mm %.4g Pa (rho c_D V = %.4g), reflected %.3g Pa (%.2f %%); arrival at 50 mm "
              "%.4f us (refined), %.4f us (uniform), analytic %.4f us; energy error %.2e / %.2e\n",
              -plateau, incident, reflected, 100 * reflected / incident, 1e6 * fine.arrival_b,
              1e6 * plain.arrival_b, 1e6 * expected, fine.energy_error, plain.energy_error);
  // A sanity check that the pulse is there at its size (coarse cells ring about the plateau).
  EXPECT_NEAR(-plateau, incident, 0.05 * incident) << "the incident pulse itself";
  EXPECT_LT(reflected, 0.02 * incident);
  EXPECT_NEAR(fine.arrival_b, expected, 0.01 * expected);
  EXPECT_LT(fine.energy_error, 0.01) << "energy balance through the refined region";
}
