// rupture/solver/gather.cpp
// Grid -> particle gather of the time step (theory E5): stress update, velocity (USL/USF) and
// the move, in batches of kBatch consecutive particles. Each batch runs as separate short
// loops: the stencils (SIMD over particles, solver/stencil_batch.hpp), the node gather (one
// particle at a time: 9 nodes of the strip's tile, solver/strip_tile.hpp, which packs the
// values the pass reads per node: one vector load per node instead of one per grid array;
// docs/performance.md, "Choices in the code"), then the
// velocity, stress and move updates SIMD over the
// batch's particles, which are contiguous in every particle array. Splitting the work this way
// keeps few array pointers live per loop (one fused per-particle loop spilled them to the
// stack: the hottest instructions on AMD Zen 4). Per particle the arithmetic and its order are
// those of theory E5, so results do not depend on the batch size or the thread count.
#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>

#include "bulk/elastic_update.hpp"
#include "core/errors.hpp"
#include "solver/energy.hpp"
#include "solver/stencil_batch.hpp"
#include "solver/strip_tile.hpp"
#include "solver/transfer.hpp"

namespace rupture {
using namespace detail;
namespace {

// A failure spreads through the grid within one step, so the diagnosis reports every bad
// particle's extent (where it started lies inside: a particle is not moved with a non-finite
// velocity, move_particles) and the worst one, not just the first index, naming every
// quantity found non-finite.
std::string diagnose_bad_particles(const State& s, double xlo, double xhi, double ylo, double yhi) {
  const Particles& P = s.particles;
  std::size_t nonfinite = 0, outside = 0, first = kNone;
  bool bad_x = false, bad_v = false, bad_s = false;
  double bx0 = INFINITY, bx1 = -INFINITY, by0 = INFINITY, by1 = -INFINITY;
  for (std::size_t p = 0; p < P.size(); ++p) {
    const bool x_ok = std::isfinite(P.x[p]) && std::isfinite(P.y[p]);
    const bool v_ok = std::isfinite(P.vx[p] + P.vy[p]);
    const bool s_ok = std::isfinite(P.sxx[p] + P.syy[p] + P.sxy[p]);
    const bool in = P.x[p] > xlo && P.x[p] < xhi && P.y[p] > ylo && P.y[p] < yhi;
    if (v_ok && s_ok && in) continue;
    if (first == kNone) first = p;
    if (!x_ok || !v_ok || !s_ok) {
      ++nonfinite;
      bad_x = bad_x || !x_ok, bad_v = bad_v || !v_ok, bad_s = bad_s || !s_ok;
    } else {
      ++outside;
    }
    if (x_ok) {
      bx0 = std::min(bx0, P.x[p]), bx1 = std::max(bx1, P.x[p]);
      by0 = std::min(by0, P.y[p]), by1 = std::max(by1, P.y[p]);
    }
  }
  const std::string region =
      bx0 <= bx1 ? fmt::format("affected region x in [{:.6g}, {:.6g}], y in [{:.6g}, {:.6g}] m",
                               bx0, bx1, by0, by1)
                 : std::string("no affected particle has a finite position");
  const std::string where = fmt::format(
      "at step {}, t = {:.6g} s; {}; first: particle {} (field {}) at (x, y) = ({:.6g}, {:.6g}) "
      "m, v = ({:.4g}, {:.4g}) m/s",
      s.step, s.time, region, P.id[first], int(P.field[first]), P.x[first], P.y[first],
      P.vx[first], P.vy[first]);
  if (nonfinite > 0) {
    std::string what;
    for (const auto& [bad, name] : {std::pair{bad_x, "position"}, {bad_v, "velocity"}, {bad_s, "stress"}})
      if (bad) what += (what.empty() ? "" : ", ") + std::string(name);
    return fmt::format(
        "unstable: non-finite {} in {} particle(s) {}; reduce time.cfl or check the loading",
        what, nonfinite, where);
  }
  return fmt::format(
      "particle left the grid: {} particle(s) {}; the grid with its ghost cells spans x in "
      "[{:.6g}, {:.6g}], y in [{:.6g}, {:.6g}] m",
      outside, where, xlo, xhi, ylo, yhi);
}

// What one batch's node gather produces, per particle k of the batch.
struct Gathered {
  alignas(64) double L00[kBatch], L01[kBatch], L10[kBatch], L11[kBatch];  // L_ij = dv_i/dx_j, 1/s
  alignas(64) double pic_x[kBatch], pic_y[kBatch];  // sum S v(t^{n+1}), m/s
  alignas(64) double dv_x[kBatch], dv_y[kBatch];    // sum S dv, m/s
  alignas(64) double mv_x[kBatch], mv_y[kBatch];    // the move's velocity, m/s
};

// The strip's gather tile (solver/strip_tile.hpp): per node the values the pass reads, packed
// in one vector. Lanes: the stress update's velocity (gvx, gvy) first when the pass updates
// the stress, then the t^{n+1} velocity (move, PIC part), then its increment (USL/USF
// velocity update).
template <G2PMode kMode>
struct GatherTile {
  static constexpr bool kStress = kMode != G2PMode::velocity_and_move;
  static constexpr bool kVel = kMode != G2PMode::stress_only;
  static constexpr bool kDv =
      kMode == G2PMode::stress_velocity_and_move || kMode == G2PMode::velocity_and_move;
  static constexpr int kVelLane = kStress ? 2 : 0, kDvLane = kVelLane + 2;
  static constexpr int kLanes = (kStress ? 2 : 0) + (kVel ? 2 : 0) + (kDv ? 2 : 0);
  using Lane = std::conditional_t<kLanes == 2, Lane2, std::conditional_t<kLanes == 4, Lane4, Lane8>>;
  // The grid arrays of the tile's lanes, in lane order (the tile is packed from them).
  static void sources(const double* gvx, const double* gvy, const GridFields& G,
                      const double* (&lanes)[6]) {
    if constexpr (kStress) lanes[0] = gvx, lanes[1] = gvy;
    if constexpr (kVel) lanes[kVelLane] = G.vel_x.data(), lanes[kVelLane + 1] = G.vel_y.data();
    if constexpr (kDv) lanes[kDvLane] = G.dvel_x.data(), lanes[kDvLane + 1] = G.dvel_y.data();
  }
};

// The nine tile nodes of the current run of particles that share a stencil: particles are
// sorted by the stencil's first node (sort_particles), so a run (about four particles at
// 2 x 2 per cell) reads them once.
template <class Lane>
struct RunNodes {
  const Lane* t0 = nullptr;  // the run's first node in the tile
  Lane node[9] = {};         // node (a, b) at 3 b + a
};

// The 3 x 3 node sums of one batch from the strip's tile. Per particle, per stencil row b: the
// row's sums across its three nodes with the x weights (sx_a for S and dS/dy, dsx_a for dS/dx),
// then down the rows with the y weights: S = sx_a sy_b, dS/dx = dsx_a sy_b, dS/dy = sx_a dsy_b.
// Every lane of the tile vector at once: no horizontal sums.
template <G2PMode kMode>
void gather_nodes(const StencilBatch2& B, int n, const typename GatherTile<kMode>::Lane* tile,
                  const TileLayout& T, const std::uint8_t* field, Gathered& out,
                  RunNodes<typename GatherTile<kMode>::Lane>& run) {
  using GT = GatherTile<kMode>;
  using Lane = typename GT::Lane;
  const std::size_t cols = std::size_t(T.cols);
  for (int k = 0; k < n; ++k) {
    const Lane* t0 = tile + T.index(field[k], B.first[0][k], B.first[1][k]);
    if (t0 != run.t0) {  // a new run of particles sharing a stencil (sort_particles)
      run.t0 = t0;
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) run.node[3 * b + a] = t0[std::size_t(b) * cols + std::size_t(a)];
    }
    const double sx0 = B.w[0][0][k], sx1 = B.w[0][1][k], sx2 = B.w[0][2][k];
    const double dx0 = B.dw[0][0][k], dx1 = B.dw[0][1][k], dx2 = B.dw[0][2][k];
    Lane S{}, Gx{}, Gy{};
    for (int b = 0; b < 3; ++b) {
      const Lane* r = run.node + 3 * b;
      const Lane row_s = sx0 * r[0] + sx1 * r[1] + sx2 * r[2];
      S += B.w[1][b][k] * row_s;
      if constexpr (GT::kStress) {
        const Lane row_d = dx0 * r[0] + dx1 * r[1] + dx2 * r[2];
        Gx += B.w[1][b][k] * row_d;
        Gy += B.dw[1][b][k] * row_s;
      }
    }
    if constexpr (GT::kStress) {
      out.L00[k] = Gx[0], out.L01[k] = Gy[0];
      out.L10[k] = Gx[1], out.L11[k] = Gy[1];
    }
    if constexpr (GT::kVel) {
      // The t^{n+1} velocity at the particle: the PIC part of the velocity update and the move.
      const double px = S[GT::kVelLane], py = S[GT::kVelLane + 1];
      out.pic_x[k] = px, out.pic_y[k] = py;
      out.mv_x[k] = px, out.mv_y[k] = py;
    }
    if constexpr (GT::kDv) out.dv_x[k] = S[GT::kDvLane], out.dv_y[k] = S[GT::kDvLane + 1];
  }
}

// theory E5 for particles [p, p + n): eps_dot = sym(L), sigma_dot = C : eps_dot (small strain,
// plane mode in C), and E14's stress work of the increment (solver/energy.hpp), summed in
// particle order into `work`. The stress is the stored state: tr eps (for the volume) follows
// from it (material/elastic.hpp), and sigma_zz and the strain are derived where needed.
void update_stress(Particles& P, std::size_t p, int n, const Gathered& g,
                   const std::vector<ElasticStiffness>& stiffness, double dt, double& work,
                   double& viscous_work) {
  alignas(64) double c11[kBatch], c12[kBatch], mu[kBatch], kt[kBatch], wk[kBatch], kv[kBatch];
  const std::uint8_t* mat = P.material.data() + p;
  const bool one = stiffness.size() == 1;  // one material: no lookup per particle
  for (int k = 0; k < n; ++k) {
    const ElasticStiffness& C = stiffness[one ? 0 : mat[k]];
    c11[k] = C.c11, c12[k] = C.c12, mu[k] = C.mu, kt[k] = C.tr_per_stress, kv[k] = C.kelvin_voigt;
  }
  double* __restrict sxx = P.sxx.data() + p;
  double* __restrict syy = P.syy.data() + p;
  double* __restrict sxy = P.sxy.data() + p;
  const double* __restrict vol0 = P.volume0.data() + p;
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    const double L[2][2] = {{g.L00[k], g.L01[k]}, {g.L10[k], g.L11[k]}};
    double de[3], ds[3];
    strain_increment<2>(L, dt, de);
    stress_increment<2>(c11[k], c12[k], mu[k], de, ds);
    const double sig[3] = {sxx[k], syy[k], sxy[k]};
    const double tr_eps = trace<2>(sig) * kt[k];  // strain_trace, before the increment
    wk[k] = stress_work<2>(vol0[k], tr_eps, sig, de, ds);
    sxx[k] += ds[0];
    syy[k] += ds[1];
    sxy[k] += ds[2];
  }
  for (int k = 0; k < n; ++k) work += wk[k];
  if (!P.viscous_on) return;
  // Kelvin-Voigt (docs/theory.md §16): the viscous stress sigma_v = eta C : eps_dot with eta =
  // f dt is f C : d eps, f this material's kelvin_voigt. The one the step's force used (the
  // last update's) did the work V sigma_v : d eps, dissipated; then it takes this increment's.
  double* __restrict vxx = P.vsxx.data() + p;
  double* __restrict vyy = P.vsyy.data() + p;
  double* __restrict vxy = P.vsxy.data() + p;
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    const double L[2][2] = {{g.L00[k], g.L01[k]}, {g.L10[k], g.L11[k]}};
    double de[3], vs[3];
    strain_increment<2>(L, dt, de);
    const double sig[3] = {sxx[k], syy[k], sxy[k]}, vs_last[3] = {vxx[k], vyy[k], vxy[k]};
    const double V = vol0[k] * (1.0 + trace<2>(sig) * kt[k]);
    wk[k] = V * contract<2>(vs_last, de);
    viscous_stress<2>(kv[k], c11[k], c12[k], mu[k], de, vs);
    vxx[k] = vs[0];
    vyy[k] = vs[1];
    vxy[k] = vs[2];
  }
  for (int k = 0; k < n; ++k) viscous_work += wk[k];  // in particle order, as the elastic work
}

