// rupture/bc/time_function.hpp
// Scalar functions of time for prescribed velocities (theory E2) and load factors (bc/loads.hpp).
// Units: value in the unit of what it scales (m/s for a velocity; 1 for a load factor), times s.
//   constant:    V(t) = value
//   trapezoid:   V = V1 t/tr (0 <= t < tr); V1 (tr <= t <= tr+tp);
//                V1 [1 - (t - tr - tp)/ts] (tr+tp < t < tr+tp+ts); 0 afterwards.
//   smooth_ramp: V = V1 (tau - sin(2 pi tau)/(2 pi)), tau = t/tr (0 <= t < tr); V1 afterwards;
//                0 before t = 0. Value and slope are continuous: dV/dt = V1 (1 - cos 2 pi tau)/tr
//                is 0 at both ends of the rise.
//   ricker:      V = V1 (1 - 2 a) exp(-a), a = [pi f0 (t - t0)]^2: the Ricker wavelet (the second
//                derivative of a Gaussian, sign reversed) of peak frequency f0 (`frequency`, Hz)
//                centred on t0 (`delay`, s); its spectrum (f/f0)^2 exp(-(f/f0)^2) peaks at f0
//                and falls to 3 % of the peak at 2.5 f0. Its integral is V1 tau exp(-a), tau = t - t0.
//   table:       value x the piecewise-linear interpolant through (t_k, v_k), k = 0..n-1, times
//                strictly increasing; v_0 before t_0 and v_{n-1} after t_{n-1} (held constant).
// (The paper prints the ramp-down with t - tp; theory E2 corrects it so V is continuous.)
// displacement(t) is the exact integral of V from 0 to t (m for a velocity): how far a driven
// edge has moved. Evaluation allocates nothing (a table is searched by bisection).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace rupture {

struct TimeFunction {
  enum class Kind { constant, trapezoid, smooth_ramp, ricker, table };
  Kind kind = Kind::constant;
  double value = 0.0;         // V1 or the constant, m/s (a table's scale)
  double rise_time = 0.0;     // tr, s (trapezoid, smooth_ramp)
  double plateau_time = 0.0;  // tp, s
  double fall_time = 0.0;     // ts, s
  double frequency = 0.0;     // f0, Hz (ricker)
  double delay = 0.0;         // t0, s (ricker)
  std::vector<double> table_t{}, table_v{};  // table points (set_table), s and value units
  std::vector<double> table_integral{};     // integral of the interpolant from t_0 to t_k

  // Makes this a table function through (t[k], v[k]); t strictly increasing (validated by input/).
  void set_table(std::vector<double> t, std::vector<double> v, double scale = 1.0) {
    kind = Kind::table;
    value = scale;
    table_t = std::move(t);
    table_v = std::move(v);
    table_integral.assign(table_t.size(), 0.0);
    for (std::size_t k = 1; k < table_t.size(); ++k)
      table_integral[k] = table_integral[k - 1] +
                          0.5 * (table_t[k] - table_t[k - 1]) * (table_v[k - 1] + table_v[k]);
  }

  double operator()(double t) const {
    if (kind == Kind::constant) return value;
    if (kind == Kind::table) return value * table_value(t);
    if (t < 0.0) return 0.0;
    if (kind == Kind::ricker) {
      const double a = ricker_exponent(t);
      return value * (1.0 - 2.0 * a) * std::exp(-a);
    }
    if (kind == Kind::smooth_ramp) {
      if (t >= rise_time) return value;
      const double tau = t / rise_time;
      return value * (tau - std::sin(2.0 * std::numbers::pi * tau) / (2.0 * std::numbers::pi));
    }
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
    if (kind == Kind::table) return value * (table_antiderivative(t) - table_antiderivative(0.0));
    if (kind == Kind::ricker)  // d/dt [tau exp(-a)] = (1 - 2a) exp(-a)
      return value * ((t - delay) * std::exp(-ricker_exponent(t)) + delay * std::exp(-ricker_exponent(0.0)));
    const double tr = rise_time, tp = plateau_time, ts = fall_time;
    if (kind == Kind::smooth_ramp) {
      if (t >= tr) return value * (0.5 * tr + (t - tr));
      const double tau = t / tr, two_pi = 2.0 * std::numbers::pi;
      // d/dtau [tau^2/2 + (cos(2 pi tau) - 1)/(4 pi^2)] = tau - sin(2 pi tau)/(2 pi)
      return value * tr * (0.5 * tau * tau + (std::cos(two_pi * tau) - 1.0) / (two_pi * two_pi));
    }
    if (t < tr) return 0.5 * value * t * t / tr;
    double u = 0.5 * value * tr;
    if (t <= tr + tp) return u + value * (t - tr);
    u += value * tp;
    const double s = t < tr + tp + ts ? t - tr - tp : ts;  // time spent on the ramp down
    return u + value * (s - 0.5 * s * s / ts);
  }

 private:
  double ricker_exponent(double t) const {
    const double u = std::numbers::pi * frequency * (t - delay);
    return u * u;
  }
  // Index k of the table interval [t_k, t_{k+1}) holding t (t_0 <= t < t_{n-1}).
  std::size_t table_interval(double t) const {
    const auto it = std::upper_bound(table_t.begin(), table_t.end(), t);
    return std::size_t(it - table_t.begin()) - 1;
  }
  double table_value(double t) const {
    if (table_t.empty()) return 0.0;
    if (t <= table_t.front()) return table_v.front();
    if (t >= table_t.back()) return table_v.back();
    const std::size_t k = table_interval(t);
    return table_v[k] + (table_v[k + 1] - table_v[k]) * (t - table_t[k]) / (table_t[k + 1] - table_t[k]);
  }
  // Integral of the (unscaled) table from t_0 to t, extended by the held end values.
  double table_antiderivative(double t) const {
    if (table_t.empty()) return 0.0;
    if (t <= table_t.front()) return table_v.front() * (t - table_t.front());
    if (t >= table_t.back())
      return table_integral.back() + table_v.back() * (t - table_t.back());
    const std::size_t k = table_interval(t);
    return table_integral[k] + 0.5 * (t - table_t[k]) * (table_v[k] + table_value(t));
  }
};

}  // namespace rupture
