// rupture/cohesive/contact.cpp: parameter ranges of the contact law.
#include "cohesive/contact.hpp"

#include <fmt/format.h>

#include <cmath>

namespace rupture {

std::string ContactLaw::validate() const {
  if (!(std::isfinite(stiffness) && stiffness > 0.0))
    return fmt::format("stiffness = {:g}: must be > 0 and finite (Pa/m)", stiffness);
  if (!(std::isfinite(friction) && friction >= 0.0))
    return fmt::format("friction = {:g}: must be >= 0 and finite (Coulomb coefficient)", friction);
  if (!(std::isfinite(tangential_stiffness) && tangential_stiffness >= 0.0))
    return fmt::format("tangential_stiffness = {:g}: must be >= 0 and finite (Pa/m; 0 = stiffness)",
                       tangential_stiffness);
  return "";
}

}  // namespace rupture
