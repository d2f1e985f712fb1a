// rupture/input/parse_interfaces.cpp
// The [interface] table: cohesive interfaces, their line, law and bonded stretch (theory §3).
// A line is horizontal (y, start, end: the original form), a polyline (points, closed) or a
// circle (center, radius); it must separate its two bodies, the upper one on the side its
// normal (direction turned +90 degrees) points to.
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "cohesive/interface.hpp"
#include "cohesive/interface_growth.hpp"
#include "input/law_registry.hpp"
#include "cohesive/polyline.hpp"
#include "material/elastic.hpp"
#include "input/case_parse.hpp"
#include "input/crack_reach.hpp"
#include "input/input_schema.hpp"

namespace rupture {

namespace {

// An array of points [[x, y], ...] (m), at least `min_count`.
Polyline read_points(Section& f, const std::string& key, std::size_t min_count) {
  const toml::node* n = f.node(key);
  const toml::array* a = n ? n->as_array() : nullptr;
  const std::string rule =
      fmt::format("must be an array of at least {} points [[x, y], ...] (m)", min_count);
  if (!a || a->size() < min_count) fail(f.key(key), n ? show(*n) : "(missing)", rule);
  Polyline p;
  for (const auto& e : *a) {
    const toml::array* xy = e.as_array();
    std::optional<double> x, y;
    if (xy && xy->size() == 2) x = (*xy)[0].value<double>(), y = (*xy)[1].value<double>();
    if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) fail(f.key(key), show(e), rule);
    p.x.push_back(*x);
    p.y.push_back(*y);
  }
  return p;
}

// The line is simple, has no zero-length piece and lies in the domain.
void check_line(Section& f, const std::string& key, const Polyline& line, const Case& c) {
  const double tol = 1e-9 * c.grid.cell_size;
  for (std::size_t i = 0; i < line.num_pieces(); ++i)
    if (line.piece_length(i) <= tol)
      fail(f.key(key), fmt::format("[{:g}, {:g}]", line.x[i], line.y[i]),
           fmt::format("point {} repeats the next one: pieces must have a length > 0", i));
  for (std::size_t v = 0; v < line.num_vertices(); ++v)
    if (!inside(line.x[v], c.grid.min[0], c.grid.max[0], tol) ||
        !inside(line.y[v], c.grid.min[1], c.grid.max[1], tol))
      fail(f.key(key), fmt::format("[{:g}, {:g}]", line.x[v], line.y[v]),
           fmt::format("point {} lies outside the grid [{:g}, {:g}]..[{:g}, {:g}]", v,
                       c.grid.min[0], c.grid.min[1], c.grid.max[0], c.grid.max[1]));
  const PieceCrossing x = first_self_crossing(line);
  if (x.i >= 0)
    fail(f.key(key),
         fmt::format("(piece {} from [{:g}, {:g}], piece {} from [{:g}, {:g}])", x.i,
                     line.x[std::size_t(x.i)], line.y[std::size_t(x.i)], x.j,
                     line.x[std::size_t(x.j)], line.y[std::size_t(x.j)]),
         "the line crosses itself; an interface must be a simple line");
}

// The line must separate the two bodies: just off it along its normal lies the upper body,
// just off it the other way the lower one (sampled along every piece). `slack` (m) is how far
// the line may lie from the bodies' common boundary: a circle's polygon is inside its circle by
// up to its sagitta, so a circle body or cut-out of the same radius is met only that far out.
void check_between_bodies(Section& f, const std::string& key, const Polyline& line, const Case& c,
                          const BodySpec& up, const BodySpec& lo, double slack = 0.0) {
  const double eps = 1e-3 * c.grid.cell_size + slack;
  for (std::size_t i = 0; i < line.num_pieces(); ++i) {
    const std::size_t j = line.piece_end(i);
    const double len = line.piece_length(i);
    const double tx = (line.x[j] - line.x[i]) / len, ty = (line.y[j] - line.y[i]) / len;
    const double nx = -ty, ny = tx;
    const int samples = 64;
    for (int k = 0; k <= samples; ++k) {
      // Skip the very ends of a piece: a vertex may sit on a body's corner.
      const double a = len * (0.001 + 0.998 * double(k) / samples);
      const double x = line.x[i] + a * tx, y = line.y[i] + a * ty;
      const bool in_up = body_contains(up, x + eps * nx, y + eps * ny);
      const bool in_lo = body_contains(lo, x - eps * nx, y - eps * ny);
      if (in_up && in_lo) continue;
      const bool swapped = body_contains(lo, x + eps * nx, y + eps * ny) &&
                           body_contains(up, x - eps * nx, y - eps * ny);
      fail(f.key(key), fmt::format("(near [{:.6g}, {:.6g}] on piece {})", x, y, i),
           swapped
               ? fmt::format("the line's normal (its direction turned +90 degrees) points into "
                             "bodies.{} there, the lower body: reverse the points or swap "
                             "upper_body and lower_body",
                             lo.name)
               : fmt::format("must lie on the boundary between bodies.{} (on the side the normal, "
                             "the line's direction turned +90 degrees, points to) and bodies.{}",
                             up.name, lo.name));
    }
  }
}

// The geometry keys: the horizontal form (y, start, end, bonded_to) or a polyline (points,
// closed, bonded_points) or a circle (center, radius). Between two bodies (up, lo) the line
// must separate them; inside one (up = lo = nullptr, the `body` form) input/parse_body_split.cpp
// checks it once the body is known, and the bonded stretches are made there.
InterfaceLine parse_interface_geometry(Section& f, InterfaceSpec& is, const Case& c,
                                       const BodySpec* up, const BodySpec* lo) {
  const double tol = 1e-9 * c.grid.cell_size;
  InterfaceLine info;
  const bool horizontal = f.has("y") || f.has("start") || f.has("end");
  const bool polyline = f.has("points");
  const bool circle = f.has("center") || f.has("radius");
  if (int(horizontal) + int(polyline) + int(circle) != 1)
    fail(f.key("points"), polyline ? "(present)" : "(missing)",
         "give the line one way: y, start and end (a horizontal line), points = [[x, y], ...] "
         "(a polyline), or center and radius (a circle)");
  const long segments = f.integer("segments", -1);
  if (segments < 1 || segments > 100000000)
    fail(f.key("segments"), double(segments), "required, an integer in [1, 1e8]");
  is.segments = int(segments);
  if (horizontal && !up) {
    info.key = "y";
    is.y = f.number("y");
    is.start = f.number("start");
    is.end = f.number("end");
    if (!(is.end > is.start))
      fail(f.key("end"), is.end, fmt::format("must be > start = {:g} m", is.start));
    if (f.has("closed"))
      fail(f.key("closed"), show(*f.node("closed")), "only allowed with points = [[x, y], ...]");
    check_line(f, "y", is.geometry(), c);
    return info;
  }
  if (horizontal) {
    info.key = "y";
    is.y = f.number("y");
    if (std::fabs(up->min[1] - is.y) > tol || std::fabs(lo->max[1] - is.y) > tol)
      fail(f.key("y"), is.y,
           fmt::format(
               "must be the bottom of the upper body ({:g}) and the top of the lower body ({:g})",
               up->min[1], lo->max[1]));
    is.start = f.number("start");
    is.end = f.number("end");
    const double x0 = std::max(up->min[0], lo->min[0]), x1 = std::min(up->max[0], lo->max[0]);
    if (!inside(is.start, x0, x1, tol))
      fail(f.key("start"), is.start,
           fmt::format("must lie where both bodies meet: [{:g}, {:g}] m", x0, x1));
    if (!(is.end > is.start) || !inside(is.end, x0, x1, tol))
      fail(f.key("end"), is.end, fmt::format("must lie in ({:g}, {:g}] m", is.start, x1));
    if (f.has("bonded_to")) {
      is.bonded = true;
      is.bonded_from = is.end;
      is.bonded_to = f.number("bonded_to");
      if (!(is.bonded_to > is.end) || !inside(is.bonded_to, x0, x1, tol))
        fail(f.key("bonded_to"), is.bonded_to,
             fmt::format("must lie in ({:g}, {:g}] m (the halves are tied from end to here)",
                         is.end, x1));
    }
    for (const char* k : {"closed", "bonded_points"})
      if (f.has(k)) fail(f.key(k), show(*f.node(k)), "only allowed with points = [[x, y], ...]");
    return info;
  }
  if (f.has("bonded_to"))
    fail(f.key("bonded_to"), show(*f.node("bonded_to")),
         "only allowed with the horizontal form (y, start, end); give bonded_points = [[x, y], "
         "...]");
  double sagitta = 0.0;  // the circle form's chords lie inside the circle by up to this, m
  if (polyline) {
    is.line = read_points(f, "points", 2);
    is.line.closed = f.boolean("closed", false);
    if (is.line.closed && is.line.num_vertices() < 3)
      fail(f.key("points"), double(is.line.num_vertices()),
           "a closed line needs at least 3 points");
  } else {
    double center[2];
    f.pair("center", center, true);
    const double radius = f.number("radius");
    if (!(radius > 0)) fail(f.key("radius"), radius, "must be > 0 (m)");
    if (segments < 8)
      fail(f.key("segments"), double(segments), "a circle needs at least 8 segments");
    // Its pieces must be longer than the geometry's tolerance (1e-9 of a cell, as for bodies).
    constexpr double kPiece = 3.141592653589793;
    const double piece = 2.0 * radius * std::sin(kPiece / double(segments));
    if (!(piece > 1e-9 * c.grid.cell_size))
      fail(f.key("radius"), radius,
           fmt::format("with {} segments the circle's pieces are {:.3g} m long, below the geometry "
                       "tolerance of 1e-9 x grid.cell_size = {:.3g} m: the circle is too small to "
                       "resolve",
                       segments, piece, 1e-9 * c.grid.cell_size));
    if (!std::isfinite(center[0] + radius) || !std::isfinite(center[1] + radius))
      fail(f.key("radius"), radius, "the circle must lie within range of a double");
    // A closed polygon with a vertex per segment, counter-clockwise: its normal points to the
    // centre, so the upper body is the one inside the circle.
    constexpr double kPi = 3.141592653589793;
    sagitta = radius * (1.0 - std::cos(kPi / double(segments)));
    info.circle = true;
    info.center[0] = center[0], info.center[1] = center[1];
    info.radius = radius;
    for (long k = 0; k < segments; ++k) {
      const double a = 2.0 * kPi * double(k) / double(segments);
      is.line.x.push_back(center[0] + radius * std::cos(a));
      is.line.y.push_back(center[1] + radius * std::sin(a));
    }
    is.line.closed = true;
  }
  const std::string key = polyline ? "points" : "center";
  info.key = key;
  info.slack = sagitta;
  check_line(f, key, is.line, c);
  if (std::size_t(segments) < is.line.num_pieces())
    fail(f.key("segments"), double(segments),
         fmt::format("must be at least the number of pieces of the line ({})",
                     is.line.num_pieces()));
  if (!up) return info;
  check_between_bodies(f, key, is.line, c, *up, *lo, sagitta);
  if (f.has("bonded_points")) {
    is.bonded_lines = {read_points(f, "bonded_points", 2)};
    check_line(f, "bonded_points", is.bonded_lines[0], c);
    check_between_bodies(f, "bonded_points", is.bonded_lines[0], c, *up, *lo);
    is.bonded = true;
  }
  return info;
}

// The keys of the laws other than `law` are an error, not ignored. Refused in the order the
// messages have always had, so that an input with several mistakes is told the same first one:
// `faults` the keys of fault laws (before rupture_slip_rate is read), else those of the
// cohesive laws: first the keys of one law only, law by law in the table's order, then those
// several laws share.
void refuse_keys_of_other_laws(Section& f, const LawEntry& law, bool faults) {
  auto shared = [](const std::string& k) {
    int owners = 0;
    for (const LawEntry& e : law_registry()) owners += e.has_key(k) ? 1 : 0;
    return owners > 1;
  };
  for (const bool of_several : {false, true})
    for (const LawEntry& other : law_registry())
      if (other.fault == faults)
        for (const std::string& k : other.keys)
          if (!law.has_key(k) && shared(k) == of_several && f.has(k))
            fail(f.key(k), show(*f.node(k)), "not a parameter of law = \"" + law.name + "\"");
}

// law = one of the registry's names (input/law_registry.hpp; the first is the default); the
// law's own parser reads its keys.
void parse_interface_law(Section& f, InterfaceSpec& is, const Case& c) {
  const LawEntry& law = *find_law(f.string("law", law_registry().front().name, law_names()));
  refuse_keys_of_other_laws(f, law, true);
  is.rupture_slip_rate = f.number("rupture_slip_rate", 1e-3);
  if (!(is.rupture_slip_rate > 0))
    fail(f.key("rupture_slip_rate"), is.rupture_slip_rate, "must be > 0 (m/s)");
  refuse_keys_of_other_laws(f, law, false);
  law.parse(f, is, c);
}

// Interfaces may meet at their ends (a kinked crack of two interfaces) but not cross: where two
// lines cross, a point of one would lie inside the other's faces. Bonded lines count too.
void check_no_crossing(Section& f, const InterfaceSpec& is, const Case& c) {
  const double tol = 1e-9 * c.grid.cell_size;
  // An end within round-off of the other line meets it (a stretch tied up to an earlier
  // interface's line ends on it, computed in floating point).
  auto meets_at_end = [tol](const Polyline& l, std::size_t i, std::size_t i1, const Polyline& m,
                            std::size_t j, std::size_t j1) {
    Polyline piece;
    piece.x = {m.x[j], m.x[j1]};
    piece.y = {m.y[j], m.y[j1]};
    return project(piece, l.x[i], l.y[i]).distance <= tol ||
           project(piece, l.x[i1], l.y[i1]).distance <= tol;
  };
  std::vector<Polyline> mine = is.tie_geometries();
  mine.push_back(is.geometry());
  for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
    std::vector<Polyline> theirs = c.interfaces[k].tie_geometries();
    theirs.push_back(c.interfaces[k].geometry());
    for (const Polyline& a : mine)
      for (const Polyline& b : theirs) {
        if (a.num_vertices() < 2 || b.num_vertices() < 2) continue;
        for (std::size_t i = 0; i < a.num_pieces(); ++i)
          for (std::size_t j = 0; j < b.num_pieces(); ++j) {
            const std::size_t i1 = a.piece_end(i), j1 = b.piece_end(j);
            if (!segments_cross(a.x[i], a.y[i], a.x[i1], a.y[i1], b.x[j], b.y[j], b.x[j1], b.y[j1]))
              continue;
            if (meets_at_end(a, i, i1, b, j, j1) || meets_at_end(b, j, j1, a, i, i1)) continue;
            fail(f.key(is.line.num_vertices() >= 2 ? "points" : "y"),
                 fmt::format("(piece from [{:g}, {:g}] to [{:g}, {:g}])", a.x[i], a.y[i], a.x[i1],
                             a.y[i1]),
                 fmt::format(
                     "crosses interface.{} (piece from [{:g}, {:g}] to [{:g}, {:g}]); interfaces "
                     "may meet at their ends but not cross",
                     c.interface_names[k], b.x[j], b.y[j], b.x[j1], b.y[j1]));
          }
      }
  }
}

