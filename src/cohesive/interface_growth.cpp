// rupture/cohesive/interface_growth.cpp
#include "cohesive/interface_growth.hpp"

#include <stdexcept>

namespace rupture {
namespace {

// Copies old[i] to grown[i + shift] for every old element.
template <class T>
void carry(const std::vector<T>& old, std::vector<T>& grown, std::size_t shift) {
  for (std::size_t i = 0; i < old.size() && i + shift < grown.size(); ++i) grown[i + shift] = old[i];
}

}  // namespace

void extend_interface(CohesiveInterface& c, LineEnd at, double x, double y, double ux, double uy) {
  if (c.closed) throw std::logic_error("extend_interface: a closed interface has no ends");
  if (!c.rank_owned.empty()) throw std::logic_error("extend_interface: one process only");
  InterfaceSpec spec = c.spec;
  Polyline line;
  const bool front = at == LineEnd::start;
  if (front) line.x.push_back(x), line.y.push_back(y);
  line.x.insert(line.x.end(), c.x0.begin(), c.x0.end());
  line.y.insert(line.y.end(), c.y0.begin(), c.y0.end());
  if (!front) line.x.push_back(x), line.y.push_back(y);
  spec.line = line;
  spec.segments = int(line.num_vertices() - 1);
  CohesiveInterface g = make_interface(spec);
  const std::size_t node_shift = front ? 1 : 0;
  const std::size_t gp_shift = node_shift * std::size_t(CohesiveInterface::kGauss);
  for (auto m : {&CohesiveInterface::ux_up, &CohesiveInterface::uy_up, &CohesiveInterface::ux_lo,
                 &CohesiveInterface::uy_lo, &CohesiveInterface::fx_node, &CohesiveInterface::fy_node,
                 &CohesiveInterface::node_crack_time, &CohesiveInterface::node_rupture_time,
                 &CohesiveInterface::node_peak_slip_rate, &CohesiveInterface::node_slip_path,
                 &CohesiveInterface::node_slip_rate, &CohesiveInterface::stiffness_node,
                 &CohesiveInterface::jump_before, &CohesiveInterface::last_increment_n,
                 &CohesiveInterface::last_increment_t, &CohesiveInterface::streak_base})
    carry(c.*m, g.*m, node_shift);
  carry(c.reversal_streak, g.reversal_streak, node_shift);
  for (auto m : {&CohesiveInterface::gp_dn, &CohesiveInterface::gp_dt, &CohesiveInterface::gp_tn,
                 &CohesiveInterface::gp_tt, &CohesiveInterface::gp_damage, &CohesiveInterface::gp_slip,
                 &CohesiveInterface::gp_state, &CohesiveInterface::gp_rate, &CohesiveInterface::gp_normal})
    carry(c.*m, g.*m, gp_shift);
  carry(c.gp_separated, g.gp_separated, gp_shift);
  const std::size_t k = front ? 0 : g.num_nodes() - 1;  // the new node
  g.ux_up[k] = g.ux_lo[k] = ux;
  g.uy_up[k] = g.uy_lo[k] = uy;
  g.node_crack_time[k] = spec.precracked ? c.time : -1.0;
  g.time = c.time;
  g.work = c.work;
  c = std::move(g);
}

}  // namespace rupture
