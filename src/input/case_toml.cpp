// rupture/input/case_toml.cpp
#include "input/case_toml.hpp"
#include "input/parameters.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/errors.hpp"
#include "cohesive/polyline.hpp"
#include "grid/nested.hpp"
#include "input/case_checks.hpp"
#include "input/case_parse.hpp"
#include "input/input_schema.hpp"
#include "input/text_limits.hpp"
#include "input/toml_section.hpp"

namespace rupture {
void parse_model(Section& top, Case& c) {
  Section model = top.table("model", false, allowed_keys("model"));
  const std::string plane = model.string("plane", "strain", {"strain", "stress"});
  c.plane = plane == "strain" ? PlaneMode::strain : PlaneMode::stress;
}

namespace {

// (E, nu): the engineers' pair.
void elastic_from_moduli(Section& m, ElasticMaterial& em) {
  em.youngs_modulus = m.number("youngs_modulus");
  if (!(em.youngs_modulus > 0))
    fail(m.key("youngs_modulus"), em.youngs_modulus, "must be > 0 (Pa)");
  em.poisson_ratio = m.number("poisson_ratio");
  if (!(em.poisson_ratio > -1.0 && em.poisson_ratio < 0.5))
    fail(m.key("poisson_ratio"), em.poisson_ratio, "must lie in (-1, 0.5)");
}

// (c_P, c_S), the seismologists' pair: the 3D body-wave speeds (plane strain's c_D and c_S),
// so mu = rho c_S^2 and lambda + 2 mu = rho c_P^2, hence (docs/theory.md, E1)
//   nu = (c_P^2 - 2 c_S^2) / (2 (c_P^2 - c_S^2)),  E = 2 mu (1 + nu).
// nu > -1 (a positive bulk modulus) needs c_P > (2/sqrt 3) c_S; nu < 0.5 holds for any finite
// c_P. Not together with E or nu: one pair describes the material.
void elastic_from_wave_speeds(Section& m, ElasticMaterial& em) {
  for (const char* k : {"youngs_modulus", "poisson_ratio"})
    if (m.has(k))
      fail(m.key(k), show(*m.node(k)),
           "not with p_wave_speed and s_wave_speed: give (youngs_modulus, poisson_ratio) or "
           "(p_wave_speed, s_wave_speed), with density");
  const double cp = m.number("p_wave_speed"), cs = m.number("s_wave_speed");
  if (!(cs > 0 && std::isfinite(cs))) fail(m.key("s_wave_speed"), cs, "must be > 0 and finite (m/s)");
  if (!(cp > 2.0 / std::sqrt(3.0) * cs && std::isfinite(cp)))
    fail(m.key("p_wave_speed"), cp,
         fmt::format("must exceed 2/sqrt(3) s_wave_speed = {:g} m/s (a positive bulk modulus: "
                     "Poisson's ratio above -1) and be finite",
                     2.0 / std::sqrt(3.0) * cs));
  const double cp2 = cp * cp, cs2 = cs * cs;
  em.poisson_ratio = (cp2 - 2.0 * cs2) / (2.0 * (cp2 - cs2));
  em.youngs_modulus = 2.0 * em.density * cs2 * (1.0 + em.poisson_ratio);
}

}  // namespace

void parse_materials(Section& top, Case& c, ParseContext& ctx) {
  auto& material_index = ctx.material_index;
  Section mats = top.table("materials", true);
  for (const auto& [k, v] : named_entries(mats)) {
    const std::string& name = k;
    Section m = mats.table(name, true, allowed_keys("materials.*"));
    ElasticMaterial em;
    em.name = name;
    em.density = m.number("density");
    if (!(em.density > 0)) fail(m.key("density"), em.density, "must be > 0 (kg/m^3)");
    if (m.has("p_wave_speed") || m.has("s_wave_speed"))
      elastic_from_wave_speeds(m, em);
    else
      elastic_from_moduli(m, em);
    // Kelvin-Voigt eta / dt: the explicit step stays stable for any value at the reduced step
    // dt <= 2 / (omega sqrt(1 + 2 eta/dt)) (docs/theory.md §16), which the step bound applies;
    // above 1 the damping is no longer a small regularization of the highest frequencies.
    em.kelvin_voigt = m.number("kelvin_voigt", 0.0);
    if (!(em.kelvin_voigt >= 0.0 && em.kelvin_voigt <= 1.0))
      fail(m.key("kelvin_voigt"), em.kelvin_voigt,
           "must lie in [0, 1] (eta / dt, the Kelvin-Voigt viscosity in units of the time step; "
           "the reference codes use 0.1)");
    material_index[name] = int(c.materials.size());
    c.materials.push_back(em);
  }
  if (c.materials.empty()) fail("materials", "{}", "at least one material is required");
  if (c.materials.size() > 255)
    fail("materials", double(c.materials.size()), "at most 255 materials");
}

void parse_time(Section& top, Case& c) {
  Section t = top.table("time", true, allowed_keys("time"));
  c.time.end = t.number("end");
  if (c.time.end <= 0) fail(t.key("end"), c.time.end, "must be > 0 (s)");
  c.time.cfl = t.number("cfl", TimeSpec{}.cfl);  // the default: input/case.hpp, once
  if (!(c.time.cfl > 0 && c.time.cfl <= 1)) fail(t.key("cfl"), c.time.cfl, "must lie in (0, 1]");
  c.time.cohesive_safety = t.number("cohesive_safety", TimeSpec{}.cohesive_safety);
  if (!(c.time.cohesive_safety > 0 && c.time.cohesive_safety <= 1))
    fail(t.key("cohesive_safety"), c.time.cohesive_safety, "must lie in (0, 1]");
  c.time.stop_at_interface_end = t.boolean("stop_at_interface_end", false);
  c.time.subcycling_given = t.has("subcycling");  // absent: set_default_subcycling decides
  const std::string subcycling = t.string("subcycling", "none", {"none", "levels"});
  c.time.subcycling = subcycling == "levels" ? Subcycling::levels : Subcycling::none;
  if (c.time.subcycling == Subcycling::levels && !c.grid.nested)
    fail(t.key("subcycling"), "\"levels\"",
         "needs grid.refinement = \"nested\" (per-level time steps step nested levels)");
}

void parse_solver(Section& top, Case& c) {
  Section s = top.table("solver", false, allowed_keys("solver"));
  const std::string scheme = s.string("scheme", "MUSL", {"MUSL", "USL", "USF"});
  c.solver.scheme = scheme == "MUSL" ? Scheme::MUSL : scheme == "USL" ? Scheme::USL : Scheme::USF;
  c.solver.flip = s.number("flip", 1.0);
  if (!(c.solver.flip >= 0 && c.solver.flip <= 1))
    fail(s.key("flip"), c.solver.flip, "must lie in [0, 1] (1 = FLIP, 0 = PIC)");
  const std::string mass = s.string("mass", "lumped", {"lumped", "averaged"});
  c.solver.mass = mass == "averaged" ? MassMatrix::averaged : MassMatrix::lumped;
  const long threads = s.integer("threads", 0);
  if (threads < 0 || threads > 1024)
    fail(s.key("threads"), double(threads), "must lie in [0, 1024] (0 = all cores)");
  c.solver.threads = int(threads);
  c.solver.memory_limit_mib = s.number("memory_limit_mib", 0.0);
  if (c.solver.memory_limit_mib < 0)
    fail(s.key("memory_limit_mib"), c.solver.memory_limit_mib, "must be >= 0 (MiB; 0 = the machine's memory)");
}

void parse_output(Section& top, Case& c) {
  Section o = top.table("output", false, allowed_keys("output"));
  c.output.history_interval = o.number("history_interval", c.time.end / 200.0);
  if (c.output.history_interval < 0)
    fail(o.key("history_interval"), c.output.history_interval, "must be >= 0 (s; 0 = every step)");
  c.output.snapshot_interval = o.number("snapshot_interval", 0.0);
  if (c.output.snapshot_interval < 0)
    fail(o.key("snapshot_interval"), c.output.snapshot_interval,
         "must be >= 0 (s; 0 = no snapshots)");
  c.output.progress_interval = o.number("progress_interval", 1.0);
  if (c.output.progress_interval <= 0)
    fail(o.key("progress_interval"), c.output.progress_interval, "must be > 0 (wall-clock s)");
  // 0.05 us (theory E10) for laboratory runs; a 384th of the run when that is longer (the paper's
  // 19.2 us run has 384 samples either way), so no absolute time scale is built in.
  const double longer = c.time.end / 384.0;
  c.output.crack_sample_interval =
      o.number("crack_sample_interval", longer > 1.001 * 0.05e-6 ? longer : 0.05e-6);
  if (c.output.crack_sample_interval <= 0)
    fail(o.key("crack_sample_interval"), c.output.crack_sample_interval, "must be > 0 (s)");
  c.output.interface_interval = o.number("interface_interval", c.output.snapshot_interval);
  c.output.mach_interval = o.number("mach_interval", c.output.snapshot_interval);
  c.output.station_interval = o.number("station_interval", 0.0);
  if (c.output.station_interval < 0)
    fail(o.key("station_interval"), c.output.station_interval, "must be >= 0 (s; 0 = every step)");
  if (c.output.mach_interval < 0)
    fail(o.key("mach_interval"), c.output.mach_interval, "must be >= 0 (s; 0 = none)");
  if (o.has("snapshot_region_min") || o.has("snapshot_region_max")) {
    c.output.has_snapshot_region = true;
    o.pair("snapshot_region_min", c.output.snapshot_region, true);
    o.pair("snapshot_region_max", c.output.snapshot_region + 2, true);
    if (!(c.output.snapshot_region[2] > c.output.snapshot_region[0] &&
          c.output.snapshot_region[3] > c.output.snapshot_region[1]))
      fail(o.key("snapshot_region_max"),
           fmt::format("[{:g}, {:g}]", c.output.snapshot_region[2], c.output.snapshot_region[3]),
           "must exceed output.snapshot_region_min in both components");
  }
  if (c.output.interface_interval < 0)
    fail(o.key("interface_interval"), c.output.interface_interval, "must be >= 0 (s; 0 = none)");
}

namespace {

void apply_override(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    fail("--set", "\"" + assignment + "\"", "must have the form dotted.key=value");
  std::string path = assignment.substr(0, eq);
  std::string text = assignment.substr(eq + 1);
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string part; std::getline(ss, part, '.');) {
    part.erase(0, part.find_first_not_of(" \t"));
    part.erase(part.find_last_not_of(" \t") + 1);
    if (part.empty()) fail("--set", "\"" + printable(assignment) + "\"", "the key has an empty component");
    parts.push_back(part);
  }
  if (parts.size() > std::size_t(kMaxKeyParts))
    fail("--set", fmt::format("{} dotted parts", parts.size()),
         fmt::format("a key has at most {} parts", kMaxKeyParts));
  check_toml_limits(text, "--set " + path);
  toml::table* t = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* n = t->get(parts[i]);
    if (!n) {
      t->insert(parts[i], toml::table{});
      n = t->get(parts[i]);
    }
    if (!n->is_table()) fail(path, show(*n), "--set cannot descend into a non-table value");
    t = n->as_table();
  }
  // Parse the value as TOML; a bare word that is not TOML is taken as a string.
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    parsed.insert("v", text);
  }
  t->insert_or_assign(parts.back(), *parsed.get("v"));
}

