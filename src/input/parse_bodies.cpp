// rupture/input/parse_bodies.cpp
// The [bodies] table: material, shape and cut-outs, initial velocity and stress, and velocity
// field of each body (docs/geometry.md).
#include <fmt/format.h>

#include <cmath>

#include "input/case_parse.hpp"
#include "input/input_schema.hpp"
#include "particles/seed.hpp"

namespace rupture {
namespace {

// The rules a rectangle body has always had: inside the grid, edges on grid lines.
void check_rectangle_body(Section& b, const Shape& r, const Case& c) {
  const double h = c.grid.cell_size, tol = 1e-9 * h;
  for (int d = 0; d < 2; ++d) {
    if (!inside(r.min[d], c.grid.min[d], c.grid.max[d], tol) ||
        !inside(r.max[d], c.grid.min[d], c.grid.max[d], tol))
      fail(b.key(inside(r.min[d], c.grid.min[d], c.grid.max[d], tol) ? "max" : "min"),
           fmt::format("[{:g}, {:g}]..[{:g}, {:g}]", r.min[0], r.min[1], r.max[0], r.max[1]),
           fmt::format("the body must lie inside the grid [{:g}, {:g}]..[{:g}, {:g}]",
                       c.grid.min[0], c.grid.min[1], c.grid.max[0], c.grid.max[1]));
    if (!whole_cells(r.min[d] - c.grid.min[d], h) || !whole_cells(r.max[d] - c.grid.min[d], h))
      fail(b.key("min"),
           fmt::format("[{:g}, {:g}]..[{:g}, {:g}]", r.min[0], r.min[1], r.max[0], r.max[1]),
           fmt::format("body edges must lie on grid lines (multiples of grid.cell_size = {:g} m "
                       "from grid.min)",
                       h));
  }
}

// Any other shape need not follow grid lines, but must lie inside the grid.
void check_shape_inside_grid(Section& b, const Shape& s, const Case& c) {
  const Box box = bounding_box(s);
  const double tol = 1e-9 * c.grid.cell_size;
  for (int d = 0; d < 2; ++d)
    if (!inside(box.min[d], c.grid.min[d], c.grid.max[d], tol) ||
        !inside(box.max[d], c.grid.min[d], c.grid.max[d], tol))
      fail(b.key(s.kind == ShapeKind::polygon ? "vertices" : "center"),
           fmt::format("a {} spanning {}", shape_name(s.kind), describe_extent(box)),
           fmt::format("the body must lie inside the grid [{:g}, {:g}]..[{:g}, {:g}]",
                       c.grid.min[0], c.grid.min[1], c.grid.max[0], c.grid.max[1]));
}

// bodies.NAME.minus: an array of tables, each one shape cut out of the body.
std::vector<Shape> parse_minus(Section& b, const Shape& outer) {
  std::vector<Shape> minus;
  const toml::node* n = b.node("minus");
  if (!n) return minus;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    fail(b.key("minus"), show(*n),
         "must be an array of tables, each a shape to cut out: [[" + b.key("minus") + "]]");
  for (std::size_t k = 0; k < a->size(); ++k) {
    Section m(*(*a)[k].as_table(), fmt::format("{}[{}]", b.key("minus"), k),
              allowed_keys("bodies.*.minus[]"));
    minus.push_back(parse_shape(m, "cut-out"));
    if (!boxes_overlap(bounding_box(minus.back()), bounding_box(outer)))
      fail(m.key("shape"), fmt::format("\"{}\" spanning {}", shape_name(minus.back().kind),
                                       describe_extent(bounding_box(minus.back()))),
           fmt::format("the cut-out lies outside the body (which spans {}): it must overlap it",
                       describe_extent(bounding_box(outer))));
  }
  return minus;
}

// An array of three finite numbers.
void triple(Section& s, const std::string& k, double out[3], const char* form) {
  const toml::node* n = s.node(k);
  if (!n) return;
  const toml::array* a = n->as_array();
  bool ok = a && a->size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i) {
    const auto v = (*a)[i].value<double>();
    ok = v && std::isfinite(*v);
    if (ok) out[i] = *v;
  }
  if (!ok) fail(s.key(k), show(*n), fmt::format("must be an array of three finite numbers {}", form));
}

}  // namespace

