// Tests for parallel/halo_nested.hpp on one process (the multi-process runs: tests/mpi/, label
// mpi): the common split's blocks tile every level's lattice and are the same rectangle of the
// plate on every level (sides moved down to a coarser level's lines), and the reaches close the transitions: a rank holding only its reaches'
// values (random, every node) condenses and distributes to the one-process values at every node
// its particles may touch, which the touched nodes alone do not.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "input/case_toml.hpp"
#include "parallel/halo.hpp"
#include "parallel/halo_nested.hpp"
#include "solver/step.hpp"

using namespace rupture;

namespace {

// The reference problem on nested levels 0-2 (finest 0.5 mm), the plate cropped as the mpi
// agreement test's.
RunState nested_reference() {
  return make_run_state(load_case(std::string(RUPTURE_SOURCE_DIR) + "/examples/rosakis1999.toml",
                              {"grid.refinement=\"nested\"", "grid.min=[0.0,-0.06]", "grid.max=[0.125,0.04]",
                               "bodies.upper.max=[0.125,0.04]", "bodies.lower.min=[0.0,-0.06]"}));
}

// Node (i, j) of level l as a global node id of the nested grid.
std::size_t global_id(const RunState& n, std::size_t l, int i, int j) {
  return n.grid.level_start[l] + n.grid.levels[l].node_index(i, j);
}

// Every (level, rank): nodes of the touched box (block and nested_touched_width) where the
// one-process condense + distribute and the rank's (holding `reaches` only) differ.
long mismatches(const RunState& n, const NestedSplit& sp, const std::vector<std::vector<NodeBox>>& reaches) {
  const std::size_t levels = n.levels.size(), N = n.grid.num_nodes();
  std::vector<unsigned char> inactive(N, 0);  // covered slaves no particle reaches: zero
  for (const std::uint32_t s : n.grid.slaves) inactive[s] = 1;
  for (const std::uint32_t k : n.active_slaves) inactive[n.grid.slaves[k]] = 0;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(N);
  for (std::size_t g = 0; g < N; ++g) v[g] = inactive[g] ? 0.0 : u(rng);
  std::vector<double> ref = v;
  condense_to_dofs(n.grid, ref.data());
  spread_to_slaves(n.grid, ref.data());
  long bad = 0;
  for (std::size_t r = 0; r < sp.cut.block.size(); ++r) {
    std::vector<double> mine(N, 0.0);
    for (std::size_t l = 0; l < levels; ++l) {
      const NodeBox& b = reaches[l][r];
      for (int j = b.j0; j <= b.j1; ++j)
        for (int i = b.i0; i <= b.i1; ++i) mine[global_id(n, l, i, j)] = v[global_id(n, l, i, j)];
    }
    condense_to_dofs(n.grid, mine.data());
    spread_to_slaves(n.grid, mine.data());
    for (std::size_t l = 0; l < levels; ++l) {
      if (sp.blocks[l][r].cells() == 0) continue;
      const NodeBox t = reach_box(sp.blocks[l][r], n.levels[l].grid, nested_touched_width(n, int(l)));
      for (int j = t.j0; j <= t.j1; ++j)
        for (int i = t.i0; i <= t.i1; ++i) {
          const std::size_t g = global_id(n, l, i, j);
          bad += !inactive[g] && mine[g] != ref[g];
        }
    }
  }
  return bad;
}

}  // namespace

TEST(HaloNested, every_level_is_tiled_by_the_same_rectangles_of_the_plate) {
  const RunState n = nested_reference();
  ASSERT_EQ(n.levels.size(), 3u);
  for (int ranks : {1, 2, 3, 4, 7, 40}) {
    const NestedSplit sp = split_nested(n, ranks);
    EXPECT_EQ(sp.cut_level, 2);  // the finest level's cells over the plate: 276 x 624, few enough
    const Grid& g0 = n.levels[0].grid;
    const double cut = g0.x.h / double(1 << sp.cut_level), tol = 1e-12;
    for (std::size_t l = 0; l < n.levels.size(); ++l) {
      const Grid& g = n.levels[l].grid;
      std::vector<int> owners(std::size_t(g.x.cells) * std::size_t(g.y.cells), 0);
      // A side of the block on the level's lattice: the cut's line on levels as fine as the
      // cut level, the level's line at or below it on coarser ones.
      const auto side = [&](const Axis& a, int k, double line) {
        if (int(l) >= sp.cut_level) {
          EXPECT_NEAR(a.node(k), line, tol);
        } else {
          EXPECT_LE(a.node(k), line + tol);
          EXPECT_GT(a.node(k) + a.h, line + tol);
        }
      };
      for (int r = 0; r < ranks; ++r) {
        const CellBlock& b = sp.blocks[l][std::size_t(r)];
        const CellBlock& c = sp.cut.block[std::size_t(r)];
        for (int y = b.r0; y < b.r1; ++y)
          for (int x = b.c0; x < b.c1; ++x) ++owners[std::size_t(x) + std::size_t(y) * std::size_t(g.x.cells)];
        if (b.cells() == 0) continue;
        if (b.c0 > 0) side(g.x, b.c0, g0.x.origin + c.c0 * cut);
        if (b.c1 < g.x.cells) side(g.x, b.c1, g0.x.origin + c.c1 * cut);
        if (b.r0 > 0) side(g.y, b.r0, g0.y.origin + c.r0 * cut);
        if (b.r1 < g.y.cells) side(g.y, b.r1, g0.y.origin + c.r1 * cut);
      }
      for (const int o : owners) ASSERT_EQ(o, 1) << "level " << l << ", " << ranks << " ranks";
    }
  }
}

TEST(HaloNested, the_reaches_give_the_one_process_transitions_at_every_touched_node) {
  const RunState n = nested_reference();
  for (int ranks : {2, 3, 4, 16}) {
    const NestedSplit sp = split_nested(n, ranks);
    EXPECT_EQ(mismatches(n, sp, sp.reaches), 0) << ranks << " ranks";
    // The touched nodes alone miss slaves of DOFs the particles read (the test can fail).
    std::vector<std::vector<NodeBox>> touched = sp.reaches;
    for (std::size_t l = 0; l < touched.size(); ++l)
      for (std::size_t r = 0; r < touched[l].size(); ++r) {
        const CellBlock& b = sp.blocks[l][r];
        touched[l][r] = b.cells() > 0 ? reach_box(b, n.levels[l].grid, nested_touched_width(n, int(l))) : NodeBox{};
        // Each reach holds the touched nodes.
        EXPECT_EQ(overlap(touched[l][r], sp.reaches[l][r]).count(), touched[l][r].count());
      }
    EXPECT_GT(mismatches(n, sp, touched), 0) << ranks << " ranks";
  }
}
