// rupture/bc/velocity_bc.cpp
#include "bc/velocity_bc.hpp"

#include <cmath>

namespace rupture {

std::vector<NodeBC> resolve_nodes(const std::vector<VelocityBC>& bcs, const Grid& grid,
                                  int num_fields) {
  std::vector<NodeBC> out;
  const double tol = 1e-9 * grid.cell_size();
  for (std::size_t c = 0; c < bcs.size(); ++c) {
    const VelocityBC& bc = bcs[c];
    const bool vertical = bc.edge == Edge::left || bc.edge == Edge::right;
    const Axis& along = vertical ? grid.y : grid.x;
    const int fixed = bc.edge == Edge::left     ? grid.ghost
                      : bc.edge == Edge::right  ? grid.x.cells - grid.ghost
                      : bc.edge == Edge::bottom ? grid.ghost
                                                : grid.y.cells - grid.ghost;
    std::vector<int> fields = bc.fields;
    if (fields.empty())
      for (int f = 0; f < num_fields; ++f) fields.push_back(f);
    for (int k = 0; k < along.nodes(); ++k) {
      const double s = along.node(k);
      if (s < bc.from - tol || s > bc.to + tol) continue;
      const std::size_t node = vertical ? grid.node_index(fixed, k) : grid.node_index(k, fixed);
      for (int f : fields) out.push_back({f, node, bc.component, int(c)});
    }
  }
  return out;
}

}  // namespace rupture
