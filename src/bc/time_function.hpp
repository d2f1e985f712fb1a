// rupture/bc/time_function.hpp
// Scalar functions of time for prescribed velocities (SPEC E2). Units: value in m/s, times in s.
//   constant:  V(t) = value
//   trapezoid: V = V1 t/tr (0 <= t < tr); V1 (tr <= t <= tr+tp);
//              V1 [1 - (t - tr - tp)/ts] (tr+tp < t < tr+tp+ts); 0 afterwards.
// (The paper prints the ramp-down with t - tp; SPEC E2 corrects it so V is continuous.)
// displacement(t) is the exact integral of V from 0 to t (m): how far a driven edge has moved.
#pragma once

namespace rupture {

struct TimeFunction {
  enum class Kind { constant, trapezoid };
  Kind kind = Kind::constant;
  double value = 0.0;         // V1 or the constant, m/s
  double rise_time = 0.0;     // tr, s
  double plateau_time = 0.0;  // tp, s
  double fall_time = 0.0;     // ts, s

  double operator()(double t) const {
    if (kind == Kind::constant) return value;
    if (t < 0.0) return 0.0;
    if (t < rise_time) return value * t / rise_time;
    const double t_end_plateau = rise_time + plateau_time;
    if (t <= t_end_plateau) return value;
    if (t < t_end_plateau + fall_time) return value * (1.0 - (t - t_end_plateau) / fall_time);
    return 0.0;
  }

  // Integral of V over [0, t], m (0 for t <= 0).
  double displacement(double t) const {
    if (t <= 0.0) return 0.0;
    if (kind == Kind::constant) return value * t;
    const double tr = rise_time, tp = plateau_time, ts = fall_time;
    if (t < tr) return 0.5 * value * t * t / tr;
    double u = 0.5 * value * tr;
    if (t <= tr + tp) return u + value * (t - tr);
    u += value * tp;
    const double s = t < tr + tp + ts ? t - tr - tp : ts;  // time spent on the ramp down
    return u + value * (s - 0.5 * s * s / ts);
  }
};

}  // namespace rupture
