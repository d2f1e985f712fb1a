// rupture/grid/grid.cpp
#include "grid/grid.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace rupture {

Grid make_uniform_grid(const double min[2], const double max[2], double h) {
  Grid g;
  const char* names[2] = {"x", "y"};
  Axis* axes[2] = {&g.x, &g.y};
  for (int d = 0; d < 2; ++d) {
    const double extent = max[d] - min[d];
    const double n = extent / h;
    const long cells = std::lround(n);
    if (cells < 1 || std::fabs(n - double(cells)) > 1e-6 * std::max(1.0, n)) {
      throw InputError(fmt::format(
          "grid.cell_size = {:g}: the domain extent along {} ({:g} m) must be a whole number "
          "(>= 1) of cells; {:g} cells does not qualify",
          h, names[d], extent, n));
    }
    axes[d]->h = h;
    axes[d]->cells = int(cells) + 2 * g.ghost;
    axes[d]->origin = min[d] - g.ghost * h;
    g.domain_min[d] = min[d];
    g.domain_max[d] = max[d];
  }
  return g;
}

void GridFields::resize(int fields, std::size_t nodes) {
  num_fields = fields;
  num_nodes = nodes;
  const std::size_t n = std::size_t(fields) * nodes;
  for (auto* v : {&mass, &mom_x, &mom_y, &force_x, &force_y, &vel_x, &vel_y, &dvel_x, &dvel_y,
                  &remap_x, &remap_y}) {
    v->assign(n, 0.0);
  }
}

std::size_t GridFields::bytes() const { return 11 * sizeof(double) * num_nodes * num_fields; }

}  // namespace rupture
