// rupture/solver/crack_segment.cpp
#include "solver/crack_segment.hpp"

#include <algorithm>
#include <cmath>

#include "cohesive/interface_growth.hpp"
#include "geometry/shape.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/crack_cut.hpp"

namespace rupture {
namespace {

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

bool add_crack_segment(const Case& c, std::size_t k, State& L, std::size_t slot,
                       const CrackTip& tip, double x, double y, bool flip_particles,
                       const std::vector<State*>& others, std::size_t tie) {
  CohesiveInterface& in = L.interfaces[slot];
  const double h = L.grid.cell_size(), tol = 1e-6 * h;
  const Point a{tip.frame.x, tip.frame.y}, p{x, y};
  const double len = std::hypot(x - a.x, y - a.y);
  const Point d{(x - a.x) / len, (y - a.y) / len};
  const Region body = crack_body(c, k, in.spec);
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
    const std::uint8_t up = std::uint8_t(in.spec.upper_field), lo = std::uint8_t(in.spec.lower_field);
    const auto flip_level = [&](State& S) {
      const Particles& P = S.particles;
      // Which change sides, looked at side by side; then moved in particle order.
      std::vector<std::uint8_t> flips(P.size(), 0);
      const long np = long(P.size());
#pragma omp parallel for schedule(static) if (np > 16384)
      for (long i = 0; i < np; ++i) {
        const std::size_t q = std::size_t(i);
        if (P.field[q] != up && P.field[q] != lo) continue;
        const double px = P.x0[q], py = P.y0[q];
        if (px < wb.min[0] || px > wb.max[0] || py < wb.min[1] || py > wb.max[1]) continue;
        flips[q] = contains(left_before, px, py) != contains(left_after, px, py);
      }
      bool moved = false;
      for (std::size_t q = 0; q < P.size(); ++q)
        if (flips[q]) move_particle_to_field(S, q, P.field[q] == up ? lo : up), moved = true;
      if (moved) measure_windows_again(S);
    };
    flip_level(L);
    for (State* S : others) flip_level(*S);
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
  // One grid: the level's ties follow its interfaces (slot); nested levels: every level has one
  // per interface of the run (k for the case's).
  const std::size_t entry = tie != kCaseTie ? tie : others.empty() ? slot : k;
  L.bonded[entry].nodes = bonded_nodes(L.grid, in.spec);
  for (State* S : others) S->bonded[entry].nodes = bonded_nodes(S->grid, in.spec);
  return edge;
}

}  // namespace rupture
