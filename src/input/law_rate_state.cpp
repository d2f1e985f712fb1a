// rupture/input/law_rate_state.cpp: rate-and-state friction's entry in the table of laws
// (input/law_registry.hpp): its input keys (read by input/parse_fault.cpp), its words in
// `rupture check` (parameters, initial state, steady-state rate dependence), and the total
// traction T0(t) + dT its nodes report. Units: Pa, m, m/s, s.
#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "cohesive/interface.hpp"
#include "input/case_parse.hpp"
#include "input/law_registry.hpp"

namespace rupture {

namespace {

void parse(Section& f, InterfaceSpec& is, const Case& c) {
  refuse_contact_keys(f, RateStateFriction::kName);
  parse_rate_state_law(f, c, is);
}

// a - b < 0 weakens with rate at steady state (unstable slip possible); the initial state and
// the friction it gives at the initial rate.
std::string describe(const InterfaceSpec& is) {
  const RateStateFriction& f = std::get<RateStateFriction>(is.law);
  std::string s = fmt::format(
      "{} law, a = {:g}, b = {:g} (a - b = {:g}: {}), Dc = {:g} m, V0 = {:g} m/s, f0 = {:g}",
      evolution_name(f.evolution), f.a, f.b, f.a - f.b,
      f.a < f.b ? "velocity weakening" : "velocity strengthening", f.dc, f.v0, f.f0);
  if (f.evolution == StateEvolution::flash_heating)
    s += fmt::format(", f_w = {:g}, V_w = {:g} m/s", f.fw, f.vw);
  s += fmt::format(", initial traction [{:g}, {:g}] Pa at V = {:g} m/s (state {:.6g})", f.tn0, f.tt0,
                   f.v_init, f.psi_init);
  if (f.nucleation_stress != 0.0)
    s += fmt::format(", nucleation {:g} Pa at [{:g}, {:g}] m, R = {:g} m, over {:g} s",
                     f.nucleation_stress, f.nucleation_x, f.nucleation_y, f.nucleation_radius,
                     f.nucleation_time);
  if (f.taper.on)
    s += fmt::format(", taper from [{:g}, {:g}] m: W = {:g} m, w = {:g} m to a = {:g}, b = {:g}, "
                     "Dc = {:g} m, V_w = {:g} m/s (0: untapered)",
                     f.taper.x, f.taper.y, f.taper.half_width, f.taper.width, f.taper.a, f.taper.b,
                     f.taper.dc, f.taper.vw);
  return s + fmt::format(", {} stretch(es)", is.stretches.size()) + is.profile.describe() + f.relaxation.describe();
}

// The total traction T0(t) + dT of the Gauss points next to the node, averaged (T0(t): the
// initial shear plus the nucleation stress at the interface's time).
CohesiveTraction node_traction(const CohesiveInterface& c, std::size_t k) {
  const RateStateFriction& f = std::get<RateStateFriction>(node_law_variant(c, k));
  const CohesiveTraction d = mean_gauss_traction(c, k);
  return {f.tn0 + d.normal, f.shear_prestress(c.x0[k], c.y0[k], c.time) + d.tangential};
}

}  // namespace

LawEntry rate_state_entry() {
  return {RateStateFriction::kName,
          "rate-and-state friction on a prestressed fault (Dieterich 1979, Ruina 1983; the SCEC "
          "TPV101-TPV105 regularized form), aging, slip or flash-heating evolution",
          "\"rate_state\": a prestressed fault with rate-and-state friction",
          law_alternative<RateStateFriction>(),
          true,
          {"evolution", "a", "b", "dc", "reference_slip_rate", "reference_friction",
           "weakened_friction", "weakening_slip_rate", "initial_slip_rate", "initial_traction",
           "normal_stiffness", "stick_stiffness", "nucleation_stress", "nucleation_centre",
           "nucleation_radius", "nucleation_time", "taper", "profile", "stretches", "normal_relaxation",
           "normal_relaxation_time", "normal_relaxation_slip", "normal_relaxation_rate"},
          parse,
          describe,
          node_traction};
}

}  // namespace rupture