// A growing line whose tied extension ends on another line drawn in the same body (a T-junction
// made by its tie): growth stops at such a tie (solver/crack_junction.hpp), so the input does,
// unless that line is on the edge of the crack's reach (input/crack_reach.hpp: its other face
// on a part no growing line changes), where it is followed as the tip grows, as an interface
// between the body and another is. Asked once every interface is known (a later line may split
// or grow the part beyond).
void check_growing_tie_ends(Section& f, std::size_t i, const Case& c) {
  const InterfaceSpec& is = c.interfaces[i];
  if (!is.growth.on()) return;
  const double tol = 1e-6 * c.grid.cell_size;
  const Shape& own = c.bodies[std::size_t(is.upper_body)].region.outer;
  for (const Polyline& t : is.bonded_lines)
    for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
      const InterfaceSpec& e = c.interfaces[k];
      if (!same_shape(c.bodies[std::size_t(e.upper_body)].region.outer, own) ||
          !same_shape(c.bodies[std::size_t(e.lower_body)].region.outer, own))
        continue;  // between the body and another: its face follows the crack's fields
      if (k == i || on_edge_of_reach(c, i, e)) continue;  // the edge of its reach: followed too
      for (const auto* faces : {&e.upper_faces, &e.lower_faces})
        for (std::size_t q = 1; q < faces->size(); ++q) {
          double x, y;
          point_at(c.interfaces[k].geometry(), (*faces)[q].from, x, y);
          for (const std::size_t v : {std::size_t(0), t.num_vertices() - 1}) {
            if (std::hypot(t.x[v] - x, t.y[v] - y) <= tol)
              fail(f.key("growth"), "\"" + f.string("growth", "") + "\"",
                   fmt::format("the line's tied extension ends on interface.{} at ({:.6g}, {:.6g}) "
                               "m (a T-junction of two lines drawn in one body): a line that grows "
                               "may have its extension end on another line in its body only where "
                               "that line's other side is a part no growing line changes "
                               "(docs/fracture.md, \"Junctions\"); end the line on it, or let the "
                               "extension miss it",
                               c.interface_names[k], x, y));
          }
        }
    }
}

}  // namespace

