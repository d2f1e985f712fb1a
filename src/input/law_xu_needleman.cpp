// rupture/input/law_xu_needleman.cpp: the Xu-Needleman law's entry in the table of laws
// (input/law_registry.hpp): its input keys, their defaults and ranges (theory E7-E8, the separation
// criterion of theory §3), and its words in `rupture check`. Units: Pa, m, J/m^2.
#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "cohesive/interface.hpp"
#include "input/case_parse.hpp"
#include "input/law_registry.hpp"

namespace rupture {

namespace {

XuNeedleman parse_xu_needleman(Section& f, InterfaceSpec& is) {
  XuNeedleman law;
  law.sigma_max = f.number("sigma_max");
  if (law.sigma_max <= 0) fail(f.key("sigma_max"), law.sigma_max, "must be > 0 (Pa)");
  law.tau_max = f.number("tau_max", law.sigma_max);
  if (law.tau_max <= 0) fail(f.key("tau_max"), law.tau_max, "must be > 0 (Pa)");
  law.delta_n = f.number("delta_n");
  if (law.delta_n <= 0) fail(f.key("delta_n"), law.delta_n, "must be > 0 (m)");
  law.q = f.number("q", 1.0);
  if (law.q <= 0) fail(f.key("q"), law.q, "must be > 0");
  law.r = f.number("r", 0.0);
  if (law.r < 0 || std::fabs(law.r - 1.0) < 1e-12)
    fail(f.key("r"), law.r, "must be >= 0 and differ from 1");
  if (f.has("delta_t")) {
    law.delta_t = f.number("delta_t");
    if (law.delta_t <= 0) fail(f.key("delta_t"), law.delta_t, "must be > 0 (m)");
  } else {
    // q = phi_t/phi_n with phi_t = sqrt(e/2) tau_max delta_t, phi_n = e sigma_max delta_n.
    law.delta_t = law.q * std::exp(1.0) * law.sigma_max * law.delta_n /
                  (std::sqrt(std::exp(1.0) / 2.0) * law.tau_max);
  }
  law.penalty = f.number("penalty", 1.0);
  if (law.penalty < 0)
    fail(f.key("penalty"), law.penalty, "must be >= 0 (multiple of phi_n/delta_n^2)");
  is.separation_factor = f.number("separation", 5.0);
  if (!(is.separation_factor > 0 && is.separation_factor <= 1000))
    fail(f.key("separation"), is.separation_factor, "must lie in (0, 1000] (multiples of delta_t)");
  return law;
}

// The law, then the contact of separated points (its stiffness defaults to the law's penalty).
void parse(Section& f, InterfaceSpec& is, const Case& /*c*/) {
  const XuNeedleman xn = parse_xu_needleman(f, is);
  is.law = xn;
  parse_separated_contact(f, is, xn.penalty_stiffness(), false);
}

std::string describe(const InterfaceSpec& is) {
  const XuNeedleman& xn = std::get<XuNeedleman>(is.law);
  return fmt::format("delta_t = {:.4g} um, phi_n = {:.4g} J/m^2, phi_t = {:.4g} J/m^2",
                     1e6 * xn.delta_t, xn.phi_n(), xn.phi_t());
}

}  // namespace

LawEntry xu_needleman_entry() {
  return {XuNeedleman::kName,
          "the Xu-Needleman exponential traction-separation law with an interpenetration "
          "penalty (docs/theory.md E7-E8), separated at |jump| = separation x delta_t",
          "",
          law_alternative<XuNeedleman>(),
          false,
          {"sigma_max", "tau_max", "delta_n", "delta_t", "q", "r", "penalty", "separation"},
          parse,
          describe,
          traction_at_node_jump};
}

}  // namespace rupture
