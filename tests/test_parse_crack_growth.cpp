// Tests of the crack keys of [interface.*] tables (input/parse_crack_growth.cpp): growth and its
// criterion's parameters reach GrowthLaw (toughness, fracture_energy, step, direction; growth
// turns stress_intensity on), a cohesive crack drawn open grows carrying its law, and every
// growth input the solver cannot honour stops with the key, the value and what is allowed (no
// pre-crack, two bodies, a refined grid, stretches, no tip, a criterion without its parameter, a
// step above half a cell); branching keeps one velocity field per allowed split (NAME.branchK)
// and needs a criterion that reads K. Why: a growth key read wrong grows another crack than the
// one asked for, silently.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "support.hpp"

using rupture::test::case_with;
using rupture::test::kGeometry;
using rupture::test::replace;

namespace rupture {
namespace {

// Crack growth (interface.NAME.growth; solver/crack_growth.hpp): a pre-crack inside one body,
// the upper one, with the lower one joined to it by a bonded interface.
const std::string kInside = "body = \"upper\"\npoints = [[0.002, 0.002], [0.005, 0.002]]\nsegments = 3\nlaw = \"contact\"\n";
const std::string kCohesive = "body = \"upper\"\npoints = [[0.002, 0.002], [0.005, 0.002]]\nsegments = 3\n"
                              "sigma_max = 24e6\ndelta_n = 0.4e-6\ndrawn_open = true\n";
const std::string kBilinear = "body = \"upper\"\npoints = [[0.002, 0.002], [0.005, 0.002]]\nsegments = 3\n"
                              "law = \"bilinear\"\nsigma_max = 24e6\ntau_max = 24e6\ndelta_nc = 4e-6\ndrawn_open = true\n";
const std::string kJoined = "\n[interface.join]\nupper_body = \"upper.below.w\"\nlower_body = \"lower\"\ny = 0.0\nstart = 0.0\n"
                            "end = 0.008\nsegments = 8\nsigma_max = 24e6\ndelta_n = 0.4e-6\n";

InterfaceSpec parse_grown(const std::string& lines) {
  const Case c = parse_case(case_with(lines + kJoined));
  return c.interfaces.at(0);
}
std::string growth_error(const std::string& lines) {
  try {
    parse_case(case_with(lines + kJoined));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ParseCrackGrowth, GrowthNeedsAPreCrackInsideOneBodyWithItsParameters) {
  const std::string g = kInside + "growth = \"max_hoop\"\n";
  const InterfaceSpec ok = parse_grown(g + "toughness = 1.5e6\ngrowth_step = 0.25\ngrowth_direction = \"straight\"");
  EXPECT_EQ(ok.growth.criterion, GrowthCriterion::max_hoop);
  EXPECT_EQ(ok.growth.direction, GrowthDirection::straight);
  EXPECT_EQ(ok.growth.toughness, 1.5e6);
  EXPECT_EQ(ok.growth.step, 0.25);
  EXPECT_TRUE(ok.stress_intensity);  // growth reads K at the tips, and records them
  const InterfaceSpec energy = parse_grown(kInside + "growth = \"energy\"\nfracture_energy = 300.0\nj_domains = [3.0, 5.0]");
  EXPECT_EQ(energy.growth.criterion, GrowthCriterion::energy);
  EXPECT_EQ(energy.growth.fracture_energy, 300.0);
  EXPECT_EQ(energy.growth.step, 0.5);  // the default
  EXPECT_EQ(energy.j_domains, (std::vector<double>{3.0, 5.0}));
  EXPECT_FALSE(parse_grown(kInside).growth.on());
  // A cohesive crack drawn open: grown segments carry its law; the cohesive criterion reads
  // the law's strength.
  const InterfaceSpec co = parse_grown(kCohesive + "growth = \"energy\"\nfracture_energy = 26.1");
  EXPECT_TRUE(co.drawn_open);
  EXPECT_FALSE(co.precracked);
  EXPECT_EQ(co.growth.criterion, GrowthCriterion::energy);
  EXPECT_FALSE(parse_grown(kCohesive).growth.on());  // a cohesive crack drawn open need not grow
  EXPECT_EQ(parse_grown(kBilinear + "growth = \"cohesive\"").growth.criterion, GrowthCriterion::cohesive);
  const InterfaceSpec hoop = parse_grown(kCohesive + "growth = \"max_hoop\"\ntoughness = 1e6");
  EXPECT_EQ(hoop.growth.criterion, GrowthCriterion::max_hoop);  // a cohesive crack by a K criterion
  // A weak plane ahead: its G_c beside the bulk's.
  const InterfaceSpec plane = parse_grown(kInside + "growth = \"energy\"\nfracture_energy = 52.2\nplane_fracture_energy = 26.1");
  EXPECT_EQ(plane.growth.plane_fracture_energy, 26.1);
  EXPECT_EQ(energy.growth.plane_fracture_energy, 0.0);  // none by default
  struct Bad {
    const char* name;
    std::string lines;
    std::vector<std::string> expect;
  };
  const std::string xn = kGeometry + "sigma_max = 24e6\ndelta_n = 0.4e-6\n";
  const std::vector<Bad> cases = {
      {"a fault's friction", replace(g, "law = \"contact\"\n", "law = \"slip_weakening\"\nstatic_friction = 0.6\ndynamic_friction = 0.5\ndc = 0.4\ninitial_traction = [-1e6, 0.0]\n") + "toughness = 1e6",
       {"'interface.w.growth' = \"max_hoop\"", "needs law = \"contact\"", "\"xu_needleman\"", "fault"}},
      {"cohesive growth of a pre-crack", kInside + "growth = \"cohesive\"",
       {"'interface.w.growth' = \"cohesive\"", "needs law = \"bilinear\"", "no strength"}},
      {"cohesive growth with Xu-Needleman", kCohesive + "growth = \"cohesive\"",
       {"'interface.w.growth' = \"cohesive\"", "needs law = \"bilinear\"", "lag"}},
      {"toughness with cohesive growth", kBilinear + "growth = \"cohesive\"\ntoughness = 1e6",
       {"'interface.w.toughness' = 1000000", "growth = \"cohesive\" reads the law's strength"}},
      {"a contact crack drawn open", kInside + "drawn_open = true",
       {"'interface.w.drawn_open' = true", "open already"}},
      {"between two bodies", kGeometry + "law = \"contact\"\ngrowth = \"max_hoop\"\ntoughness = 1e6",
       {"'interface.w.growth' = \"max_hoop\"", "inside one body", "'interface.w.body'"}},
      {"no toughness", g, {"'interface.w.toughness' = (missing)", "K_Ic"}},
      {"zero toughness", g + "toughness = 0.0", {"'interface.w.toughness' = 0", "must be > 0"}},
      {"energy without G_c", kInside + "growth = \"energy\"", {"'interface.w.fracture_energy' = (missing)", "G_c"}},
      {"toughness with energy", kInside + "growth = \"energy\"\nfracture_energy = 1.0\ntoughness = 1e6",
       {"'interface.w.toughness' = 1000000", "is for growth = \"max_hoop\""}},
      {"a step above half a cell", g + "toughness = 1e6\ngrowth_step = 0.6",
       {"'interface.w.growth_step' = 0.6", "(0, 0.5]", "half a cell"}},
      {"a zero step", g + "toughness = 1e6\ngrowth_step = 0.0", {"'interface.w.growth_step' = 0", "(0, 0.5]"}},
      {"a weak plane with max_hoop", g + "toughness = 1e6\nplane_fracture_energy = 10.0",
       {"'interface.w.plane_fracture_energy' = 10", "needs growth = \"energy\""}},
      {"a weak plane going straight", kInside + "growth = \"energy\"\nfracture_energy = 1.0\nplane_fracture_energy = 0.5\ngrowth_direction = \"straight\"",
       {"'interface.w.plane_fracture_energy' = 0.5", "growth_direction = \"max_hoop\""}},
      {"a zero weak plane", kInside + "growth = \"energy\"\nfracture_energy = 1.0\nplane_fracture_energy = 0.0",
       {"'interface.w.plane_fracture_energy' = 0", "must be > 0"}},
      {"a weak plane without growth", kInside + "plane_fracture_energy = 1.0",
       {"'interface.w.plane_fracture_energy' = 1", "needs growth"}},
      {"toughness without growth", kInside + "toughness = 1e6", {"'interface.w.toughness' = 1000000", "needs growth"}},
      {"an unknown criterion", kInside + "growth = \"kink\"", {"'interface.w.growth' = \"kink\"", "max_hoop", "energy"}},
      {"an unknown direction", g + "toughness = 1e6\ngrowth_direction = \"up\"",
       {"'interface.w.growth_direction' = \"up\"", "straight"}},
      {"edge to edge: no tip", replace(g, "[[0.002, 0.002], [0.005, 0.002]]", "[[0.0, 0.002], [0.008, 0.002]]") + "toughness = 1e6",
       {"'interface.w.growth' = \"max_hoop\"", "needs a crack tip"}},
  };
  for (const Bad& b : cases) {
    const std::string msg = growth_error(b.lines);
    EXPECT_FALSE(msg.empty()) << b.name << ": no error raised";
    for (const std::string& s : b.expect)
      EXPECT_NE(msg.find(s), std::string::npos) << b.name << ": '" << s << "' not in: " << msg;
  }
}

// nucleation = "strength" (solver/crack_nucleation.hpp): the strength defaults to the law's
// sigma_max, is required where the law has none, and needs growth.
TEST(ParseCrackGrowth, NucleationTakesTheLawsStrengthOrItsOwn) {
  const std::string cohesive = replace(kBilinear, "drawn_open = true\n", "") + "growth = \"cohesive\"\n";
  EXPECT_EQ(parse_grown(cohesive + "nucleation = \"strength\"").nucleation_strength, 24e6);
  EXPECT_EQ(parse_grown(cohesive + "nucleation = \"strength\"\nnucleation_strength = 5e6").nucleation_strength, 5e6);
  EXPECT_EQ(parse_grown(cohesive).nucleation_strength, 0.0);  // none by default
  const std::string contact = kInside + "growth = \"max_hoop\"\ntoughness = 1e6\n";
  EXPECT_EQ(parse_grown(contact + "nucleation = \"strength\"\nnucleation_strength = 3e6").nucleation_strength, 3e6);
  struct Bad {
    const char* name;
    std::string lines;
    std::vector<std::string> expect;
  };
  const std::vector<Bad> cases = {
      {"contact without a strength", contact + "nucleation = \"strength\"",
       {"'interface.w.nucleation_strength' = (missing)", "law = \"contact\""}},
      {"a zero strength", cohesive + "nucleation = \"strength\"\nnucleation_strength = 0.0",
       {"'interface.w.nucleation_strength' = 0", "must be > 0"}},
      {"a strength without nucleation", cohesive + "nucleation_strength = 1e6",
       {"'interface.w.nucleation_strength' = 1000000", "needs nucleation = \"strength\""}},
      {"nucleation without growth", kBilinear + "nucleation = \"strength\"",
       {"'interface.w.nucleation' = \"strength\"", "needs growth"}},
      {"an unknown criterion", cohesive + "nucleation = \"stress\"", {"'interface.w.nucleation' = \"stress\"", "strength"}},
  };
  for (const Bad& b : cases) {
    const std::string msg = growth_error(b.lines);
    EXPECT_FALSE(msg.empty()) << b.name << ": no error raised";
    for (const std::string& s : b.expect)
      EXPECT_NE(msg.find(s), std::string::npos) << b.name << ": '" << s << "' not in: " << msg;
  }
}

TEST(ParseCrackGrowth, BranchingKeepsAFieldPerSplitAndNeedsAKCriterion) {
  const Case c = parse_case(case_with(kInside + "growth = \"energy\"\nfracture_energy = 3.0\nbranching = \"yoffe\"\n"
                                                "max_branches = 2" + kJoined));
  const InterfaceSpec& w = c.interfaces.at(0);
  EXPECT_EQ(w.growth.branching, BranchCriterion::yoffe);
  EXPECT_EQ(w.growth.max_branches, 2);
  // Two kept fields, after every body's, named after the crack; no body holds them.
  ASSERT_EQ(w.branch_fields.size(), 2u);
  const std::size_t n = c.field_names.size();
  EXPECT_EQ(w.branch_fields[0], int(n) - 2);
  EXPECT_EQ(w.branch_fields[1], int(n) - 1);
  EXPECT_EQ(c.field_names[n - 2], "w.branch1");
  EXPECT_EQ(c.field_names[n - 1], "w.branch2");
  for (const BodySpec& b : c.bodies) EXPECT_LT(b.field, int(n) - 2) << b.name;
  EXPECT_EQ(parse_grown(kInside + "growth = \"energy\"\nfracture_energy = 3.0\nbranching = \"yoffe\"").growth.max_branches, 1);
  EXPECT_TRUE(parse_grown(kInside + "growth = \"energy\"\nfracture_energy = 3.0").branch_fields.empty());
  const std::string e = kInside + "growth = \"energy\"\nfracture_energy = 3.0\n";
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {kInside + "branching = \"yoffe\"", {"'interface.w.branching' = \"yoffe\"", "needs growth"}},
      {e + "max_branches = 2", {"'interface.w.max_branches' = 2", "needs branching = \"yoffe\""}},
      {e + "branching = \"fork\"", {"'interface.w.branching' = \"fork\"", "yoffe"}},
      {e + "branching = \"yoffe\"\nmax_branches = 0", {"'interface.w.max_branches' = 0", "1 to 8"}},
      {e + "branching = \"yoffe\"\nmax_branches = 1.5", {"'interface.w.max_branches' = 1.5", "whole number"}},
      {kBilinear + "growth = \"cohesive\"\nbranching = \"yoffe\"",
       {"'interface.w.branching' = \"yoffe\"", "needs growth = \"energy\" or \"max_hoop\""}},
  };
  for (const auto& [lines, expect] : cases) {
    const std::string msg = growth_error(lines);
    EXPECT_FALSE(msg.empty()) << lines << ": no error raised";
    for (const std::string& s : expect) EXPECT_NE(msg.find(s), std::string::npos) << "'" << s << "' not in: " << msg;
  }
}

}  // namespace
}  // namespace rupture

