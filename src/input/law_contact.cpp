// rupture/input/law_contact.cpp: the entry of law = "contact" in the table of laws
// (input/law_registry.hpp): a pre-crack, no cohesion, whose faces only touch (the contact law of
// cohesive/contact.hpp alone on every point; its stiffness, Pa/m, by default one cell of the
// stiffer adjoining body: input/case_parse.hpp cell_penalty_stiffness).
#include "cohesive/interface.hpp"
#include "input/case_parse.hpp"
#include "input/law_registry.hpp"

namespace rupture {

namespace {

// Every point starts separated; contact is on, its stiffness M / h unless given.
void parse(Section& f, InterfaceSpec& is, const Case& c) {
  is.precracked = true;
  parse_separated_contact(f, is, cell_penalty_stiffness(c, is), true);
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
