// solver.mass = "averaged" (solver/consistent_mass.hpp, docs/theory.md §19): the consistent
// mass's band sums to the lumped mass and is symmetric, the solves keep the total momentum and
// force and invert the consistent mass on a resolved wave to the sweeps' predicted error, and a
// standing P wave's period shows the dispersion the Bloch analysis predicts: a few percent in
// phase speed with the lumped mass under FLIP, a few tenths of a percent with the averaged one.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <numeric>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "material/elastic.hpp"
#include "solver/consistent_mass.hpp"
#include "solver/field_windows.hpp"
#include "solver/transfer.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

constexpr double kH = 1e-3;  // cell, m

// A Homalite strip [0, L] x [0, 3h], L = one wavelength of cells_per_wave cells, its ends
// fixed along x and rollers on top and bottom: u_x = sin(2 pi x / L) is a standing P mode.
std::string standing_wave_toml(int cells_per_wave, const std::string& mass) {
  return fmt::format(R"({0}
[model]
plane = "strain"
[grid]
min = [0.0, 0.0]
max = [{1}, {2}]
cell_size = {3}
[bodies.strip]
material = "homalite"
min = [0.0, 0.0]
max = [{1}, {2}]
[time]
end = 1.0
cfl = 0.4
[solver]
mass = "{4}"
[boundary.left]
edge = "left"
component = "x"
velocity = 0.0
[boundary.right]
edge = "right"
component = "x"
velocity = 0.0
[boundary.bottom]
edge = "bottom"
component = "y"
velocity = 0.0
[boundary.top]
edge = "top"
component = "y"
velocity = 0.0
)",
                     test::kHomaliteToml, cells_per_wave * kH, 3 * kH, kH, mass);
}

// The strip without its boundary conditions (a free body: no node's value is prescribed, so
// the solves' sums are the body's momentum and force).
std::string free_strip_toml(int cells = 8) {
  const std::string text = standing_wave_toml(cells, "averaged");
  return text.substr(0, text.find("[boundary.left]"));
}

// The case's state at t = 0 with its nodal masses and consistent-mass band, as a step has them.
State with_band(const std::string& toml) {
  State s = make_state(parse_case(toml));
  build_scatter_plan(s);
  fit_field_windows(s);
  particles_to_grid(s, false);
  assemble_consistent_mass(s);
  return s;
}

// The phase speed of the standing mode over c_D, minus 1: the particles start with
// v_x = sin(k x), at rest in strain, so the mode's stress sigma_xx ~ cos(k x) sin(omega t)
// (the stress, not the particles' velocity: FLIP keeps the part of the velocity the grid does
// not carry, a constant offset of the velocity's mode); its first return to zero (linear
// between steps) is at pi / omega.
double phase_speed_error(int cells_per_wave, const std::string& mass) {
  State s = make_state(parse_case(standing_wave_toml(cells_per_wave, mass)));
  const double L = cells_per_wave * kH, k = 2.0 * M_PI / L;
  Particles& P = s.particles;
  for (std::size_t p = 0; p < P.size(); ++p) P.vx[p] = std::sin(k * P.x[p]);
  const auto mode = [&]() {
    double sum = 0.0;
    for (std::size_t p = 0; p < P.size(); ++p) sum += P.volume0[p] * P.sxx[p] * std::cos(k * P.x[p]);
    return sum;
  };
  step(s);
  double t0 = s.time, a0 = mode();
  const double sign = a0 > 0 ? 1.0 : -1.0;
  for (int n = 0; n < 100000; ++n) {
    step(s);
    const double a = mode();
    if (sign * a <= 0.0) {
      const double t_zero = t0 + a0 / (a0 - a) * (s.time - t0);
      const double omega = M_PI / t_zero;
      const ElasticMaterial homalite{"homalite", 5.2e9, 0.34, 1246.0};
      const double cd = wave_speeds(homalite, PlaneMode::strain).dilatational;
      return omega / k / cd - 1.0;
    }
    t0 = s.time, a0 = a;
  }
  return NAN;
}

}  // namespace

