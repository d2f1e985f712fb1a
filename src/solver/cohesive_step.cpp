// rupture/solver/cohesive_step.cpp
#include "solver/cohesive_step.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>
#include <type_traits>
#include <cmath>
#include <variant>

#include "core/errors.hpp"
#include "core/fault_injection.hpp"
#include "solver/rank_exchange.hpp"

namespace rupture {
namespace {

constexpr int kG = CohesiveInterface::kGauss;
// The 4-point Gauss-Legendre rule on [-1, 1] (E9).
constexpr const double* kXi = CohesiveInterface::kGaussXi;
constexpr const double* kW = CohesiveInterface::kGaussWeight;

// Bilinear hat weights of the point (x, y): nodes (i, j), (i+1, j), (i, j+1), (i+1, j+1).
struct PointStencil {
  int i, j;  // the node at the lower left of the point's cell
  double wx[2], wy[2];
};

inline PointStencil point_stencil(const Grid& g, double x, double y) {
  if (g.graded()) {
    const int i = g.x.cell_of(x), j = g.y.cell_of(y);
    const double ax = (x - g.x.node(i)) / g.x.width(i), ay = (y - g.y.node(j)) / g.y.width(j);
    return {i, j, {1.0 - ax, ax}, {1.0 - ay, ay}};
  }
  const double fx = (x - g.x.origin) / g.x.h, fy = (y - g.y.origin) / g.y.h;
  // A face on the grid's last node line uses the last cell (weight 1 on that line).
  const int i = std::min(int(std::floor(fx)), g.x.cells - 1);
  const int j = std::min(int(std::floor(fy)), g.y.cells - 1);
  const double ax = fx - i, ay = fy - j;
  return {i, j, {1.0 - ax, ax}, {1.0 - ay, ay}};
}

// A face point moves with, and loads, its own field's nodes around it, weighted by bilinear
// weight times nodal mass: c_i = w_i m_i / sum_j w_j m_j. The face then acts as a point of
// mass sum w m: every node it touches gets the same acceleration from its force, and a node
// its body barely reaches (the tail of a particle's GIMP weight: mass ~1e-11 of a particle)
// neither receives a force it cannot carry nor lends the face its huge f/m velocity. With
// plain bilinear weights, a face drifting a nanometre across its node row picked up such
// nodes and blew up within a few steps. Power is consistent: sum_i f c_i . v_i = f . v_face.
// A face on a T-junction (share < 1) moves with both parts' material around it: each field's
// four weights normalized on their own, then weighted by its share of the node's part of the
// line (all to one field where the other has no mass there).
inline FaceStencil face_stencil(const State& s, FaceFields fields, double x, double y) {
  const PointStencil p = point_stencil(s.grid, x, y);
  FaceStencil f;
  double sum[2] = {0.0, 0.0};
  const int used = fields.share < 1.0 ? 2 : 1;
  for (int part = 0; part < 2; ++part)
    for (int jj = 0; jj < 2; ++jj)
      for (int ii = 0; ii < 2; ++ii) {
        const int q = 4 * part + 2 * jj + ii;
        if (part >= used) {
          f.node[q] = f.node[q - 4], f.c[q] = 0.0;
          continue;
        }
        const int field = part == 0 ? fields.a : fields.b;
        f.node[q] = s.fields.index(field, p.i + ii, p.j + jj);  // in the window: field_windows
        const double m = s.fields.mass[f.node[q]];
        f.c[q] = m > s.mass_floor ? p.wx[ii] * p.wy[jj] * m : 0.0;
        sum[part] += f.c[q];
      }
  double share[2] = {used == 2 ? fields.share : 1.0, used == 2 ? 1.0 - fields.share : 0.0};
  if (sum[0] <= 0.0) share[0] = 0.0, share[1] = used == 2 ? 1.0 : 0.0;
  if (used == 2 && sum[1] <= 0.0) share[1] = 0.0, share[0] = sum[0] > 0.0 ? 1.0 : 0.0;
  for (int part = 0; part < 2; ++part) {
    const double scale = sum[part] > 0.0 ? share[part] / sum[part] : 0.0;
    for (int q = 4 * part; q < 4 * part + 4; ++q) f.c[q] *= scale;
  }
  f.mass = share[0] * sum[0] + share[1] * sum[1];
  return f;
}

// A face point must keep its bilinear 2x2 stencil inside the grid (its edges included: a
// fault may run across the whole domain, as in the 1D slip-weakening test).
inline bool face_inside(const Grid& g, double x, double y) {
  return x >= g.x.node(0) && x <= g.x.node(g.x.cells) && y >= g.y.node(0) &&
         y <= g.y.node(g.y.cells);
}

}  // namespace

namespace {

// A face lighter than light_face_mass meets the contact penalty in proportion to its mass. The
// penalty's share of the step bound is 2 k w / M for a face of mass M (solver/time_step.cpp), so
// it stays below four times the one the set-up assumes (M = rho h^2 / 2, light_face_mass a
// quarter of it) and contact never cuts the step below half the set-up's cohesive bound; a
// face of normal mass keeps the full penalty (a light one closes at the frequency of a face of
// the threshold's mass under the full penalty, twice a normal face's). Faces on a sliver of material or on the outer side of a grown crack's bend
// carry a thousandth of a normal face's mass, and their full penalty cut the step 20-fold or
// more (docs/fracture.md, "Contact on light faces"). 1 where the faces are not known yet.
double light_face_scale(const CohesiveInterface& c, std::size_t k) {
  if (c.light_face_mass <= 0.0 || c.face_up.size() != c.num_nodes() || !c.knows(k)) return 1.0;
  const double m = std::min(c.face_up[k].mass, c.face_lo[k].mass);
  return m < c.light_face_mass ? m / c.light_face_mass : 1.0;
}

// The Gauss-point and node loops of evaluate_interface for one law type (dispatched once per
// interface: no law test inside the loops; what differs between laws is asked of the law,
// cohesive/law.hpp).
template <class Law>
void evaluate_with(CohesiveInterface& c, const Law& law, double t, double t_before) {
  const bool contact = c.spec.contact;
  const ContactLaw& contact_law = c.spec.contact_law;
  const long nseg = long(c.num_segments());
  // The tractions' work per Gauss point, summed after the loop in Gauss-point order: the same to
  // the bit whatever the number of threads (a run may change it between steps:
  // run/thread_tuner.hpp).
  thread_local std::vector<double> gp_work;
  gp_work.assign(std::size_t(nseg) * kG, 0.0);
  double* const work_of = gp_work.data();
#pragma omp parallel for schedule(static)
  for (long sl = 0; sl < nseg; ++sl) {
    const std::size_t s = std::size_t(sl), e = c.segment_end(s);
    // Distributed: the segments touching an owned node (their Gauss histories are kept alike
    // by both ends' owners); the work counted by the owner of the first.
    if (!c.owns(s) && !c.owns(e)) continue;
    const double count_work = c.owns(s) ? 1.0 : 0.0;
    const double half = 0.5 * c.seg_length[s];
    // The segment's frame: normal n, tangent t = (n_y, -n_x) (exactly +y, +x on a line drawn in
    // +x).
    const double nx = c.seg_nx[s], ny = c.seg_ny[s], tx = ny, ty = -nx;
    const double scale = contact || std::is_same_v<Law, ContactLaw>
                             ? std::min(light_face_scale(c, s), light_face_scale(c, e)) : 1.0;
    ContactLaw light = contact_law;
    light.stiffness *= scale, light.tangential_stiffness *= scale;  // 0 stays "as the normal"
    const double jx_a = c.jump_x(s), jx_b = c.jump_x(e);
    const double jy_a = c.jump_y(s), jy_b = c.jump_y(e);
    double fa_n = 0, fa_t = 0, fb_n = 0, fb_t = 0, ka = 0, kb = 0;
    for (int g = 0; g < kG; ++g) {
      const std::size_t i = s * kG + std::size_t(g);
      const double Na = 0.5 * (1.0 - kXi[g]), Nb = 0.5 * (1.0 + kXi[g]);
      const double jx = Na * jx_a + Nb * jx_b, jy = Na * jy_a + Nb * jy_b;  // linear jump
      const double dn = nx * jx + ny * jy, dt = tx * jx + ty * jy;          // in the segment frame
      const Law& L = gauss_point_law(c, law, i);  // a stretch's or a point's own law
      GaussHistory h{c.gp_damage[i], c.gp_slip[i], c.gp_dt[i], c.gp_state[i], c.gp_rate[i], c.gp_normal[i]};
      h.x = Na * c.x0[s] + Nb * c.x0[e], h.y = Na * c.y0[s] + Nb * c.y0[e];  // reference position
      h.time = t, h.duration = t - t_before;
      LawResponse r{0.0, 0.0, 0.0};
      // Xu-Needleman: separated at |jump| >= 5 delta_t (theory §3); the other laws never here.
      if (!c.gp_separated[i] && L.separates_at(dn, dt, c.spec.separation_factor))
        c.gp_separated[i] = 1, h.slip = dt;
      if (!c.gp_separated[i]) {
        if constexpr (std::is_same_v<Law, ContactLaw>) {  // a pre-crack's own law is contact
          ContactLaw light_law = L;
          light_law.stiffness *= scale, light_law.tangential_stiffness *= scale;
          r = (scale < 1.0 ? light_law : L).respond(dn, dt, h);
        } else {
          r = L.respond(dn, dt, h);  // E7-E8; stiffness: the E6 bound (solver/time_step.hpp)
        }
        if (L.separated(h)) c.gp_separated[i] = 1, h.slip = dt, r = {0.0, 0.0, 0.0};
      } else if (contact) {
        r = (scale < 1.0 ? light : contact_law).respond(dn, dt, h);
      }
      c.gp_damage[i] = h.damage, c.gp_slip[i] = h.slip, c.gp_state[i] = h.state, c.gp_rate[i] = h.rate;
      c.gp_normal[i] = h.normal_seen;
      const double tn = r.tn, tt = r.tt, k = r.stiffness;
      // Work of the tractions over the step, trapezoidal in time (E14).
      const double jw = kW[g] * half;
      work_of[i] = count_work * jw * (0.5 * (c.gp_tn[i] + tn) * (dn - c.gp_dn[i]) +
                                      0.5 * (c.gp_tt[i] + tt) * (dt - c.gp_dt[i]));
      c.gp_dn[i] = dn, c.gp_dt[i] = dt, c.gp_tn[i] = tn, c.gp_tt[i] = tt;
      fa_n += jw * Na * tn, fa_t += jw * Na * tt;
      fb_n += jw * Nb * tn, fb_t += jw * Nb * tt;
      ka += jw * Na * k, kb += jw * Nb * k;
    }
    c.seg_ka[s] = ka, c.seg_kb[s] = kb;
    // Force on the upper face: -T^ = -(T^n n + T^t t) (rotation of the faces neglected, theory §3).
    c.seg_fa_x[s] = -(fa_n * nx + fa_t * tx), c.seg_fa_y[s] = -(fa_n * ny + fa_t * ty);
    c.seg_fb_x[s] = -(fb_n * nx + fb_t * tx), c.seg_fb_y[s] = -(fb_n * ny + fb_t * ty);
  }
  double work = 0.0;
  for (const double w : gp_work) work += w;
  c.work += work;
  c.time = t;
  const long nn = long(c.num_nodes());
  const std::size_t last_seg = c.num_segments() - 1;
#pragma omp parallel for schedule(static)
  for (long kl = 0; kl < nn; ++kl) {
    const std::size_t k = std::size_t(kl);
    if (!c.owns(k)) continue;  // distributed: its owner's (synced where this rank needs it)
    double fx = 0, fy = 0, stiff = 0;
    // The segment ending on node k (on a closed line, node 0 ends the last one), then the one
    // starting there.
    const bool has_prev = k > 0 || c.closed;
    const std::size_t prev = k > 0 ? k - 1 : last_seg;
    if (has_prev) fx += c.seg_fb_x[prev], fy += c.seg_fb_y[prev], stiff += c.seg_kb[prev];
    if (k <= last_seg) fx += c.seg_fa_x[k], fy += c.seg_fa_y[k], stiff += c.seg_ka[k];
    c.fx_node[k] = fx, c.fy_node[k] = fy, c.stiffness_node[k] = stiff;
    // Rupture front and peak slip rate (SCEC: the first time the slip rate exceeds 1 mm/s).
    // Where the law keeps a slip path (a fault: Law::kSlipPathRate) the rate that counts is
    // that path's (sliding only): the stick spring's elastic jump, which passing waves load, is
    // no slip.
    const double dt = t - t_before;
    double slip_rate = dt > 0.0 ? std::fabs(c.last_increment_t[k]) / dt : 0.0;
    c.node_slip_rate[k] = dt > 0.0 ? c.last_increment_t[k] / dt : 0.0;
    if constexpr (Law::kSlipPathRate) {
      const std::size_t G = std::size_t(kG);
      double path = 0.0;
      int count = 0;
      if (k <= last_seg) path += c.gp_damage[k * G], ++count;
      if (has_prev) path += c.gp_damage[prev * G + G - 1], ++count;
      path /= count;
      const double sliding = dt > 0.0 ? (path - c.node_slip_path[k]) / dt : 0.0;
      c.node_slip_path[k] = path;
      slip_rate = sliding;
      c.node_slip_rate[k] = std::copysign(sliding, c.last_increment_t[k]);
    }
    c.node_peak_slip_rate[k] = std::max(c.node_peak_slip_rate[k], slip_rate);
    if (c.node_rupture_time[k] < 0.0 && slip_rate > c.spec.rupture_slip_rate)
      c.node_rupture_time[k] = t;
    const Law& L = node_law_of(c, law, k);
    const double crit = L.crack_threshold(c.spec.separation_factor);
    const double opening = L.crack_measure(c.jump_normal(k), c.jump_tangential(k));
    if (c.node_crack_time[k] < 0.0 && opening >= crit) {
      // Linear in time between the step's ends: the E10 tip is then sampled at exact times.
      const double before = c.jump_before[k];
      const double f =
          before < crit && opening > before ? (crit - before) / (opening - before) : 1.0;
      c.node_crack_time[k] = t_before + f * (t - t_before);
    }
  }
}

}  // namespace

void evaluate_interface(CohesiveInterface& c, double t, double t_before) {
  std::visit([&](const auto& law) { evaluate_with(c, law, t, t_before); }, c.spec.law);
}

namespace {
// jump_before: each node's crack measure before the faces move (node crack times, E10).
void record_openings(CohesiveInterface& c) {
  std::visit(
      [&](const auto& law) {
        for (std::size_t k = 0; k < c.num_nodes(); ++k) {
          const auto& L = node_law_of(c, law, k);
          c.jump_before[k] = L.crack_measure(c.jump_normal(k), c.jump_tangential(k));
        }
      },
      c.spec.law);
}
}  // namespace

void update_face_stencils(State& s) {
  for (CohesiveInterface& c : s.interfaces) {
    const long n = long(c.num_nodes());
    c.face_up.resize(c.num_nodes());
    c.face_lo.resize(c.num_nodes());
    long bad = n;
#pragma omp parallel for schedule(static) reduction(min : bad)
    for (long kl = 0; kl < n; ++kl) {
      const std::size_t k = std::size_t(kl);
      if (!c.knows(k)) continue;  // distributed: far from this rank's block
      const double xa = c.x0[k] + c.ux_up[k], ya = c.y0[k] + c.uy_up[k];
      const double xb = c.x0[k] + c.ux_lo[k], yb = c.y0[k] + c.uy_lo[k];
      if (!face_inside(s.grid, xa, ya) || !face_inside(s.grid, xb, yb)) {
        bad = std::min(bad, kl);
        continue;
      }
      c.face_up[k] = face_stencil(s, c.faces_up(k), xa, ya);  // a T-junction: per node
      c.face_lo[k] = face_stencil(s, c.faces_lo(k), xb, yb);
    }
    if (bad == n && n > 0 && fault_due(FaultSite::face_outside_grid, s.step)) bad = 0;  // tests
    if (bad < n) {
      // Distributed: this rank's faces stay as they were (no force from them this step) and
      // the run stops with every rank at the step's end (parallel/halo.hpp).
      const std::size_t k = std::size_t(bad);
      fail_in_step(s, fmt::format(
          "unstable: cohesive interface node {} at (x, y) = ({:.6g}, {:.6g}) m has a face at a "
          "non-finite "
          "position or outside the grid at step {}, t = {:.6g} s: upper face displacement ({:.4g}, "
          "{:.4g}) m, lower ({:.4g}, {:.4g}) m; reduce time.cohesive_safety or time.cfl",
          k, c.x0[k], c.y0[k], s.step, s.time, c.ux_up[k], c.uy_up[k], c.ux_lo[k], c.uy_lo[k]));
    }
  }
}

void add_cohesive_forces(State& s) {
  if (failed_in_step(s)) return;  // distributed: faces this rank found broken give no force
  GridFields& G = s.fields;
  for (CohesiveInterface& c : s.interfaces) {
    // Serial: ~15 face nodes share each grid node; this loop is O(interface nodes), tiny
    // next to the particle loops, and its fixed order keeps results thread-count independent.
    for (std::size_t k = 0; k < c.num_nodes(); ++k) {
      const double fx = c.fx_node[k], fy = c.fy_node[k];
      if ((fx == 0.0 && fy == 0.0) || !c.owns(k)) continue;  // distributed: owners load the grid
      const FaceStencil& a = c.face_up[k];
      const FaceStencil& b = c.face_lo[k];
      for (int q = 0; q < FaceStencil::kSlots; ++q) {
        G.force_x[a.node[q]] += a.c[q] * fx, G.force_y[a.node[q]] += a.c[q] * fy;  // upper: -T^
        G.force_x[b.node[q]] -= b.c[q] * fx, G.force_y[b.node[q]] -= b.c[q] * fy;  // lower: +T^
      }
    }
  }
}

namespace {

// Whether a tie's end (x, y) lies on the crack's line: at a tip (a tie runs on from it), or on
// a closed line where the bonded stretch meets the open part. The tie stops exactly there.
bool at_tip(const Polyline& crack, double x, double y, double tol) {
  if (crack.num_vertices() < 2) return false;
  return project(crack, x, y).distance <= tol;
}

// `tie` is where the band is laid (the drawn tie, or the tie where the material has carried it:
// solver/tie_follow.hpp); free_start / free_end: whether its ends are not a crack's tip.
void nodes_near_tie(const Grid& g, const Polyline& tie, bool free_start, bool free_end,
                    std::vector<std::size_t>& out) {
  if (tie.num_vertices() < 2) return;
  // A grid node gets mass from both bodies when the GIMP support of one body's particles reaches
  // across the line to it. A particle centred at x_p with half-width l_p loads the nodes with
  // |x_i - x_p| < h + l_p on each axis (h: that axis's cell width). Its centre may lie on the
  // line (a line not along the grid cuts the particles anywhere), l_p <= h / 2 (one particle per
  // cell and direction at least), and once it moves by d (each axis) it reaches h + l_p + d.
  // The tie takes every node strictly closer than 2 (|n_x| h_x + |n_y| h_y) to its line: all a
  // particle reaches while it stays within half a cell (each axis) of where it was set up. The
  // two fields there sum to exactly what one field would hold: one continuum (docs/fracture.md,
  // "The tie's reach": a body split along a line equals the undivided body to round-off).
  // A tie ends at a crack's tip (on the crack's line) or on an edge (or another line). At a tip
  // it stops exactly (the nodes beyond it are the crack's, whose two fields must stay apart); at
  // any other end it reaches as far beyond, to the nodes particles there load once a free edge
  // bulges outward.
  const double len = tie.length();
  double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
  for (std::size_t v = 0; v < tie.num_vertices(); ++v) {
    xlo = std::min(xlo, tie.x[v]), xhi = std::max(xhi, tie.x[v]);
    ylo = std::min(ylo, tie.y[v]), yhi = std::max(yhi, tie.y[v]);
  }
  auto node_width = [](const Axis& a, int i) {
    return std::max(a.width(std::clamp(i - 1, 0, a.cells - 1)),
                    a.width(std::clamp(i, 0, a.cells - 1)));
  };
  const double tol = 1e-9 * std::min(g.x.h, g.y.h);
  for (int j = 0; j < g.nodes_y(); ++j) {
    const double y = g.y.node(j), hy = node_width(g.y, j);
    if (y < ylo - 4.0 * hy || y > yhi + 4.0 * hy) continue;
    for (int i = 0; i < g.nodes_x(); ++i) {
      const double x = g.x.node(i), hx = node_width(g.x, i);
      if (x < xlo - 4.0 * hx || x > xhi + 4.0 * hx) continue;
      const LineProjection p = project(tie, x, y);
      const double reach = 2.0 * (std::fabs(p.nx) * hx + std::fabs(p.ny) * hy);
      if (p.beyond <= tol) {
        if (p.distance < reach - tol) out.push_back(g.node_index(i, j));
        continue;
      }
      // Beyond an end: along the line (tangent (n_y, -n_x)) and across it.
      const bool at_start = p.s <= 0.5 * len;
      if (!(at_start ? free_start : free_end)) continue;
      const double across = std::sqrt(std::max(p.distance * p.distance - p.beyond * p.beyond, 0.0));
      const double reach_along = 2.0 * (std::fabs(p.ny) * hx + std::fabs(p.nx) * hy);
      if (p.beyond < reach_along - tol && across < reach - tol) out.push_back(g.node_index(i, j));
    }
  }
}

}  // namespace

std::vector<std::size_t> bonded_nodes(const Grid& g, const InterfaceSpec& spec) {
  return bonded_nodes(g, spec.tie_geometries(), spec.geometry());
}

std::vector<std::size_t> bonded_nodes(const Grid& g, const std::vector<Polyline>& ties,
                                      const Polyline& crack) {
  return bonded_nodes(g, ties, crack, ties);
}

std::vector<std::size_t> bonded_nodes(const Grid& g, const std::vector<Polyline>& ties,
                                      const Polyline& crack, const std::vector<Polyline>& laid) {
  std::vector<std::size_t> out;
  const double tip_tol = 1e-6 * std::min(g.x.h, g.y.h);
  for (std::size_t i = 0; i < ties.size() && i < laid.size(); ++i) {
    const Polyline& tie = ties[i];
    if (tie.num_vertices() < 2) continue;
    // Whether an end is a tip is read where the crack is drawn (the reference configuration).
    const std::size_t last = tie.num_vertices() - 1;
    nodes_near_tie(g, laid[i], !at_tip(crack, tie.x[0], tie.y[0], tip_tol),
                   !at_tip(crack, tie.x[last], tie.y[last], tip_tol), out);
  }
  // Several tied stretches (a crack inside a body with both ends inside it) may share a node;
  // it is tied once (a tie sums both fields: twice would double it).
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

namespace {

// The ties' signature: their field pairs and nodes (FNV-1a over the values).
std::uint64_t tie_signature(const std::vector<BondedTie>& ties) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](std::uint64_t v) { h = (h ^ v) * 1099511628211ull; };
  mix(ties.size());
  for (const BondedTie& b : ties) {
    mix(std::uint64_t(b.upper_field)), mix(std::uint64_t(b.lower_field)), mix(b.nodes.size());
    for (const std::size_t n : b.nodes) mix(n);
  }
  return h;
}

// The nodes in more than one tie where the ties share a field, and which ties' nodes they are.
void find_junctions(const std::vector<BondedTie>& ties, TieJunctions& out) {
  out.nodes.clear();
  out.shared.assign(ties.size(), {});
  if (ties.size() < 2) return;
  std::vector<std::pair<std::size_t, std::size_t>> at;  // (node, tie)
  for (std::size_t t = 0; t < ties.size(); ++t)
    for (const std::size_t n : ties[t].nodes) at.push_back({n, t});
  std::sort(at.begin(), at.end());
  for (std::size_t i = 0; i < at.size();) {
    std::size_t j = i + 1;
    while (j < at.size() && at[j].first == at[i].first) ++j;
    if (j - i > 1) {
      TieJunction J;
      J.node = at[i].first;
      for (std::size_t e = i; e < j; ++e)
        for (const int f : {ties[at[e].second].upper_field, ties[at[e].second].lower_field})
          if (std::find(J.fields.begin(), J.fields.end(), f) == J.fields.end()) J.fields.push_back(f);
      // Ties of disjoint field pairs (two cracks' ties crossing, four fields) stay pairs: only
      // ties that share a field join. Union of the pairs, each group labelled by its first entry.
      const std::size_t m = J.fields.size();
      J.group.resize(m);
      for (std::size_t a = 0; a < m; ++a) J.group[a] = int(a);
      auto find = [&](int a) {
        while (J.group[std::size_t(a)] != a) a = J.group[std::size_t(a)];
        return a;
      };
      auto entry = [&](int f) { return int(std::find(J.fields.begin(), J.fields.end(), f) - J.fields.begin()); };
      for (std::size_t e = i; e < j; ++e) {
        const int ra = find(entry(ties[at[e].second].upper_field)), rc = find(entry(ties[at[e].second].lower_field));
        J.group[std::size_t(std::max(ra, rc))] = std::min(ra, rc);
      }
      for (std::size_t a = 0; a < m; ++a) J.group[a] = find(int(a));
      if (m < 2 * (j - i)) {  // some ties share a field: the node is joined here, not pairwise
        for (std::size_t e = i; e < j; ++e) {
          const std::vector<std::size_t>& nodes = ties[at[e].second].nodes;
          std::vector<char>& mark = out.shared[at[e].second];
          mark.resize(nodes.size(), 0);
          mark[std::size_t(std::lower_bound(nodes.begin(), nodes.end(), J.node) - nodes.begin())] = 1;
        }
        out.nodes.push_back(std::move(J));
      }
    }
    i = j;
  }
}

}  // namespace

