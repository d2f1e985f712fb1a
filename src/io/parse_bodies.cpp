// rupture/io/parse_bodies.cpp
// The [bodies] table: material, shape, initial state and velocity field of each body.
#include <fmt/format.h>

#include <cmath>

#include "io/case_parse.hpp"

namespace rupture {

void parse_bodies(Section& top, Case& c, ParseContext& ctx) {
  auto& material_index = ctx.material_index;
  auto& body_index = ctx.body_index;
  Section bodies = top.table("bodies", true);
  const double h = c.grid.cell_size, tol = 1e-9 * h;
  for (const auto& [k, v] : in_input_order(bodies.raw())) {
    const std::string& name = k;
    Section b = bodies.table(name, true, {"material", "min", "max", "velocity"});
    BodySpec bs;
    bs.name = name;
    const std::string mat = b.string("material", "");
    if (mat.empty())
      fail(b.key("material"), "(missing)", "required, the name of a [materials] entry");
    if (!material_index.count(mat)) {
      std::vector<std::string> names;
      for (const auto& m : c.materials) names.push_back(m.name);
      fail(b.key("material"), "\"" + mat + "\"", "must name a material: " + Section::join(names));
    }
    bs.material = material_index[mat];
    b.pair("min", bs.min, true);
    b.pair("max", bs.max, true);
    b.pair("velocity", bs.velocity, false);
    for (int d = 0; d < 2; ++d) {
      if (!(bs.max[d] > bs.min[d]))
        fail(b.key("max"), fmt::format("[{:g}, {:g}]", bs.max[0], bs.max[1]),
             fmt::format("the body is empty: must exceed {} = [{:g}, {:g}] in both components",
                         b.key("min"), bs.min[0], bs.min[1]));
      if (!inside(bs.min[d], c.grid.min[d], c.grid.max[d], tol) ||
          !inside(bs.max[d], c.grid.min[d], c.grid.max[d], tol))
        fail(b.key(inside(bs.min[d], c.grid.min[d], c.grid.max[d], tol) ? "max" : "min"),
             fmt::format("[{:g}, {:g}]..[{:g}, {:g}]", bs.min[0], bs.min[1], bs.max[0], bs.max[1]),
             fmt::format("the body must lie inside the grid [{:g}, {:g}]..[{:g}, {:g}]",
                         c.grid.min[0], c.grid.min[1], c.grid.max[0], c.grid.max[1]));
      if (!whole_cells(bs.min[d] - c.grid.min[d], h) || !whole_cells(bs.max[d] - c.grid.min[d], h))
        fail(b.key("min"),
             fmt::format("[{:g}, {:g}]..[{:g}, {:g}]", bs.min[0], bs.min[1], bs.max[0], bs.max[1]),
             fmt::format("body edges must lie on grid lines (multiples of grid.cell_size = {:g} m "
                         "from grid.min)",
                         h));
    }
    bs.field = int(c.bodies.size());
    body_index[name] = bs.field;
    c.bodies.push_back(bs);
  }
  if (c.bodies.empty()) fail("bodies", "{}", "at least one body is required");
  if (c.bodies.size() > 255) fail("bodies", double(c.bodies.size()), "at most 255 bodies");
  for (std::size_t i = 0; i < c.bodies.size(); ++i)
    for (std::size_t j = i + 1; j < c.bodies.size(); ++j) {
      const BodySpec &a = c.bodies[i], &b = c.bodies[j];
      const double ox = std::min(a.max[0], b.max[0]) - std::max(a.min[0], b.min[0]);
      const double oy = std::min(a.max[1], b.max[1]) - std::max(a.min[1], b.min[1]);
      if (ox > tol && oy > tol)
        fail("bodies." + b.name, "\"" + b.name + "\"",
             "overlaps bodies." + a.name + "; bodies must not overlap");
    }
}

void check_bodies_on_graded_grid(const Case& c) {
  if (!c.grid.refined()) return;
  // Bodies fill whole cells of the graded grid: their edges must be grid lines.
  const Grid grid = build_grid(c.grid);
  const Axis* axes[2] = {&grid.x, &grid.y};
  for (const BodySpec& b : c.bodies)
    for (int d = 0; d < 2; ++d)
      for (const double v : {b.min[d], b.max[d]}) {
        const Axis& a = *axes[d];
        const int k = a.cell_of(v);
        const double lo = a.node(k), hi = a.node(k + 1), tol = 1e-9 * a.h;
        if (std::fabs(v - lo) > tol && std::fabs(v - hi) > tol)
          fail("bodies." + b.name + (v == b.min[d] ? ".min" : ".max"), v,
               fmt::format("with grid refinement, body edges must lie on grid lines; along {} "
                           "the nearest are {:g} and {:g} m (cells of {:g} m there)",
                           d == 0 ? "x" : "y", lo, hi, hi - lo));
      }
}

}  // namespace rupture
