// rupture/cohesive/slip_weakening.hpp
// Linear slip-weakening friction on a prestressed fault (Ida 1972; Andrews 1976), in the
// traction-offset form of dynamic-rupture codes: the bulk carries the stress change, the fault
// adds its initial traction (tn0, tt0). Keeps the traction-law contract of cohesive/law.hpp:
// respond() returns the traction *change* dT = T - T0 that the bodies receive (upper face -dT),
// so a fault at rest under a prestress below its strength loads nothing. Formulas:
// docs/cohesive_laws.md "Slip-weakening friction". Units: Pa, m, Pa/m, J/m^2.
//
// Total traction T = T0 + dT, normal tension positive (tn < 0 compresses the fault):
//   closed (tn0 + kn Dn <= 0):  Tn = tn0 + kn Dn                (penalty: no interpenetration)
//                               strength = cohesion + mu(D) (-Tn)
//                               stuck:   Tt = tt0 + kt (Dt - slip)   while |Tt| <= strength
//                               sliding: Tt = strength sign(trial), slip = Dt - (Tt - tt0)/kt
//   open (tn0 + kn Dn > 0):     T = 0 (the faces part; dT = -T0)
//   mu(D) = mu_s - (mu_s - mu_d) min(D, Dc) / Dc,   D = slip path (GaussHistory::damage)
// D grows by |dDt| over every step in which the point slides or is open: the weakening follows
// the jump the bulk sees, so the sliding fault obeys T = strength(D) with no error from the
// stick penalty (the 1D test's ODE tau0 - (rho c_S / 2) V = strength(D) holds exactly).
// With a normal-stress regularization (cohesive/normal_relaxation.hpp) the strength's
// compression is the relaxed sigma* instead of -Tn; the penalty's Tn itself is unchanged.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>

#include "cohesive/law_types.hpp"
#include "cohesive/normal_relaxation.hpp"

namespace rupture {

struct SlipWeakening {
  double static_friction = 0.0;   // mu_s
  double dynamic_friction = 0.0;  // mu_d <= mu_s
  double dc = 0.0;                // m, slip-weakening distance
  double cohesion = 0.0;          // Pa, >= 0
  double normal_stiffness = 0.0;  // Pa/m, kn: penalty against interpenetration
  double stick_stiffness = 0.0;   // Pa/m, kt: stuck faces' tangential spring
  double tn0 = 0.0;               // Pa, initial normal traction (< 0: compression)
  double tt0 = 0.0;               // Pa, initial shear traction (> 0 drives the upper face along +t)
  NormalRelaxation relaxation;    // the compression friction sees (off: -Tn itself)

  // "" when every parameter lies in its range, else a message naming the first one that does
  // not, its value and the range (slip_weakening.cpp).
  std::string validate() const;

  double friction(double slip_path) const {
    return static_friction -
           (static_friction - dynamic_friction) * std::min(slip_path, dc) / dc;
  }
  // Shear strength at normal traction tn (tension positive) after a slip path D, Pa.
  double strength(double tn, double slip_path) const {
    return cohesion + friction(slip_path) * std::max(0.0, -tn);
  }
  // Stress drop measures of the fault at its initial normal traction, Pa.
  double static_strength() const { return strength(tn0, 0.0); }
  double dynamic_strength() const { return strength(tn0, dc); }
  // (mu_s - mu_d) |tn0| / Dc: how fast strength falls with slip at the initial normal traction.
  double weakening_rate() const { return (static_friction - dynamic_friction) * std::max(0.0, -tn0) / dc; }

  // The contract's members (cohesive/law.hpp). Fracture energy: the area under the weakening
  // curve above the dynamic level, 0.5 (mu_s - mu_d) |tn0| Dc (mode II; mode I has none).
  double fracture_energy_normal() const { return 0.0; }
  double fracture_energy_tangential() const { return 0.5 * weakening_rate() * dc * dc; }
  double initial_stiffness() const { return std::max(normal_stiffness, stick_stiffness); }
  bool separated(const GaussHistory&) const { return false; }  // friction never lets go
  // A node has broken once its slip reaches Dc (the end of the weakening zone, E10's tip).
  double crack_measure(double /*dn*/, double dt) const { return std::fabs(dt) / dc; }
  double crack_threshold(double /*separation_factor*/) const { return 1.0; }
  // Slipping: the jump has passed a hundredth of Dc (the instability watch's scale too).
  bool softening(double /*dn*/, double dt) const { return std::fabs(dt) >= opening_scale(); }
  double opening_scale() const { return 1e-2 * dc; }
  // Friction never lets go; its rupture front is the slip of its path D (GaussHistory::damage):
  // a node's slip rate is that of D, sliding only (the stick spring's elastic jump, which
  // passing waves load, is no slip). No traction zone ahead of the tip: the zone is where the
  // fault slips (softening).
  bool separates_at(double /*dn*/, double /*dt*/, double /*separation_factor*/) const {
    return false;
  }
  double load_fraction(double /*dn*/, double /*dt*/) const { return 0.0; }
  static constexpr bool kSlipPathRate = true;
  static constexpr const char* kName = "slip_weakening";

  // The traction change dT at jumps (dn, dt); h.damage = slip path D, h.slip = the stick
  // spring's rest length, h.jump_t = dt at the previous call (the loop's gp_dt),
  // h.normal_seen = sigma* - sigma0 (with a regularization; h.duration the step).
  LawResponse respond(double dn, double dt, GaussHistory& h) const {
    const double kt = stick_stiffness;
    LawResponse r{0.0, 0.0, initial_stiffness()};  // closed or about to close: max(kn, kt)
    const double path = std::fabs(dt - h.jump_t);
    const double tn = tn0 + normal_stiffness * dn;
    const double seen = relaxation.seen(std::max(0.0, -tn), std::max(0.0, -tn0), dt - h.jump_t,
                                        h.duration, h);  // -Tn without a regularization
    if (tn > 0.0) {  // open: no traction; the stick spring follows, the path grows
      h.damage += path;
      h.slip = dt + tt0 / kt;
      r.tn = -tn0, r.tt = -tt0;
      return r;
    }
    const double trial = tt0 + kt * (dt - h.slip);
    double tt = trial;
    const double s_trial = strength(-seen, h.damage + path);
    if (std::fabs(trial) > s_trial) {
      h.damage += path;
      tt = std::copysign(s_trial, trial);
      h.slip = dt - (tt - tt0) / kt;
    }
    r.tn = tn - tn0, r.tt = tt - tt0;
    return r;
  }

  // Energy held by the two penalty springs (relative to the prestressed state) while closed:
  // 0.5 kn Dn^2 + 0.5 kt (Dt - slip)^2. Work done on the point minus this = the work of the
  // traction change on the slip, int (T - T0) dslip (the prestress's own share, int T0 dslip,
  // is released by the bulk, whose energy E14 counts from the prestressed state).
  // Open faces hold nothing.
  double stored_energy(double dn, double dt, const GaussHistory& h) const {
    if (tn0 + normal_stiffness * dn > 0.0) return 0.0;
    const double stick = dt - h.slip;
    return 0.5 * normal_stiffness * dn * dn + 0.5 * stick_stiffness * stick * stick;
  }

  // The total traction T = T0 + dT for a response r (outputs: stations, profiles).
  double total_normal(const LawResponse& r) const { return tn0 + r.tn; }
  double total_shear(const LawResponse& r) const { return tt0 + r.tt; }
};

}  // namespace rupture
