// rupture/grid/nested.cpp
#include "grid/nested.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace rupture {

bool LevelLattice::owns_units(double u, double v) const {
  const double p[2] = {u, v};
  for (int d = 0; d < 2; ++d) {
    if (!outer_lo[d] && !(p[d] > double(lo[d]))) return false;
    if (!outer_hi[d] && !(p[d] < double(hi[d]))) return false;
  }
  return true;
}

int NestedGrid::level_of(double x, double y) const {
  const double u = (x - min[0]) / finest, v = (y - min[1]) / finest;
  for (int l = int(levels.size()) - 1; l > 0; --l)
    if (levels[std::size_t(l)].owns_units(u, v)) return l;
  return 0;
}

void NestedGrid::node_position(std::size_t id, double& x, double& y) const {
  const std::size_t l =
      std::size_t(std::upper_bound(level_start.begin(), level_start.end(), id) - level_start.begin()) - 1;
  const LevelLattice& L = levels[l];
  const std::size_t n = id - level_start[l];
  x = L.x.node(int(n % std::size_t(L.nodes_x())));
  y = L.y.node(int(n / std::size_t(L.nodes_x())));
}

Grid level_grid(const NestedGrid& g, int l) {
  const LevelLattice& L = g.levels[std::size_t(l)];
  Grid out;
  out.x = L.x, out.y = L.y;
  out.ghost = kGhostRing;
  for (int d = 0; d < 2; ++d) out.domain_min[d] = g.min[d], out.domain_max[d] = g.max[d];
  return out;
}

namespace {

long floor_to(long u, long m) { return (u >= 0 ? u / m : -((-u + m - 1) / m)) * m; }
long ceil_to(long u, long m) { return -floor_to(-u, m); }

// Adds the DOF terms of level l's node at finest-unit point (U, V), times c, to out.
void resolve(const NestedGrid& g, int l, long U, long V, double c, std::vector<SlaveTerm>& out,
             int depth) {
  assert(depth < 64);
  const LevelLattice& L = g.levels[std::size_t(l)];
  const std::size_t nl = g.levels.size();
  const auto id = [&](const LevelLattice& at, int lev, long u, long v) {
    const long i = (u - at.node0[0]) / at.unit, j = (v - at.node0[1]) / at.unit;
    assert(i >= 0 && i < at.nodes_x() && j >= 0 && j < at.nodes_y());
    return std::uint32_t(g.level_start[std::size_t(lev)] + at.node_index(int(i), int(j)));
  };
  if (std::size_t(l) + 1 < nl && g.levels[std::size_t(l) + 1].owns_units(double(U), double(V))) {
    resolve(g, l + 1, U, V, c, out, depth + 1);  // covered: the finer level's node (injection)
    return;
  }
  if (L.owns_units(double(U), double(V))) {
    out.push_back({id(L, l, U, V), c});
    return;
  }
  // Hanging or ghost node: bilinear interpolant of the coarser level.
  assert(l > 0);
  const LevelLattice& C = g.levels[std::size_t(l) - 1];
  long us[2], vs[2];
  int nu = 1, nv = 1;
  us[0] = floor_to(U - C.node0[0], C.unit) + C.node0[0];
  if (us[0] != U) us[1] = us[0] + C.unit, nu = 2;
  vs[0] = floor_to(V - C.node0[1], C.unit) + C.node0[1];
  if (vs[0] != V) vs[1] = vs[0] + C.unit, nv = 2;
  const double w = c / double(nu * nv);  // midpoints 1/2, cell centres 1/4 (exact)
  for (int a = 0; a < nu; ++a)
    for (int b = 0; b < nv; ++b) resolve(g, l - 1, us[a], vs[b], w, out, depth + 1);
}

}  // namespace

