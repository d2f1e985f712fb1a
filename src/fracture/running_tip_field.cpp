// rupture/fracture/running_tip_field.cpp
#include "fracture/running_tip_field.hpp"

#include <cmath>
#include <complex>
#include <numbers>

namespace rupture {

namespace {

struct Speeds {
  double ad, as, D;
};

Speeds speeds_at(double v, const WaveSpeeds& w) {
  Speeds s;
  s.ad = std::sqrt(1.0 - v * v / (w.dilatational * w.dilatational));
  s.as = std::sqrt(1.0 - v * v / (w.shear * w.shear));
  s.D = 4.0 * s.ad * s.as - (1.0 + s.as * s.as) * (1.0 + s.as * s.as);
  return s;
}

}  // namespace

void running_tip_fields(double x1, double x2, double v, double mu, const WaveSpeeds& w,
                        RunningTipField& opening, RunningTipField& sliding) {
  using cd = std::complex<double>;
  const Speeds sp = speeds_at(v, w);
  const double ad = sp.ad, as = sp.as, bs = 1.0 + as * as;
  const double C = 1.0 / (std::sqrt(2.0 * std::numbers::pi) * mu * sp.D);
  // sqrt z, P = z^-1/2 (d sqrt z / dx1 = P / 2, d / dx2 = i a P / 2) and Q = z^-3/2
  // (dP / dx1 = -Q / 2). The principal root's cut is the crack: x2 = +-0 behind the tip.
  const cd zd(x1, ad * x2), zs(x1, as * x2);
  const cd rd = std::sqrt(zd), rs = std::sqrt(zs);
  const cd Pd = 1.0 / rd, Ps = 1.0 / rs, Qd = Pd / zd, Qs = Ps / zs;
  const double L = w.dilatational * w.dilatational / (w.shear * w.shear) - 2.0;  // lambda / mu
  const auto hooke = [&](NearTipField& f) {
    const double div = f.u1_1 + f.u2_2;
    f.s11 = mu * (L * div + 2.0 * f.u1_1);
    f.s22 = mu * (L * div + 2.0 * f.u2_2);
    f.s12 = mu * (f.u1_2 + f.u2_1);
  };
  {  // mode I
    const cd A = bs * rd - 2.0 * ad * as * rs, B = -ad * bs * rd + 2.0 * ad * rs;  // u1 ~ Re A, u2 ~ Im B
    const cd A1 = bs * Pd - 2.0 * ad * as * Ps, B1 = -ad * bs * Pd + 2.0 * ad * Ps;  // their d/dx1 (x2)
    const cd A2 = ad * bs * Pd - 2.0 * ad * as * as * Ps, B2 = -ad * ad * bs * Pd + 2.0 * ad * as * Ps;  // d/dx2 / i
    const cd A11 = bs * Qd - 2.0 * ad * as * Qs, B11 = -ad * bs * Qd + 2.0 * ad * Qs;
    NearTipField& f = opening.f;
    f.u1 = 2.0 * C * A.real(), f.u2 = 2.0 * C * B.imag();
    f.u1_1 = C * A1.real(), f.u2_1 = C * B1.imag();
    f.u1_2 = -C * A2.imag(), f.u2_2 = C * B2.real();  // Re(i w) = -Im w, Im(i w) = Re w
    opening.u1_11 = -0.5 * C * A11.real(), opening.u2_11 = -0.5 * C * B11.imag();
    hooke(f);
  }
  {  // mode II
    const cd A = 2.0 * as * rd - as * bs * rs, B = 2.0 * ad * as * rd - bs * rs;  // u1 ~ Im A, u2 ~ Re B
    const cd A1 = 2.0 * as * Pd - as * bs * Ps, B1 = 2.0 * ad * as * Pd - bs * Ps;
    const cd A2 = 2.0 * ad * as * Pd - as * as * bs * Ps, B2 = 2.0 * ad * ad * as * Pd - as * bs * Ps;
    const cd A11 = 2.0 * as * Qd - as * bs * Qs, B11 = 2.0 * ad * as * Qd - bs * Qs;
    NearTipField& f = sliding.f;
    f.u1 = 2.0 * C * A.imag(), f.u2 = 2.0 * C * B.real();
    f.u1_1 = C * A1.imag(), f.u2_1 = C * B1.real();
    f.u1_2 = C * A2.real(), f.u2_2 = -C * B2.imag();
    sliding.u1_11 = -0.5 * C * A11.imag(), sliding.u2_11 = -0.5 * C * B11.real();
    hooke(f);
  }
}

RunningTipFactors running_tip_factors(double v, const WaveSpeeds& w) {
  RunningTipFactors a;
  if (v < kRunningTipSpeed * w.shear) return a;
  const Speeds sp = speeds_at(v, w);
  const double cs2 = w.shear * w.shear;
  const double scale = 2.0 * (1.0 - cs2 / (w.dilatational * w.dilatational)) * v * v / (cs2 * sp.D);
  a.A_I = scale * sp.ad, a.A_II = scale * sp.as;
  return a;
}

}  // namespace rupture
