// rupture/cohesive/rate_state.hpp
// Rate-and-state friction on a prestressed fault (Dieterich 1979, Ruina 1983), in the
// regularized form of the SCEC TPV101-TPV105 benchmarks (Lapusta et al. 2000; Rice & Ben-Zion
// 1996), behind the traction-law contract of cohesive/law.hpp and in the traction-offset form
// of cohesive/slip_weakening.hpp: respond() returns the traction change dT = T - T0(t) that the
// bodies receive. Formulas and their derivation: docs/faults.md "Rate-and-state friction".
// Units: Pa, m, m/s, s, Pa/m.
//
//   friction    f(V, psi) = a asinh[V / (2 V0) exp(psi / a)]          (V >= 0: slip rate)
//   strength    T = sigma f(V, psi),  sigma = max(0, -Tn) (compression)
//   evolution   aging:  d theta/dt = 1 - V theta / Dc, psi = f0 + b ln(V0 theta / Dc)
//               slip:   d psi/dt = -(V / Dc) (psi - psi_ss(V)), psi_ss = f0 - b ln(V / V0)
//               flash_heating (TPV103): the slip law with
//                 psi_ss = a ln[(2 V0 / V) sinh(f_ss(V) / a)],
//                 f_ss = f_w + (f_LV - f_w) / (1 + (V / V_w)^8)^(1/8),
//                 f_LV = f0 - (b - a) ln(V / V0)
//   prestress   T0(t) = T0 + dtau F(r) G(t) along the shear (the nucleation stress):
//               F = exp(r^2 / (r^2 - R^2)) for r < R (R = 0: F = 1 everywhere), else 0;
//               G = exp((t - T)^2 / (t (t - 2T))) for 0 < t < T, else 1 (T = 0: a step at 0+)
//
// The slip rate solve (docs/faults.md): the two faces are held by the stick spring kt, as in the
// slip-weakening law, so the plastic slip s and the shear traction satisfy
//   T = T_trial - kt dt V,  T_trial = T0(t) + kt (Dt - s_old)      (V the step's slip rate)
// and friction T = sigma f(V, psi): one equation in V, with the left side falling and the right
// rising in V, solved by a bracketed Newton iteration (unique root). Its tangent dT/dDt is
// kt sigma f_V / (sigma f_V + kt dt) < kt: the stick spring's stability bound holds.
// The state over a step at a constant rate is exact (the exponential relaxation towards the
// steady state, stable for any step), in a predictor-corrector: psi* from V_old, V* from psi*,
// psi from the mean (V_old + V*) / 2, V from psi.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "cohesive/law_types.hpp"
#include "cohesive/normal_relaxation.hpp"

