// rupture/output/interface_csv.cpp
#include "output/interface_csv.hpp"

#include <fmt/format.h>

#include "input/law_registry.hpp"
#include "core/atomic_file.hpp"

namespace rupture {

CohesiveTraction node_traction(const CohesiveInterface& c, std::size_t k) {
  return law_entry(c.spec).node_traction(c, k);  // the law's (input/law_registry.hpp)
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
