// rupture/fracture/growth_criterion.hpp
// When a crack tip grows and in which direction, from its stress intensity factors
// (docs/fracture.md, "Growth"). Plain data chosen per crack in the input; free functions.
//  - criterion max_hoop (Erdogan & Sih 1963): the tip grows when the hoop stress intensity in
//    the maximum hoop stress direction theta_c, K_eq = cos(theta_c/2) [K_I cos^2(theta_c/2)
//    - 3/2 K_II sin(theta_c)], reaches the toughness K_Ic;
//  - criterion energy (Irwin): when G = (K_I^2 + K_II^2) / E' reaches G_c (G from K, not from
//    J: docs/fracture.md's open finding on J of inclined cracks);
//  - criterion cohesive (a crack whose new segments carry a cohesive law; a strength
//    criterion read through the law): a tip whose end segment carries cohesion grows once
//    that segment is past the law's peak traction (CrackFront::softening: the traction ahead
//    has reached the strength and the process zone has reached the end of the line, which
//    extends so the zone can go on); a tip whose end segment carries none (a cut, or a segment
//    that has let go) grows as soon as it is pulled open (K_I > 0: a sharp tip's stress
//    exceeds any strength, so the first segment, which then carries at most sigma_max, comes at
//    once, as Camacho & Ortiz 1996 insert an extrinsic law where the strength is reached);
//  - direction max_hoop: theta_c (hoop_stress_angle); straight: along the crack.
// A closed tip (K_I < 0) does not grow by K_Ic, G_c or from a cut. Units: Pa m^1/2, J/m^2, radians.
#pragma once

namespace rupture {

enum class GrowthCriterion { none, max_hoop, energy, cohesive };
enum class GrowthDirection { max_hoop, straight };

struct GrowthLaw {
  GrowthCriterion criterion = GrowthCriterion::none;
  GrowthDirection direction = GrowthDirection::max_hoop;
  double toughness = 0.0;        // K_Ic, Pa m^1/2 (max_hoop)
  double fracture_energy = 0.0;  // G_c, J/m^2 (energy)
  double step = 0.5;             // length of one growth step, in cells (0, 0.5]
  bool on() const { return criterion != GrowthCriterion::none; }
};

// The hoop stress intensity sigma_thetatheta sqrt(2 pi r) of the Williams field at angle theta
// from the crack line, Pa m^1/2.
double hoop_stress_intensity(double K_I, double K_II, double theta);

// What the cohesive criterion reads at the end of the line (solver/crack_growth.cpp).
enum class CrackFront {
  open,       // the end segment carries no cohesion (a cut, or let go): a sharp tip
  loading,    // a cohesive end segment before the law's peak traction
  softening,  // a cohesive end segment past the peak: the process zone has reached it
};

struct GrowthDecision {
  bool grow = false;
  double angle = 0.0;    // direction of the new segment from the crack's, radians (ccw)
  double driving = 0.0;  // K_eq (Pa m^1/2), G (J/m^2) or, cohesive, 1 past the peak / 0
  double critical = 0.0; // its critical value (cohesive: 1)
};

// e_prime: E (plane stress) or E / (1 - nu^2) (plane strain), Pa. front: the end segment's
// state (read by the cohesive criterion only).
GrowthDecision decide_growth(const GrowthLaw& law, double K_I, double K_II, double e_prime,
                             CrackFront front = CrackFront::open);

}  // namespace rupture
