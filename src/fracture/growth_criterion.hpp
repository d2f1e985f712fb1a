// rupture/fracture/growth_criterion.hpp
// When a crack tip grows and in which direction, from its stress intensity factors
// (docs/fracture.md, "Growth"). Plain data chosen per crack in the input; free functions.
//  - criterion max_hoop (Erdogan & Sih 1963): the tip grows when the hoop stress intensity in
//    the maximum hoop stress direction theta_c, K_eq = cos(theta_c/2) [K_I cos^2(theta_c/2)
//    - 3/2 K_II sin(theta_c)], reaches the toughness K_Ic;
//  - criterion energy (Irwin): when G = (K_I^2 + K_II^2) / E' reaches G_c (G from K, not from
//    J: docs/fracture.md's open finding on J of inclined cracks);
//  - criterion cohesive (a crack whose new segments carry a cohesive law; a strength
//    criterion read through the law): a tip whose end segment carries cohesion grows once
//    that segment is past the law's peak traction (CrackFront::softening: the traction ahead
//    has reached the strength and the process zone has reached the end of the line, which
//    extends so the zone can go on); a tip whose end segment carries none (a cut, or a segment
//    that has let go) grows as soon as it is pulled open (K_I > 0: a sharp tip's stress
//    exceeds any strength, so the first segment, which then carries at most sigma_max, comes at
//    once, as Camacho & Ortiz 1996 insert an extrinsic law where the strength is reached);
//  - criterion prescribed (a generation-phase run: the tip's motion given, the fields it makes
//    read; decide_prescribed): the tip grows whenever the path it has grown plus one step is
//    within speed (t - start), so it runs at the given speed from the given time;
//  - direction max_hoop: theta_c (hoop_stress_angle); straight: along the crack.
//  - a weak plane (energy, plane_fracture_energy > 0): while the tip is still on the drawn
//    line's straight extension, two ways compete (He & Hutchinson 1989): along the plane, with
//    G_0 = (K_I+^2 + K_II^2) / E' against the plane's G_c,p, or out of it at theta_c(K_I+, K_II),
//    with the kinked crack's G(theta_c) = (k_I^2 + k_II^2) / E' (kinked_intensities) against the
//    bulk's G_c, K_I+ = max(K_I, 0) (a shear crack pressed shut runs or kinks in mode II); the larger
//    ratio G / G_c wins once it reaches 1. Pure mode II: G(theta_c) / G_0 = 4/3, so the crack
//    stays on the plane iff G_c,p < 0.75 G_c. Off the plane the tip is a kink at angle phi
//    (kink: its end segment's direction from the crack's, in which K_I, K_II were read over the
//    J domains, which see the crack before the kink while the kink is shorter than they are):
//    its own intensities are k = kinked_intensities(K_I+, K_II, phi); it grows at theta_c(k)
//    from its end segment (phi + theta_c(k) from the crack's) when the G of that increment,
//    K_eq(k)^2 / E' (its k_II is 0), reaches the bulk's G_c. At phi = theta_c that is the
//    G(theta_c) that made it kink (theta_c(k) = 0), so a kink runs on straight; once the kink is
//    longer than the domains, phi -> 0 and the increment's G is that of max_hoop with K_I+.
// A closed tip (K_I < 0: its faces press together and carry contact) is read as K_I+ = max(K_I, 0)
// by every criterion that reads K (the closed flaw of the wing-crack analyses): it grows in mode
// II at theta_c(0, K_II) = -/+70.53 degrees once its shear alone reaches the toughness. A closed
// cut does not grow by the cohesive criterion (that one waits to be pulled open).
// Units: Pa m^1/2, J/m^2, radians.
#pragma once

#include "fracture/running_tip_field.hpp"

