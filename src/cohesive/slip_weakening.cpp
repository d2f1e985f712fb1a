// rupture/cohesive/slip_weakening.cpp: parameter ranges of slip-weakening friction.
#include "cohesive/slip_weakening.hpp"

#include <fmt/format.h>

#include <cmath>

namespace rupture {

namespace {
// "name = value: rule", the shape of the input layer's messages (input/case_toml.cpp).
std::string out_of_range(const char* name, double value, const std::string& rule) {
  return fmt::format("{} = {:g}: {}", name, value, rule);
}
}  // namespace

std::string SlipWeakening::validate() const {
  if (!(std::isfinite(static_friction) && static_friction >= 0.0))
    return out_of_range("static_friction", static_friction, "must be >= 0 and finite");
  if (!(std::isfinite(dynamic_friction) && dynamic_friction >= 0.0 &&
        dynamic_friction <= static_friction))
    return out_of_range("dynamic_friction", dynamic_friction,
                        fmt::format("must lie in [0, static_friction = {:g}]", static_friction));
  if (!(std::isfinite(dc) && dc > 0.0))
    return out_of_range("dc", dc, "must be > 0 and finite (m, the slip-weakening distance)");
  if (!(std::isfinite(cohesion) && cohesion >= 0.0))
    return out_of_range("cohesion", cohesion, "must be >= 0 and finite (Pa)");
  if (!(std::isfinite(normal_stiffness) && normal_stiffness > 0.0))
    return out_of_range("normal_stiffness", normal_stiffness, "must be > 0 and finite (Pa/m)");
  if (!(std::isfinite(stick_stiffness) && stick_stiffness > 0.0))
    return out_of_range("stick_stiffness", stick_stiffness, "must be > 0 and finite (Pa/m)");
  if (!std::isfinite(tn0)) return out_of_range("initial_traction", tn0, "must be finite (Pa)");
  if (!std::isfinite(tt0)) return out_of_range("initial_traction", tt0, "must be finite (Pa)");
  return "";
}

}  // namespace rupture
