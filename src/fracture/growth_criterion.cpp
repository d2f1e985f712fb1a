// rupture/fracture/growth_criterion.cpp
#include "fracture/growth_criterion.hpp"

#include <cmath>

#include "fracture/j_integral.hpp"

namespace rupture {

double hoop_stress_intensity(double K_I, double K_II, double theta) {
  const double c = std::cos(0.5 * theta);
  return c * (K_I * c * c - 1.5 * K_II * std::sin(theta));
}

GrowthDecision decide_growth(const GrowthLaw& law, double K_I, double K_II, double e_prime,
                             CrackFront front) {
  GrowthDecision d;
  if (!law.on()) return d;
  const double hoop = hoop_stress_angle(K_I, K_II);
  d.angle = law.direction == GrowthDirection::max_hoop ? hoop : 0.0;
  if (law.criterion == GrowthCriterion::cohesive) {
    d.critical = 1.0;
    d.driving = front == CrackFront::softening || (front == CrackFront::open && K_I > 0.0) ? 1.0 : 0.0;
    d.grow = d.driving >= d.critical;
    return d;
  }
  if (law.criterion == GrowthCriterion::max_hoop) {
    d.driving = hoop_stress_intensity(K_I, K_II, hoop);
    d.critical = law.toughness;
  } else {
    d.driving = (K_I * K_I + K_II * K_II) / e_prime;
    d.critical = law.fracture_energy;
  }
  // A tip whose faces press together (K_I < 0) stays: the Williams field of a closed crack
  // does not describe it (its faces carry contact instead).
  d.grow = K_I > 0.0 && d.driving >= d.critical;
  return d;
}

}  // namespace rupture
