// rupture/input/law_registry.hpp
// The traction laws an [interface] table may name, in one table. Each entry holds the law's
// input name, a one-line description, its own input keys (those input/input_schema.cpp documents
// with when = "law = ... <name> ..."), and the hooks the generic code calls instead of asking
// which law it has: the parser of its keys, its words in `rupture check`, and the traction a
// node reports (interface profiles, stations). Each law's entry is defined in its own file,
// input/law_<name>.cpp; the table lists them in the order of the input's `law = ...` values, the
// first being the default. Nothing here is on the hot path: the interface loop dispatches on
// CohesiveLaw once per interface (std::visit) and asks the law's own members
// (cohesive/law.hpp). It lives in input/ because it reads TOML; cohesive/ knows nothing of it.
// Units: SI (Pa, m).
//
// To add a law: input/law_<name>.cpp defines <name>_entry() (declared below), one line in
// law_registry() lists it (input/law_registry.cpp), its keys go in input/input_schema.cpp, and
// tests/test_law_registry.cpp checks the entry against the schema and the parser.
#pragma once
#include <cstddef>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "cohesive/law.hpp"

namespace rupture {

class Section;
struct Case;
struct InterfaceSpec;
struct CohesiveInterface;

// The index of law type L among CohesiveLaw's alternatives (-1: not one of them).
template <class L, std::size_t I = 0>
constexpr int law_alternative() {
  if constexpr (I == std::variant_size_v<CohesiveLaw>)
    return -1;
  else if constexpr (std::is_same_v<std::variant_alternative_t<I, CohesiveLaw>, L>)
    return int(I);
  else
    return law_alternative<L, I + 1>();
}

struct LawEntry {
  std::string name;         // law = "<name>" in the input (a cohesive law's kName)
  std::string description;  // one line: what the law is
  // Its words in the description of interface.*.law ("" none), each after a "; ".
  std::string schema_note;
  // Its alternative in CohesiveLaw (law_alternative<L>()), or -1 for a law that has none: no
  // cohesion at all, a pre-crack (InterfaceSpec::precracked; is.law keeps its unused default).
  int alternative = -1;
  // A frictional fault rather than a cohesive law (always in contact; its keys are refused
  // with another law before the keys all laws have are read, input/parse_interfaces.cpp).
  bool fault = false;
  // Its own keys of [interface.*] (those it shares with another law included), in the order
  // they are refused with another law, which is an input error.
  std::vector<std::string> keys;
  // Reads the law's keys of [interface.NAME] table f into is (the other laws' keys are already
  // refused, rupture_slip_rate read): is.law and whatever else of the spec the law decides
  // (separation_factor, precracked, contact and contact_law, stretches). A bad value is an
  // InputError naming its key. c: the case parsed so far (materials, bodies, grid).
  void (*parse)(Section& f, InterfaceSpec& is, const Case& c) = nullptr;
  // `rupture check`'s words for the interface's law, after its name: its parameters and
  // energies (J/m^2), or what it is.
  std::string (*describe)(const InterfaceSpec& is) = nullptr;
  // The traction at node k, Pa, normal and tangential in the node's frame, as the interface
  // profiles and the stations report it (output/interface_csv.hpp node_traction).
  CohesiveTraction (*node_traction)(const CohesiveInterface& c, std::size_t k) = nullptr;

  bool has_key(const std::string& key) const;
};

// Every law, in the order of the input's `law = ...` values (the first is the default).
const std::vector<LawEntry>& law_registry();
// Their names, in that order.
std::vector<std::string> law_names();
// The entry named `name`, or nullptr.
const LawEntry* find_law(const std::string& name);
// The entry of the law alternative `law` holds.
const LawEntry& law_entry(const CohesiveLaw& law);
// The entry of an interface's law: a pre-crack's (precracked: the one without an
// alternative), else that of is.law.
const LawEntry& law_entry(const InterfaceSpec& is);

// The node traction of a cohesive law (a LawEntry::node_traction): the law at the node's jump,
// with the largest damage of the Gauss points around it; 0 once the node has cracked.
CohesiveTraction traction_at_node_jump(const CohesiveInterface& c, std::size_t k);

// The fault laws' shared parts (input/law_registry.cpp). The mean traction change dT of the
// Gauss points next to node k (the first of the segment starting there, the last of the one
// ending there), Pa: a fault adds its prestress to report the total.
CohesiveTraction mean_gauss_traction(const CohesiveInterface& c, std::size_t k);
// A fault is always in frictional contact: the contact keys of separated points are an input
// error with law = "<law>".
void refuse_contact_keys(Section& f, const std::string& law);

// Each law's entry, defined in its own file.
LawEntry xu_needleman_entry();    // input/law_xu_needleman.cpp
LawEntry bilinear_entry();        // input/law_bilinear.cpp
LawEntry contact_entry();         // input/law_contact.cpp
LawEntry slip_weakening_entry();  // input/law_slip_weakening.cpp
LawEntry rate_state_entry();      // input/law_rate_state.cpp

}  // namespace rupture
