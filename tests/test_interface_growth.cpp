// Tests of cohesive/interface_growth.hpp: a crack tip's new segment at either end of a
// pre-crack keeps every existing node's and Gauss point's state where it was (the jumps, the
// law history), has the geometry asked for (its length, its normal: the direction turned +90
// degrees), arc lengths from the new start, and a new node with no jump (intact material).
#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

#include "cohesive/interface_growth.hpp"

namespace rupture {
namespace {

CohesiveInterface precrack() {
  InterfaceSpec s;
  s.line.x = {0.0, 1.0, 2.0};
  s.line.y = {0.0, 0.0, 0.5};
  s.segments = 4;
  s.precracked = true;
  s.contact = true;
  CohesiveInterface c = make_interface(s);
  for (std::size_t k = 0; k < c.num_nodes(); ++k)
    c.ux_up[k] = 0.1 * double(k), c.uy_lo[k] = -0.01 * double(k), c.node_slip_path[k] = double(k);
  for (std::size_t i = 0; i < c.gp_dn.size(); ++i) c.gp_dn[i] = 1e-3 * double(i), c.gp_slip[i] = double(i);
  c.time = 2.5e-6;
  c.work = 3.0;
  c.light_face_mass = 1.5e-4;
  return c;
}

TEST(InterfaceGrowth, NewSegmentAtTheEndKeepsEveryStateAndHasTheAskedGeometry) {
  const CohesiveInterface before = precrack();
  CohesiveInterface c = before;
  const double a = 0.3, th = 0.7;  // a segment of length 0.3 at 0.7 rad
  const std::size_t n = before.num_nodes();
  extend_interface(c, LineEnd::end, 2.0 + a * std::cos(th), 0.5 + a * std::sin(th), 0.25, -0.05);
  ASSERT_EQ(c.num_nodes(), n + 1);
  ASSERT_EQ(c.num_segments(), before.num_segments() + 1);
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_DOUBLE_EQ(c.x0[k], before.x0[k]);
    EXPECT_DOUBLE_EQ(c.y0[k], before.y0[k]);
    EXPECT_DOUBLE_EQ(c.s0[k], before.s0[k]);
    EXPECT_EQ(c.ux_up[k], before.ux_up[k]);
    EXPECT_EQ(c.uy_lo[k], before.uy_lo[k]);
    EXPECT_EQ(c.node_slip_path[k], before.node_slip_path[k]);
  }
  for (std::size_t i = 0; i < before.gp_dn.size(); ++i) {
    EXPECT_EQ(c.gp_dn[i], before.gp_dn[i]);
    EXPECT_EQ(c.gp_slip[i], before.gp_slip[i]);
  }
  for (std::size_t s = 0; s < before.num_segments(); ++s) {
    EXPECT_NEAR(c.seg_nx[s], before.seg_nx[s], 1e-15);
    EXPECT_NEAR(c.seg_ny[s], before.seg_ny[s], 1e-15);
  }
  const std::size_t s = c.num_segments() - 1;
  EXPECT_NEAR(c.seg_length[s], a, 1e-14);
  EXPECT_NEAR(c.seg_nx[s], -std::sin(th), 1e-14);
  EXPECT_NEAR(c.seg_ny[s], std::cos(th), 1e-14);
  EXPECT_NEAR(c.length(), before.length() + a, 1e-14);
  EXPECT_EQ(c.light_face_mass, before.light_face_mass);
  EXPECT_EQ(c.ux_up[n], 0.25);
  EXPECT_EQ(c.ux_lo[n], 0.25);
  EXPECT_EQ(c.uy_up[n], -0.05);
  EXPECT_EQ(c.jump_x(n), 0.0);
  EXPECT_EQ(c.jump_y(n), 0.0);
  EXPECT_EQ(c.node_crack_time[n], before.time);  // a pre-crack's new node: cracked now
  for (int q = 0; q < CohesiveInterface::kGauss; ++q) EXPECT_EQ(c.gp_separated[s * 4 + std::size_t(q)], 1);
  EXPECT_EQ(c.time, before.time);
  EXPECT_EQ(c.work, before.work);
}

TEST(InterfaceGrowth, NewSegmentAtTheStartShiftsTheStateByOneNodeAndOneSegment) {
  const CohesiveInterface before = precrack();
  CohesiveInterface c = before;
  extend_interface(c, LineEnd::start, -0.2, -0.1, 0.0, 0.0);
  const std::size_t n = before.num_nodes();
  ASSERT_EQ(c.num_nodes(), n + 1);
  const double first = std::hypot(0.2, 0.1);
  EXPECT_NEAR(c.seg_length[0], first, 1e-15);
  // The normal of the new first piece, drawn from (-0.2, -0.1) to (0, 0).
  EXPECT_NEAR(c.seg_nx[0], -0.1 / first, 1e-14);
  EXPECT_NEAR(c.seg_ny[0], 0.2 / first, 1e-14);
  for (std::size_t k = 0; k < n; ++k) {
    EXPECT_DOUBLE_EQ(c.x0[k + 1], before.x0[k]);
    EXPECT_NEAR(c.s0[k + 1], before.s0[k] + first, 1e-14);
    EXPECT_EQ(c.ux_up[k + 1], before.ux_up[k]);
    EXPECT_EQ(c.node_slip_path[k + 1], before.node_slip_path[k]);
  }
  for (std::size_t i = 0; i < before.gp_dn.size(); ++i) EXPECT_EQ(c.gp_slip[i + 4], before.gp_slip[i]);
  EXPECT_EQ(c.ux_up[0], 0.0);
  EXPECT_EQ(c.jump_x(0), 0.0);
}

TEST(InterfaceGrowth, TipsAreTheEndsThatMeetABondedStretchPointingOutward) {
  InterfaceSpec s;
  s.line.x = {0.0, 1.0, 2.0};
  s.line.y = {0.0, 0.0, 1.0};
  Polyline tie;  // beyond the end only: an edge crack from the start
  tie.x = {2.0, 3.0};
  tie.y = {1.0, 2.0};
  s.bonded_lines = {tie};
  s.bonded = true;
  std::vector<CrackTip> tips = precrack_tips(s, 1e-9);
  ASSERT_EQ(tips.size(), 1u);
  EXPECT_EQ(tips[0].end, LineEnd::end);
  EXPECT_DOUBLE_EQ(tips[0].frame.x, 2.0);
  EXPECT_NEAR(tips[0].frame.e1x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(tips[0].frame.e1y, std::sqrt(0.5), 1e-15);
  Polyline back;  // and one before the start: a crack inside the body, two tips
  back.x = {-1.0, 0.0};
  back.y = {0.0, 0.0};
  s.bonded_lines.push_back(back);
  tips = precrack_tips(s, 1e-9);
  ASSERT_EQ(tips.size(), 2u);
  EXPECT_EQ(tips[0].end, LineEnd::start);
  EXPECT_DOUBLE_EQ(tips[0].frame.e1x, -1.0);
  s.bonded_lines.clear();
  s.bonded = false;
  EXPECT_TRUE(precrack_tips(s, 1e-9).empty());  // edge to edge: nothing to grow into
}

}  // namespace
}  // namespace rupture

