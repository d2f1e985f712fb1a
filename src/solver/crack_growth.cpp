// rupture/solver/crack_growth.cpp
#include "solver/crack_growth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

#include <fmt/format.h>

#include "cohesive/interface_growth.hpp"
#include "core/errors.hpp"
#include "geometry/shape.hpp"
#include "solver/cohesive_step.hpp"

namespace rupture {
namespace {

constexpr double kDegree = 180.0 / std::numbers::pi;

// The body the crack was drawn in: its shape and cut-outs, without the cuts of lines.
Region crack_body(const Case& c, std::size_t k) {
  const Region& r = c.bodies[std::size_t(c.interfaces[k].upper_body)].region;
  return Region{r.outer, r.minus};
}

// A frame around the body, the line and p with room to spare (as input/ frames a split).
Box cut_frame(const Region& body, const Polyline& line, const Point& p, double h) {
  Box f = bounding_box(body);
  auto take = [&](double x, double y) {
    f.min[0] = std::min(f.min[0], x), f.max[0] = std::max(f.max[0], x);
    f.min[1] = std::min(f.min[1], y), f.max[1] = std::max(f.max[1], y);
  };
  for (std::size_t i = 0; i < line.num_vertices(); ++i) take(line.x[i], line.y[i]);
  take(p.x, p.y);
  const double pad = 3.0 * h + 0.01 * std::max(f.max[0] - f.min[0], f.max[1] - f.min[1]);  // > the tie's lead
  for (int d = 0; d < 2; ++d) f.min[d] -= pad, f.max[d] += pad;
  return f;
}

bool near(const Point& a, double x, double y, double tol) { return std::hypot(a.x - x, a.y - y) <= tol; }

// The nearest point of the body's edge within `within` of p (rays every 15 degrees), if any.
bool nearest_edge(const Region& body, const Point& p, double within, Point& at) {
  constexpr int kRays = 24;
  double best = INFINITY;
  for (int i = 0; i < kRays; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kRays;
    const Point b{p.x + within * std::cos(a), p.y + within * std::sin(a)};
    const std::vector<Stretch> st = inside_stretches(body, p, b);
    if (st.empty() || !near(p, st[0].from.x, st[0].from.y, 1e-9 * within)) continue;  // p not inside
    if (near(b, st[0].to.x, st[0].to.y, 1e-12 * within)) continue;  // the ray stays inside
    const double d = std::hypot(st[0].to.x - p.x, st[0].to.y - p.y);
    if (d < best) best = d, at = st[0].to;
  }
  return best < INFINITY;
}

// The end segment's state: open where its Gauss point nearest the tip is separated (a cut, or a
// cohesive segment that has let go); else whether its point farthest from the tip is past the
// law's peak traction. The point nearest the tip is not asked: its jump is nearly the end
// node's, which the tie ahead holds shut, so it can stay below the peak while the stress ahead
// grows (seen with Xu-Needleman: 0.95 sigma_max while K_I rose to twice K_c; docs/fracture.md).
CrackFront crack_front(const CohesiveInterface& in, LineEnd end) {
  const std::size_t n = in.gp_separated.size(), G = std::size_t(CohesiveInterface::kGauss);
  const std::size_t near_gp = end == LineEnd::start ? 0 : n - 1, far_gp = end == LineEnd::start ? G - 1 : n - G;
  if (in.spec.precracked || in.gp_separated[near_gp]) return CrackFront::open;
  const bool past = std::visit([&](const auto& law) { return law.softening(in.gp_dn[far_gp], in.gp_dt[far_gp]); },
                               in.spec.law);
  return past ? CrackFront::softening : CrackFront::loading;
}

// The weak plane at a tip (GrowthLaw::plane_fracture_energy): the drawn line's direction at
// that end (unit, pointing out of the line), and whether the tip is still on its straight
// extension: none of the tip's segments so far turned (their angles are exactly 0, the plane's
// own steps being laid along this direction).
struct WeakPlane {
  bool on = false;
  double dx = 0.0, dy = 0.0;
};
WeakPlane weak_plane(const InterfaceSpec& drawn, const CrackGrowthRecord& record, LineEnd end) {
  WeakPlane w;
  if (drawn.growth.plane_fracture_energy <= 0.0) return w;
  const double end_column = end == LineEnd::start ? 0.0 : 1.0;
  const std::vector<double>& r = record.rows;
  for (std::size_t i = 0; i + kGrowthColumns <= r.size(); i += kGrowthColumns)
    if (r[i + 2] == end_column && r[i + 5] != 0.0) return w;
  const Polyline line = drawn.geometry();
  const std::size_t n = line.num_vertices();
  const std::size_t a = end == LineEnd::start ? 1 : n - 2, b = end == LineEnd::start ? 0 : n - 1;
  const double lx = line.x[b] - line.x[a], ly = line.y[b] - line.y[a], l = std::hypot(lx, ly);
  w.on = true, w.dx = lx / l, w.dy = ly / l;
  return w;
}

// The end piece's direction at a tip from the chord's (the frame K is read in), radians ccw.
double end_piece_turn(const InterfaceSpec& spec, const CrackTip& tip, double h) {
  for (const CrackTip& e : precrack_tips(spec, 1e-6 * h))
    if (e.end == tip.end) {
      const TipFrame &a = tip.frame, &b = e.frame;
      return std::atan2(a.e1x * b.e1y - a.e1y * b.e1x, a.e1x * b.e1x + a.e1y * b.e1y);
    }
  return 0.0;
}

Point unit(const Point& from, const Point& to) {
  const double l = std::hypot(to.x - from.x, to.y - from.y);
  return {(to.x - from.x) / l, (to.y - from.y) / l};
}

// Which side of the frame a point on its edge lies on (0..3: x min, x max, y min, y max).
int frame_side(const Box& f, const Point& q) {
  const double dx0 = std::fabs(q.x - f.min[0]), dx1 = std::fabs(q.x - f.max[0]);
  const double dy0 = std::fabs(q.y - f.min[1]), dy1 = std::fabs(q.y - f.max[1]);
  const double m = std::min({dx0, dx1, dy0, dy1});
  return m == dx0 ? 0 : m == dx1 ? 1 : m == dy0 ? 2 : 3;
}

// Whether another interface on the level has one of this one's fields (several cracks drawn in
// one body): their ties then keep their directions (tie_cut), or a turned crack's straight
// extension could cross another's tie, and a node both ties reach would join three fields.
bool shares_fields(const State& L, std::size_t slot) {
  const InterfaceSpec& a = L.interfaces[slot].spec;
  for (std::size_t j = 0; j < L.interfaces.size(); ++j) {
    const InterfaceSpec& b = L.interfaces[j].spec;
    if (j != slot && (b.upper_field == a.upper_field || b.upper_field == a.lower_field ||
                      b.lower_field == a.upper_field || b.lower_field == a.lower_field))
      return true;
  }
  return false;
}

// The tie's lead along the crack's end direction, in cells (tie_cut).
constexpr double kTieLead = 2.0;

// The cut beyond a tip at p (a polyline from p to the frame's edge; the tie is its part inside
// the body). It leaves p along the end segment's direction d, so that every grid node a
// particle beside the tip reaches across it sees a straight crack-and-tie there (a node's GIMP
// support reaches at most h|n_x| + h|n_y| <= sqrt(2) h < kTieLead h from the line), then turns
// to the tie direction t. Straight on along d where t is d (one crack in its body: any tie
// joins the same continuum, and the extension is the plain choice) or the lead leaves the body.
// With several cracks in one body t is kept from the drawn line's direction (docs/fracture.md,
// "Several cracks in one body").
std::vector<Point> tie_cut(const Region& body, const Box& frame, const Point& p, const Point& d,
                           const Point& t, double lead, double tol) {
  if (d.x * t.x + d.y * t.y >= 1.0 - 1e-12) return {p, leave_box(frame, p, d)};
  const Point bend{p.x + lead * d.x, p.y + lead * d.y};
  const std::vector<Stretch> st = inside_stretches(body, p, bend);
  if (st.empty() || !near(bend, st[0].to.x, st[0].to.y, tol)) return {p, leave_box(frame, p, d)};
  return {p, bend, leave_box(frame, bend, t)};
}

// The cut beyond the tip at a as the ties lie now: the tie polyline from a, on to the frame's
// edge along its last piece; along e1 (the end piece) where no tie starts at a.
std::vector<Point> current_cut(const InterfaceSpec& spec, const Box& frame, const Point& a, const Point& e1, double tol) {
  for (const Polyline& t : spec.tie_geometries()) {
    const std::size_t n = t.num_vertices();
    if (n < 2) continue;
    const bool front = near(a, t.x.front(), t.y.front(), tol), back = near(a, t.x.back(), t.y.back(), tol);
    if (!front && !back) continue;
    std::vector<Point> v;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = front ? i : n - 1 - i;
      v.push_back({t.x[j], t.y[j]});
    }
    v.front() = a;
    v.back() = leave_box(frame, v[n - 2], unit(v[n - 2], v[n - 1]));
    return v;
  }
  return {a, leave_box(frame, a, e1)};
}

}  // namespace

