// rupture/cohesive/law.hpp
// The traction-law contract: what the interface loop (E7-E9) asks of a cohesive law at one
// Gauss point, the laws that keep it (a std::variant, chosen once per interface and
// dispatched once with std::visit around a loop templated on the law), and contact for the
// points that have no cohesion left. Units: SI (m, Pa, Pa/m, J/m^2).
//
// Contract. The loop gives each Gauss point its normal and tangential jumps (dn, dt, m, in
// the segment's frame, dn = n.(u+ - u-)) and its GaussHistory h; a law L provides, as const
// members with exactly these shapes (checked by the concept TractionLaw below):
//   LawResponse L::respond(double dn, double dt, GaussHistory& h) const;
//       The resisting traction T^ = (tn, tt), Pa: the upper face receives -T^, the lower +T^
//       (as XuNeedleman::traction; tn > 0 resists opening, tn < 0 resists interpenetration).
//       The stiffness, Pa/m, is >= 0 and bounds the largest eigenvalue of the tangent
//       dT^/dDelta here, including a penalty that a step's round-off could switch on
//       (docs/time_step.md). Updates h irreversibly (damage only grows); call it once per
//       Gauss point per step, with the step's final jumps.
//   double L::stored_energy(double dn, double dt, const GaussHistory& h) const;
//       The recoverable energy at this state, J/m^2, given the history respond() left: the
//       potential for an elastic law, the damaged spring's 0.5 T^.Delta for a damage law.
//       Dissipated energy = work done on the point - stored energy.
//   double L::fracture_energy_normal() const;      G_Ic, J/m^2
//   double L::fracture_energy_tangential() const;  G_IIc, J/m^2
//   double L::initial_stiffness() const;           Pa/m, the undamaged law's elastic stiffness
//   bool L::separated(const GaussHistory& h) const;
//       True once the law carries no cohesion (irreversible). XuNeedleman answers false: its
//       criterion (|Delta| >= 5 delta_t, theory §3) is separates_at, which the loop asks first.
//   double L::crack_measure(double dn, double dt) const;  double L::crack_threshold(double f)
//   const;
//       A node has cracked (E10) once crack_measure of its jumps reaches crack_threshold
//       (f = the interface's separation factor, used by Xu-Needleman only).
//   bool L::softening(double dn, double dt) const;   past the peak traction (cohesive zone)
//   double L::opening_scale() const;                 a small opening of the law's own scale, m
// and the questions the generic code asks instead of testing which law it has:
//   bool L::separates_at(double dn, double dt, double f) const;
//       True where the interface separates the point by its jump alone, before the law is
//       asked (Xu-Needleman: |Delta| >= f delta_t, theory §3); false for a law whose own history
//       says so (separated()).
//   double L::load_fraction(double dn, double dt) const;
//       The traction of a pristine point at these jumps as a fraction of its strength (the
//       crack tracker's traction zone, cohesive/crack_tip.hpp); 0 for a law with no such zone
//       ahead of its tip (friction: the zone is where the fault slips).
//   static constexpr bool L::kSlipPathRate;
//       True where GaussHistory::damage is a slip path (friction): a node's slip rate (rupture
//       front, peak slip rate) is then the rate of that path, sliding only, not of its jump.
//   static constexpr const char* L::kName;   the name the input file uses (law = "...")
// No allocation, no virtual call: every member is inline and the structs are plain data.
//
// To add a law: one header (+ .cpp for validate()) with a struct keeping the contract, its
// test file, one more alternative in CohesiveLaw, and its entry in the table of laws the
// input may name (input/law_registry.hpp: its keys, parser, words in `rupture check`, node
// traction; docs/cohesive_laws.md).
#pragma once
#include <concepts>
#include <variant>

#include "cohesive/bilinear.hpp"
#include "cohesive/contact.hpp"
#include "cohesive/law_types.hpp"
#include "cohesive/rate_state.hpp"
#include "cohesive/slip_weakening.hpp"
#include "cohesive/xu_needleman.hpp"

namespace rupture {

template <class L>
concept TractionLaw = requires(const L& law, double d, GaussHistory& h, const GaussHistory& ch) {
  { law.respond(d, d, h) } -> std::same_as<LawResponse>;
  { law.stored_energy(d, d, ch) } -> std::same_as<double>;
  { law.fracture_energy_normal() } -> std::same_as<double>;
  { law.fracture_energy_tangential() } -> std::same_as<double>;
  { law.initial_stiffness() } -> std::same_as<double>;
  { law.separated(ch) } -> std::same_as<bool>;
  { law.crack_measure(d, d) } -> std::same_as<double>;
  { law.crack_threshold(d) } -> std::same_as<double>;
  { law.softening(d, d) } -> std::same_as<bool>;
  { law.opening_scale() } -> std::same_as<double>;
  { law.separates_at(d, d, d) } -> std::same_as<bool>;
  { law.load_fraction(d, d) } -> std::same_as<double>;
  requires std::same_as<decltype(L::kSlipPathRate), const bool>;
  { L::kName } -> std::convertible_to<const char*>;
};

using CohesiveLaw = std::variant<XuNeedleman, BilinearLaw, SlipWeakening, RateStateFriction>;

static_assert(TractionLaw<XuNeedleman>);
static_assert(TractionLaw<BilinearLaw>);
static_assert(TractionLaw<SlipWeakening>);
static_assert(TractionLaw<RateStateFriction>);

// The name the input file uses for the law.
inline const char* law_name(const CohesiveLaw& law) {
  return std::visit([](const auto& l) -> const char* { return l.kName; }, law);
}

// The stability stiffness of a pristine point at rest (Dn = Dt = 0), Pa/m: what the time-step
// estimate needs at t = 0 (for XuNeedleman, stability_stiffness(0, 0)).
inline double stiffness_at_rest(const CohesiveLaw& law) {
  return std::visit(
      [](const auto& l) {
        GaussHistory h;
        return l.respond(0.0, 0.0, h).stiffness;
      },
      law);
}

}  // namespace rupture
