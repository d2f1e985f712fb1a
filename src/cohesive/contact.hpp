// rupture/cohesive/contact.hpp
// Frictional contact between faces with no cohesion left (separated Gauss points, pre-cracks):
// a normal penalty against interpenetration and Coulomb friction, regularised by a tangential
// stick spring and integrated by return mapping (the slip is the history). Open faces carry no
// traction. Units: Pa, m, Pa/m, J/m^2. Formulas: docs/cohesive_laws.md.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>

#include "cohesive/law_types.hpp"

namespace rupture {

struct ContactLaw {
  double stiffness = 0.0;             // Pa/m, normal penalty kn: Tn = kn Dn for Dn < 0
  double friction = 0.0;              // Coulomb coefficient mu (0 = frictionless)
  double tangential_stiffness = 0.0;  // Pa/m, stick penalty kt; 0 = the same as stiffness

  // "" when the parameters lie in their ranges, else a message naming the first that does not.
  std::string validate() const;

  double stick_stiffness() const {
    return tangential_stiffness > 0.0 ? tangential_stiffness : stiffness;
  }

  // Stability stiffness (docs/time_step.md): the closed side's largest tangent eigenvalue,
  // kn, or max(kn, kt) when friction can stick. The tangent is diag(kn, kt) when stuck and
  // [[kn, 0], [-+mu kn, 0]] when slipping (eigenvalues kn, 0). Taken for open faces too, as
  // XuNeedleman does: a step can close them.
  double stability_stiffness() const {
    return friction > 0.0 ? std::max(stiffness, stick_stiffness()) : stiffness;
  }

  // Open (Dn >= 0): no traction, and the slip follows Dt so the stick spring is unloaded.
  // Closed: Tn = kn Dn (< 0, independent of Dt); trial Tt = kt (Dt - slip); where
  // |trial| > mu |Tn| the point slides: Tt = mu |Tn| sign(trial), slip = Dt - Tt / kt.
  LawResponse respond(double dn, double dt, GaussHistory& h) const {
    LawResponse r{0.0, 0.0, stability_stiffness()};
    if (dn >= 0.0) {
      h.slip = dt;
      return r;
    }
    const double kt = stick_stiffness();
    r.tn = stiffness * dn;
    const double trial = kt * (dt - h.slip), limit = friction * -r.tn;
    if (std::fabs(trial) > limit) {
      r.tt = std::copysign(limit, trial);
      h.slip = dt - r.tt / kt;
    } else {
      r.tt = trial;
    }
    return r;
  }

  // Energy held by the two penalty springs at (dn, dt) after respond(): 0.5 kn Dn^2 +
  // 0.5 kt (Dt - slip)^2 when closed, 0 when open.
  double stored_energy(double dn, double dt, const GaussHistory& h) const {
    if (dn >= 0.0) return 0.0;
    const double stick = dt - h.slip;
    return 0.5 * stiffness * dn * dn + 0.5 * stick_stiffness() * stick * stick;
  }

  // Frictional work over one step, J/m^2: 0.5 (Tt_before + Tt_after) (slip_after -
  // slip_before), the slip-trapezoid. Since Tt = kt (Dt - slip) at every state, it is exactly
  // the interface's trapezoidal tangential work 0.5 (Tt_b + Tt_a)(Dt_a - Dt_b) minus the change
  // of 0.5 Tt^2 / kt, for any step. It is >= 0 unless a single step reverses a sliding point
  // (|dDt| > 2 mu |Tn| / kt); it counts the stick spring's energy as lost when the faces open.
  static double dissipated_increment(double tt_before, double slip_before, double tt_after,
                                     double slip_after) {
    return 0.5 * (tt_before + tt_after) * (slip_after - slip_before);
  }
};

}  // namespace rupture