// The input echo holds tables read from files inline (table = [...] for table_file = "..."), so
// run.json records the values the run used.
std::string input_echo(const toml::table& root, const ParseContext& ctx) {
  std::ostringstream echo;
  if (ctx.file_tables.empty()) {
    echo << toml::toml_formatter{root};
    return echo.str();
  }
  toml::table copy = root;
  for (const ParseContext::FileTable& ft : ctx.file_tables) {
    toml::table* t = &copy;
    for (const std::string& key : ft.path) t = t ? t->get_as<toml::table>(key) : nullptr;
    if (!t) continue;
    toml::array rows;
    for (std::size_t k = 0; k < ft.t.size(); ++k) rows.push_back(toml::array{ft.t[k], ft.v[k]});
    t->erase("table_file");
    t->insert_or_assign("table", std::move(rows));
  }
  echo << toml::toml_formatter{copy};
  return echo.str();
}

// time.subcycling's default, once the whole case is known: per-level steps where they are
// verified (docs/performance.md "Per-level time steps": MUSL, velocity conditions, interfaces
// on one level, no crack that grows: docs/fracture.md "Growth on nested levels"), one dt for
// every level elsewhere. Given explicitly, "levels" keeps its named refusals
// (solver/nested_state.cpp check_nested_support).
void set_default_subcycling(Case& c) {
  if (c.time.subcycling_given || !c.grid.nested) return;
  bool verified = c.solver.scheme == Scheme::MUSL && c.loads.empty() && c.absorbing_edges.empty();
  for (const InterfaceSpec& spec : c.interfaces) verified = verified && !spec.growth.on();
  if (verified && c.interfaces.size() > 1) {
    const NestedGrid g = make_nested_grid(c.grid.min, c.grid.max, c.grid.coarse_cell_size, c.grid.cell_size,
                                          refine_boxes(c.grid), std::max(0.0, c.grid.margin));
    int first = -1;
    for (const InterfaceSpec& spec : c.interfaces) {
      const LineNodes nodes = discretize(spec.geometry(), spec.segments);
      const int l = g.level_of(nodes.x[0], nodes.y[0]);  // the level that must hold it whole
      if (first >= 0 && l != first) verified = false;
      first = l;
    }
  }
  c.time.subcycling = verified ? Subcycling::levels : Subcycling::none;
}