double cell_penalty_stiffness(const Case& c, const InterfaceSpec& is) {
  double m = 0.0;
  for (int b : {is.upper_body, is.lower_body})
    m = std::max(m, stiffness(c.materials[std::size_t(c.bodies[std::size_t(b)].material)], c.plane).c11);
  return m / c.grid.cell_size;
}

void parse_separated_contact(Section& f, InterfaceSpec& is, double default_stiffness,
                             bool contact_only) {
  is.contact = f.boolean("contact", contact_only);
  if (contact_only && !is.contact)
    fail(f.key("contact"), "false", "law = \"contact\" is contact only: it needs contact = true");
  const bool contact_keys =
      f.has("friction") || f.has("contact_stiffness") || f.has("contact_tangential_stiffness");
  if (!is.contact && contact_keys)
    fail(f.key("contact"), "false", "friction and contact_stiffness need contact = true");
  if (!is.contact) return;
  ContactLaw& k = is.contact_law;
  k.stiffness = f.number("contact_stiffness", default_stiffness);
  k.friction = f.number("friction", 0.0);
  k.tangential_stiffness = f.number("contact_tangential_stiffness", 0.0);
  fail_on_invalid(f, k.validate(),
                  {{"stiffness", "contact_stiffness"},
                   {"tangential_stiffness", "contact_tangential_stiffness"}});
  if (!(k.stiffness > 0))
    fail(f.key("contact_stiffness"), k.stiffness,
         "must be > 0 (Pa/m; the law's penalty is 0 here: give it)");
}

