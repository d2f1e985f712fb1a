// rupture/io/case_toml.cpp
#include "io/case_toml.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <sstream>
#include <toml++/toml.h>

#include "core/errors.hpp"
#include "io/case_checks.hpp"

namespace rupture {
namespace {

std::string show(const toml::node& n) {
  std::ostringstream os;
  if (auto s = n.as_string()) {
    os << '"' << s->get() << '"';
  } else if (n.is_table()) {
    os << "{...}";
  } else {
    n.visit([&os](const auto& v) { os << v; });
  }
  return os.str();
}

[[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& rule) {
  throw InputError(fmt::format("input key '{}' = {}: {}", key, value, rule));
}

[[noreturn]] void fail(const std::string& key, double value, const std::string& rule) {
  fail(key, fmt::format("{:g}", value), rule);
}

// A view of one TOML table that records which keys were read, so that unknown keys
// (typos) are reported instead of silently ignored.
class Section {
 public:
  // `allowed` lists the keys this table may hold; empty = any key (tables of named entries).
  // Unknown keys are reported at once, before any value is read.
  Section(const toml::table& t, std::string path, std::vector<std::string> allowed = {})
      : t_(t), path_(std::move(path)) {
    if (allowed.empty()) return;
    for (const auto& [k, v] : t_) {
      const std::string name(k.str());
      if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
      std::string hint;
      for (const std::string& a : allowed)
        if (edit_distance(a, name) <= 2) hint = " (did you mean '" + key(a) + "'?)";
      fail(key(name), show(v), "unknown key" + hint + "; allowed here: " + join(allowed));
    }
  }

  std::string key(const std::string& k) const { return path_.empty() ? k : path_ + "." + k; }
  bool has(const std::string& k) const { return t_.contains(k); }
  const toml::node* node(const std::string& k) const { return t_.get(k); }

  double number(const std::string& k) {
    const toml::node* n = node(k);
    if (!n) fail(key(k), "(missing)", "required, a number");
    if (auto v = n->value<double>(); v && (n->is_floating_point() || n->is_integer())) {
      if (!std::isfinite(*v)) fail(key(k), show(*n), "must be a finite number");
      return *v;
    }
    fail(key(k), show(*n), "must be a number");
  }
  double number(const std::string& k, double fallback) { return has(k) ? number(k) : fallback; }

  long integer(const std::string& k, long fallback) {
    const toml::node* n = node(k);
    if (!n) return fallback;
    if (!n->is_integer()) fail(key(k), show(*n), "must be an integer");
    return long(*n->value<std::int64_t>());
  }

  bool boolean(const std::string& k, bool fallback) {
    const toml::node* n = node(k);
    if (!n) return fallback;
    if (!n->is_boolean()) fail(key(k), show(*n), "must be true or false");
    return *n->value<bool>();
  }

  std::string string(const std::string& k, const std::string& fallback,
                     const std::vector<std::string>& allowed = {}) {
    const toml::node* n = node(k);
    if (!n) {
      if (fallback.empty() && !allowed.empty())
        fail(key(k), "(missing)", "required, one of " + join(allowed));
      return fallback;
    }
    if (!n->is_string()) fail(key(k), show(*n), "must be a string");
    std::string v = n->as_string()->get();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), v) == allowed.end())
      fail(key(k), show(*n), "must be one of " + join(allowed));
    return v;
  }

  // A 2-vector [a, b] of numbers.
  void pair(const std::string& k, double out[2], bool required) {
    const toml::node* n = node(k);
    if (!n) {
      if (required) fail(key(k), "(missing)", "required, an array of two numbers [x, y]");
      return;
    }
    const toml::array* a = n->as_array();
    if (!a || a->size() != 2) fail(key(k), show(*n), "must be an array of two numbers [x, y]");
    for (std::size_t i = 0; i < 2; ++i) {
      auto v = (*a)[i].value<double>();
      if (!v || !std::isfinite(*v)) fail(key(k), show(*n), "must be an array of two finite numbers");
      out[i] = *v;
    }
  }

