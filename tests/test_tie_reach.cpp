// Tests of the tie's reach (solver/cohesive_step.hpp, bonded_nodes): where a body is split
// along a line and tied over it, the two fields must share every grid node that particles of
// both reach, or the split body is not the undivided one. The tie takes the nodes within
// 2 (|n_x| h_x + |n_y| h_y) of its line (what a particle within half a cell of it reaches) and as
// far beyond an end, except at a crack's tip, where it stops exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/state.hpp"
#include "support_run.hpp"

#include "support_lines.hpp"

using namespace rupture;

namespace {

Polyline line(std::vector<double> x, std::vector<double> y) { return test::polyline(std::move(x), std::move(y)); }

// Cells of 1 m, node i at x = i.
Grid unit_grid(int nx, int ny) {
  Grid g;
  g.x.h = 1.0, g.x.cells = nx;
  g.y.h = 1.0, g.y.cells = ny;
  return g;
}

bool has(const std::vector<std::size_t>& v, std::size_t n) { return std::binary_search(v.begin(), v.end(), n); }

const std::string kSite = std::string(RUPTURE_SOURCE_DIR) + "/tests/inputs/nucleation_site.toml";

}  // namespace

// A horizontal tie on a grid line from a crack's tip at x = 5 to the edge at x = 20 (cells of
// 1): the rows at distance 0 and 1 are tied (2 excluded: strictly closer than 2 h); not a node
// behind the tip; beyond the free end one column (at 1 < 2 h beyond), not two.
TEST(TieReach, ARowEitherSideAndBeyondTheFreeEndNotBehindTheTip) {
  const Grid g = unit_grid(20, 10);
  const Polyline crack = line({0.0, 5.0}, {5.0, 5.0});
  const Polyline tie = line({5.0, 15.0}, {5.0, 5.0});
  const std::vector<std::size_t> n = bonded_nodes(g, {tie}, crack);
  for (int j = 0; j < g.nodes_y(); ++j)
    for (int i = 0; i < g.nodes_x(); ++i) {
      const bool expect = i >= 5 && i <= 16 && std::abs(j - 5) <= 1;
      EXPECT_EQ(has(n, g.node_index(i, j)), expect) << "node (" << i << ", " << j << ")";
    }
  // The same tie with its other end at a tip too (a crack beyond x = 15): exact at both.
  const std::vector<std::size_t> both = bonded_nodes(g, {tie}, line({5.0, 15.0}, {5.0, 5.0}));
  EXPECT_FALSE(has(both, g.node_index(16, 5)));
  EXPECT_TRUE(has(both, g.node_index(15, 5)));
  EXPECT_FALSE(has(both, g.node_index(4, 5)));
}

// A bonded stretch of a closed line (its ends on the line, where the open part begins) stops
// exactly at both ends: the open part's two fields stay apart there.
TEST(TieReach, AStretchOfAClosedLineStopsAtBothEnds) {
  const Grid g = unit_grid(20, 10);
  Polyline square = line({5.0, 15.0, 15.0, 5.0}, {5.0, 5.0, 8.0, 8.0});
  square.closed = true;
  const std::vector<std::size_t> n = bonded_nodes(g, {line({7.0, 12.0}, {5.0, 5.0})}, square);
  for (int j = 0; j < g.nodes_y(); ++j)
    for (int i = 0; i < g.nodes_x(); ++i) {
      const bool expect = i >= 7 && i <= 12 && std::abs(j - 5) <= 1;
      EXPECT_EQ(has(n, g.node_index(i, j)), expect) << "node (" << i << ", " << j << ")";
    }
}

// Turned by 90 degrees the tie takes the turned nodes: the reach is read along the line's
// normal, whichever axis it is.
TEST(TieReach, TurnedTieTakesTheTurnedNodes) {
  const Grid g = unit_grid(10, 20);
  const std::vector<std::size_t> n =
      bonded_nodes(g, {line({5.0, 5.0}, {5.0, 15.0})}, line({5.0, 5.0}, {0.0, 5.0}));
  for (int j = 0; j < g.nodes_y(); ++j)
    for (int i = 0; i < g.nodes_x(); ++i) {
      const bool expect = j >= 5 && j <= 16 && std::abs(i - 5) <= 1;
      EXPECT_EQ(has(n, g.node_index(i, j)), expect) << "node (" << i << ", " << j << ")";
    }
}

// The physics: a plate split along a 4 mm line (a site that does not come loose: its tie runs
// over the line and on to the edges) under a uniform prestress moves as the plate without the
// line, particle for particle, to the bit, as the release waves from its free edges cross it
// (15 us): horizontal (on a grid line) and at 30 degrees. With the tie's earlier reach (the
// support without the particles' half-width, no reach beyond the ends) the stations beside the
// line differed by 0.09 % at 30 degrees.
TEST(TieReach, SplitAndTiedPlateIsTheUndividedPlate) {
  const std::string text = test::read_text(kSite);
  ASSERT_FALSE(text.empty());
  const std::size_t a = text.find("[interface.site]"), b = text.find("[time]");
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  const std::string plain = text.substr(0, a) + text.substr(b);
  for (const double deg : {0.0, 30.0}) {
    const std::vector<std::string> sets{"parameters.ratio=0.5",
                                        "parameters.c=" + std::to_string(std::cos(deg * M_PI / 180.0)),
                                        "parameters.s=" + std::to_string(std::sin(deg * M_PI / 180.0)),
                                        "time.end=15e-6"};
    State split = make_state(parse_case(text, sets));
    State whole = make_state(parse_case(plain, sets));
    ASSERT_EQ(split.particles.size(), whole.particles.size());
    test::run_to(split, 15e-6);
    test::run_to(whole, 15e-6);
    ASSERT_EQ(split.step, whole.step);
    // Particle for particle by where it was made (the split body's are numbered by field).
    const auto key = [](const Particles& P, std::size_t q) { return std::make_pair(P.x0[q], P.y0[q]); };
    std::map<std::pair<double, double>, std::size_t> at;
    for (std::size_t q = 0; q < whole.particles.size(); ++q) at[key(whole.particles, q)] = q;
    ASSERT_EQ(at.size(), whole.particles.size());
    double worst = 0.0, moved = 0.0;
    for (std::size_t q = 0; q < split.particles.size(); ++q) {
      const auto found = at.find(key(split.particles, q));
      ASSERT_NE(found, at.end());
      const std::size_t w = found->second;
      worst = std::max({worst, std::fabs(split.particles.x[q] - whole.particles.x[w]),
                        std::fabs(split.particles.y[q] - whole.particles.y[w])});
      moved = std::max({moved, std::fabs(whole.particles.x[w] - whole.particles.x0[w]),
                        std::fabs(whole.particles.y[w] - whole.particles.y0[w])});
    }
    std::printf("%g degrees: %ld steps, particles moved up to %.3g m, split against undivided %.3g m\n", deg,
                whole.step, moved, worst);
    EXPECT_GT(moved, 1e-6) << deg << " degrees: the plate moved";
    EXPECT_LE(worst, 1e-9 * moved) << deg << " degrees (round-off)";
  }
}