// Bounds a strip's particles must keep: inside the grid (see below), within the scatter plan's
// drift tolerance, finite.
struct MoveLimits {
  double xlo, xhi, ylo, yhi;  // m
  double col_lo, col_hi;      // cell columns allowed (the strip's, +-1)
};

// Moves particles [p, p + n) with the gathered velocity; sets `drifted` when one left its
// strip's tolerance, raises `fastest` to the largest |v_x| + |v_y| of a finite particle. A
// non-finite velocity does not move its particle: the run stops at the end of the pass
// (first_bad: that velocity reaches the particle's stress or velocity in the same pass), and
// the diagnosis then reports where the particles went bad.
void move_particles(Particles& P, std::size_t p, int n, const Gathered& g, double dt,
                    const Axis& ax, const MoveLimits& lim, bool& drifted, double& fastest) {
  double* __restrict x = P.x.data() + p;
  double* __restrict y = P.y.data() + p;
  alignas(64) double col[kBatch];
  double fast = fastest;
  if (ax.graded()) {
    for (int k = 0; k < n; ++k) {
      const double dx = dt * g.mv_x[k], dy = dt * g.mv_y[k];
      const bool finite = std::fabs(dx + dy) <= DBL_MAX;
      x[k] += finite ? dx : 0.0;
      y[k] += finite ? dy : 0.0;
      col[k] = std::isfinite(x[k]) ? double(ax.cell_of(x[k])) : lim.col_lo;
    }
  } else {
    const double inv_h = 1.0 / ax.h, origin = ax.origin;
#pragma omp simd
    for (int k = 0; k < n; ++k) {
      const double dx = dt * g.mv_x[k], dy = dt * g.mv_y[k];
      const bool finite = std::fabs(dx + dy) <= DBL_MAX;
      x[k] += finite ? dx : 0.0;
      y[k] += finite ? dy : 0.0;
      // floor for the particles inside the grid (u > 0); a non-finite or outside one is
      // diagnosed by the caller, so its column is only kept inside the tolerance here.
      const double u = (x[k] - origin) * inv_h;
      col[k] = ((std::fabs(u) <= DBL_MAX) & (u > 0.0)) ? std::floor(u) : lim.col_lo;
    }
  }
  // Non-short-circuit tests and an int or-reduction: with && and a bool || reduction GCC 12
  // left both loops scalar (docs/performance.md, "Choices in the code").
  int out = 0;
#pragma omp simd reduction(max : fast) reduction(| : out)
  for (int k = 0; k < n; ++k) {
    const bool finite = std::fabs(x[k] + y[k]) <= DBL_MAX;
    out |= int(finite & ((col[k] < lim.col_lo) | (col[k] > lim.col_hi)));
    const double speed = std::fabs(g.mv_x[k]) + std::fabs(g.mv_y[k]);
    fast = std::max(fast, speed <= DBL_MAX ? speed : 0.0);  // a non-finite one did not move
  }
  drifted = drifted || out != 0;
  fastest = fast;
}