namespace rupture {

enum class StateEvolution : std::uint8_t { aging, slip, flash_heating };

// The smooth taper of the TPV101-TPV103 benchmarks: the parameters keep their values within a
// distance W (half_width) of the centre and reach the taper's values beyond W + w (width)
// through
//   B(r) = 1 (r <= W),  0.5 [1 + tanh(w / (r - W - w) + w / (r - W))] (W < r < W + w),  0 beyond
//   p(r) = p_outside + (p - p_outside) B(r)            for p = a, b, Dc, V_w
// (a value <= 0 here: that parameter is not tapered). Units: m, m/s.
struct RateStateTaper {
  bool on = false;
  double x = 0.0, y = 0.0;             // m, centre
  double half_width = 0.0, width = 0.0;  // m, W and w
  double a = 0.0, b = 0.0, dc = 0.0, vw = 0.0;  // the values beyond W + w (<= 0: untapered)
  double weight(double px, double py) const {  // B(r)
    const double r = std::hypot(px - x, py - y);
    if (r <= half_width) return 1.0;
    if (r >= half_width + width) return 0.0;
    return 0.5 * (1.0 + std::tanh(width / (r - half_width - width) + width / (r - half_width)));
  }
};

// The input's names of the evolution laws ("aging", "slip", "flash_heating").
const char* evolution_name(StateEvolution e);

struct RateStateFriction {
  StateEvolution evolution = StateEvolution::aging;
  double a = 0.0, b = 0.0;           // direct and evolution effects (dimensionless, > 0)
  double dc = 0.0;                   // m, state evolution slip (L in TPV103)
  double v0 = 1e-6;                  // m/s, reference slip rate
  double f0 = 0.6;                   // reference friction coefficient at steady state at V0
  double fw = 0.0;                   // flash_heating: fully weakened friction coefficient
  double vw = 0.0;                   // flash_heating: weakening slip rate, m/s
  double v_init = 0.0;               // m/s, initial slip rate (the state balances T0 at it)
  double psi_init = 0.0;             // the initial state (set by initialize_state())
  double normal_stiffness = 0.0;     // Pa/m, kn: penalty against interpenetration
  double stick_stiffness = 0.0;      // Pa/m, kt: the faces' tangential spring
  double tn0 = 0.0;                  // Pa, initial normal traction (< 0: compression)
  double tt0 = 0.0;                  // Pa, initial shear traction
  double nucleation_stress = 0.0;    // Pa, dtau (0: none)
  double nucleation_x = 0.0, nucleation_y = 0.0;  // m, its centre
  double nucleation_radius = 0.0;    // m, R (0: uniform over the fault)
  double nucleation_time = 0.0;      // s, T (0: a step at t = 0+)
  RateStateTaper taper;              // along-strike taper of a, b, Dc, V_w (off by default)
  NormalRelaxation relaxation;       // the compression friction sees (off: -Tn itself)

  // "" when every parameter lies in its range (and the initial state balances the initial
  // traction), else "name = value: rule" for the first that does not (rate_state.cpp).
  std::string validate() const;
  // psi_init from the steady balance |tt0| = sigma0 f(v_init, psi) (sigma0 = -tn0):
  //   psi = a ln[(2 V0 / v_init) sinh(|tt0| / (sigma0 a))]
  // (the TPV101/103 initial state); false where no state balances it (no compression, no shear).
  bool initialize_state();
  // The law at a point: this one, or where a taper is on, its parameters there with the initial
  // state that balances the initial traction with them.
  RateStateFriction at(double x, double y) const {
    RateStateFriction l = *this;
    l.taper.on = false;
    if (!taper.on) return l;
    const double B = taper.weight(x, y);
    if (B == 1.0) return l;
    const auto blend = [B](double in, double out) { return out > 0.0 ? out + (in - out) * B : in; };
    l.a = blend(a, taper.a), l.b = blend(b, taper.b), l.dc = blend(dc, taper.dc), l.vw = blend(vw, taper.vw);
    l.initialize_state();
    return l;
  }

