// rupture/fracture/j_integral.hpp
// The J-integral and the stress intensity factors K_I, K_II of one crack tip, from the domain
// form of the dynamic J-integral and of the interaction integral, summed over material points
// (the particles as quadrature points; docs/fracture.md).
//   J = sum_p A_p { [sigma_ij u_i,1 - (W + T) delta_1j] q_,j + rho (a_i u_i,1 - v_i v_i,1) q }
//   M = sum_p A_p { [sigma_ij u^a_i,1 + sigma^a_ij u_i,1 - sigma_ij eps^a_ij delta_1j] q_,j
//                   + rho a_i u^a_i,1 q },   K = E' M / 2 per auxiliary mode (a: the unit
//       Williams field of fracture/near_tip_field.hpp, mode I then mode II),
// in the tip frame (x1 along the crack ahead of the tip), W = sigma:eps / 2, T = rho v.v / 2,
// E' = E / (1 - nu^2) in plane strain, E in plane stress. q is 1 inside the circle of radius
// `inner` about the tip, 0 outside the one of radius `outer`, and the smooth step
// 1 - (3 xi^2 - 2 xi^3), xi = (r - inner) / (outer - inner), between (its gradient vanishes at
// both circles: the particle sums converge at second order whatever the crack's angle to the
// lattice). Contract: the material is one
// homogeneous linear elastic solid over the domain, with a stress-free reference state; the
// crack faces inside the domain are straight and traction-free (the form then needs no face
// term), or carry the loads of FaceTraction and FaceContact (their face terms, below); the tip
// is stationary, or runs steadily near it at TipMaterial::speed v: then the
// auxiliary fields are the running tip's, u^a_dot = -v u^a_,1, and M takes its steady form
//   M = sum_p A_p [sigma_ij u^a_i,1 + sigma^a_ij u_i,1 - (sigma_ij eps^a_ij - rho v v_k u^a_k,1) delta_1j] q_,j
// (the volume inertia terms, which cancel point by point for a steady field, dropped: their
// r^-2 products are what a discretely advancing tip gets wrong; theory.md §18a). J itself is the
// running tip's energy release rate as it stands. Units: SI (J in J/m^2, K in Pa sqrt(m)).
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace rupture {

// One material point in the domain, global frame.
struct DomainPoint {
  double x, y;                    // position, m
  double area;                    // current area (volume per unit thickness), m^2
  double density;                 // kg/m^3
  double sxx, syy, sxy;           // stress, Pa
  double exx, eyy, exy;           // strain (tensor components), -
  double ux_x, ux_y, uy_x, uy_y;  // displacement gradient du_i/dx_j, -
  double vx, vy;                  // velocity, m/s
  double vx_x, vx_y, vy_x, vy_y;  // velocity gradient, 1/s
  double ax, ay;                  // acceleration, m/s^2
  std::uint32_t id;               // the particle's (Particles::id)
  // Displacement from the stress-free state, m: only the loaded faces' J term reads it (below).
  double ux = 0.0, uy = 0.0;
};

// A traction prescribed on a crack face inside the domain, carried by one of the points (a
// surface particle and its share of the loaded length, as the load applies it): the faces are
// then not traction-free, and both integrals take the face term (docs/fracture.md)
//   J -= int t_i u_i,1 q ds,   M -= sum t_i u^a_i,1 q l,
// q and u^a taken on the face (the point projected onto the crack line, on its own side). J's
// term is integrated by parts along the face, so it reads the face's displacement (the point's,
// carried to the line by its gradient u_i,2, less the tip's: TipFrame::ux, uy) against q_,1
// rather than u_i,1, which the grid's maps smear near the tip where it goes as r^-1/2:
//   int t_i u_i,1 q ds = sum t_i (u_i - u_tip,i) q_,1 l + t_i (u_i - u_tip,i) q at the ends of
//   the loaded stretch that lie behind the tip (the far end +, the near end -).
// Contract: the faces lie on the crack line behind the tip (x1 < 0).
struct FaceTraction {
  std::size_t point = 0;     // index into the points
  double length = 0.0;       // m
  double tx = 0.0, ty = 0.0; // traction on the body, global frame, Pa
  // The loaded segment's ends, global frame, m (a share holding one inside the domain takes the
  // end term above). NaN: the load runs on beyond the domain and to the tip.
  double from_x = kNoEnd, from_y = kNoEnd, to_x = kNoEnd, to_y = kNoEnd;
  static constexpr double kNoEnd = std::numeric_limits<double>::quiet_NaN();
};

// Where the crack's faces press or rub on each other inside the domain (contact, or what is left
// of a cohesive law once separated): a quadrature point of the line behind the tip carrying the
// traction t on the upper face's material and -t on the lower's. Faces in contact are not
// traction-free, so both integrals take the face term over the two faces (docs/fracture.md,
// "Faces in contact"):
//   J -= int t_i [[u_i]],1 q ds,   M -= int t_i (u^a_i,1(upper) - u^a_i,1(lower)) q ds,
// [[u]] = u(upper) - u(lower) the jump, u^a on each face (theta = +/-pi), the r^-1/2 of u^a
// integrated over the point's share as for FaceTraction. M takes the shear part s of t only: on
// the faces the mode I field opens them (u^a_1 = 0) and the mode II field slides them (u^a_2 =
// 0), so the pressure would act on K_I alone, and it is left out: a pressed tip's K_I is the
// closed flaw's 0 (fracture/growth_criterion.hpp), and the penalty's pressure within a cell of a
// tip is not resolved (it differs by ten times between the two tips of one crack). Without the
// term a closed crack's pressure p reads as a K_I of -c p sqrt(R) on a domain of radius R, and
// friction's traction as a K_II of the same form (docs/validation.md, Kalthoff-Winkler). Contract: the points lie on the crack
// line behind the tip (x1 < 0; others are skipped).
struct FaceContact {
  double x = 0.0, y = 0.0;        // the point, m
  double length = 0.0;            // its share of the line, m
  double tx = 0.0, ty = 0.0;      // traction on the upper face's material, Pa
  double sx = 0.0, sy = 0.0;      // its shear part, along the face (friction's), Pa
  double nx = 0.0, ny = 1.0;      // unit normal of the line, towards the upper face
  double jx_s = 0.0, jy_s = 0.0;  // d[[u]]/ds along the line's direction (tx_s, ty_s), -
  double tx_s = 1.0, ty_s = 0.0;  // unit direction of the line there
};

// The tip and the direction the crack points to (unit vector e1, from the crack into the
// material ahead), global frame.
struct TipFrame {
  double x = 0.0, y = 0.0;       // m
  double e1x = 1.0, e1y = 0.0;   // -
  double ux = 0.0, uy = 0.0;     // displacement at the tip, m (the loaded faces' J term)
};

struct JDomain {
  double inner = 0.0, outer = 0.0;  // radii, m (0 <= inner < outer)
};

struct TipMaterial {
  double e_prime = 0.0;  // E', Pa
  double mu = 0.0;       // shear modulus, Pa
  double kappa = 0.0;    // Kolosov's constant, -
  // A running tip (docs/fracture.md, "A running tip"): its speed along e1 and the solid's wave
  // speeds (dilatational of the plane problem, shear). At speed >= kRunningTipSpeed c_s the
  // auxiliary fields are the running tip's (fracture/running_tip_field.hpp), the interaction
  // integral its steady form above and K = M mu c_s^2 D / (v^2 a_d,s), from
  // J(K + K^a) = (A_I K_I^2 + A_II K_II^2) / E'; below, the stationary forms, bit for bit.
  double speed = 0.0;               // m/s
  double c_d = 0.0, c_s = 0.0;      // m/s
};

struct TipIntegrals {
  double J = 0.0;              // J/m^2
  double K_I = 0.0, K_II = 0.0;  // Pa sqrt(m)
  std::size_t points = 0;      // material points with q or grad q non-zero
};

// The integrals over the points (those outside the outer square contribute nothing).
TipIntegrals tip_integrals(const std::vector<DomainPoint>& points, const TipFrame& tip,
                           const JDomain& domain, const TipMaterial& material,
                           const std::vector<FaceTraction>& faces = {},
                           const std::vector<FaceContact>& contacts = {});

// The same on several domains at once (each point's auxiliary fields evaluated once; the
// results are those of one call per domain, bit for bit).
std::vector<TipIntegrals> tip_integrals(const std::vector<DomainPoint>& points, const TipFrame& tip,
                                        const std::vector<JDomain>& domains,
                                        const TipMaterial& material,
                                        const std::vector<FaceTraction>& faces = {},
                                        const std::vector<FaceContact>& contacts = {});

// The maximum hoop stress direction (Erdogan & Sih 1963): the angle from the crack's direction
// to the one a tip with K_I, K_II would kink into, radians, counterclockwise:
// theta = 2 atan[(K_I - sqrt(K_I^2 + 8 K_II^2)) / (4 K_II)] (0 when K_II = 0; -70.5 degrees in
// pure mode II with K_II > 0).
double hoop_stress_angle(double K_I, double K_II);

}  // namespace rupture