TEST(ConsistentMass, band_is_symmetric_and_sums_to_the_lumped_mass) {
  State s = make_state(parse_case(standing_wave_toml(8, "averaged")));
  // Move the particles off their lattice (a deformed body): the band must follow them.
  for (std::size_t p = 0; p < s.particles.size(); ++p) {
    s.particles.x[p] += 0.2 * kH * std::sin(17.0 * double(p));
    s.particles.y[p] += 0.1 * kH * std::cos(11.0 * double(p));
  }
  s.step = 1;  // the sort and the windows of a step that follows a move
  build_scatter_plan(s);
  fit_field_windows(s);
  particles_to_grid(s, false);
  assemble_consistent_mass(s);
  const GridFields& G = s.fields;
  const std::vector<double>& band = s.consistent_mass.band;
  ASSERT_EQ(band.size(), G.size() * 25);
  const int cols = G.cols[0], rows = G.rows[0];
  double largest = 0.0;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const std::size_t e = G.index(0, G.col0[0] + i, G.row0[0] + j);
      double sum = 0.0;
      for (int o = 0; o < 25; ++o) {
        const double m = band[e * 25 + std::size_t(o)];
        EXPECT_GE(m, 0.0);
        sum += m;
        const int dx = o % 5 - 2, dy = o / 5 - 2;
        if (m == 0.0 || i + dx < 0 || i + dx >= cols || j + dy < 0 || j + dy >= rows) continue;
        const std::size_t n = G.index(0, G.col0[0] + i + dx, G.row0[0] + j + dy);
        EXPECT_NEAR(band[n * 25 + std::size_t((2 - dy) * 5 + 2 - dx)], m, 1e-14 * m) << "M_ij = M_ji";
      }
      EXPECT_NEAR(sum, G.mass[e], 1e-12 * G.mass[e]) << "row sum = lumped mass at node " << e;
      largest = std::max(largest, G.mass[e]);
    }
  EXPECT_GT(largest, 0.0);
}

TEST(ConsistentMass, solves_keep_the_total_and_a_uniform_velocity) {
  State s = with_band(free_strip_toml());
  const GridFields& G = s.fields;
  const std::size_t n = G.size();
  // A smooth field and a rough one.
  std::vector<double> bx(n), by(n);
  for (std::size_t e = 0; e < n; ++e) {
    bx[e] = G.mass[e] * std::sin(0.3 * double(e));
    by[e] = G.mass[e] * (e % 2 ? 1.0 : -0.5);
  }
  for (const bool consistent : {true, false}) {
    std::vector<double> x = bx, y = by;
    solve_mass(s, consistent ? MassSolve::momentum_at_start : MassSolve::force, x.data(), y.data());
    // Each Richardson sweep keeps sum_i m_i x_i = sum_i b_i (the band's rows sum to m_i):
    // momentum (and the force's impulse) is neither made nor lost.
    const double sx0 = std::accumulate(bx.begin(), bx.end(), 0.0), sx = std::accumulate(x.begin(), x.end(), 0.0);
    const double sy0 = std::accumulate(by.begin(), by.end(), 0.0), sy = std::accumulate(y.begin(), y.end(), 0.0);
    const double scale = std::accumulate(G.mass.begin(), G.mass.end(), 0.0);
    EXPECT_NEAR(sx, sx0, 1e-13 * scale) << (consistent ? "M_C" : "M_A");
    EXPECT_NEAR(sy, sy0, 1e-13 * scale) << (consistent ? "M_C" : "M_A");
  }
  // A uniform velocity is its own projection (M_C 1 = M_L 1): b = m gives back b = m.
  std::vector<double> ux(G.mass), uy(G.mass);
  solve_mass(s, MassSolve::momentum_at_start, ux.data(), uy.data());
  for (std::size_t e = 0; e < n; ++e) EXPECT_NEAR(ux[e], G.mass[e], 1e-12 * (G.mass[e] + 1e-30));
}

