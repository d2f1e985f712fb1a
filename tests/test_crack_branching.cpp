// Tests of solver/crack_branching.hpp: a tip split in two makes three parts of the body, each
// particle in the field of the part it lies in (the left part above the crack and the left
// branch's cut, the wedge between the two cuts in the crack's kept field, the right part below),
// the crack's tie gone and the branches' ties apart beyond the junction; on a block pulled
// symmetrically about the crack's line, the split keeps the symmetry (fields and motion are
// mirror images) and the energy balance closes after it. (With the junction's nodes tied pairwise,
// tie after tie, instead of joining the three fields once, the mirror mismatch was 2.46 m/s of
// 2.55: the momentum summed twice.)
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "cohesive/interface_growth.hpp"
#include "geometry/shape.hpp"
#include "input/case_toml.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/crack_branching.hpp"
#include "solver/nested_state.hpp"
#include "solver/state.hpp"
#include "support.hpp"
#include "support_run.hpp"

using namespace rupture;

namespace {

constexpr double kH = 0.5e-3;  // m

// A 20 x 10 mm block with an edge crack from its left edge along y = 5 mm to x = 8 mm, its top
// and bottom edges pulled by 2 MPa (raised over 1 us), its tip allowed one split.
Case pulled_block(const std::string& grid_extra = "") {
  return parse_case(fmt::format(R"({0}
[model]
plane = "strain"
[grid]
min = [0.0, 0.0]
max = [0.02, 0.01]
cell_size = {1}
particles_per_cell = 2
{2}
[bodies.block]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.01]
[interface.crack]
body = "block"
points = [[0.0, 0.005], [0.008, 0.005]]
segments = 16
law = "contact"
growth = "energy"
fracture_energy = 1e6
branching = "yoffe"
[loads.top]
type = "traction"
from = [0.0, 0.01]
to = [0.02, 0.01]
normal = 2e6
function = "smooth_ramp"
rise_time = 1e-6
[loads.bottom]
type = "traction"
from = [0.0, 0.0]
to = [0.02, 0.0]
normal = 2e6
function = "smooth_ramp"
rise_time = 1e-6
[time]
end = 10e-6
)",
                                test::kHomaliteToml, kH, grid_extra));
}

constexpr double kDeg = std::numbers::pi / 180.0;

// Splits the crack's tip into branches at +-degrees, each `length` long.
std::array<std::size_t, 2> split(const Case& c, State& s, double degrees, double length) {
  const std::vector<CrackTip> tips = precrack_tips(s.interfaces[0].spec, 1e-6 * kH);
  EXPECT_EQ(tips.size(), 1u);
  const TipFrame& f = tips[0].frame;
  const double a = degrees * kDeg;
  return split_crack_tip(c, 0, s, 0, tips[0], f.x + length * std::cos(a), f.y + length * std::sin(a),
                         f.x + length * std::cos(a), f.y - length * std::sin(a), c.interfaces[0].branch_fields[0], true);
}

}  // namespace

