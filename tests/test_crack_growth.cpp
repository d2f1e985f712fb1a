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
#include "solver/cohesive_step.hpp"
#include "solver/crack_cut.hpp"
#include "solver/crack_growth.hpp"
#include "solver/crack_junction.hpp"
#include "solver/run_state.hpp"
#include "core/errors.hpp"
#include "solver/energy.hpp"
#include "solver/nested_state.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

constexpr double kH = 0.5e-3;  // m

// A 20 x 10 mm block with cuts up from its bottom edge, 3 mm deep, at each x of `cuts` (m),
// pressed down at the top between them and held at the bottom corners. `refine`: keys added to
// [grid] and tables after it (nested levels), with one step for every level.
// `cut_keys`: more keys of every cut (growth).
Case block_with_cuts(const std::vector<double>& cuts, const std::string& refine = "", const std::string& cut_keys = "") {
  std::string interfaces;
  for (std::size_t k = 0; k < cuts.size(); ++k)
    interfaces += fmt::format(R"([interface.cut{0}]
body = "block"
points = [[{1}, 0.0], [{1}, 0.003]]
segments = 6
law = "contact"
{2}
)",
                              k, cuts[k], cut_keys);
  return parse_case(fmt::format(R"({0}
[model]
plane = "strain"
[grid]
min = [0.0, 0.0]
max = [0.02, 0.01]
cell_size = {1}
particles_per_cell = 2
{3}
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
{4}
)",
                                test::kHomaliteToml, kH, interfaces, refine,
                                refine.empty() ? "" : "subcycling = \"none\""));
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
int misplaced(const InterfaceSpec& spec, const Particles& P) {
  const Box frame{{-0.001, -0.001}, {0.021, 0.011}};
  const Shape left = left_part(frame, cut_of(spec, frame));
  int left_up = 0, left_lo = 0, right_up = 0, right_lo = 0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    if (P.field[p] != spec.upper_field && P.field[p] != spec.lower_field) continue;
    const bool up = P.field[p] == spec.upper_field, is_left = contains(left, P.x0[p], P.y0[p]);
    (is_left ? (up ? left_up : left_lo) : (up ? right_up : right_lo)) += 1;
  }
  return std::min(left_up + right_lo, left_lo + right_up);
}
int misplaced(const State& s, std::size_t k) { return misplaced(s.interfaces[k].spec, s.particles); }

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

// Nested levels: the cut and the block above it on 0.5 mm cells, the rest of the block on 1 mm
// (left and right of x = 6 .. 14 mm). A segment turned by 60 degrees sends its new tie out to the
// block's side through the coarse level, so particles there change sides too, and each level
// ties the new extension on its own lattice. Without the other levels (the one-grid call) the
// coarse level keeps particles on the wrong side: the check can fail.
TEST(CrackGrowth, on_nested_levels_every_level_follows_the_turned_cut) {
  const Case c = block_with_cuts({0.01025}, R"(coarse_cell_size = 1e-3
refinement = "nested"
[grid.refine.tip]
min = [0.006, 0.0]
max = [0.014, 0.01]
level = 1)");
  for (const bool all_levels : {true, false}) {
    RunState s = make_nested_state(c);
    ASSERT_EQ(s.levels.size(), 2u);
    ASSERT_EQ(s.interface_levels[0], 1);
    State& fine = s.levels[1];
    State& coarse = s.levels[0];
    const std::size_t slot = s.interface_slots[0];
    int coarse_particles = 0;
    for (const std::uint8_t f : coarse.particles.field) coarse_particles += f <= 1;
    ASSERT_GT(coarse_particles, 0);
    const InterfaceSpec& spec = fine.interfaces[slot].spec;
    EXPECT_EQ(misplaced(spec, fine.particles) + misplaced(spec, coarse.particles), 0) << "as drawn";
    const std::vector<State*> others = all_levels ? std::vector<State*>{&coarse} : std::vector<State*>{};
    for (const double deg : {-60.0, 0.0}) {
      const std::vector<CrackTip> tips = precrack_tips(spec, 1e-6 * kH);
      ASSERT_EQ(tips.size(), 1u);
      const TipFrame& f = tips[0].frame;
      const double a = deg * std::numbers::pi / 180.0;
      const double dx = std::cos(a) * f.e1x - std::sin(a) * f.e1y, dy = std::sin(a) * f.e1x + std::cos(a) * f.e1y;
      add_crack_segment(c, 0, fine, slot, tips[0], f.x + 0.5 * kH * dx, f.y + 0.5 * kH * dy, true, others);
    }
    if (all_levels) {
      EXPECT_EQ(misplaced(spec, fine.particles), 0);
      EXPECT_EQ(misplaced(spec, coarse.particles), 0) << "the coarse level follows the cut";
      // Each level's tie is the new extension's, on its own lattice (case interface 0).
      EXPECT_EQ(fine.bonded[0].nodes, bonded_nodes(fine.grid, spec));
      EXPECT_EQ(coarse.bonded[0].nodes, bonded_nodes(coarse.grid, spec));
      EXPECT_FALSE(coarse.bonded[0].nodes.empty());
    } else {
      EXPECT_GT(misplaced(spec, coarse.particles), 0) << "the test would see a level left behind";
    }
  }
}