Case build_case(const toml::table& root, const std::string& case_dir) {
  Case c;
  Section top(root, "", allowed_keys(""));
  c.title = top.string("title", "");
  ParseContext ctx;
  ctx.case_dir = case_dir;
  parse_model(top, c);
  parse_materials(top, c, ctx);
  parse_grid(top, c);
  parse_bodies(top, c, ctx);
  parse_time(top, c);
  parse_solver(top, c);
  check_grid_limits(c);  // before anything walks the bodies' seed points
  // Before the tables that name bodies: a line inside a body splits it into parts, and a
  // condition or load naming the body acts on all of them.
  parse_interfaces(top, c, ctx);
  parse_boundary(top, c, ctx);
  parse_absorbing(top, c);
  parse_loads(top, c, ctx);
  set_automatic_margin(c);
  parse_output(top, c);
  parse_stations(top, c);
  check_memory_before_seeding(c);  // before the checks below walk the bodies' seed points
  set_default_subcycling(c);
  check_bodies_on_graded_grid(c);
  check_body_seeding(c);

  check_case_consistency(c);

  c.input_toml = input_echo(root, ctx);
  c.read_table_files = !ctx.file_tables.empty();
  return c;
}

}  // namespace

const char* scheme_name(Scheme s) {
  switch (s) {
    case Scheme::USF:
      return "USF";
    case Scheme::USL:
      return "USL";
    case Scheme::MUSL:
      return "MUSL";
  }
  return "?";
}