double CrackGrowthRecord::length() const {
  double l = 0.0;
  for (std::size_t i = 0; i + kGrowthColumns <= rows.size(); i += kGrowthColumns) l += rows[i + 6];
  return l;
}

bool add_crack_segment(const Case& c, std::size_t k, State& L, std::size_t slot,
                       const CrackTip& tip, double x, double y, bool flip_particles) {
  CohesiveInterface& in = L.interfaces[slot];
  const double h = L.grid.cell_size(), tol = 1e-6 * h;
  const Point a{tip.frame.x, tip.frame.y}, p{x, y};
  const double len = std::hypot(x - a.x, y - a.y);
  const Point d{(x - a.x) / len, (y - a.y) / len};
  const Region body = crack_body(c, k);
  const Box frame = cut_frame(body, in.spec.geometry(), p, h);
  // The cut beyond the tip before the segment, and after it (see tie_cut).
  const std::vector<Point> old_cut = current_cut(in.spec, frame, a, Point{tip.frame.e1x, tip.frame.e1y}, tol);
  const std::size_t o = old_cut.size();
  const Point t_old = unit(old_cut[o - 2], old_cut[o - 1]);
  const Point beyond{p.x + 1e-3 * h * d.x, p.y + 1e-3 * h * d.y};
  const std::vector<Stretch> ahead = inside_stretches(body, a, beyond);
  const bool on_edge = ahead.empty() || !near(beyond, ahead[0].to.x, ahead[0].to.y, 1e-6 * h);
  const Point t_new = shares_fields(L, slot) && !on_edge && t_old.x * d.x + t_old.y * d.y > 0.0 ? t_old : d;
  const std::vector<Point> new_cut = tie_cut(body, frame, p, d, t_new, kTieLead * h, tol);
  // The particles of the two parts between the old cut and the new one change sides: each part
  // is again the material on its side of the crack and its tie. Both cuts run back from the tip
  // along the end piece (the same ray: only the region between their forward parts differs).
  if (flip_particles) {
    const Point back = leave_box(frame, a, Point{-tip.frame.e1x, -tip.frame.e1y});
    std::vector<Point> before{back}, after{back, a};
    before.insert(before.end(), old_cut.begin(), old_cut.end());
    after.insert(after.end(), new_cut.begin(), new_cut.end());
    const Shape left_before = left_part(frame, before), left_after = left_part(frame, after);
    // Where the two can differ: around both forward parts, and the whole frame when they leave
    // it on different sides (the region between them then holds a corner of it).
    Box wb{{a.x, a.y}, {a.x, a.y}};
    for (const auto* cut : {&old_cut, &new_cut})
      for (const Point& q : *cut)
        wb.min[0] = std::min(wb.min[0], q.x), wb.max[0] = std::max(wb.max[0], q.x),
        wb.min[1] = std::min(wb.min[1], q.y), wb.max[1] = std::max(wb.max[1], q.y);
    if (frame_side(frame, old_cut.back()) != frame_side(frame, new_cut.back())) wb = frame;
    Particles& P = L.particles;
    ScatterPlan& plan = L.plan;
    const std::uint8_t up = std::uint8_t(in.spec.upper_field), lo = std::uint8_t(in.spec.lower_field);
    const std::size_t fields = std::size_t(L.fields.num_fields);
    const int cy = L.grid.y.cells;
    for (std::size_t q = 0; q < P.size(); ++q) {
      if (P.field[q] != up && P.field[q] != lo) continue;
      const double px = P.x0[q], py = P.y0[q];
      if (px < wb.min[0] || px > wb.max[0] || py < wb.min[1] || py > wb.max[1]) continue;
      if (contains(left_before, px, py) == contains(left_after, px, py)) continue;
      P.field[q] = P.field[q] == up ? lo : up;
      // The strips' node rows per field (ScatterPlan::row_lo, row_hi, from the last sort) take
      // the particle's row now in its new field: the drift since the sort widens them from
      // there on, as it does for the rows the sort found, so the tile keeps its stencil.
      if (!plan.rows_known) continue;
      const auto at = std::upper_bound(plan.strip_begin.begin(), plan.strip_begin.end(), q);
      const std::size_t strip = std::size_t(at - plan.strip_begin.begin()) - 1;
      const int row = std::clamp(stencil_first(L.grid.y, P.y[q], P.half_y[q]), 0, cy - 1);
      const std::size_t e = strip * fields + P.field[q];
      plan.row_lo[e] = std::min(plan.row_lo[e], row);
      plan.row_hi[e] = std::max(plan.row_hi[e], row);
    }
    L.window_drift = INFINITY;  // the windows: measure the particles again
  }
  // The segment, its new node displaced as the tip node.
  const std::size_t tip_node = tip.end == LineEnd::start ? 0 : in.num_nodes() - 1;
  const double ux = 0.5 * (in.ux_up[tip_node] + in.ux_lo[tip_node]);
  const double uy = 0.5 * (in.uy_up[tip_node] + in.uy_lo[tip_node]);
  extend_interface(in, tip.end, x, y, ux, uy);
  // The tie beyond the tip: the new cut's stretches inside the body, the first (from the new
  // tip, through the bend) one polyline, so no node at the bend counts as beyond its ends.
  std::vector<Polyline> ties;
  for (const Polyline& t : in.spec.tie_geometries()) {
    const bool at_tip = t.num_vertices() >= 2 && (near(a, t.x.front(), t.y.front(), tol) ||
                                                  near(a, t.x.back(), t.y.back(), tol));
    if (!at_tip) ties.push_back(t);
  }
  bool edge = true;
  for (std::size_t i = 0; i + 1 < new_cut.size(); ++i)
    for (const Stretch& st : inside_stretches(body, new_cut[i], new_cut[i + 1])) {
      if (std::hypot(st.to.x - st.from.x, st.to.y - st.from.y) <= tol) continue;
      const bool joins = i > 0 && !ties.empty() && near(st.from, ties.back().x.back(), ties.back().y.back(), tol) &&
                         near(st.from, new_cut[i].x, new_cut[i].y, tol);
      if (joins) {
        ties.back().x.push_back(st.to.x), ties.back().y.push_back(st.to.y);
        continue;
      }
      Polyline t;
      t.x = {st.from.x, st.to.x};
      t.y = {st.from.y, st.to.y};
      ties.push_back(t);
      if (i == 0 && near(p, st.from.x, st.from.y, tol)) edge = false;
    }
  in.spec.bonded_lines = ties;
  in.spec.bonded = !ties.empty();
  L.bonded[slot].nodes = bonded_nodes(L.grid, in.spec);
  return edge;
}

