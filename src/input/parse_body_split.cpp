// rupture/input/parse_body_split.cpp
// An interface inside one body (interface.NAME.body; docs/interfaces.md): the body is split
// along the line into two bodies in two velocity fields, here, when the case is built, so the
// solver sees what it always sees: two bodies joined by an interface, tied where bonded.
//  - The line must lie inside the body, or inside one part of it once earlier lines have split
//    it: points just off both its sides are in that part. Its ends may lie on the body's edge.
//  - An open line is extended straight beyond each end (along its end piece) until it leaves a
//    frame around the body. Wherever an extension runs through the part's material it is tied
//    (a bonded line of the interface): beyond the crack's ends the body stays intact. An end on
//    the edge adds nothing (unless its extension enters the body again, as across a notch).
//    The part on the side the line's normal points to keeps the body's name, index and field;
//    the other side becomes the body NAME.below.IFACE, with a field of that name, listed right
//    after it.
//  - A closed line (points with closed = true, or a circle) needs no extension: its inside
//    becomes NAME.inside.IFACE.
//  - Particles are seeded exactly as for the unsplit body; each goes to the part whose side of
//    the cut holds it (geometry/shape.hpp Region::sides).
//  - Earlier interfaces whose face lay on the body move to the part now holding that face. A
//    face the new line ends on (a T-junction) changes field there (InterfaceSpec::upper_faces);
//    any other face the cut would divide between the two parts, or a tied stretch it divides,
//    is an InputError.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "input/case_parse.hpp"

