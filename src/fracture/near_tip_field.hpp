// rupture/fracture/near_tip_field.hpp
// The leading (Williams, r^-1/2) term of the field at a straight crack tip in a linear elastic
// solid, for a unit stress intensity factor, in the crack-tip frame: x1 ahead of the tip along
// the crack, x2 normal to it, the crack faces on x1 < 0, x2 = 0 (docs/theory.md §18).
// Contract: the stress is sigma = K / sqrt(2 pi r) f(theta) and the displacement
// u = K / (2 mu) sqrt(r / (2 pi)) g(theta) (Anderson, Fracture Mechanics, Table 2.1-2.2), with
// kappa = 3 - 4 nu (plane strain) or (3 - nu) / (1 + nu) (plane stress); the gradient is that of
// u, so C : sym(grad u) = sigma holds to round-off (tests/test_near_tip_field.cpp). These are
// the auxiliary fields of the interaction integral (fracture/j_integral.hpp). Units: Pa, m, for
// K = 1 Pa sqrt(m).
#pragma once

#include "material/elastic.hpp"

namespace rupture {

enum class CrackMode { opening, sliding };  // mode I, mode II

struct NearTipField {
  double s11, s22, s12;          // stress, Pa
  double u1, u2;                 // displacement, m
  double u1_1, u1_2, u2_1, u2_2; // du_i/dx_j, -
};

// kappa of the plane mode (Kolosov's constant), -.
double kolosov_kappa(double poisson_ratio, PlaneMode mode);

// The unit-K field of `mode` at (x1, x2) in the tip frame (r > 0; theta in (-pi, pi], the upper
// face at +pi), for shear modulus mu (Pa) and kappa.
NearTipField williams_field(CrackMode mode, double x1, double x2, double mu, double kappa);
// Both modes' at one point (the trigonometry evaluated once).
void williams_fields(double x1, double x2, double mu, double kappa, NearTipField& opening, NearTipField& sliding);

}  // namespace rupture
