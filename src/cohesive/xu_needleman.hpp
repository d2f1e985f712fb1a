// rupture/cohesive/xu_needleman.hpp
// The Xu-Needleman exponential traction-separation law (theory E7) with the interpenetration
// penalty (theory E8). Units: tractions and strengths in Pa, openings in m, energies in J/m^2.
// Returned tractions are the resisting magnitudes T^ = dphi/dDelta in (normal, tangential)
// components; the interface applies -T^ to the upper face and +T^ to the lower face.
// Contract: delta_n, delta_t > 0; r != 1; everything finite.
#pragma once
#include <algorithm>
#include <cmath>

#include "cohesive/law_types.hpp"

namespace rupture {

struct CohesiveTraction {
  double normal;      // T^n, Pa
  double tangential;  // T^t, Pa
};

// The law's tangent stiffness dT^/dDelta (Pa/m), symmetric (T^ is the gradient of phi).
struct CohesiveTangent {
  double nn, nt, tt;  // dTn/dDn, dTn/dDt = dTt/dDn, dTt/dDt
  // Largest eigenvalue, or 0 where the law softens in every direction (no stiffness to
  // destabilise the explicit step).
  double max_eigenvalue() const {
    const double mean = 0.5 * (nn + tt), half = 0.5 * (nn - tt);
    return std::max(0.0, mean + std::sqrt(half * half + nt * nt));
  }
};

struct XuNeedleman {
  double sigma_max = 0.0;  // Pa
  double tau_max = 0.0;    // Pa
  double delta_n = 0.0;    // m
  double delta_t = 0.0;    // m
  double q = 1.0;          // phi_t / phi_n (theory (E7): phi_t = sqrt(e/2) tau_max delta_t)
  double r = 0.0;          // Delta_n* / delta_n
  double penalty = 1.0;    // k_pen: K = k_pen phi_n / delta_n^2 for Delta_n < 0 (E8)

  double phi_n() const { return std::exp(1.0) * sigma_max * delta_n; }
  double phi_t() const { return std::sqrt(std::exp(1.0) / 2.0) * tau_max * delta_t; }
  double penalty_stiffness() const { return penalty * phi_n() / (delta_n * delta_n); }
  // Initial normal stiffness of the law, e sigma_max / delta_n (theory E6).
  double initial_stiffness() const { return std::exp(1.0) * sigma_max / delta_n; }

  // Normalized openings and their exponentials, shared by the traction and its tangent.
  struct Openings {
    double xn, xt;  // Dn / delta_n, Dt / delta_t
    double en, et;  // e^{-xn}, e^{-xt^2}
  };
  Openings openings(double dn, double dt) const {
    const double xn = dn / delta_n, xt = dt / delta_t;
    return {xn, xt, std::exp(-xn), std::exp(-xt * xt)};
  }

  // theory E7 (+ E8 for dn < 0). dn, dt: normal and tangential openings, m.
  CohesiveTraction traction(double dn, double dt) const { return traction(openings(dn, dt), dn); }
  CohesiveTraction traction(const Openings& o, double dn) const {
    const double pn = phi_n();
    CohesiveTraction T;
    T.normal =
        (pn / delta_n) * o.en * (o.xn * o.et + (1.0 - q) / (r - 1.0) * (1.0 - o.et) * (r - o.xn));
    T.tangential = (pn / delta_n) * (2.0 * delta_n / delta_t) * o.xt *
                   (q + (r - q) / (r - 1.0) * o.xn) * o.en * o.et;
    if (dn < 0.0) T.normal += penalty_stiffness() * dn;
    return T;
  }

  // dT^/dDelta of E7 (+ E8 when compressed), differentiated in closed form.
  CohesiveTangent tangent(double dn, double dt) const {
    return tangent(openings(dn, dt), dn < 0.0);
  }
  CohesiveTangent tangent(const Openings& o, bool compressed) const {
    const double pn = phi_n();
    const double a = (1.0 - q) / (r - 1.0), b = (r - q) / (r - 1.0);
    CohesiveTangent K;
    K.nn = pn / (delta_n * delta_n) * o.en *
           (o.et * (1.0 - o.xn) - a * (1.0 - o.et) * (1.0 + r - o.xn));
    K.nt = 2.0 * pn / (delta_n * delta_t) * o.xt * o.en * o.et * (b - q - b * o.xn);
    K.tt =
        2.0 * pn / (delta_t * delta_t) * (q + b * o.xn) * o.en * o.et * (1.0 - 2.0 * o.xt * o.xt);
    if (compressed) K.nn += penalty_stiffness();
    return K;
  }

