// rupture/solver/field_windows.cpp
#include "solver/field_windows.hpp"

#include "solver/rank_exchange.hpp"

#include <algorithm>
#include <climits>
#include <vector>

namespace rupture {
namespace {

// Per field, the node columns and rows needed, inclusive (lo > hi: none).
struct Need {
  std::vector<int> lo[2], hi[2];
  explicit Need(int fields) {
    for (int d = 0; d < 2; ++d) {
      lo[d].assign(std::size_t(fields), INT_MAX);
      hi[d].assign(std::size_t(fields), INT_MIN);
    }
  }
  void add(int f, int i0, int i1, int j0, int j1) {
    const std::size_t k = std::size_t(f);
    lo[0][k] = std::min(lo[0][k], i0), hi[0][k] = std::max(hi[0][k], i1);
    lo[1][k] = std::min(lo[1][k], j0), hi[1][k] = std::max(hi[1][k], j1);
  }
};

int cell(const Axis& a, double x) { return std::clamp(a.cell_of(x), 0, a.cells - 1); }

void add_particles(const State& s, Need& need) {
  const Particles& P = s.particles;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const int c = cell(s.grid.x, P.x[p]), r = cell(s.grid.y, P.y[p]);
    need.add(P.field[p], c - 1, c + 2, r - 1, r + 2);
  }
}

void add_faces_and_ties(const State& s, Need& need) {
  const std::size_t nx = std::size_t(s.grid.nodes_x());
  for (std::size_t c = 0; c < s.interfaces.size(); ++c) {
    const CohesiveInterface& ci = s.interfaces[c];
    for (std::size_t k = 0; k < ci.num_nodes(); ++k) {
      const FaceFields up = ci.faces_up(k), lo = ci.faces_lo(k);
      if (!ci.knows(k)) continue;  // distributed: far from this rank's block
      const int cu = cell(s.grid.x, ci.x0[k] + ci.ux_up[k]), ru = cell(s.grid.y, ci.y0[k] + ci.uy_up[k]);
      const int cl = cell(s.grid.x, ci.x0[k] + ci.ux_lo[k]), rl = cell(s.grid.y, ci.y0[k] + ci.uy_lo[k]);
      need.add(up.a, cu, cu + 1, ru, ru + 1);
      need.add(lo.a, cl, cl + 1, rl, rl + 1);
      if (up.share < 1.0) need.add(up.b, cu, cu + 1, ru, ru + 1);  // a T-junction's node
      if (lo.share < 1.0) need.add(lo.b, cl, cl + 1, rl, rl + 1);
    }
  }
  for (const BondedTie& b : s.bonded)
    for (const std::size_t n : b.nodes) {
      const int i = int(n % nx), j = int(n / nx);
      need.add(b.upper_field, i, i, j, j);
      need.add(b.lower_field, i, i, j, j);
    }
}

// Nodes a measured field keeps between what it needs and its window's side (unless the side is
// the grid's edge): the particles may move kWindowDrift cells before they are measured again
// (plus one: a cell index of a point moved that far can change by one more).
constexpr int kSlack = int(kWindowDrift) + 1;
static_assert(kSlack <= kWindowMargin, "a fresh window must keep the slack");

// Whether every window holds what its field needs and, when `tight` (the particles were
// measured), keeps kSlack nodes to spare on every side, and reaches at most one margin beyond
// the window a re-fit would make (so a field that moved away gives its old nodes back).
bool fits(const GridFields& G, const Need& need, const int n[2], bool tight) {
  if (G.start.size() != need.lo[0].size() + 1) return false;
  const std::vector<int>* first[2] = {&G.col0, &G.row0};
  const std::vector<int>* count[2] = {&G.cols, &G.rows};
  for (std::size_t f = 0; f < need.lo[0].size(); ++f) {
    if (need.lo[0][f] > need.hi[0][f]) continue;
    for (int d = 0; d < 2; ++d) {
      const int a = (*first[d])[f], b = a + (*count[d])[f] - 1;
      if (need.lo[d][f] < a || need.hi[d][f] > b) return false;
      // Without the slack a window measured as just fitting let its particles move out of it
      // before the next measure (a block flying at 400 m/s, re-sorted only every 25 steps).
      if (tight && ((a > 0 && need.lo[d][f] - kSlack < a) || (b < n[d] - 1 && need.hi[d][f] + kSlack > b)))
        return false;
      const int ideal_a = std::max(0, need.lo[d][f] - kWindowMargin);
      const int ideal_b = std::min(n[d] - 1, need.hi[d][f] + kWindowMargin);
      if (tight && (a < ideal_a - kWindowMargin || b > ideal_b + kWindowMargin)) return false;
    }
  }
  return true;
}

}  // namespace

void fit_field_windows(State& s) {
  const int fields = s.fields.num_fields;
  const int n[2] = {s.grid.nodes_x(), s.grid.nodes_y()};
  if (s.whole_grid_fields) {
    // A distributed nested level keeps the window of its reach (parallel/halo_nested.hpp).
    if (s.halo && s.halo->fixes_windows()) return;
    if (s.fields.size() != std::size_t(fields) * s.grid.num_nodes())
      s.fields.resize(fields, std::size_t(n[0]), std::size_t(n[1]));
    return;
  }
  // Particles are measured after every sort, when they may have moved kWindowDrift since the
  // last measure (State::window_drift, summed by the particle move), and when the last check
  // was not the previous step (a fresh or restored state).
  const double unit = std::min(s.grid.x.h, s.grid.y.h);  // the finest cell (graded: the unit)
  const bool measure = s.plan.sorted_step == s.step || s.window_drift >= kWindowDrift * unit ||
                       s.windows_checked_step != s.step - 1;
  s.windows_checked_step = s.step;
  if (measure) s.window_drift = 0.0;
  Need need(fields);
  if (measure) add_particles(s, need);
  add_faces_and_ties(s, need);
  if (fits(s.fields, need, n, measure)) return;
  if (!measure) add_particles(s, need);
  std::vector<int> first[2], count[2];
  for (int d = 0; d < 2; ++d) {
    first[d].assign(std::size_t(fields), 0);
    count[d].assign(std::size_t(fields), 1);  // a field with nothing in it: one node
    for (std::size_t f = 0; f < std::size_t(fields); ++f) {
      if (need.lo[0][f] > need.hi[0][f]) continue;
      const int a = std::max(0, need.lo[d][f] - kWindowMargin);
      const int b = std::min(n[d] - 1, need.hi[d][f] + kWindowMargin);
      first[d][f] = a, count[d][f] = b - a + 1;
    }
  }
  s.fields.set_windows(std::size_t(n[0]), std::size_t(n[1]), first[0], count[0], first[1],
                       count[1]);  // also drops a whole-grid layout (make_state's first)
  ++s.window_fits;
}

std::size_t window_nodes_estimate(const Grid& g, const Box& box) {
  const Axis* axes[2] = {&g.x, &g.y};
  std::size_t nodes = 1;
  for (int d = 0; d < 2; ++d) {
    const Axis& a = *axes[d];
    const int lo = std::max(0, cell(a, box.min[d]) - 1 - kWindowMargin);
    const int hi = std::min(a.nodes() - 1, cell(a, box.max[d]) + 2 + kWindowMargin);
    nodes *= std::size_t(hi - lo + 1);
  }
  return nodes;
}

}  // namespace rupture
