// rupture/input/law_slip_weakening.cpp: slip-weakening friction's entry in the table of laws
// (input/law_registry.hpp): its input keys (read by input/parse_fault.cpp), its words in
// `rupture check` (strengths and the seismic ratio S), and the total traction T0 + dT its
// nodes report. Units: Pa, m, Pa/m.
#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "cohesive/interface.hpp"
#include "input/case_parse.hpp"
#include "input/law_registry.hpp"

namespace rupture {

namespace {

// A fault is always in frictional contact: the contact keys of separated points are refused;
// the friction, the initial traction and the stretches come from input/parse_fault.cpp.
void parse(Section& f, InterfaceSpec& is, const Case& c) {
  refuse_contact_keys(f, SlipWeakening::kName);
  parse_fault_law(f, c, is);
}

// The fault's background: strengths at the initial normal traction and the seismic ratio
// S = (tau_s - tau0)/(tau0 - tau_d) (Andrews 1976: supershear possible below ~1.77 in 2D
// in-plane).
std::string describe(const InterfaceSpec& is) {
  const SlipWeakening& f = std::get<SlipWeakening>(is.law);
  const double ts = f.static_strength(), td = f.dynamic_strength(), t0 = std::fabs(f.tt0);
  return fmt::format(
      "mu_s = {:g}, mu_d = {:g}, Dc = {:g} m, initial traction [{:g}, {:g}] Pa, strength "
      "{:.4g} Pa static, {:.4g} Pa dynamic, S = {}, {} stretch(es)",
      f.static_friction, f.dynamic_friction, f.dc, f.tn0, f.tt0, ts, td,
      t0 > td ? fmt::format("{:.3g}", (ts - t0) / (t0 - td)) : std::string("inf"),
      is.stretches.size()) + f.relaxation.describe();
}

// Friction is history-dependent: the total traction T0 + dT of the Gauss points next to the
// node (the segments' first and last), averaged.
CohesiveTraction node_traction(const CohesiveInterface& c, std::size_t k) {
  const SlipWeakening& f = std::get<SlipWeakening>(node_law_variant(c, k));
  const CohesiveTraction d = mean_gauss_traction(c, k);
  return {f.tn0 + d.normal, f.tt0 + d.tangential};
}

}  // namespace

LawEntry slip_weakening_entry() {
  return {SlipWeakening::kName,
          "linear slip-weakening friction on a prestressed fault (Ida 1972, Andrews 1976), in "
          "the traction-offset form",
          "\"slip_weakening\": a prestressed fault with linear slip-weakening friction",
          law_alternative<SlipWeakening>(),
          true,
          {"static_friction", "dynamic_friction", "dc", "cohesion", "normal_stiffness",
           "stick_stiffness", "initial_traction", "stretches", "overstressed", "normal_relaxation",
           "normal_relaxation_time", "normal_relaxation_slip", "normal_relaxation_rate"},
          parse,
          describe,
          node_traction};
}

}  // namespace rupture
