// Tests of the traction-law contract (cohesive/law.hpp): the Xu-Needleman wrappers are
// bitwise its own functions, and dispatch through the variant (once, around a loop templated
// on the law, as the interface will do it) gives bitwise what direct calls give.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "cohesive/law.hpp"

using namespace rupture;

namespace {
XuNeedleman spec_xn() {
  XuNeedleman law;
  law.sigma_max = 24e6;
  law.tau_max = 24e6;
  law.delta_n = 0.4e-6;
  law.delta_t = std::sqrt(2.0 * std::exp(1.0)) * law.delta_n;
  return law;
}
BilinearLaw test_bilinear() {
  BilinearLaw law;
  law.sigma_max = 24e6;
  law.tau_max = 30e6;
  law.delta_nc = 2e-6;
  law.delta_tc = 3e-6;
  law.lambda0 = 0.02;
  return law;
}

// A path of openings that loads, unloads, compresses and separates.
std::vector<std::pair<double, double>> test_path() {
  std::vector<std::pair<double, double>> path;
  for (int i = 0; i <= 400; ++i) {
    const double s = i / 100.0;
    path.emplace_back(1.5e-6 * std::sin(3 * s) - 0.2e-6 * s, 2.5e-6 * std::sin(1.7 * s) * s);
  }
  return path;
}

struct Sample {
  LawResponse r;
  GaussHistory h;
  double stored;
};

// What the interface loop will look like: a template over the law, no dispatch inside.
template <TractionLaw L>
std::vector<Sample> walk(const L& law, const std::vector<std::pair<double, double>>& path) {
  std::vector<Sample> out;
  GaussHistory h;
  for (const auto& [dn, dt] : path) {
    const LawResponse r = law.respond(dn, dt, h);
    out.push_back({r, h, law.stored_energy(dn, dt, h)});
  }
  return out;
}

bool bitwise_equal(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expect_bitwise(const std::vector<Sample>& a, const std::vector<Sample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(bitwise_equal(a[i].r.tn, b[i].r.tn)) << i;
    EXPECT_TRUE(bitwise_equal(a[i].r.tt, b[i].r.tt)) << i;
    EXPECT_TRUE(bitwise_equal(a[i].r.stiffness, b[i].r.stiffness)) << i;
    EXPECT_TRUE(bitwise_equal(a[i].h.damage, b[i].h.damage)) << i;
    EXPECT_TRUE(bitwise_equal(a[i].stored, b[i].stored)) << i;
  }
}
}  // namespace

TEST(CohesiveLaw, xu_needleman_respond_is_bitwise_traction_and_stability_stiffness) {
  const XuNeedleman law = spec_xn();
  GaussHistory h;
  for (const auto& [dn, dt] : test_path()) {
    const LawResponse r = law.respond(dn, dt, h);
    const CohesiveTraction T = law.traction(dn, dt);
    EXPECT_TRUE(bitwise_equal(r.tn, T.normal)) << dn << " " << dt;
    EXPECT_TRUE(bitwise_equal(r.tt, T.tangential)) << dn << " " << dt;
    EXPECT_TRUE(bitwise_equal(r.stiffness, law.stability_stiffness(dn, dt))) << dn << " " << dt;
    EXPECT_TRUE(bitwise_equal(law.stored_energy(dn, dt, h), law.potential(dn, dt)));
  }
  EXPECT_EQ(h.damage, 0.0);  // no history
  EXPECT_EQ(h.slip, 0.0);
  EXPECT_FALSE(law.separated(h));
  EXPECT_EQ(law.fracture_energy_normal(), law.phi_n());
  EXPECT_EQ(law.fracture_energy_tangential(), law.phi_t());
}

TEST(CohesiveLaw, variant_dispatch_is_bitwise_the_direct_call) {
  const auto path = test_path();
  const XuNeedleman xn = spec_xn();
  const BilinearLaw bl = test_bilinear();
  for (const CohesiveLaw& law : {CohesiveLaw{xn}, CohesiveLaw{bl}}) {
    const std::vector<Sample> via = std::visit([&](const auto& l) { return walk(l, path); }, law);
    const std::vector<Sample> direct =
        std::holds_alternative<XuNeedleman>(law) ? walk(xn, path) : walk(bl, path);
    expect_bitwise(via, direct);
    const double gi = std::visit([](const auto& l) { return l.fracture_energy_normal(); }, law);
    const double gii =
        std::visit([](const auto& l) { return l.fracture_energy_tangential(); }, law);
    const double k0 = std::visit([](const auto& l) { return l.initial_stiffness(); }, law);
    if (std::holds_alternative<XuNeedleman>(law)) {
      EXPECT_EQ(gi, xn.phi_n());
      EXPECT_EQ(gii, xn.phi_t());
      EXPECT_EQ(k0, xn.initial_stiffness());
    } else {
      EXPECT_EQ(gi, 0.5 * bl.sigma_max * bl.delta_nc);
      EXPECT_EQ(gii, 0.5 * bl.tau_max * bl.delta_tc);
      EXPECT_EQ(k0, bl.initial_stiffness());
    }
  }
  // The bilinear walk really is history-dependent: the path separates the point.
  EXPECT_TRUE(bl.separated(walk(bl, path).back().h));
}

TEST(CohesiveLaw, names_and_stiffness_at_rest) {
  const XuNeedleman xn = spec_xn();
  const BilinearLaw bl = test_bilinear();
  EXPECT_STREQ(law_name(CohesiveLaw{xn}), "xu_needleman");
  EXPECT_STREQ(law_name(CohesiveLaw{bl}), "bilinear");
  EXPECT_EQ(stiffness_at_rest(CohesiveLaw{xn}), xn.stability_stiffness(0.0, 0.0));
  EXPECT_DOUBLE_EQ(stiffness_at_rest(CohesiveLaw{bl}),
                   bl.penalty_stiffness());  // k_pen = 1 x elastic
}
