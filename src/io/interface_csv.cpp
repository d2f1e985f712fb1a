// rupture/io/interface_csv.cpp
#include "io/interface_csv.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <variant>

#include "io/atomic_file.hpp"

namespace rupture {

CohesiveTraction node_traction(const CohesiveInterface& c, std::size_t k) {
  const std::size_t G = std::size_t(CohesiveInterface::kGauss);
  const CohesiveLaw& law = node_law_variant(c, k);
  if (const auto* f = std::get_if<SlipWeakening>(&law)) {
    // Friction is history-dependent: the total traction T0 + dT of the Gauss points next to the
    // node (the segments' first and last), averaged.
    double tn = 0.0, tt = 0.0;
    int count = 0;
    if (k < c.num_segments()) tn += c.gp_tn[k * G], tt += c.gp_tt[k * G], ++count;
    if (k > 0 || c.closed) {
      const std::size_t prev = k > 0 ? k - 1 : c.num_segments() - 1;
      tn += c.gp_tn[prev * G + G - 1], tt += c.gp_tt[prev * G + G - 1], ++count;
    }
    return {f->tn0 + tn / count, f->tt0 + tt / count};
  }
  if (c.node_crack_time[k] >= 0.0) return {0.0, 0.0};
  // The law at the node's jump, with the largest damage of the Gauss points around it.
  GaussHistory h;
  for (std::size_t g = 0; g < G; ++g) {
    if (k < c.num_segments()) h.damage = std::max(h.damage, c.gp_damage[k * G + g]);
    if (k > 0) h.damage = std::max(h.damage, c.gp_damage[(k - 1) * G + g]);
  }
  const double dn = c.jump_normal(k), dt = c.jump_tangential(k);
  const LawResponse r = std::visit([&](const auto& l) { return l.respond(dn, dt, h); }, law);
  return {r.tn, r.tt};
}

void write_interface_csv(const std::string& path, const CohesiveInterface& c, double time) {
  std::string s =
      "time,x,jump_n,jump_t,traction_n,traction_t,force_x,force_y,y_upper,y_lower,cracked,y,s,"
      "x_upper,x_lower\n";
  s.reserve(s.size() + c.num_nodes() * 180);
  for (std::size_t k = 0; k < c.num_nodes(); ++k) {
    const double dn = c.jump_normal(k), dt = c.jump_tangential(k);
    const bool cracked = c.node_crack_time[k] >= 0.0;
    const CohesiveTraction T = node_traction(c, k);
    // Jumps and tractions in the node's frame (normal, tangent); forces and positions in x, y.
    s += fmt::format(
        "{:.9e},{:.9e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e},{:.9e},{:.9e},{},{:.9e},{:.9e},{:."
        "9e},{:.9e}\n",
        time, c.x0[k], dn, dt, T.normal, T.tangential, c.fx_node[k], c.fy_node[k],
        c.y0[k] + c.uy_up[k], c.y0[k] + c.uy_lo[k], cracked ? 1 : 0, c.y0[k], c.s0[k],
        c.x0[k] + c.ux_up[k], c.x0[k] + c.ux_lo[k]);
  }
  write_file_atomic(path, s);
}

}  // namespace rupture
