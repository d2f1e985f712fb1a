// rupture/cohesive/bilinear.hpp
// A bilinear (linear-softening) mixed-mode cohesive law with irreversible damage, after
// Geubelle & Baylor (1998), Composites Part B 29:589-602. Elastic up to an effective opening
// lambda0, softening linearly to zero traction at lambda = 1, unloading along the secant to
// the origin, a penalty against interpenetration. Formulas: docs/cohesive_laws.md.
// Units: tractions Pa, openings m, stiffnesses Pa/m, energies J/m^2.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>

#include "cohesive/law_types.hpp"

namespace rupture {

// dT^/dDelta of the bilinear law: not symmetric in general (the softening law has a potential
// only when G_Ic = G_IIc), but its eigenvalues are real (see BilinearLaw::tangent).
struct BilinearTangent {
  double nn, nt, tn, tt;  // dTn/dDn, dTn/dDt, dTt/dDn, dTt/dDt
  // Largest real part of the eigenvalues, or 0 where none is positive.
  double max_eigenvalue() const {
    const double mean = 0.5 * (nn + tt), half = 0.5 * (nn - tt);
    const double disc = half * half + nt * tn;
    return std::max(0.0, disc > 0.0 ? mean + std::sqrt(disc) : mean);
  }
};

struct BilinearLaw {
  double sigma_max = 0.0;  // Pa, mode I strength (peak normal traction)
  double tau_max = 0.0;    // Pa, mode II strength (peak tangential traction)
  double delta_nc = 0.0;   // m, critical normal opening (zero traction beyond, pure mode I)
  double delta_tc = 0.0;   // m, critical tangential opening (pure mode II)
  double lambda0 = 0.01;   // effective opening at the peak, in (0, 1): end of the elastic part
  double penalty = 1.0;    // k_pen = penalty * sigma_max / (lambda0 delta_nc) for Dn < 0

  // "" when every parameter lies in its range, else a message naming the first one that does
  // not, its value and the range (bilinear.cpp).
  std::string validate() const;

  double penalty_stiffness() const { return penalty * sigma_max / (lambda0 * delta_nc); }
  double fracture_energy_normal() const { return 0.5 * sigma_max * delta_nc; }    // G_Ic
  double fracture_energy_tangential() const { return 0.5 * tau_max * delta_tc; }  // G_IIc
  // Energy to separate along a straight opening ray (Dn, Dt) ∝ (dir_n, dir_t), dir_n >= 0:
  // G = G_Ic cos^2 psi + G_IIc sin^2 psi, psi the ray's angle in (Dn/delta_nc, Dt/delta_tc).
  double fracture_energy_radial(double dir_n, double dir_t) const {
    const double a = std::max(dir_n, 0.0) / delta_nc, b = dir_t / delta_tc;
    return (fracture_energy_normal() * a * a + fracture_energy_tangential() * b * b) /
           (a * a + b * b);
  }
  // The largest eigenvalue of the undamaged elastic stiffness (open side, penalty excluded).
  double initial_stiffness() const {
    return std::max(sigma_max / delta_nc, tau_max / delta_tc) / lambda0;
  }

  // Effective opening lambda = sqrt((<Dn>/delta_nc)^2 + (Dt/delta_tc)^2).
  double effective_opening(double dn, double dt) const {
    const double xn = std::max(dn, 0.0) / delta_nc, xt = dt / delta_tc;
    return std::sqrt(xn * xn + xt * xt);
  }
  // Secant factor g(kappa) = (1 - kappa) / ((1 - lambda0) kappa) for kappa = max(lambda0, S)
  // in [lambda0, 1], 0 beyond: Tn = sigma_max g Dn/delta_nc, Tt = tau_max g Dt/delta_tc.
  double secant_factor(double damage) const {
    const double kappa = std::max(lambda0, damage);
    return kappa >= 1.0 ? 0.0 : (1.0 - kappa) / ((1.0 - lambda0) * kappa);
  }
  bool separated(const GaussHistory& h) const { return h.damage >= 1.0; }
  // Crack tracking (E10): a node has cracked once its effective opening reaches 1 (full
  // softening); it softens beyond lambda0; lambda0 x the smaller critical opening is the
  // law's small opening scale (the instability watch's floor).
  double crack_measure(double dn, double dt) const { return effective_opening(dn, dt); }
  double crack_threshold(double /*separation_factor*/) const { return 1.0; }
  bool softening(double dn, double dt) const { return effective_opening(dn, dt) >= lambda0; }
  double opening_scale() const { return lambda0 * std::min(delta_nc, delta_tc); }
  // Its damage separates it (separated()): the interface has no criterion of its own.
  bool separates_at(double /*dn*/, double /*dt*/, double /*separation_factor*/) const {
    return false;
  }
  // The pristine traction as a fraction of the strengths: max(|Tt| / tau_max, Tn / sigma_max).
  double load_fraction(double dn, double dt) const {
    GaussHistory fresh;
    const LawResponse r = respond(dn, dt, fresh);
    return std::max(std::fabs(r.tt) / tau_max, r.tn / sigma_max);
  }
  static constexpr bool kSlipPathRate = false;  // the slip rate is the jump's
  static constexpr const char* kName = "bilinear";