// Two cuts up from the bottom edge at x = 6 and 14 mm, each tied on to the top edge: three parts.
// Once the right one has run through to the top edge (no tie, no tip left) it has cut the block
// in two for good: the part right of it is beyond the left crack's reach (solver/crack_junction.hpp
// cut_off_parts) and the right cut is an edge of that reach. The left crack then turned by 100
// degrees (heading right and down: its tie runs straight on, as in the John-Shah beam broken at
// its mid-span) has its tie end on the right cut instead of crossing it, which no junction check
// refuses, and no particle beyond the right cut changes field. Without the part cut off the same
// segment's tie runs on across the right cut, tying the left crack's two fields at nodes in the
// part beyond (the check can fail).
TEST(CrackGrowth, a_line_that_has_cut_the_body_in_two_is_the_edge_of_another_cracks_reach) {
  // Both grow (prescribed): the part right of the right cut is not beyond the left crack's reach
  // at set-up (input/crack_reach.hpp), only once the right cut has run through.
  const Case c = block_with_cuts({0.006, 0.014}, "", "growth = \"prescribed\"\ngrowth_speed = 100.0");
  for (const bool cut_off : {true, false}) {
    RunState s = make_run_state(c);
    State& L = s.levels[0];
    const std::size_t a = s.interface_slots[0], b = s.interface_slots[1];
    EXPECT_TRUE(cut_off_parts(c, s, 0, {a}).empty()) << "the right cut is tied: nothing cut off";
    ASSERT_EQ(junction_lines(other_lines(c, s, {}, 0, {a})).size(), 2u) << "the right cut and its tie";
    // The right cut runs through to the top edge.
    for (int n = 0; n < 40; ++n) {
      const std::vector<CrackTip> t = precrack_tips(L.interfaces[b].spec, 1e-6 * kH);
      if (t.empty()) break;
      add_crack_segment(c, 1, L, b, t[0], 0.014, std::min(t[0].frame.y + 0.5 * kH, 0.01), true);
    }
    ASSERT_TRUE(precrack_tips(L.interfaces[b].spec, 1e-6 * kH).empty());
    ASSERT_TRUE(L.interfaces[b].spec.tie_geometries().empty());
    const std::vector<OtherLine> all = other_lines(c, s, {}, 0, {a});
    ASSERT_EQ(all.size(), 1u);
    EXPECT_TRUE(all[0].edge) << "the right cut is the edge of the left crack's reach";
    EXPECT_TRUE(junction_lines(all).empty());
    const std::vector<std::vector<Side>> parts = cut_off_parts(c, s, 0, {a});
    ASSERT_EQ(parts.size(), 1u);
    Region cut_away{Shape{ShapeKind::rectangle, {-1.0, -1.0}, {1.0, 1.0}}, {}, parts[0]};
    EXPECT_TRUE(contains(cut_away, 0.0145, 0.005));
    EXPECT_TRUE(contains(cut_away, 0.019, 0.0005));
    EXPECT_FALSE(contains(cut_away, 0.0135, 0.005));
    EXPECT_FALSE(contains(cut_away, 0.006, 0.009));
    if (cut_off) L.interfaces[a].spec.reach_cut_off = parts;
    const std::vector<std::uint8_t> fields = L.particles.field;
    grow(c, L, 0, -100.0, 0.5 * kH);
    const std::vector<Polyline> ties = L.interfaces[a].spec.tie_geometries();
    ASSERT_FALSE(ties.empty());
    double right = -INFINITY;
    for (const Polyline& t : ties)
      for (std::size_t i = 0; i < t.num_vertices(); ++i) right = std::max(right, t.x[i]);
    int beyond = 0, changed = 0;
    for (std::size_t q = 0; q < L.particles.size(); ++q) {
      changed += L.particles.field[q] != fields[q];
      if (L.particles.x0[q] > 0.014) beyond += L.particles.field[q] != fields[q];
    }
    EXPECT_GT(changed, 0) << "the turned cut moves the left crack's particles";
    if (!cut_off) {
      EXPECT_GT(right, 0.0145) << "the tie runs on across the right cut";
      continue;
    }
    EXPECT_NEAR(right, 0.014, 1e-9) << "the tie ends on the right cut";
    EXPECT_NO_THROW(stop_at_tie_junction(c, 0, 0.0, junction_lines(other_lines(c, s, {}, 0, {a})), ties, kH));
    EXPECT_EQ(beyond, 0) << "no particle beyond the right cut changes field";
  }
}