void parse_bodies(Section& top, Case& c, ParseContext& ctx) {
  auto& material_index = ctx.material_index;
  Section bodies = top.table("bodies", true);
  const double tol = 1e-9 * c.grid.cell_size;
  for (const auto& [k, v] : named_entries(bodies)) {
    const std::string& name = k;
    Section b = bodies.table(name, true, allowed_keys("bodies.*"));
    BodySpec bs;
    bs.name = name;
    const std::string mat = b.string("material", "");
    if (mat.empty())
      fail(b.key("material"), b.has("material") ? "\"\"" : "(missing)",
           "required, the name of a [materials] entry");
    if (!material_index.count(mat)) {
      std::vector<std::string> names;
      for (const auto& m : c.materials) names.push_back(m.name);
      fail(b.key("material"), "\"" + mat + "\"", "must name a material: " + Section::join(names));
    }
    bs.material = material_index[mat];
    bs.region.outer = parse_shape(b, "body");
    if (bs.region.outer.kind == ShapeKind::rectangle)
      check_rectangle_body(b, bs.region.outer, c);
    else
      check_shape_inside_grid(b, bs.region.outer, c);
    const Box box = bounding_box(bs.region.outer);
    for (int d = 0; d < 2; ++d) bs.min[d] = box.min[d], bs.max[d] = box.max[d];
    bs.region.minus = parse_minus(b, bs.region.outer);
    b.pair("velocity", bs.velocity, false);
    triple(b, "stress", bs.stress, "[sxx, syy, sxy] (Pa)");
    const std::string field = b.string("field", name);
    if (field.empty())
      fail(b.key("field"), "\"\"", "must name a velocity field (bodies sharing one are one "
                                   "continuum); by default the body's own name");
    check_name(b.key("field"), field);
    const auto f = std::find(c.field_names.begin(), c.field_names.end(), field);
    bs.field = int(f - c.field_names.begin());
    if (f == c.field_names.end()) {
      if (c.field_names.size() == 255)
        fail(b.key("field"), "\"" + field + "\"",
             "at most 255 velocity fields: let bodies that form one continuum share a field");
      c.field_names.push_back(field);
    }
    ctx.body_parts[name] = {int(c.bodies.size())};
    c.bodies.push_back(bs);
  }
  if (c.bodies.empty()) fail("bodies", "{}", "at least one body is required");
  // Plain rectangles overlap when their boxes do; other shapes are checked on their particles
  // once the grid is known (check_body_seeding).
  for (std::size_t i = 0; i < c.bodies.size(); ++i)
    for (std::size_t j = i + 1; j < c.bodies.size(); ++j) {
      const BodySpec &a = c.bodies[i], &b = c.bodies[j];
      if (!a.plain_rectangle() || !b.plain_rectangle()) continue;
      const double ox = std::min(a.max[0], b.max[0]) - std::max(a.min[0], b.min[0]);
      const double oy = std::min(a.max[1], b.max[1]) - std::max(a.min[1], b.min[1]);
      if (ox > tol && oy > tol)
        fail("bodies." + b.name, "\"" + b.name + "\"",
             "overlaps bodies." + a.name + "; bodies must not overlap");
    }
}

const std::vector<int>& named_bodies(Section& s, const std::string& key, const std::string& name,
                                     const Case& c, const ParseContext& ctx) {
  const auto it = ctx.body_parts.find(name);
  if (it != ctx.body_parts.end()) return it->second;
  // The bodies' names in input order, then the names of parts made by splits.
  std::vector<std::string> names;
  for (const BodySpec& b : c.bodies) names.push_back(b.name);
  for (const auto& [n, parts] : ctx.body_parts)
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  std::string hint;
  std::size_t best = 3;  // a hint only for a near miss (at most 2 edits), as for unknown keys
  for (const std::string& n : names)
    if (const std::size_t d = edit_distance(name, n); d < best) best = d, hint = n;
  fail(s.key(key), "\"" + name + "\"",
       "must name a body among " + Section::join(names) +
           (hint.empty() ? "" : " (did you mean \"" + hint + "\"?)"));
}