namespace rupture {
namespace {

constexpr int kSamples = 64;  // points per piece and side, as the two-body check samples

// The value of the key the line was given by: y (horizontal form), points or center.
std::string describe_line(const std::string& key, const Polyline& l) {
  if (key == "y")
    return fmt::format("{:g} (the line from x = {:g} to {:g})", l.y[0], l.x[0], l.x[1]);
  auto point = [&](std::size_t k) { return fmt::format("[{:g}, {:g}]", l.x[k], l.y[k]); };
  const std::size_t n = l.num_vertices();
  std::string s = "[";
  if (n <= 4) {
    for (std::size_t k = 0; k < n; ++k) s += (k ? ", " : "") + point(k);
  } else {
    s += point(0) + ", " + point(1) + fmt::format(", ... {} points ..., ", n) + point(n - 1);
  }
  return s + "]" + (l.closed ? " (closed)" : "");
}

// Points `off` away from the line on one side (+1: where its normal points, -1: the other),
// along every piece, skipping the very ends of a piece (a vertex may sit on a body's edge).
template <class Visit>
void side_points(const Polyline& line, double off, int side, Visit visit) {
  for (std::size_t i = 0; i < line.num_pieces(); ++i) {
    const std::size_t j = line.piece_end(i);
    const double len = line.piece_length(i);
    const double tx = (line.x[j] - line.x[i]) / len, ty = (line.y[j] - line.y[i]) / len;
    for (int k = 0; k <= kSamples; ++k) {
      const double a = len * (0.001 + 0.998 * double(k) / kSamples);
      visit(line.x[i] + a * tx - side * off * ty, line.y[i] + a * ty + side * off * tx, i);
    }
  }
}

// The part (of `parts`, the bodies the name `body` stands for) that holds the whole line.
int part_holding_line(Section& f, const std::string& key, const Polyline& line,
                      const std::string& body, const std::vector<int>& parts, const Case& c,
                      double off) {
  for (const int p : parts) {
    bool all = true;
    for (const int side : {1, -1})
      side_points(line, off, side, [&](double x, double y, std::size_t) {
        all = all && body_contains(c.bodies[std::size_t(p)], x, y);
      });
    if (all) return p;
  }
  // Say why: a point outside the body, or a line passing from one part into another.
  int first_part = -1;
  Point at_first, at_other;
  std::string other;
  for (const int side : {1, -1})
    side_points(line, off, side, [&](double x, double y, std::size_t piece) {
      int in = -1;
      for (const int p : parts)
        if (body_contains(c.bodies[std::size_t(p)], x, y)) in = p;
      if (in < 0)
        fail(f.key(key), describe_line(key, line),
             fmt::format("must lie inside bodies.{} (its ends may lie on the body's edge): the "
                         "point ({:.6g}, {:.6g}) m next to piece {} is outside it",
                         body, x, y, piece));
      if (first_part < 0) first_part = in, at_first = {x, y};
      if (in != first_part && other.empty())
        other = c.bodies[std::size_t(in)].name, at_other = {x, y};
    });
  fail(f.key(key), describe_line(key, line),
       fmt::format("runs through two parts of bodies.{} that earlier lines inside it made: "
                   "bodies.{} (near ({:.6g}, {:.6g}) m) and bodies.{} (near ({:.6g}, {:.6g}) m); "
                   "a line inside a body must lie inside one of its parts (lines may not cross, "
                   "nor run along or end on another line's tied extension)",
                   body, c.bodies[std::size_t(first_part)].name, at_first.x, at_first.y, other,
                   at_other.x, at_other.y));
}

// How a body is cut: the new part is the one inside `shape`.
struct Split {
  Shape shape;
  bool new_part_is_upper = false;  // the line's normal points into the new part
  const char* new_side = "below";  // names: NAME.<new_side>.IFACE, NAME.<kept_side>.IFACE
  const char* kept_side = "above";
  std::vector<Polyline> ties;  // the extensions' stretches through the body, tied
};

Split plan_split(Section& f, const std::string& key, const Polyline& line,
                 const InterfaceLine& info, const BodySpec& body, const Case& c) {
  Split s;
  if (line.closed) {
    s.new_side = "inside", s.kept_side = "outside";
    if (info.circle) {
      // The circle itself, as for a circular body: the polygon of the line lies inside it by
      // at most its sagitta, and its normal points to the centre.
      s.shape.kind = ShapeKind::circle;
      s.shape.center[0] = info.center[0], s.shape.center[1] = info.center[1];
      s.shape.radii[0] = s.shape.radii[1] = info.radius;
      s.new_part_is_upper = true;
    } else {
      s.shape.kind = ShapeKind::polygon;
      for (std::size_t k = 0; k < line.num_vertices(); ++k)
        s.shape.vertices.push_back({line.x[k], line.y[k]});
      s.new_part_is_upper = signed_area(s.shape.vertices) > 0.0;  // counter-clockwise
    }
    return s;
  }
  // A frame around the body and the line with room to spare: the extensions run out to it.
  Box frame = bounding_box(body.region);
  for (std::size_t k = 0; k < line.num_vertices(); ++k) {
    frame.min[0] = std::min(frame.min[0], line.x[k]),
    frame.max[0] = std::max(frame.max[0], line.x[k]);
    frame.min[1] = std::min(frame.min[1], line.y[k]),
    frame.max[1] = std::max(frame.max[1], line.y[k]);
  }
  const double pad =
      c.grid.cell_size + 0.01 * std::max(frame.max[0] - frame.min[0], frame.max[1] - frame.min[1]);
  for (int d = 0; d < 2; ++d) frame.min[d] -= pad, frame.max[d] += pad;
  const std::size_t n = line.num_vertices();
  const Point first{line.x[0], line.y[0]}, last{line.x[n - 1], line.y[n - 1]};
  const Point back{line.x[0] - line.x[1], line.y[0] - line.y[1]};
  const Point ahead{line.x[n - 1] - line.x[n - 2], line.y[n - 1] - line.y[n - 2]};
  const Point start = leave_box(frame, first, back), end = leave_box(frame, last, ahead);
  // Tied wherever an extension runs through the material; each stretch runs in the line's
  // direction and the one at an end inside the body begins or ends exactly on that end.
  const double tol = 1e-9 * c.grid.cell_size;
  std::vector<Stretch> stretches = inside_stretches(body.region, start, first);
  for (const Stretch& st : inside_stretches(body.region, last, end)) stretches.push_back(st);
  for (const Stretch& st : stretches) {
    if (std::hypot(st.to.x - st.from.x, st.to.y - st.from.y) <= tol) continue;
    Polyline tie;
    tie.x = {st.from.x, st.to.x};
    tie.y = {st.from.y, st.to.y};
    s.ties.push_back(tie);
  }
  // The new part is the side opposite the normal: left of the cut walked backwards.
  std::vector<Point> cut{end, last};
  for (std::size_t k = n - 1; k-- > 0;) cut.push_back({line.x[k], line.y[k]});
  cut.push_back(start);
  s.shape = left_part(frame, cut);
  if (polygon_self_intersection(s.shape.vertices))
    fail(f.key(key), describe_line(key, line),
         fmt::format("extended straight beyond its ends (to ({:.6g}, {:.6g}) and ({:.6g}, "
                     "{:.6g}) m), the line crosses itself, so it does not cut bodies.{} in two; a "
                     "line inside a body must not turn so far that its extensions meet it (or "
                     "give the two parts as bodies, with upper_body and lower_body)",
                     start.x, start.y, end.x, end.y, body.name));
  return s;
}

// Adds the new part after body b and points the interface at both parts; returns its index.
int apply_split(Section& f, InterfaceSpec& is, Case& c, ParseContext& ctx, const std::string& iface,
                int b, const Split& s) {
  const std::string base = c.bodies[std::size_t(b)].name;
  const std::string part = base + "." + s.new_side + "." + iface;
  const std::string kept = base + "." + s.kept_side + "." + iface;
  for (const std::string& name : {part, kept})
    if (ctx.body_parts.count(name) ||
        std::find(c.field_names.begin(), c.field_names.end(), name) != c.field_names.end())
      fail(f.key("body"), "\"" + base + "\"",
           fmt::format("splitting it names its parts \"{}\" and \"{}\", but \"{}\" is already a "
                       "body or field name: rename that body or field",
                       kept, part, name));
  if (c.field_names.size() >= 255)
    fail(f.key("body"), "\"" + base + "\"",
         "splitting the body adds a velocity field, and there are 255 already (at most 255)");
  BodySpec added = c.bodies[std::size_t(b)];
  added.name = part;
  added.region.sides.push_back({s.shape, true});
  added.field = int(c.field_names.size());
  c.field_names.push_back(part);
  c.bodies[std::size_t(b)].region.sides.push_back({s.shape, false});
  // Listed right after the body: later indices move up by one.
  const int at = b + 1;
  for (auto& [name, parts] : ctx.body_parts)
    for (int& p : parts)
      if (p >= at) ++p;
  for (InterfaceSpec& e : c.interfaces) {
    if (e.upper_body >= at) ++e.upper_body;
    if (e.lower_body >= at) ++e.lower_body;
  }
  c.bodies.insert(c.bodies.begin() + at, added);
  // Every name that stood for body b now stands for both its parts.
  for (auto& [name, parts] : ctx.body_parts)
    if (std::find(parts.begin(), parts.end(), b) != parts.end()) parts.push_back(at);
  ctx.body_parts[part] = {at};
  ctx.body_parts[kept] = {b};
  is.upper_body = s.new_part_is_upper ? at : b;
  is.lower_body = s.new_part_is_upper ? b : at;
  is.upper_field = c.bodies[std::size_t(is.upper_body)].field;
  is.lower_field = c.bodies[std::size_t(is.lower_body)].field;
  is.bonded_lines = s.ties;
  is.bonded = !s.ties.empty();
  return at;
}

// Points as side_points, with their arc length along the line (m) instead of the piece.
template <class Visit>
void side_points_along(const Polyline& line, double off, int side, Visit visit) {
  std::vector<double> at{0.0};
  for (std::size_t i = 0; i < line.num_pieces(); ++i) at.push_back(at.back() + line.piece_length(i));
  side_points(line, off, side, [&](double x, double y, std::size_t piece) {
    const double dx = x - line.x[piece], dy = y - line.y[piece];
    const std::size_t j = line.piece_end(piece);
    const double len = line.piece_length(piece);
    visit(x, y, at[piece] + (dx * (line.x[j] - line.x[piece]) + dy * (line.y[j] - line.y[piece])) / len);
  });
}

[[noreturn]] void fail_divided_face(Section& f, const std::string& key, const Polyline& line,
                                    const Case& c, std::size_t k, int side, int b, int at,
                                    Point kept_at, Point new_at, const char* why) {
  fail(f.key(key), describe_line(key, line),
       fmt::format("splits bodies.{} across the {} face of interface.{}, which would lie partly on "
                   "bodies.{} (near ({:.6g}, {:.6g}) m) and partly on bodies.{} (near ({:.6g}, "
                   "{:.6g}) m), two velocity fields; {}",
                   c.bodies[std::size_t(b)].name, side > 0 ? "upper" : "lower", c.interface_names[k],
                   c.bodies[std::size_t(b)].name, kept_at.x, kept_at.y,
                   c.bodies[std::size_t(at)].name, new_at.x, new_at.y, why));
}

// Earlier interfaces with a face on body b: the face now lies on b or on the new part `at`, or
// partly on each where the new line ends on it (a T-junction): the face then changes field at
// that end (InterfaceSpec::upper_faces / lower_faces). Their tied stretches must lie on one part.
void move_earlier_faces(Section& f, const std::string& key, const Polyline& line,
                        const std::vector<Polyline>& ties, Case& c, int b, int at, double off) {
  const double h = c.grid.cell_size;
  for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
    InterfaceSpec& e = c.interfaces[k];
    const Polyline geometry = e.geometry();
    for (const int side : {1, -1}) {
      int& body = side > 0 ? e.upper_body : e.lower_body;
      int& field = side > 0 ? e.upper_field : e.lower_field;
      std::vector<FaceField>& faces = side > 0 ? e.upper_faces : e.lower_faces;
      const std::vector<FaceField> before =
          faces.empty() ? std::vector<FaceField>{{0.0, field, body}} : faces;
      // The tied stretches move whole: they stay on upper_field / lower_field.
      if (body == b) {
        long on_kept = 0, on_new = 0;
        Point kept_at, new_at;
        for (const Polyline& l : e.tie_geometries())
          side_points(l, off, side, [&](double x, double y, std::size_t) {
            if (body_contains(c.bodies[std::size_t(b)], x, y)) ++on_kept, kept_at = {x, y};
            if (body_contains(c.bodies[std::size_t(at)], x, y)) ++on_new, new_at = {x, y};
          });
        if (on_new > 0 && on_kept > 0)
          fail_divided_face(f, key, line, c, k, side, b, at, kept_at, new_at,
                            "a line inside a body may not end on another line's tied extension, "
                            "nor run, extended straight, through a region another interface "
                            "encloses");
        if (on_new > 0) body = at, field = c.bodies[std::size_t(at)].field;
      }
      // The line's own face, stretch by stretch.
      std::vector<FaceField> after;
      for (std::size_t q = 0; q < before.size(); ++q) {
        const FaceField& st = before[q];
        if (st.body != b) {
          after.push_back(st);
          continue;
        }
        const double to = q + 1 < before.size() ? before[q + 1].from : INFINITY;
        std::vector<std::pair<double, bool>> samples;  // (arc length, on the new part)
        Point kept_at, new_at;
        side_points_along(geometry, off, side, [&](double x, double y, double sp) {
          if (sp < st.from || sp > to) return;
          const bool in_new = body_contains(c.bodies[std::size_t(at)], x, y);
          if (in_new) new_at = {x, y};
          else if (body_contains(c.bodies[std::size_t(b)], x, y)) kept_at = {x, y};
          else return;
          samples.push_back({sp, in_new});
        });
        const long on_new = std::count_if(samples.begin(), samples.end(), [](auto& v) { return v.second; });
        if (on_new == 0 || on_new == long(samples.size())) {
          after.push_back(on_new ? FaceField{st.from, c.bodies[std::size_t(at)].field, at} : st);
          continue;
        }
        // Divided: only where the new line, or its tied extension, ends on this one, each part
        // on one side of that end (beside a tie's end both parts are tied: one continuum).
        std::vector<Point> ends{{line.x.front(), line.y.front()}, {line.x.back(), line.y.back()}};
        for (const Polyline& t : ties)
          ends.push_back({t.x.front(), t.y.front()}), ends.push_back({t.x.back(), t.y.back()});
        double s_end = 0.0, best = INFINITY;
        for (const Point& q : ends) {
          const LineProjection pr = project(geometry, q.x, q.y);
          if (pr.distance < best && pr.beyond == 0.0) best = pr.distance, s_end = pr.s;
        }
        const char* why =
            "a line inside a body (or its tied extension) may end on another line (a "
            "T-junction), which then changes field at that end, but it may not cross it, nor "
            "run, extended straight, through a region another interface encloses";
        if (line.closed || best > 1e-6 * h)
          fail_divided_face(f, key, line, c, k, side, b, at, kept_at, new_at, why);
        int first = -1;  // which part holds the face before the end (0 kept, 1 new)
        for (const auto& [sp, in_new] : samples) {
          if (std::fabs(sp - s_end) <= 1e-3 * h) continue;  // at the end itself
          const int part = in_new ? 1 : 0;
          if (sp < s_end && first < 0) first = part;
          if ((sp < s_end && part != first) || (sp > s_end && part == first) || first < 0)
            fail_divided_face(f, key, line, c, k, side, b, at, kept_at, new_at, why);
        }
        if (e.growth.on())
          fail(f.key(key), describe_line(key, line),
               fmt::format("ends on interface.{}, whose {} face would then change velocity field "
                           "at that end (a T-junction); a line that grows (interface.{}.growth) "
                           "may not have another end on it (yet)",
                           c.interface_names[k], side > 0 ? "upper" : "lower", c.interface_names[k]));
        const int fields[2] = {c.bodies[std::size_t(b)].field, c.bodies[std::size_t(at)].field};
        const int bodies[2] = {b, at};
        after.push_back({st.from, fields[first], bodies[first]});
        after.push_back({s_end, fields[1 - first], bodies[1 - first]});
      }
      // Neighbours on one field are one stretch; a face all on the ties' field is uniform.
      faces.clear();
      for (const FaceField& st : after)
        if (faces.empty() || faces.back().field != st.field) faces.push_back(st);
      if (e.tie_geometries().empty()) body = faces[0].body, field = faces[0].field;
      if (faces.size() == 1 && faces[0].field == field) faces.clear();
    }
  }
}

}  // namespace