  // The stiffness that bounds the explicit step at this opening (theory E6, docs/time_step.md):
  // the largest tangent eigenvalue, taken also on the compressed side of Dn = 0 when the face
  // is open or just closed, since the penalty (E8) switches on there and a step's round-off
  // moves a closed face across the kink.
  double stability_stiffness(double dn, double dt) const {
    return stability_stiffness(openings(dn, dt), dn);
  }
  double stability_stiffness(const Openings& o, double dn) const {
    const double here = tangent(o, dn < 0.0).max_eigenvalue();
    if (dn < 0.0) return here;
    const Openings closed{0.0, o.xt, 1.0, o.et};  // Dn -> 0 from below, same Dt
    return std::max(here, tangent(closed, true).max_eigenvalue());
  }

  // The potential phi(dn, dt) whose gradient is the traction (J/m^2), penalty included:
  // phi = phi_n + phi_n e^{-xn} { [1 - r + xn] (1-q)/(r-1) - [q + (r-q)/(r-1) xn] e^{-xt^2} }.
  double potential(double dn, double dt) const {
    const double pn = phi_n();
    const double xn = dn / delta_n, xt = dt / delta_t;
    double phi = pn + pn * std::exp(-xn) *
                          ((1.0 - r + xn) * (1.0 - q) / (r - 1.0) -
                           (q + (r - q) / (r - 1.0) * xn) * std::exp(-xt * xt));
    if (dn < 0.0) phi += 0.5 * penalty_stiffness() * dn * dn;
    return phi;
  }

  // The traction-law contract (cohesive/law.hpp), as thin wrappers of the functions above with
  // bitwise the same results. The law has no history: it is elastic (a potential), and its
  // separation criterion (|Delta| >= 5 delta_t, theory (E9)) belongs to the interface.
  LawResponse respond(double dn, double dt, GaussHistory& /*unused*/) const {
    const Openings o = openings(dn, dt);
    const CohesiveTraction T = traction(o, dn);
    return {T.normal, T.tangential, stability_stiffness(o, dn)};
  }
  double stored_energy(double dn, double dt, const GaussHistory& /*unused*/) const {
    return potential(dn, dt);
  }
  double fracture_energy_normal() const { return phi_n(); }
  double fracture_energy_tangential() const { return phi_t(); }
  bool separated(const GaussHistory& /*unused*/) const { return false; }
  // Crack tracking (E10, theory §3): a node has cracked once |jump| reaches separation_factor x
  // delta_t; past the peak shear traction (delta_t / sqrt 2) it is softening; delta_n is the
  // law's small opening scale (the instability watch's floor).
  double crack_measure(double dn, double dt) const { return std::hypot(dn, dt); }
  double crack_threshold(double separation_factor) const { return separation_factor * delta_t; }
  bool softening(double dn, double dt) const {
    return std::hypot(dn, dt) >= delta_t / std::sqrt(2.0);
  }
  double opening_scale() const { return delta_n; }
  // Separated at |jump| >= separation_factor x delta_t (theory §3), asked by the interface loop
  // before respond(). Squares, not std::hypot (a libm call, ~1 % of a run): the openings are
  // far from overflow, and the two differ only within an ulp of the threshold.
  bool separates_at(double dn, double dt, double separation_factor) const {
    const double threshold = crack_threshold(separation_factor);
    return dn * dn + dt * dt >= threshold * threshold;
  }
  // The pristine traction as a fraction of the strengths: max(|Tt| / tau_max, Tn / sigma_max).
  double load_fraction(double dn, double dt) const {
    GaussHistory fresh;
    const LawResponse pristine = respond(dn, dt, fresh);
    return std::max(std::fabs(pristine.tt) / tau_max, pristine.tn / sigma_max);
  }
  static constexpr bool kSlipPathRate = false;  // the slip rate is the jump's
  static constexpr const char* kName = "xu_needleman";
};

}  // namespace rupture
