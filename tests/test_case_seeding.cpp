// Tests of solver/case_seeding.hpp (a case's particles at t = 0 without storing them, and a
// State holding some of them), the snapshots' rows (output/snapshot.hpp: SnapshotRows) and the
// stations' choice of particle (output/stations.hpp: NearestParticle): what a distributed run's
// ranks compute alone must be what one process computes from every particle.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "output/snapshot.hpp"
#include "output/stations.hpp"
#include "solver/case_seeding.hpp"
#include "solver/state.hpp"

using namespace rupture;

namespace {

std::string example(const std::string& name) {
  std::ifstream in(std::string(RUPTURE_SOURCE_DIR) + "/examples/" + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Cases that take every seeding path: polygons with an oblique traction on a staircase edge
// (point-in-shape seeding, the traction shared by nearest particles), a graded grid (graded
// rectangles), circles and a body with a hole, and plain rectangles on a uniform grid.
std::vector<Case> cases() {
  std::vector<Case> out;
  out.push_back(parse_case(example("inclined_weak_plane.toml") + R"(
[loads.top]
type = "traction"
from = [-0.015, 0.0259807621]
to = [0.0456217783, 0.0609807621]
traction = [0.0, 1.0e6]
)"));
  // The seeding of one grid: the example's boxes as the graded grid (nested levels seed each
  // level's region: tests/verification/test_nested_solver.cpp).
  out.push_back(parse_case(example("rosakis1999.toml"), {"grid.refinement=\"graded\""}));
  out.push_back(parse_case(example("inclusion.toml")));
  out.push_back(parse_case(example("rosakis1999.toml"), {"grid.coarse_cell_size=0", "grid.cell_size=1e-3"}));
  return out;
}

int cell_index(const Grid& g, double x, double y) {
  const int i = std::clamp(g.x.cell_of(x), 0, g.x.cells - 1), j = std::clamp(g.y.cell_of(y), 0, g.y.cells - 1);
  return i + j * g.x.cells;
}

}  // namespace

// The count per cell, the number and the lightest mass: those of the particles make_state makes.
TEST(CaseSeeding, tally_counts_the_particles_make_state_makes_per_cell) {
  for (const Case& c : cases()) {
    const State s = make_state(c);
    const CaseTally t = tally_case_points(c, s.grid);
    std::vector<std::uint32_t> count(std::size_t(s.grid.x.cells) * std::size_t(s.grid.y.cells), 0);
    double lightest = 1e300;
    for (std::size_t p = 0; p < s.particles.size(); ++p) {
      ++count[std::size_t(cell_index(s.grid, s.particles.x[p], s.particles.y[p]))];
      lightest = std::min(lightest, s.particles.mass[p]);
    }
    EXPECT_EQ(t.particles, s.particles.size()) << c.title;
    EXPECT_TRUE(t.per_cell == count) << c.title;
    EXPECT_EQ(t.min_mass, lightest) << c.title;
    std::uint32_t visited = 0;  // ids 0, 1, ... in the visiting order
    for_each_case_point(c, s.grid, [&](const SeedPoint&, std::size_t, std::uint32_t id) { EXPECT_EQ(id, visited++); });
    EXPECT_EQ(visited, s.particles.size());
  }
}

// Parts of the plane (3 stripes of cells, and one part with nothing) each make their particles:
// together every particle of make_state once, bit for bit, with its id; the traction patches
// found among the particles near the segments are the whole set-up's.
TEST(CaseSeeding, owned_parts_make_every_particle_once_bit_for_bit) {
  for (const Case& c : cases()) {
    const State whole = make_state(c);
    const Particles& W = whole.particles;
    std::map<std::uint32_t, std::size_t> at;
    for (std::size_t p = 0; p < W.size(); ++p) at[W.id[p]] = p;
    std::vector<int> seen(W.size(), 0);
    const int cols = whole.grid.x.cells;
    for (int part = 0; part < 4; ++part) {
      ParticleShare share;
      share.own = [&](double x, double y) {
        return part < 3 && (cell_index(whole.grid, x, y) % cols) * 3 / cols == part;
      };
      const State s = make_state(c, &share);
      const Particles& P = s.particles;
      if (part == 3) {
        EXPECT_EQ(P.size(), 0u) << c.title;
      }
      for (std::size_t p = 0; p < P.size(); ++p) {
        const auto it = at.find(P.id[p]);
        ASSERT_NE(it, at.end()) << c.title << ": id " << P.id[p];
        const std::size_t q = it->second;
        ++seen[q];
        EXPECT_TRUE(P.x[p] == W.x[q] && P.y[p] == W.y[q] && P.vx[p] == W.vx[q] && P.vy[p] == W.vy[q] &&
                    P.mass[p] == W.mass[q] && P.volume0[p] == W.volume0[q] && P.half_x[p] == W.half_x[q] &&
                    P.half_y[p] == W.half_y[q] && P.sxx[p] == W.sxx[q] && P.syy[p] == W.syy[q] &&
                    P.sxy[p] == W.sxy[q] && P.field[p] == W.field[q] && P.material[p] == W.material[q])
            << c.title << ": particle " << P.id[p];
      }
      ASSERT_EQ(s.loads.patches.size(), whole.loads.patches.size());
      for (std::size_t k = 0; k < s.loads.patches.size(); ++k) {
        EXPECT_EQ(s.loads.patches[k].ids, whole.loads.patches[k].ids) << c.title;
        EXPECT_EQ(s.loads.patches[k].length, whole.loads.patches[k].length) << c.title;
        EXPECT_EQ(s.loads.patches[k].normal[0], whole.loads.patches[k].normal[0]) << c.title;
        EXPECT_EQ(s.loads.patches[k].normal[1], whole.loads.patches[k].normal[1]) << c.title;
      }
      EXPECT_EQ(s.bc_nodes.size(), whole.bc_nodes.size()) << c.title;
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), long(W.size())) << c.title << ": every particle once";
  }
  // The example's own traction and the one added on the oblique edge (a 70 mm staircase of
  // 0.25 mm particles: shared among its nearest surface particles) were both compared.
  const State s = make_state(cases()[0]);
  ASSERT_EQ(s.loads.patches.size(), 2u);
  EXPECT_GT(s.loads.patches[1].ids.size(), 100u);
}

// Rows as runs of ids: the row of every id equals its place among the ids held (the dense
// table one process used to keep), with as many runs as maximal runs of consecutive ids.
TEST(SnapshotRows, runs_give_every_held_id_its_place_in_id_order) {
  std::mt19937 rng(7);
  for (const double keep : {1.0, 0.97, 0.5, 0.03}) {
    std::bernoulli_distribution held(keep);
    SnapshotRows rows;
    std::vector<std::int64_t> dense(20000, -1);
    std::int64_t next = 0;
    long runs = 0;
    bool previous = false;
    for (std::uint32_t id = 0; id < dense.size(); ++id) {
      const bool h = held(rng);
      if (h) rows.add(id), dense[id] = next++;
      runs += h && !previous;
      previous = h;
    }
    EXPECT_EQ(rows.rows, next);
    EXPECT_EQ(long(rows.first_id.size()), runs) << keep;
    for (std::uint32_t id = 0; id < dense.size() + 5; ++id)
      ASSERT_EQ(rows.row(id), id < dense.size() ? dense[id] : -1) << "id " << id << ", kept " << keep;
  }
  Particles p;  // from particles in any order: the rows of their ids sorted
  for (const std::uint32_t id : {9u, 3u, 4u, 0u, 5u}) {
    p.resize(p.size() + 1);
    p.id.back() = id;
    p.x.back() = double(id), p.y.back() = 0.0;
  }
  const double region[4] = {0.0, -1.0, 8.0, 1.0};  // id 9 outside
  const SnapshotRows r = snapshot_rows(p, region);
  EXPECT_EQ(r.rows, 4);
  EXPECT_EQ(r.row(0), 0);
  EXPECT_EQ(r.row(3), 1);
  EXPECT_EQ(r.row(5), 3);
  EXPECT_EQ(r.row(9), -1);
  EXPECT_EQ(r.row(1), -1);
}

// A station equally near several particles reads the lowest id, whatever their order.
TEST(Stations, nearest_particle_is_the_lowest_id_among_equally_near_ones) {
  const double xs[4] = {-1.0, 1.0, -1.0, 1.0}, ys[4] = {-1.0, -1.0, 1.0, 1.0};
  std::vector<std::uint32_t> ids = {12, 5, 40, 7};
  for (int shuffle = 0; shuffle < 4; ++shuffle) {
    NearestParticle n{0.0, 0.0};
    for (int k = 0; k < 4; ++k) n.visit(xs[(k + shuffle) % 4], ys[(k + shuffle) % 4], ids[std::size_t((k + shuffle) % 4)]);
    n.visit(3.0, 0.0, 1);  // farther
    EXPECT_EQ(n.id, 5u) << shuffle;
  }
  NearestParticle m{0.9, 0.9};
  for (int k = 0; k < 4; ++k) m.visit(xs[k], ys[k], ids[std::size_t(k)]);
  EXPECT_EQ(m.id, 7u);
}
