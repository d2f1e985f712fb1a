// Tests for parallel/halo.hpp on one process (the multi-process behaviour: tests/mpi/, label
// mpi): the reach of a block (its nodes and kHaloNodes more, clipped to the grid), the common
// nodes of two reaches, the particle record sent on migration (exact round trip), and a
// one-rank split that keeps every particle, starts the strain work from the elastic energy,
// owns every node and steps exactly as the plain solver.
#include <gtest/gtest.h>

#include <cmath>

#include "input/case_toml.hpp"
#include "parallel/halo.hpp"
#include "solver/energy.hpp"
#include "solver/step.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

Case strip() { return parse_case(test::strip_case_toml(), {}, "strip"); }

}  // namespace

TEST(Halo, reach_is_the_blocks_nodes_and_two_more_clipped_to_the_grid) {
  const State s = make_state(strip());
  const int nx = s.grid.nodes_x(), ny = s.grid.nodes_y();
  const NodeBox inner = reach_box(CellBlock{5, 9, 3, 6}, s.grid, kHaloNodes);
  EXPECT_EQ(inner.i0, 3);
  EXPECT_EQ(inner.i1, 11);  // nodes 5..9 of cells 5..8, and two more each side
  EXPECT_EQ(inner.j0, 1);
  EXPECT_EQ(inner.j1, 8);
  const NodeBox edge = reach_box(CellBlock{0, 2, 0, s.grid.y.cells}, s.grid, kHaloNodes);
  EXPECT_EQ(edge.i0, 0);
  EXPECT_EQ(edge.j1, ny - 1);
  EXPECT_LT(edge.i1, nx);
  // Two blocks that share a cut: their reaches share 2 x kHaloNodes + 1 node columns.
  const NodeBox a = reach_box(CellBlock{0, 10, 0, 4}, s.grid, kHaloNodes);
  const NodeBox b = reach_box(CellBlock{10, 20, 0, 4}, s.grid, kHaloNodes);
  const NodeBox ab = overlap(a, b);
  EXPECT_EQ(ab.i1 - ab.i0 + 1, 2 * kHaloNodes + 1);
  EXPECT_EQ(ab.count(), long(2 * kHaloNodes + 1) * long(4 + 1 + kHaloNodes));
  EXPECT_TRUE(overlap(reach_box(CellBlock{0, 3, 0, 3}, s.grid, kHaloNodes),
                      reach_box(CellBlock{12, 15, 0, 3}, s.grid, kHaloNodes)).empty());
}

TEST(Halo, a_migrating_particle_arrives_bit_for_bit) {
  State s = make_state(strip());
  Particles& P = s.particles;
  P.vx[7] = -1.0 / 3.0, P.sxy[7] = 2.5e6 * std::sqrt(2.0), P.id[7] = 4000000001u;
  double packed[Particles::kPacked];
  P.pack(7, packed);
  Particles copy;
  copy.push_packed(packed);
  ASSERT_EQ(copy.size(), 1u);
  for (auto [a, b] : {std::pair{&P.x, &copy.x}, {&P.y, &copy.y}, {&P.vx, &copy.vx}, {&P.vy, &copy.vy},
                      {&P.mass, &copy.mass}, {&P.volume0, &copy.volume0}, {&P.half_x, &copy.half_x},
                      {&P.half_y, &copy.half_y}, {&P.sxx, &copy.sxx}, {&P.syy, &copy.syy},
                      {&P.sxy, &copy.sxy}})
    EXPECT_EQ((*a)[7], (*b)[0]);
  EXPECT_EQ(copy.field[0], P.field[7]);
  EXPECT_EQ(copy.material[0], P.material[7]);
  EXPECT_EQ(copy.id[0], 4000000001u);
}

TEST(Halo, one_rank_keeps_everything_and_steps_as_the_plain_solver) {
  const Case c = strip();
  State plain = make_state(c);
  State one = make_state(c);
  distribute(one, Comm::single());
  ASSERT_TRUE(one.halo);
  EXPECT_TRUE(halo_of(one).peers.empty());
  EXPECT_EQ(one.particles.size(), plain.particles.size());
  EXPECT_EQ(one.strain_work, strain_energy(one.particles, one.stiffness));
  for (std::size_t n = 0; n < one.grid.num_nodes(); ++n) ASSERT_TRUE(counts_node(one, 0, n));
  plain.dt_cap = one.dt_cap = INFINITY;
  for (int k = 0; k < 20; ++k) {
    step(plain);
    step(one);
  }
  // No peers: the halo sums change nothing; only the migration check's re-sort may reorder
  // sums, and none is due in 20 steps of a slow push.
  EXPECT_EQ(halo_of(one).migrations, 0);
  ASSERT_EQ(one.particles.size(), plain.particles.size());
  for (std::size_t p = 0; p < plain.particles.size(); ++p) {
    ASSERT_EQ(one.particles.id[p], plain.particles.id[p]);
    EXPECT_EQ(one.particles.x[p], plain.particles.x[p]);
    EXPECT_EQ(one.particles.vy[p], plain.particles.vy[p]);
    EXPECT_EQ(one.particles.sxy[p], plain.particles.sxy[p]);
  }
  EXPECT_EQ(one.external_work, plain.external_work);
}