// A law's validate() message "name = value: rule" as the input error of its key (`keys` maps a
// parameter name to its input key where they differ).
void fail_on_invalid(Section& f, const std::string& problem,
                     const std::map<std::string, std::string>& keys) {
  if (problem.empty()) return;
  const std::size_t eq = problem.find(" = "), colon = problem.find(": ", eq);
  const std::string name = problem.substr(0, eq);
  const auto it = keys.find(name);
  fail(f.key(it == keys.end() ? name : it->second), problem.substr(eq + 3, colon - eq - 3),
       problem.substr(colon + 2));
}

void parse_interfaces(Section& top, Case& c, ParseContext& ctx) {
  Section ifs = top.table("interface", false);
  for (const auto& [k, v] : named_entries(ifs)) {
    const std::string& name = k;
    Section f = ifs.table(name, true, allowed_keys("interface.*"));
    InterfaceSpec is;
    if (f.has("body")) {
      // A line inside one body: the body is split along it (input/parse_body_split.cpp).
      for (const char* which : {"upper_body", "lower_body"})
        if (f.has(which))
          fail(f.key(which), show(*f.node(which)),
               fmt::format("give either {} (a line inside one body, which is split along it) or "
                           "upper_body and lower_body (a line between two bodies), not both",
                           f.key("body")));
      for (const char* tie : {"bonded_to", "bonded_points"})
        if (f.has(tie))
          fail(f.key(tie), show(*f.node(tie)),
               fmt::format("not allowed with {}: where the line ends inside the body it is "
                           "extended straight to the body's edge and tied there automatically "
                           "(docs/interfaces.md)",
                           f.key("body")));
      const InterfaceLine line = parse_interface_geometry(f, is, c, nullptr, nullptr);
      split_body_along_interface(f, is, c, ctx, name, line);
    } else {
      for (const char* which : {"upper_body", "lower_body"}) {
        if (!f.has(which))
          fail(f.key(which), "(missing)",
               fmt::format("required: upper_body and lower_body (a line between two bodies), or "
                           "{} alone (a line inside one body)",
                           f.key("body")));
        (std::string(which) == "upper_body" ? is.upper_body : is.lower_body) =
            single_body(f, which, c, ctx);
      }
      if (is.upper_body == is.lower_body)
        fail(f.key("lower_body"), "\"" + c.bodies[is.lower_body].name + "\"",
             "must differ from upper_body");
      const BodySpec &up = c.bodies[is.upper_body], &lo = c.bodies[is.lower_body];
      is.upper_field = up.field;
      is.lower_field = lo.field;
      // The interface joins two velocity fields: bodies of one field are one continuum.
      if (up.field == lo.field)
        fail(f.key("lower_body"), "\"" + lo.name + "\"",
             fmt::format("bodies.{} and bodies.{} share the velocity field \"{}\" (one continuum): "
                         "an interface must join bodies of two different fields (give one of "
                         "them its own bodies.NAME.field)",
                         up.name, lo.name, c.field_names[std::size_t(up.field)]));
      parse_interface_geometry(f, is, c, &up, &lo);
    }
    parse_interface_law(f, is, c);
    parse_drawn_open(f, is);
    parse_stress_intensity(f, is);
    parse_growth(f, is, c);
    parse_nucleation(f, is);
    reserve_branch_fields(f, is, c, name);
    check_no_crossing(f, is, c);
    c.interfaces.push_back(is);
    c.interface_names.push_back(name);
  }
  for (std::size_t i = 0; i < c.interfaces.size(); ++i) {
    Section f = ifs.table(c.interface_names[i], true, allowed_keys("interface.*"));
    check_growing_tie_ends(f, i, c);
  }
  // Split bodies got new fields as they came; number them again in order of first appearance
  // among the bodies (the parts of a body are listed after it), as fields always are.
  renumber_fields(c);
}

}  // namespace rupture
