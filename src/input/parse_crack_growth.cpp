// rupture/input/parse_crack_growth.cpp
// The keys of an [interface] table that make a crack read and grow its tips (docs/fracture.md):
// stress_intensity and j_domains (fracture/j_integral.hpp), drawn_open, growth and its
// criterion's parameters (fracture/growth_criterion.hpp; solver/crack_growth.hpp), branching
// (fracture/branching_criterion.hpp; solver/crack_branching.hpp) and the fields its branches'
// wedges will take. Each refuses, by its key, what the crack's law or grid cannot do.
#include <fmt/format.h>

#include <variant>

#include "cohesive/interface.hpp"
#include "cohesive/interface_growth.hpp"
#include "cohesive/polyline.hpp"
#include "input/case_parse.hpp"
#include "input/input_schema.hpp"
#include "fracture/running_tip_field.hpp"
#include "material/elastic.hpp"

namespace rupture {
namespace {

// Whether the interface's law is a crack's cohesive law (Xu-Needleman or bilinear; not contact,
// which has no cohesion, nor a fault's friction).
bool cohesive_crack_law(const InterfaceSpec& is) {
  return !is.precracked && (std::holds_alternative<XuNeedleman>(is.law) || std::holds_alternative<BilinearLaw>(is.law));
}

// branching, max_branches (fracture/branching_criterion.hpp; solver/crack_branching.hpp).
void parse_branching(Section& f, GrowthLaw& g) {
  const std::string b = f.string("branching", "none", {"none", "yoffe"});
  g.branching = b == "yoffe" ? BranchCriterion::yoffe : BranchCriterion::none;
  if (g.branching == BranchCriterion::none) {
    if (f.has("max_branches"))
      fail(f.key("max_branches"), show(*f.node("max_branches")), "needs branching = \"yoffe\"");
    return;
  }
  if (g.criterion == GrowthCriterion::cohesive || g.criterion == GrowthCriterion::prescribed)
    fail(f.key("branching"), "\"" + b + "\"",
         "needs growth = \"energy\" or \"max_hoop\" (Yoffe's criterion reads the running tip's K field; "
         "the cohesive criterion reads the line's state)");
  const double n = f.number("max_branches", 1.0);
  if (!(n >= 1.0 && n <= 8.0 && n == std::floor(n)))
    fail(f.key("max_branches"), n,
         "must be a whole number from 1 to 8 (each branch event keeps a velocity field for the "
         "wedge between the two new tips)");
  g.max_branches = int(n);
}

}  // namespace

// stress_intensity, j_domains (fracture/j_integral.hpp): the domains' outer radii in cells,
// increasing, each at least 2 (the inner radius is half of it: a ring of at least a cell).
void parse_stress_intensity(Section& f, InterfaceSpec& is) {
  is.stress_intensity = f.boolean("stress_intensity", false);
  if (!f.has("j_domains")) return;
  const toml::node* growth = f.node("growth");
  const bool grows = growth && growth->value<std::string>().value_or("none") != "none";
  if (!is.stress_intensity && !grows)
    fail(f.key("j_domains"), show(*f.node("j_domains")), "needs stress_intensity = true (or growth)");
  const toml::array* a = f.node("j_domains")->as_array();
  const std::string rule = "must be an array of 1 to 8 increasing numbers >= 2 (the J domains' "
                           "outer radii, in cells)";
  if (!a || a->empty() || a->size() > 8) fail(f.key("j_domains"), show(*f.node("j_domains")), rule);
  is.j_domains.clear();
  for (const toml::node& n : *a) {
    const std::optional<double> v = n.value<double>();
    if (!v || !std::isfinite(*v) || *v < 2.0 || (!is.j_domains.empty() && *v <= is.j_domains.back()))
      fail(f.key("j_domains"), show(*f.node("j_domains")), rule);
    is.j_domains.push_back(*v);
  }
}

// drawn_open: a cohesive crack whose drawn line is a cut (its points start separated) and whose
// grown segments carry the law.
void parse_drawn_open(Section& f, InterfaceSpec& is) {
  is.drawn_open = f.boolean("drawn_open", false);
  if (!is.drawn_open) return;
  if (is.precracked)
    fail(f.key("drawn_open"), "true", "law = \"contact\" is open already (drawn_open is for a cohesive law: "
                                      "xu_needleman or bilinear)");
  if (!cohesive_crack_law(is))
    fail(f.key("drawn_open"), "true", "is for a crack's cohesive law (xu_needleman or bilinear), not a fault's friction");
}

// growth, toughness, fracture_energy, growth_direction, growth_step
// (fracture/growth_criterion.hpp; solver/crack_growth.hpp): a crack (law contact, or a cohesive
// law that its new segments carry) drawn inside one body, with at least one tip, on a uniform
// grid. Growth reads K at the tips, so it records them too (stress_intensity).
void parse_growth(Section& f, InterfaceSpec& is, const Case& c) {
  GrowthLaw& g = is.growth;
  const std::string criterion = f.string("growth", "none", {"none", "max_hoop", "energy", "cohesive", "prescribed"});
  g.criterion = criterion == "max_hoop"     ? GrowthCriterion::max_hoop
                : criterion == "energy"     ? GrowthCriterion::energy
                : criterion == "cohesive"   ? GrowthCriterion::cohesive
                : criterion == "prescribed" ? GrowthCriterion::prescribed
                                            : GrowthCriterion::none;
  if (!g.on()) {
    for (const char* key : {"toughness", "fracture_energy", "plane_fracture_energy", "growth_direction", "growth_step",
                            "branching", "max_branches", "running_tip", "growth_speed", "growth_start"})
      if (f.has(key)) fail(f.key(key), show(*f.node(key)), "needs growth = \"max_hoop\", \"energy\", \"cohesive\" or \"prescribed\"");
    return;
  }
  const std::string shown = "\"" + criterion + "\"";
  if (!is.precracked && !cohesive_crack_law(is))
    fail(f.key("growth"), shown,
         "grows a crack: needs law = \"contact\" (no cohesion), \"xu_needleman\" or \"bilinear\" "
         "(new segments carry the law); a fault's friction does not grow off its line");
  if (g.criterion == GrowthCriterion::cohesive && !std::holds_alternative<BilinearLaw>(is.law))
    fail(f.key("growth"), shown,
         "reads the crack's cohesive law (a new segment once the last is past its peak traction): "
         "needs law = \"bilinear\", whose elastic branch ends at lambda0 (Xu-Needleman's compliant "
         "rise lets the line lag its process zone, docs/fracture.md; grow it by \"energy\" or "
         "\"max_hoop\"); law = \"contact\" has no strength");
  if (!f.has("body"))
    fail(f.key("growth"), shown,
         fmt::format("grows a crack drawn inside one body: give '{}' (the body it lies in) instead "
                     "of upper_body and lower_body",
                     f.key("body")));
  if (c.grid.refined() && !c.grid.nested)
    fail(f.key("growth"), shown,
         "needs a uniform grid or nested levels (grid.refinement = \"nested\"): on a graded grid a "
         "grown segment, measured in cells, would change its length along the way");
  if (!is.stretches.empty())
    fail(f.key("growth"), shown, "is not allowed with stretches (their arc lengths would move as the crack grows)");
  if (precrack_tips(is, 1e-6 * c.grid.cell_size).empty())
    fail(f.key("growth"), shown,
         "needs a crack tip: an end of the line inside the body (the line runs from edge to edge, "
         "or is closed, so nothing is left to grow into)");
  auto refuse = [&](const char* key, const char* why) {
    if (f.has(key)) fail(f.key(key), show(*f.node(key)), why);
  };
  if (g.criterion == GrowthCriterion::max_hoop) {
    refuse("fracture_energy", "is for growth = \"energy\"; growth = \"max_hoop\" takes toughness");
    if (!f.has("toughness"))
      fail(f.key("toughness"), "(missing)", "required with growth = \"max_hoop\": K_Ic, Pa m^1/2, > 0");
    g.toughness = f.number("toughness", 0.0);
    if (!(g.toughness > 0.0) || !std::isfinite(g.toughness))
      fail(f.key("toughness"), g.toughness, "must be > 0 (K_Ic, Pa m^1/2)");
  } else if (g.criterion == GrowthCriterion::prescribed) {
    refuse("toughness", "is for growth = \"max_hoop\"; growth = \"prescribed\" takes growth_speed");
    refuse("fracture_energy", "is for growth = \"energy\"; growth = \"prescribed\" takes growth_speed");
    if (!f.has("growth_speed"))
      fail(f.key("growth_speed"), "(missing)", "required with growth = \"prescribed\": the tips' speed, m/s, > 0");
    g.speed = f.number("growth_speed", 0.0);
    if (!(g.speed > 0.0) || !std::isfinite(g.speed))
      fail(f.key("growth_speed"), g.speed, "must be > 0 (m/s)");
    g.start = f.number("growth_start", 0.0);
    if (!(g.start >= 0.0) || !std::isfinite(g.start)) fail(f.key("growth_start"), g.start, "must be >= 0 (s)");
  } else if (g.criterion == GrowthCriterion::cohesive) {
    refuse("toughness", "is for growth = \"max_hoop\"; growth = \"cohesive\" reads the law's strength");
    refuse("fracture_energy", "is for growth = \"energy\"; growth = \"cohesive\" reads the law's strength");
  } else {
    refuse("toughness", "is for growth = \"max_hoop\"; growth = \"energy\" takes fracture_energy");
    if (!f.has("fracture_energy"))
      fail(f.key("fracture_energy"), "(missing)", "required with growth = \"energy\": G_c, J/m^2, > 0");
    g.fracture_energy = f.number("fracture_energy", 0.0);
    if (!(g.fracture_energy > 0.0) || !std::isfinite(g.fracture_energy))
      fail(f.key("fracture_energy"), g.fracture_energy, "must be > 0 (G_c, J/m^2)");
  }
  const std::string dir = f.string("growth_direction", "max_hoop", {"max_hoop", "straight"});
  g.direction = dir == "straight" ? GrowthDirection::straight : GrowthDirection::max_hoop;
  if (f.has("plane_fracture_energy")) {
    if (g.criterion != GrowthCriterion::energy)
      fail(f.key("plane_fracture_energy"), show(*f.node("plane_fracture_energy")),
           "is a weak plane's G_c, weighed against fracture_energy: needs growth = \"energy\"");
    if (g.direction != GrowthDirection::max_hoop)
      fail(f.key("plane_fracture_energy"), show(*f.node("plane_fracture_energy")),
           "needs growth_direction = \"max_hoop\" (the way out of the plane it competes with)");
    g.plane_fracture_energy = f.number("plane_fracture_energy", 0.0);
    if (!(g.plane_fracture_energy > 0.0) || !std::isfinite(g.plane_fracture_energy))
      fail(f.key("plane_fracture_energy"), g.plane_fracture_energy, "must be > 0 (G_c of the weak plane, J/m^2)");
  }
  if (g.criterion != GrowthCriterion::prescribed) {
    refuse("growth_speed", "is for growth = \"prescribed\" (the tips' given speed)");
    refuse("growth_start", "is for growth = \"prescribed\" (when the tips start to run)");
  }
  g.step = f.number("growth_step", 0.5);
  if (!(g.step > 0.0 && g.step <= 0.5))
    fail(f.key("growth_step"), g.step,
         "must be in (0, 0.5] (cells): a tip grows at most half a cell at a time, so a segment "
         "never jumps over the grid nodes that carry the fields on either side");
  is.stress_intensity = true;
  parse_branching(f, g);
  is.running_tip = f.boolean("running_tip", false);
  if (is.running_tip && g.criterion == GrowthCriterion::energy && g.plane_fracture_energy > 0.0)
    fail(f.key("running_tip"), "true",
         "is not yet read by the weak plane's criterion (plane_fracture_energy): its kinked "
         "intensities are those of a stationary tip (Cotterell & Rice)");
  if (is.running_tip && g.criterion == GrowthCriterion::prescribed) {
    const BodySpec& b = c.bodies[std::size_t(is.upper_body)];
    const double cR = wave_speeds(c.materials[std::size_t(b.material)], c.plane).rayleigh;
    if (g.speed >= kRunningTipCap * cR)
      fail(f.key("growth_speed"), g.speed,
           fmt::format("must be below {:.4g} m/s ({} c_R of the body's material) with running_tip = true: "
                       "the running tip's field is singular at c_R = {:.4g} m/s", kRunningTipCap * cR,
                       kRunningTipCap, cR));
  }
}

// nucleation and nucleation_strength (solver/crack_nucleation.hpp): the drawn line stays intact
// until the normal stress across it reaches the strength, then it is the crack and grows.
void parse_nucleation(Section& f, InterfaceSpec& is) {
  const std::string n = f.string("nucleation", "none", {"none", "strength"});
  if (n == "none") {
    if (f.has("nucleation_strength"))
      fail(f.key("nucleation_strength"), show(*f.node("nucleation_strength")), "needs nucleation = \"strength\"");
    return;
  }
  if (!is.growth.on())
    fail(f.key("nucleation"), "\"strength\"",
         "makes the drawn line a crack once the stress across it reaches the strength, and the crack then "
         "grows: needs growth = \"max_hoop\", \"energy\", \"cohesive\" or \"prescribed\"");
  double law_strength = 0.0;  // the law's own, where it has one
  if (const auto* b = std::get_if<BilinearLaw>(&is.law); b && !is.precracked) law_strength = b->sigma_max;
  if (const auto* x = std::get_if<XuNeedleman>(&is.law); x && !is.precracked) law_strength = x->sigma_max;
  if (!f.has("nucleation_strength") && law_strength <= 0.0)
    fail(f.key("nucleation_strength"), "(missing)",
         "required with nucleation = \"strength\" when the law has no strength of its own (law = \"contact\"): "
         "the normal stress across the line at which it comes loose, Pa, > 0");
  is.nucleation_strength = f.number("nucleation_strength", law_strength);
  if (!(is.nucleation_strength > 0.0) || !std::isfinite(is.nucleation_strength))
    fail(f.key("nucleation_strength"), is.nucleation_strength, "must be > 0 (Pa)");
}

// The fields the branch events' wedges will take, named NAME.branchK (K = 1, 2, ...).
void reserve_branch_fields(Section& f, InterfaceSpec& is, Case& c, const std::string& name) {
  for (int k = 1; k <= is.growth.max_branches; ++k) {
    const std::string field = fmt::format("{}.branch{}", name, k);
    if (std::find(c.field_names.begin(), c.field_names.end(), field) != c.field_names.end())
      fail(f.key("max_branches"), is.growth.max_branches,
           fmt::format("the branches' wedges take fields named \"{}\", but that is already a field "
                       "name: rename that field",
                       field));
    if (c.field_names.size() >= 255)
      fail(f.key("max_branches"), is.growth.max_branches,
           "each branch event keeps a velocity field, and there are 255 already (at most 255)");
    is.branch_fields.push_back(int(c.field_names.size()));
    c.field_names.push_back(field);
  }
}

}  // namespace rupture