NestedGrid make_nested_grid(const double min[2], const double max[2], double coarse, double finest,
                            const std::vector<RefineBox>& boxes, double margin) {
  NestedGrid g;
  g.finest = finest;
  const char* names[2] = {"x", "y"};
  const double ratio = coarse / finest;
  const int L = int(std::lround(std::log2(ratio)));
  if (L < 0 || std::fabs(ratio - double(1L << L)) > 1e-9 * ratio)
    throw InputError(fmt::format("grid.coarse_cell_size = {:g}: must be the finest cell size {:g} "
                                 "times a power of two (1, 2, 4, ...)", coarse, finest));
  long extent[2];
  for (int d = 0; d < 2; ++d) {
    g.min[d] = min[d], g.max[d] = max[d];
    const double n = (max[d] - min[d]) / finest;
    extent[d] = std::lround(n);
    if (extent[d] < 1 || std::fabs(n - double(extent[d])) > 1e-6 * std::max(1.0, n))
      throw InputError(fmt::format(
          "grid.cell_size = {:g}: the domain extent along {} ({:g} m) must be a whole number of "
          "finest cells; {:g} does not qualify", finest, names[d], max[d] - min[d], n));
  }
  const long c0 = 1L << L;
  const long ring0 = long(ghost_cells(margin, coarse)) * c0;
  long outer_lo = -ring0, outer_hi[2];
  for (int d = 0; d < 2; ++d) outer_hi[d] = ceil_to(extent[d], c0) + ring0;

  // Each box's level, and the bounding rectangle of the boxes at level >= l, in finest units.
  std::vector<int> box_level;
  int finest_level = 0;
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const double r = coarse / boxes[b].size;
    const int l = int(std::lround(std::log2(r)));
    if (l < 0 || l > L || std::fabs(r - double(1L << l)) > 1e-9 * r)
      throw InputError(fmt::format("grid.refine box {}: cell size {:g} must be {:g} / 2^l with "
                                   "0 <= l <= {}", b + 1, boxes[b].size, coarse, L));
    box_level.push_back(l);
    finest_level = std::max(finest_level, l);
  }
  g.levels.resize(std::size_t(finest_level) + 1);
  for (int l = 0; l <= finest_level; ++l) {
    LevelLattice& lev = g.levels[std::size_t(l)];
    lev.level = l;
    lev.unit = c0 >> l;
    if (l == 0) continue;
    const long parent = lev.unit * 2;
    bool any = false;
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      if (box_level[b] < l) continue;
      for (int d = 0; d < 2; ++d) {
        // In finest units, bounded in floating point to a few frames' widths either side: a box
        // edge far outside (input may put one at 1e300 m) gives a value a long holds, and one
        // beyond the frame anyway, not an overflowed conversion (UBSan, fuzz_case_toml).
        const double far = 2.0 * double(outer_hi[d] - outer_lo);
        auto units = [&](double v) { return long(std::clamp(v, -far, 1.5 * far)); };
        const long lo = floor_to(units(std::floor((boxes[b].min[d] - min[d]) / finest + 1e-9)), parent);
        const long hi = ceil_to(units(std::ceil((boxes[b].max[d] - min[d]) / finest - 1e-9)), parent);
        lev.lo[d] = any ? std::min(lev.lo[d], lo) : lo;
        lev.hi[d] = any ? std::max(lev.hi[d], hi) : hi;
      }
      any = true;
    }
  }
  // Proper nesting, finest first: R_{l-1} holds R_l plus kNestingCells of its own cells.
  for (int l = finest_level; l >= 2; --l) {
    LevelLattice& fine = g.levels[std::size_t(l)];
    LevelLattice& up = g.levels[std::size_t(l) - 1];
    const long grow = kNestingCells * up.unit, snap = up.unit * 2;
    for (int d = 0; d < 2; ++d) {
      up.lo[d] = std::min(up.lo[d], floor_to(fine.lo[d] - grow, snap));
      up.hi[d] = std::max(up.hi[d], ceil_to(fine.hi[d] + grow, snap));
    }
  }
  // Outer sides, lattices.
  for (int l = 0; l <= finest_level; ++l) {
    LevelLattice& lev = g.levels[std::size_t(l)];
    Axis* axes[2] = {&lev.x, &lev.y};
    for (int d = 0; d < 2; ++d) {
      if (l == 0 || lev.lo[d] <= 0) lev.outer_lo[d] = true, lev.lo[d] = outer_lo;
      if (l == 0 || lev.hi[d] >= extent[d]) lev.outer_hi[d] = true, lev.hi[d] = outer_hi[d];
      const long a = lev.outer_lo[d] ? lev.lo[d] : lev.lo[d] - kGhostRing * lev.unit;
      const long b = lev.outer_hi[d] ? lev.hi[d] : lev.hi[d] + kGhostRing * lev.unit;
      lev.node0[d] = a;
      axes[d]->h = double(lev.unit) * finest;
      axes[d]->origin = min[d] + double(a) * finest;
      axes[d]->cells = int((b - a) / lev.unit);
    }
  }
  g.level_start.assign(1, 0);
  for (const LevelLattice& lev : g.levels) g.level_start.push_back(g.level_start.back() + lev.num_nodes());

  // Classify every node; resolve each slave to DOFs.
  g.is_dof.assign(g.num_nodes(), 0);
  g.term_start.push_back(0);
  std::vector<SlaveTerm> t;
  for (int l = 0; l <= finest_level; ++l) {
    const LevelLattice& lev = g.levels[std::size_t(l)];
    for (int j = 0; j < lev.nodes_y(); ++j)
      for (int i = 0; i < lev.nodes_x(); ++i) {
        const long U = lev.node0[0] + i * lev.unit, V = lev.node0[1] + j * lev.unit;
        const std::size_t id = g.level_start[std::size_t(l)] + lev.node_index(i, j);
        const bool covered = std::size_t(l) + 1 < g.levels.size() &&
                             g.levels[std::size_t(l) + 1].owns_units(double(U), double(V));
        if (!covered && lev.owns_units(double(U), double(V))) {
          g.is_dof[id] = 1;
          continue;
        }
        t.clear();
        resolve(g, l, U, V, 1.0, t, 0);
        std::sort(t.begin(), t.end(), [](const SlaveTerm& a, const SlaveTerm& b) { return a.dof < b.dof; });
        g.slaves.push_back(std::uint32_t(id));
        for (std::size_t k = 0; k < t.size(); ++k) {
          if (k > 0 && t[k].dof == g.terms.back().dof && g.terms.size() > g.term_start.back())
            g.terms.back().c += t[k].c;
          else
            g.terms.push_back(t[k]);
        }
        g.term_start.push_back(std::uint32_t(g.terms.size()));
      }
  }
  return g;
}

