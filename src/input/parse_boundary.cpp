// rupture/input/parse_boundary.cpp
// The [boundary] table: prescribed velocities on domain edges (theory E2).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "input/case_parse.hpp"
#include "input/input_schema.hpp"

namespace rupture {

void parse_boundary(Section& top, Case& c, ParseContext& ctx) {
  Section bcs = top.table("boundary", false);
  for (const auto& [k, v] : named_entries(bcs)) {
    const std::string& name = k;
    Section b = bcs.table(name, true, allowed_keys("boundary.*"));
    VelocityBC bc;
    bc.name = name;
    const std::string edge = b.string("edge", "", {"left", "right", "bottom", "top"});
    bc.edge = edge == "left"     ? Edge::left
              : edge == "right"  ? Edge::right
              : edge == "bottom" ? Edge::bottom
                                 : Edge::top;
    const bool vertical = bc.edge == Edge::left || bc.edge == Edge::right;
    const int along = vertical ? 1 : 0;
    const double lo = c.grid.min[along], hi = c.grid.max[along];
    bc.from = b.number("from", lo);
    bc.to = b.number("to", hi);
    const std::string coord = vertical ? "y" : "x";
    if (!(bc.from <= bc.to))
      fail(b.key("to"), bc.to, fmt::format("must be >= {} = {:g}", b.key("from"), bc.from));
    const double tol = 1e-9 * c.grid.cell_size;
    if (!inside(bc.from, lo, hi, tol))
      fail(b.key("from"), bc.from,
           fmt::format("must lie on the {} edge: {} in [{:g}, {:g}] m", edge, coord, lo, hi));
    if (!inside(bc.to, lo, hi, tol))
      fail(b.key("to"), bc.to,
           fmt::format("must lie on the {} edge: {} in [{:g}, {:g}] m", edge, coord, lo, hi));
    const std::string comp = b.string("component", "", {"x", "y"});
    bc.component = comp == "x" ? 0 : 1;
    for (const std::string& body : b.strings("bodies"))
      // Conditions act on velocity fields: a body's field (once, if bodies share one), the
      // fields of all its parts if a line inside it split it.
      for (const int part : named_bodies(b, "bodies", body, c, ctx)) {
        const int field = c.bodies[std::size_t(part)].field;
        if (std::find(bc.fields.begin(), bc.fields.end(), field) == bc.fields.end())
          bc.fields.push_back(field);
      }
    bc.velocity = parse_time_function(b, "velocity", {"boundary", name}, ctx);
    bc.follow_edge = b.boolean("follow_edge", true);
    if (b.has("follow_edge") && !bc.normal())
      fail(b.key("follow_edge"), show(*b.node("follow_edge")),
           fmt::format("only applies to the velocity component normal to the {} edge ({})", edge,
                       vertical ? "x" : "y"));
    c.boundary.push_back(bc);
  }
}

void set_automatic_margin(Case& c) {
  if (c.grid.margin >= 0.0) return;  // given
  // Automatic ghost margin (GridSpec::margin): the largest displacement of any prescribed or
  // initial velocity over the run. 1000 samples of a piecewise-linear V miss nothing that matters.
  double m = 0.0;
  for (const VelocityBC& bc : c.boundary)
    for (int k = 1; k <= 1000; ++k)
      m = std::max(m, std::fabs(bc.velocity.displacement(c.time.end * k / 1000.0)));
  for (const VelocityRegion& r : c.loads.velocity_regions)
    for (int k = 1; k <= 1000; ++k)
      m = std::max(m, std::fabs(r.displacement(c.time.end * k / 1000.0)));
  for (const BodySpec& b : c.bodies)
    m = std::max(m, std::hypot(b.velocity[0], b.velocity[1]) * c.time.end);
  // A traction T f(t) on a surface drives it at the plane-wave speed T f / (rho c_D) of the
  // most compliant material (the lowest impedance): it moves by T F(t) / (rho c_D), F the
  // integral of f. A body force g f(t) moves a free body by at most |g| F(t) t.
  double impedance = INFINITY;  // rho c_D, Pa s/m
  for (const ElasticMaterial& mat : c.materials)
    impedance = std::min(impedance, mat.density * wave_speeds(mat, c.plane).dilatational);
  for (const TractionLoad& l : c.loads.tractions) {
    const double T = l.global ? std::hypot(l.traction[0], l.traction[1]) : std::hypot(l.normal, l.shear);
    for (int k = 1; k <= 1000; ++k)
      m = std::max(m, T * std::fabs(l.factor.displacement(c.time.end * k / 1000.0)) / impedance);
  }
  for (const BodyForceLoad& l : c.loads.body_forces) {
    const double g = std::hypot(l.acceleration[0], l.acceleration[1]);
    for (int k = 1; k <= 1000; ++k) {
      const double t = c.time.end * k / 1000.0;
      m = std::max(m, g * std::fabs(l.factor.displacement(t)) * t);
    }
  }
  // Capped like an explicit grid.margin: a long run with a constant velocity would otherwise
  // ask for an unbounded grid; a surface moving farther is caught as "particle left the grid".
  c.grid.margin = std::min(m, c.grid.max_margin());
}

// [absorbing] edges = ["left", ...]: dashpot edges (bc/absorbing.hpp). An edge that is also
// driven by a [boundary] condition is an error: the dashpot would fight the prescribed motion.
void parse_absorbing(Section& top, Case& c) {
  Section a = top.table("absorbing", false, allowed_keys("absorbing"));
  if (!top.has("absorbing")) return;
  const std::vector<std::string> names = a.strings("edges");
  if (names.empty()) fail(a.key("edges"), "(missing)", "required: a non-empty array of edges");
  for (const std::string& n : names) {
    Edge e;
    if (n == "left") e = Edge::left;
    else if (n == "right") e = Edge::right;
    else if (n == "bottom") e = Edge::bottom;
    else if (n == "top") e = Edge::top;
    else fail(a.key("edges"), "\"" + n + "\"", "each must be one of \"left\", \"right\", \"bottom\", \"top\"");
    if (std::find(c.absorbing_edges.begin(), c.absorbing_edges.end(), e) != c.absorbing_edges.end())
      fail(a.key("edges"), "\"" + n + "\"", "lists an edge twice");
    for (const VelocityBC& bc : c.boundary)
      if (bc.edge == e)
        fail(a.key("edges"), "\"" + n + "\"",
             fmt::format("the {} edge is driven by boundary.{}: an absorbing edge cannot also "
                         "have a prescribed velocity",
                         n, bc.name));
    c.absorbing_edges.push_back(e);
  }
}

}  // namespace rupture
