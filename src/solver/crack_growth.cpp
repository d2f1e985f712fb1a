// rupture/solver/crack_growth.cpp
#include "solver/crack_growth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "cohesive/interface_growth.hpp"
#include "core/errors.hpp"
#include "geometry/shape.hpp"
#include "solver/crack_branching.hpp"
#include "solver/crack_cut.hpp"
#include "solver/crack_junction.hpp"
#include "solver/crack_nucleation.hpp"

namespace rupture {
namespace {

constexpr double kDegree = 180.0 / std::numbers::pi;

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
  for (const GrowthRow& r : record.rows)
    if (!r.split && r.end == end && r.angle != 0.0) return w;
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

}  // namespace

namespace {

// The crack's lines on its level: its own (branch -1; its tips labelled by their index among
// its tips) and its branches' (branch b; the tip labelled 2 + b).
struct CrackLine {
  std::size_t slot;
  int branch;
};
std::vector<CrackLine> crack_lines(const RunState& s, std::size_t k, const CrackGrowthRecord& record) {
  std::vector<CrackLine> lines{{s.interface_slots[k], -1}};
  for (std::size_t b = 0; b < record.branch_slots.size(); ++b) lines.push_back({record.branch_slots[b], int(b)});
  return lines;
}

// Where a line's tie is in every level's State::bonded: one grid, its slot; nested levels, its
// index among the run's interfaces (the case's, then the branches', RunState::interface_levels),
// the same on every level.
std::size_t tie_entry(const RunState& s, int level, std::size_t slot) {
  if (!s.is_nested()) return slot;
  for (std::size_t g = 0; g < s.num_interfaces(); ++g)
    if (s.interface_levels[g] == level && s.interface_slots[g] == slot) return g;
  throw std::logic_error("crack growth: a line on no level of the run");
}

// The run's levels other than `level` (nested levels; none on one grid).
std::vector<State*> other_levels(RunState& s, int level) {
  std::vector<State*> others;
  if (s.is_nested())
    for (std::size_t l = 0; l < s.levels.size(); ++l)
      if (int(l) != level) others.push_back(&s.levels[l]);
  return others;
}

// The split's ties (solver/crack_branching.hpp BranchTies): nested levels, the parent's entry
// and the run's interface count; one grid, the defaults.
BranchTies branch_ties(const RunState& s, int level, std::size_t slot) {
  if (!s.is_nested()) return {};
  return {tie_entry(s, level, slot), s.num_interfaces()};
}

// Splits the tip g grows at into two branches at +-g.split from its growth direction (each a
// growth step long, ending on the body's edge at most), and records the split and the two
// first segments. False (nothing done) where a branch would leave the body at once.
template <class Grow, class Check>
bool split_tip(const Case& c, std::size_t k, RunState& s, int level, std::size_t slot, const CrackTip& tip,
               const Grow& g, CrackGrowthRecord& record, const Check& check_junction) {
  const double h = s.levels[std::size_t(level)].grid.cell_size(), step = c.interfaces[k].growth.step * h;
  const Region body = crack_body(c, k, s.levels[std::size_t(level)].interfaces[slot].spec);
  const TipFrame& f = tip.frame;
  const double axis = g.angle;
  Point end[2];
  for (int b = 0; b < 2; ++b) {
    const double t = axis + (b == 0 ? g.split : -g.split), cs = std::cos(t), sn = std::sin(t);
    const Point to{f.x + step * (cs * f.e1x - sn * f.e1y), f.y + step * (sn * f.e1x + cs * f.e1y)};
    const std::vector<Stretch> in_body = inside_stretches(body, {f.x, f.y}, to);
    if (in_body.empty() || std::hypot(in_body[0].from.x - f.x, in_body[0].from.y - f.y) > 1e-6 * h) return false;
    end[b] = in_body[0].to;
    if (std::hypot(end[b].x - f.x, end[b].y - f.y) <= 1e-6 * h) return false;
  }
  for (int b = 0; b < 2; ++b) check_junction(Point{f.x, f.y}, end[b]);
  const std::size_t n = record.branch_slots.size();
  const std::array<std::size_t, 2> slots =
      split_crack_tip(c, k, s.levels[std::size_t(level)], slot, tip, end[0].x, end[0].y, end[1].x, end[1].y,
                      c.interfaces[k].branch_fields[n / 2], true, other_levels(s, level), branch_ties(s, level, slot));
  for (const std::size_t b : slots) s.interface_levels.push_back(level), s.interface_slots.push_back(b);
  record.rows.push_back({s.time, g.label, tip.end, true, f.x, f.y, g.split * kDegree, 0.0, g.K_I, g.K_II});
  for (int b = 0; b < 2; ++b) {
    record.branch_slots.push_back(slots[std::size_t(b)]);
    const double len = std::hypot(end[b].x - f.x, end[b].y - f.y);
    const double turn = (axis + (b == 0 ? g.split : -g.split)) * kDegree;
    record.rows.push_back({s.time, int(2 + n + std::size_t(b)), LineEnd::end, false, end[b].x, end[b].y, turn, len,
                           g.K_I, g.K_II});
  }
  return true;
}

// The parts other lines have cut off crack k's body since the run began, on each of its lines
// (solver/crack_junction.hpp cut_off_parts): before its growth step, and before each row a
// restore lays again.
void follow_cut_off_parts(const Case& c, RunState& s, std::size_t k, const std::vector<CrackLine>& lines) {
  std::vector<std::size_t> own;
  for (const CrackLine& l : lines) own.push_back(l.slot);
  std::vector<std::vector<Side>> cut = cut_off_parts(c, s, k, own);
  State& L = s.levels[std::size_t(s.interface_levels[k])];
  for (const std::size_t slot : own) L.interfaces[slot].spec.reach_cut_off = cut;
}

// On nested levels a tip is read from its level's particles and lattice alone, so every particle
// its J domains map (within `reach` of the tip, m) must be on that level: the disk must lie inside
// the level's rectangle (its sides on the domain's edge are open) and off the next finer level's
// (whose particles are that level's). Else the run stops here, with the place and time: the
// reading would be wrong, not merely coarse.
void check_tip_on_level(const Case& c, std::size_t k, const RunState& s, int level, const TipFrame& f,
                        double reach) {
  if (!s.is_nested()) return;
  const LevelLattice& lv = s.grid.levels[std::size_t(level)];
  const double p[2] = {f.x, f.y};
  if (std::size_t(level) + 1 < s.grid.levels.size()) {
    const LevelLattice& fine = s.grid.levels[std::size_t(level) + 1];
    double lo[2], hi[2], gap2 = 0.0;
    for (int d = 0; d < 2; ++d) {
      lo[d] = s.grid.min[d] + double(fine.lo[d]) * s.grid.finest;
      hi[d] = s.grid.min[d] + double(fine.hi[d]) * s.grid.finest;
      const double out = std::max({lo[d] - p[d], 0.0, p[d] - hi[d]});
      gap2 += out * out;
    }
    if (gap2 < reach * reach)
      throw SimulationError(fmt::format(
          "crack growth: interface '{}' has its tip at ({:.6g}, {:.6g}) m at t = {:.6g} s, within {:.3g} m "
          "(its J domains and the particles they map) of nested level {}'s box [{:.6g}, {:.6g}] x [{:.6g}, "
          "{:.6g}] m, whose particles its level {} does not hold: a tip is read on the level that holds its "
          "crack; keep finer [grid.refine] boxes that far from the crack's path, or put the crack in one",
          c.interface_names[k], f.x, f.y, s.time, reach, level + 1, lo[0], hi[0], lo[1], hi[1], level));
  }
  for (int d = 0; d < 2; ++d) {
    const double lo = s.grid.min[d] + double(lv.lo[d]) * s.grid.finest;
    const double hi = s.grid.min[d] + double(lv.hi[d]) * s.grid.finest;
    if ((lv.outer_lo[d] || p[d] - reach >= lo) && (lv.outer_hi[d] || p[d] + reach <= hi)) continue;
    throw SimulationError(fmt::format(
        "crack growth: interface '{}' has its tip at ({:.6g}, {:.6g}) m at t = {:.6g} s, within {:.3g} m "
        "(its J domains and the particles they map) of the border of nested level {} ({} from {:.6g} to "
        "{:.6g} m): a tip is read on the level that holds its crack; widen that level's [grid.refine] box "
        "to hold the crack's path",
        c.interface_names[k], f.x, f.y, s.time, reach, level, d == 0 ? "x" : "y", lo, hi));
  }
}

// The smallest outer J domain radius a branch near its sibling is read with, in cells: the
// smallest of the default domains (4, 6, 8 cells), with which every reading is made.
constexpr double kSmallestDomain = 4.0;

}  // namespace

double growing_tip_speed(const Case& c, std::size_t k, const CrackGrowthRecord& record, int label, LineEnd end,
                         double now, double window) {
  const GrowthLaw& g = c.interfaces[k].growth;
  if (g.criterion == GrowthCriterion::prescribed) return now > g.start ? g.speed : 0.0;
  return tip_speed(record, label, end, now, window);
}

TipMaterial growing_tip_material(const Case& c, std::size_t k, const CrackGrowthRecord& record,
                                 int label, LineEnd end, double now, double window) {
  TipMaterial m = tip_material(c, k);
  if (!c.interfaces[k].running_tip) return m;
  const WaveSpeeds w = crack_wave_speeds(c, k);
  // The running field holds below c_R, where D -> 0: K = M mu c_s^2 D / (v^2 a) -> 0 and
  // A -> infinity. A measured speed at or above it (a discrete tip that cuts through to an edge
  // several segments in one step) is read at kRunningTipCap c_R.
  m.speed = std::min(growing_tip_speed(c, k, record, label, end, now, window), kRunningTipCap * w.rayleigh);
  m.c_d = w.dilatational, m.c_s = w.shear;
  return m;
}

void grow_cracks(const Case& c, RunState& s, std::vector<CrackGrowthRecord>& records,
                 const std::function<void()>& before_growth) {
  records.resize(c.interfaces.size());
  bool grown = false;
  for (std::size_t k = 0; k < c.interfaces.size(); ++k) {
    const InterfaceSpec& is = c.interfaces[k];
    if (!is.growth.on()) continue;
    const int level = s.interface_levels[k];
    State& L = s.levels[std::size_t(level)];
    const double h = L.grid.cell_size();
    // A line not yet loose is intact material: it comes loose once the stress across it reaches
    // the strength (solver/crack_nucleation.hpp), and grows from the next step on.
    if (is.nucleation_strength > 0.0 && !records[k].nucleated()) {
      if (site_stress(L, L.interfaces[s.interface_slots[k]], h) < is.nucleation_strength) continue;
      if (!grown) {
        grown = true;
        if (before_growth) before_growth();
      }
      release_site(c, k, L, s.interface_slots[k], other_levels(s, level));
      records[k].nucleation_time = s.time;
      continue;
    }
    const TipMaterial mat = tip_material(c, k);
    const std::vector<InitialStrain> initial = initial_field_strains(c);
    const std::vector<CrackLine> lines = crack_lines(s, k, records[k]);
    follow_cut_off_parts(c, s, k, lines);
    // Read every tip first, then grow: one tip's segment does not change another's reading.
    // The frame K is read in and the kink turns from: the crack as the outer J domain sees it
    // (the chord over its radius; a kink shorter than that is not yet the crack's direction).
    struct Tip {
      std::size_t line;
      CrackTip tip;
      int label;
      CrackFront front;
      bool read;
      double domains = 1.0;  // the J domains' scale (a branch near its sibling; 0: too near to read K_II)
      TipMaterial mat{};     // with the tip's speed when it is read as running (running_tip)
    };
    std::vector<Tip> tips;
    const double r_out = is.j_domains.back() * h;
    for (std::size_t l = 0; l < lines.size(); ++l) {
      const CohesiveInterface& in = L.interfaces[lines[l].slot];
      const std::vector<CrackTip> t = precrack_tips(in.spec, 1e-6 * h, r_out);
      for (std::size_t i = 0; i < t.size(); ++i) {
        // The cohesive criterion cannot grow a tip whose end segment is still loading, whatever
        // K: such a tip is not read (the J domains are most of what growth costs a step).
        const CrackFront front = crack_front(in, t[i].end);
        Tip tip{l, t[i], lines[l].branch < 0 ? int(i) : 2 + lines[l].branch, front,
                is.growth.criterion != GrowthCriterion::cohesive || front != CrackFront::loading};
        tip.mat = growing_tip_material(c, k, records[k], tip.label, t[i].end, s.time, r_out);
        // A branch whose sibling's line passes inside its outer J domain: the domain integrals
        // assume one crack in the domain, so its domains shrink to keep the sibling out, down to
        // an outer radius of kSmallestDomain cells; nearer than that it is not steered (below).
        if (lines[l].branch >= 0) {
          const std::size_t sibling = records[k].branch_slots[std::size_t(lines[l].branch ^ 1)];
          const double d = distance_to_line(L.interfaces[sibling].spec.geometry(), {t[i].frame.x, t[i].frame.y});
          if (d < r_out) tip.domains = d >= kSmallestDomain * h ? d / r_out : 0.0;
        }
        tips.push_back(tip);
      }
    }
    // The particles a read maps (tip_domain_points: the outer domain and three cells).
    for (const Tip& t : tips)
      if (t.read) check_tip_on_level(c, k, s, level, t.tip.frame, r_out + 3.0 * h);
    const std::vector<State*> others = other_levels(s, level);
    // Several tips are read side by side (each read only looks at the level). One tip is read
    // outside any parallel region: its read's own loops over its points are then parallel (a
    // region nested in a one-thread region costs libgomp a new team every time: ten times the
    // read on the Kalthoff-Winkler case).
    std::vector<std::vector<TipIntegrals>> readings(tips.size());
    const auto read = [&](std::size_t t) {
      if (!tips[t].read) return;
      const CohesiveInterface& line = L.interfaces[lines[tips[t].line].slot];
      const InterfaceSpec& spec = line.spec;
      if (tips[t].domains == 1.0) {
        readings[t] = read_tip(L, line, spec, tips[t].tip.frame, tips[t].mat, s.time, initial);
        return;
      }
      InterfaceSpec near_sibling = spec;
      for (double& r : near_sibling.j_domains) r *= std::max(tips[t].domains, kSmallestDomain * h / r_out);
      readings[t] = read_tip(L, line, near_sibling, tips[t].tip.frame, tips[t].mat, s.time, initial);
    };
    // Distributed: one tip after another (each read sums over the ranks; MPI calls stay outside
    // OpenMP regions).
    if (tips.size() == 1 || L.halo) {
      for (std::size_t t = 0; t < tips.size(); ++t) read(t);
    } else {
#pragma omp parallel for schedule(static, 1)
      for (std::size_t t = 0; t < tips.size(); ++t) read(t);
    }
    struct Grow {
      std::size_t line;
      CrackTip tip;
      double x, y, angle, K_I, K_II;
      int label;
      double split = 0.0;  // > 0: the tip splits, its branches at +-split from the direction above
    };
    std::vector<Grow> grow;
    const Region body = crack_body(c, k, L.interfaces[s.interface_slots[k]].spec);
    std::size_t splits = std::size_t(records[k].branches());
    for (std::size_t t = 0; t < tips.size(); ++t) {
      if (!tips[t].read) continue;
      const std::vector<TipIntegrals>& r = readings[t];
      const InterfaceSpec& spec = L.interfaces[lines[tips[t].line].slot].spec;
      double KI = 0.0, KII = 0.0;
      for (const TipIntegrals& d : r) KI += d.K_I / double(r.size()), KII += d.K_II / double(r.size());
      const WeakPlane plane = tips[t].label < 2 ? weak_plane(is, records[k], tips[t].tip.end) : WeakPlane{};
      // The end piece's turn is read only by the weak plane's criterion (off the plane).
      const double kink = is.growth.plane_fracture_energy > 0.0 && !plane.on
                              ? end_piece_turn(spec, tips[t].tip, h) : 0.0;
      const TipMaterial& tm = tips[t].mat;
      const RunningTipFactors running =
          tm.speed > 0.0 ? running_tip_factors(tm.speed, WaveSpeeds{tm.c_d, tm.c_s, 0.0, 0.0}) : RunningTipFactors{};
      GrowthDecision g =
          is.growth.criterion == GrowthCriterion::prescribed
              ? decide_prescribed(is.growth, KI, KII, tip_grown(records[k], tips[t].label, tips[t].tip.end),
                                  is.growth.step * h, s.time)
              : decide_growth(is.growth, KI, KII, mat.e_prime, tips[t].front, plane.on, kink, running);
      if (!g.grow) continue;
      // A branch whose sibling's line is nearer than the smallest domain runs straight on: its
      // K_II would be the sibling's faces'.
      if (tips[t].domains == 0.0) g.angle = 0.0;
      const TipFrame& f = tips[t].tip.frame;
      const double cs = std::cos(g.angle), sn = std::sin(g.angle);
      double dx = cs * f.e1x - sn * f.e1y, dy = sn * f.e1x + cs * f.e1y;
      if (plane.on && g.angle == 0.0) dx = plane.dx, dy = plane.dy;  // along the plane, exactly
      const double step = is.growth.step * h;
      double x = f.x + step * dx, y = f.y + step * dy;
      // A segment that would leave the body ends on its edge.
      const std::vector<Stretch> in_body = inside_stretches(body, {f.x, f.y}, {x, y});
      if (in_body.empty() || std::hypot(in_body[0].from.x - f.x, in_body[0].from.y - f.y) > 1e-6 * h)
        continue;  // the tip is on the edge already
      x = in_body[0].to.x, y = in_body[0].to.y;
      if (std::hypot(x - f.x, y - f.y) <= 1e-6 * h) continue;
      Grow gr{tips[t].line, tips[t].tip, x, y, g.angle, KI, KII, tips[t].label};
      // A tip that grows may split instead (Yoffe): at its speed over the outer domain's radius
      // of path, while the crack has fields kept for the wedges.
      if (is.growth.branching == BranchCriterion::yoffe && splits < is.branch_fields.size()) {
        const double v = tip_speed(records[k], tips[t].label, tips[t].tip.end, s.time, is.j_domains.back() * h);
        const BranchDecision b = decide_branching(v, crack_wave_speeds(c, k));
        if (b.branch) gr.split = b.angle, ++splits;
      }
      grow.push_back(gr);
    }
    if (!grow.empty() && !grown) {
      grown = true;
      if (before_growth) before_growth();
    }
    // Every segment laid below is checked first against the other lines drawn in the body, and
    // the ties it leaves after (solver/crack_junction.hpp: a junction stops the run).
    std::vector<std::size_t> own;
    for (const CrackLine& l : lines) own.push_back(l.slot);
    const std::vector<OtherLine> all_lines = grow.empty() ? std::vector<OtherLine>{} : other_lines(c, s, records, k, own);
    const std::vector<OtherLine> others_lines = junction_lines(all_lines);
    const auto check_junction = [&](const Point& from, const Point& to) {
      stop_at_segment_junction(c, k, s.time, others_lines, from, to, h);
    };
    // After each segment: the ties against the lines in the body, and the interfaces on the
    // body's edge the crack or its tie now meets (their faces follow the crack's fields).
    const auto check_ties = [&](std::size_t slot) {
      stop_at_tie_junction(c, k, s.time, others_lines, L.interfaces[slot].spec.tie_geometries(), h);
      std::vector<std::size_t> mine{s.interface_slots[k]};
      for (const std::size_t b : records[k].branch_slots) mine.push_back(b);
      follow_edge_junctions(c, s, k, mine, all_lines, s.time, h);
    };
    // The end first: a new segment at the start shifts nothing the end's tip needs, and the
    // other way round, but each reads the line as it is now.
    for (const Grow& g : grow) {
      const std::size_t slot = lines[g.line].slot;
      const std::vector<CrackTip> now = precrack_tips(L.interfaces[slot].spec, 1e-6 * h);
      const auto it = std::find_if(now.begin(), now.end(), [&](const CrackTip& t) { return t.end == g.tip.end; });
      if (it == now.end()) continue;
      if (g.split > 0.0 && split_tip(c, k, s, level, slot, *it, g, records[k], check_junction)) {
        for (std::size_t b = records[k].branch_slots.size() - 2; b < records[k].branch_slots.size(); ++b)
          check_ties(records[k].branch_slots[b]);
        continue;
      }
      check_junction({it->frame.x, it->frame.y}, {g.x, g.y});
      const bool through = add_crack_segment(c, k, L, slot, *it, g.x, g.y, true, others, tie_entry(s, level, slot));
      const double len = std::hypot(g.x - g.tip.frame.x, g.y - g.tip.frame.y);
      records[k].rows.push_back({s.time, g.label, g.tip.end, false, g.x, g.y, g.angle * kDegree, len, g.K_I, g.K_II});
      check_ties(slot);  // after the row: the path written at the stop holds the segment laid
      // A free surface less than a cell away: the ligament left holds fewer than two particles
      // across and cannot carry a field of its own on the grid (nor can a J domain cut by the
      // edge read the tip), so the crack cuts through to the nearest point of the edge, in
      // segments of at most the growth step (a junction: the tie there is gone).
      Point edge;
      if (through || !nearest_edge(body, {g.x, g.y}, h, edge)) continue;
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
        check_junction({f.x, f.y}, {x, y});
        const bool done = add_crack_segment(c, k, L, slot, *at, x, y, true, others, tie_entry(s, level, slot));
        records[k].rows.push_back({s.time, g.label, g.tip.end, false, x, y, turn * kDegree, l, g.K_I, g.K_II});
        check_ties(slot);
        if (done || l == left) break;
      }
    }
  }
}