TEST(ConsistentMass, momentum_solve_inverts_the_consistent_mass_on_a_resolved_wave) {
  // A strip 32 cells long, a velocity of 8 cells per wavelength along it, uniform across it:
  // from b = M_C v the momentum solve gives back v to the sweeps' error, (1 - lambda)^3 =
  // 1.3e-3 (lambda = 0.89, docs/theory.md §19), at the nodes 8 or more from the free ends
  // (whose truncated rows make the error there, and each sweep carries it two nodes in).
  State s = with_band(free_strip_toml(32));
  const GridFields& G = s.fields;
  const std::size_t n = G.size();
  const double k = 2.0 * M_PI / (8 * kH);
  std::vector<double> v(n, 0.0), b(n), b_y(n, 0.0);
  const int cols = G.cols[0], rows = G.rows[0];
  const auto x_of = [&](int i) { return s.grid.x.origin + (G.col0[0] + i) * kH; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) v[G.index(0, G.col0[0] + i, G.row0[0] + j)] = std::sin(k * x_of(i) + 0.3);
  apply_consistent_mass(s, v.data(), b.data());
  std::vector<double> lumped(n);
  for (std::size_t e = 0; e < n; ++e) lumped[e] = G.mass[e] > 0.0 ? b[e] / G.mass[e] : 0.0;
  solve_mass(s, MassSolve::momentum_at_start, b.data(), b_y.data());
  double worst = 0.0, worst_lumped = 0.0;
  int checked = 0;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const std::size_t e = G.index(0, G.col0[0] + i, G.row0[0] + j);
      if (G.mass[e] <= 0.0 || x_of(i) < 7.9 * kH || x_of(i) > 24.1 * kH) continue;
      worst = std::max(worst, std::fabs(b[e] / G.mass[e] - v[e]));
      worst_lumped = std::max(worst_lumped, std::fabs(lumped[e] - v[e]));
      ++checked;
    }
  std::printf("M_C^-1 M_C v: largest error %.2e (M_L^-1 M_C v: %.2e) over %d nodes\n", worst, worst_lumped, checked);
  EXPECT_GT(checked, 40);
  EXPECT_LT(worst, 2e-3) << "M_C^-1 (M_C v) = v to the sweeps' error";
  EXPECT_GT(worst_lumped, 0.09) << "the lumped mass alone smooths v by 1 - lambda = 0.11";
}

TEST(ConsistentMass, standing_wave_has_the_dispersion_of_the_analysis) {
  // Bloch analysis of the 2 x 2 particle lattice (docs/theory.md §19), phase speed along an
  // axis: lumped mass under FLIP -2.07 % (kh = 0.39) and -8.06 % (0.79); averaged mass with
  // two sweeps +0.074 % and +0.17 %. The central difference in time adds (omega dt)^2 / 24:
  // +0.10 and +0.41 % at the lumped step (cfl 0.4), +0.05 and +0.21 % at the averaged one
  // (1/sqrt(2) of it). Predicted: -1.97, -7.68, +0.13, +0.37 %.
  const double lumped16 = phase_speed_error(16, "lumped"), lumped8 = phase_speed_error(8, "lumped");
  const double averaged16 = phase_speed_error(16, "averaged"), averaged8 = phase_speed_error(8, "averaged");
  std::printf("phase speed error, 16 and 8 cells per wavelength: lumped %+.3f %% %+.3f %%, averaged %+.3f %% %+.3f %%\n",
              100 * lumped16, 100 * lumped8, 100 * averaged16, 100 * averaged8);
  // The averaged mass on its prediction (measured +0.122 and +0.364 % when written).
  EXPECT_NEAR(averaged16, 0.0013, 0.0005);
  EXPECT_NEAR(averaged8, 0.0037, 0.0005);
  // The lumped mass: measured -2.20 and -8.72 %, 12 % beyond the analysis's -1.97 and -7.68
  // (docs/theory.md §19); its error second order (a factor near 4 for half the cell) and more
  // than ten times the averaged one's at both.
  EXPECT_LT(lumped16, -0.0197 * 0.9);
  EXPECT_LT(lumped8, -0.0768 * 0.9);
  EXPECT_NEAR(lumped8 / lumped16, 4.0, 0.4);
  EXPECT_LT(std::fabs(averaged8), 0.1 * std::fabs(lumped8));
  EXPECT_LT(std::fabs(averaged16), 0.1 * std::fabs(lumped16));
}

TEST(ConsistentMass, averaged_mass_refuses_what_it_does_not_support_naming_the_key) {
  const auto refused = [](const std::string& text, const std::string& key) {
    try {
      parse_case(text);
      ADD_FAILURE() << "accepted: " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  refused(test::replace(test::strip_case_toml(), "flip = 1.0", "flip = 1.0\nmass = \"consistent\""), "solver.mass");
  refused(test::case_with(test::kGeometry + "sigma_max = 10e6\ndelta_n = 1e-5\n") + "[solver]\nmass = \"averaged\"\n",
          "solver.mass");
  std::string nested = standing_wave_toml(8, "averaged");
  nested = test::replace(nested, "cell_size = 0.001", "cell_size = 0.001\nrefinement = \"nested\"\ncoarse_cell_size = 0.002\n[grid.refine.box]\nmin = [0.0, 0.0]\nmax = [0.004, 0.003]\nlevel = 1");
  refused(nested, "solver.mass");
}
