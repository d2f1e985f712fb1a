// rupture/cohesive/contact.cpp: parameter ranges of the contact law, and the entry of
// law = "contact" in the law registry (cohesive/law_registry.hpp): a pre-crack, no cohesion,
// whose faces only touch (the contact law alone on every point). Units: Pa/m.
#include "cohesive/contact.hpp"

#include <fmt/format.h>

#include <cmath>

#include "cohesive/interface.hpp"
#include "cohesive/law_registry.hpp"
#include "io/case_parse.hpp"

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

namespace {

// Every point starts separated; contact is on and its stiffness must be given.
void parse(Section& f, InterfaceSpec& is, const Case& /*c*/) {
  is.precracked = true;
  parse_separated_contact(f, is, 0.0, true);
}

std::string describe(const InterfaceSpec& /*is*/) { return "no cohesion (pre-crack)"; }

}  // namespace

LawEntry contact_entry() {
  return {"contact",
          "no cohesion: a pre-crack whose faces only press and rub on each other (penalty "
          "contact with Coulomb friction)",
          "\"contact\" has no cohesion: a pre-crack whose faces only touch",
          -1,
          false,
          {},
          parse,
          describe,
          traction_at_node_jump};
}

}  // namespace rupture
