// rupture/cohesive/rate_state.cpp: parameter ranges and the initial state of rate-and-state
// friction.
#include "cohesive/rate_state.hpp"

#include <fmt/format.h>

#include <cmath>

namespace rupture {

namespace {
// "name = value: rule", the shape of the input layer's messages (input/case_toml.cpp).
std::string out_of_range(const char* name, double value, const std::string& rule) {
  return fmt::format("{} = {:g}: {}", name, value, rule);
}
bool positive(double v) { return std::isfinite(v) && v > 0.0; }
}  // namespace

const char* evolution_name(StateEvolution e) {
  switch (e) {
    case StateEvolution::aging:
      return "aging";
    case StateEvolution::slip:
      return "slip";
    case StateEvolution::flash_heating:
      return "flash_heating";
  }
  return "?";
}

std::string RateStateFriction::validate() const {
  if (!positive(a)) return out_of_range("a", a, "must be > 0 and finite (the direct effect)");
  if (!positive(b)) return out_of_range("b", b, "must be > 0 and finite (the evolution effect)");
  if (!positive(dc)) return out_of_range("dc", dc, "must be > 0 and finite (m, the state evolution slip)");
  if (!positive(v0)) return out_of_range("reference_slip_rate", v0, "must be > 0 and finite (m/s, V0)");
  if (!(std::isfinite(f0) && f0 >= 0.0))
    return out_of_range("reference_friction", f0, "must be >= 0 and finite (f0)");
  if (!positive(v_init))
    return out_of_range("initial_slip_rate", v_init, "must be > 0 and finite (m/s)");
  if (evolution == StateEvolution::flash_heating) {
    if (!(std::isfinite(fw) && fw >= 0.0))
      return out_of_range("weakened_friction", fw, "must be >= 0 and finite with evolution = \"flash_heating\"");
    if (!positive(vw))
      return out_of_range("weakening_slip_rate", vw, "must be > 0 and finite (m/s) with evolution = \"flash_heating\"");
  }
  if (!positive(normal_stiffness))
    return out_of_range("normal_stiffness", normal_stiffness, "must be > 0 and finite (Pa/m)");
  if (!positive(stick_stiffness))
    return out_of_range("stick_stiffness", stick_stiffness, "must be > 0 and finite (Pa/m)");
  if (!std::isfinite(tn0)) return out_of_range("initial_traction", tn0, "must be finite (Pa)");
  if (!std::isfinite(tt0)) return out_of_range("initial_traction", tt0, "must be finite (Pa)");
  if (!(tn0 < 0.0))
    return out_of_range("initial_traction", tn0,
                        "the normal traction must be < 0 (compression): no state balances a shear "
                        "traction on a fault without normal stress");
  if (!(tt0 != 0.0))
    return out_of_range("initial_traction", tt0,
                        "the shear traction must not be 0: a fault slipping at initial_slip_rate > 0 "
                        "carries the friction of that rate, and no state gives a friction of 0");
  if (!std::isfinite(psi_init))
    return out_of_range("initial_traction", tt0,
                        fmt::format("no finite state balances it at initial_slip_rate = {:g} m/s "
                                    "(|shear| / (compression x a) = {:g} overflows)",
                                    v_init, std::fabs(tt0) / (-tn0 * a)));
  if (!(std::isfinite(nucleation_stress))) return out_of_range("nucleation_stress", nucleation_stress, "must be finite (Pa)");
  if (!(std::isfinite(nucleation_radius) && nucleation_radius >= 0.0))
    return out_of_range("nucleation_radius", nucleation_radius, "must be >= 0 and finite (m; 0: uniform)");
  if (!(std::isfinite(nucleation_time) && nucleation_time >= 0.0))
    return out_of_range("nucleation_time", nucleation_time, "must be >= 0 and finite (s; 0: a step)");
  if (taper.on) {
    if (!(std::isfinite(taper.half_width) && taper.half_width >= 0.0))
      return out_of_range("taper.half_width", taper.half_width, "must be >= 0 and finite (m)");
    if (!positive(taper.width)) return out_of_range("taper.width", taper.width, "must be > 0 and finite (m)");
    const double values[4] = {taper.a, taper.b, taper.dc, taper.vw};
    const char* names[4] = {"taper.a", "taper.b", "taper.dc", "taper.weakening_slip_rate"};
    bool any = false;
    for (int k = 0; k < 4; ++k) {
      if (!(std::isfinite(values[k]) && values[k] >= 0.0))
        return out_of_range(names[k], values[k], "must be > 0 and finite (0 or absent: not tapered)");
      any = any || values[k] > 0.0;
    }
    if (!any) return out_of_range("taper.width", taper.width, "a taper needs one of a, b, dc, weakening_slip_rate");
    if (taper.vw > 0.0 && evolution != StateEvolution::flash_heating)
      return out_of_range("taper.weakening_slip_rate", taper.vw, "only with evolution = \"flash_heating\"");
    // The state balancing the initial traction must exist beyond the taper too.
    RateStateFriction beyond = at(taper.x + taper.half_width + taper.width, taper.y);
    if (!std::isfinite(beyond.psi_init))
      return out_of_range("taper.a", taper.a, "no finite state balances the initial traction with it");
  }
  return "";
}

bool RateStateFriction::initialize_state() {
  const double sigma = -tn0, tau = std::fabs(tt0);
  if (!(sigma > 0.0 && tau > 0.0 && a > 0.0 && v_init > 0.0 && v0 > 0.0)) {
    psi_init = 0.0;
    return false;
  }
  // psi = a ln[(2 V0 / V) sinh(y)], y = tau / (sigma a); ln sinh(y) = y + ln(1 - e^-2y) - ln 2.
  const double y = tau / (sigma * a);
  const double log_sinh = y > 20.0 ? y - std::log(2.0) : std::log(std::sinh(y));
  psi_init = a * (std::log(2.0 * v0 / v_init) + log_sinh);
  return std::isfinite(psi_init);
}

}  // namespace rupture
