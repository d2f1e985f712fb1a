// rupture/fracture/j_integral.cpp
#include "fracture/j_integral.hpp"

#include <algorithm>
#include <cmath>

#include "fracture/near_tip_field.hpp"
#include "fracture/running_tip_field.hpp"

namespace rupture {

namespace {

// A 2x2 tensor T' = R T R^T with R the rotation to the tip frame (rows e1, e2).
struct Rotation {
  double c, s;  // e1 = (c, s), e2 = (-s, c)
  void vec(double ax, double ay, double& a1, double& a2) const {
    a1 = c * ax + s * ay, a2 = -s * ax + c * ay;
  }
  // T'_ij = R_ik T_kl R_jl for T = [txx txy; tyx tyy].
  void ten(double txx, double txy, double tyx, double tyy, double& t11, double& t12, double& t21,
           double& t22) const {
    // R T
    const double a11 = c * txx + s * tyx, a12 = c * txy + s * tyy;
    const double a21 = -s * txx + c * tyx, a22 = -s * txy + c * tyy;
    // (R T) R^T
    t11 = a11 * c + a12 * s, t12 = -a11 * s + a12 * c;
    t21 = a21 * c + a22 * s, t22 = -a21 * s + a22 * c;
  }
};

}  // namespace

namespace {

// What a point contributes, in the tip frame, before the weight q: the same for every domain
// (the Williams fields cost most of the integrals, so they are evaluated once per point).
struct PointTerms {
  double x1, x2, r;
  double s11, s12, s21, s22, u11, u21, w11, w21;
  double v1, v2, a1, a2, W, T, area, density;
  NearTipField f[2];
};

// The running tip's speed, or 0 for a stationary one (below kRunningTipSpeed c_s).
double running_speed(const TipMaterial& m) {
  return m.speed >= kRunningTipSpeed * m.c_s && m.c_s > 0.0 ? m.speed : 0.0;
}

PointTerms point_terms(const DomainPoint& p, const Rotation& R, const TipFrame& tip,
                       const TipMaterial& m) {
  PointTerms t;
  R.vec(p.x - tip.x, p.y - tip.y, t.x1, t.x2);
  t.r = std::sqrt(t.x1 * t.x1 + t.x2 * t.x2);  // m (not hypot: slow, and lengths here are far from overflow)
  double e11, e12, e21, e22, u12, u22, w12, w22;
  R.ten(p.sxx, p.sxy, p.sxy, p.syy, t.s11, t.s12, t.s21, t.s22);
  R.ten(p.exx, p.exy, p.exy, p.eyy, e11, e12, e21, e22);
  R.ten(p.ux_x, p.ux_y, p.uy_x, p.uy_y, t.u11, u12, t.u21, u22);  // u_i,j
  R.ten(p.vx_x, p.vx_y, p.vy_x, p.vy_y, t.w11, w12, t.w21, w22);  // v_i,j
  R.vec(p.vx, p.vy, t.v1, t.v2);
  R.vec(p.ax, p.ay, t.a1, t.a2);
  t.W = 0.5 * (t.s11 * e11 + t.s22 * e22 + 2.0 * t.s12 * e12);
  t.T = 0.5 * p.density * (t.v1 * t.v1 + t.v2 * t.v2);
  t.area = p.area, t.density = p.density;
  const double v = running_speed(m);
  if (v == 0.0) {
    williams_fields(t.x1, t.x2, m.mu, m.kappa, t.f[0], t.f[1]);
    return t;
  }
  RunningTipField f[2];
  running_tip_fields(t.x1, t.x2, v, m.mu, WaveSpeeds{m.c_d, m.c_s, 0.0, 0.0}, f[0], f[1]);
  for (int k = 0; k < 2; ++k) t.f[k] = f[k].f;
  return t;
}

// Whether face share f (its point at x2, r behind the tip) is the one of its loaded segment and
// side of the line nearest the segment's end at re behind the tip (ties: the first in the list).
bool nearest_to_end(const std::vector<FaceTraction>& faces, const std::vector<DomainPoint>& points,
                    const Rotation& R, const TipFrame& tip, const FaceTraction& f, double x2, double re,
                    double r) {
  const double mine = std::fabs(r - re);
  bool earlier = true;
  for (const FaceTraction& g : faces) {
    if (&g == &f) {
      earlier = false;
      continue;
    }
    if (g.from_x != f.from_x || g.from_y != f.from_y || g.to_x != f.to_x || g.to_y != f.to_y) continue;
    double y1, y2;
    const DomainPoint& p = points[g.point];
    R.vec(p.x - tip.x, p.y - tip.y, y1, y2);
    if ((y2 < 0.0) != (x2 < 0.0)) continue;
    const double theirs = std::fabs(std::fabs(y1) - re);
    if (theirs < mine || (earlier && theirs == mine)) return false;
  }
  return true;
}

// The unit auxiliary fields of both modes on a face at x1 < 0, just above the line (yf > 0) or
// just below it (yf < 0): the stationary tip's, or the running tip's at speed v.
void face_fields(double x1, double yf, const TipMaterial& m, double v, NearTipField a[2]) {
  if (v == 0.0) {
    williams_fields(x1, yf, m.mu, m.kappa, a[0], a[1]);
    return;
  }
  RunningTipField rf[2];
  running_tip_fields(x1, yf, v, m.mu, WaveSpeeds{m.c_d, m.c_s, 0.0, 0.0}, rf[0], rf[1]);
  a[0] = rf[0].f, a[1] = rf[1].f;
}

TipIntegrals integrate(const std::vector<PointTerms>& terms, const std::vector<DomainPoint>& points,
                       const Rotation& R, const TipFrame& tip, const JDomain& domain,
                       const TipMaterial& m, const std::vector<FaceTraction>& faces,
                       const std::vector<FaceContact>& contacts) {
  const double width = domain.outer - domain.inner;
  TipIntegrals out;
  double J = 0.0, M[2] = {0.0, 0.0};
  const double v = running_speed(m);
  for (const PointTerms& t : terms) {
    const double r = t.r, x1 = t.x1, x2 = t.x2;
    if (r >= domain.outer) continue;
    // q = 1 - (3 xi^2 - 2 xi^3), xi = (r - inner) / (outer - inner): its gradient vanishes at
    // both edges of the ring, so the particles' midpoint sums converge at second order where a
    // ring edge cuts their cells (a kinked q would leave a first-order error there).
    double q = 1.0, q1 = 0.0, q2 = 0.0;
    if (r > domain.inner) {
      const double xi = (r - domain.inner) / width;
      q = 1.0 - xi * xi * (3.0 - 2.0 * xi);
      const double dq = -6.0 * xi * (1.0 - xi) / width;  // dq/dr
      q1 = dq * x1 / r, q2 = dq * x2 / r;
    }
    ++out.points;
    const double s11 = t.s11, s12 = t.s12, s21 = t.s21, s22 = t.s22, u11 = t.u11, u21 = t.u21;
    // sigma_ij u_i,1 q_,j - (W + T) q_,1 and the inertia terms.
    J += t.area * ((s11 * u11 + s21 * u21 - (t.W + t.T)) * q1 + (s12 * u11 + s22 * u21) * q2 +
                   t.density * (t.a1 * u11 + t.a2 * u21 - t.v1 * t.w11 - t.v2 * t.w21) * q);
    for (int k = 0; k < 2; ++k) {
      if (v == 0.0 && q1 == 0.0 && q2 == 0.0 && (t.a1 == 0.0 && t.a2 == 0.0)) break;  // nothing to add
      if (v > 0.0 && q1 == 0.0 && q2 == 0.0) break;  // a running tip's form lives on the ring
      const NearTipField& f = t.f[k];
      const double cross = s11 * (f.u1_1) + s22 * (f.u2_2) + s12 * (f.u1_2 + f.u2_1);  // sigma : eps^a
      // A stationary tip: the inertia term rho a_i u^a_i,1 q over the whole disc. A running tip:
      // the steady form (theory.md §18a). For a field steady in the tip's frame (u_dot = -v u_,1,
      // u_ddot = v^2 u_,11) the bilinear inertia integrand rho (u_ddot_i u^a_i,1 + u^a_ddot_i
      // u_i,1 - u_dot_i u^a_dot_i,1 - u^a_dot_i u_dot_i,1) q vanishes point by point; each of its
      // terms goes as r^-2, and near a tip that advances segment by segment the particles' a and
      // v do not cancel them, so their log-divergent sum over the inner disc is the reading's
      // error (K_I 29 % low at 0.6 c_R on Freund's running crack with it, 3.5 % high without:
      // docs/fracture.md). So that term is dropped, and T's cross term with the auxiliary field,
      // -rho v_k u^a_dot_k = rho v v_k u^a_k,1, stays on the ring (q_,1).
      const double inertia = v == 0.0 ? t.density * (t.a1 * f.u1_1 + t.a2 * f.u2_1) * q : 0.0;
      const double kinetic = v == 0.0 ? 0.0 : t.density * v * (t.v1 * f.u1_1 + t.v2 * f.u2_1);
      M[k] += t.area * ((s11 * f.u1_1 + s21 * f.u2_1 + f.s11 * u11 + f.s12 * u21 - cross + kinetic) * q1 +
                        (s12 * f.u1_1 + s22 * f.u2_1 + f.s12 * u11 + f.s22 * u21) * q2 + inertia);
    }
  }
  // Loaded faces: the boundary term of the divergence theorem that free faces do not have.
  const auto weight = [&](double r) {  // q on the face, r behind the tip
    if (r >= domain.outer) return 0.0;
    if (r <= domain.inner) return 1.0;
    const double xi = (r - domain.inner) / width;
    return 1.0 - xi * xi * (3.0 - 2.0 * xi);
  };
  for (const FaceTraction& f : faces) {
    const DomainPoint& p = points[f.point];
    double x1, x2, t1, t2;
    R.vec(p.x - tip.x, p.y - tip.y, x1, x2);
    const double r = std::fabs(x1), lo = std::max(r - 0.5 * f.length, 0.0), hi = r + 0.5 * f.length;
    if (lo >= domain.outer) continue;
    R.vec(f.tx, f.ty, t1, t2);
    double u11, u12, u21, u22, d1, d2;
    R.ten(p.ux_x, p.ux_y, p.uy_x, p.uy_y, u11, u12, u21, u22);
    // J: by parts along the face (j_integral.hpp), with the face's displacement relative to the
    // tip's: the point's, carried across the half cell to the line by its gradient (in a uniform
    // strain the faces' own displacement does not change along them, and releases nothing).
    R.vec(p.ux - tip.ux, p.uy - tip.uy, d1, d2);
    d1 -= x2 * u12, d2 -= x2 * u22;
    const double td = t1 * d1 + t2 * d2;
    const double tg = t1 * u11 + t2 * u21;  // t_i u_i,1: to carry the displacement to an end
    double dq1 = 0.0;  // q_,1 on the face (x1 = -r): -dq/dr
    if (r > domain.inner && r < domain.outer) {
      const double xi = (r - domain.inner) / width;
      dq1 = 6.0 * xi * (1.0 - xi) / width;
    }
    J += td * dq1 * f.length;
    // Where the loaded segment ends behind the tip (not at it: there the face's displacement is
    // the tip's, and the term is nothing), the end term, with the displacement of the share
    // nearest that end on this side of the line. (A distributed run whose rank border cuts the
    // face right there gives it to the nearest share on each rank.)
    const double ends[2][2] = {{f.from_x, f.from_y}, {f.to_x, f.to_y}};
    for (int e = 0; e < 2 && std::isfinite(f.from_x); ++e) {
      double e1, e2, o1, o2;
      R.vec(ends[e][0] - tip.x, ends[e][1] - tip.y, e1, e2);
      R.vec(ends[1 - e][0] - tip.x, ends[1 - e][1] - tip.y, o1, o2);
      const double re = -e1;  // how far behind the tip the end lies
      if (re <= 0.0 || re >= domain.outer || !nearest_to_end(faces, points, R, tip, f, x2, re, r)) continue;
      // +: the far end (the other nearer the tip); the share's displacement carried to the end
      J += (-o1 < re ? 1.0 : -1.0) * (td - tg * (re - r)) * weight(re);
    }
    // M: the auxiliary gradient is exact; near the tip it goes as c r^-1/2 along a face, so it
    // is integrated as that over the point's share (r from r - l/2 to r + l/2, cut at the tip),
    // where a midpoint value would leave an O(sqrt h) error (tests/test_j_integral.cpp). On the
    // face, on the point's own side (the auxiliary field jumps across the line).
    const double q = weight(r);
    const double share = 2.0 * (std::sqrt(hi) - std::sqrt(lo)) * std::sqrt(r);  // = l far away
    NearTipField a[2];
    face_fields(x1, std::copysign(1e-12 * std::fabs(x1), x2), m, v, a);
    for (int k = 0; k < 2; ++k) M[k] -= share * (t1 * a[k].u1_1 + t2 * a[k].u2_1) * q;
  }
  // Faces in contact: the traction t on the upper face, -t on the lower (j_integral.hpp).
  for (const FaceContact& c : contacts) {
    double x1, x2, t1, t2, n1, n2, d1, d2;
    R.vec(c.x - tip.x, c.y - tip.y, x1, x2);
    const double r = std::fabs(x1);
    if (x1 >= 0.0 || r - 0.5 * c.length >= domain.outer) continue;
    const double lo = std::max(r - 0.5 * c.length, 0.0), hi = r + 0.5 * c.length;
    R.vec(c.tx, c.ty, t1, t2);
    R.vec(c.nx, c.ny, n1, n2);
    // J: t_i [[u_i]],1 with d/dx1 = (tau . e1) d/ds along the face (a face along the crack: +/- d/ds).
    double tau1, tau2;
    R.vec(c.tx_s, c.ty_s, tau1, tau2);
    R.vec(c.jx_s, c.jy_s, d1, d2);
    const double q = weight(r);
    J -= (t1 * d1 + t2 * d2) * tau1 * q * c.length;
    // M: each face's auxiliary gradient, the upper face on the side its normal points to; the
    // shear part of the traction only (j_integral.hpp). Frictionless faces add nothing.
    if (c.sx == 0.0 && c.sy == 0.0) continue;
    R.vec(c.sx, c.sy, t1, t2);
    const double share = 2.0 * (std::sqrt(hi) - std::sqrt(lo)) * std::sqrt(r);
    const double up = n2 >= 0.0 ? 1.0 : -1.0;
    for (const double side : {up, -up}) {
      const double sign = side == up ? 1.0 : -1.0;  // the traction on that face's material
      NearTipField a[2];
      face_fields(x1, side * 1e-12 * r, m, v, a);
      for (int k = 0; k < 2; ++k) M[k] -= sign * share * (t1 * a[k].u1_1 + t2 * a[k].u2_1) * q;
    }
  }
  out.J = J;
  if (v == 0.0) {
    out.K_I = 0.5 * m.e_prime * M[0];
    out.K_II = 0.5 * m.e_prime * M[1];
    return out;
  }
  // J(K + K^a) - J(K) - J(K^a) = 2 A K K^a / E' per mode, E' / 2 = 2 mu (1 - c_s^2/c_d^2) (theory.md
  // (18.2)), so K = 2 mu (1 - c_s^2/c_d^2) M / A = mu c_s^2 D M / (v^2 a_d,s).
  const RunningTipFactors A = running_tip_factors(v, WaveSpeeds{m.c_d, m.c_s, 0.0, 0.0});
  const double half_e_prime = 2.0 * m.mu * (1.0 - m.c_s * m.c_s / (m.c_d * m.c_d));
  out.K_I = half_e_prime * M[0] / A.A_I;
  out.K_II = half_e_prime * M[1] / A.A_II;
  return out;
}

}  // namespace

std::vector<TipIntegrals> tip_integrals(const std::vector<DomainPoint>& points, const TipFrame& tip,
                                        const std::vector<JDomain>& domains, const TipMaterial& m,
                                        const std::vector<FaceTraction>& faces,
                                        const std::vector<FaceContact>& contacts) {
  const double norm = std::hypot(tip.e1x, tip.e1y);
  const Rotation R{tip.e1x / norm, tip.e1y / norm};
  double reach = 0.0;
  for (const JDomain& d : domains) reach = std::max(reach, d.outer);
  std::vector<std::size_t> inside;
  for (std::size_t i = 0; i < points.size(); ++i) {
    double x1, x2;
    R.vec(points[i].x - tip.x, points[i].y - tip.y, x1, x2);
    if (x1 * x1 + x2 * x2 < reach * reach) inside.push_back(i);
  }
  // The points' terms side by side (each its own; the sums below stay in one order, so the
  // result does not depend on the threads). A caller already inside a parallel region (several
  // tips read side by side) runs this on its own thread.
  thread_local std::vector<PointTerms> kept;  // its capacity is reused call after call
  std::vector<PointTerms>& terms = kept;       // this thread's, shared with the loop's threads
  terms.resize(inside.size());
  const long n = long(inside.size());
#pragma omp parallel for schedule(static) if (n > 256)
  for (long i = 0; i < n; ++i) terms[std::size_t(i)] = point_terms(points[inside[std::size_t(i)]], R, tip, m);
  std::vector<TipIntegrals> out;
  for (const JDomain& d : domains) out.push_back(integrate(terms, points, R, tip, d, m, faces, contacts));
  return out;
}

TipIntegrals tip_integrals(const std::vector<DomainPoint>& points, const TipFrame& tip,
                           const JDomain& domain, const TipMaterial& m,
                           const std::vector<FaceTraction>& faces,
                           const std::vector<FaceContact>& contacts) {
  return tip_integrals(points, tip, std::vector<JDomain>{domain}, m, faces, contacts).front();
}

double hoop_stress_angle(double K_I, double K_II) {
  if (K_II == 0.0) return 0.0;
  return 2.0 * std::atan((K_I - std::sqrt(K_I * K_I + 8.0 * K_II * K_II)) / (4.0 * K_II));
}

}  // namespace rupture