void grow_cracks(const Case& c, RunState& s, std::vector<CrackGrowthRecord>& records) {
  records.resize(c.interfaces.size());
  for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
    const InterfaceSpec& is = c.interfaces[k];
    if (!is.growth.on()) continue;
    State& L = s.levels[std::size_t(s.interface_levels[k])];
    const std::size_t slot = s.interface_slots[k];
    const double h = L.grid.cell_size();
    const TipMaterial mat = tip_material(c, k);
    const std::vector<InitialStrain> initial = initial_field_strains(c);
    // Read every tip first, then grow: one tip's segment does not change another's reading.
    // The frame K is read in and the kink turns from: the crack as the outer J domain sees it
    // (the chord over its radius; a kink shorter than that is not yet the crack's direction).
    const std::vector<CrackTip> tips = precrack_tips(L.interfaces[slot].spec, 1e-6 * h, is.j_domains.back() * h);
    struct Grow {
      CrackTip tip;
      double x, y, angle, K_I, K_II;
      std::size_t index;
    };
    std::vector<Grow> grow;
    // The cohesive criterion cannot grow a tip whose end segment is still loading, whatever K:
    // such a tip is not read (the J domains are most of what growth costs a step).
    std::vector<CrackFront> fronts(tips.size());
    std::vector<char> read(tips.size());
    for (std::size_t t = 0; t < tips.size(); ++t) {
      fronts[t] = crack_front(L.interfaces[slot], tips[t].end);
      read[t] = is.growth.criterion != GrowthCriterion::cohesive || fronts[t] != CrackFront::loading;
    }
    // The tips are read side by side (each read only looks at the level).
    std::vector<std::vector<TipIntegrals>> readings(tips.size());
#pragma omp parallel for schedule(static, 1)
    for (std::size_t t = 0; t < tips.size(); ++t)
      if (read[t]) readings[t] = read_tip(L, L.interfaces[slot].spec, tips[t].frame, mat, s.time, initial);
    for (std::size_t t = 0; t < tips.size(); ++t) {
      if (!read[t]) continue;
      const std::vector<TipIntegrals>& r = readings[t];
      double KI = 0.0, KII = 0.0;
      for (const TipIntegrals& d : r) KI += d.K_I / double(r.size()), KII += d.K_II / double(r.size());
      const WeakPlane plane = weak_plane(is, records[k], tips[t].end);
      // The end piece's turn is read only by the weak plane's criterion (off the plane).
      const double kink = is.growth.plane_fracture_energy > 0.0 && !plane.on
                              ? end_piece_turn(L.interfaces[slot].spec, tips[t], h) : 0.0;
      const GrowthDecision g = decide_growth(is.growth, KI, KII, mat.e_prime, fronts[t], plane.on, kink);
      if (!g.grow) continue;
      const TipFrame& f = tips[t].frame;
      const double cs = std::cos(g.angle), sn = std::sin(g.angle);
      double dx = cs * f.e1x - sn * f.e1y, dy = sn * f.e1x + cs * f.e1y;
      if (plane.on && g.angle == 0.0) dx = plane.dx, dy = plane.dy;  // along the plane, exactly
      const double step = is.growth.step * h;
      double x = f.x + step * dx, y = f.y + step * dy;
      // A segment that would leave the body ends on its edge.
      const std::vector<Stretch> in_body = inside_stretches(crack_body(c, k), {f.x, f.y}, {x, y});
      if (in_body.empty() || std::hypot(in_body[0].from.x - f.x, in_body[0].from.y - f.y) > 1e-6 * h)
        continue;  // the tip is on the edge already
      x = in_body[0].to.x, y = in_body[0].to.y;
      if (std::hypot(x - f.x, y - f.y) <= 1e-6 * h) continue;
      grow.push_back({tips[t], x, y, g.angle, KI, KII, t});
    }
    // The end first: a new segment at the start shifts nothing the end's tip needs, and the
    // other way round, but each reads the line as it is now.
    for (const Grow& g : grow) {
      const std::vector<CrackTip> now = precrack_tips(L.interfaces[slot].spec, 1e-6 * h);
      const auto it = std::find_if(now.begin(), now.end(), [&](const CrackTip& t) { return t.end == g.tip.end; });
      if (it == now.end()) continue;
      const bool through = add_crack_segment(c, k, L, slot, *it, g.x, g.y, true);
      const double end_column = g.tip.end == LineEnd::start ? 0.0 : 1.0;
      const double len = std::hypot(g.x - g.tip.frame.x, g.y - g.tip.frame.y);
      records[k].rows.insert(records[k].rows.end(),
                             {s.time, double(g.index), end_column, g.x, g.y, g.angle * kDegree, len, g.K_I, g.K_II});
      // A free surface less than a cell away: the ligament left holds fewer than two particles
      // across and cannot carry a field of its own on the grid (nor can a J domain cut by the
      // edge read the tip), so the crack cuts through to the nearest point of the edge, in
      // segments of at most the growth step (a junction: the tie there is gone).
      Point edge;
      if (through || !nearest_edge(crack_body(c, k), {g.x, g.y}, h, edge)) continue;
      for (int piece = 0; piece < 4; ++piece) {
        const std::vector<CrackTip> tip = precrack_tips(L.interfaces[slot].spec, 1e-6 * h);
        const auto at = std::find_if(tip.begin(), tip.end(), [&](const CrackTip& t) { return t.end == g.tip.end; });
        if (at == tip.end()) break;
        const TipFrame& f = at->frame;
        const double dx = edge.x - f.x, dy = edge.y - f.y, left = std::hypot(dx, dy);
        if (left <= 1e-6 * h) break;
        const double l = std::min(left, is.growth.step * h);
        const double x = l == left ? edge.x : f.x + dx * l / left, y = l == left ? edge.y : f.y + dy * l / left;
        const double turn = std::atan2(f.e1x * dy - f.e1y * dx, f.e1x * dx + f.e1y * dy);
        const bool done = add_crack_segment(c, k, L, slot, *at, x, y, true);
        records[k].rows.insert(records[k].rows.end(),
                               {s.time, double(g.index), end_column, x, y, turn * kDegree, l, g.K_I, g.K_II});
        if (done || l == left) break;
      }
    }
  }
}

void regrow_cracks(const Case& c, RunState& s, const std::vector<CrackGrowthRecord>& records) {
  for (std::size_t k = 0; k < records.size() && k < c.interfaces.size(); ++k) {
    State& L = s.levels[std::size_t(s.interface_levels[k])];
    const std::size_t slot = s.interface_slots[k];
    const double h = L.grid.cell_size();
    const std::vector<double>& r = records[k].rows;
    for (std::size_t i = 0; i + kGrowthColumns <= r.size(); i += kGrowthColumns) {
      const LineEnd end = r[i + 2] == 0.0 ? LineEnd::start : LineEnd::end;
      const std::vector<CrackTip> now = precrack_tips(L.interfaces[slot].spec, 1e-6 * h);
      const auto it = std::find_if(now.begin(), now.end(), [&](const CrackTip& t) { return t.end == end; });
      if (it == now.end())
        throw InputError(fmt::format("checkpoint: run.growth[{}] row {}: the crack has no tip at its {} to grow "
                                     "from (the checkpoint is not of this case)",
                                     k, i / kGrowthColumns, end == LineEnd::start ? "start" : "end"));
      add_crack_segment(c, k, L, slot, *it, r[i + 3], r[i + 4], false);
    }
  }
}

}  // namespace rupture
