// Verification: initiation of a mode I cohesive crack under Freund's crack-face loading (theory
// E18). A semi-infinite crack in an unbounded plane-strain solid, at rest, whose faces are
// suddenly loaded at t = 0 by a uniform pressure sigma* (the upper face pushed up, the lower
// down) has the stress intensity factor
//   K_I(t) = 2 sigma* sqrt(c_D t (1 - 2 nu) / pi) / (1 - nu)
// (Freund, Dynamic Fracture Mechanics, 1990, section 2.5; the same K_I as for a plane tensile
// step sigma* striking the crack at normal incidence, which is this problem plus a uniform
// field). A cohesive crack separates when K_I reaches K_c = sqrt(E' phi_n), E' = E/(1 - nu^2),
// phi_n = e sigma_max delta_n (Griffith with G = K^2/E' at zero speed): t_F = pi K_c^2 (1 - nu)^2
// / (4 sigma*^2 c_D (1 - 2 nu)).
//
// Model: a Homalite plate 30 x 20 mm, two bodies (y > 0 and y < 0, two velocity fields); a
// pre-crack with no interface from x = 0 to a = 20 mm, a Xu-Needleman weak plane (the
// paper's parameters, tau_max = sigma_max) from a to the right edge. The crack faces carry the step
// traction (loads with bodies = [...], normal = -sigma*). The formula holds until a wave from
// the plate's edges reaches the tip: from the loaded faces' end at the left edge (a / c_D =
// 7.9 us), the top and bottom edges (2 H / c_D = 7.9 us) and the right edge (2 (W - a) / c_D).
//
// What the run shows (0.25 mm; 62.5 um in docs/validation.md): the tip's opening passes delta_n
// (peak traction) well before t_F, the tip's J (the law's energy at the tip's opening, = K^2/E'
// for a stationary tip) gives K = 0.58-0.61 K_c at t_F (0.88 K_c at 62.5 um: the zone, ~0.3 mm,
// is one cell here), the zone front starts to move near 1.2 t_F (62.5 um), and the tip node
// reaches the separation criterion 5 delta_t = 11.7 delta_n, far in the law's exponential tail
// (99.99 % of phi_n), only once the crack has grown: t_init = 2.2 t_F at 62.5 um, 2.4-2.8 t_F
// here. So what is asserted is what is robust:
//  - the crack starts at the tip of the pre-crack;
//  - after t_F (the cohesive zone must form and open to 5 delta_t after K_I reaches K_c) and
//    before 3.5 t_F;
//  - the tip's J at t_F is below K_c but of its order (0.5 to 1);
//  - the K-dominated part scales as 1/sigma*^2: with sigma_1 = sqrt(2) sigma_2, t_F2/t_F1 = 2;
//    the measured ratio approaches it from below (the delay is a smaller fraction of a longer
//    t_F), so t_init/t_F falls with the load and the ratio lies in [1.4, 2].
// scripts/mode_I_study.sh refines the grid (docs/validation.md has the numbers).
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "input/case_toml.hpp"
#include "material/elastic.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

constexpr double kA = 0.02, kW = 0.03, kH = 0.01;  // crack length, plate width, half-height, m
const ElasticMaterial kHomalite{"homalite", 5.2e9, 0.34, 1246.0};

Case plate(double sigma, double h, double end) {
  return parse_case(fmt::format(R"({0}
[grid]
min = [0.0, -{3}]
max = [{2}, {3}]
cell_size = {4}
[bodies.upper]
material = "homalite"
min = [0.0, 0.0]
max = [{2}, {3}]
[bodies.lower]
material = "homalite"
min = [0.0, -{3}]
max = [{2}, 0.0]
[interface.weak_plane]
upper_body = "upper"
lower_body = "lower"
y = 0.0
start = {1}
end = {2}
segments = {6}
sigma_max = 24e6
tau_max = 24e6
delta_n = 0.4e-6
[loads.upper_face]
type = "traction"
from = [0.0, 0.0]
to = [{1}, 0.0]
normal = {7}
bodies = ["upper"]
[loads.lower_face]
type = "traction"
from = [0.0, 0.0]
to = [{1}, 0.0]
normal = {7}
bodies = ["lower"]
[time]
end = {5}
)",
                                test::kHomaliteToml, kA, kW, kH, h, end,
                                int(std::lround((kW - kA) / 10e-6)), -sigma));
}

// Freund's initiation time (see the header), s.
double freund_time(double sigma, const ElasticMaterial& m, double phi_n) {
  const double nu = m.poisson_ratio, cd = wave_speeds(m, PlaneMode::strain).dilatational;
  const double kc2 = m.youngs_modulus / (1 - nu * nu) * phi_n;
  return std::numbers::pi * kc2 * (1 - nu) * (1 - nu) / (4 * sigma * sigma * cd * (1 - 2 * nu));
}