namespace rupture {
namespace {

// A cohesive crack drawn open (drawn_open): the drawn points start separated, as a pre-crack's,
// and the segments it grows at either end carry the law (intact, not yet cracked); the points it
// had keep their state. A pre-crack's new segments stay without cohesion.
TEST(InterfaceGrowth, ACohesiveCracksNewSegmentsCarryTheLawAPreCracksDoNot) {
  InterfaceSpec s;
  s.line.x = {0.0, 1.0};
  s.line.y = {0.0, 0.0};
  s.segments = 2;
  s.law = XuNeedleman{1e6, 1e6, 1e-6, 2e-6};
  s.drawn_open = true;
  CohesiveInterface c = make_interface(s);
  for (std::uint8_t v : c.gp_separated) EXPECT_EQ(v, 1);  // the cut
  for (double t : c.node_crack_time) EXPECT_EQ(t, 0.0);
  c.time = 1e-6;
  extend_interface(c, LineEnd::end, 1.25, 0.0, 0.0, 0.0);
  extend_interface(c, LineEnd::start, -0.25, 0.0, 0.0, 0.0);
  const std::size_t G = CohesiveInterface::kGauss, n = c.gp_separated.size();
  ASSERT_EQ(n, 4 * G);
  for (std::size_t q = 0; q < n; ++q)
    EXPECT_EQ(c.gp_separated[q], q < G || q >= n - G ? 0 : 1) << "point " << q;
  EXPECT_EQ(c.node_crack_time.front(), -1.0);  // the new nodes have not cracked
  EXPECT_EQ(c.node_crack_time.back(), -1.0);
  EXPECT_EQ(c.node_crack_time[1], 0.0);
  CohesiveInterface p = precrack();
  extend_interface(p, LineEnd::end, 2.5, 1.0, 0.0, 0.0);
  for (std::uint8_t v : p.gp_separated) EXPECT_EQ(v, 1);
}

}  // namespace

// Every array of state a grown line carries (InterfaceArrays' kGrown, walked generically: an
// array added to the list is checked here too) keeps its values, shifted to the new numbering,
// at either end; the new node's and new Gauss points' entries are the only ones that change.
TEST(InterfaceGrowth, EveryGrownArrayOfTheListIsCarriedToTheNewNumbering) {
  for (const LineEnd at : {LineEnd::start, LineEnd::end}) {
    CohesiveInterface c = precrack();
    std::size_t k = 0;
    for_each_interface_array([&](const auto& a) {
      using T = typename std::decay_t<decltype(a)>::value_type;
      if (!a.has(kGrown)) return;  // x0: the geometry the new line is made from
      auto& v = c.*a.member;
      const std::size_t n = a.extent == InterfaceExtent::node    ? c.num_nodes()
                            : a.extent == InterfaceExtent::gauss ? c.num_segments() * CohesiveInterface::kGauss
                                                                 : c.num_segments();
      v.resize(n);
      for (std::size_t i = 0; i < n; ++i) v[i] = T(1 + (k * 7 + i) % 100);
      ++k;
    });
    const CohesiveInterface before = c;
    const bool front = at == LineEnd::start;
    extend_interface(c, at, front ? -0.25 : 2.0, front ? 0.0 : 0.75, 0.0, 0.0);
    for_each_interface_array([&](const auto& a) {
      if (!a.has(kGrown)) return;
      const auto& old = before.*a.member;
      const auto& now = c.*a.member;
      const std::size_t per = a.extent == InterfaceExtent::gauss ? CohesiveInterface::kGauss : 1;
      ASSERT_EQ(now.size(), old.size() + per) << a.name;
      const std::size_t shift = front ? per : 0;
      for (std::size_t i = 0; i < old.size(); ++i) {
        EXPECT_EQ(now[i + shift], old[i]) << a.name << " at " << i;
      }
    });
  }
}

}  // namespace rupture
