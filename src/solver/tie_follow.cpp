// rupture/solver/tie_follow.cpp
#include "solver/tie_follow.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "solver/cohesive_step.hpp"
#include "solver/crack_cut.hpp"
#include "solver/rank_exchange.hpp"

namespace rupture {

TieSamples sample_ties(const std::vector<Polyline>& ties, double spacing) {
  TieSamples at;
  for (const Polyline& t : ties) {
    at.start.push_back(at.x.size());
    const std::size_t n = t.num_vertices();
    for (std::size_t v = 0; v < n; ++v) {
      at.x.push_back(t.x[v]), at.y.push_back(t.y[v]);
      if (v + 1 == n) break;
      const double dx = t.x[v + 1] - t.x[v], dy = t.y[v + 1] - t.y[v];
      const int pieces = std::max(1, int(std::ceil(std::hypot(dx, dy) / spacing)));
      for (int k = 1; k < pieces; ++k) {
        const double f = double(k) / pieces;
        at.x.push_back(t.x[v] + f * dx), at.y.push_back(t.y[v] + f * dy);
      }
    }
  }
  at.start.push_back(at.x.size());
  return at;
}

namespace {

// Douglas-Peucker: keeps the points of [a, b] the chord from a to b misses by more than `tol`
// (their distance to the chord, not to its line: a point beyond an end counts from that end; the
// farthest first, recursively), appending them and b to `out`.
void keep_bends(const std::vector<double>& x, const std::vector<double>& y, std::size_t a, std::size_t b,
                double tol, Polyline& out) {
  double far = tol;
  std::size_t at = b;
  const double dx = x[b] - x[a], dy = y[b] - y[a], len2 = dx * dx + dy * dy;
  for (std::size_t j = a + 1; j < b; ++j) {
    const double f = len2 > 0.0 ? std::clamp(((x[j] - x[a]) * dx + (y[j] - y[a]) * dy) / len2, 0.0, 1.0) : 0.0;
    const double d = std::hypot(x[j] - x[a] - f * dx, y[j] - y[a] - f * dy);
    if (d > far) far = d, at = j;
  }
  if (at != b) {
    keep_bends(x, y, a, at, tol, out);
    keep_bends(x, y, at, b, tol, out);
  } else {
    out.x.push_back(x[b]), out.y.push_back(y[b]);
  }
}

}  // namespace

std::vector<Polyline> carried_ties(const TieSamples& at, const std::vector<double>& ux,
                                   const std::vector<double>& uy, double tolerance) {
  std::vector<Polyline> out;
  for (std::size_t i = 0; i + 1 < at.start.size(); ++i) {
    const std::size_t a = at.start[i], b = at.start[i + 1];
    std::vector<double> x, y;
    for (std::size_t j = a; j < b; ++j) x.push_back(at.x[j] + ux[j]), y.push_back(at.y[j] + uy[j]);
    Polyline p;
    if (!x.empty()) {
      p.x.push_back(x[0]), p.y.push_back(y[0]);
      if (x.size() > 1) keep_bends(x, y, 0, x.size() - 1, tolerance, p);
    }
    out.push_back(std::move(p));
  }
  return out;
}

namespace {

// The samples binned by cells of `radius` over their box (CSR), so each particle looks at the
// samples of its bin and the eight around it.
struct SampleBins {
  double xlo = 0.0, ylo = 0.0, xhi = 0.0, yhi = 0.0, radius = 0.0;
  long bx = 0, by = 0;
  std::vector<std::size_t> first, order;
  SampleBins(const TieSamples& at, double r) : radius(r) {
    const std::size_t n = at.x.size();
    if (n == 0) return;
    xlo = *std::min_element(at.x.begin(), at.x.end()) - r, xhi = *std::max_element(at.x.begin(), at.x.end()) + r;
    ylo = *std::min_element(at.y.begin(), at.y.end()) - r, yhi = *std::max_element(at.y.begin(), at.y.end()) + r;
    bx = long((xhi - xlo) / r) + 1, by = long((yhi - ylo) / r) + 1;
    first.assign(std::size_t(bx * by) + 1, 0), order.resize(n);
    for (std::size_t j = 0; j < n; ++j) ++first[bin(at.x[j], at.y[j]) + 1];
    for (std::size_t b = 1; b < first.size(); ++b) first[b] += first[b - 1];
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t j = 0; j < n; ++j) order[fill[bin(at.x[j], at.y[j])]++] = j;
  }
  long col(double x) const { return std::clamp(long((x - xlo) / radius), 0L, bx - 1); }
  long row(double y) const { return std::clamp(long((y - ylo) / radius), 0L, by - 1); }
  std::size_t bin(double x, double y) const { return std::size_t(row(y) * bx + col(x)); }
};

// Adds each particle's displacement to the sums of the samples within the radius of its
// reference position (per sample: sum of u_x, of u_y, and the count).
void add_displacements(const Particles& P, const TieSamples& at, const SampleBins& bins, std::vector<double>& sums) {
  if (at.x.empty()) return;
  const double r2 = bins.radius * bins.radius;
  for (std::size_t q = 0; q < P.size(); ++q) {
    const double x0 = P.x0[q], y0 = P.y0[q];
    if (x0 < bins.xlo || x0 > bins.xhi || y0 < bins.ylo || y0 > bins.yhi) continue;
    const long i = bins.col(x0), j = bins.row(y0);
    for (long b = std::max(0L, j - 1); b <= std::min(bins.by - 1, j + 1); ++b)
      for (long a = std::max(0L, i - 1); a <= std::min(bins.bx - 1, i + 1); ++a) {
        const std::size_t cell = std::size_t(b * bins.bx + a);
        for (std::size_t k = bins.first[cell]; k < bins.first[cell + 1]; ++k) {
          const std::size_t m = bins.order[k];
          const double dx = x0 - at.x[m], dy = y0 - at.y[m];
          if (dx * dx + dy * dy > r2) continue;
          sums[3 * m] += P.x[q] - x0, sums[3 * m + 1] += P.y[q] - y0, sums[3 * m + 2] += 1.0;
        }
      }
  }
}

// The means from the sums (summed over the ranks); a point with none takes the nearest of its
// tie's that has some (a tie's end beyond a corner), none on the whole tie: 0.
void means(const TieSamples& at, const std::vector<double>& sums, std::vector<double>& ux, std::vector<double>& uy) {
  ux.assign(at.x.size(), 0.0), uy.assign(at.x.size(), 0.0);
  for (std::size_t i = 0; i + 1 < at.start.size(); ++i)
    for (std::size_t j = at.start[i]; j < at.start[i + 1]; ++j) {
      std::size_t from = j;
      for (std::size_t d = 1; sums[3 * from + 2] == 0.0; ++d) {
        const bool below = j >= at.start[i] + d, above = j + d < at.start[i + 1];
        if (!below && !above) break;
        if (below && sums[3 * (j - d) + 2] > 0.0) from = j - d;
        else if (above && sums[3 * (j + d) + 2] > 0.0) from = j + d;
      }
      const double count = sums[3 * from + 2];
      if (count > 0.0) ux[j] = sums[3 * from] / count, uy[j] = sums[3 * from + 1] / count;
    }
}

// The same over every level's particles (nested levels: each level holds its own).
void level_displacements(const RunState& s, const TieSamples& at, double radius, std::vector<double>& ux,
                         std::vector<double>& uy) {
  std::vector<double> sums(3 * at.x.size(), 0.0);
  const SampleBins bins(at, radius);
  for (const State& L : s.levels) add_displacements(L.particles, at, bins, sums);
  sum_over_ranks(s.levels[s.grid_level], sums.data(), sums.size());
  means(at, sums, ux, uy);
}

}  // namespace