void condense_to_dofs(const NestedGrid& g, double* values) {
  for (std::size_t k = 0; k < g.slaves.size(); ++k) {
    const double v = values[g.slaves[k]];
    for (std::uint32_t t = g.term_start[k]; t < g.term_start[k + 1]; ++t) values[g.terms[t].dof] += g.terms[t].c * v;
    values[g.slaves[k]] = 0.0;
  }
}

void spread_to_slaves(const NestedGrid& g, double* values) {
  for (std::size_t k = 0; k < g.slaves.size(); ++k) {
    double v = 0.0;
    for (std::uint32_t t = g.term_start[k]; t < g.term_start[k + 1]; ++t) v += g.terms[t].c * values[g.terms[t].dof];
    values[g.slaves[k]] = v;
  }
}

std::vector<LevelCount> count_level_cells(const NestedGrid& g, const double bmin[2],
                                          const double bmax[2], int ppc) {
  std::vector<LevelCount> out(g.levels.size());
  for (std::size_t l = 0; l < g.levels.size(); ++l) {
    const LevelLattice& lev = g.levels[l];
    const double u = double(lev.unit);
    for (int j = 0; j < lev.y.cells; ++j)
      for (int i = 0; i < lev.x.cells; ++i) {
        const double cu = double(lev.node0[0]) + (i + 0.5) * u, cv = double(lev.node0[1]) + (j + 0.5) * u;
        if (!lev.owns_units(cu, cv)) continue;
        if (l + 1 < g.levels.size() && g.levels[l + 1].owns_units(cu, cv)) continue;
        std::size_t inside = 0;
        for (int b = 0; b < ppc; ++b)
          for (int a = 0; a < ppc; ++a) {
            const double x = lev.x.node(i) + (a + 0.5) / ppc * lev.x.h;
            const double y = lev.y.node(j) + (b + 0.5) / ppc * lev.y.h;
            inside += x > bmin[0] && x < bmax[0] && y > bmin[1] && y < bmax[1];
          }
        if (inside == 0) continue;
        ++out[l].cells;
        out[l].particles += inside;
      }
  }
  return out;
}

}  // namespace rupture
