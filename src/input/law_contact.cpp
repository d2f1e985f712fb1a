// rupture/input/law_contact.cpp: the entry of law = "contact" in the table of laws
// (input/law_registry.hpp): a pre-crack, no cohesion, whose faces only touch (the contact law of
// cohesive/contact.hpp alone on every point; its stiffness, Pa/m, must be given).
#include "cohesive/interface.hpp"
#include "input/case_parse.hpp"
#include "input/law_registry.hpp"

namespace rupture {

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
