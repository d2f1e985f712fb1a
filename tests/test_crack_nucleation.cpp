// Tests of solver/crack_nucleation.hpp: a line that nucleates is tied over itself until the
// normal stress across it reaches the strength, read from the particles near each segment;
// then its tie is the set-up's extension again, and growth records when it came loose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "input/case_toml.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/crack_growth.hpp"
#include "solver/crack_nucleation.hpp"
#include "solver/run_state.hpp"
#include "solver/state.hpp"

using namespace rupture;

namespace {

const std::string kSite = std::string(RUPTURE_SOURCE_DIR) + "/tests/inputs/nucleation_site.toml";

Case site(double ratio) {
  return load_case(kSite, {"parameters.ratio=" + std::to_string(ratio)});
}

Polyline line(std::vector<double> x, std::vector<double> y) {
  Polyline p;
  p.x = std::move(x), p.y = std::move(y);
  return p;
}

bool same(const Polyline& a, const Polyline& b) {
  if (a.num_vertices() != b.num_vertices()) return false;
  for (std::size_t i = 0; i < a.num_vertices(); ++i)
    if (std::abs(a.x[i] - b.x[i]) > 1e-12 || std::abs(a.y[i] - b.y[i]) > 1e-12) return false;
  return true;
}

}  // namespace

// The drawn line joins the ties that meet its ends, whichever way each runs; a tie elsewhere
// stays apart.
TEST(CrackNucleation, DormantTiesRunOverTheDrawnLine) {
  InterfaceSpec is;
  is.line = line({0.0, 0.0}, {0.0, 1.0});
  is.bonded_lines = {line({0.0, 0.0}, {1.0, 3.0}), line({0.0, 0.0}, {0.0, -2.0}), line({5.0, 6.0}, {0.0, 0.0})};
  is.bonded = true;
  const std::vector<Polyline> t = dormant_ties(is, 1e-9);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_TRUE(same(t[0], line({0.0, 0.0, 0.0, 0.0}, {-2.0, 0.0, 1.0, 3.0})));
  EXPECT_TRUE(same(t[1], line({5.0, 6.0}, {0.0, 0.0})));
  // Reversed ties join the same way.
  is.bonded_lines = {line({0.0, 0.0}, {3.0, 1.0}), line({0.0, 0.0}, {-2.0, 0.0})};
  const std::vector<Polyline> r = dormant_ties(is, 1e-9);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(same(r[0], line({0.0, 0.0, 0.0, 0.0}, {-2.0, 0.0, 1.0, 3.0})));
  // A line that does not nucleate starts as drawn.
  EXPECT_EQ(as_set_up(is, 1e-9).bonded_lines.size(), 2u);
  is.nucleation_strength = 1.0;
  EXPECT_EQ(as_set_up(is, 1e-9).bonded_lines.size(), 1u);
}

// Under the plate's uniform initial stress every segment reads n . sigma . n of the line's
// normal at 30 degrees (ratio x 2 MPa), whatever the stress elsewhere: particles farther than a
// cell from the line do not count.
TEST(CrackNucleation, SiteStressIsTheNormalStressAcrossTheLine) {
  const Case c = site(0.99);
  State s = make_state(c);
  const CohesiveInterface& in = s.interfaces[0];
  const double h = c.grid.cell_size;
  EXPECT_NEAR(site_stress(s, in, h), 0.99 * 2e6, 1e-9 * 2e6);
  // Far particles carry any stress: still the same reading.
  const double cx = 0.02, cy = 0.02;
  int changed = 0;
  for (std::size_t q = 0; q < s.particles.size(); ++q)
    if (std::hypot(s.particles.x0[q] - cx, s.particles.y0[q] - cy) > 0.0035) s.particles.syy[q] = 1e12, ++changed;
  EXPECT_GT(changed, 1000);
  EXPECT_NEAR(site_stress(s, in, h), 0.99 * 2e6, 1e-9 * 2e6);
  // One particle near the middle segments loaded more raises the largest segment mean.
  for (std::size_t q = 0; q < s.particles.size(); ++q)
    if (std::hypot(s.particles.x0[q] - cx, s.particles.y0[q] - cy) < 0.0004) s.particles.syy[q] += 1e7;
  EXPECT_GT(site_stress(s, in, h), 0.99 * 2e6 + 1e5);
}

// Intact until it comes loose: the tie runs over the drawn line (its middle's nodes tied), growth
// below the strength leaves it so, and at the strength it comes loose at once: the tie is the
// set-up's (the line's own nodes no longer tied), and the time is recorded.
TEST(CrackNucleation, ComesLooseAtTheStrength) {
  for (const double ratio : {0.99, 1.01}) {
    const Case c = site(ratio);
    RunState s = make_run_state(c);
    State& L = s.levels[0];
    const Grid& g = L.grid;
    const int i = int(std::lround((0.02 - g.x.origin) / g.x.h)), j = int(std::lround((0.02 - g.y.origin) / g.y.h));
    const std::size_t middle = g.node_index(i, j);  // the node at the line's middle (20, 20) mm
    const auto tied = [&] {
      const std::vector<std::size_t>& n = L.bonded[0].nodes;
      return std::find(n.begin(), n.end(), middle) != n.end();
    };
    EXPECT_TRUE(tied());
    std::vector<CrackGrowthRecord> records;
    s.time = 1e-7;
    grow_cracks(c, s, records);
    ASSERT_EQ(records.size(), 1u);
    if (ratio < 1.0) {
      EXPECT_FALSE(records[0].nucleated());
      EXPECT_TRUE(tied());
      continue;
    }
    EXPECT_EQ(records[0].nucleation_time, 1e-7);
    EXPECT_FALSE(tied());
    EXPECT_EQ(L.bonded[0].nodes, bonded_nodes(g, c.interfaces[0]));
    EXPECT_FALSE(records[0].grown());  // it grows from the next step on, by its criterion
    // A restore lays the set-up's tie again from the record.
    RunState r = make_run_state(c);
    regrow_cracks(c, r, records);
    EXPECT_EQ(r.levels[0].bonded[0].nodes, L.bonded[0].nodes);
  }
}