int single_body(Section& s, const std::string& key, const Case& c, const ParseContext& ctx) {
  const std::string name = s.string(key, "");
  const std::vector<int>& parts = named_bodies(s, key, name, c, ctx);
  if (parts.size() == 1) return parts[0];
  std::vector<std::string> names;
  for (const int p : parts) names.push_back(c.bodies[std::size_t(p)].name);
  fail(s.key(key), "\"" + name + "\"",
       fmt::format("bodies.{} has been split along a line inside it into {}: name the part on "
                   "this side of the interface",
                   name, Section::join(names)));
}

void check_bodies_on_graded_grid(const Case& c) {
  if (!c.grid.refined()) return;
  // Rectangular bodies fill whole cells of the graded grid: their edges must be grid lines.
  const Grid grid = build_grid(c.grid);
  const Axis* axes[2] = {&grid.x, &grid.y};
  for (const BodySpec& b : c.bodies) {
    if (b.region.outer.kind != ShapeKind::rectangle) continue;
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
}

void check_body_seeding(const Case& c) {
  const Grid grid = build_grid(c.grid);
  const int ppc = c.grid.particles_per_cell;
  for (const BodySpec& b : c.bodies) {
    if (b.plain_rectangle()) continue;  // whole cells on grid lines: never empty
    // Particles of the outer shape, and how many each cut-out removes.
    long kept = 0;
    std::vector<long> removed(b.region.minus.size(), 0);
    const Region uncut{b.region.outer, {}, b.region.sides};  // the body before its cut-outs
    for_each_seed_point(grid, uncut, ppc, [&](const SeedPoint& s) {
      bool in_hole = false;
      for (std::size_t k = 0; k < b.region.minus.size(); ++k)
        if (contains(b.region.minus[k], s.x, s.y)) ++removed[k], in_hole = true;
      if (!in_hole) ++kept;
    });
    for (std::size_t k = 0; k < removed.size(); ++k)
      if (removed[k] == 0)
        fail(fmt::format("bodies.{}.minus[{}]", b.name, k),
             fmt::format("\"{}\" spanning {}", shape_name(b.region.minus[k].kind),
                         describe_extent(bounding_box(b.region.minus[k]))),
             fmt::format("the cut-out removes no particle of the body: it holds no sub-cell centre "
                         "of it ({} x {} per cell); make it larger or refine the grid",
                         ppc, ppc));
    if (kept == 0)
      fail("bodies." + b.name, "\"" + b.name + "\"",
           fmt::format("the body holds no particle: no sub-cell centre ({} x {} per cell, cells "
                       "of {:g} m) lies inside it; make it larger or refine the grid",
                       ppc, ppc, c.grid.cell_size));
  }
  // Overlap involving a shape other than a plain rectangle: a particle of one body inside the
  // other (parse_bodies checked rectangle pairs).
  for (std::size_t i = 0; i < c.bodies.size(); ++i)
    for (std::size_t j = i + 1; j < c.bodies.size(); ++j) {
      const BodySpec &a = c.bodies[i], &b = c.bodies[j];
      if (a.plain_rectangle() && b.plain_rectangle()) continue;
      if (!boxes_overlap(bounding_box(a.region), bounding_box(b.region))) continue;
      bool found = false;
      Point where;
      for_each_seed_point(grid, a.region, ppc, [&](const SeedPoint& s) {
        if (!found && contains(b.region, s.x, s.y)) found = true, where = {s.x, s.y};
      });
      if (found)
        fail("bodies." + b.name, "\"" + b.name + "\"",
             fmt::format("overlaps bodies.{} (both hold the particle at ({:g}, {:g}) m); bodies "
                         "must not overlap",
                         a.name, where.x, where.y));
    }
}

}  // namespace rupture
