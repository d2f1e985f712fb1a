// rupture/input/law_registry.cpp: the table of traction laws (input/law_registry.hpp), its
// look-ups, and the node traction the cohesive laws share.
#include "input/law_registry.hpp"

#include <algorithm>

#include "cohesive/interface.hpp"
#include "input/case_parse.hpp"

namespace rupture {

const std::vector<LawEntry>& law_registry() {
  static const std::vector<LawEntry> table = {
      xu_needleman_entry(),
      bilinear_entry(),
      contact_entry(),
      slip_weakening_entry(),
      rate_state_entry(),
  };
  return table;
}

bool LawEntry::has_key(const std::string& key) const {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::vector<std::string> law_names() {
  std::vector<std::string> names;
  for (const LawEntry& e : law_registry()) names.push_back(e.name);
  return names;
}

const LawEntry* find_law(const std::string& name) {
  for (const LawEntry& e : law_registry())
    if (e.name == name) return &e;
  return nullptr;
}

namespace {
// The entry with alternative `index` (-1: the pre-crack's). Every alternative has one
// (tests/test_law_registry.cpp).
const LawEntry& entry_of_alternative(int index) {
  for (const LawEntry& e : law_registry())
    if (e.alternative == index) return e;
  return law_registry().front();
}
}  // namespace

const LawEntry& law_entry(const CohesiveLaw& law) {
  return entry_of_alternative(int(law.index()));
}

const LawEntry& law_entry(const InterfaceSpec& is) {
  return entry_of_alternative(is.precracked ? -1 : int(is.law.index()));
}

CohesiveTraction mean_gauss_traction(const CohesiveInterface& c, std::size_t k) {
  const std::size_t G = std::size_t(CohesiveInterface::kGauss);
  double tn = 0.0, tt = 0.0;
  int count = 0;
  if (k < c.num_segments()) tn += c.gp_tn[k * G], tt += c.gp_tt[k * G], ++count;
  if (k > 0 || c.closed) {
    const std::size_t prev = k > 0 ? k - 1 : c.num_segments() - 1;
    tn += c.gp_tn[prev * G + G - 1], tt += c.gp_tt[prev * G + G - 1], ++count;
  }
  return {tn / count, tt / count};
}

void refuse_contact_keys(Section& f, const std::string& law) {
  for (const char* k : {"contact", "friction", "contact_stiffness", "contact_tangential_stiffness"})
    if (f.has(k))
      fail(f.key(k), show(*f.node(k)),
           "not with law = \"" + law + "\": a fault is always in frictional contact (use "
           "normal_stiffness, stick_stiffness)");
}

CohesiveTraction traction_at_node_jump(const CohesiveInterface& c, std::size_t k) {
  const std::size_t G = std::size_t(CohesiveInterface::kGauss);
  if (c.node_crack_time[k] >= 0.0) return {0.0, 0.0};
  // The law at the node's jump, with the largest damage of the Gauss points around it.
  GaussHistory h;
  for (std::size_t g = 0; g < G; ++g) {
    if (k < c.num_segments()) h.damage = std::max(h.damage, c.gp_damage[k * G + g]);
    if (k > 0) h.damage = std::max(h.damage, c.gp_damage[(k - 1) * G + g]);
  }
  const double dn = c.jump_normal(k), dt = c.jump_tangential(k);
  const LawResponse r =
      std::visit([&](const auto& l) { return l.respond(dn, dt, h); }, node_law_variant(c, k));
  return {r.tn, r.tt};
}

}  // namespace rupture
