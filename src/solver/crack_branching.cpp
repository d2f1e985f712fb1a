// rupture/solver/crack_branching.cpp
#include "solver/crack_branching.hpp"

#include <algorithm>
#include <cmath>

#include "cohesive/interface.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/crack_cut.hpp"

namespace rupture {
namespace {

// The tie beyond a new branch's first vertex p: the stretches of the straight cut along d
// inside the body (none where p is on its edge).
std::vector<Polyline> straight_tie(const Region& body, const Box& frame, const Point& p, const Point& d, double tol) {
  std::vector<Polyline> ties;
  for (const Stretch& st : inside_stretches(body, p, leave_box(frame, p, d))) {
    if (std::hypot(st.to.x - st.from.x, st.to.y - st.from.y) <= tol) continue;
    Polyline t;
    t.x = {st.from.x, st.to.x};
    t.y = {st.from.y, st.to.y};
    ties.push_back(t);
  }
  return ties;
}

}  // namespace

WaveSpeeds crack_wave_speeds(const Case& c, std::size_t k) {
  return wave_speeds(c.materials[std::size_t(c.bodies[std::size_t(c.interfaces[k].upper_body)].material)], c.plane);
}

std::array<std::size_t, 2> split_crack_tip(const Case& c, std::size_t k, State& L, std::size_t slot,
                                           const CrackTip& tip, double left_x, double left_y, double right_x,
                                           double right_y, int wedge_field, bool flip_particles,
                                           const std::vector<State*>& others, BranchTies entries) {
  const double h = L.grid.cell_size(), tol = 1e-6 * h;
  const Point a{tip.frame.x, tip.frame.y}, pl{left_x, left_y}, pr{right_x, right_y};
  const Point dl = unit(a, pl), dr = unit(a, pr);
  const Region body = crack_body(c, k, L.interfaces[slot].spec);
  InterfaceSpec parent = L.interfaces[slot].spec;
  const Box frame = cut_frame(body, parent.geometry(), a, h);
  // Left of the crack's direction at the tip: the upper field at the line's end (the normal is
  // the left one of the line's direction, start to end), the lower at its start.
  const int left = tip.end == LineEnd::end ? parent.upper_field : parent.lower_field;
  const int right = tip.end == LineEnd::end ? parent.lower_field : parent.upper_field;
  // The tie beyond the tip goes: the tip is a junction.
  std::vector<Polyline> ties;
  for (const Polyline& t : parent.tie_geometries()) {
    const bool at_tip = t.num_vertices() >= 2 && (near(a, t.x.front(), t.y.front(), tol) ||
                                                  near(a, t.x.back(), t.y.back(), tol));
    if (!at_tip) ties.push_back(t);
  }
  std::vector<State*> levels{&L};
  levels.insert(levels.end(), others.begin(), others.end());
  const std::size_t parent_tie = entries.parent != std::size_t(-1) ? entries.parent : slot;
  {
    CohesiveInterface& in = L.interfaces[slot];
    in.spec.bonded_lines = ties;
    in.spec.bonded = !ties.empty();
    for (State* S : levels) S->bonded[parent_tie].nodes = bonded_nodes(S->grid, in.spec);
  }
  // The wedge: left of the walk in along the left cut and out along the right one (on every
  // level: each holds its own particles).
  if (flip_particles) {
    const Shape wedge = left_part(frame, {leave_box(frame, a, dl), a, leave_box(frame, a, dr)});
    for (State* S : levels) {
      const Particles& P = S->particles;
      for (std::size_t q = 0; q < P.size(); ++q) {
        if (P.field[q] != left && P.field[q] != right) continue;
        if (contains(wedge, P.x0[q], P.y0[q])) move_particle_to_field(*S, q, std::uint8_t(wedge_field));
      }
      measure_windows_again(*S);
    }
  }
  // The two branches, their nodes displaced as the tip node.
  const CohesiveInterface& from = L.interfaces[slot];
  const std::size_t tip_node = tip.end == LineEnd::start ? 0 : from.num_nodes() - 1;
  const double ux = 0.5 * (from.ux_up[tip_node] + from.ux_lo[tip_node]);
  const double uy = 0.5 * (from.uy_up[tip_node] + from.uy_lo[tip_node]);
  const double light = from.light_face_mass, time = from.time;
  InterfaceSpec base = parent;
  base.branch_fields.clear();
  base.drawn_open = false;  // a cohesive branch's segments carry the law, intact
  base.segments = 1;
  std::array<std::size_t, 2> slots{};
  const struct {
    Point p, d;
    int upper, lower;
  } branch[2] = {{pl, dl, left, wedge_field}, {pr, dr, wedge_field, right}};
  for (int b = 0; b < 2; ++b) {
    InterfaceSpec sp = base;
    sp.line = Polyline{};
    sp.line.x = {a.x, branch[b].p.x};
    sp.line.y = {a.y, branch[b].p.y};
    sp.upper_field = branch[b].upper;
    sp.lower_field = branch[b].lower;
    sp.bonded_lines = straight_tie(body, frame, branch[b].p, branch[b].d, tol);
    sp.bonded = !sp.bonded_lines.empty();
    CohesiveInterface ci = make_interface(sp);
    std::fill(ci.ux_up.begin(), ci.ux_up.end(), ux), std::fill(ci.ux_lo.begin(), ci.ux_lo.end(), ux);
    std::fill(ci.uy_up.begin(), ci.uy_up.end(), uy), std::fill(ci.uy_lo.begin(), ci.uy_lo.end(), uy);
    ci.light_face_mass = light;
    ci.time = time;
    evaluate_interface(ci, time, time);
    // At the new interface's index: stretches with ties of their own come after the interfaces
    // (nested levels: after the run's interfaces, on every level).
    const std::size_t at = entries.first_new != std::size_t(-1) ? entries.first_new + std::size_t(b) : L.interfaces.size();
    for (State* S : levels)
      S->bonded.insert(S->bonded.begin() + long(at), BondedTie{sp.upper_field, sp.lower_field, bonded_nodes(S->grid, sp)});
    L.interfaces.push_back(std::move(ci));
    slots[std::size_t(b)] = L.interfaces.size() - 1;
  }
  return slots;
}

}  // namespace rupture
