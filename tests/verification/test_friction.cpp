// Contact and Coulomb friction on an interface (cohesive/contact.hpp), through the whole time
// step: a block pressed onto a base across a frictional contact interface and pushed
// tangentially by a slowly rising body force sticks while the push is below mu N and slides
// once it exceeds it; the pressed faces do not interpenetrate.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "input/case_toml.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

// Homalite block 10 x 4 mm on a base of the same width held at its bottom edge (the domain's).
// The block's top is pressed by p (smooth ramp over 100 us, about 8 periods of the column's
// fundamental mode 4 L / c_D = 13 us, so little vibration is left); from 120 us a body force on
// the block rises linearly to twice the Coulomb limit at 520 us: F(t) = 2 mu N (t - 120 us) /
// 400 us, N = p L, slow against the transit times (~2 us): the response is quasi-static.
constexpr double kP = 1e6, kMu = 0.4, kL = 0.01, kStiffness = 1e15;
constexpr double kRho = 1246.0, kBlockArea = 0.01 * 0.004;
constexpr double kRampStart = 120e-6, kRampLength = 400e-6, kPressRise = 100e-6;

std::string friction_case() {
  const double push = 2.0 * kMu * kP * kL / (kRho * kBlockArea);  // m/s^2 at the ramp's end
  return fmt::format(R"(
{0}
[grid]
min = [0.0, 0.001]
max = [0.016, 0.010]
cell_size = 0.5e-3
[bodies.base]
material = "homalite"
min = [0.003, 0.001]
max = [0.013, 0.005]
[bodies.block]
material = "homalite"
min = [0.003, 0.005]
max = [0.013, 0.009]
[interface.contact]
upper_body = "block"
lower_body = "base"
y = 0.005
start = 0.003
end = 0.013
segments = 40
law = "contact"
contact_stiffness = {1:g}
friction = {2:g}
[boundary.hold_x]
edge = "bottom"
component = "x"
bodies = ["base"]
velocity = 0.0
[boundary.hold_y]
edge = "bottom"
component = "y"
bodies = ["base"]
velocity = 0.0
[loads.press]
type = "traction"
from = [0.003, 0.009]
to = [0.013, 0.009]
normal = {3:g}
function = "smooth_ramp"
rise_time = {7:g}
[loads.push]
type = "body_force"
bodies = ["block"]
acceleration = [{4:.10g}, 0.0]
function = "table"
table = [[0.0, 0.0], [{5:g}, 0.0], [{6:g}, 1.0]]
[time]
end = 600e-6
[output]
history_interval = 1e-6
)",
                     test::kHomaliteToml, kStiffness, kMu, -kP, push, kRampStart,
                     kRampStart + kRampLength, kPressRise);
}

}  // namespace

TEST(Friction, block_slides_once_the_push_exceeds_mu_times_the_normal_force) {
  State s = make_state(parse_case(friction_case()));
  ASSERT_EQ(s.interfaces.size(), 1u);
  double slide_time = -1.0, max_penetration = 0.0, friction_at_slide = 0.0, normal_at_slide = 0.0;
  while (s.time < 600e-6 && slide_time < 0.0) {
    step(s);
    const CohesiveInterface& c = s.interfaces[0];
    for (std::size_t k = 0; k < c.num_nodes(); ++k)
      if (s.time > kPressRise) max_penetration = std::max(max_penetration, -c.jump_normal(k));
    // Gross sliding: every Gauss point of the contact either open or on the Coulomb limit
    // |T_t| = mu |T_n| in the push direction (each point's own criterion, nothing fitted).
    bool all_slide = s.time > kRampStart;
    double friction = 0.0, normal = 0.0;
    for (std::size_t i = 0; i < c.gp_tn.size(); ++i) {
      const double w =
          0.25 * c.seg_length[i / CohesiveInterface::kGauss];  // rough weight: sums only
      friction += w * c.gp_tt[i], normal -= w * c.gp_tn[i];
      const bool open = c.gp_tn[i] == 0.0;
      // The resisting traction T^t > 0 holds the upper face back (force -T^t on it).
      const bool at_limit = c.gp_tt[i] >= (1.0 - 1e-9) * kMu * -c.gp_tn[i];
      all_slide = all_slide && (open || at_limit);
    }
    if (all_slide) slide_time = s.time, friction_at_slide = friction, normal_at_slide = normal;
  }
  // The push F(t) = 2 mu N (t - 20 us) / 200 us reaches mu N at 120 us.
  const double push_at_slide = (slide_time - kRampStart) / kRampLength * 2.0;  // in units of mu N
  std::printf(
      "gross sliding at %.3f us (push = mu N at %.3f us): push = %.4f mu N; interface friction "
      "%.4g N/m against mu x normal %.4g N/m; max interpenetration %.3g m\n",
      1e6 * slide_time, 1e6 * (kRampStart + 0.5 * kRampLength), push_at_slide, friction_at_slide,
      kMu * normal_at_slide, max_penetration);
  ASSERT_GT(slide_time, 0.0) << "the block never slid";
  EXPECT_NEAR(push_at_slide, 1.0, 0.02) << "sliding must start at push = mu N within 2 %";
  // Under pressure p the penalty leaves p / k of interpenetration: 1e-9 m here, within 1 % of
  // the reference law's delta_n = 0.4 um (theory §3).
  EXPECT_LT(max_penetration, 0.01 * 0.4e-6);
  EXPECT_GT(max_penetration, 0.0) << "the faces must be pressed together";
}