void tie_bonded_nodes(State& s, TieWhat what) {
  GridFields& G = s.fields;
  // Nodes where ties sharing a field meet (a split crack's junction) sum every field the ties
  // join, once; any other tied node sums its tie's two fields (two ties of one pair of fields
  // at a node are one tie: bonded_nodes lists the node once).
  if (s.bonded.size() >= 2) {
    const std::uint64_t sig = tie_signature(s.bonded);
    if (sig != s.junctions.signature || s.junctions.shared.size() != s.bonded.size())
      find_junctions(s.bonded, s.junctions), s.junctions.signature = sig;
  } else if (!s.junctions.nodes.empty() || !s.junctions.shared.empty()) {
    s.junctions = TieJunctions{};
  }
  const TieJunctions& junctions = s.junctions;
  auto each = [&](auto&& tie) {
    if (what == TieWhat::mass_momentum) {
      for (auto* v : {&G.mass, &G.mom_x, &G.mom_y}) tie(*v);
    } else if (what == TieWhat::force) {
      tie(G.force_x);
      tie(G.force_y);
    } else {
      tie(G.remap_x);
      tie(G.remap_y);
    }
  };
  // Only the fields with mass at a node take the sum: a field no particle of it reaches there is
  // left empty (the sum is the other's alone, and a copy would hand that material's velocity
  // to the empty field's face stencils beside a tip). The mass pass decides it; the later passes
  // find the same fields with mass (a tied copy holds the positive sum, an empty one zero).
  for (std::size_t t = 0; t < s.bonded.size(); ++t) {
    const BondedTie& b = s.bonded[t];
    const int up = b.upper_field, lo = b.lower_field;
    const std::vector<char>* skip = t < junctions.shared.size() ? &junctions.shared[t] : nullptr;
    for (std::size_t i = 0; i < b.nodes.size(); ++i) {
      if (skip && !skip->empty() && (*skip)[i]) continue;
      const std::size_t n = b.nodes[i];
      const std::size_t iu = G.index(up, n), il = G.index(lo, n);  // in both windows
      if (!(G.mass[iu] > 0.0 && G.mass[il] > 0.0)) continue;
      each([&](std::vector<double>& v) { v[iu] = v[il] = v[iu] + v[il]; });
    }
  }
  for (const TieJunction& J : junctions.nodes)
    each([&](std::vector<double>& v) {
      for (std::size_t a = 0; a < J.fields.size(); ++a) {
        if (J.group[a] != int(a)) continue;  // each group once, from its first field
        double sum = 0.0;
        for (std::size_t e = 0; e < J.fields.size(); ++e)
          if (J.group[e] == int(a)) sum += v[G.index(J.fields[e], J.node)];
        for (std::size_t e = 0; e < J.fields.size(); ++e)
          if (J.group[e] == int(a) && G.mass[G.index(J.fields[e], J.node)] > 0.0)
            v[G.index(J.fields[e], J.node)] = sum;  // a field's mass: positive until set, then the sum
      }
    });
}