// The first of particles [p, p + n) that is non-finite or outside the limits; kNone if none.
// kVelocity = false: the velocity is not read (the MUSL pass, where it was updated before the
// re-map: a non-finite particle velocity makes the re-mapped momentum of all nine of its nodes
// non-finite, m S v with S = 0 included, hence its velocity gradient and stress in this pass,
// which are checked: tests/test_solver). Saves reading two arrays.
template <bool kVelocity>
std::size_t first_bad(const Particles& P, std::size_t p, int n, const MoveLimits& lim) {
  const double* __restrict x = P.x.data() + p;
  const double* __restrict y = P.y.data() + p;
  const double* __restrict vx = P.vx.data() + p;
  const double* __restrict vy = P.vy.data() + p;
  const double* __restrict sxx = P.sxx.data() + p;
  const double* __restrict syy = P.syy.data() + p;
  const double* __restrict sxy = P.sxy.data() + p;
  // An int or-reduction with non-short-circuit tests: GCC 12 leaves a bool || reduction
  // scalar (docs/performance.md, "Choices in the code").
  int any = 0;
#pragma omp simd reduction(| : any)
  for (int k = 0; k < n; ++k) {
    const double v = kVelocity ? vx[k] + vy[k] : 0.0;
    const bool finite = std::fabs(v + sxx[k] + syy[k] + sxy[k]) <= DBL_MAX;
    const bool inside = (x[k] > lim.xlo) & (x[k] < lim.xhi) & (y[k] > lim.ylo) & (y[k] < lim.yhi);
    any |= int(!(finite & inside));
  }
  if (!any) return kNone;
  for (int k = 0; k < n; ++k) {
    const bool finite = std::isfinite(vx[k] + vy[k] + sxx[k] + syy[k] + sxy[k]);
    const bool inside = x[k] > lim.xlo && x[k] < lim.xhi && y[k] > lim.ylo && y[k] < lim.yhi;
    if (!finite || !inside) return p + std::size_t(k);
  }
  return kNone;
}

