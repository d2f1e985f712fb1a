// rupture/solver/field_bands.cpp
#include "solver/field_bands.hpp"

#include <algorithm>
#include <climits>
#include <vector>

namespace rupture {
namespace {

struct RowSpan {
  std::vector<int> lo, hi;  // per field: node rows needed, inclusive (lo > hi: none)
  explicit RowSpan(int fields) : lo(std::size_t(fields), INT_MAX), hi(std::size_t(fields), INT_MIN) {}
  void add(int f, int a, int b) {
    lo[std::size_t(f)] = std::min(lo[std::size_t(f)], a);
    hi[std::size_t(f)] = std::max(hi[std::size_t(f)], b);
  }
};

int cell_row(const Grid& g, double y) { return std::clamp(g.y.cell_of(y), 0, g.y.cells - 1); }

void add_particles(const State& s, RowSpan& need) {
  const Particles& P = s.particles;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const int r = cell_row(s.grid, P.y[p]);
    need.add(P.field[p], r - 1, r + 2);
  }
}

void add_faces_and_ties(const State& s, RowSpan& need) {
  const int nx = s.grid.nodes_x();
  for (std::size_t c = 0; c < s.interfaces.size(); ++c) {
    const CohesiveInterface& ci = s.interfaces[c];
    const int up = ci.spec.upper_field, lo = ci.spec.lower_field;
    for (std::size_t k = 0; k < ci.num_nodes(); ++k) {
      const int ru = cell_row(s.grid, ci.y0[k] + ci.uy_up[k]);
      const int rl = cell_row(s.grid, ci.y0[k] + ci.uy_lo[k]);
      need.add(up, ru, ru + 1);
      need.add(lo, rl, rl + 1);
    }
    for (const std::size_t n : s.bonded[c]) {
      const int j = int(n / std::size_t(nx));
      need.add(up, j, j);
      need.add(lo, j, j);
    }
  }
}

bool inside(const GridFields& G, const RowSpan& need) {
  if (G.row0.size() != need.lo.size()) return false;
  for (std::size_t f = 0; f < need.lo.size(); ++f) {
    if (need.lo[f] > need.hi[f]) continue;
    if (need.lo[f] < G.row0[f] || need.hi[f] >= G.row0[f] + G.rows[f]) return false;
  }
  return true;
}

}  // namespace

void fit_field_bands(State& s) {
  const int fields = s.fields.num_fields;
  const int ny = s.grid.nodes_y();
  // Particles are measured after every sort, and whenever the last check was not the previous
  // step (a fresh or restored state); otherwise the move's check keeps them inside.
  const bool measure = s.plan.sorted_step == s.step || s.bands_checked_step != s.step - 1;
  s.bands_checked_step = s.step;
  RowSpan need(fields);
  if (measure) add_particles(s, need);
  add_faces_and_ties(s, need);
  if (inside(s.fields, need)) return;
  if (!measure) add_particles(s, need);
  std::vector<int> row0(static_cast<std::size_t>(fields)), rows(row0.size());
  for (std::size_t f = 0; f < std::size_t(fields); ++f) {
    if (need.lo[f] > need.hi[f]) {  // a field with nothing in it: one row
      row0[f] = 0, rows[f] = 1;
      continue;
    }
    const int a = std::max(0, need.lo[f] - kBandMargin);
    const int b = std::min(ny - 1, need.hi[f] + kBandMargin);
    row0[f] = a, rows[f] = b - a + 1;
  }
  s.fields.set_bands(std::size_t(s.grid.nodes_x()), std::size_t(ny), row0, rows);
}

std::size_t band_rows_estimate(const Grid& g, double ymin, double ymax) {
  const int a = std::max(0, cell_row(g, ymin) - 1 - kBandMargin);
  const int b = std::min(g.nodes_y() - 1, cell_row(g, ymax) + 2 + kBandMargin);
  return std::size_t(b - a + 1);
}

}  // namespace rupture
