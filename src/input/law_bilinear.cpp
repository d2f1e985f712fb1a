// rupture/input/law_bilinear.cpp: the bilinear law's entry in the table of laws
// (input/law_registry.hpp): its input keys and defaults (ranges: BilinearLaw::validate), and its
// words in `rupture check`. Units: Pa, m, J/m^2.
#include <fmt/format.h>

#include <variant>

#include "cohesive/interface.hpp"
#include "input/case_parse.hpp"
#include "input/law_registry.hpp"

namespace rupture {

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
  return {BilinearLaw::kName,
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