// What a growing tip is checked against before each segment (solver/crack_growth.cpp: a
// junction with another line drawn in its body stops the run): the nearest approach of a
// segment to a polyline, and which lines are drawn inside the crack's body.
TEST(CrackGrowth, a_segment_meets_a_line_where_it_crosses_or_passes_within_the_tolerance) {
  Polyline line;
  line.x = {0.0, 0.010, 0.010};
  line.y = {0.0, 0.0, 0.010};
  // Crossing the first piece: distance 0 at the crossing.
  const auto cross = segment_meets_line(line, {0.004, -0.002}, {0.006, 0.002}, 1e-3);
  ASSERT_TRUE(cross.has_value());
  EXPECT_EQ(cross->distance, 0.0);
  EXPECT_NEAR(cross->at.x, 0.005, 1e-15);
  EXPECT_NEAR(cross->at.y, 0.0, 1e-15);
  // Parallel to the first piece 0.5 mm above it: met within 1 mm, not within 0.4 mm.
  const auto above = segment_meets_line(line, {0.002, 0.0005}, {0.006, 0.0005}, 1e-3);
  ASSERT_TRUE(above.has_value());
  EXPECT_NEAR(above->distance, 0.5e-3, 1e-15);
  EXPECT_FALSE(segment_meets_line(line, {0.002, 0.0005}, {0.006, 0.0005}, 0.4e-3).has_value());
  // Heading at the second piece's far end from beyond it: the end vertex is the nearest point.
  const auto end = segment_meets_line(line, {0.013, 0.014}, {0.0106, 0.0106}, 1e-3);
  ASSERT_TRUE(end.has_value());
  EXPECT_NEAR(end->at.x, 0.010, 1e-15);
  EXPECT_NEAR(end->at.y, 0.010, 1e-15);
  EXPECT_NEAR(end->distance, std::hypot(0.6e-3, 0.6e-3), 1e-15);
  // Beside the corner, outside both pieces' reach.
  EXPECT_FALSE(segment_meets_line(line, {0.012, -0.002}, {0.014, -0.004}, 1e-3).has_value());
}

TEST(CrackGrowth, lines_drawn_in_one_body_are_told_from_interfaces_between_bodies) {
  const std::string dir = std::string(RUPTURE_SOURCE_DIR) + "/examples/";
  const Case beam = load_case(dir + "john_shah.toml");  // the notch and the mid-span seed, one beam
  ASSERT_EQ(beam.interfaces.size(), 2u);
  EXPECT_TRUE(drawn_in_crack_body(beam, 0, beam.interfaces[1]));
  EXPECT_TRUE(drawn_in_crack_body(beam, 1, beam.interfaces[0]));
  const Case bond = load_case(dir + "bimaterial.toml");  // two bodies joined along their edge
  ASSERT_EQ(bond.interfaces.size(), 1u);
  EXPECT_FALSE(drawn_in_crack_body(bond, 0, bond.interfaces[0]));
}

