// rupture/input/parse_loads.cpp
// The [loads] table (bc/loads.hpp, docs/loads.md): tractions on surface segments, body forces,
// prescribed velocities of material regions, point forces, each with a dimensionless time
// function.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geometry/shape.hpp"
#include "input/case_parse.hpp"
#include "input/input_schema.hpp"

namespace rupture {

namespace {

std::string show_pair(const double v[2]) { return fmt::format("[{:g}, {:g}]", v[0], v[1]); }

// A point of the physical domain (grid.min..grid.max), with a round-off tolerance.
void check_in_domain(Section& l, const std::string& key, const double p[2], const Case& c) {
  const double tol = 1e-9 * c.grid.cell_size;
  for (int d = 0; d < 2; ++d)
    if (!inside(p[d], c.grid.min[d], c.grid.max[d], tol))
      fail(l.key(key), show_pair(p),
           fmt::format("must lie in the grid domain [{:g}, {:g}]..[{:g}, {:g}] m", c.grid.min[0],
                       c.grid.min[1], c.grid.max[0], c.grid.max[1]));
}

std::vector<int> body_fields(Section& l, const Case& c, ParseContext& ctx) {
  std::vector<int> fields;
  for (const std::string& body : l.strings("bodies"))
    // Loads act on velocity fields: a body's field (once, if bodies share one), the fields of
    // all its parts if a line inside it split it, as for [boundary] conditions. (Particles
    // carry the field number, not the body index.)
    for (const int part : named_bodies(l, "bodies", body, c, ctx)) {
      const int field = c.bodies[std::size_t(part)].field;
      if (std::find(fields.begin(), fields.end(), field) == fields.end()) fields.push_back(field);
    }
  return fields;
}

}  // namespace

void parse_loads(Section& top, Case& c, ParseContext& ctx) {
  Section loads = top.table("loads", false);
  for (const auto& [k, v] : named_entries(loads)) {
    const std::string& name = k;
    Section probe = loads.table(name, true);
    const std::string type = probe.string("type", "", {"traction", "body_force", "velocity", "point_force"});
    Section l = loads.table(name, true, allowed_keys("loads.*", "type", type));
    const TimeFunction factor = parse_time_function(l, "", {"loads", name}, ctx);
    if (type == "traction") {
      TractionLoad t;
      t.name = name;
      t.factor = factor;
      l.pair("from", t.from, true);
      l.pair("to", t.to, true);
      check_in_domain(l, "from", t.from, c);
      check_in_domain(l, "to", t.to, c);
      const double length = std::hypot(t.to[0] - t.from[0], t.to[1] - t.from[1]);
      if (!(length > 1e-6 * c.grid.cell_size))
        fail(l.key("to"), show_pair(t.to),
             fmt::format("must differ from {} = {}: the segment has length {:g} m", l.key("from"),
                         show_pair(t.from), length));
      const bool framed = l.has("normal") || l.has("shear");
      if (l.has("traction") && framed)
        fail(l.key("traction"), show(*l.node("traction")),
             fmt::format("give either {} = [tx, ty] (global, Pa) or {} and/or {} (segment frame, "
                         "Pa), not both",
                         l.key("traction"), l.key("normal"), l.key("shear")));
      if (!l.has("traction") && !framed)
        fail(l.key("traction"), "(missing)",
             fmt::format("required: {} = [tx, ty] (global, Pa), or {} and/or {} (segment frame, Pa)",
                         l.key("traction"), l.key("normal"), l.key("shear")));
      t.global = !framed;
      l.pair("traction", t.traction, false);
      t.normal = l.number("normal", 0.0);
      t.shear = l.number("shear", 0.0);
      t.fields = body_fields(l, c, ctx);
      c.loads.tractions.push_back(t);
    } else if (type == "body_force") {
      BodyForceLoad b;
      b.name = name;
      b.factor = factor;
      l.pair("acceleration", b.acceleration, true);
      b.fields = body_fields(l, c, ctx);
      c.loads.body_forces.push_back(b);
    } else if (type == "point_force") {
      PointForceLoad f;
      f.name = name;
      f.factor = factor;
      l.pair("point", f.point, true);
      check_in_domain(l, "point", f.point, c);
      l.pair("force", f.force, true);
      f.fields = body_fields(l, c, ctx);
      // Inside a body it may act on (the particles there: solver/load_step.cpp).
      bool inside_one = false;
      for (const BodySpec& body : c.bodies)
        if (f.fields.empty() || std::count(f.fields.begin(), f.fields.end(), body.field) > 0)
          inside_one = inside_one || contains(body.region, f.point[0], f.point[1]);
      if (!inside_one)
        fail(l.key("point"), show_pair(f.point),
             f.fields.empty() ? "lies outside every body: a point force must act inside material"
                              : "lies outside the bodies it names: a point force must act inside "
                                "their material");
      c.loads.point_forces.push_back(f);
    } else {
      VelocityRegion r;
      r.name = name;
      r.factor = factor;
      l.pair("min", r.min, true);
      l.pair("max", r.max, true);
      check_in_domain(l, "min", r.min, c);
      check_in_domain(l, "max", r.max, c);
      for (int d = 0; d < 2; ++d)
        if (!(r.max[d] > r.min[d]))
          fail(l.key("max"), show_pair(r.max),
               fmt::format("the region is empty: must exceed {} = {} in both components",
                           l.key("min"), show_pair(r.min)));
      double dir[2] = {0.0, 0.0};
      l.pair("direction", dir, true);
      const double norm = std::hypot(dir[0], dir[1]);
      if (!(norm > 0.0))
        fail(l.key("direction"), show_pair(dir), "must be a nonzero vector [dx, dy]");
      r.direction[0] = dir[0] / norm, r.direction[1] = dir[1] / norm;
      r.speed = l.number("velocity");
      r.fields = body_fields(l, c, ctx);
      c.loads.velocity_regions.push_back(r);
    }
  }
}

}  // namespace rupture
