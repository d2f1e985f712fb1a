// rupture/fracture/growth_criterion.hpp
// When a crack tip grows and in which direction, from its stress intensity factors
// (docs/fracture.md, "Growth"). Plain data chosen per crack in the input; free functions.
//  - criterion max_hoop (Erdogan & Sih 1963): the tip grows when the hoop stress intensity in
//    the maximum hoop stress direction theta_c, K_eq = cos(theta_c/2) [K_I cos^2(theta_c/2)
//    - 3/2 K_II sin(theta_c)], reaches the toughness K_Ic;
//  - criterion energy (Irwin): when G = (K_I^2 + K_II^2) / E' reaches G_c (G from K, not from
//    J: docs/fracture.md's open finding on J of inclined cracks);
//  - direction max_hoop: theta_c (hoop_stress_angle); straight: along the crack.
// A closed tip (K_I < 0) does not grow. Units: Pa m^1/2, J/m^2, radians.
#pragma once

namespace rupture {

enum class GrowthCriterion { none, max_hoop, energy };
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

struct GrowthDecision {
  bool grow = false;
  double angle = 0.0;    // direction of the new segment from the crack's, radians (ccw)
  double driving = 0.0;  // K_eq (Pa m^1/2) or G (J/m^2): what was compared
  double critical = 0.0; // its critical value
};

// e_prime: E (plane stress) or E / (1 - nu^2) (plane strain), Pa.
GrowthDecision decide_growth(const GrowthLaw& law, double K_I, double K_II, double e_prime);

}  // namespace rupture
