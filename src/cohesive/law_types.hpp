// rupture/cohesive/law_types.hpp
// The two plain structs every traction law shares: the history a Gauss point carries between
// steps and what a law returns there. Include cohesive/law.hpp, which states the contract;
// this header exists only so that each law's own header can use them without a cycle.
// Units: SI (m, Pa, Pa/m).
#pragma once

namespace rupture {

// Per-Gauss-point history, stored by the interface as one array per member (checkpointed).
// Zero-initialised = pristine. What each member means:
//   damage  BilinearLaw: the largest effective opening lambda reached so far (dimensionless,
//           >= 0, never decreases; >= 1 = fully separated). XuNeedleman: unused (stays 0).
//   slip    ContactLaw: the plastic (frictional) slip, m, the rest length of the tangential
//           stick spring. Cohesive laws leave it alone, so the same record carries over when a
//           separated point hands over to contact. SlipWeakening: the same (stick spring).
//   jump_t  the tangential jump at the previous step, m: not stored apart but loaded by the
//           interface loop from its gp_dt (SlipWeakening measures its slip path with it).
//   state   RateStateFriction: its state psi minus the initial state (dimensionless; 0 =
//           pristine). The other laws leave it alone.
//   rate    RateStateFriction: its slip rate V minus the initial rate, m/s (signed along t).
//   normal_seen  SlipWeakening and RateStateFriction with a normal-stress regularization
//           (cohesive/normal_relaxation.hpp): the compression friction sees, sigma*, minus the
//           initial compression, Pa (0 = pristine). The other laws leave it alone.
// SlipWeakening and RateStateFriction keep their slip path D (m, never decreases) in `damage`.
// The loop also loads what the point's law may ask (and no law stores): where the point lies
// (x, y: its reference position, m), the time of the jumps (s) and the step that led there
// (duration, s; 0 at set-up).
struct GaussHistory {
  double damage = 0.0;
  double slip = 0.0;
  double jump_t = 0.0;
  double state = 0.0;
  double rate = 0.0;
  double normal_seen = 0.0;
  double x = 0.0, y = 0.0;
  double time = 0.0, duration = 0.0;
};

// What a law returns at one Gauss point.
struct LawResponse {
  double tn;         // resisting normal traction T^n, Pa (> 0 pulls the faces together)
  double tt;         // resisting tangential traction T^t, Pa
  double stiffness;  // stability stiffness, Pa/m: >= the largest eigenvalue of dT^/dDelta here
};

}  // namespace rupture
