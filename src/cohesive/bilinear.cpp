// rupture/cohesive/bilinear.cpp: parameter ranges of the bilinear law, and its entry in the
// law registry (cohesive/law_registry.hpp): its input keys and defaults, its words in
// `rupture check`. Units: Pa, m, J/m^2.
#include "cohesive/bilinear.hpp"

#include <fmt/format.h>

#include <cmath>

#include "cohesive/interface.hpp"
#include "cohesive/law_registry.hpp"
#include "io/case_parse.hpp"

namespace rupture {

namespace {
// "name = value: rule", the shape of the input layer's messages (io/case_toml.cpp).
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

namespace {

BilinearLaw parse_bilinear(Section& f) {
  BilinearLaw law;
  law.sigma_max = f.number("sigma_max");
  law.tau_max = f.number("tau_max", law.sigma_max);
  law.delta_nc = f.number("delta_nc");
  law.delta_tc = f.number("delta_tc", law.delta_nc);
  law.lambda0 = f.number("lambda0", 0.01);
  law.penalty = f.number("penalty", 1.0);
  fail_on_invalid(f, law.validate(), {});
  return law;
}

// The law, then the contact of separated points (its stiffness defaults to the law's penalty).
void parse(Section& f, InterfaceSpec& is, const Case& /*c*/) {
  const BilinearLaw b = parse_bilinear(f);
  is.law = b;
  parse_separated_contact(f, is, b.penalty_stiffness(), false);
}

std::string describe(const InterfaceSpec& is) {
  const BilinearLaw& b = std::get<BilinearLaw>(is.law);
  return fmt::format("G_Ic = {:.4g} J/m^2, G_IIc = {:.4g} J/m^2", b.fracture_energy_normal(),
                     b.fracture_energy_tangential());
}

}  // namespace

LawEntry bilinear_entry() {
  return {"bilinear",
          "a bilinear (linear-softening) mixed-mode law with irreversible damage (Geubelle & "
          "Baylor 1998)",
          "",
          law_alternative<BilinearLaw>(),
          false,
          {"sigma_max", "tau_max", "penalty", "delta_nc", "delta_tc", "lambda0"},
          parse,
          describe,
          traction_at_node_jump};
}

}  // namespace rupture