namespace {

// Two bonded bodies, a crack in the lower one drawn from its left edge (growing at a prescribed
// speed, its tie on to the right edge); `bond_lines`: more keys of the bond. in_body: one plate
// with the bond drawn inside it (body = "plate": the parts above and below it are the two
// bodies; the part above is beyond the crack's reach, input/crack_reach.hpp, so the bond is the
// edge of its reach), `bond_points` its line.
std::string bonded_bodies_with_a_crack(const std::string& bond_lines = "", bool in_body = false,
                                       const std::string& bond_points = "[[0.0, 0.006], [0.02, 0.006]]") {
  const std::string bodies = in_body ? R"([bodies.plate]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.01])"
                                     : R"([bodies.lower]
material = "homalite"
min = [0.0, 0.0]
max = [0.02, 0.006]
[bodies.upper]
material = "homalite"
min = [0.0, 0.006]
max = [0.02, 0.01])";
  return fmt::format(R"({0}
[model]
plane = "strain"
[grid]
min = [0.0, 0.0]
max = [0.02, 0.01]
cell_size = {1}
{3}
[interface.bond]
{4}
points = {5}
segments = 40
law = "xu_needleman"
sigma_max = 1e9
tau_max = 1e9
delta_n = 1e-6
delta_t = 1e-6
{2}
[interface.cut]
body = "{6}"
points = [[0.0, 0.002], [0.005, 0.002]]
segments = 10
law = "contact"
growth = "prescribed"
growth_speed = 100.0
[time]
end = 1e-6
)",
                     test::kHomaliteToml, kH, bond_lines, bodies,
                     in_body ? "body = \"plate\"" : "upper_body = \"upper\"\nlower_body = \"lower\"", bond_points,
                     in_body ? "plate" : "lower");
}

// Grows the crack (interface 1) by segments of half a cell turned `degrees` from the drawn
// direction, each ending on the bond (y = 6 mm) at most, until it reaches the bond (at most 30),
// as growth does: the tie checked, then the faces of the lines on the edge followed. Returns the
// SimulationError's message, if one stops it; `through` whether the crack reached the bond.
std::string turn_towards_the_bond(const Case& c, RunState& s, double degrees, bool& through) {
  State& L = s.levels[0];
  const std::size_t slot = s.interface_slots[1];
  const std::vector<OtherLine> all = other_lines(c, s, {}, 1, {slot});
  const double a = degrees * std::numbers::pi / 180.0;
  through = false;
  try {
    for (int n = 0; n < 30 && !through; ++n) {
      const std::vector<CrackTip> t = precrack_tips(L.interfaces[slot].spec, 1e-6 * kH);
      const TipFrame& f = t.at(0).frame;
      Point to{f.x + 0.5 * kH * std::cos(a), f.y + 0.5 * kH * std::sin(a)};
      if (to.y > 0.006) to = {f.x + (0.006 - f.y) / std::tan(a), 0.006};
      stop_at_segment_junction(c, 1, 0.0, junction_lines(all), {f.x, f.y}, to, kH);
      through = add_crack_segment(c, 1, L, slot, t[0], to.x, to.y, true);
      stop_at_tie_junction(c, 1, 0.0, junction_lines(all), L.interfaces[slot].spec.tie_geometries(), kH);
      follow_edge_junctions(c, s, 1, {slot}, all, 0.0, kH);
    }
  } catch (const SimulationError& e) {
    return e.what();
  }
  return "";
}

