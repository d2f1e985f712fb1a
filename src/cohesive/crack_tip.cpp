// rupture/cohesive/crack_tip.cpp
#include "cohesive/crack_tip.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/atomic_file.hpp"

namespace rupture {

double least_squares_slope(const double* t, const double* y, std::size_t n) {
  if (n < 2) return NAN;
  double tm = 0, ym = 0;
  for (std::size_t k = 0; k < n; ++k) tm += t[k], ym += y[k];
  tm /= double(n), ym /= double(n);
  double num = 0, den = 0;
  for (std::size_t k = 0; k < n; ++k)
    num += (t[k] - tm) * (y[k] - ym), den += (t[k] - tm) * (t[k] - tm);
  return den > 0 ? num / den : NAN;
}

CrackTracker::CrackTracker(const CohesiveInterface& c, double end_tolerance, double daughter_ligament)
    : x0_(c.x0),
      y0_(c.y0),
      s0_(c.s0),
      daughter_ligament_(daughter_ligament),
      length_(c.closed ? c.length() : 0.0),
      end_tolerance_(end_tolerance) {}

void CrackTracker::follow(const CohesiveInterface& c, bool shift_samples) {
  double shift = 0.0;
  if (shift_samples && !x0_.empty())  // the old start among the new nodes: its new arc length
    for (std::size_t j = 0; j < c.x0.size(); ++j)
      if (c.x0[j] == x0_[0] && c.y0[j] == y0_[0]) {
        shift = c.s0[j];
        break;
      }
  x0_ = c.x0, y0_ = c.y0, s0_ = c.s0;
  if (shift == 0.0) return;
  for (CrackSample& s : samples_) {
    if (s.stretch_begin.empty()) continue;  // nothing separated: tip and back stay at 0
    s.tip += shift, s.back += shift;
    for (double& b : s.stretch_begin) b += shift;
    for (double& e : s.stretch_end) e += shift;
  }
}

void CrackTracker::position(double s, double& x, double& y) const {
  if (s0_.empty()) {
    x = y = NAN;
    return;
  }
  if (length_ > 0.0) s -= length_ * std::floor(s / length_);  // closed line: s modulo its length
  const auto it = std::lower_bound(s0_.begin(), s0_.end(), s);
  const std::size_t k = std::size_t(it - s0_.begin());
  if (k < s0_.size() && s0_[k] == s) {
    x = x0_[k], y = y0_[k];
    return;
  }
  if (k == 0 || k == s0_.size()) {
    const std::size_t e = k == 0 ? 0 : s0_.size() - 1;
    x = x0_[e], y = y0_[e];
    return;
  }
  const double f = (s - s0_[k - 1]) / (s0_[k] - s0_[k - 1]);
  x = x0_[k - 1] + f * (x0_[k] - x0_[k - 1]);
  y = y0_[k - 1] + f * (y0_[k] - y0_[k - 1]);
}

namespace {

// Zone lengths ahead of the tip (from node `first`): see CrackTracker::kTractionZoneFraction.
template <class Law>
void zone_lengths(const CohesiveInterface& c, const Law& law, std::size_t first, double t,
                  CrackSample& s) {
  auto cracked_by = [&](std::size_t k) {
    return c.node_crack_time[k] >= 0.0 && c.node_crack_time[k] <= t;
  };
  // Cohesive (process) zone: intact nodes ahead of the tip already softening.
  double zone_end = s.tip;
  for (std::size_t k = first; k < c.num_nodes(); ++k) {
    if (cracked_by(k)) continue;
    if (law.softening(c.jump_normal(k), c.jump_tangential(k))) zone_end = c.s0[k];
  }
  s.cohesive_zone = zone_end - s.tip;
  double loaded_end = s.tip;
  for (std::size_t k = first; k < c.num_nodes(); ++k) {
    if (cracked_by(k)) break;  // a daughter crack ends the contiguous zone
    // Softening nodes belong to the zone whatever their (decaying) traction; ahead of them,
    // the zone goes on while the rising-branch traction stays above the fraction.
    const double dn = c.jump_normal(k), dt = c.jump_tangential(k);
    if (!law.softening(dn, dt) && law.load_fraction(dn, dt) < CrackTracker::kTractionZoneFraction)
      break;
    loaded_end = c.s0[k];
  }
  s.traction_zone = loaded_end - s.tip;
}

}  // namespace

// A closed line (cohesive/polyline.hpp) has no start: the crack is followed from the node that
// cracked first (the initiation point). Its stretch runs forward (increasing s, the tip) and
// backward (the back tip) from there, unwrapped through node 0 so both move continuously
// (tip - back reaches the line's length when the whole ring has cracked); the other stretches
// are listed going round from an intact node, so none is split at node 0.
void CrackTracker::sample_closed(const CohesiveInterface& c, double t, CrackSample& s) {
  const std::size_t n = c.num_nodes();
  const double L = c.length();
  auto cracked_by = [&](std::size_t k) {
    return c.node_crack_time[k] >= 0.0 && c.node_crack_time[k] <= t;
  };
  std::size_t first = n;
  for (std::size_t k = 0; k < n; ++k)
    if (cracked_by(k) && (first == n || c.node_crack_time[k] < c.node_crack_time[first])) first = k;
  if (first == n) return;  // intact: tip = back = 0
  std::size_t ahead = 0, behind = 0;
  while (ahead + 1 < n && cracked_by((first + ahead + 1) % n)) ++ahead;
  while (behind + ahead + 1 < n && cracked_by((first + n - behind - 1) % n)) ++behind;
  auto arc = [&](std::size_t from, std::size_t steps, int dir) {  // arc length walked, m
    double d = 0.0;
    for (std::size_t k = 0; k < steps; ++k) {
      const std::size_t seg = dir > 0 ? (from + k) % n : (from + n - k - 1) % n;
      d += c.seg_length[seg];
    }
    return d;
  };
  s.tip = c.s0[first] + arc(first, ahead, +1);
  s.back = c.s0[first] - arc(first, behind, -1);
  // Stretches, going round from an intact node.
  std::size_t start = 0;
  while (start < n && cracked_by(start)) ++start;
  if (start == n) {
    s.stretch_begin.push_back(s.back), s.stretch_end.push_back(s.tip);
    return;
  }
  bool in = false;
  double begin = 0.0, offset = 0.0;
  for (std::size_t j = 1; j <= n; ++j) {
    const std::size_t k = (start + j) % n;
    if (k == 0 && j > 0) offset = L;  // went through node 0: keep s increasing
    const bool cracked = j < n && cracked_by(k);
    const double sk = c.s0[k] + offset;
    if (cracked && !in) begin = sk;
    if (!cracked && in) {
      const std::size_t prev = (k + n - 1) % n;
      s.stretch_begin.push_back(begin);
      s.stretch_end.push_back(c.s0[prev] + (prev > k ? offset - L : offset));
    }
    in = cracked;
  }
}

void CrackTracker::sample(const CohesiveInterface& c, double t) {
  if (c.closed) {
    CrackSample s;
    s.time = t;
    sample_closed(c, t, s);
    samples_.push_back(std::move(s));
    return;
  }
  CrackSample s;
  s.time = t;
  s.tip = 0.0;
  bool in_stretch = false;
  std::size_t tip_node = 0;
  bool any = false;
  auto cracked_by = [&](std::size_t k) {
    return c.node_crack_time[k] >= 0.0 && c.node_crack_time[k] <= t;
  };
  for (std::size_t k = 0; k < c.num_nodes(); ++k) {
    const bool cracked = cracked_by(k);
    if (cracked && !in_stretch) s.stretch_begin.push_back(c.s0[k]);
    if (!cracked && in_stretch) s.stretch_end.push_back(c.s0[k - 1]);
    if (cracked) s.tip = c.s0[k], tip_node = k, any = true;
    in_stretch = cracked;
  }
  if (in_stretch) s.stretch_end.push_back(c.s0.back());
  s.back = s.stretch_begin.empty() ? 0.0 : s.stretch_begin.back();
  std::visit([&](const auto& law) { zone_lengths(c, law, any ? tip_node + 1 : 0, t, s); },
             c.spec.law);
  if (end_reached_time_ < 0.0 && any && s.tip >= c.length() - end_tolerance_) end_reached_time_ = t;
  samples_.push_back(std::move(s));
}

std::vector<double> CrackTracker::speeds() const {
  const std::size_t n = samples_.size(), half = kWindow / 2;
  std::vector<double> t(n), x(n), v(n, NAN);
  for (std::size_t k = 0; k < n; ++k) t[k] = samples_[k].time, x[k] = samples_[k].tip;
  for (std::size_t k = half; k + half < n; ++k)
    v[k] = least_squares_slope(&t[k - half], &x[k - half], kWindow);
  return v;
}

std::string crack_regime(double speed, const WaveSpeeds& w) {
  if (!(speed >= 1e-3 * w.shear)) return "none";
  if (speed < w.rayleigh) return "sub-Rayleigh";
  if (speed < w.shear) return "Rayleigh-to-shear";
  if (speed < w.dilatational) return "intersonic";
  return "supersonic";
}

CrackSummary CrackTracker::summarize(const CohesiveInterface& c, const WaveSpeeds& waves,
                                     double window) const {
  const double c_s = waves.shear;
  CrackSummary r;
  for (std::size_t k = 0; k < c.num_nodes(); ++k) {
    const double tc = c.node_crack_time[k];
    if (tc >= 0.0 && (r.initiation_time < 0.0 || tc < r.initiation_time))
      r.initiation_time = tc, r.initiation_s = c.s0[k];
  }
  r.initiated = r.initiation_time >= 0.0;
  if (samples_.empty()) return r;
  r.final_tip_s = samples_.back().tip;
  position(r.final_tip_s, r.final_tip, r.final_tip_y);
  r.final_cohesive_zone = samples_.back().cohesive_zone;
  r.final_traction_zone = samples_.back().traction_zone;
  r.end_reached_time = end_reached_time_;
  const std::vector<double> v = speeds();
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (std::isnan(v[k])) continue;
    r.peak_speed = std::max(r.peak_speed, v[k]);
    if (r.intersonic_time < 0.0 && v[k] > c_s) r.intersonic_time = samples_[k].time;
  }
  for (const CrackSample& s : samples_) {
    for (std::size_t k = 1; k < s.stretch_begin.size() && r.daughter_time < 0.0; ++k)
      if (s.stretch_begin[k] - s.stretch_end[k - 1] >= daughter_ligament_) r.daughter_time = s.time;
    if (r.daughter_time >= 0.0) break;
  }
  // The last window's slope through the tip positions (and the back tip's).
  const double t_end = samples_.back().time;
  std::vector<double> t, x, b;
  for (const CrackSample& s : samples_)
    if (s.time >= t_end - window - 1e-15)
      t.push_back(s.time), x.push_back(s.tip), b.push_back(s.back);
  r.last_window_speed = t.size() >= 2 ? least_squares_slope(t.data(), x.data(), t.size()) : 0.0;
  if (!std::isfinite(r.last_window_speed)) r.last_window_speed = 0.0;
  r.back_speed = t.size() >= 2 ? 0.0 - least_squares_slope(t.data(), b.data(), t.size()) : 0.0;
  if (!std::isfinite(r.back_speed)) r.back_speed = 0.0;
  // Arrest: the tip has stood still since arrest_time, for kArrestTime or more.
  if (r.initiated) {
    std::size_t k = samples_.size() - 1;
    while (k > 0 && samples_[k - 1].tip == samples_.back().tip) --k;
    if (samples_[k].time > r.initiation_time && t_end - samples_[k].time >= duration_floor(kArrestTime) - 1e-15) {
      r.arrested = true;
      r.arrest_time = samples_[k].time;
      r.arrest_s = samples_.back().tip;
    }
  }
  // The steady running phase (CrackSummary::sustained_speed).
  r.sustained_speed = r.last_window_speed;
  std::size_t first = 0, last = 0;
  if (r.initiated && steady_phase(v, waves.rayleigh * kMovingFraction, first, last)) {
    t.clear(), x.clear();
    for (std::size_t k = first; k <= last; ++k) t.push_back(samples_[k].time), x.push_back(samples_[k].tip);
    r.sustained_speed = least_squares_slope(t.data(), x.data(), t.size());
    r.steady_begin = samples_[first].time;
    r.steady_end = samples_[last].time;
  }
  r.regime = r.initiated ? crack_regime(r.sustained_speed, waves) : "none";
  return r;
}

