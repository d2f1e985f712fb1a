// rupture/input/parse_fault.cpp
// law = "slip_weakening" in an [interface] table: the fault's friction and initial traction, its
// stretches (nucleation patch, stress patches, barriers) and the check that some of it holds
// (docs/faults.md).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <variant>

#include "cohesive/interface.hpp"
#include "cohesive/polyline.hpp"
#include "input/case_parse.hpp"
#include "input/input_schema.hpp"
#include "material/elastic.hpp"

namespace rupture {

namespace {

// The slip-weakening keys of table f on top of `law` (an interface, or a stretch overriding
// its interface's values).
void read_slip_weakening(Section& f, SlipWeakening& law) {
  law.static_friction = f.number("static_friction", law.static_friction);
  law.dynamic_friction = f.number("dynamic_friction", law.dynamic_friction);
  law.dc = f.number("dc", law.dc);
  law.cohesion = f.number("cohesion", law.cohesion);
  law.normal_stiffness = f.number("normal_stiffness", law.normal_stiffness);
  law.stick_stiffness = f.number("stick_stiffness", law.stick_stiffness);
  double t0[2] = {law.tn0, law.tt0};
  f.pair("initial_traction", t0, false);
  law.tn0 = t0[0], law.tt0 = t0[1];
  fail_on_invalid(f, law.validate(), {{"tn0", "initial_traction"}, {"tt0", "initial_traction"}});
}

// A stretch end [x, y]: projected on the line, its arc length from the line's start (m); it
// must lie on the line (within half a cell).
double stretch_end(Section& f, const std::string& key, const Polyline& line, const Case& c) {
  double p[2];
  f.pair(key, p, true);
  const LineProjection q = project(line, p[0], p[1]);
  if (q.distance > 0.5 * c.grid.cell_size)
    fail(f.key(key), fmt::format("[{:g}, {:g}]", p[0], p[1]),
         fmt::format("must lie on the interface's line (it is {:g} m away; allowed: half a cell, "
                     "{:g} m)",
                     q.distance, 0.5 * c.grid.cell_size));
  return q.s;
}

// interface.NAME.stretches: an array of tables, each a stretch [from, to] of the line with
// its own law parameters (those not given are the interface's).
void parse_stretches(Section& f, InterfaceSpec& is, const Case& c) {
  const toml::node* n = f.node("stretches");
  if (!n) return;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    fail(f.key("stretches"), show(*n),
         "must be an array of tables [[" + f.key("stretches") + "]], each with from, to and "
         "the law parameters that differ there");
  const Polyline line = is.geometry();
  for (std::size_t k = 0; k < a->size(); ++k) {
    Section st(*(*a)[k].as_table(), fmt::format("{}[{}]", f.key("stretches"), k),
               allowed_keys("interface.*.stretches[]"));
    LawStretch ls;
    ls.from = stretch_end(st, "from", line, c);
    ls.to = stretch_end(st, "to", line, c);
    if (ls.to < ls.from) std::swap(ls.from, ls.to);
    if (!(ls.to > ls.from))
      fail(st.key("to"), show(*st.node("to")), "must differ from `from`: a stretch has a length");
    SlipWeakening law = std::get<SlipWeakening>(is.law);
    read_slip_weakening(st, law);
    ls.law = law;
    is.stretches.push_back(ls);
  }
}

// A fault whose prestress exceeds its static strength everywhere has nothing to nucleate from
// and nothing to stop it: it is an input mistake, not a rupture.
// `overstressed = true` says it is meant (the 1D slip-weakening test: the whole fault starts
// sliding at once).
void check_prestress(Section& f, const InterfaceSpec& is) {
  if (f.boolean("overstressed", false)) return;
  // Gauss point by Gauss point without making the interface (a line of 1e7 segments would
  // allocate gigabytes before the memory check).
  bool below = false;
  for_each_gauss_point_law(is, [&](std::uint16_t w) {
    const SlipWeakening& L = w == 0 ? std::get<SlipWeakening>(is.law)
                                    : std::get<SlipWeakening>(is.stretches[w - 1u].law);
    below = std::fabs(L.tt0) <= L.static_strength();
    return !below;
  });
  if (below) return;
  const SlipWeakening& L = std::get<SlipWeakening>(is.law);
  fail(f.key("initial_traction"), fmt::format("[{:g}, {:g}]", L.tn0, L.tt0),
       fmt::format("the initial shear traction exceeds the static strength (cohesion + "
                   "static_friction x compression = {:g} Pa) everywhere on the fault: give it "
                   "below that outside a nucleation stretch, or set overstressed = true if the "
                   "whole fault is meant to start sliding",
                   L.static_strength()));
}

}  // namespace

// law = "slip_weakening": friction on a prestressed fault (cohesive/slip_weakening.hpp).
void parse_fault_law(Section& f, const Case& c, InterfaceSpec& is) {
  SlipWeakening law;
  for (const char* k : {"static_friction", "dynamic_friction", "dc"})
    if (!f.has(k)) fail(f.key(k), "(missing)", "required with law = \"slip_weakening\"");
  law.normal_stiffness = law.stick_stiffness = cell_penalty_stiffness(c, is);  // kn = kt = M / h
  read_slip_weakening(f, law);
  is.law = law;
  parse_stretches(f, is, c);
  check_prestress(f, is);
}

}  // namespace rupture
