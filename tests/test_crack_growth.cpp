// Tests of solver/crack_growth.hpp: a grown segment's cut (the crack and its tie beyond the
// tip) divides the two parts exactly, so every particle of the two fields lies on its own side;
// and with two cracks drawn in one body a turned segment keeps its tie apart from the other
// crack's (a straight-on tie would cross it, and a node both ties reach would join three fields:
// the beam under impact with an offset notch and a mid-span seed gained energy and blew up).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "cohesive/interface_growth.hpp"
#include "geometry/shape.hpp"
#include "input/case_toml.hpp"
#include "solver/crack_growth.hpp"
#include "solver/energy.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

constexpr double kH = 0.5e-3;  // m

// A 20 x 10 mm block with cuts up from its bottom edge, 3 mm deep, at each x of `cuts` (m),
// pressed down at the top between them and held at the bottom corners.
Case block_with_cuts(const std::vector<double>& cuts) {
  std::string interfaces;
  for (std::size_t k = 0; k < cuts.size(); ++k)
    interfaces += fmt::format(R"([interface.cut{0}]
body = "block"
points = [[{1}, 0.0], [{1}, 0.003]]
segments = 6
law = "contact"
)",
                              k, cuts[k]);
  return parse_case(fmt::format(R"({0}
[model]
plane = "strain"
[grid]
min = [0.0, 0.0]
max = [0.02, 0.01]
cell_size = {1}
particles_per_cell = 2
[bodies.block]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.01]
{2}
[loads.press]
type = "velocity"
min = [0.009, 0.0095]
max = [0.011, 0.01]
direction = [0.0, -1.0]
velocity = 2.0
function = "smooth_ramp"
rise_time = 1e-6
[boundary.left]
edge = "bottom"
from = 0.0
to = 0.001
component = "y"
velocity = 0.0
[boundary.right]
edge = "bottom"
from = 0.019
to = 0.02
component = "y"
velocity = 0.0
[time]
end = 40e-6
)",
                                test::kHomaliteToml, kH, interfaces));
}

// Grows interface `k`'s upper tip by one segment of `length` at `degrees` from its direction.
void grow(const Case& c, State& s, std::size_t k, double degrees, double length) {
  const std::vector<CrackTip> tips = precrack_tips(s.interfaces[k].spec, 1e-6 * kH);
  ASSERT_EQ(tips.size(), 1u);
  const TipFrame& f = tips[0].frame;
  const double a = degrees * std::numbers::pi / 180.0;
  const double dx = std::cos(a) * f.e1x - std::sin(a) * f.e1y, dy = std::sin(a) * f.e1x + std::cos(a) * f.e1y;
  add_crack_segment(c, k, s, k, tips[0], f.x + length * dx, f.y + length * dy, true);
}

// The crack's cut from below the block to above it: the line, then its tie.
std::vector<Point> cut_of(const InterfaceSpec& spec, const Box& frame) {
  const Polyline line = spec.geometry();
  std::vector<Point> cut{{line.x[0], frame.min[1]}};
  for (std::size_t i = 0; i < line.num_vertices(); ++i) cut.push_back({line.x[i], line.y[i]});
  for (const Polyline& t : spec.tie_geometries())
    for (std::size_t i = 1; i < t.num_vertices(); ++i) cut.push_back({t.x[i], t.y[i]});
  const Point last = cut.back(), before = cut[cut.size() - 2];
  cut.push_back(leave_box(frame, last, {last.x - before.x, last.y - before.y}));
  return cut;
}

// Particles of the crack's two fields on the wrong side of its cut: each side's should all hold
// one field, the other side's the other one.
int misplaced(const State& s, std::size_t k) {
  const InterfaceSpec& spec = s.interfaces[k].spec;
  const Box frame{{-0.001, -0.001}, {0.021, 0.011}};
  const Shape left = left_part(frame, cut_of(spec, frame));
  int left_up = 0, left_lo = 0, right_up = 0, right_lo = 0;
  const Particles& P = s.particles;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.field[p] != spec.upper_field && P.field[p] != spec.lower_field) continue;
    const bool up = P.field[p] == spec.upper_field, is_left = contains(left, P.x0[p], P.y0[p]);
    (is_left ? (up ? left_up : left_lo) : (up ? right_up : right_lo)) += 1;
  }
  return std::min(left_up + right_lo, left_lo + right_up);
}

}  // namespace

TEST(CrackGrowth, a_turned_segment_moves_the_swept_particles_to_the_side_they_are_on) {
  const Case c = block_with_cuts({0.01025});
  State s = make_state(c);
  EXPECT_EQ(misplaced(s, 0), 0) << "as drawn";
  for (const double deg : {-40.0, 25.0, 30.0}) {
    grow(c, s, 0, deg, 0.5 * kH);
    EXPECT_EQ(misplaced(s, 0), 0) << "after a turn of " << deg << " degrees";
  }
}

TEST(CrackGrowth, two_cracks_in_one_body_keep_their_ties_apart_and_the_energy_balance_closes) {
  const Case c = block_with_cuts({0.00625, 0.01375});
  State s = make_state(c);
  ASSERT_EQ(s.interfaces.size(), 2u);
  // The left cut turns 70 degrees towards the right one (clockwise from up), twice.
  grow(c, s, 0, -70.0, 0.5 * kH);
  grow(c, s, 0, 0.0, 0.5 * kH);
  // Its tie leaves the tip along the turned segment for two cells, then runs up: nowhere does it
  // come within two cells of the right cut's tie (x = 13.75 mm); straight on it would cross it
  // at y = 3.3 + 7.4 tan(20 deg) = 6 mm.
  const InterfaceSpec& a = s.interfaces[0].spec;
  double closest = INFINITY;
  for (const Polyline& t : a.tie_geometries())
    for (std::size_t i = 0; i < t.num_vertices(); ++i) {
      closest = std::min(closest, std::fabs(t.x[i] - 0.01375));
      if (i > 0 && (t.x[i - 1] - 0.01375) * (t.x[i] - 0.01375) <= 0.0) closest = 0.0;  // a piece crosses it
    }
  EXPECT_GT(closest, 2.0 * kH) << "the left crack's tie keeps off the right crack's";
  // No grid node is tied by both cracks.
  std::vector<std::size_t> both;
  std::set_intersection(s.bonded[0].nodes.begin(), s.bonded[0].nodes.end(), s.bonded[1].nodes.begin(),
                        s.bonded[1].nodes.end(), std::back_inserter(both));
  EXPECT_TRUE(both.empty()) << both.size() << " nodes tied by both";
  EXPECT_EQ(misplaced(s, 0), 0);
  EXPECT_EQ(misplaced(s, 1), 0);
  // Pressed at the top: the energy supplied is what the block holds.
  while (s.time < 40e-6) step(s);
  const double total = kinetic_energy(s.particles) + strain_energy(s.particles, s.stiffness);
  const double err = std::fabs(s.initial_energy + s.external_work - total) / std::fabs(s.external_work);
  EXPECT_LT(err, 0.01) << "energy balance";
  std::printf("two cracks: tie %.3f mm from the other's at the closest, energy error %.3e after %ld steps\n",
              closest * 1e3, err, s.step);
}
