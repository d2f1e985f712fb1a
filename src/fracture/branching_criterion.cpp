// rupture/fracture/branching_criterion.cpp
#include "fracture/branching_criterion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rupture {
namespace {

// 4 a_d a_s - (1 + a_s^2)^2 (Rayleigh's function, Freund's D(v)).
double rayleigh_function(double v, const WaveSpeeds& w) {
  const double ad = std::sqrt(1.0 - v * v / (w.dilatational * w.dilatational)), as2 = 1.0 - v * v / (w.shear * w.shear);
  return 4.0 * ad * std::sqrt(as2) - (1.0 + as2) * (1.0 + as2);
}

}  // namespace

double rayleigh_speed(const WaveSpeeds& w) {
  // D > 0 just above v = 0 (D ~ 2 (1 - c_s^2/c_d^2) v^2/c_s^2) and D = -1 at c_s.
  double lo = 1e-3 * w.shear, hi = w.shear;
  for (int i = 0; i < 200 && hi - lo > 1e-14 * w.shear; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rayleigh_function(mid, w) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

AngularStress running_mode_one(double theta, double v, const WaveSpeeds& w) {
  // Freund (1990) eq. 4.3.11: with a_d,s = sqrt(1 - v^2/c_d,s^2), the point (r cos t, r sin t)
  // seen in the scaled coordinates (x, a y): gamma = sqrt(1 - (v sin t / c)^2) = r_d,s / r,
  // tan theta_d,s = a_d,s tan theta.
  const double ad = std::sqrt(1.0 - v * v / (w.dilatational * w.dilatational)), as = std::sqrt(1.0 - v * v / (w.shear * w.shear));
  const double D = 4.0 * ad * as - (1.0 + as * as) * (1.0 + as * as);
  const double c = std::cos(theta), s = std::sin(theta);
  const double td = std::atan2(ad * s, c), ts = std::atan2(as * s, c);
  const double gd = std::sqrt(c * c + ad * ad * s * s), gs = std::sqrt(c * c + as * as * s * s);
  const double cd = std::cos(0.5 * td) / std::sqrt(gd), cs = std::cos(0.5 * ts) / std::sqrt(gs);
  const double sd = std::sin(0.5 * td) / std::sqrt(gd), ss = std::sin(0.5 * ts) / std::sqrt(gs);
  AngularStress a;
  a.xx = ((1.0 + as * as) * (1.0 + 2.0 * ad * ad - as * as) * cd - 4.0 * ad * as * cs) / D;
  a.yy = (-(1.0 + as * as) * (1.0 + as * as) * cd + 4.0 * ad * as * cs) / D;
  a.xy = 2.0 * ad * (1.0 + as * as) * (sd - ss) / D;
  return a;
}

double running_hoop(double theta, double v, const WaveSpeeds& w) {
  const AngularStress a = running_mode_one(theta, v, w);
  const double c = std::cos(theta), s = std::sin(theta);
  return a.xx * s * s + a.yy * c * c - 2.0 * a.xy * s * c;
}

double largest_hoop_angle(double v, const WaveSpeeds& w) {
  // A scan at 0.1 degree, then golden-section refinement around the best point.
  constexpr int kScan = 900;
  constexpr double kHalfPi = 0.5 * std::numbers::pi;
  int best = 0;
  double top = running_hoop(0.0, v, w);
  for (int i = 1; i <= kScan; ++i) {
    const double f = running_hoop(kHalfPi * i / kScan, v, w);
    if (f > top) top = f, best = i;
  }
  if (best == 0) return 0.0;
  double a = kHalfPi * std::max(best - 1, 0) / kScan, b = kHalfPi * std::min(best + 1, kScan) / kScan;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 60; ++i) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (running_hoop(x1, v, w) > running_hoop(x2, v, w))
      b = x2;
    else
      a = x1;
  }
  return 0.5 * (a + b);
}

double yoffe_speed(const WaveSpeeds& w) {
  // The hoop stress is even in theta: its largest value leaves the axis where its curvature
  // there changes sign, read as f(delta) - f(0) ~ f''(0) delta^2 / 2.
  constexpr double kDelta = 1e-3;
  auto off_axis = [&](double v) { return running_hoop(kDelta, v, w) > running_hoop(0.0, v, w); };
  const double cR = rayleigh_speed(w);
  double lo = 1e-3 * cR, hi = 0.999 * cR;
  if (!off_axis(hi)) return cR;
  for (int i = 0; i < 100 && hi - lo > 1e-12 * cR; ++i) {
    const double mid = 0.5 * (lo + hi);
    (off_axis(mid) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

BranchDecision decide_branching(double v, const WaveSpeeds& w) {
  BranchDecision d;
  if (!(v >= yoffe_speed(w)) || v >= rayleigh_speed(w)) return d;
  d.angle = largest_hoop_angle(v, w);
  d.branch = d.angle > 0.0;
  return d;
}

}  // namespace rupture