// What one strip's pass leaves for its State's totals, reduced in strip order after the loop
// (so the totals do not depend on the number of threads or on which thread took the strip).
struct StripResult {
  double work = 0.0;     // E14's stress work of the strip's particles, J
  double viscous = 0.0;  // the Kelvin-Voigt stresses' work (dissipated), J
  double fastest = 0.0;  // the largest |v_x| + |v_y| a particle moved with, m/s
  std::size_t bad = kNone;  // the first non-finite particle or one outside the grid
  bool drifted = false;     // a particle left the strip's drift tolerance
};

// The bounds every particle of s must keep: inside the grid with its whole 3-node stencil (the
// stencil starts at the cell of x - lp, so on the high side the particle stays out of the last
// cell, where the stencil would reach node cells + 1; on the low side lp <= half a cell
// suffices).
struct GridLimits {
  double xlo, xhi, ylo, yhi;  // m
};
GridLimits grid_limits(const State& s) {
  const Axis& ax = s.grid.x;
  const Axis& ay = s.grid.y;
  return {ax.node(0) + 0.5 * ax.width(0), ax.node(ax.cells - 1), ay.node(0) + 0.5 * ay.width(0),
          ay.node(ay.cells - 1)};
}

// One strip of s (theory E5 for its particles), in batches of kBatch. One specialization per
// G2PMode, so the loops carry no mode tests.
template <G2PMode kMode>
StripResult strip_to_particles(State& s, int strip, const double* gvx, const double* gvy) {
  Particles& P = s.particles;
  const GridFields& G = s.fields;
  const double dt = s.dt, flip = s.flip;
  using GT = GatherTile<kMode>;  // which updates the pass makes: the lanes it gathers
  constexpr bool do_velocity = GT::kDv, do_stress = GT::kStress, do_move = GT::kVel;
  const GridLimits gl = grid_limits(s);
  const int width = s.plan.strip_cells;
  // Drift tolerance of the scatter plan: one cell column either side of the strip.
  const MoveLimits lim{gl.xlo, gl.xhi, gl.ylo, gl.yhi, double(strip * width - 1),
                       double(strip * width + width)};
  const std::size_t begin = s.plan.strip_begin[std::size_t(strip)];
  const std::size_t end = s.plan.strip_begin[std::size_t(strip) + 1];
  StripResult r;
  if (begin == end) return r;
  thread_local TileLayout T;
  thread_local std::vector<typename GT::Lane> buffer;
  tile_layout(s, strip, begin, end, T);
  typename GT::Lane* tile = tile_buffer(buffer, T.size(), false);
  const double* lanes[6] = {};
  GT::sources(gvx, gvy, G, lanes);
  for_each_tile_row(s, T, [&](std::size_t t, std::size_t e, int count) {
    pack_tile_row<GT::kLanes>(tile + t, count, lanes, e);
  });
  StencilBatch2 B;
  Gathered g;
  RunNodes<typename GT::Lane> run;
  for (std::size_t p0 = begin; p0 < end; p0 += kBatch) {
    const int n = int(std::min<std::size_t>(kBatch, end - p0));
    if constexpr (kMode != G2PMode::stress_and_move)
      for (const std::vector<double>* a : {&P.vx, &P.vy}) prefetch_batch(a->data(), p0);
    for (const std::vector<double>* a : {&P.sxx, &P.syy, &P.sxy, &P.volume0})
      prefetch_batch(a->data(), p0);
    prefetch_batch(P.material.data(), p0);
    batch_stencils(s, p0, n, B);
    gather_nodes<kMode>(B, n, tile, T, P.field.data() + p0, g, run);
    if constexpr (do_velocity) {
      double* __restrict vx = P.vx.data() + p0;
      double* __restrict vy = P.vy.data() + p0;
#pragma omp simd
      for (int k = 0; k < n; ++k) {
        vx[k] = flip * (vx[k] + g.dv_x[k]) + (1.0 - flip) * g.pic_x[k];
        vy[k] = flip * (vy[k] + g.dv_y[k]) + (1.0 - flip) * g.pic_y[k];
      }
    }
    if constexpr (do_stress) update_stress(P, p0, n, g, s.stiffness, dt, r.work, r.viscous);
    if constexpr (do_move) move_particles(P, p0, n, g, dt, s.grid.x, lim, r.drifted, r.fastest);
    const std::size_t b = first_bad<kMode != G2PMode::stress_and_move>(P, p0, n, lim);
    if (b != kNone) r.bad = std::min(r.bad, b);
  }
  return r;
}