  // ---- The friction law ----
  // ln asinh-free evaluation: f = a asinh(z), z = V / (2 V0) exp(psi / a), without overflow.
  double friction(double v, double psi) const {
    const double l = std::log(v / (2.0 * v0)) + psi / a;  // ln z
    if (l > 0.0) return a * (l + std::log1p(std::sqrt(1.0 + std::exp(-2.0 * l))));
    return a * std::asinh(std::exp(l));
  }
  // df/dV = a z / (V sqrt(1 + z^2)).
  double friction_rate_derivative(double v, double psi) const {
    const double l = std::log(v / (2.0 * v0)) + psi / a;
    if (l > 0.0) return a / (v * std::sqrt(1.0 + std::exp(-2.0 * l)));
    const double z = std::exp(l);
    return a * z / (v * std::sqrt(1.0 + z * z));
  }
  // The steady-state friction coefficient at V (V > 0).
  double steady_friction(double v) const {
    const double flv = f0 - (b - a) * std::log(v / v0);
    if (evolution != StateEvolution::flash_heating) return flv;
    return fw + (flv - fw) / std::pow(1.0 + std::pow(v / vw, 8.0), 0.125);
  }
  // The state reached at a steady slip rate V (the slip laws' psi_ss; for aging, f0 - b ln(V/V0)).
  double steady_state(double v) const {
    if (evolution != StateEvolution::flash_heating) return f0 - b * std::log(v / v0);
    const double y = steady_friction(v) / a;  // ln sinh(y) = y + ln(1 - e^-2y) - ln 2
    return a * (std::log(2.0 * v0 / v) + y + std::log(-std::expm1(-2.0 * y)) - std::log(2.0));
  }
  // The state after a time dt at a constant slip rate V >= 0 from psi (exact for constant V).
  double evolve(double psi, double v, double dt) const {
    const double x = v * dt / dc;
    if (evolution == StateEvolution::aging) {
      // theta(t) = Dc / V + (theta - Dc / V) e^-x; Dc/V (1 - e^-x) = dt (1 - e^-x) / x.
      const double theta = dc / v0 * std::exp((psi - f0) / b);
      const double grow = x > 1e-12 ? -std::expm1(-x) / x * dt : dt;
      return f0 + b * std::log(v0 / dc * (theta * std::exp(-x) + grow));
    }
    if (!(v > 0.0)) return psi;
    const double ss = steady_state(v);
    return ss + (psi - ss) * std::exp(-x);
  }
  // The nucleation shape F(r) and ramp G(t).
  double nucleation_shape(double x, double y) const {
    if (nucleation_radius <= 0.0) return 1.0;
    const double r2 = (x - nucleation_x) * (x - nucleation_x) + (y - nucleation_y) * (y - nucleation_y);
    const double R2 = nucleation_radius * nucleation_radius;
    return r2 < R2 ? std::exp(r2 / (r2 - R2)) : 0.0;
  }
  double nucleation_ramp(double t) const {
    if (t <= 0.0) return 0.0;
    if (t >= nucleation_time) return 1.0;
    const double T = nucleation_time;
    return std::exp((t - T) * (t - T) / (t * (t - 2.0 * T)));
  }
  // The shear prestress at a point and time, T0(t) = tt0 + dtau F G, Pa.
  double shear_prestress(double x, double y, double t) const {
    if (nucleation_stress == 0.0) return tt0;
    return tt0 + nucleation_stress * nucleation_shape(x, y) * nucleation_ramp(t);
  }

  // The slip rate V >= 0 where |trial| - kt dt V = sigma f(V, psi) (sigma >= 0, kdt = kt dt
  // > 0): Newton on u = ln V (the friction is nearly linear in u there), kept inside the
  // bracket [V_hi e^-100, V_hi = |trial| / kdt], bisecting (in u) where a step leaves it; to a
  // relative 1e-13 in V. `guess` > 0 starts it (the last step's rate).
  double solve_slip_rate(double trial, double sigma, double psi, double kdt, double guess) const {
    const double t = std::fabs(trial);
    if (!(t > 0.0)) return 0.0;
    const double v_hi = t / kdt;
    if (!(sigma > 0.0)) return v_hi;  // no compression: free slip
    double hi = std::log(v_hi), lo = hi - 100.0;
    double u = guess > 0.0 ? std::clamp(std::log(guess), lo, hi) : hi - 20.0;
    for (int it = 0; it < 200; ++it) {
      const double v = std::exp(u);
      const double g = sigma * friction(v, psi) + kdt * v - t;  // rises with u
      if (g > 0.0) hi = u;
      else lo = u;
      const double dg = v * (sigma * friction_rate_derivative(v, psi) + kdt);
      double next = u - g / dg;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::fabs(next - u) <= 1e-13 || hi - lo <= 1e-13) return std::exp(next);
      u = next;
    }
    return std::exp(u);
  }

