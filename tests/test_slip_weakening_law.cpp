// The slip-weakening friction law at one Gauss point (cohesive/slip_weakening.hpp): the
// traction-offset form, stick below the strength, sliding on the weakening curve, opening.
#include <gtest/gtest.h>

#include "cohesive/law.hpp"

using namespace rupture;

namespace {
SlipWeakening fault() {
  SlipWeakening f;
  f.static_friction = 0.6, f.dynamic_friction = 0.4, f.dc = 0.5, f.cohesion = 1e6;
  f.normal_stiffness = 2e10, f.stick_stiffness = 1e10;
  f.tn0 = -100e6, f.tt0 = 50e6;  // strength 61 MPa static, 41 MPa dynamic
  return f;
}
// Drives a point along tangential jumps dts (normal jump dn), as the interface loop does
// (jump_t = the previous call's dt); returns the last response.
LawResponse drive(const SlipWeakening& f, GaussHistory& h, std::initializer_list<double> dts,
                  double dn = 0.0) {
  LawResponse r{};
  for (double dt : dts) {
    r = f.respond(dn, dt, h);
    h.jump_t = dt;
  }
  return r;
}
}  // namespace

TEST(SlipWeakeningLaw, prestress_below_strength_loads_nothing_at_rest) {
  const SlipWeakening f = fault();
  EXPECT_EQ(f.validate(), "");
  EXPECT_DOUBLE_EQ(f.static_strength(), 61e6);
  EXPECT_DOUBLE_EQ(f.dynamic_strength(), 41e6);
  GaussHistory h;
  const LawResponse r = f.respond(0.0, 0.0, h);
  EXPECT_EQ(r.tn, 0.0);
  EXPECT_EQ(r.tt, 0.0);
  EXPECT_EQ(r.stiffness, 2e10);  // max(kn, kt)
  EXPECT_EQ(h.damage, 0.0);
}

TEST(SlipWeakeningLaw, sticks_elastically_then_slides_on_the_weakening_curve) {
  const SlipWeakening f = fault();
  GaussHistory h;
  // Stuck: the stick spring adds kt dt to the 50 MPa prestress, up to the 61 MPa strength.
  LawResponse r = drive(f, h, {0.5e-3});
  EXPECT_NEAR(f.total_shear(r), 55e6, 1e-3);
  EXPECT_EQ(h.damage, 0.0);
  // Past it: the traction is the strength at the slip path walked while sliding.
  r = drive(f, h, {1.2e-3, 0.1012});  // 1.1e-3 stuck reaches 61 MPa; then a path of 0.1 m
  EXPECT_GT(h.damage, 0.09);
  EXPECT_NEAR(f.total_shear(r), f.strength(-100e6, h.damage), 1e-6);
  EXPECT_NEAR(f.total_shear(r), 61e6 - 20e6 * h.damage / 0.5, 1e-6);
  // Beyond Dc: the dynamic level, and the path keeps growing.
  r = drive(f, h, {0.3, 0.6, 0.9});
  EXPECT_NEAR(f.total_shear(r), 41e6, 1e-6);
  EXPECT_GT(h.damage, 0.5);
  // Reversal: the slip stops (stuck at the plastic slip reached), the path stays.
  const double path = h.damage;
  r = drive(f, h, {0.9 - 1e-4});
  EXPECT_NEAR(f.total_shear(r), 41e6 - 1e10 * 1e-4, 1e-3);
  EXPECT_EQ(h.damage, path);
  // Negative shear: the strength bounds |T| on both sides.
  r = drive(f, h, {0.0, -0.5});
  EXPECT_NEAR(f.total_shear(r), -41e6, 1e-6);
}

TEST(SlipWeakeningLaw, compression_resists_interpenetration_and_tension_opens) {
  const SlipWeakening f = fault();
  GaussHistory h;
  // Pressed: the normal penalty, and a higher strength.
  LawResponse r = f.respond(-1e-3, 0.0, h);
  EXPECT_NEAR(f.total_normal(r), -120e6, 1e-3);
  // Pulled past the prestress (tn0 + kn dn > 0): both faces free, dT = -T0.
  r = f.respond(6e-3, 0.0, h);
  EXPECT_EQ(f.total_normal(r), 0.0);
  EXPECT_EQ(f.total_shear(r), 0.0);
  EXPECT_EQ(f.stored_energy(6e-3, 0.0, h), 0.0);
}

TEST(SlipWeakeningLaw, parameters_out_of_range_are_named) {
  SlipWeakening f = fault();
  f.dynamic_friction = 0.7;
  EXPECT_NE(f.validate().find("dynamic_friction = 0.7"), std::string::npos) << f.validate();
  f = fault();
  f.dc = 0.0;
  EXPECT_NE(f.validate().find("dc = 0"), std::string::npos) << f.validate();
}