  std::vector<std::string> strings(const std::string& k) {
    std::vector<std::string> out;
    const toml::node* n = node(k);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) fail(key(k), show(*n), "must be an array of strings");
    for (const auto& e : *a) {
      if (!e.is_string()) fail(key(k), show(*n), "must be an array of strings");
      out.push_back(e.as_string()->get());
    }
    return out;
  }

  Section table(const std::string& k, bool required, std::vector<std::string> allowed = {}) {
    static const toml::table empty;
    const toml::node* n = node(k);
    if (!n) {
      if (required) fail(key(k), "(missing)", "required table [" + key(k) + "]");
      return Section(empty, key(k));
    }
    if (!n->is_table()) fail(key(k), show(*n), "must be a table");
    return Section(*n->as_table(), key(k), std::move(allowed));
  }

  const toml::table& raw() const { return t_; }

  static std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + ("\"" + v[i] + "\"");
    return s.empty() ? "(none)" : s;
  }

 private:
  const toml::table& t_;
  std::string path_;

  static std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      std::size_t diag = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
        diag = up;
      }
    }
    return row[b.size()];
  }
};

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
    if (part.empty()) fail("--set", "\"" + assignment + "\"", "the key has an empty component");
    parts.push_back(part);
  }
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

bool inside(double a, double lo, double hi, double tol) { return a >= lo - tol && a <= hi + tol; }

bool whole_cells(double length, double h) {
  const double n = length / h;
  return std::fabs(n - std::round(n)) <= 1e-6 * std::max(1.0, n);
}