namespace rupture {
namespace {

// growth = "prescribed" (a generation-phase run) and running_tip: the speed is required and
// positive, the criterion's own keys and the prescribed ones do not mix, running_tip needs
// growth and a speed the running tip's field holds at (below 0.95 c_R of the body).
TEST(ParseCrackGrowth, PrescribedGrowthAndRunningTip) {
  const InterfaceSpec p = parse_grown(kInside + "growth = \"prescribed\"\ngrowth_speed = 300.0\ngrowth_start = 1e-6\n"
                                                "running_tip = true");
  EXPECT_EQ(p.growth.criterion, GrowthCriterion::prescribed);
  EXPECT_EQ(p.growth.speed, 300.0);
  EXPECT_EQ(p.growth.start, 1e-6);
  EXPECT_TRUE(p.running_tip);
  EXPECT_TRUE(p.stress_intensity);
  EXPECT_FALSE(parse_grown(kInside + "growth = \"energy\"\nfracture_energy = 300.0").running_tip);  // the default
  const auto has = [](const std::string& e, const std::string& part) {
    EXPECT_NE(e.find(part), std::string::npos) << e;
  };
  has(growth_error(kInside + "growth = \"prescribed\""), "interface.w.growth_speed");
  has(growth_error(kInside + "growth = \"prescribed\"\ngrowth_speed = -3.0"), "must be > 0");
  has(growth_error(kInside + "growth = \"prescribed\"\ngrowth_speed = 300.0\ngrowth_start = -1.0"), "must be >= 0");
  has(growth_error(kInside + "growth = \"prescribed\"\ngrowth_speed = 300.0\ntoughness = 1e6"), "takes growth_speed");
  has(growth_error(kInside + "growth = \"max_hoop\"\ntoughness = 1e6\ngrowth_speed = 300.0"), "is for growth = \"prescribed\"");
  has(growth_error(kInside + "running_tip = true"), "needs growth");
  has(growth_error(kInside + "growth = \"prescribed\"\ngrowth_speed = 1e5\nrunning_tip = true"), "c_R");
  has(growth_error(kInside + "growth = \"prescribed\"\ngrowth_speed = 300.0\nbranching = \"yoffe\""),
      "interface.w.branching");
  has(growth_error(kInside + "growth = \"energy\"\nfracture_energy = 300.0\nplane_fracture_energy = 100.0\n"
                             "running_tip = true"),
      "interface.w.running_tip");
}

}  // namespace
}  // namespace rupture