struct Initiation {
  double time = -1.0;  // s
  double x = NAN;      // m
  double k_tip_at_tF = NAN;  // sqrt(E' J_tip) at Freund's time, Pa m^1/2
};

// Runs until the first interface node separates (or `end`).
Initiation run_until_initiation(double sigma, double h, double end, double t_freund) {
  State s = make_state(plate(sigma, h, end));
  const CohesiveInterface& c = s.interfaces[0];
  const XuNeedleman& law = std::get<XuNeedleman>(c.spec.law);
  const double e_prime = kHomalite.youngs_modulus / (1 - kHomalite.poisson_ratio * kHomalite.poisson_ratio);
  Initiation r;
  while (s.time < end && r.time < 0) {
    step(s);
    if (std::isnan(r.k_tip_at_tF) && s.time >= t_freund) {
      // Stationary tip: J = K^2/E' equals the energy the law has taken at the tip's opening
      // (pure mode I: phi_n [1 - (1 + x) e^-x], x = jump_n / delta_n).
      const double x = c.jump_normal(0) / law.delta_n;
      r.k_tip_at_tF = std::sqrt(e_prime * law.phi_n() * (1 - (1 + x) * std::exp(-x)));
    }
    for (std::size_t k = 0; k < c.num_nodes(); ++k)
      if (c.node_crack_time[k] >= 0 && (r.time < 0 || c.node_crack_time[k] < r.time))
        r.time = c.node_crack_time[k], r.x = c.x0[k];
  }
  return r;
}

}  // namespace

TEST(ModeI, initiation_follows_freund_K_I_of_t_and_scales_as_one_over_sigma_squared) {
  const double h = 0.25e-3, phi_n = std::exp(1.0) * 24e6 * 0.4e-6;
  const double cd = wave_speeds(kHomalite, PlaneMode::strain).dilatational;
  const double valid = std::min(kA, 2 * kH) / cd;  // no edge wave at the tip before this
  const double e_prime = kHomalite.youngs_modulus / (1 - kHomalite.poisson_ratio * kHomalite.poisson_ratio);  // no edge wave at the tip before this
  const double loads[2] = {7e6, 7e6 / std::sqrt(2.0)};
  double measured[2], predicted[2];
  for (int k = 0; k < 2; ++k) {
    predicted[k] = freund_time(loads[k], kHomalite, phi_n);
    const Initiation r = run_until_initiation(loads[k], h, valid, predicted[k]);
    measured[k] = r.time;
    std::printf("sigma* = %.4g MPa: Freund t_F = %.4f us, measured initiation %.4f us at x = %.3f mm "
                "(ratio %.3f, delay %.3f us); at t_F the tip's J gives K = %.3f K_c; edge waves reach the tip "
                "at %.2f us\n",
                loads[k] / 1e6, predicted[k] * 1e6, r.time * 1e6, r.x * 1e3, r.time / predicted[k],
                (r.time - predicted[k]) * 1e6, r.k_tip_at_tF / std::sqrt(e_prime * phi_n), valid * 1e6);
    RecordProperty(fmt::format("t_init_{}MPa_us", loads[k] / 1e6), fmt::format("{:.4f}", r.time * 1e6));
    RecordProperty(fmt::format("t_freund_{}MPa_us", loads[k] / 1e6), fmt::format("{:.4f}", predicted[k] * 1e6));
    ASSERT_GT(r.time, 0.0) << "no initiation before the edge waves arrive";
    EXPECT_NEAR(r.x, kA, 0.5 * h) << "the crack must start at the pre-crack's tip";
    EXPECT_GT(r.time, predicted[k]) << "the cohesive zone must form after K_I reaches K_c";
    EXPECT_LT(r.time, 3.5 * predicted[k]) << "initiation far later than Freund's K_I(t) = K_c";
    const double k_ratio = r.k_tip_at_tF / std::sqrt(e_prime * phi_n);
    EXPECT_GT(k_ratio, 0.5) << "the tip's J at t_F (K / K_c)";
    EXPECT_LT(k_ratio, 1.0) << "the tip's J at t_F (K / K_c)";
  }
  const double ratio = measured[1] / measured[0];
  std::printf("t_init(%.4g MPa) / t_init(%.4g MPa) = %.3f; (sigma_1/sigma_2)^2 = %.3f\n", loads[1] / 1e6,
              loads[0] / 1e6, ratio, predicted[1] / predicted[0]);
  EXPECT_GT(ratio, 1.4) << "K-dominated initiation scales as 1/sigma*^2 (2 here)";
  EXPECT_LE(ratio, 2.0) << "the delay is a smaller fraction of t_F at the lower load";
  EXPECT_LT(measured[1] / predicted[1], measured[0] / predicted[0]) << "t_init/t_F falls with the load";
}