namespace {

// A face pair driven past its stability limit oscillates at the step's own period: with
// omega dt > 2 the central-difference multiplier is real and below -1 (mu + 1/mu = 2 -
// omega^2 dt^2), so its jump increment reverses sign every step and grows by |mu| each time.
// Resolved physics never does that (a cohesive zone spans many steps, and a stable mode has
// |mu| = 1), so a run of reversals, each larger than the last, that has grown the increment a
// thousandfold is taken as the instability, once the increment matters (a thousandth of
// delta_n a step), which is long before the jump reaches the separation criterion.
constexpr int kUnstableStreak = 4;
constexpr double kUnstableGrowth = 1e3;
constexpr double kUnstableIncrement = 1e-3;  // x delta_n

void fail_cohesive_oscillation(State& s, const CohesiveInterface& c, std::size_t k) {
  fail_in_step(s, fmt::format(
      "unstable: cohesive interface oscillates at node {} (x, y) = ({:.6g}, {:.6g}) m: its jump "
      "increment reversed sign and grew for {} steps in a row, {:.3g} times over, to ({:.3g}, "
      "{:.3g}) m "
      "per step (normal, tangential), at step {}, t = {:.6g} s, with dt = {:.4g} s against a "
      "cohesive "
      "stability limit of {:.4g} s; the step is too long for the interface stiffness (reduce "
      "time.cohesive_safety or time.cfl)",
      k, c.x0[k], c.y0[k], c.reversal_streak[k],
      std::hypot(c.last_increment_n[k], c.last_increment_t[k]) / c.streak_base[k],
      c.last_increment_n[k], c.last_increment_t[k], s.step, s.time, s.dt, s.limits.cohesive_dt));
}

}  // namespace

