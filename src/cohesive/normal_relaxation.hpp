// rupture/cohesive/normal_relaxation.hpp
// The normal stress friction sees, regularized after Prakash & Clifton (1993): on a fault
// between different materials slip changes the normal stress, and Coulomb friction that
// follows it at once is ill-posed (Renardy 1992; Adams 1995; Ranjith & Rice 2001: steady
// sliding is unstable at every wavelength, the shortest growing fastest, so a numerical
// solution does not converge with the grid). Friction then sees sigma*, which relaxes
// towards the actual compression sigma = max(0, -Tn) over a time or a slip scale:
//   time form:  d sigma*/dt = -(sigma* - sigma) / T                  (Ranjith & Rice 2001)
//   slip form:  d sigma*/dt = -(|V| + V*) / L (sigma* - sigma)       (Prakash & Clifton 1993;
//               Cochard & Rice 2000; Rubin & Ampuero 2007)
// Over a step of duration dt in which the tangential jump moved by ds, with sigma held at
// its end-of-step value (an exponential integrator: exact for a constant sigma and constant
// slip rate, stable for any step, first order in dt where sigma varies within the step):
//   sigma*_new = sigma + (sigma*_old - sigma) exp(-x),  x = dt / T  or  (|ds| + V* dt) / L.
// The slip form's |ds| is the jump's tangential increment, the slip path while sliding (the
// stick spring's elastic change while stuck, a small fraction of a cell's strain).
// Scala, Festa & Vilotte (2017, GJI 209) show that the slip form gives solutions that do not
// depend on L below a characteristic length, the time form not. docs/faults.md, "Normal-
// stress regularization". Units: Pa, s, m, m/s.
#pragma once
#include <cmath>
#include <cstdint>
#include <string>

#include "cohesive/law_types.hpp"

namespace rupture {

enum class RelaxationForm : std::uint8_t { none, time, slip };

struct NormalRelaxation {
  RelaxationForm form = RelaxationForm::none;
  double time = 0.0;  // s, T (time form)
  double slip = 0.0;  // m, L (slip form)
  double rate = 0.0;  // m/s, V* >= 0 (slip form)

  bool on() const { return form != RelaxationForm::none; }

  // "" when the parameters of the form lie in their ranges, else "key = value: rule" naming
  // the input key (normal_relaxation_*; cohesive/normal_relaxation.cpp).
  std::string validate() const;
  // `rupture check`'s words: "" when off, else ", normal stress seen relaxed over ...".
  std::string describe() const;

  // The normal stress friction sees at the end of a step (Pa, compression positive), given
  // the actual compression sigma there, the initial one sigma0 (h.normal_seen = sigma* -
  // sigma0; 0 = pristine: sigma* starts at sigma0), the jump's tangential increment ds (m)
  // and the step's duration (s). Updates h.normal_seen. Without a form: sigma itself.
  double seen(double sigma, double sigma0, double ds, double duration, GaussHistory& h) const {
    if (form == RelaxationForm::none) return sigma;
    const double x = form == RelaxationForm::time ? duration / time
                                                  : (std::fabs(ds) + rate * duration) / slip;
    const double s = sigma + (sigma0 + h.normal_seen - sigma) * std::exp(-x);
    h.normal_seen = s - sigma0;
    return s;
  }
};

}  // namespace rupture