void regrow_cracks(const Case& c, RunState& s, std::vector<CrackGrowthRecord>& records) {
  // The rows of every crack in the order the run laid them (by time, and crack by crack within a
  // step, as grow_cracks goes), a site's release at its time: a row's cut then meets the other
  // lines as they were when it was laid (follow_cut_off_parts).
  struct Event {
    double time;
    std::size_t k, row;  // row: the index in records[k].rows; kRelease: the release
  };
  constexpr std::size_t kRelease = std::size_t(-1);
  std::vector<Event> events;
  for (std::size_t k = 0; k < records.size() && k < c.interfaces.size(); ++k) {
    records[k].branch_slots.clear();
    if (records[k].nucleated()) events.push_back({records[k].nucleation_time, k, kRelease});
    const std::vector<GrowthRow>& r = records[k].rows;
    for (std::size_t i = 0; i < r.size(); ++i) {
      events.push_back({r[i].time, k, i});
      if (r[i].split) i += 2;  // a split and its two branches: one event
    }
  }
  std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    return a.time < b.time || (a.time == b.time && a.k < b.k);
  });
  for (const Event& e : events) {
    const std::size_t k = e.k, i = e.row;
    const int level = s.interface_levels[k];
    State& L = s.levels[std::size_t(level)];
    const double h = L.grid.cell_size();
    const std::vector<GrowthRow>& r = records[k].rows;
    const std::vector<State*> others = other_levels(s, level);
    if (i == kRelease) {
      release_site(c, k, L, s.interface_slots[k], others);
      continue;
    }
    follow_cut_off_parts(c, s, k, crack_lines(s, k, records[k]));
    const int label = r[i].tip;
    const bool split = r[i].split;
    const std::size_t b = std::size_t(label >= 2 ? label - 2 : 0);
    if (label >= 2 && b >= records[k].branch_slots.size())
      throw InputError(fmt::format("checkpoint: run.growth[{}] row {}: tip {} is a branch that has not split off "
                                   "(the checkpoint is not of this case)", k, i, label));
    const std::size_t slot = label >= 2 ? records[k].branch_slots[b] : s.interface_slots[k];
    const std::vector<CrackTip> now = precrack_tips(L.interfaces[slot].spec, 1e-6 * h);
    // The tip the row grew (or split): a branch's one tip, or the crack's at the row's end.
    const LineEnd at = label >= 2 ? LineEnd::end : r[i].end;
    const auto it = std::find_if(now.begin(), now.end(), [&](const CrackTip& t) { return t.end == at; });
    if (it == now.end())
      throw InputError(fmt::format("checkpoint: run.growth[{}] row {}: the crack has no tip at its {} to grow "
                                   "from (the checkpoint is not of this case)",
                                   k, i, at == LineEnd::start ? "start" : "end"));
    if (!split) {
      add_crack_segment(c, k, L, slot, *it, r[i].x, r[i].y, false, others, tie_entry(s, level, slot));
      continue;
    }
    // A split: the next two rows are its branches' first segments.
    const std::size_t n = records[k].branch_slots.size();
    if (i + 3 > r.size() || n / 2 >= c.interfaces[k].branch_fields.size())
      throw InputError(fmt::format("checkpoint: run.growth[{}] row {}: a split without its two branches, or "
                                   "more splits than the crack's max_branches (the checkpoint is not of this case)",
                                   k, i));
    const GrowthRow &a = r[i + 1], &bb = r[i + 2];
    const std::array<std::size_t, 2> slots =
        split_crack_tip(c, k, L, slot, *it, a.x, a.y, bb.x, bb.y,
                        c.interfaces[k].branch_fields[n / 2], false, others, branch_ties(s, level, slot));
    for (const std::size_t sl : slots) s.interface_levels.push_back(level), s.interface_slots.push_back(sl);
    records[k].branch_slots.push_back(slots[0]);
    records[k].branch_slots.push_back(slots[1]);
  }
}

void rejoin_cracks(const Case& c, RunState& s, const std::vector<CrackGrowthRecord>& records) {
  for (std::size_t k = 0; k < records.size() && k < c.interfaces.size(); ++k) {
    if (!c.interfaces[k].growth.on() || !records[k].grown()) continue;
    std::vector<std::size_t> own{s.interface_slots[k]};
    for (const std::size_t b : records[k].branch_slots) own.push_back(b);
    const double h = s.levels[std::size_t(s.interface_levels[k])].grid.cell_size();
    follow_edge_junctions(c, s, k, own, other_lines(c, s, records, k, own), s.time, h);
  }
}

}  // namespace rupture
