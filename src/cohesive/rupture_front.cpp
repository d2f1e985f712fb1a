// rupture/cohesive/rupture_front.cpp
#include "cohesive/rupture_front.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "cohesive/crack_tip.hpp"
#include "cohesive/slip_weakening.hpp"

namespace rupture {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// One side: the ruptured nodes contiguous with the patch, by distance d from its edge, with
// their rupture times and arc lengths. Each window starts at a node and takes the nodes within
// `window` of it (at least 3); its slowness is the least-squares slope dt/dd.
struct SideNodes {
  std::vector<double> d, t, s;
};

FrontSide summarize_side(const SideNodes& n, double window, double dt, double c_max,
                         const WaveSpeeds& w) {
  const double c_s = w.shear;
  FrontSide r;
  r.nodes = int(n.d.size());
  if (n.d.empty()) return r;
  r.leave_time = *std::min_element(n.t.begin(), n.t.end());
  r.reach_s = n.s.back();
  std::vector<double> speed;  // per window (inf: not increasing away from the patch)
  std::vector<double> start_s, start_t;
  for (std::size_t i = 0; i < n.d.size(); ++i) {
    std::size_t j = i;
    while (j + 1 < n.d.size() && n.d[j + 1] - n.d[i] <= window * (1.0 + 1e-12)) ++j;
    if (j - i + 1 < 3 || n.d[j] - n.d[i] < 0.5 * window) break;  // the side's end: no full window
    const double p = least_squares_slope(&n.d[i], &n.t[i], j - i + 1);  // s/m
    // The fitted rupture times across the window must differ by two steps or more.
    const bool resolved = p > 0.0 && p * (n.d[j] - n.d[i]) >= 2.0 * dt && 1.0 / p <= c_max;
    speed.push_back(resolved ? 1.0 / p : INFINITY);
    start_s.push_back(n.s[i]);
    start_t.push_back(n.t[i]);
  }
  std::vector<double> finite;
  for (const double v : speed) {
    if (std::isfinite(v)) {
      finite.push_back(v);
      r.peak_speed = std::max(r.peak_speed, v);
    } else {
      ++r.triggered;
    }
  }
  r.speed = median(finite);
  r.regime = crack_regime(r.speed, w);
  // Supershear: the windows from some start to the side's end all faster than c_S, over at
  // least one window's length (a single fast window at the end is not a transition).
  std::size_t k = speed.size();
  while (k > 0 && speed[k - 1] > c_s) --k;
  if (k < speed.size() && std::fabs(start_s.back() - start_s[k]) >= window * (1.0 - 1e-12)) {
    r.supershear_s = start_s[k];
    r.supershear_time = start_t[k];
  }
  return r;
}

}  // namespace

FrontSummary summarize_front(const std::vector<double>& s, const std::vector<double>& rupture_time,
                             const std::vector<unsigned char>& nucleation, double window, double dt,
                             double c_max, const WaveSpeeds& w) {
  FrontSummary r;
  const std::size_t n = s.size();
  std::size_t first = n;  // the first node to rupture
  for (std::size_t k = 0; k < n; ++k)
    if (rupture_time[k] >= 0.0 && (first == n || rupture_time[k] < rupture_time[first])) first = k;
  if (first == n) return r;
  r.ruptured = true;
  r.nucleation_time = rupture_time[first];
  // The patch: the overstressed nodes (their extent, from the first to the last), else the
  // first node to rupture.
  std::size_t lo = n, hi = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (nucleation[k]) lo = std::min(lo, k), hi = std::max(hi, k);
  r.nucleation_overstressed = lo < n;
  if (!r.nucleation_overstressed) lo = hi = first;
  r.nucleation_begin_s = s[lo];
  r.nucleation_end_s = s[hi];
  SideNodes fwd, bwd;
  for (std::size_t k = hi + 1; k < n && rupture_time[k] >= 0.0; ++k)
    fwd.d.push_back(s[k] - s[hi]), fwd.t.push_back(rupture_time[k]), fwd.s.push_back(s[k]);
  for (std::size_t k = lo; k-- > 0 && rupture_time[k] >= 0.0;)
    bwd.d.push_back(s[lo] - s[k]), bwd.t.push_back(rupture_time[k]), bwd.s.push_back(s[k]);
  r.forward = summarize_side(fwd, window, dt, c_max, w);
  r.backward = summarize_side(bwd, window, dt, c_max, w);
  r.speed = std::max(r.forward.speed, r.backward.speed);
  r.peak_speed = std::max(r.forward.peak_speed, r.backward.peak_speed);
  r.regime = crack_regime(r.speed, w);
  return r;
}

bool is_fault(const CohesiveInterface& c) {
  return std::holds_alternative<SlipWeakening>(c.spec.law) ||
         std::holds_alternative<RateStateFriction>(c.spec.law);
}

FrontSummary summarize_front(const CohesiveInterface& c, double cell_size, double dt,
                             double c_max, const WaveSpeeds& w) {
  const std::size_t n = c.num_nodes();
  std::vector<double> s(c.s0.begin(), c.s0.begin() + std::ptrdiff_t(n));
  std::vector<double> t(c.node_rupture_time.begin(), c.node_rupture_time.begin() + std::ptrdiff_t(n));
  std::vector<unsigned char> patch(n, 0);
  // Slip weakening: the nodes overstressed at t = 0. Rate-and-state has no static strength:
  // its patch is the first node to rupture (summarize_front's fallback).
  if (std::holds_alternative<SlipWeakening>(c.spec.law))
    for (std::size_t k = 0; k < n; ++k) {
      const SlipWeakening& f = std::get<SlipWeakening>(node_law_variant(c, k));
      patch[k] = std::fabs(f.tt0) > f.static_strength() ? 1 : 0;  // overstressed at t = 0
    }
  return summarize_front(s, t, patch, kFrontWindowCells * cell_size, dt, c_max, w);
}

}  // namespace rupture
