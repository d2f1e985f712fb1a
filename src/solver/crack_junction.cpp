// rupture/solver/crack_junction.cpp
#include "solver/crack_junction.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "input/crack_reach.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/crack_cut.hpp"
#include "solver/rank_exchange.hpp"

namespace rupture {

namespace {

// The fields of the crack's lines (their faces', as drawn: a crack's faces change no field).
std::vector<int> crack_fields(const State& L, const std::vector<std::size_t>& own) {
  std::vector<int> f;
  for (const std::size_t slot : own)
    for (const int x : {L.interfaces[slot].spec.upper_field, L.interfaces[slot].spec.lower_field})
      if (std::find(f.begin(), f.end(), x) == f.end()) f.push_back(x);
  return f;
}

// The fields a face lies on (its stretches', or the whole face's).
std::vector<int> face_fields(const std::vector<FaceField>& faces, int whole) {
  std::vector<int> f;
  for (const FaceField& x : faces) f.push_back(x.field);
  if (f.empty()) f.push_back(whole);
  return f;
}

// Whether `line` has cut the crack's body in two for good (cut_off_parts): 1 when the part on
// its upper face's side is cut off, -1 its lower face's, 0 neither. A closed line (an inclusion's
// edge) has no tip either; what it holds is beyond the crack's reach only as the set-up says
// (input/crack_reach.hpp).
int cuts_off(const CohesiveInterface& line, const std::vector<int>& mine, double tol) {
  const InterfaceSpec& spec = line.spec;
  if (line.closed || !spec.tie_geometries().empty() || !precrack_tips(spec, tol).empty()) return 0;
  const auto on_crack = [&](const std::vector<int>& f) {
    return std::all_of(f.begin(), f.end(), [&](int x) { return std::find(mine.begin(), mine.end(), x) != mine.end(); });
  };
  const auto one_other = [&](const std::vector<int>& f) {
    return std::all_of(f.begin(), f.end(), [&](int x) { return x == f.front() && std::find(mine.begin(), mine.end(), x) == mine.end(); });
  };
  const std::vector<int> up = face_fields(spec.upper_faces, spec.upper_field);
  const std::vector<int> lo = face_fields(spec.lower_faces, spec.lower_field);
  if (on_crack(lo) && one_other(up)) return 1;
  if (on_crack(up) && one_other(lo)) return -1;
  return 0;
}

}  // namespace

std::vector<std::vector<Side>> cut_off_parts(const Case& c, const RunState& s, std::size_t k,
                                             const std::vector<std::size_t>& own) {
  const State& L = s.levels[std::size_t(s.interface_levels[k])];
  const double h = L.grid.cell_size();
  const std::vector<int> mine = crack_fields(L, own);
  const Region body = crack_body(c, k);
  std::vector<std::vector<Side>> parts;
  for (std::size_t slot = 0; slot < L.interfaces.size(); ++slot) {
    if (std::find(own.begin(), own.end(), slot) != own.end()) continue;
    const InterfaceSpec& spec = L.interfaces[slot].spec;
    if (!drawn_in_crack_body(c, k, spec)) continue;
    const int side = cuts_off(L.interfaces[slot], mine, 1e-6 * h);
    if (side == 0) continue;
    const Polyline line = spec.geometry();
    const std::size_t n = line.num_vertices();
    if (n < 2) continue;
    const Point first{line.x[0], line.y[0]}, last{line.x[n - 1], line.y[n - 1]};
    const Box frame = cut_frame(body, line, first, h);
    std::vector<Point> walk{leave_box(frame, first, unit(Point{line.x[1], line.y[1]}, first))};
    for (std::size_t i = 0; i < n; ++i) walk.push_back({line.x[i], line.y[i]});
    walk.push_back(leave_box(frame, last, unit(Point{line.x[n - 2], line.y[n - 2]}, last)));
    // Left of the line's direction is its upper face's side.
    parts.push_back({Side{left_part(frame, walk), side > 0}});
  }
  return parts;
}

std::vector<OtherLine> other_lines(const Case& c, const RunState& s, const std::vector<CrackGrowthRecord>& records,
                                   std::size_t k, const std::vector<std::size_t>& own) {
  const int level = s.interface_levels[k];
  const State& L = s.levels[std::size_t(level)];
  const std::vector<int> mine = crack_fields(L, own);
  std::vector<OtherLine> lines;
  for (std::size_t slot = 0; slot < L.interfaces.size(); ++slot) {
    if (std::find(own.begin(), own.end(), slot) != own.end()) continue;
    const InterfaceSpec& spec = L.interfaces[slot].spec;
    std::string name = "a line";
    for (std::size_t j = 0; j < c.interfaces.size() && j < s.interface_slots.size(); ++j) {
      if (s.interface_levels[j] == level && s.interface_slots[j] == slot)
        name = fmt::format("interface '{}'", c.interface_names[j]);
      if (j < records.size())
        for (const std::size_t b : records[j].branch_slots)
          if (b == slot) name = fmt::format("a branch of interface '{}'", c.interface_names[j]);
    }
    const bool in_body = drawn_in_crack_body(c, k, spec);
    const bool edge =
        in_body && (on_edge_of_reach(c, k, spec) || cuts_off(L.interfaces[slot], mine, 1e-6 * L.grid.cell_size()) != 0);
    lines.push_back({spec.geometry(), name, false, in_body, edge, slot});
    for (const Polyline& t : spec.tie_geometries()) lines.push_back({t, name, true, in_body, edge, slot});
  }
  return lines;
}

namespace {

std::string body_of(const Case& c, std::size_t k) {
  return c.bodies[std::size_t(c.interfaces[k].upper_body)].name;
}

}  // namespace

void stop_at_segment_junction(const Case& c, std::size_t k, double time, const std::vector<OtherLine>& others,
                              const Point& from, const Point& to, double h) {
  for (const OtherLine& o : others) {
    const std::optional<LineMeeting> m = segment_meets_line(o.line, from, to, h);
    if (!m) continue;
    const std::string what =
        o.in_body ? fmt::format("a junction of two lines drawn inside one body ({}) is not supported yet (each crack "
                                "splits the body into two velocity fields along itself and its tied extension; the "
                                "pieces a junction cuts off would need fields of their own",
                                body_of(c, k))
                  : fmt::format("a crack that reaches an interface between two bodies (a T-junction on the edge of "
                                "{}) is not supported yet (that interface's face would lie on the two velocity "
                                "fields on either side of the crack",
                                body_of(c, k));
    throw SimulationError(fmt::format(
        "crack growth: interface '{}' has its tip at ({:.6g}, {:.6g}) m at t = {:.6g} s, and its next "
        "segment, to ({:.6g}, {:.6g}) m, comes within {:.3g} m (one cell) of {}'s {} at ({:.6g}, {:.6g}) m: "
        "{}: docs/fracture.md, \"Junctions\"); the run stops here, with what it wrote. Draw the lines "
        "farther apart{}",
        c.interface_names[k], from.x, from.y, time, to.x, to.y, h, o.name,
        o.tie ? "tied extension (intact material, where it holds its two fields together)" : "line", m->at.x,
        m->at.y, what, o.in_body ? ", or in separate bodies joined by an [interface]" : ""));
  }
}

void stop_at_tie_junction(const Case& c, std::size_t k, double time, const std::vector<OtherLine>& others,
                          const std::vector<Polyline>& ties, double h) {
  for (const Polyline& tie : ties)
    for (std::size_t i = 0; i + 1 < tie.num_vertices(); ++i)
      for (const OtherLine& o : others) {
        const std::optional<LineMeeting> m =
            segment_meets_line(o.line, {tie.x[i], tie.y[i]}, {tie.x[i + 1], tie.y[i + 1]}, 1e-6 * h);
        if (!m) continue;
        throw SimulationError(fmt::format(
            "crack growth: interface '{}' turned at t = {:.6g} s so that its tied extension (from "
            "({:.6g}, {:.6g}) m to ({:.6g}, {:.6g}) m, the straight way on to the edge of {}) meets {}'s {} at "
            "({:.6g}, {:.6g}) m: {} is not supported yet (that interface's face would lie on two velocity "
            "fields, those on either side of the crack: docs/fracture.md, \"Junctions\"); the run stops "
            "here, with what it wrote",
            c.interface_names[k], time, tie.x[i], tie.y[i], tie.x[i + 1], tie.y[i + 1], body_of(c, k), o.name,
            o.tie ? "tied extension" : "line", m->at.x, m->at.y,
            o.in_body ? "ties of two lines in one body that meet"
                      : "a crack heading for an interface between two bodies (a T-junction on the body's edge)"));
      }
}

std::vector<OtherLine> junction_lines(const std::vector<OtherLine>& others) {
  std::vector<OtherLine> out;
  for (const OtherLine& o : others)
    if ((o.in_body && !o.edge) || o.tie) out.push_back(o);
  return out;
}

namespace {

// The field of the crack's particle (fields a or b) nearest to each point in the reference
// configuration, within `within` (m); -1: none. Distributed: the nearest over every rank (two
// collective maxima for all the points; ties in distance go to the lower field).
std::vector<int> nearest_fields(const State& L, int a, int b, const std::vector<Point>& at, double within) {
  const Particles& P = L.particles;
  const std::size_t n = at.size();
  std::vector<double> best(n, within);
  std::vector<int> field(n, -1);
  for (std::size_t q = 0; q < P.size(); ++q) {
    if (P.field[q] != a && P.field[q] != b) continue;
    for (std::size_t i = 0; i < n; ++i) {
      const double d = std::hypot(P.x0[q] - at[i].x, P.y0[q] - at[i].y);
      if (d < best[i] || (d == best[i] && field[i] >= 0 && P.field[q] < field[i])) best[i] = d, field[i] = P.field[q];
    }
  }
  std::vector<double> v(n);  // -distance: the largest over the ranks is the nearest
  for (std::size_t i = 0; i < n; ++i) v[i] = field[i] >= 0 ? -best[i] : -INFINITY;
  max_over_ranks(L, v.data(), n);
  for (std::size_t i = 0; i < n; ++i) v[i] = field[i] >= 0 && -best[i] == v[i] ? -double(field[i]) : -INFINITY;
  max_over_ranks(L, v.data(), n);
  std::vector<int> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = std::isfinite(v[i]) ? int(-v[i]) : -1;
  return out;
}

int nearest_field(const State& L, int a, int b, double x, double y, double within) {
  return nearest_fields(L, a, b, {Point{x, y}}, within)[0];
}

}  // namespace

void follow_edge_junctions(const Case& c, RunState& s, std::size_t k, const std::vector<std::size_t>& own,
                           const std::vector<OtherLine>& others, double time, double h) {
  const int level = s.interface_levels[k];
  State& L = s.levels[std::size_t(level)];
  const InterfaceSpec& crack = L.interfaces[own.front()].spec;
  const int fa = crack.upper_field, fb = crack.lower_field;
  const double tol = 1e-6 * h;
  // Where the crack's lines may come to the interface: its ends and its ties' vertices (their
  // ends, and the bend where a tie's lead turns to the drawn direction, which may then run
  // along the interface less than a cell from it, with no particle between).
  std::vector<Point> ends;
  for (const std::size_t slot : own) {
    const Polyline line = L.interfaces[slot].spec.geometry();
    if (line.num_vertices() >= 2)
      ends.push_back({line.x.front(), line.y.front()}), ends.push_back({line.x.back(), line.y.back()});
    for (const Polyline& t : L.interfaces[slot].spec.tie_geometries())
      for (std::size_t v = 0; v < t.num_vertices(); ++v) ends.push_back({t.x[v], t.y[v]});
  }
  bool changed = false;
  for (const OtherLine& o : others) {
    if ((o.in_body && !o.edge) || o.tie) continue;
    CohesiveInterface& B = L.interfaces[o.slot];
    const Polyline line = B.spec.geometry();
    std::vector<double> meet;
    Point at;
    for (const Point& q : ends) {
      const LineProjection pr = project(line, q.x, q.y);
      if (pr.distance <= h && pr.beyond == 0.0) meet.push_back(pr.s), at = q;
    }
    // The side of the interface on the crack's body: the face wholly on the crack's fields.
    auto on = [&](const std::vector<FaceField>& faces, int whole) {
      if (faces.empty()) return whole == fa || whole == fb;
      return std::all_of(faces.begin(), faces.end(), [&](const FaceField& f) { return f.field == fa || f.field == fb; });
    };
    const int side = on(B.spec.upper_faces, B.spec.upper_field) ? 1 : on(B.spec.lower_faces, B.spec.lower_field) ? -1 : 0;
    std::vector<FaceField>& faces = side > 0 ? B.spec.upper_faces : B.spec.lower_faces;
    if (meet.empty() && (side == 0 || faces.empty())) continue;
    const auto fail = [&](const std::string& why) {
      throw SimulationError(fmt::format(
          "crack growth: interface '{}' meets {} at ({:.6g}, {:.6g}) m at t = {:.6g} s (a T-junction on the "
          "edge of {}): {}, which is not supported yet (docs/fracture.md, \"Junctions\"); the run stops "
          "here, with what it wrote",
          c.interface_names[k], o.name, at.x, at.y, time, body_of(c, k), why));
    };
    if (own.size() > 1) fail("the crack has branched");
    if (side == 0) fail("that interface's faces lie on neither of the crack's two fields");
    // Its tied stretches: each joins the crack's material beside it to the other face's. Where
    // the crack's cut runs on along the line into a stretch, the piece it cuts off is on the
    // crack's other field there, and that stretch takes its own pair of fields (BondedTie::of).
    // The field beside each stretch: the crack's particles half a cell off it, a cell from each
    // end and at its middle. Where they differ, the crack's own tie runs along the stretch with
    // less than a cell between them (the cut cannot divide it: a tie that touches another line's
    // tie stops the run, stop_at_tie_junction); the nodes both ties reach then join all three
    // fields (TieJunctions), and the stretch keeps its pair.
    const std::vector<Polyline> ties = B.spec.tie_geometries();
    if (!ties.empty()) {
      const int tied = side > 0 ? B.spec.upper_field : B.spec.lower_field;
      const int across = side > 0 ? B.spec.lower_field : B.spec.upper_field;
      std::vector<Point> beside;
      for (const Polyline& t : ties) {
        const double lt = t.length();
        for (const double along : {std::min(h, 0.5 * lt), 0.5 * lt, std::max(lt - h, 0.5 * lt)}) {
          double x, y;
          point_at(t, along, x, y);
          const LineProjection pr = project(line, x, y);
          beside.push_back({x + side * 0.5 * h * pr.nx, y + side * 0.5 * h * pr.ny});
        }
      }
      const std::vector<int> f = nearest_fields(L, fa, fb, beside, 0.75 * h);
      std::vector<BondedTie> own_pairs;  // the stretches on the crack's other field
      for (std::size_t i = 0; i < ties.size(); ++i) {
        int field = -1;
        bool mixed = false;
        for (std::size_t j = 3 * i; j < 3 * i + 3; ++j) {
          if (f[j] < 0) continue;
          mixed = mixed || (field >= 0 && f[j] != field);
          field = f[j];
        }
        if (field < 0 || field == tied || mixed) continue;
        BondedTie b;
        b.upper_field = side > 0 ? field : across;
        b.lower_field = side > 0 ? across : field;
        b.of = o.slot, b.line = int(i);
        own_pairs.push_back(b);
      }
      // Set where they changed (each rank alike: the fields are read over all ranks); the
      // line's own entry keeps the others. Laid over the whole grid: the driver distributes the
      // ties again (parallel/halo.hpp, follow_grown_interfaces).
      std::vector<BondedTie> had;
      for (const BondedTie& b : L.bonded)
        if (b.of == o.slot) had.push_back(b);
      const auto same = [](const BondedTie& p, const BondedTie& q) {
        return p.line == q.line && p.upper_field == q.upper_field && p.lower_field == q.lower_field;
      };
      if (had.size() != own_pairs.size() || !std::equal(had.begin(), had.end(), own_pairs.begin(), same)) {
        if (s.levels.size() > 1)
          fail("a tied stretch of that line would join another pair of fields than the rest of it, which "
               "is not supported on nested levels");
        std::erase_if(L.bonded, [&](const BondedTie& b) { return b.of == o.slot; });
        std::vector<Polyline> rest;
        for (std::size_t i = 0; i < ties.size(); ++i)
          if (std::none_of(own_pairs.begin(), own_pairs.end(), [&](const BondedTie& b) { return b.line == int(i); }))
            rest.push_back(ties[i]);
        L.bonded[o.slot].nodes = bonded_nodes(L.grid, rest, B.spec.geometry());
        for (BondedTie& b : own_pairs) {
          b.nodes = bonded_nodes(L.grid, std::vector<Polyline>{ties[std::size_t(b.line)]},
                                B.spec.geometry());
          L.bonded.push_back(b);
        }
        changed = true;
      }
    }
    std::sort(meet.begin(), meet.end());
    std::vector<double> cuts{0.0};
    for (const double m : meet)
      if (m - cuts.back() > tol) cuts.push_back(m);
    const double length = line.length();
    if (length - cuts.back() <= tol) cuts.pop_back();
    // Each stretch's field: the crack's particles half a cell off its middle, inside the body.
    std::vector<FaceField> now;
    for (std::size_t i = 0; i < cuts.size(); ++i) {
      const double to = i + 1 < cuts.size() ? cuts[i + 1] : length;
      double x, y;
      point_at(line, 0.5 * (cuts[i] + to), x, y);
      const LineProjection pr = project(line, x, y);
      const int f = nearest_field(L, fa, fb, x + side * 0.5 * h * pr.nx, y + side * 0.5 * h * pr.ny, 1.5 * h);
      if (f < 0) fail("no particle of the crack's fields lies beside that interface's face there");
      if (now.empty() || now.back().field != f) {
        int body = side > 0 ? B.spec.upper_body : B.spec.lower_body;  // the part of field f
        for (std::size_t b = 0; b < c.bodies.size(); ++b)
          if (c.bodies[b].field == f) body = int(b);
        now.push_back({cuts[i], f, body});
      }
    }
    int& whole = side > 0 ? B.spec.upper_field : B.spec.lower_field;
    const int before = whole;
    std::vector<FaceField> next = now;
    if (next.size() == 1 && next[0].field != whole && !ties.empty()) {
      next[0].from = 0.0;  // the face on the other field, its tied stretch on this one: stretches
    } else if (next.size() == 1) {
      whole = next[0].field, next.clear();
    }
    if (whole == before && next.size() == faces.size() &&
        std::equal(next.begin(), next.end(), faces.begin(),
                   [](const FaceField& p, const FaceField& q) { return p.from == q.from && p.field == q.field; }))
      continue;
    faces = next;
    std::vector<FaceFields>& nodes = side > 0 ? B.node_faces_up : B.node_faces_lo;
    nodes.clear();
    if (!faces.empty()) {
      nodes.resize(B.num_nodes());
      for (std::size_t n = 0; n < B.num_nodes(); ++n) nodes[n] = face_fields_at(B, faces, n);
    }
    changed = true;
  }
  if (changed) measure_windows_again(L);
}

}  // namespace rupture