void split_body_along_interface(Section& f, InterfaceSpec& is, Case& c, ParseContext& ctx,
                                const std::string& name, const InterfaceLine& info) {
  const std::string body = f.string("body", "");
  const std::vector<int> parts = named_bodies(f, "body", body, c, ctx);  // a copy: it changes
  const Polyline line = is.geometry();
  const double off = 1e-3 * c.grid.cell_size;  // "just off the line", as the two-body check
  const int b = part_holding_line(f, info.key, line, body, parts, c, off);
  const Split s = plan_split(f, info.key, line, info, c.bodies[std::size_t(b)], c);
  const int at = apply_split(f, is, c, ctx, name, b, s);
  move_earlier_faces(f, info.key, line, is.bonded_lines, c, b, at, off);
}

void renumber_fields(Case& c) {
  std::vector<int> number(c.field_names.size(), -1);
  std::vector<std::string> names;
  for (const BodySpec& b : c.bodies) {
    int& k = number[std::size_t(b.field)];
    if (k < 0) k = int(names.size()), names.push_back(c.field_names[std::size_t(b.field)]);
  }
  // The fields kept for branches' wedges (no body yet) after every body's, in input order.
  for (const InterfaceSpec& i : c.interfaces)
    for (const int f : i.branch_fields) number[std::size_t(f)] = int(names.size()), names.push_back(c.field_names[std::size_t(f)]);
  for (BodySpec& b : c.bodies) b.field = number[std::size_t(b.field)];
  for (InterfaceSpec& i : c.interfaces) {
    i.upper_field = number[std::size_t(i.upper_field)];
    i.lower_field = number[std::size_t(i.lower_field)];
    for (auto* faces : {&i.upper_faces, &i.lower_faces})
      for (FaceField& st : *faces) st.field = number[std::size_t(st.field)];
    for (int& f : i.branch_fields) f = number[std::size_t(f)];
  }
  c.field_names = names;
}

}  // namespace rupture