Case build_case(const toml::table& root) {
  Case c;
  Section top(root, "", {"title", "model", "materials", "grid", "bodies", "time", "solver", "boundary", "interface", "output"});
  c.title = top.string("title", "");

  {
    Section model = top.table("model", false, {"plane"});
    const std::string plane = model.string("plane", "strain", {"strain", "stress"});
    c.plane = plane == "strain" ? PlaneMode::strain : PlaneMode::stress;
  }

  std::map<std::string, int> material_index;
  {
    Section mats = top.table("materials", true);
    for (const auto& [k, v] : mats.raw()) {
      const std::string name(k.str());
      Section m = mats.table(name, true, {"youngs_modulus", "poisson_ratio", "density"});
      ElasticMaterial em;
      em.name = name;
      em.youngs_modulus = m.number("youngs_modulus");
      if (em.youngs_modulus <= 0) fail(m.key("youngs_modulus"), em.youngs_modulus, "must be > 0 (Pa)");
      em.poisson_ratio = m.number("poisson_ratio");
      if (!(em.poisson_ratio > -1.0 && em.poisson_ratio < 0.5))
        fail(m.key("poisson_ratio"), em.poisson_ratio, "must lie in (-1, 0.5)");
      em.density = m.number("density");
      if (em.density <= 0) fail(m.key("density"), em.density, "must be > 0 (kg/m^3)");
      material_index[name] = int(c.materials.size());
      c.materials.push_back(em);
    }
    if (c.materials.empty()) fail("materials", "{}", "at least one material is required");
    if (c.materials.size() > 255) fail("materials", double(c.materials.size()), "at most 255 materials");
  }

  {
    Section g = top.table("grid", true, {"min", "max", "cell_size", "particles_per_cell",
                                          "coarse_cell_size", "refine", "margin"});
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
    if (cells > 2e9) fail(g.key("cell_size"), c.grid.cell_size, fmt::format("gives {:.3g} cells; at most 2e9", cells));
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
    for (const auto& [k, v] : refine.raw()) {
      if (!c.grid.refined()) break;
      const std::string name(k.str());
      Section r = refine.table(name, true, {"min", "max", "level"});
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
          fail(r.key("min"), fmt::format("[{:g}, {:g}]..[{:g}, {:g}]", L.min[0], L.min[1], L.max[0], L.max[1]),
               fmt::format("box edges must lie on multiples of grid.cell_size = {:g} m from grid.min",
                           c.grid.cell_size));
      }
      c.grid.refine.push_back(L);
    }
    c.grid.margin = g.number("margin", -1.0);  // < 0: automatic, set once the loads are known
    if (g.has("margin") && !(c.grid.margin >= 0 && c.grid.margin <= c.grid.max_margin()))
      fail(g.key("margin"), c.grid.margin, "must lie in [0, half the larger domain extent] (m)");
    const long ppc = g.integer("particles_per_cell", 2);
    if (ppc < 1 || ppc > 8) fail(g.key("particles_per_cell"), double(ppc), "must lie in [1, 8] (per direction)");
    c.grid.particles_per_cell = int(ppc);
  }

  std::map<std::string, int> body_index;
  {
    Section bodies = top.table("bodies", true);
    const double h = c.grid.cell_size, tol = 1e-9 * h;
    for (const auto& [k, v] : bodies.raw()) {
      const std::string name(k.str());
      Section b = bodies.table(name, true, {"material", "min", "max", "velocity"});
      BodySpec bs;
      bs.name = name;
      const std::string mat = b.string("material", "");
      if (mat.empty()) fail(b.key("material"), "(missing)", "required, the name of a [materials] entry");
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
          fail(b.key("min"), fmt::format("[{:g}, {:g}]..[{:g}, {:g}]", bs.min[0], bs.min[1], bs.max[0], bs.max[1]),
               fmt::format("body edges must lie on grid lines (multiples of grid.cell_size = {:g} m from grid.min)", h));
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

  {
    Section t = top.table("time", true, {"end", "cfl", "cohesive_safety", "stop_at_interface_end"});
    c.time.end = t.number("end");
    if (c.time.end <= 0) fail(t.key("end"), c.time.end, "must be > 0 (s)");
    c.time.cfl = t.number("cfl", 0.4);
    if (!(c.time.cfl > 0 && c.time.cfl <= 1)) fail(t.key("cfl"), c.time.cfl, "must lie in (0, 1]");
    c.time.cohesive_safety = t.number("cohesive_safety", 0.9);
    if (!(c.time.cohesive_safety > 0 && c.time.cohesive_safety <= 1))
      fail(t.key("cohesive_safety"), c.time.cohesive_safety, "must lie in (0, 1]");
    c.time.stop_at_interface_end = t.boolean("stop_at_interface_end", false);
  }

  {
    Section s = top.table("solver", false, {"scheme", "flip", "threads"});
    const std::string scheme = s.string("scheme", "MUSL", {"MUSL", "USL", "USF"});
    c.solver.scheme = scheme == "MUSL" ? Scheme::MUSL : scheme == "USL" ? Scheme::USL : Scheme::USF;
    c.solver.flip = s.number("flip", 1.0);
    if (!(c.solver.flip >= 0 && c.solver.flip <= 1)) fail(s.key("flip"), c.solver.flip, "must lie in [0, 1] (1 = FLIP, 0 = PIC)");
    const long threads = s.integer("threads", 0);
    if (threads < 0 || threads > 1024) fail(s.key("threads"), double(threads), "must lie in [0, 1024] (0 = all cores)");
    c.solver.threads = int(threads);
  }

  {
    Section bcs = top.table("boundary", false);
    for (const auto& [k, v] : bcs.raw()) {
      const std::string name(k.str());
      Section b = bcs.table(name, true, {"edge", "from", "to", "component", "bodies", "function", "velocity", "rise_time", "plateau_time", "fall_time", "follow_edge"});
      VelocityBC bc;
      bc.name = name;
      const std::string edge = b.string("edge", "", {"left", "right", "bottom", "top"});
      bc.edge = edge == "left" ? Edge::left : edge == "right" ? Edge::right : edge == "bottom" ? Edge::bottom : Edge::top;
      const bool vertical = bc.edge == Edge::left || bc.edge == Edge::right;
      const int along = vertical ? 1 : 0;
      const double lo = c.grid.min[along], hi = c.grid.max[along];
      bc.from = b.number("from", lo);
      bc.to = b.number("to", hi);
      const std::string coord = vertical ? "y" : "x";
      if (!(bc.from <= bc.to)) fail(b.key("to"), bc.to, fmt::format("must be >= {} = {:g}", b.key("from"), bc.from));
      const double tol = 1e-9 * c.grid.cell_size;
      if (!inside(bc.from, lo, hi, tol)) fail(b.key("from"), bc.from, fmt::format("must lie on the {} edge: {} in [{:g}, {:g}] m", edge, coord, lo, hi));
      if (!inside(bc.to, lo, hi, tol)) fail(b.key("to"), bc.to, fmt::format("must lie on the {} edge: {} in [{:g}, {:g}] m", edge, coord, lo, hi));
      const std::string comp = b.string("component", "", {"x", "y"});
      bc.component = comp == "x" ? 0 : 1;
      for (const std::string& body : b.strings("bodies")) {
        if (!body_index.count(body)) {
          std::vector<std::string> names;
          for (const auto& bb : c.bodies) names.push_back(bb.name);
          fail(b.key("bodies"), "\"" + body + "\"", "must name bodies among " + Section::join(names));
        }
        bc.fields.push_back(body_index[body]);
      }
      const std::string fn = b.string("function", "constant", {"constant", "trapezoid"});
      bc.velocity.value = b.number("velocity");
      if (fn == "trapezoid") {
        bc.velocity.kind = TimeFunction::Kind::trapezoid;
        bc.velocity.rise_time = b.number("rise_time");
        if (bc.velocity.rise_time <= 0) fail(b.key("rise_time"), bc.velocity.rise_time, "must be > 0 (s)");
        bc.velocity.plateau_time = b.number("plateau_time");
        if (bc.velocity.plateau_time < 0) fail(b.key("plateau_time"), bc.velocity.plateau_time, "must be >= 0 (s)");
        bc.velocity.fall_time = b.number("fall_time");
        if (bc.velocity.fall_time <= 0) fail(b.key("fall_time"), bc.velocity.fall_time, "must be > 0 (s)");
      } else {
        for (const char* key : {"rise_time", "plateau_time", "fall_time"})
          if (b.has(key)) fail(b.key(key), show(*b.node(key)), "only allowed with function = \"trapezoid\"");
      }
      bc.follow_edge = b.boolean("follow_edge", true);
      if (b.has("follow_edge") && !bc.normal())
        fail(b.key("follow_edge"), show(*b.node("follow_edge")),
             fmt::format("only applies to the velocity component normal to the {} edge ({})", edge, vertical ? "x" : "y"));
      c.boundary.push_back(bc);
    }
  }

  if (c.grid.margin < 0.0) {
    // Automatic ghost margin (GridSpec::margin): the largest displacement of any prescribed or
    // initial velocity over the run. 1000 samples of a piecewise-linear V miss nothing that matters.
    double m = 0.0;
    for (const VelocityBC& bc : c.boundary)
      for (int k = 1; k <= 1000; ++k) m = std::max(m, std::fabs(bc.velocity.displacement(c.time.end * k / 1000.0)));
    for (const BodySpec& b : c.bodies) m = std::max(m, std::hypot(b.velocity[0], b.velocity[1]) * c.time.end);
    // Capped like an explicit grid.margin: a long run with a constant velocity would otherwise
    // ask for an unbounded grid; a surface moving farther is caught as "particle left the grid".
    c.grid.margin = std::min(m, c.grid.max_margin());
  }

  {
    Section ifs = top.table("interface", false);
    for (const auto& [k, v] : ifs.raw()) {
      const std::string name(k.str());
      Section f = ifs.table(name, true, {"upper_body", "lower_body", "y", "start", "end", "segments",
                                         "sigma_max", "tau_max", "delta_n", "delta_t", "q", "r",
                                         "penalty", "separation", "bonded_to"});
      InterfaceSpec is;
      std::vector<std::string> names;
      for (const auto& bb : c.bodies) names.push_back(bb.name);
      for (const char* which : {"upper_body", "lower_body"}) {
        const std::string body = f.string(which, "");
        if (!body_index.count(body))
          fail(f.key(which), "\"" + body + "\"", "must name a body among " + Section::join(names));
        (std::string(which) == "upper_body" ? is.upper_field : is.lower_field) = body_index[body];
      }
      if (is.upper_field == is.lower_field)
        fail(f.key("lower_body"), "\"" + c.bodies[is.lower_field].name + "\"", "must differ from upper_body");
      const BodySpec &up = c.bodies[is.upper_field], &lo = c.bodies[is.lower_field];
      is.y = f.number("y");
      const double tol = 1e-9 * c.grid.cell_size;
      if (std::fabs(up.min[1] - is.y) > tol || std::fabs(lo.max[1] - is.y) > tol)
        fail(f.key("y"), is.y, fmt::format("must be the bottom of the upper body ({:g}) and the top of the lower body ({:g})", up.min[1], lo.max[1]));
      is.start = f.number("start");
      is.end = f.number("end");
      const double x0 = std::max(up.min[0], lo.min[0]), x1 = std::min(up.max[0], lo.max[0]);
      if (!inside(is.start, x0, x1, tol)) fail(f.key("start"), is.start, fmt::format("must lie where both bodies meet: [{:g}, {:g}] m", x0, x1));
      if (!(is.end > is.start) || !inside(is.end, x0, x1, tol)) fail(f.key("end"), is.end, fmt::format("must lie in ({:g}, {:g}] m", is.start, x1));
      const long segments = f.integer("segments", -1);
      if (segments < 1 || segments > 100000000) fail(f.key("segments"), double(segments), "required, an integer in [1, 1e8]");
      is.segments = int(segments);
      XuNeedleman& law = is.law;
      law.sigma_max = f.number("sigma_max");
      if (law.sigma_max <= 0) fail(f.key("sigma_max"), law.sigma_max, "must be > 0 (Pa)");
      law.tau_max = f.number("tau_max", law.sigma_max);
      if (law.tau_max <= 0) fail(f.key("tau_max"), law.tau_max, "must be > 0 (Pa)");
      law.delta_n = f.number("delta_n");
      if (law.delta_n <= 0) fail(f.key("delta_n"), law.delta_n, "must be > 0 (m)");
      law.q = f.number("q", 1.0);
      if (law.q <= 0) fail(f.key("q"), law.q, "must be > 0");
      law.r = f.number("r", 0.0);
      if (law.r < 0 || std::fabs(law.r - 1.0) < 1e-12) fail(f.key("r"), law.r, "must be >= 0 and differ from 1");
      if (f.has("delta_t")) {
        law.delta_t = f.number("delta_t");
        if (law.delta_t <= 0) fail(f.key("delta_t"), law.delta_t, "must be > 0 (m)");
      } else {
        // q = phi_t/phi_n with phi_t = sqrt(e/2) tau_max delta_t, phi_n = e sigma_max delta_n.
        law.delta_t = law.q * std::exp(1.0) * law.sigma_max * law.delta_n / (std::sqrt(std::exp(1.0) / 2.0) * law.tau_max);
      }
      law.penalty = f.number("penalty", 1.0);
      if (law.penalty < 0) fail(f.key("penalty"), law.penalty, "must be >= 0 (multiple of phi_n/delta_n^2)");
      is.separation_factor = f.number("separation", 5.0);
      if (!(is.separation_factor > 0 && is.separation_factor <= 1000)) fail(f.key("separation"), is.separation_factor, "must lie in (0, 1000] (multiples of delta_t)");
      if (f.has("bonded_to")) {
        is.bonded = true;
        is.bonded_from = is.end;
        is.bonded_to = f.number("bonded_to");
        if (!(is.bonded_to > is.end) || !inside(is.bonded_to, x0, x1, tol))
          fail(f.key("bonded_to"), is.bonded_to, fmt::format("must lie in ({:g}, {:g}] m (the halves are tied from end to here)", is.end, x1));
      }
      c.interfaces.push_back(is);
      c.interface_names.push_back(name);
    }
  }

  {
    Section o = top.table("output", false, {"history_interval", "snapshot_interval", "progress_interval", "crack_sample_interval", "interface_interval", "snapshot_region_min", "snapshot_region_max"});
    c.output.history_interval = o.number("history_interval", c.time.end / 200.0);
    if (c.output.history_interval < 0) fail(o.key("history_interval"), c.output.history_interval, "must be >= 0 (s; 0 = every step)");
    c.output.snapshot_interval = o.number("snapshot_interval", 0.0);
    if (c.output.snapshot_interval < 0) fail(o.key("snapshot_interval"), c.output.snapshot_interval, "must be >= 0 (s; 0 = no snapshots)");
    c.output.progress_interval = o.number("progress_interval", 1.0);
    if (c.output.progress_interval <= 0) fail(o.key("progress_interval"), c.output.progress_interval, "must be > 0 (wall-clock s)");
    c.output.crack_sample_interval = o.number("crack_sample_interval", 0.05e-6);
    if (c.output.crack_sample_interval <= 0) fail(o.key("crack_sample_interval"), c.output.crack_sample_interval, "must be > 0 (s)");
    c.output.interface_interval = o.number("interface_interval", c.output.snapshot_interval);
    if (o.has("snapshot_region_min") || o.has("snapshot_region_max")) {
      c.output.has_snapshot_region = true;
      o.pair("snapshot_region_min", c.output.snapshot_region, true);
      o.pair("snapshot_region_max", c.output.snapshot_region + 2, true);
      if (!(c.output.snapshot_region[2] > c.output.snapshot_region[0] && c.output.snapshot_region[3] > c.output.snapshot_region[1]))
        fail(o.key("snapshot_region_max"), fmt::format("[{:g}, {:g}]", c.output.snapshot_region[2], c.output.snapshot_region[3]),
             "must exceed output.snapshot_region_min in both components");
    }
    if (c.output.interface_interval < 0) fail(o.key("interface_interval"), c.output.interface_interval, "must be >= 0 (s; 0 = none)");
  }

  if (c.grid.refined()) {
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

  check_case_consistency(c);

  std::ostringstream echo;
  echo << toml::toml_formatter{root};
  c.input_toml = echo.str();
  return c;
}

}  // namespace

const char* scheme_name(Scheme s) {
  switch (s) {
    case Scheme::USF: return "USF";
    case Scheme::USL: return "USL";
    case Scheme::MUSL: return "MUSL";
  }
  return "?";
}

Grid build_grid(const GridSpec& g) {
  const double margin = std::max(0.0, g.margin);
  if (!g.refined()) return make_uniform_grid(g.min, g.max, g.cell_size, margin);
  std::vector<RefineBox> boxes;
  for (const RefineLevel& L : g.refine)
    boxes.push_back({{L.min[0], L.min[1]}, {L.max[0], L.max[1]}, g.level_size(L.level)});
  return make_graded_grid(g.min, g.max, g.coarse_cell_size, g.cell_size, boxes, margin);
}

Case parse_case(const std::string& toml_text, const std::vector<std::string>& overrides,
                const std::string& origin) {
  toml::table root;
  try {
    root = toml::parse(toml_text, origin);
  } catch (const toml::parse_error& e) {
    const auto& src = e.source();
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", origin, src.begin.line,
                                 src.begin.column, e.description()));
  }
  for (const std::string& o : overrides) apply_override(root, o);
  return build_case(root);
}

Case load_case(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("cannot read case file '{}'", path));
  std::stringstream buf;
  buf << in.rdbuf();
  return parse_case(buf.str(), overrides, path);
}

}  // namespace rupture