TEST(CrackBranching, the_wedge_between_the_branches_takes_the_kept_field) {
  const Case c = pulled_block();
  ASSERT_EQ(c.interfaces[0].branch_fields.size(), 1u);
  State s = make_state(c);
  const int up = c.interfaces[0].upper_field, lo = c.interfaces[0].lower_field, w = c.interfaces[0].branch_fields[0];
  ASSERT_EQ(std::count(s.particles.field.begin(), s.particles.field.end(), std::uint8_t(w)), 0);
  const std::array<std::size_t, 2> slots = split(c, s, 20.0, 0.5 * kH);
  ASSERT_EQ(s.interfaces.size(), 3u);
  // The crack's tip is a junction: no tie, no tip.
  EXPECT_FALSE(s.interfaces[0].spec.bonded);
  EXPECT_TRUE(precrack_tips(s.interfaces[0].spec, 1e-6 * kH).empty());
  EXPECT_TRUE(s.bonded[0].nodes.empty());
  // The branches: left between the upper part and the wedge, right between the wedge and the
  // lower part, each with one tip and a tie to the right edge.
  const InterfaceSpec &l = s.interfaces[slots[0]].spec, &r = s.interfaces[slots[1]].spec;
  EXPECT_EQ(l.upper_field, up);
  EXPECT_EQ(l.lower_field, w);
  EXPECT_EQ(r.upper_field, w);
  EXPECT_EQ(r.lower_field, lo);
  EXPECT_EQ(precrack_tips(l, 1e-6 * kH).size(), 1u);
  EXPECT_EQ(precrack_tips(r, 1e-6 * kH).size(), 1u);
  // The nodes both branches tie are at the junction (the three parts join there, ahead of both
  // new tips: solver/cohesive_step.hpp): where the ties, 40 degrees apart, are less than twice a
  // tie's reach (2 (|n_x| + |n_y|) h <= 2 sqrt(2) h) apart, up to 2 sqrt(2) h / tan(20 deg) =
  // 7.8 h beyond the first segments' ends; no node farther out is tied by both. Ahead of both
  // tips the three parts are intact material, one continuum.
  std::vector<std::size_t> a = s.bonded[slots[0]].nodes, b = s.bonded[slots[1]].nodes, both;
  ASSERT_FALSE(a.empty());
  ASSERT_FALSE(b.empty());
  std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
  for (const std::size_t n : both) {
    const double x = s.grid.x.node(int(n % std::size_t(s.grid.nodes_x()))), y = s.grid.y.node(int(n / std::size_t(s.grid.nodes_x())));
    EXPECT_LT(std::hypot(x - 0.008, y - 0.005), 0.5 * kH + 2.0 * std::sqrt(2.0) * kH / std::tan(20.0 * kDeg))
        << "node " << n << " at " << x << ", " << y;
  }
  // Every particle in the field of the part it lies in: above the crack and the left cut,
  // between the cuts, below the crack and the right cut (the cuts: straight rays from the tip).
  const double tx = 0.008, ty = 0.005, t20 = std::tan(20.0 * kDeg);
  int wrong = 0, wedge = 0;
  const Particles& P = s.particles;
  for (std::size_t q = 0; q < P.size(); ++q) {
    const double x = P.x0[q], y = P.y0[q] - ty;
    const bool in_wedge = x > tx && std::fabs(y) < (x - tx) * t20;
    const int expected = in_wedge ? w : y > 0.0 ? up : lo;
    wrong += P.field[q] != expected;
    wedge += in_wedge;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(wedge, 100);
}

TEST(CrackBranching, a_symmetric_split_keeps_the_mirror_symmetry_and_the_energy_balance) {
  const Case c = pulled_block();
  State s = make_state(c);
  test::run_to(s, 2e-6);
  split(c, s, 25.0, 0.5 * kH);
  test::run_to(s, 6e-6);
  const double err = test::energy_error(s);
  EXPECT_LT(err, 0.01) << "energy balance error " << err;
  std::printf("energy balance error after the split: %.4f %%\n", 100.0 * err);
  // Mirror images about y = 5 mm: the particle at (x, 10 mm - y) moves as this one with v_y
  // reversed (the lattice and the load are symmetric; the split's fields too).
  const Particles& P = s.particles;
  std::vector<std::size_t> order(P.size());
  for (std::size_t q = 0; q < P.size(); ++q) order[q] = q;
  auto key = [&](std::size_t q) { return std::make_pair(std::lround(P.x0[q] / (0.25 * kH)), std::lround(P.y0[q] / (0.25 * kH))); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  double vmax = 0.0, worst = 0.0;
  for (std::size_t q = 0; q < P.size(); ++q) vmax = std::max(vmax, std::hypot(P.vx[q], P.vy[q]));
  for (std::size_t q = 0; q < P.size(); ++q) {
    const auto [i, j] = key(q);
    const auto mirror = std::make_pair(i, std::lround(0.01 / (0.25 * kH)) - j);
    const auto it = std::lower_bound(order.begin(), order.end(), mirror,
                                     [&](std::size_t a, const std::pair<long, long>& m) { return key(a) < m; });
    ASSERT_TRUE(it != order.end() && key(*it) == mirror);
    worst = std::max({worst, std::fabs(P.vx[q] - P.vx[*it]), std::fabs(P.vy[q] + P.vy[*it])});
  }
  EXPECT_LT(worst, 1e-6 * vmax) << "largest mirror mismatch " << worst << " m/s of " << vmax;
}

// Nested levels: the crack and the material round it on 0.5 mm cells (x < 12 mm, 3 < y < 7 mm),
// the rest of the block on 1 mm. The branches' cuts run on to the block's right edge through the
// coarse level, so the wedge holds particles of both levels: each level's take the wedge's field,
// the split line's tie goes on every level, and the branches' ties are laid on each level's own
// lattice, after the run's interfaces (RunState::interface_levels). Without the other levels in
// the call the coarse level keeps its wedge particles in the old fields: the check can fail.
TEST(CrackBranching, on_nested_levels_every_level_takes_the_wedge_and_the_ties) {
  const Case c = pulled_block(R"(coarse_cell_size = 1e-3
refinement = "nested"
[grid.refine.crack]
min = [0.0, 0.003]
max = [0.012, 0.007]
level = 1)");
  const int up = c.interfaces[0].upper_field, lo = c.interfaces[0].lower_field, w = c.interfaces[0].branch_fields[0];
  const double tx = 0.008, ty = 0.005, t20 = std::tan(20.0 * kDeg);
  for (const bool all_levels : {true, false}) {
    RunState r = make_nested_state(c);
    ASSERT_EQ(r.levels.size(), 2u);
    ASSERT_EQ(r.interface_levels[0], 1);
    State &fine = r.levels[1], &coarse = r.levels[0];
    ASSERT_EQ(fine.bonded.size(), 1u);
    ASSERT_EQ(coarse.bonded.size(), 1u);
    ASSERT_FALSE(coarse.bonded[0].nodes.empty()) << "the coarse level ties the crack's extension";
    const std::vector<CrackTip> tips = precrack_tips(fine.interfaces[0].spec, 1e-6 * kH);
    ASSERT_EQ(tips.size(), 1u);
    const TipFrame& f = tips[0].frame;
    const double a = 20.0 * kDeg, len = 0.5 * kH;
    const std::vector<State*> others = all_levels ? std::vector<State*>{&coarse} : std::vector<State*>{};
    const BranchTies ties = all_levels ? BranchTies{0, r.num_interfaces()} : BranchTies{};
    const std::array<std::size_t, 2> slots =
        split_crack_tip(c, 0, fine, r.interface_slots[0], tips[0], f.x + len * std::cos(a), f.y + len * std::sin(a),
                        f.x + len * std::cos(a), f.y - len * std::sin(a), w, true, others, ties);
    // Every particle of a level in the field of the part it lies in.
    const auto wrong_on = [&](const State& L, int& wedge) {
      int wrong = 0;
      wedge = 0;
      const Particles& P = L.particles;
      for (std::size_t q = 0; q < P.size(); ++q) {
        const double x = P.x0[q], y = P.y0[q] - ty;
        const bool in_wedge = x > tx && std::fabs(y) < (x - tx) * t20;
        wrong += P.field[q] != (in_wedge ? w : y > 0.0 ? up : lo);
        wedge += in_wedge;
      }
      return wrong;
    };
    int fine_wedge = 0, coarse_wedge = 0;
    EXPECT_EQ(wrong_on(fine, fine_wedge), 0);
    EXPECT_GT(fine_wedge, 10);
    const int coarse_wrong = wrong_on(coarse, coarse_wedge);
    ASSERT_GT(coarse_wedge, 10) << "the wedge reaches the coarse level";
    if (!all_levels) {
      EXPECT_GT(coarse_wrong, 0) << "the test would see a level left behind";
      continue;
    }
    EXPECT_EQ(coarse_wrong, 0) << "the coarse level's wedge takes the kept field";
    // The split line's tie is gone on both levels; each branch's tie is laid on each level's
    // lattice at the branch's index among the run's interfaces (1 and 2 here).
    for (const State* L : {&fine, &coarse}) {
      ASSERT_EQ(L->bonded.size(), 3u);
      EXPECT_TRUE(L->bonded[0].nodes.empty());
      for (int b = 0; b < 2; ++b) {
        const InterfaceSpec& sp = fine.interfaces[slots[std::size_t(b)]].spec;
        EXPECT_EQ(L->bonded[1 + std::size_t(b)].nodes, bonded_nodes(L->grid, sp));
        EXPECT_FALSE(L->bonded[1 + std::size_t(b)].nodes.empty());
        EXPECT_EQ(L->bonded[1 + std::size_t(b)].upper_field, sp.upper_field);
      }
    }
  }
}
