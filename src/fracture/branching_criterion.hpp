// rupture/fracture/branching_criterion.hpp
// When a running tip splits in two (docs/fracture.md, "Branching"): Yoffe's (1951) criterion.
// The near-tip stress of a mode-I crack running steadily at speed v is
//   sigma_ij = K_I / sqrt(2 pi r) Sigma_ij(theta, v)
// (Freund, Dynamic Fracture Mechanics, 1990, eq. 4.3.11 and its footnotes; the functions below),
// and its hoop stress sigma_thetatheta is largest straight ahead (theta = 0) at low speed; above
// a speed near 0.6 c_R the largest hoop stress lies off the axis, at +-theta_b, and the crack
// branches there: the two new tips leave at +-theta_b.
// Units: m/s, radians. Plane strain or plane stress enter only through c_d (the dilatational
// wave speed of the plane problem: sqrt((lambda + 2 mu) / rho) in plane strain,
// sqrt(E / (rho (1 - nu^2))) in plane stress).
#pragma once
#include "material/elastic.hpp"

namespace rupture {

// The field depends on the wave speeds (material/elastic.hpp): dilatational c_d of the plane
// problem and shear c_s; c_R is found from them here.

// The Rayleigh wave speed: the root in (0, c_s) of 4 a_d a_s - (1 + a_s^2)^2 = 0.
double rayleigh_speed(const WaveSpeeds& w);

// Freund's angular functions of the running mode-I tip at v in (0, c_R), normalised so that
// Sigma_yy(0, v) = 1; (x along the crack, ahead of the tip). As v -> 0 they become Williams'.
struct AngularStress {
  double xx = 0.0, yy = 0.0, xy = 0.0;
};
AngularStress running_mode_one(double theta, double v, const WaveSpeeds& w);

// sigma_thetatheta sqrt(2 pi r) / K_I of that field.
double running_hoop(double theta, double v, const WaveSpeeds& w);

// The angle in [0, pi/2] of the largest hoop stress at speed v (0: straight ahead).
double largest_hoop_angle(double v, const WaveSpeeds& w);

// Yoffe's speed: the lowest speed at which the largest hoop stress leaves the axis (m/s).
double yoffe_speed(const WaveSpeeds& w);

// The decision for a tip running at v: branch when v reaches Yoffe's speed, each new tip at
// +-angle (radians) from the running direction, where the hoop stress at v is largest.
struct BranchDecision {
  bool branch = false;
  double angle = 0.0;
};
BranchDecision decide_branching(double v, const WaveSpeeds& w);

}  // namespace rupture