// A crack in the lower of two bonded bodies, drawn from the left edge: its tie runs on to the
// right edge (with another interface on its body, two cells along the crack, then the drawn
// direction: docs/fracture.md, "Several cracks in one body"). Turned 60 degrees towards the bond,
// its tie's lead comes to meet the bond, and then the crack itself, which ends there (the bond is
// its body's edge): from the first meeting on, the bond's lower face lies on the crack's two
// fields, changing where the tie or the crack meets it (solver/crack_junction.hpp
// follow_edge_junctions), so each piece stays bonded; nothing stops. Turned 10 degrees it never
// meets the bond, whose face stays on one field.
// The same with the bond drawn inside one plate (on the edge of the crack's reach): the same
// faces, fields and meeting.
void check_turns_onto_the_bond(bool in_body) {
  const Case c = parse_case(bonded_bodies_with_a_crack("", in_body));
  ASSERT_EQ(c.interfaces.size(), 2u);
  ASSERT_EQ(c.interface_names[1], "cut");
  // The crack's fields, above and below it (lower, lower.below.cut; in one plate the part above
  // the bond is bodies[0]).
  const std::size_t b0 = in_body ? 1 : 0;
  const int above = c.bodies[b0].field, below = c.bodies[b0 + 1].field;
  ASSERT_EQ(c.bodies[b0 + 1].name, in_body ? "plate.below.bond.below.cut" : "lower.below.cut");
  for (const double deg : {10.0, 60.0}) {
    RunState s = make_run_state(c);
    State& L = s.levels[0];
    const std::size_t slot = s.interface_slots[1];
    const std::vector<OtherLine> all = other_lines(c, s, {}, 1, {slot});
    ASSERT_EQ(all.size(), 1u) << "the bond (no tie)";
    EXPECT_EQ(all[0].in_body, in_body);
    EXPECT_EQ(all[0].edge, in_body) << "drawn in the body: on the edge of the crack's reach";
    EXPECT_TRUE(junction_lines(all).empty()) << "the bond is the edge, not a junction";
    const CohesiveInterface& bond = L.interfaces[s.interface_slots[0]];
    const double a = deg * std::numbers::pi / 180.0;
    // Grow up to 30 segments of half a cell (7.5 mm), each ending on the body's edge at most.
    double first_meeting = -1.0;
    bool through = false;
    CrackGrowthRecord record;  // the segments as a run records them (for the restore below)
    for (int n = 0; n < 30 && !through; ++n) {
      const std::vector<CrackTip> t = precrack_tips(L.interfaces[slot].spec, 1e-6 * kH);
      ASSERT_EQ(t.size(), 1u);
      const TipFrame& f = t[0].frame;
      Point to{f.x + 0.5 * kH * std::cos(a), f.y + 0.5 * kH * std::sin(a)};
      if (to.y > 0.006) to = {f.x + (0.006 - f.y) / std::tan(a), 0.006};
      stop_at_segment_junction(c, 1, 0.0, junction_lines(all), {f.x, f.y}, to, kH);
      through = add_crack_segment(c, 1, L, slot, t[0], to.x, to.y, true);
      record.rows.push_back({1e-9 * n, 0, LineEnd::end, false, to.x, to.y, 0.0, 0.5 * kH, 0.0, 0.0});
      stop_at_tie_junction(c, 1, 0.0, junction_lines(all), L.interfaces[slot].spec.tie_geometries(), kH);
      follow_edge_junctions(c, s, 1, {slot}, all, 0.0, kH);
      if (first_meeting < 0.0 && !bond.node_faces_lo.empty()) first_meeting = f.y;
      // Every node of the bond's lower face on the field of the particles below it.
      for (std::size_t k = 0; k < bond.num_nodes(); ++k) {
        const FaceFields ff = bond.faces_lo(k);
        bool near_change = ff.share < 1.0;  // the node on a change: by shares
        for (std::size_t q = 1; q < bond.spec.lower_faces.size(); ++q)
          near_change = near_change || std::fabs(bond.s0[k] - bond.spec.lower_faces[q].from) < kH;
        if (near_change) continue;
        const Particles& P = L.particles;
        double best = INFINITY;
        int field = -1;
        for (std::size_t q = 0; q < P.size(); ++q) {
          const double d = std::hypot(P.x0[q] - bond.x0[k], P.y0[q] - (bond.y0[k] - 0.25 * kH));
          if ((P.field[q] == above || P.field[q] == below) && d < best) best = d, field = P.field[q];
        }
        EXPECT_EQ(int(ff.a), field) << deg << " degrees, segment " << n << ", bond node " << k;
      }
    }
    // Every particle of the crack's two fields on its side of the crack and its cut: the crack
    // and its tie, or, once it has reached the bond, the crack and the bond on to the right edge
    // (the bond's other side is not the crack's: those particles never change).
    const Polyline cut = L.interfaces[slot].spec.geometry();
    {
      const Box frame{{-0.001, -0.001}, {0.021, 0.011}};
      std::vector<Point> walk{{-0.001, cut.y[0]}};
      for (std::size_t i = 0; i < cut.num_vertices(); ++i) walk.push_back({cut.x[i], cut.y[i]});
      if (through) {
        walk.push_back({0.021, 0.006});
      } else {
        for (const Polyline& t : L.interfaces[slot].spec.tie_geometries())
          for (std::size_t i = 1; i < t.num_vertices(); ++i) walk.push_back({t.x[i], t.y[i]});
        const Point last = walk.back(), before = walk[walk.size() - 2];
        walk.push_back(leave_box(frame, last, {last.x - before.x, last.y - before.y}));
      }
      const Shape left = left_part(frame, walk);
      int wrong = 0, counted = 0;
      const Particles& P = L.particles;
      for (std::size_t q = 0; q < P.size(); ++q) {
        if (P.field[q] != above && P.field[q] != below) continue;
        ++counted;
        wrong += contains(left, P.x0[q], P.y0[q]) != (P.field[q] == above);
      }
      EXPECT_EQ(wrong, 0) << deg << " degrees: particles of the crack's fields on the wrong side, of " << counted;
    }
    if (deg == 10.0) {
      EXPECT_FALSE(through);
      EXPECT_TRUE(bond.node_faces_lo.empty()) << "far from the bond";
      EXPECT_EQ(bond.spec.lower_field, above);
    } else {
      ASSERT_TRUE(through) << "the crack reaches the bond";
      EXPECT_NEAR(cut.y.back(), 0.006, 1e-12);
      EXPECT_TRUE(L.interfaces[slot].spec.tie_geometries().size() <= 1u) << "no tie beyond the bond";
      ASSERT_EQ(bond.spec.lower_faces.size(), 2u);
      EXPECT_NEAR(bond.spec.lower_faces[1].from, cut.x.back(), 1e-9) << "the face changes where the crack ends";
      EXPECT_EQ(bond.spec.lower_faces[0].field, above);
      EXPECT_EQ(bond.spec.lower_faces[1].field, below);
      std::printf("%s, turned 60 degrees: the tie first met the bond with the tip at y = %.3f mm; the crack "
                  "ends on it at x = %.3f mm\n", in_body ? "in one plate" : "two bodies", 1e3 * first_meeting,
                  1e3 * cut.x.back());
      EXPECT_GT(first_meeting, 0.006 - 2.5 * kH) << "the tie meets the bond only near it";
      // A restore: the segments laid again, the particles' fields as the checkpoint holds them,
      // and the bond's faces follow them again (derived, not stored).
      std::vector<CrackGrowthRecord> records(2);
      records[1] = record;
      RunState r = make_run_state(c);
      regrow_cracks(c, r, records);
      r.levels[0].particles.field = L.particles.field;
      const CohesiveInterface& again = r.levels[0].interfaces[r.interface_slots[0]];
      EXPECT_TRUE(again.node_faces_lo.empty()) << "before the rejoin: the case's faces";
      rejoin_cracks(c, r, records);
      ASSERT_EQ(again.spec.lower_faces.size(), bond.spec.lower_faces.size());
      for (std::size_t q = 0; q < bond.spec.lower_faces.size(); ++q) {
        EXPECT_EQ(again.spec.lower_faces[q].from, bond.spec.lower_faces[q].from);
        EXPECT_EQ(again.spec.lower_faces[q].field, bond.spec.lower_faces[q].field);
      }
      ASSERT_EQ(again.node_faces_lo.size(), bond.node_faces_lo.size());
      for (std::size_t n = 0; n < bond.num_nodes(); ++n) {
        EXPECT_EQ(again.node_faces_lo[n].a, bond.node_faces_lo[n].a) << n;
        EXPECT_EQ(again.node_faces_lo[n].share, bond.node_faces_lo[n].share) << n;
      }
    }
  }
}

}  // namespace