std::vector<RefineBox> refine_boxes(const GridSpec& g) {
  std::vector<RefineBox> boxes;
  for (const RefineLevel& L : g.refine)
    boxes.push_back({{L.min[0], L.min[1]}, {L.max[0], L.max[1]}, g.level_size(L.level)});
  return boxes;
}

Grid build_grid(const GridSpec& g) {
  const double margin = std::max(0.0, g.margin);
  if (!g.refined()) return make_uniform_grid(g.min, g.max, g.cell_size, margin);
  return make_graded_grid(g.min, g.max, g.coarse_cell_size, g.cell_size, refine_boxes(g), margin);
}

Case parse_case(const std::string& toml_text, const std::vector<std::string>& overrides,
                const std::string& origin) {
  check_toml_limits(toml_text, origin);  // before the parser: no input can exhaust its stack
  toml::table root;
  try {
    root = toml::parse(toml_text, origin);
  } catch (const toml::parse_error& e) {
    const auto& src = e.source();
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", origin, src.begin.line,
                                 src.begin.column, e.description()));
  }
  for (const std::string& o : overrides) apply_override(root, o);
  substitute_parameters(root);  // after --set, so a parameter set there moves what uses it
  // Relative table_file paths start at the case file's directory (the working directory for
  // text that came from no file).
  std::string case_dir;
  if (origin != "<string>") case_dir = std::filesystem::path(origin).parent_path().string();
  return build_case(root, case_dir);
}

Case load_case(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_case(read_bounded_file(path, kMaxCaseBytes, "case file"), overrides, path);
}

}  // namespace rupture