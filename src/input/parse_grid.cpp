// rupture/input/parse_grid.cpp
// The [grid] table: domain, cell size, refinement levels, particles per cell, ghost margin.
#include <fmt/format.h>

#include <cmath>

#include "input/case_parse.hpp"
#include "input/input_schema.hpp"

namespace rupture {

void parse_grid(Section& top, Case& c) {
  Section g = top.table("grid", true, allowed_keys("grid"));
  g.pair("min", c.grid.min, true);
  g.pair("max", c.grid.max, true);
  for (int d = 0; d < 2; ++d) {
    if (!(c.grid.max[d] > c.grid.min[d]))
      fail(g.key("max"), fmt::format("[{:g}, {:g}]", c.grid.max[0], c.grid.max[1]),
           fmt::format("must exceed grid.min = [{:g}, {:g}] in both components", c.grid.min[0],
                       c.grid.min[1]));
  }
  c.grid.cell_size = g.number("cell_size");
  if (c.grid.cell_size <= 0) fail(g.key("cell_size"), c.grid.cell_size, "must be > 0 (m)");
  for (int d = 0; d < 2; ++d) {
    const double len = c.grid.max[d] - c.grid.min[d];
    if (!whole_cells(len, c.grid.cell_size))
      fail(g.key("cell_size"), c.grid.cell_size,
           fmt::format("must divide the domain extent along {} ({:g} m) into whole cells",
                       d == 0 ? "x" : "y", len));
  }
  const double cells = (c.grid.max[0] - c.grid.min[0]) * (c.grid.max[1] - c.grid.min[1]) /
                       (c.grid.cell_size * c.grid.cell_size);
  if (cells > 2e9)
    fail(g.key("cell_size"), c.grid.cell_size,
         fmt::format("gives {:.3g} cells; at most 2e9", cells));
  // coarse_cell_size = 0 turns refinement off (a uniform grid; refine boxes are ignored).
  if (g.has("coarse_cell_size") && g.number("coarse_cell_size") != 0.0) {
    const double h0 = g.number("coarse_cell_size");
    const double ratio = h0 / c.grid.cell_size;
    const long r = std::lround(ratio);
    if (!(h0 > 0) || r < 1 || std::fabs(ratio - double(r)) > 1e-6 * ratio || (r & (r - 1)) != 0)
      fail(g.key("coarse_cell_size"), h0,
           fmt::format("must be grid.cell_size ({:g} m) times a power of two (1, 2, 4, ...)",
                       c.grid.cell_size));
    c.grid.coarse_cell_size = h0;
  }
  Section refine = g.table("refine", false);
  if (!refine.raw().empty() && !g.has("coarse_cell_size"))
    fail(g.key("refine"), "(present)", "needs grid.coarse_cell_size, the level-0 cell size");
  for (const auto& [k, v] : named_entries(refine)) {
    if (!c.grid.refined()) break;
    const std::string& name = k;
    Section r = refine.table(name, true, allowed_keys("grid.refine.*"));
    RefineLevel L;
    L.name = name;
    r.pair("min", L.min, true);
    r.pair("max", L.max, true);
    const long level = r.integer("level", -1);
    if (level < 1 || level > 20) fail(r.key("level"), double(level), "must lie in [1, 20]");
    L.level = int(level);
    for (int d = 0; d < 2; ++d) {
      if (!(L.max[d] > L.min[d]))
        fail(r.key("max"), fmt::format("[{:g}, {:g}]", L.max[0], L.max[1]),
             fmt::format("must exceed {} in both components", r.key("min")));
      if (!whole_cells(L.min[d] - c.grid.min[d], c.grid.cell_size) ||
          !whole_cells(L.max[d] - c.grid.min[d], c.grid.cell_size))
        fail(r.key("min"),
             fmt::format("[{:g}, {:g}]..[{:g}, {:g}]", L.min[0], L.min[1], L.max[0], L.max[1]),
             fmt::format("box edges must lie on multiples of grid.cell_size = {:g} m from grid.min",
                         c.grid.cell_size));
    }
    if (L.max[0] <= c.grid.min[0] || L.min[0] >= c.grid.max[0] || L.max[1] <= c.grid.min[1] ||
        L.min[1] >= c.grid.max[1])
      fail(r.key("min"), fmt::format("[{:g}, {:g}]..[{:g}, {:g}]", L.min[0], L.min[1], L.max[0], L.max[1]),
           fmt::format("the box lies outside the grid [{:g}, {:g}]..[{:g}, {:g}] m: it would refine "
                       "nothing; move it over the grid or remove it",
                       c.grid.min[0], c.grid.min[1], c.grid.max[0], c.grid.max[1]));
    c.grid.refine.push_back(L);
  }
  // Nested levels by default: the same boxes with a fraction of the particles and per-level
  // steps (docs/performance.md); a grid without boxes has nothing to nest.
  const bool boxes = c.grid.refined() && !c.grid.refine.empty();
  const std::string realization = g.string("refinement", boxes ? "nested" : "graded", {"graded", "nested"});
  c.grid.nested = realization == "nested";
  if (c.grid.nested && !boxes)
    fail(g.key("refinement"), "\"nested\"",
         "needs grid.coarse_cell_size and [grid.refine] boxes (nested levels refine boxes)");
  c.grid.margin = g.number("margin", -1.0);  // < 0: automatic, set once the loads are known
  if (g.has("margin") && !(c.grid.margin >= 0 && c.grid.margin <= c.grid.max_margin()))
    fail(g.key("margin"), c.grid.margin, "must lie in [0, half the larger domain extent] (m)");
  const long ppc = g.integer("particles_per_cell", 2);
  if (ppc < 1 || ppc > 8)
    fail(g.key("particles_per_cell"), double(ppc), "must lie in [1, 8] (per direction)");
  c.grid.particles_per_cell = int(ppc);
}

}  // namespace rupture