TEST(CrackGrowth, a_crack_turned_onto_an_interface_between_bodies_splits_its_face) {
  check_turns_onto_the_bond(false);
}

TEST(CrackGrowth, a_crack_turned_onto_a_line_on_the_edge_of_its_reach_splits_its_face) {
  check_turns_onto_the_bond(true);
}

// The same crack turned 60 degrees towards a line with a tied stretch. It meets the line at
// x = 7.31 mm and its cut runs on along the line to the right edge, so the piece it cuts off
// (right of the meeting, below the line) takes the crack's field below it. A tied stretch left of
// the meeting (bonded_points to 3 mm; in one plate, the line drawn from the right edge to 3 mm,
// tied on to the left edge) keeps the line's pair of fields; to 7 mm, the crack's last segment
// would come within a cell of that intact stretch, and growth stops (a tip that reaches a tie is
// no junction: the material there is whole). One right of it (bonded_points from 12 mm; in one plate, the line drawn from
// the left edge to 12 mm, tied on to the right edge) gets its own pair, the line's other face and
// the crack's field below (State::bonded: an entry of its own, after the interfaces), on the
// nodes of that stretch; the line's own entry keeps the rest.
TEST(CrackGrowth, a_tied_stretch_the_cut_runs_along_joins_the_piece_beside_it) {
  struct Variant {
    std::string text;
    bool own_pair, stops;
  } const variants[] = {
      {bonded_bodies_with_a_crack("bonded_points = [[0.0, 0.006], [0.003, 0.006]]"), false, false},
      {bonded_bodies_with_a_crack("bonded_points = [[0.0, 0.006], [0.007, 0.006]]"), false, true},
      {bonded_bodies_with_a_crack("", true, "[[0.02, 0.006], [0.003, 0.006]]"), false, false},
      {bonded_bodies_with_a_crack("bonded_points = [[0.012, 0.006], [0.02, 0.006]]"), true, false},
      {bonded_bodies_with_a_crack("", true, "[[0.0, 0.006], [0.012, 0.006]]"), true, false},
  };
  for (std::size_t v = 0; v < std::size(variants); ++v) {
    const Case c = parse_case(variants[v].text);
    RunState s = make_run_state(c);
    bool through = false;
    const std::string error = turn_towards_the_bond(c, s, 60.0, through);
    if (variants[v].stops) {
      EXPECT_NE(error.find("interface 'bond''s tied extension"), std::string::npos) << error;
      continue;
    }
    EXPECT_EQ(error, "") << "variant " << v;
    EXPECT_TRUE(through) << "variant " << v;
    const State& L = s.levels[0];
    const std::size_t slot = s.interface_slots[0];
    const CohesiveInterface& bond = L.interfaces[slot];
    // The face below the line changes at the meeting (drawn right to left, that face is its
    // upper one, and the meeting is 20 - 7.31 mm along it).
    const bool reversed = bond.spec.geometry().x[0] > 0.01;
    const std::vector<FaceField>& below = reversed ? bond.spec.upper_faces : bond.spec.lower_faces;
    ASSERT_EQ(below.size(), 2u) << "variant " << v;
    EXPECT_NEAR(below[1].from, reversed ? 0.02 - 0.0073094 : 0.0073094, 1e-6) << "variant " << v;
    const int cut_below = below[reversed ? 0 : 1].field;  // the crack's field below, right of the meeting
    std::vector<BondedTie> own;
    for (const BondedTie& b : L.bonded)
      if (b.of == slot) own.push_back(b);
    ASSERT_EQ(L.bonded.size(), L.interfaces.size() + own.size()) << "the line's stretches after the interfaces";
    if (!variants[v].own_pair) {
      EXPECT_TRUE(own.empty()) << "variant " << v;
      EXPECT_EQ(L.bonded[slot].nodes, bonded_nodes(L.grid, bond.spec)) << "variant " << v;
      continue;
    }
    ASSERT_EQ(own.size(), 1u) << "variant " << v;
    const int above = reversed ? bond.spec.lower_field : bond.spec.upper_field;
    EXPECT_EQ(reversed ? own[0].lower_field : own[0].upper_field, above) << "variant " << v;
    EXPECT_EQ(reversed ? own[0].upper_field : own[0].lower_field, cut_below) << "variant " << v;
    EXPECT_EQ(own[0].nodes, bonded_nodes(L.grid, bond.spec)) << "its one tied stretch, all its nodes";
    EXPECT_TRUE(L.bonded[slot].nodes.empty()) << "variant " << v;
    std::printf("variant %zu: the tied stretch joins fields %d and %d (the line's pair: %d and %d), %zu nodes\n", v,
                own[0].upper_field, own[0].lower_field, bond.spec.upper_field, bond.spec.lower_field,
                own[0].nodes.size());
  }
}