using StripPass = StripResult (*)(State&, int, const double*, const double*);
StripPass strip_pass(G2PMode mode) {
  switch (mode) {
    case G2PMode::stress_and_move: return strip_to_particles<G2PMode::stress_and_move>;
    case G2PMode::stress_velocity_and_move: return strip_to_particles<G2PMode::stress_velocity_and_move>;
    case G2PMode::stress_only: return strip_to_particles<G2PMode::stress_only>;
    case G2PMode::velocity_and_move: return strip_to_particles<G2PMode::velocity_and_move>;
  }
  return nullptr;
}

// Every strip of every State in one parallel region (nested levels: a thread moves on to the
// next level's strips instead of waiting at the end of each level's), then each State's
// totals from its strips' results in strip order. The velocity read is (s.fields.*gx,
// s.fields.*gy) of each State.
void states_to_particles(State* const* states, std::size_t count, NodalArray gx, NodalArray gy,
                         G2PMode mode) {
  const StripPass pass = strip_pass(mode);
  thread_local std::vector<std::size_t> first_task;  // the calling thread's: reached by pointer
  thread_local std::vector<StripResult> results;
  first_task.assign(count + 1, 0);
  for (std::size_t l = 0; l < count; ++l)
    first_task[l + 1] = first_task[l] + std::size_t(states[l]->plan.num_strips);
  results.assign(first_task[count], StripResult{});
  const std::size_t* const first = first_task.data();
  StripResult* const out = results.data();
  const long tasks = long(first_task[count]);
#pragma omp parallel for schedule(dynamic, 1)
  for (long t = 0; t < tasks; ++t) {
    const std::size_t l = std::size_t(std::upper_bound(first, first + count + 1, std::size_t(t)) - first) - 1;
    State& s = *states[l];
    out[t] = pass(s, int(std::size_t(t) - first[l]), (s.fields.*gx).data(), (s.fields.*gy).data());
  }
  const bool stress = mode != G2PMode::velocity_and_move, move = mode != G2PMode::stress_only;
  for (std::size_t l = 0; l < count; ++l) {
    State& s = *states[l];
    std::size_t bad = kNone;
    bool drifted = false;
    double fastest = 0.0;
    for (std::size_t t = first[l]; t < first[l + 1]; ++t) {
      if (stress) s.strain_work += out[t].work, s.viscous_work += out[t].viscous;
      bad = std::min(bad, out[t].bad);
      drifted = drifted || out[t].drifted;
      fastest = std::max(fastest, out[t].fastest);
    }
    if (drifted) s.plan.valid = false;
    // |dx| + |dy| >= the distance moved (solver/field_windows: a bound on how far any particle
    // has gone since its window was measured).
    if (move) {
      s.last_move = s.dt * fastest;
      s.window_drift += s.last_move;
      s.plan.drift += s.dt * fastest;
    }
    if (bad != kNone) {
      const GridLimits gl = grid_limits(s);
      throw SimulationError(diagnose_bad_particles(s, gl.xlo, gl.xhi, gl.ylo, gl.yhi));
    }
  }
}

}  // namespace

void grid_to_particles(State& s, NodalArray gx, NodalArray gy, G2PMode mode) {
  State* one = &s;
  states_to_particles(&one, 1, gx, gy, mode);
}

void grid_to_particles(State* const* states, std::size_t count, NodalArray gx, NodalArray gy,
                       G2PMode mode) {
  states_to_particles(states, count, gx, gy, mode);
}

}  // namespace rupture
