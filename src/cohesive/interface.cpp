// rupture/cohesive/interface.cpp
#include "cohesive/interface.hpp"

#include <cmath>

namespace rupture {

CohesiveInterface make_interface(const InterfaceSpec& spec) {
  CohesiveInterface c;
  c.spec = spec;
  const std::size_t n = std::size_t(spec.segments) + 1;
  c.x0.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    c.x0[k] = spec.start + (spec.end - spec.start) * double(k) / double(spec.segments);
  for (auto* v : {&c.ux_up, &c.uy_up, &c.ux_lo, &c.uy_lo, &c.fx_node, &c.fy_node, &c.stiffness_node,
                  &c.jump_before, &c.last_increment_n, &c.last_increment_t,
                  &c.streak_base})
    v->assign(n, 0.0);
  c.node_crack_time.assign(n, -1.0);
  c.reversal_streak.assign(n, 0);
  const std::size_t g = std::size_t(spec.segments) * CohesiveInterface::kGauss;
  for (auto* v : {&c.gp_dn, &c.gp_dt, &c.gp_tn, &c.gp_tt}) v->assign(g, 0.0);
  c.gp_separated.assign(g, 0);
  for (auto* v : {&c.seg_fa_x, &c.seg_fa_y, &c.seg_fb_x, &c.seg_fb_y, &c.seg_ka, &c.seg_kb}) v->assign(std::size_t(spec.segments), 0.0);
  return c;
}

double CohesiveInterface::stored_energy() const {
  // 4-point Gauss weights (they sum to 2 over [-1, 1]).
  static constexpr double w[kGauss] = {0.3478548451374538, 0.6521451548625461,
                                       0.6521451548625461, 0.3478548451374538};
  double e = 0.0;
  for (std::size_t s = 0; s < num_segments(); ++s) {
    const double half = 0.5 * (x0[s + 1] - x0[s]);
    for (int g = 0; g < kGauss; ++g) {
      const std::size_t i = s * kGauss + std::size_t(g);
      if (!gp_separated[i]) e += w[g] * half * spec.law.potential(gp_dn[i], gp_dt[i]);
    }
  }
  return e;
}

}  // namespace rupture