void material_displacement(const State& s, const TieSamples& at, double radius, std::vector<double>& ux,
                           std::vector<double>& uy) {
  std::vector<double> sums(3 * at.x.size(), 0.0);
  add_displacements(s.particles, at, SampleBins(at, radius), sums);
  sum_over_ranks(s, sums.data(), sums.size());
  means(at, sums, ux, uy);
}

namespace {

// The cell of the finest level holding an interface: the band's reach and the quarter cell are
// read on it (a coarser level's band reaches further in metres).
double cell_of(const RunState& s) {
  const Grid& g = s.run_grid();
  return std::min(g.x.min_width(), g.y.min_width());
}

// Samples at most two cells apart: the straight pieces between them miss a bent line's
// curvature kappa by kappa (2h)^2 / 8, far below a cell at the strains the bulk law is for.
double spacing_of(const RunState& s) { return 2.0 * cell_of(s); }

// The carried line is laid as the fewest straight pieces through its points that miss none of
// them by more than this many cells (a straight tie carried by a smooth move stays one or a few
// pieces, so the band costs what a drawn one does): part of the quarter cell of margin.
constexpr double kStraightness = 1.0 / 16.0;

// An interface and where its ties are on each level: one grid, State::bonded[slot] (a branch's
// too) and the entries of stretches with their own pair of fields (BondedTie::of, line;
// solver/crack_junction.cpp); nested levels, bonded[k] of every level (neither branches nor
// stretches with their own pair are made there).
struct Tied {
  CohesiveInterface* c = nullptr;
  std::size_t index = 0;  // one grid: its slot; nested: the case's interface k
};

std::vector<Tied> interfaces_of(RunState& s) {
  std::vector<Tied> out;
  if (!s.is_nested()) {
    for (std::size_t i = 0; i < s.levels[0].interfaces.size(); ++i) out.push_back({&s.levels[0].interfaces[i], i});
  } else {
    for (std::size_t k = 0; k < s.num_interfaces(); ++k) out.push_back({&s.interface(k), k});
  }
  return out;
}

// Lays the interface's ties where its recorded samples are carried to (tie_ux, tie_uy).
void lay(RunState& s, const Tied& t) {
  const CohesiveInterface& c = *t.c;
  const std::vector<Polyline> ties = c.spec.tie_geometries();
  const Polyline crack = c.spec.geometry();
  const std::vector<Polyline> laid =
      carried_ties(sample_ties(ties, spacing_of(s)), c.tie_ux, c.tie_uy, kStraightness * cell_of(s));
  if (s.is_nested()) {
    for (State& L : s.levels) L.bonded[t.index].nodes = bonded_nodes(L.grid, ties, crack, laid);
    return;
  }
  State& L = s.levels[0];
  std::vector<char> own(ties.size(), 0);
  for (BondedTie& b : L.bonded) {
    if (b.of != t.index || b.line < 0 || std::size_t(b.line) >= ties.size()) continue;
    own[std::size_t(b.line)] = 1;
    b.nodes = bonded_nodes(L.grid, {ties[std::size_t(b.line)]}, crack, {laid[std::size_t(b.line)]});
  }
  std::vector<Polyline> rest, rest_laid;
  for (std::size_t i = 0; i < ties.size(); ++i)
    if (!own[i]) rest.push_back(ties[i]), rest_laid.push_back(laid[i]);
  L.bonded[t.index].nodes = bonded_nodes(L.grid, rest, crack, rest_laid);
}

void measure_every_window(RunState& s) {
  for (State& L : s.levels) measure_windows_again(L);
}

}  // namespace