double CrackTracker::duration_floor(double lab) const {
  const std::size_t n = samples_.size();
  if (n < 2) return lab;
  const double spacing = (samples_.back().time - samples_.front().time) / double(n - 1);
  return std::max(lab, kMinSamples * spacing);
}

bool CrackTracker::steady_phase(const std::vector<double>& v, double moving, std::size_t& first,
                                std::size_t& last) const {
  // For each end sample, latest first, the earliest start whose speeds all stay in the band;
  // the first end whose stretch lasts kSteadyMin wins. O(samples x stretch): a few thousand.
  const double steady_min = duration_floor(kSteadyMin);
  for (std::size_t j = v.size(); j-- > 0;) {
    if (!(v[j] > moving)) continue;
    double lo = v[j], hi = v[j];
    std::size_t i = j;
    while (i > 0 && v[i - 1] > moving) {
      const double l = std::min(lo, v[i - 1]), h = std::max(hi, v[i - 1]);
      if (h - l > kSteadyBand * (h + l)) break;
      lo = l, hi = h, --i;
    }
    if (samples_[j].time - samples_[i].time >= steady_min - 1e-15) {
      first = i, last = j;
      return true;
    }
  }
  return false;
}

void CrackTracker::write(const std::string& dir, const std::string& suffix, double c_r,
                         double c_s) const {
  const std::vector<double> v = speeds();
  // The back tip's speed (E11 window, positive when it runs towards the line's start).
  const std::size_t n = samples_.size(), half = kWindow / 2;
  std::vector<double> tt(n), bb(n), vb(n, NAN);
  for (std::size_t k = 0; k < n; ++k) tt[k] = samples_[k].time, bb[k] = samples_[k].back;
  for (std::size_t k = half; k + half < n; ++k)
    vb[k] = -least_squares_slope(&tt[k - half], &bb[k - half], kWindow);
  std::string tip =
      "time,tip_x,speed,speed_over_cR,speed_over_cS,stretches,cohesive_zone_length,"
      "leading_stretch_begin,leading_stretch_end,traction_zone_length,tip_y,tip_s,back_s,back_x,"
      "back_y,back_speed\n";
  std::string stretches = "time,index,x_begin,x_end,y_begin,y_end,s_begin,s_end\n";
  for (std::size_t k = 0; k < samples_.size(); ++k) {
    const CrackSample& s = samples_[k];
    const bool has = !s.stretch_begin.empty();
    double tx, ty, bx, by, lbx = NAN, lby, lex = NAN, ley;
    position(s.tip, tx, ty);
    position(s.back, bx, by);
    if (has) position(s.stretch_begin.back(), lbx, lby), position(s.stretch_end.back(), lex, ley);
    tip += fmt::format(
        "{:.9e},{:.9e},{:.6e},{:.6e},{:.6e},{},{:.6e},{:.9e},{:.9e},{:.6e},{:.9e},{:.9e},{:.9e},{:."
        "9e},{:.9e},{:.6e}\n",
        s.time, tx, v[k], v[k] / c_r, v[k] / c_s, s.stretch_begin.size(), s.cohesive_zone, lbx, lex,
        s.traction_zone, ty, s.tip, s.back, bx, by, vb[k]);
    for (std::size_t i = 0; i < s.stretch_begin.size(); ++i) {
      double xb, yb, xe, ye;
      position(s.stretch_begin[i], xb, yb);
      position(s.stretch_end[i], xe, ye);
      stretches += fmt::format("{:.9e},{},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e}\n", s.time, i,
                               xb, xe, yb, ye, s.stretch_begin[i], s.stretch_end[i]);
    }
  }
  write_file_atomic(dir + "/crack_tip" + suffix + ".csv", tip);
  write_file_atomic(dir + "/crack_stretches" + suffix + ".csv", stretches);
}

void write_rupture_times(const std::string& dir, const std::string& suffix,
                         const CohesiveInterface& c) {
  std::string out = "s,x,y,crack_time,rupture_time,peak_slip_rate,slip,opening\n";
  for (std::size_t k = 0; k < c.num_nodes(); ++k)
    out += fmt::format("{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.6e},{:.6e},{:.6e}\n", c.s0[k],
                       c.x0[k], c.y0[k], c.node_crack_time[k], c.node_rupture_time[k],
                       c.node_peak_slip_rate[k], c.jump_tangential(k), c.jump_normal(k));
  write_file_atomic(dir + "/rupture_time" + suffix + ".csv", out);
}

}  // namespace rupture
