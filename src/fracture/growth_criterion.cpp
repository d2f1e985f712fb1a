// rupture/fracture/growth_criterion.cpp
#include "fracture/growth_criterion.hpp"

#include <algorithm>
#include <cmath>

#include "fracture/j_integral.hpp"

namespace rupture {

double hoop_stress_intensity(double K_I, double K_II, double theta) {
  const double c = std::cos(0.5 * theta);
  return c * (K_I * c * c - 1.5 * K_II * std::sin(theta));
}

KinkIntensities kinked_intensities(double K_I, double K_II, double theta) {
  const double c1 = std::cos(0.5 * theta), c3 = std::cos(1.5 * theta);
  const double s1 = std::sin(0.5 * theta), s3 = std::sin(1.5 * theta);
  return {0.25 * (3.0 * c1 + c3) * K_I - 0.75 * (s1 + s3) * K_II, 0.25 * (s1 + s3) * K_I + 0.25 * (c1 + 3.0 * c3) * K_II};
}

namespace {
// The weak plane's competition (header): along the plane or out of it at theta_c, whichever
// has the larger G / G_c. A tip pressed shut (K_I < 0: its faces carry contact, and what the
// domains read as K_I is the faces' pressure, not a singular field) is read as K_I = 0 both ways,
// the closed flaw of the wing-crack analyses (Horii & Nemat-Nasser 1986): it runs along the
// plane in mode II or kinks at theta_c(0, K_II) = -/+70.5 degrees.
GrowthDecision decide_on_plane(const GrowthLaw& law, double K_I, double K_II, double e_prime, double hoop) {
  GrowthDecision d;
  const double KIp = std::max(K_I, 0.0);
  const double along = (KIp * KIp + K_II * K_II) / e_prime;
  const KinkIntensities k = kinked_intensities(KIp, K_II, hoop);
  const double out = k.k_I > 0.0 ? (k.k_I * k.k_I + k.k_II * k.k_II) / e_prime : 0.0;
  const bool kink = out / law.fracture_energy > along / law.plane_fracture_energy;
  d.angle = kink ? hoop : 0.0;
  d.driving = kink ? out : along;
  d.critical = kink ? law.fracture_energy : law.plane_fracture_energy;
  d.grow = d.driving >= d.critical;
  return d;
}
}  // namespace

GrowthDecision decide_growth(const GrowthLaw& law, double K_I, double K_II, double e_prime,
                             CrackFront front, bool on_plane, double kink, const RunningTipFactors& running) {
  GrowthDecision d;
  if (!law.on() || law.criterion == GrowthCriterion::prescribed) return d;  // K does not move it: decide_prescribed
  if (law.criterion == GrowthCriterion::energy && law.plane_fracture_energy > 0.0) {
    // A crack with a weak plane is a closed flaw's (decide_on_plane): K_I+ = max(K_I, 0) on the
    // plane and off it; off it, the kink's own intensities (header).
    const double KIp = std::max(K_I, 0.0);
    if (on_plane) return decide_on_plane(law, K_I, K_II, e_prime, hoop_stress_angle(KIp, K_II));
    const KinkIntensities k = kinked_intensities(KIp, K_II, kink);
    const double turn = hoop_stress_angle(k.k_I, k.k_II), next = hoop_stress_intensity(k.k_I, k.k_II, turn);
    d.angle = kink + turn;
    d.driving = next > 0.0 ? next * next / e_prime : 0.0;
    d.critical = law.fracture_energy;
    d.grow = d.driving >= d.critical;
    return d;
  }
  // A tip whose faces press together (K_I < 0) is read as the closed flaw of the wing-crack
  // analyses (Horii & Nemat-Nasser 1986), K_I+ = max(K_I, 0), as on a weak plane: the faces
  // carry contact, so no singular field can close the tip, and what the domains read as a
  // negative K_I is the faces' pressure. Its shear still drives it: in pure mode II it grows
  // at theta_c = -/+70.53 degrees once K_II^2 / E' (energy) or 2/sqrt3 |K_II| (max_hoop)
  // reaches the toughness. (Refusing such a tip made the start wait for the sign of K_I,
  // a few per cent of K_II: docs/validation.md, Kalthoff-Winkler.)
  const double KIp = std::max(K_I, 0.0);
  const double hoop = hoop_stress_angle(KIp, K_II);
  d.angle = law.direction == GrowthDirection::max_hoop ? hoop : 0.0;
  if (law.criterion == GrowthCriterion::cohesive) {
    d.critical = 1.0;
    d.driving = front == CrackFront::softening || (front == CrackFront::open && K_I > 0.0) ? 1.0 : 0.0;
    d.grow = d.driving >= d.critical;
    return d;
  }
  if (law.criterion == GrowthCriterion::max_hoop) {
    d.driving = hoop_stress_intensity(KIp, K_II, hoop);
    d.critical = law.toughness;
  } else {
    d.driving = (running.A_I * KIp * KIp + running.A_II * K_II * K_II) / e_prime;
    d.critical = law.fracture_energy;
  }
  d.grow = d.driving > 0.0 && d.driving >= d.critical;
  return d;
}

GrowthDecision decide_prescribed(const GrowthLaw& law, double K_I, double K_II, double grown, double step,
                                 double time) {
  GrowthDecision d;
  if (law.criterion != GrowthCriterion::prescribed) return d;
  d.angle = law.direction == GrowthDirection::max_hoop ? hoop_stress_angle(std::max(K_I, 0.0), K_II) : 0.0;
  d.driving = time > law.start ? law.speed * (time - law.start) : 0.0;
  d.critical = grown + step;
  d.grow = d.driving >= d.critical * (1.0 - 1e-12);
  return d;
}

}  // namespace rupture