  // ---- The contract's members (cohesive/law.hpp) ----
  double fracture_energy_normal() const { return 0.0; }
  // Rate-and-state has no fixed fracture energy (it depends on the slip history); 0.
  double fracture_energy_tangential() const { return 0.0; }
  double initial_stiffness() const { return std::max(normal_stiffness, stick_stiffness); }
  bool separated(const GaussHistory&) const { return false; }  // friction never lets go
  // A node has broken once its slip reaches Dc (the state has then largely evolved).
  double crack_measure(double /*dn*/, double dt) const { return std::fabs(dt) / dc; }
  double crack_threshold(double /*separation_factor*/) const { return 1.0; }
  bool softening(double /*dn*/, double dt) const { return std::fabs(dt) >= opening_scale(); }
  double opening_scale() const { return 1e-2 * dc; }
  bool separates_at(double, double, double) const { return false; }
  double load_fraction(double, double) const { return 0.0; }
  static constexpr bool kSlipPathRate = true;
  static constexpr const char* kName = "rate_state";

  // The traction change dT at jumps (dn, dt). History (cohesive/law_types.hpp): h.slip = the
  // plastic slip s (the stick spring's rest length), h.damage = the slip path, h.state =
  // psi - psi_init, h.rate = V - v_init (signed V along t), h.normal_seen = sigma* - sigma0
  // (with a regularization); inputs h.x, h.y, h.time (the
  // point and the time of the jumps) and h.duration (the step that led there, s).
  LawResponse respond(double dn, double dt, GaussHistory& h) const {
    if (taper.on) return at(h.x, h.y).respond(dn, dt, h);
    const double kt = stick_stiffness;
    LawResponse r{0.0, 0.0, initial_stiffness()};
    const double t0 = shear_prestress(h.x, h.y, h.time);
    const double tn = tn0 + normal_stiffness * dn;
    // The compression friction sees: -Tn, or with a regularization the relaxed sigma*
    // (cohesive/normal_relaxation.hpp; h.normal_seen updated).
    const double sigma =
        relaxation.seen(std::max(0.0, -tn), std::max(0.0, -tn0), dt - h.jump_t, h.duration, h);
    const double psi_old = psi_init + h.state, v_old = std::fabs(v_init + h.rate);
    const double step = h.duration;
    const double trial = t0 + kt * (dt - h.slip);
    if (!(step > 0.0)) {  // no time has passed: the spring alone (t = 0)
      r.tn = (tn > 0.0 ? 0.0 : tn) - tn0, r.tt = (tn > 0.0 ? 0.0 : trial) - t0;
      return r;
    }
    const double kdt = kt * step;
    double v, psi;
    if (tn > 0.0) {  // open: no traction, the spring follows the jump
      v = std::fabs(trial) / kdt;
      psi = evolve(psi_old, v, step);
    } else {
      const double pred = evolve(psi_old, v_old, step);  // predictor
      const double v_pred = solve_slip_rate(trial, sigma, pred, kdt, v_old);
      psi = evolve(psi_old, 0.5 * (v_old + v_pred), step);  // corrector
      v = solve_slip_rate(trial, sigma, psi, kdt, v_pred);
    }
    const double signed_v = std::copysign(v, trial);
    const double tt = tn > 0.0 ? 0.0 : trial - kdt * signed_v;
    h.slip += signed_v * step;
    h.damage += v * step;
    h.state = psi - psi_init;
    h.rate = signed_v - v_init;
    r.tn = (tn > 0.0 ? 0.0 : tn) - tn0, r.tt = tt - t0;
    return r;
  }

  // The penalty springs' energy while closed (cohesive/slip_weakening.hpp's stored_energy).
  double stored_energy(double dn, double dt, const GaussHistory& h) const {
    if (tn0 + normal_stiffness * dn > 0.0) return 0.0;
    const double stick = dt - h.slip;
    return 0.5 * normal_stiffness * dn * dn + 0.5 * stick_stiffness * stick * stick;
  }
};

}  // namespace rupture