  // Traction at (dn, dt) after updating the damage S = max(S, lambda) (irreversible).
  LawResponse respond(double dn, double dt, GaussHistory& h) const {
    const double xn = std::max(dn, 0.0) / delta_nc, xt = dt / delta_tc;
    h.damage = std::max(h.damage, std::sqrt(xn * xn + xt * xt));
    const double g = secant_factor(h.damage);
    const double kp = penalty_stiffness();
    LawResponse r;
    r.tn = sigma_max * g * xn + (dn < 0.0 ? kp * dn : 0.0);  // penalty independent of Dt
    r.tt = tau_max * g * xt;
    r.stiffness = stability_stiffness(g);
    return r;
  }

  // The stability stiffness (docs/time_step.md) for secant factor g. The tangent's largest
  // eigenvalue is at most the secant's, g max(sigma_max/delta_nc, tau_max/delta_tc) (see
  // tangent); the penalty is always included, as XuNeedleman::stability_stiffness does for a
  // face that is open or just closed: a step can move it across Dn = 0.
  double stability_stiffness(double g) const {
    return std::max(g * std::max(sigma_max / delta_nc, tau_max / delta_tc), penalty_stiffness());
  }

  // Recoverable energy of the damaged spring at (dn, dt) with the damage respond() would leave:
  // 0.5 T.Delta = 0.5 g (sigma_max delta_nc xn^2 + tau_max delta_tc xt^2) + 0.5 k_pen <-Dn>^2.
  double stored_energy(double dn, double dt, const GaussHistory& h) const {
    const double xn = std::max(dn, 0.0) / delta_nc, xt = dt / delta_tc;
    const double g = secant_factor(std::max(h.damage, std::sqrt(xn * xn + xt * xt)));
    const double closed = std::min(dn, 0.0);
    return 0.5 * g * (sigma_max * delta_nc * xn * xn + tau_max * delta_tc * xt * xt) +
           0.5 * penalty_stiffness() * closed * closed;
  }

  // dT^/dDelta for a step from history h to (dn, dt), in closed form. Unloading, reloading or
  // elastic (lambda <= max(lambda0, S)): the secant diag(g sigma_max/delta_nc, g tau_max/
  // delta_tc). Softening (lambda > max(lambda0, S)): K = D_s - g'(lambda) c x (x/delta)^T with
  // c = (sigma_max, tau_max), g' = -1 / ((1 - lambda0) lambda^2). The rank-one term is similar
  // (diagonal scaling by sqrt(c_i delta_i)) to a symmetric positive one, so the eigenvalues are
  // real and at most those of the secant (Weyl): the secant bounds the step. Dn < 0: the normal
  // row and column are the penalty's alone.
  BilinearTangent tangent(double dn, double dt, const GaussHistory& h) const {
    const double xn = std::max(dn, 0.0) / delta_nc, xt = dt / delta_tc;
    const double lambda = std::sqrt(xn * xn + xt * xt);
    const double g = secant_factor(std::max(h.damage, lambda));
    BilinearTangent K{sigma_max * g / delta_nc, 0.0, 0.0, tau_max * g / delta_tc};
    if (lambda > std::max(lambda0, h.damage) && lambda < 1.0) {
      const double s = 1.0 / ((1.0 - lambda0) * lambda * lambda * lambda);  // -g'(lambda)/lambda
      K.nn -= s * sigma_max * xn * xn / delta_nc;
      K.nt -= s * sigma_max * xn * xt / delta_tc;
      K.tn -= s * tau_max * xt * xn / delta_nc;
      K.tt -= s * tau_max * xt * xt / delta_tc;
    }
    if (dn < 0.0) K.nn = penalty_stiffness(), K.nt = 0.0, K.tn = 0.0;
    return K;
  }
};

}  // namespace rupture
