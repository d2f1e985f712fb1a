// Tests of the [interface.*] tables (input/parse_interfaces.cpp, input/parse_fault.cpp for law =
// "slip_weakening"): each law's keys reach the right fields of InterfaceSpec and of the law
// (values in SI units as docs/input.md lists them: Pa, m, Pa/m, m/s; nothing converted),
// the documented defaults are applied (tau_max = sigma_max, delta_t from q, delta_tc =
// delta_nc, lambda0, penalty, separation, the contact stiffness from the law's penalty, the
// fault's stiffnesses M / h), and every bad table stops with a message naming the key, the
// value given and what is allowed: unknown law, missing required keys, sigma_max <= 0,
// start >= end, an unknown body, an unknown key, a key of another law, and the other ranges.
// Why: a key read into the wrong field or a default that differs from the documentation runs
// silently with another interface than the one asked for.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "support.hpp"

using namespace rupture;

namespace {

using test::case_with;

using test::kGeometry;

InterfaceSpec parse_one(const std::string& lines) {
  const Case c = parse_case(case_with(lines));
  EXPECT_EQ(c.interfaces.size(), 1u);
  EXPECT_EQ(c.interface_names.at(0), "w");
  return c.interfaces.at(0);
}

std::string error_of(const std::string& lines) {
  try {
    parse_case(case_with(lines));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

using test::replace;

const double kE = std::exp(1.0);

}  // namespace

TEST(ParseInterfaces, geometry_and_bodies_reach_the_spec) {
  const InterfaceSpec is = parse_one(kGeometry + "sigma_max = 24e6\ndelta_n = 0.4e-6");
  EXPECT_EQ(is.upper_body, 0);  // bodies in input order
  EXPECT_EQ(is.lower_body, 1);
  EXPECT_EQ(is.upper_field, 0);
  EXPECT_EQ(is.lower_field, 1);
  EXPECT_EQ(is.y, 0.0);
  EXPECT_EQ(is.start, 0.002);
  EXPECT_EQ(is.end, 0.006);
  EXPECT_EQ(is.segments, 3);
  EXPECT_TRUE(is.line.x.empty());  // the horizontal form
  EXPECT_FALSE(is.bonded);
  EXPECT_FALSE(is.precracked);
  EXPECT_FALSE(is.contact);
  EXPECT_TRUE(is.stretches.empty());
  // bonded_to: the halves tied from end to there.
  const InterfaceSpec tied = parse_one(kGeometry + "bonded_to = 0.008\nsigma_max = 24e6\ndelta_n = 0.4e-6");
  EXPECT_TRUE(tied.bonded);
  EXPECT_EQ(tied.bonded_from, 0.006);
  EXPECT_EQ(tied.bonded_to, 0.008);
}

TEST(ParseInterfaces, xu_needleman_keys_reach_their_fields) {
  const InterfaceSpec is = parse_one(kGeometry +
                                     "law = \"xu_needleman\"\nsigma_max = 30e6\ntau_max = 20e6\ndelta_n = 0.5e-6\n"
                                     "delta_t = 1.2e-6\nq = 0.8\nr = 0.3\npenalty = 2.5\nseparation = 7.0\n"
                                     "rupture_slip_rate = 2e-3");
  ASSERT_TRUE(std::holds_alternative<XuNeedleman>(is.law));
  const XuNeedleman& law = std::get<XuNeedleman>(is.law);
  EXPECT_EQ(law.sigma_max, 30e6);  // Pa
  EXPECT_EQ(law.tau_max, 20e6);    // Pa
  EXPECT_EQ(law.delta_n, 0.5e-6);  // m
  EXPECT_EQ(law.delta_t, 1.2e-6);  // m: given, not derived from q
  EXPECT_EQ(law.q, 0.8);
  EXPECT_EQ(law.r, 0.3);
  EXPECT_EQ(law.penalty, 2.5);
  EXPECT_EQ(is.separation_factor, 7.0);
  EXPECT_EQ(is.rupture_slip_rate, 2e-3);  // m/s
  EXPECT_FALSE(is.contact);
}

TEST(ParseInterfaces, xu_needleman_defaults) {
  // law defaults to xu_needleman; tau_max to sigma_max; q = 1, r = 0, penalty = 1,
  // separation = 5, rupture_slip_rate = 1e-3 m/s; delta_t = q e sigma_max delta_n /
  // (sqrt(e/2) tau_max), which is sqrt(2 e) delta_n when tau_max = sigma_max and q = 1.
  const InterfaceSpec is = parse_one(kGeometry + "sigma_max = 24e6\ndelta_n = 0.4e-6");
  ASSERT_TRUE(std::holds_alternative<XuNeedleman>(is.law));
  const XuNeedleman& law = std::get<XuNeedleman>(is.law);
  EXPECT_EQ(law.tau_max, 24e6);
  EXPECT_EQ(law.q, 1.0);
  EXPECT_EQ(law.r, 0.0);
  EXPECT_EQ(law.penalty, 1.0);
  EXPECT_EQ(is.separation_factor, 5.0);
  EXPECT_EQ(is.rupture_slip_rate, 1e-3);
  EXPECT_NEAR(law.delta_t, std::sqrt(2.0 * kE) * 0.4e-6, 1e-15 * 0.4e-6);
  EXPECT_FALSE(is.contact);
  EXPECT_FALSE(is.precracked);
  // With q and tau_max given, delta_t follows both.
  const XuNeedleman other =
      std::get<XuNeedleman>(parse_one(kGeometry + "sigma_max = 24e6\ntau_max = 12e6\ndelta_n = 0.4e-6\nq = 0.5").law);
  EXPECT_NEAR(other.delta_t, 0.5 * kE * 24e6 * 0.4e-6 / (std::sqrt(kE / 2.0) * 12e6), 1e-15 * other.delta_t);
  EXPECT_NEAR(other.phi_t() / other.phi_n(), 0.5, 1e-14);  // q = phi_t / phi_n, as documented
}

TEST(ParseInterfaces, bilinear_keys_and_defaults) {
  const InterfaceSpec is = parse_one(kGeometry +
                                     "law = \"bilinear\"\nsigma_max = 30e6\ntau_max = 20e6\ndelta_nc = 2e-6\n"
                                     "delta_tc = 3e-6\nlambda0 = 0.05\npenalty = 4.0");
  ASSERT_TRUE(std::holds_alternative<BilinearLaw>(is.law));
  const BilinearLaw& law = std::get<BilinearLaw>(is.law);
  EXPECT_EQ(law.sigma_max, 30e6);
  EXPECT_EQ(law.tau_max, 20e6);
  EXPECT_EQ(law.delta_nc, 2e-6);
  EXPECT_EQ(law.delta_tc, 3e-6);
  EXPECT_EQ(law.lambda0, 0.05);
  EXPECT_EQ(law.penalty, 4.0);
  // Defaults: tau_max = sigma_max, delta_tc = delta_nc, lambda0 = 0.01, penalty = 1.
  const BilinearLaw d =
      std::get<BilinearLaw>(parse_one(kGeometry + "law = \"bilinear\"\nsigma_max = 30e6\ndelta_nc = 2e-6").law);
  EXPECT_EQ(d.tau_max, 30e6);
  EXPECT_EQ(d.delta_tc, 2e-6);
  EXPECT_EQ(d.lambda0, 0.01);
  EXPECT_EQ(d.penalty, 1.0);
}

TEST(ParseInterfaces, contact_keys_and_defaults) {
  // Contact after separation on a cohesive law: its stiffness defaults to the law's penalty
  // stiffness (Xu-Needleman: penalty phi_n / delta_n^2 = penalty e sigma_max / delta_n).
  const InterfaceSpec xn = parse_one(kGeometry + "sigma_max = 24e6\ndelta_n = 0.4e-6\npenalty = 2.0\ncontact = true");
  EXPECT_TRUE(xn.contact);
  EXPECT_FALSE(xn.precracked);
  EXPECT_NEAR(xn.contact_law.stiffness, 2.0 * kE * 24e6 / 0.4e-6, 1e-14 * xn.contact_law.stiffness);
  EXPECT_EQ(xn.contact_law.friction, 0.0);
  EXPECT_EQ(xn.contact_law.tangential_stiffness, 0.0);
  // Bilinear: penalty sigma_max / (lambda0 delta_nc).
  const InterfaceSpec bl = parse_one(kGeometry + "law = \"bilinear\"\nsigma_max = 30e6\ndelta_nc = 2e-6\n"
                                                 "lambda0 = 0.1\ncontact = true\nfriction = 0.3");
  EXPECT_NEAR(bl.contact_law.stiffness, 30e6 / (0.1 * 2e-6), 1e-14 * bl.contact_law.stiffness);
  EXPECT_EQ(bl.contact_law.friction, 0.3);
  // law = "contact": a pre-crack, contact on, its keys as given.
  const InterfaceSpec pc = parse_one(kGeometry + "law = \"contact\"\ncontact_stiffness = 1e15\nfriction = 0.4\n"
                                                 "contact_tangential_stiffness = 2e14");
  EXPECT_TRUE(pc.precracked);
  EXPECT_TRUE(pc.contact);
  EXPECT_EQ(pc.contact_law.stiffness, 1e15);  // Pa/m
  EXPECT_EQ(pc.contact_law.friction, 0.4);
  EXPECT_EQ(pc.contact_law.tangential_stiffness, 2e14);
  // law = "contact" without contact_stiffness: one cell of the stiffer body, M / h (as a fault's
  // penalties; M = lambda + 2 mu, plane strain), so the penetration under a pressure p is
  // p h / M, the compression of one cell.
  const InterfaceSpec pd = parse_one(kGeometry + "law = \"contact\"");
  const double E = 5.2e9, nu = 0.34;
  const double M = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  EXPECT_TRUE(pd.precracked && pd.contact);
  EXPECT_NEAR(pd.contact_law.stiffness, M / 1e-3, 1e-12 * M / 1e-3);
}

TEST(ParseInterfaces, slip_weakening_keys_and_defaults) {
  const InterfaceSpec is = parse_one(kGeometry +
                                     "law = \"slip_weakening\"\nstatic_friction = 0.677\ndynamic_friction = 0.525\n"
                                     "dc = 0.4e-6\ncohesion = 1e5\ninitial_traction = [-2e6, 1e6]\n"
                                     "normal_stiffness = 3e15\nstick_stiffness = 4e15\nrupture_slip_rate = 5e-3");
  ASSERT_TRUE(std::holds_alternative<SlipWeakening>(is.law));
  const SlipWeakening& law = std::get<SlipWeakening>(is.law);
  EXPECT_EQ(law.static_friction, 0.677);
  EXPECT_EQ(law.dynamic_friction, 0.525);
  EXPECT_EQ(law.dc, 0.4e-6);               // m
  EXPECT_EQ(law.cohesion, 1e5);            // Pa
  EXPECT_EQ(law.tn0, -2e6);                // Pa, [normal, shear]
  EXPECT_EQ(law.tt0, 1e6);
  EXPECT_EQ(law.normal_stiffness, 3e15);   // Pa/m
  EXPECT_EQ(law.stick_stiffness, 4e15);
  EXPECT_EQ(is.rupture_slip_rate, 5e-3);
  // Defaults: cohesion 0, initial traction [0, 0], both stiffnesses M / h with M = lambda + 2 mu
  // (plane strain) of the stiffer body and h the cell size.
  const SlipWeakening d = std::get<SlipWeakening>(
      parse_one(kGeometry + "law = \"slip_weakening\"\nstatic_friction = 0.6\ndynamic_friction = 0.5\ndc = 1e-6").law);
  const double E = 5.2e9, nu = 0.34;
  const double M = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  EXPECT_EQ(d.cohesion, 0.0);
  EXPECT_EQ(d.tn0, 0.0);
  EXPECT_EQ(d.tt0, 0.0);
  EXPECT_NEAR(d.normal_stiffness, M / 1e-3, 1e-12 * M / 1e-3);
  EXPECT_NEAR(d.stick_stiffness, M / 1e-3, 1e-12 * M / 1e-3);
}

TEST(ParseInterfaces, every_bad_table_names_the_key_the_value_and_what_is_allowed) {
  const std::string xn = kGeometry + "sigma_max = 24e6\ndelta_n = 0.4e-6\n";
  const std::string bl = kGeometry + "law = \"bilinear\"\nsigma_max = 24e6\ndelta_nc = 2e-6\n";
  const std::string sw = kGeometry + "law = \"slip_weakening\"\nstatic_friction = 0.6\ndynamic_friction = 0.5\ndc = 1e-6\n";
  struct Bad {
    const char* name;
    std::string lines;
    std::vector<std::string> expect;
  };
  const std::vector<Bad> cases = {
      {"unknown law", xn + "law = \"cohesive\"",
       {"'interface.w.law' = \"cohesive\"", "must be one of", "\"xu_needleman\"", "\"bilinear\"", "\"contact\"",
        "\"slip_weakening\""}},
      {"law not a string", xn + "law = 3", {"'interface.w.law' = 3", "must be a string"}},
      {"missing sigma_max (xu_needleman)", replace(xn, "sigma_max = 24e6\n", ""),
       {"'interface.w.sigma_max' = (missing)", "required, a number"}},
      {"missing delta_n", replace(xn, "delta_n = 0.4e-6\n", ""), {"'interface.w.delta_n' = (missing)", "required"}},
      {"missing sigma_max (bilinear)", replace(bl, "sigma_max = 24e6\n", ""),
       {"'interface.w.sigma_max' = (missing)", "required"}},
      {"missing delta_nc", replace(bl, "delta_nc = 2e-6\n", ""), {"'interface.w.delta_nc' = (missing)", "required"}},
      {"missing static_friction", replace(sw, "static_friction = 0.6\n", ""),
       {"'interface.w.static_friction' = (missing)", "required with law = \"slip_weakening\""}},
      {"missing dc", replace(sw, "dc = 1e-6\n", ""), {"'interface.w.dc' = (missing)", "required"}},
      {"missing segments", replace(xn, "segments = 3\n", ""), {"'interface.w.segments'", "required, an integer in [1, 1e8]"}},
      {"missing upper_body", replace(xn, "upper_body = \"upper\"\n", ""),
       {"'interface.w.upper_body' = (missing)", "required: upper_body and lower_body"}},
      {"missing end", replace(xn, "end = 0.006\n", ""), {"'interface.w.end' = (missing)", "required"}},
      {"negative sigma_max (xu_needleman)", replace(xn, "sigma_max = 24e6", "sigma_max = -24e6"),
       {"'interface.w.sigma_max' = -2.4e+07", "must be > 0 (Pa)"}},
      {"zero sigma_max (xu_needleman)", replace(xn, "sigma_max = 24e6", "sigma_max = 0.0"),
       {"'interface.w.sigma_max' = 0:", "must be > 0 (Pa)"}},
      {"negative sigma_max (bilinear)", replace(bl, "sigma_max = 24e6", "sigma_max = -24e6"),
       {"'interface.w.sigma_max' = -2.4e+07", "must be > 0"}},
      {"zero sigma_max (bilinear)", replace(bl, "sigma_max = 24e6", "sigma_max = 0"),
       {"'interface.w.sigma_max' = 0:", "must be > 0"}},
      {"negative tau_max", xn + "tau_max = -1e6", {"'interface.w.tau_max' = -1e+06", "must be > 0 (Pa)"}},
      {"zero delta_n", replace(xn, "delta_n = 0.4e-6", "delta_n = 0.0"), {"'interface.w.delta_n' = 0:", "> 0 (m)"}},
      {"zero delta_t", xn + "delta_t = 0.0", {"'interface.w.delta_t' = 0:", "> 0 (m)"}},
      {"zero q", xn + "q = 0.0", {"'interface.w.q' = 0:", "must be > 0"}},
      {"r = 1", xn + "r = 1.0", {"'interface.w.r' = 1:", ">= 0 and differ from 1"}},
      {"negative r", xn + "r = -0.5", {"'interface.w.r' = -0.5", ">= 0 and differ from 1"}},
      {"negative penalty", xn + "penalty = -1.0", {"'interface.w.penalty' = -1", ">= 0"}},
      {"zero separation", xn + "separation = 0.0", {"'interface.w.separation' = 0:", "(0, 1000]"}},
      {"lambda0 = 1", bl + "lambda0 = 1.0", {"'interface.w.lambda0' = 1:", "(0, 1)"}},
      {"negative delta_tc", bl + "delta_tc = -2e-6", {"'interface.w.delta_tc' = -2e-06", "> 0"}},
      {"zero rupture_slip_rate", xn + "rupture_slip_rate = 0.0", {"'interface.w.rupture_slip_rate' = 0:", "> 0 (m/s)"}},
      {"sigma_max not a number", replace(xn, "sigma_max = 24e6", "sigma_max = \"24 MPa\""),
       {"'interface.w.sigma_max' = \"24 MPa\"", "must be a number"}},
      {"start > end", replace(replace(xn, "start = 0.002", "start = 0.006"), "end = 0.006", "end = 0.002"),
       {"'interface.w.end' = 0.002", "must lie in (0.006, 0.008] m"}},
      {"start = end", replace(xn, "end = 0.006", "end = 0.002"), {"'interface.w.end' = 0.002", "must lie in (0.002, 0.008] m"}},
      {"start outside the bodies", replace(xn, "start = 0.002", "start = -0.001"),
       {"'interface.w.start' = -0.001", "must lie where both bodies meet: [0, 0.008] m"}},
      {"end past the bodies", replace(xn, "end = 0.006", "end = 0.009"), {"'interface.w.end' = 0.009", "(0.002, 0.008] m"}},
      {"y off the bodies' boundary", replace(xn, "y = 0.0", "y = 0.001"),
       {"'interface.w.y' = 0.001", "must be the bottom of the upper body (0) and the top of the lower body (0)"}},
      {"zero segments", replace(xn, "segments = 3", "segments = 0"), {"'interface.w.segments' = 0:", "[1, 1e8]"}},
      {"unknown body (near miss)", replace(xn, "upper_body = \"upper\"", "upper_body = \"uper\""),
       {"'interface.w.upper_body' = \"uper\"", "must name a body among", "upper", "lower", "did you mean \"upper\"?"}},
      {"unknown body", replace(xn, "lower_body = \"lower\"", "lower_body = \"granite\""),
       {"'interface.w.lower_body' = \"granite\"", "must name a body among", "upper", "lower"}},
      {"the same body twice", replace(xn, "lower_body = \"lower\"", "lower_body = \"upper\""),
       {"'interface.w.lower_body' = \"upper\"", "must differ from upper_body"}},
      {"unknown key", xn + "strength = 1.0", {"'interface.w.strength' = 1", "unknown key", "allowed here:", "sigma_max"}},
      {"unknown key (typo)", xn + "sigma_mx = 1.0",
       {"'interface.w.sigma_mx' = 1", "unknown key", "did you mean 'interface.w.sigma_max'?"}},
      // (A key of another law is shown as TOML prints it, at full precision: values exact in
      // binary here.)
      {"a bilinear key with xu_needleman", xn + "delta_nc = 0.5",
       {"'interface.w.delta_nc' = 0.5", "not a parameter of law = \"xu_needleman\""}},
      {"a xu_needleman key with bilinear", bl + "q = 1.0", {"'interface.w.q' = 1", "not a parameter of law = \"bilinear\""}},
      {"a friction key with xu_needleman", xn + "static_friction = 0.5",
       {"'interface.w.static_friction' = 0.5", "not a parameter of law = \"xu_needleman\""}},
      {"a cohesive key with slip_weakening", sw + "sigma_max = 2.5",
       {"'interface.w.sigma_max' = 2.5", "not a parameter of law = \"slip_weakening\""}},
      {"contact keys without contact", xn + "friction = 0.3",
       {"'interface.w.contact' = false", "friction and contact_stiffness need contact = true"}},
      {"law contact with a zero stiffness", kGeometry + "law = \"contact\"\ncontact_stiffness = 0.0",
       {"'interface.w.contact_stiffness' = 0", "> 0"}},
      {"law contact with contact off", kGeometry + "law = \"contact\"\ncontact = false\ncontact_stiffness = 1e15",
       {"'interface.w.contact' = false", "needs contact = true"}},
      {"contact on a fault", sw + "contact = true", {"'interface.w.contact' = true", "not with law = \"slip_weakening\""}},
      {"dynamic above static friction", replace(sw, "dynamic_friction = 0.5", "dynamic_friction = 0.7"),
       {"'interface.w.dynamic_friction' = 0.7", "must lie in [0, static_friction = 0.6]"}},
      {"j_domains without stress_intensity", xn + "j_domains = [4.0, 6.0]",
       {"'interface.w.j_domains' = [ 4.0, 6.0 ]", "needs stress_intensity = true"}},
      {"j_domains decreasing", xn + "stress_intensity = true\nj_domains = [6.0, 4.0]",
       {"'interface.w.j_domains' = [ 6.0, 4.0 ]", "increasing numbers >= 2", "in cells"}},
      {"j_domains below two cells", xn + "stress_intensity = true\nj_domains = [1.0]",
       {"'interface.w.j_domains' = [ 1.0 ]", ">= 2"}},
      {"j_domains empty", xn + "stress_intensity = true\nj_domains = []", {"'interface.w.j_domains' = []", "1 to 8"}},
      {"j_domains not numbers", xn + "stress_intensity = true\nj_domains = [\"wide\"]",
       {"'interface.w.j_domains'", "1 to 8 increasing numbers"}},
      {"stress_intensity not a boolean", xn + "stress_intensity = 1", {"'interface.w.stress_intensity' = 1", "true or false"}},
  };
  for (const Bad& b : cases) {
    const std::string msg = error_of(b.lines);
    EXPECT_FALSE(msg.empty()) << b.name << ": no error raised";
    for (const std::string& s : b.expect)
      EXPECT_NE(msg.find(s), std::string::npos) << b.name << ": '" << s << "' not in: " << msg;
  }
  // The base tables themselves are valid (each error above comes from its one change).
  for (const std::string* ok : {&xn, &bl, &sw}) EXPECT_EQ(error_of(*ok), "");
}
