// rupture/input/parse_fault.cpp
// The fault laws of an [interface] table, law = "slip_weakening" and law = "rate_state": the
// fault's friction and initial traction, its stretches (nucleation patch, stress patches,
// barriers, the rate-and-state parameters along strike), the slip-weakening check that some of
// it holds and the rate-and-state initial state and nucleation stress (docs/faults.md).
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>
#include <cmath>
#include <optional>
#include <utility>
#include <variant>

#include "cohesive/interface.hpp"
#include "cohesive/polyline.hpp"
#include "input/case_parse.hpp"
#include "input/input_schema.hpp"
#include "material/elastic.hpp"

namespace rupture {

namespace {

bool has(const std::vector<std::string>& keys, const std::string& k) {
  return std::find(keys.begin(), keys.end(), k) != keys.end();
}

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

// The stretch keys each fault law reads (a stretch of the other law's keys is refused, not
// ignored).
const std::vector<std::string>& stretch_keys(bool rate_state) {
  static const std::vector<std::string> sw = {"static_friction", "dynamic_friction", "dc", "cohesion",
                                              "initial_traction", "normal_stiffness", "stick_stiffness"};
  static const std::vector<std::string> rs = {"a", "b", "dc", "reference_friction", "weakened_friction",
                                              "weakening_slip_rate", "initial_traction",
                                              "normal_stiffness", "stick_stiffness"};
  return rate_state ? rs : sw;
}

// interface.NAME.stretches: an array of tables, each a stretch [from, to] of the line with
// its own law parameters (those not given are the interface's), read by `read` on top of a
// copy of the interface's law.
template <class Law, class Read>
void parse_stretches(Section& f, InterfaceSpec& is, const Case& c, Read read) {
  const toml::node* n = f.node("stretches");
  if (!n) return;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    fail(f.key("stretches"), show(*n),
         "must be an array of tables [[" + f.key("stretches") + "]], each with from, to and "
         "the law parameters that differ there");
  const Polyline line = is.geometry();
  constexpr bool rate_state = std::is_same_v<Law, RateStateFriction>;
  for (std::size_t k = 0; k < a->size(); ++k) {
    Section st(*(*a)[k].as_table(), fmt::format("{}[{}]", f.key("stretches"), k),
               allowed_keys("interface.*.stretches[]"));
    for (const std::string& key : stretch_keys(!rate_state))
      if (st.has(key) && !has(stretch_keys(rate_state), key))
        fail(st.key(key), show(*st.node(key)),
             fmt::format("not a parameter of law = \"{}\"", Law::kName));
    LawStretch ls;
    ls.from = stretch_end(st, "from", line, c);
    ls.to = stretch_end(st, "to", line, c);
    if (ls.to < ls.from) std::swap(ls.from, ls.to);
    if (!(ls.to > ls.from))
      fail(st.key("to"), show(*st.node("to")), "must differ from `from`: a stretch has a length");
    Law law = std::get<Law>(is.law);
    read(st, law);
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

// interface.NAME.normal_relaxation and its scales (cohesive/normal_relaxation.hpp), for the
// whole fault: a stretch keeps its interface's. A scale of the other form is refused rather
// than ignored; with "none" the scales are kept unused (one key switches it off).
NormalRelaxation read_relaxation(Section& f) {
  NormalRelaxation r;
  const std::string form = f.string("normal_relaxation", "none", {"none", "time", "slip"});
  r.form = form == "time"   ? RelaxationForm::time
           : form == "slip" ? RelaxationForm::slip
                            : RelaxationForm::none;
  const std::vector<std::string> keys =
      r.form == RelaxationForm::time   ? std::vector<std::string>{"normal_relaxation_time"}
      : r.form == RelaxationForm::slip ? std::vector<std::string>{"normal_relaxation_slip",
                                                                  "normal_relaxation_rate"}
                                       : std::vector<std::string>{};
  for (const char* k : {"normal_relaxation_time", "normal_relaxation_slip", "normal_relaxation_rate"}) {
    if (has(keys, k) && !f.has(k))
      fail(f.key(k), "(missing)", fmt::format("required with normal_relaxation = \"{}\"", form));
    // With "none" the scales may stay (unused), so that one key switches the regularization off.
    if (!has(keys, k) && f.has(k) && r.form != RelaxationForm::none)
      fail(f.key(k), show(*f.node(k)),
           fmt::format("not a parameter of normal_relaxation = \"{}\" (time: "
                       "normal_relaxation_time; slip: normal_relaxation_slip and "
                       "normal_relaxation_rate)",
                       form));
  }
  r.time = f.number("normal_relaxation_time", 0.0);
  r.slip = f.number("normal_relaxation_slip", 0.0);
  r.rate = f.number("normal_relaxation_rate", 0.0);
  fail_on_invalid(f, r.validate(), {});
  return r;
}

}  // namespace

// law = "slip_weakening": friction on a prestressed fault (cohesive/slip_weakening.hpp).
void parse_fault_law(Section& f, const Case& c, InterfaceSpec& is) {
  SlipWeakening law;
  for (const char* k : {"static_friction", "dynamic_friction", "dc"})
    if (!f.has(k)) fail(f.key(k), "(missing)", "required with law = \"slip_weakening\"");
  law.normal_stiffness = law.stick_stiffness = cell_penalty_stiffness(c, is);  // kn = kt = M / h
  law.relaxation = read_relaxation(f);
  read_slip_weakening(f, law);
  is.law = law;
  parse_stretches<SlipWeakening>(f, is, c, read_slip_weakening);
  check_prestress(f, is);
}

namespace {

// The rate-and-state keys of table f on top of `law` (an interface, or a stretch overriding its
// interface's values); then the initial state from the balance of the initial traction.
void read_rate_state(Section& f, RateStateFriction& law) {
  law.a = f.number("a", law.a);
  law.b = f.number("b", law.b);
  law.dc = f.number("dc", law.dc);
  law.f0 = f.number("reference_friction", law.f0);
  law.fw = f.number("weakened_friction", law.fw);
  law.vw = f.number("weakening_slip_rate", law.vw);
  law.normal_stiffness = f.number("normal_stiffness", law.normal_stiffness);
  law.stick_stiffness = f.number("stick_stiffness", law.stick_stiffness);
  double t0[2] = {law.tn0, law.tt0};
  f.pair("initial_traction", t0, false);
  law.tn0 = t0[0], law.tt0 = t0[1];
  law.initialize_state();
  fail_on_invalid(f, law.validate(), {});  // its messages name the input keys (taper.*: f's)
}

// One table of [interface.NAME.profile]: [[coordinate, value], ...], at least two points,
// coordinates strictly increasing, values > 0 and finite.
ProfileTable read_profile_table(Section& p, const std::string& k) {
  ProfileTable t;
  const toml::node* n = p.node(k);
  if (!n) return t;
  const std::string rule = "must be an array of [coordinate, value] pairs of finite numbers, "
                           "coordinates increasing strictly, values > 0";
  const toml::array* a = n->as_array();
  if (!a) fail(p.key(k), show(*n), rule);
  for (std::size_t r = 0; r < a->size(); ++r) {
    const toml::array* row = (*a)[r].as_array();
    const auto u = row && row->size() == 2 ? (*row)[0].value<double>() : std::nullopt;
    const auto v = row && row->size() == 2 ? (*row)[1].value<double>() : std::nullopt;
    if (!u || !v || !std::isfinite(*u) || !std::isfinite(*v) || !(*v > 0.0))
      fail(p.key(k), show(*n), fmt::format("{}; row {} is not", rule, r + 1));
    if (!t.at.empty() && !(*u > t.at.back()))
      fail(p.key(k), show(*n),
           fmt::format("{}; row {} has coordinate {:g} m after {:g} m", rule, r + 1, *u, t.at.back()));
    t.at.push_back(*u), t.value.push_back(*v);
  }
  if (t.at.size() < 2)
    fail(p.key(k), show(*n), fmt::format("a profile needs at least two points (it has {})", t.at.size()));
  return t;
}

// [interface.NAME.profile]: a, b, dc, weakening_slip_rate tabulated along x, y or the arc
// length s (cohesive/fault_profile.hpp). A tabulated parameter may not be tapered too, nor set
// by a stretch (which would be ignored).
void read_profile(Section& f, InterfaceSpec& is, const RateStateFriction& law) {
  Section p = f.table("profile", false, allowed_keys("interface.*.profile"));
  RateStateProfile& prof = is.profile;
  const std::string along = p.string("along", "", {"x", "y", "s"});
  prof.along = along == "x" ? ProfileAxis::x : along == "y" ? ProfileAxis::y : ProfileAxis::s;
  prof.a = read_profile_table(p, "a");
  prof.b = read_profile_table(p, "b");
  prof.dc = read_profile_table(p, "dc");
  prof.vw = read_profile_table(p, "weakening_slip_rate");
  if (!prof.on())
    fail(f.key("profile"), "{...}", "needs at least one of a, b, dc, weakening_slip_rate");
  if (prof.vw.on() && law.evolution != StateEvolution::flash_heating)
    fail(p.key("weakening_slip_rate"), show(*p.node("weakening_slip_rate")),
         "only with evolution = \"flash_heating\"");
  const struct {
    const char* key;
    bool tabulated;
    double tapered;
  } params[] = {{"a", prof.a.on(), law.taper.a}, {"b", prof.b.on(), law.taper.b},
                {"dc", prof.dc.on(), law.taper.dc}, {"weakening_slip_rate", prof.vw.on(), law.taper.vw}};
  for (const auto& q : params)
    if (q.tabulated && law.taper.on && q.tapered > 0.0)
      fail(p.key(q.key), show(*p.node(q.key)),
           fmt::format("{} is also tapered ({}.{}): give it one way", q.key, f.key("taper"), q.key));
  if (const toml::node* n = f.node("stretches"); n && n->as_array())
    for (std::size_t k = 0; k < n->as_array()->size(); ++k)
      if (const toml::table* st = (*n->as_array())[k].as_table())
        for (const auto& q : params)
          if (q.tabulated && st->contains(q.key))
            fail(fmt::format("{}[{}].{}", f.key("stretches"), k, q.key), show(*st->get(q.key)),
                 fmt::format("{} is tabulated along the fault by {}.{}", q.key, f.key("profile"), q.key));
}

}  // namespace

// law = "rate_state": rate-and-state friction on a prestressed fault (cohesive/rate_state.hpp).
void parse_rate_state_law(Section& f, const Case& c, InterfaceSpec& is) {
  RateStateFriction law;
  for (const char* k : {"a", "b", "dc", "initial_slip_rate", "initial_traction"})
    if (!f.has(k)) fail(f.key(k), "(missing)", "required with law = \"rate_state\"");
  const std::string evolution = f.string("evolution", "aging", {"aging", "slip", "flash_heating"});
  law.evolution = evolution == "slip"    ? StateEvolution::slip
                  : evolution == "aging" ? StateEvolution::aging
                                         : StateEvolution::flash_heating;
  if (law.evolution == StateEvolution::flash_heating)
    for (const char* k : {"weakened_friction", "weakening_slip_rate"})
      if (!f.has(k)) fail(f.key(k), "(missing)", "required with evolution = \"flash_heating\"");
  law.v0 = f.number("reference_slip_rate", law.v0);
  law.v_init = f.number("initial_slip_rate");
  law.nucleation_stress = f.number("nucleation_stress", 0.0);
  double centre[2] = {0.0, 0.0};
  f.pair("nucleation_centre", centre, false);
  law.nucleation_x = centre[0], law.nucleation_y = centre[1];
  law.nucleation_radius = f.number("nucleation_radius", 0.0);
  law.nucleation_time = f.number("nucleation_time", 0.0);
  if (law.nucleation_stress == 0.0)
    for (const char* k : {"nucleation_centre", "nucleation_radius", "nucleation_time"})
      if (f.has(k))
        fail(f.key(k), show(*f.node(k)), "needs nucleation_stress (the stress it shapes)");
  law.normal_stiffness = law.stick_stiffness = cell_penalty_stiffness(c, is);  // kn = kt = M / h
  law.relaxation = read_relaxation(f);
  if (f.has("taper")) {  // [interface.NAME.taper]: TPV101-103's smooth taper
    Section t = f.table("taper", false, allowed_keys("interface.*.taper"));
    RateStateTaper& tp = law.taper;
    tp.on = true;
    double at[2] = {0.0, 0.0};
    t.pair("centre", at, true);
    tp.x = at[0], tp.y = at[1];
    tp.half_width = t.number("half_width");
    tp.width = t.number("width");
    tp.a = t.number("a", 0.0), tp.b = t.number("b", 0.0), tp.dc = t.number("dc", 0.0);
    tp.vw = t.number("weakening_slip_rate", 0.0);
  }
  read_rate_state(f, law);
  is.law = law;
  if (f.has("profile")) read_profile(f, is, law);
  parse_stretches<RateStateFriction>(f, is, c, read_rate_state);
}

}  // namespace rupture