bool follow_ties(RunState& s, const std::function<void()>& before_laying) {
  // Per-level time steps: the levels' coupled nodes hold the ties' (solver/nested_state.cpp),
  // fixed at set-up; the ties stay where drawn.
  if (s.subcycled()) return false;
  const std::vector<Tied> all_tied = interfaces_of(s);
  const double spacing = spacing_of(s), quarter = 0.25 * cell_of(s);
  std::vector<TieSamples> at(all_tied.size());
  std::vector<char> tied(all_tied.size(), 0), changed(all_tied.size(), 0);
  bool any = false, any_changed = false;
  for (std::size_t i = 0; i < all_tied.size(); ++i) {
    CohesiveInterface& c = *all_tied[i].c;
    const std::vector<Polyline> ties = c.spec.tie_geometries();
    if (ties.empty()) {  // its tie went (a crack through to the edge, a site come loose)
      c.tie_x0.clear(), c.tie_y0.clear(), c.tie_ux.clear(), c.tie_uy.clear();
      continue;
    }
    at[i] = sample_ties(ties, spacing);
    tied[i] = 1, any = true;
    changed[i] = at[i].x != c.tie_x0 || at[i].y != c.tie_y0;
    any_changed = any_changed || changed[i];
  }
  if (!any) return false;
  // The bounds, kept on the run's grid level: each level's particles moved by at most its own
  // last move, each rank's by at most its own.
  State& R = s.levels[s.grid_level];
  double move = 0.0;
  for (const State& L : s.levels) move = std::max(move, L.last_move);
  double bound[2] = {R.tie_drift + move, R.travel + move};
  max_over_ranks(R, bound, 2);
  R.tie_drift = bound[0], R.travel = bound[1];
  if (R.tie_drift < quarter && !(any_changed && R.travel >= quarter)) {
    // Nothing can have moved a quarter cell since the ties were laid: ties growth laid where
    // drawn stay there (the material has moved less than a quarter cell from where it was).
    for (std::size_t i = 0; i < all_tied.size(); ++i) {
      if (!changed[i]) continue;
      CohesiveInterface& c = *all_tied[i].c;
      c.tie_x0 = at[i].x, c.tie_y0 = at[i].y;
      c.tie_ux.assign(c.tie_x0.size(), 0.0), c.tie_uy.assign(c.tie_x0.size(), 0.0);
    }
    return false;
  }
  // Measured: every tie's points at once (one sum over the ranks); the fallback of a point with
  // no particle near stays inside its own tie.
  TieSamples all;
  for (std::size_t i = 0; i < all_tied.size(); ++i) {
    if (!tied[i]) continue;
    const std::size_t o = all.x.size();
    for (std::size_t t = 0; t + 1 < at[i].start.size(); ++t) all.start.push_back(o + at[i].start[t]);
    all.x.insert(all.x.end(), at[i].x.begin(), at[i].x.end());
    all.y.insert(all.y.end(), at[i].y.begin(), at[i].y.end());
  }
  all.start.push_back(all.x.size());
  std::vector<double> ux, uy;
  level_displacements(s, all, cell_of(s), ux, uy);
  double residual = 0.0;
  bool laid = false;
  for (std::size_t i = 0, o = 0; i < all_tied.size(); ++i) {
    if (!tied[i]) continue;
    CohesiveInterface& c = *all_tied[i].c;
    const std::size_t n = at[i].x.size();
    double drift = 0.0;
    for (std::size_t j = 0; j < n && !changed[i]; ++j)
      drift = std::max(drift, std::hypot(ux[o + j] - c.tie_ux[j], uy[o + j] - c.tie_uy[j]));
    if (changed[i] || drift > quarter) {
      if (!laid && before_laying) before_laying();
      laid = true;
      c.tie_x0 = at[i].x, c.tie_y0 = at[i].y;
      c.tie_ux.assign(ux.begin() + long(o), ux.begin() + long(o + n));
      c.tie_uy.assign(uy.begin() + long(o), uy.begin() + long(o + n));
      lay(s, all_tied[i]);
    } else {
      residual = std::max(residual, drift);
    }
    o += n;
  }
  R.tie_drift = residual;
  if (laid) measure_every_window(s);
  return laid;
}

void lay_followed_ties(RunState& s) {
  if (s.subcycled()) return;
  bool laid = false;
  for (const Tied& t : interfaces_of(s)) {
    const CohesiveInterface& c = *t.c;
    if (c.tie_x0.empty()) continue;
    const TieSamples at = sample_ties(c.spec.tie_geometries(), spacing_of(s));
    if (at.x != c.tie_x0 || at.y != c.tie_y0) continue;  // not its lines: the next step lays them
    lay(s, t), laid = true;
  }
  if (laid) measure_every_window(s);
}

}  // namespace rupture