void advance_interfaces(State& s, const double* vel_x, const double* vel_y) {
  const double dt = s.dt;
  for (CohesiveInterface& c : s.interfaces) {
    const long n = long(c.num_nodes());
    const double floor = kUnstableIncrement * opening_scale(c.spec.law);
    record_openings(c);  // the crack measure before the faces move (node crack times)
    long unstable = n;
    const bool frozen = failed_in_step(s);  // distributed: this rank's stencils may be broken
#pragma omp parallel for schedule(static) reduction(min : unstable)
    for (long kl = 0; kl < n; ++kl) {
      const std::size_t k = std::size_t(kl);
      if (frozen || !c.owns(k)) continue;  // distributed: the owner moves it, sends it (below)
      // Each face moves with its own field's t^{n+1} grid velocity (the one its body's strain is
      // updated with), through the stencil its force was spread with (update_face_stencils).
      const FaceStencil& a = c.face_up[k];
      const FaceStencil& b = c.face_lo[k];
      double vax = 0, vay = 0, vbx = 0, vby = 0;
      for (int q = 0; q < FaceStencil::kSlots; ++q) {
        vax += a.c[q] * vel_x[a.node[q]], vay += a.c[q] * vel_y[a.node[q]];
        vbx += b.c[q] * vel_x[b.node[q]], vby += b.c[q] * vel_y[b.node[q]];
      }
      c.ux_up[k] += dt * vax, c.uy_up[k] += dt * vay;
      c.ux_lo[k] += dt * vbx, c.uy_lo[k] += dt * vby;
      // Instability watch on the intact part (an opened crack moves freely).
      // The jump increment in the node's frame (n, t = (n_y, -n_x)): exactly (y, x) on a line
      // drawn in +x.
      const double dvx = dt * (vax - vbx), dvy = dt * (vay - vby);
      const double inc_n = c.node_nx[k] * dvx + c.node_ny[k] * dvy;
      const double inc_t = c.node_ny[k] * dvx - c.node_nx[k] * dvy;
      const double last_n = c.last_increment_n[k], last_t = c.last_increment_t[k];
      const double size = std::hypot(inc_n, inc_t), last = std::hypot(last_n, last_t);
      const bool reverses = inc_n * last_n + inc_t * last_t < 0.0;
      if (reverses && size > last && c.node_crack_time[k] < 0.0) {
        if (c.reversal_streak[k]++ == 0) c.streak_base[k] = last;
      } else {
        c.reversal_streak[k] = 0;
      }
      c.last_increment_n[k] = inc_n, c.last_increment_t[k] = inc_t;
      if (c.reversal_streak[k] >= kUnstableStreak && size > floor &&
          size > kUnstableGrowth * c.streak_base[k])
        unstable = std::min(unstable, kl);
    }
    if (unstable == n && !frozen && fault_due(FaultSite::cohesive_oscillation, s.step))  // tests
      for (std::size_t k = 0; k < c.num_nodes() && unstable == n; ++k)
        if (c.owns(k)) unstable = long(k);
    // Distributed: the syncs below are collective, so the rank takes part, then all stop.
    if (unstable < n) fail_cohesive_oscillation(s, c, std::size_t(unstable));
    // Distributed: the ghosts' faces from their owners, before the segments that reach them
    // are evaluated; after it, the ghosts' stiffness (the next step's bound, E6).
    sync_interface_nodes(s, c, {&CohesiveInterface::ux_up, &CohesiveInterface::uy_up,
                                &CohesiveInterface::ux_lo, &CohesiveInterface::uy_lo});
    evaluate_interface(c, s.time, s.time - dt);
    sync_interface_nodes(s, c, {&CohesiveInterface::stiffness_node});
  }
}

}  // namespace rupture