namespace rupture {

enum class GrowthCriterion { none, max_hoop, energy, cohesive, prescribed };
enum class GrowthDirection { max_hoop, straight };
// When a growing tip splits in two (fracture/branching_criterion.hpp; solver/crack_branching.hpp).
enum class BranchCriterion { none, yoffe };

struct GrowthLaw {
  GrowthCriterion criterion = GrowthCriterion::none;
  GrowthDirection direction = GrowthDirection::max_hoop;
  double toughness = 0.0;        // K_Ic, Pa m^1/2 (max_hoop)
  double fracture_energy = 0.0;  // G_c, J/m^2 (energy)
  double plane_fracture_energy = 0.0;  // G_c,p of the weak plane ahead, J/m^2 (energy; 0: none)
  double step = 0.5;             // length of one growth step, in cells (0, 0.5]
  double speed = 0.0;            // prescribed: the tip's speed, m/s (> 0)
  double start = 0.0;            // prescribed: when the tips start to run, s (>= 0)
  BranchCriterion branching = BranchCriterion::none;
  int max_branches = 0;          // how many times the crack's tips may split (each: a new field)
  bool on() const { return criterion != GrowthCriterion::none; }
};

// The hoop stress intensity sigma_thetatheta sqrt(2 pi r) of the Williams field at angle theta
// from the crack line, Pa m^1/2.
double hoop_stress_intensity(double K_I, double K_II, double theta);

// The stress intensities at the tip of a short kink at angle theta from a crack with K_I, K_II
// (Cotterell & Rice 1980's first-order result for a kink much shorter than the crack; the
// stresses of the Williams field resolved on the kink's line): k_I = 1/4 [3 cos(t/2) + cos(3t/2)] K_I
// - 3/4 [sin(t/2) + sin(3t/2)] K_II, k_II = 1/4 [sin(t/2) + sin(3t/2)] K_I + 1/4 [cos(t/2)
// + 3 cos(3t/2)] K_II. At theta_c, k_I is the hoop intensity and k_II = 0.
struct KinkIntensities {
  double k_I = 0.0, k_II = 0.0;  // Pa m^1/2
};
KinkIntensities kinked_intensities(double K_I, double K_II, double theta);

// What the cohesive criterion reads at the end of the line (solver/crack_growth.cpp).
enum class CrackFront {
  open,       // the end segment carries no cohesion (a cut, or let go): a sharp tip
  loading,    // a cohesive end segment before the law's peak traction
  softening,  // a cohesive end segment past the peak: the process zone has reached it
};

struct GrowthDecision {
  bool grow = false;
  double angle = 0.0;    // direction of the new segment from the crack's, radians (ccw)
  double driving = 0.0;  // K_eq (Pa m^1/2), G (J/m^2) or, cohesive, 1 past the peak / 0
  double critical = 0.0; // its critical value (cohesive: 1)
};

// e_prime: E (plane stress) or E / (1 - nu^2) (plane strain), Pa. front: the end segment's
// state (read by the cohesive criterion only). on_plane: the tip lies on the weak plane (the
// drawn line's straight extension; read only with plane_fracture_energy); kink: off the plane,
// the end segment's angle from the direction K was read in (radians, ccw; the same use).
// running: a running tip's A_I, A_II (fracture/running_tip_field.hpp; K_I, K_II then read with
// the running tip's fields): the energy criterion's G = (A_I K_I^2 + A_II K_II^2) / E' (Freund
// eq. 5.3.10); max_hoop weighs the running tip's K against the same toughness (K_Ic read as the
// running toughness K_ID, independent of speed).
GrowthDecision decide_growth(const GrowthLaw& law, double K_I, double K_II, double e_prime,
                             CrackFront front = CrackFront::open, bool on_plane = false,
                             double kink = 0.0, const RunningTipFactors& running = {});

// The prescribed criterion at `time` for a tip that has grown `grown` (m) and would grow a step
// of `step` (m): it grows when grown + step <= speed (time - start) (to round-off), in the
// law's direction; driving: the path due, critical: the path with the step (m).
GrowthDecision decide_prescribed(const GrowthLaw& law, double K_I, double K_II, double grown, double step,
                                 double time);

}  // namespace rupture
