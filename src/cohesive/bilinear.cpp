// rupture/cohesive/bilinear.cpp: parameter ranges of the bilinear law.
#include "cohesive/bilinear.hpp"

#include <fmt/format.h>

#include <cmath>

namespace rupture {

namespace {
// "name = value: rule", the shape of the input layer's messages (input/case_toml.cpp).
std::string out_of_range(const char* name, double value, const char* rule) {
  return fmt::format("{} = {:g}: {}", name, value, rule);
}
bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}
}  // namespace

std::string BilinearLaw::validate() const {
  if (!positive(sigma_max))
    return out_of_range("sigma_max", sigma_max, "must be > 0 and finite (Pa)");
  if (!positive(tau_max)) return out_of_range("tau_max", tau_max, "must be > 0 and finite (Pa)");
  if (!positive(delta_nc)) return out_of_range("delta_nc", delta_nc, "must be > 0 and finite (m)");
  if (!positive(delta_tc)) return out_of_range("delta_tc", delta_tc, "must be > 0 and finite (m)");
  if (!(lambda0 > 0.0 && lambda0 < 1.0))
    return out_of_range("lambda0", lambda0,
                        "must lie in (0, 1) (elastic fraction of the critical opening)");
  if (!(std::isfinite(penalty) && penalty >= 0.0))
    return out_of_range("penalty", penalty,
                        "must be >= 0 and finite (multiple of sigma_max/(lambda0 delta_nc))");
  return "";
}

}  // namespace rupture
