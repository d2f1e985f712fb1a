// rupture/cohesive/normal_relaxation.cpp: the normal-stress regularization's description and the
// ranges of its parameters.
#include "cohesive/normal_relaxation.hpp"

#include <fmt/format.h>

namespace rupture {

std::string NormalRelaxation::describe() const {
  if (form == RelaxationForm::time)
    return fmt::format(", normal stress seen relaxed over T = {:g} s (Prakash-Clifton, time form)", time);
  if (form == RelaxationForm::slip)
    return fmt::format(", normal stress seen relaxed over L = {:g} m with V* = {:g} m/s "
                       "(Prakash-Clifton, slip form)",
                       slip, rate);
  return "";
}

std::string NormalRelaxation::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (form == RelaxationForm::time && !positive(time))
    return fmt::format("normal_relaxation_time = {:g}: must be > 0 and finite (s, the time T over "
                       "which the normal stress friction sees relaxes)",
                       time);
  if (form == RelaxationForm::slip) {
    if (!positive(slip))
      return fmt::format("normal_relaxation_slip = {:g}: must be > 0 and finite (m, the slip L over "
                         "which the normal stress friction sees relaxes)",
                         slip);
    if (!(std::isfinite(rate) && rate >= 0.0))
      return fmt::format("normal_relaxation_rate = {:g}: must be >= 0 and finite (m/s, V* in "
                         "(|V| + V*) / L)",
                         rate);
  }
  return "";
}

}  // namespace rupture
