// rupture/fracture/running_tip_field.hpp
// The leading (r^-1/2) term of the field at a straight crack tip running steadily at speed v
// (0 < v < c_R) in a linear elastic solid, for a unit stress intensity factor, in the tip
// frame (x1 ahead of the tip along the crack, x2 normal to it, faces on x1 < 0, x2 = 0):
// Freund, Dynamic Fracture Mechanics (1990), sec. 4.3, written with z_d = x1 + i a_d x2,
// z_s = x1 + i a_s x2, a_d,s = sqrt(1 - v^2/c_d,s^2), D = 4 a_d a_s - (1 + a_s^2)^2 and
// C = 1 / (sqrt(2 pi) mu D) (docs/theory.md §18a):
//   mode I:  u1 = 2C Re[(1 + a_s^2) sqrt z_d - 2 a_d a_s sqrt z_s],
//            u2 = 2C Im[-a_d (1 + a_s^2) sqrt z_d + 2 a_d sqrt z_s];
//   mode II: u1 = 2C Im[2 a_s sqrt z_d - a_s (1 + a_s^2) sqrt z_s],
//            u2 = 2C Re[2 a_d a_s sqrt z_d - (1 + a_s^2) sqrt z_s];
// the stress is Hooke's of their gradient (lambda / mu = c_d^2 / c_s^2 - 2: plane strain with
// c_d = sqrt((lambda + 2 mu) / rho), plane stress with the plate's c_d). Contract: the field
// satisfies the steady equation of motion sigma_ij,j = rho v^2 u_i,11 (rho = mu / c_s^2), its
// faces are traction-free, sigma_22 (mode I) and sigma_12 (mode II) straight ahead are
// 1 / sqrt(2 pi r), and as v -> 0 it becomes the Williams field (fracture/near_tip_field.hpp);
// tests/test_running_tip_field.cpp checks each. Its energy release rate is
// G = (A_I K_I^2 + A_II K_II^2) / E' (Freund eq. 5.3.10). These are the auxiliary fields of the
// interaction integral at a running tip (fracture/j_integral.hpp). Units: Pa, m, m/s.
#pragma once

#include "fracture/near_tip_field.hpp"
#include "material/elastic.hpp"

namespace rupture {

// Below this fraction of c_s a tip is read as stationary: the running field's terms cancel to
// O(v^2 / c^2), and its closed form loses (c / v)^2 of the digits (1e-6 of the field at 1e-3;
// the Williams field differs from it by O(v^2 / c^2) = 1e-6 there).
inline constexpr double kRunningTipSpeed = 1e-3;  // of c_s

// The fastest speed a tip is read at, as a fraction of c_R (the field and A_I, A_II are singular
// at c_R; at 0.95 c_R, nu = 0.3 plane strain, A_I = 5.7: the reading is ill-conditioned beyond).
inline constexpr double kRunningTipCap = 0.95;

// The unit-K field and the second derivatives along x1 of its displacement (-: per m).
struct RunningTipField {
  NearTipField f;
  double u1_11 = 0.0, u2_11 = 0.0;  // d^2 u_i / dx1^2, 1/m
};

// Both modes' fields at (x1, x2) (r > 0) for a tip running at v in [kRunningTipSpeed c_s, c_R)
// in a solid of shear modulus mu (Pa) and wave speeds w (dilatational of the plane problem, shear).
void running_tip_fields(double x1, double x2, double v, double mu, const WaveSpeeds& w,
                        RunningTipField& opening, RunningTipField& sliding);

// A_I(v), A_II(v) of G = (A_I K_I^2 + A_II K_II^2) / E' (-; both 1 at v = 0, infinite at c_R):
// A = 2 (1 - c_s^2/c_d^2) v^2 a / (c_s^2 D), a = a_d (mode I) or a_s (mode II).
struct RunningTipFactors {
  double A_I = 1.0, A_II = 1.0;
};
RunningTipFactors running_tip_factors(double v, const WaveSpeeds& w);

}  // namespace rupture
