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

std::vector<Polyline> carried_ties(const TieSamples& at, const std::vector<double>& ux,
                                   const std::vector<double>& uy) {
  std::vector<Polyline> out;
  for (std::size_t i = 0; i + 1 < at.start.size(); ++i) {
    Polyline p;
    for (std::size_t j = at.start[i]; j < at.start[i + 1]; ++j)
      p.x.push_back(at.x[j] + ux[j]), p.y.push_back(at.y[j] + uy[j]);
    out.push_back(std::move(p));
  }
  return out;
}

void material_displacement(const State& s, const TieSamples& at, double radius, std::vector<double>& ux,
                           std::vector<double>& uy) {
  const std::size_t n = at.x.size();
  std::vector<double> sums(3 * n, 0.0);  // per sample: sum of u_x, of u_y, and the count
  if (n > 0) {
    // The samples binned by cells of `radius` over their box, so each particle looks at the
    // samples of its bin and the eight around it.
    const double xlo = *std::min_element(at.x.begin(), at.x.end()) - radius;
    const double ylo = *std::min_element(at.y.begin(), at.y.end()) - radius;
    const double xhi = *std::max_element(at.x.begin(), at.x.end()) + radius;
    const double yhi = *std::max_element(at.y.begin(), at.y.end()) + radius;
    const long bx = long((xhi - xlo) / radius) + 1, by = long((yhi - ylo) / radius) + 1;
    std::vector<std::size_t> first(std::size_t(bx * by) + 1, 0), order(n);
    const auto bin = [&](double x, double y) {
      return std::size_t(std::clamp(long((y - ylo) / radius), 0L, by - 1) * bx +
                         std::clamp(long((x - xlo) / radius), 0L, bx - 1));
    };
    for (std::size_t j = 0; j < n; ++j) ++first[bin(at.x[j], at.y[j]) + 1];
    for (std::size_t b = 1; b < first.size(); ++b) first[b] += first[b - 1];
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t j = 0; j < n; ++j) order[fill[bin(at.x[j], at.y[j])]++] = j;
    const double r2 = radius * radius;
    const Particles& P = s.particles;
    for (std::size_t q = 0; q < P.size(); ++q) {
      const double x0 = P.x0[q], y0 = P.y0[q];
      if (x0 < xlo || x0 > xhi || y0 < ylo || y0 > yhi) continue;
      const long i = std::clamp(long((x0 - xlo) / radius), 0L, bx - 1);
      const long j = std::clamp(long((y0 - ylo) / radius), 0L, by - 1);
      for (long b = std::max(0L, j - 1); b <= std::min(by - 1, j + 1); ++b)
        for (long a = std::max(0L, i - 1); a <= std::min(bx - 1, i + 1); ++a) {
          const std::size_t cell = std::size_t(b * bx + a);
          for (std::size_t k = first[cell]; k < first[cell + 1]; ++k) {
            const std::size_t m = order[k];
            const double dx = x0 - at.x[m], dy = y0 - at.y[m];
            if (dx * dx + dy * dy > r2) continue;
            sums[3 * m] += P.x[q] - x0, sums[3 * m + 1] += P.y[q] - y0, sums[3 * m + 2] += 1.0;
          }
        }
    }
  }
  sum_over_ranks(s, sums.data(), sums.size());
  ux.assign(n, 0.0), uy.assign(n, 0.0);
  for (std::size_t i = 0; i + 1 < at.start.size(); ++i)
    for (std::size_t j = at.start[i]; j < at.start[i + 1]; ++j) {
      // A point with no particle near (a tie's end beyond a corner): the nearest of its tie's
      // that has some.
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

namespace {

double cell_of(const State& L) { return std::min(L.grid.x.min_width(), L.grid.y.min_width()); }

// Samples at most two cells apart: the straight pieces between them miss a bent line's
// curvature kappa by kappa (2h)^2 / 8, far below a cell at the strains the bulk law is for.
double spacing_of(const State& L) { return 2.0 * cell_of(L); }

// Lays interface `slot`'s ties where its recorded samples are carried to (tie_ux, tie_uy): its
// own entry of L.bonded, and the entries of stretches with their own pair of fields
// (BondedTie::of, line; solver/crack_junction.cpp) for those lines.
void lay(State& L, std::size_t slot) {
  const CohesiveInterface& c = L.interfaces[slot];
  const std::vector<Polyline> ties = c.spec.tie_geometries();
  const Polyline crack = c.spec.geometry();
  const TieSamples at = sample_ties(ties, spacing_of(L));
  const std::vector<Polyline> laid = carried_ties(at, c.tie_ux, c.tie_uy);
  std::vector<char> own(ties.size(), 0);
  for (BondedTie& b : L.bonded) {
    if (b.of != slot || b.line < 0 || std::size_t(b.line) >= ties.size()) continue;
    own[std::size_t(b.line)] = 1;
    b.nodes = bonded_nodes(L.grid, {ties[std::size_t(b.line)]}, crack, {laid[std::size_t(b.line)]});
  }
  std::vector<Polyline> rest, rest_laid;
  for (std::size_t i = 0; i < ties.size(); ++i)
    if (!own[i]) rest.push_back(ties[i]), rest_laid.push_back(laid[i]);
  L.bonded[slot].nodes = bonded_nodes(L.grid, rest, crack, rest_laid);
}

}  // namespace

bool follow_ties(RunState& s, const std::function<void()>& before_laying) {
  if (s.levels.size() != 1) return false;
  State& L = s.levels[0];
  const double spacing = spacing_of(L), quarter = 0.25 * cell_of(L);
  std::vector<TieSamples> at(L.interfaces.size());
  std::vector<char> tied(L.interfaces.size(), 0), changed(L.interfaces.size(), 0);
  bool any = false, any_changed = false;
  for (std::size_t i = 0; i < L.interfaces.size(); ++i) {
    CohesiveInterface& c = L.interfaces[i];
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
  double bound[2] = {L.tie_drift + L.last_move, L.travel + L.last_move};
  max_over_ranks(L, bound, 2);  // each rank's particles moved by at most its own bound
  L.tie_drift = bound[0], L.travel = bound[1];
  if (L.tie_drift < quarter && !(any_changed && L.travel >= quarter)) {
    // Nothing can have moved a quarter cell since the ties were laid: ties growth laid where
    // drawn stay there (the material has moved less than a quarter cell from where it was).
    for (std::size_t i = 0; i < L.interfaces.size(); ++i) {
      if (!changed[i]) continue;
      CohesiveInterface& c = L.interfaces[i];
      c.tie_x0 = at[i].x, c.tie_y0 = at[i].y;
      c.tie_ux.assign(c.tie_x0.size(), 0.0), c.tie_uy.assign(c.tie_x0.size(), 0.0);
    }
    return false;
  }
  // Measured: every tie's points at once (one sum over the ranks).
  TieSamples all;
  for (std::size_t i = 0; i < L.interfaces.size(); ++i) {
    if (!tied[i]) continue;
    all.x.insert(all.x.end(), at[i].x.begin(), at[i].x.end());
    all.y.insert(all.y.end(), at[i].y.begin(), at[i].y.end());
  }
  for (std::size_t i = 0, o = 0; i < L.interfaces.size(); ++i) {
    if (!tied[i]) continue;
    for (std::size_t t = 0; t + 1 < at[i].start.size(); ++t) all.start.push_back(o + at[i].start[t]);
    o += at[i].x.size();
  }
  all.start.push_back(all.x.size());
  std::vector<double> ux, uy;
  material_displacement(L, all, cell_of(L), ux, uy);
  double residual = 0.0;
  bool laid = false;
  for (std::size_t i = 0, o = 0; i < L.interfaces.size(); ++i) {
    if (!tied[i]) continue;
    CohesiveInterface& c = L.interfaces[i];
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
      lay(L, i);
    } else {
      residual = std::max(residual, drift);
    }
    o += n;
  }
  L.tie_drift = residual;
  if (laid) measure_windows_again(L);
  return laid;
}

void lay_followed_ties(RunState& s) {
  if (s.levels.size() != 1) return;
  State& L = s.levels[0];
  bool laid = false;
  for (std::size_t i = 0; i < L.interfaces.size(); ++i) {
    const CohesiveInterface& c = L.interfaces[i];
    if (c.tie_x0.empty()) continue;
    const TieSamples at = sample_ties(c.spec.tie_geometries(), spacing_of(L));
    if (at.x != c.tie_x0 || at.y != c.tie_y0) continue;  // not its lines: the next step lays them
    lay(L, i), laid = true;
  }
  if (laid) measure_windows_again(L);
}

}  // namespace rupture
