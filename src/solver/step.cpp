// rupture/solver/step.cpp
// The time step, phase by phase (SPEC E4-E6). Scatters (particle -> grid) go through the
// two-colour strip plan of ScatterPlan; gathers (grid -> particle) are plain parallel loops.
#include "solver/step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "core/errors.hpp"
#include "solver/cohesive_step.hpp"

namespace rupture {
namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// Stencils of a batch of consecutive particles, computed SIMD over particles (the weights are
// then reused across the batch's node loops). For particle k: weights sx[a][k], sy[b][k] of
// node (first_x + a, first_y + b) and their derivatives; base[k] = field offset + index of
// node (first_x, first_y).
constexpr int kBatch = 16;
struct StencilBatch {
  alignas(64) double sx[3][kBatch];
  alignas(64) double dsx[3][kBatch];
  alignas(64) double sy[3][kBatch];
  alignas(64) double dsy[3][kBatch];
  std::size_t base[kBatch];
};

// One axis for n <= kBatch particles: the stencil rule of grid/grid.hpp (stencil()), with
// the weights of gimp_uniform_node written out over plain arrays so the loop vectorizes.
inline void axis_stencils(const Axis& ax, const double* __restrict xp, const double* __restrict lp,
                          int n, double (&w)[3][kBatch], double (&dw)[3][kBatch],
                          int* __restrict first) {
  const double inv_h = 1.0 / ax.h, origin = ax.origin;
  double* __restrict w0 = w[0];
  double* __restrict w1 = w[1];
  double* __restrict w2 = w[2];
  double* __restrict d0 = dw[0];
  double* __restrict d1 = dw[1];
  double* __restrict d2 = dw[2];
  double fl[kBatch];
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    const double xi = (xp[k] - origin) * inv_h;
    // xi > 0 for every particle (the grid keeps its ghost cells around them: checked after each
    // move), so truncation is floor; unlike std::floor it vectorizes without -ffast-math.
    const double cell = double(int(xi));
    const double f = (xi - cell < 0.5) ? cell - 1.0 : cell;
    fl[k] = f;
    const double u = xi - f, l = lp[k] * inv_h, inv_2l = 0.5 / l;
    gimp_uniform_node(u, l, inv_2l, inv_h, w0[k], d0[k]);
    gimp_uniform_node(u - 1.0, l, inv_2l, inv_h, w1[k], d1[k]);
    gimp_uniform_node(u - 2.0, l, inv_2l, inv_h, w2[k], d2[k]);
  }
  for (int k = 0; k < n; ++k) first[k] = int(fl[k]);
}

inline void batch_stencils(const State& s, std::size_t p0, int n, StencilBatch& B) {
  const Particles& P = s.particles;
  int fx[kBatch], fy[kBatch];
  axis_stencils(s.grid.x, P.x.data() + p0, P.half_x.data() + p0, n, B.sx, B.dsx, fx);
  axis_stencils(s.grid.y, P.y.data() + p0, P.half_y.data() + p0, n, B.sy, B.dsy, fy);
  const std::size_t nx = std::size_t(s.grid.nodes_x()), nn = s.fields.num_nodes;
  for (int k = 0; k < n; ++k)
    B.base[k] = std::size_t(P.field[p0 + std::size_t(k)]) * nn + std::size_t(fy[k]) * nx +
                std::size_t(fx[k]);
}

// Runs body(p, k, B) for particles [begin, end), batch by batch (k: index in the batch B).
template <class Body>
inline void for_each_in_batches(const State& s, std::size_t begin, std::size_t end, Body&& body) {
  StencilBatch B;
  for (std::size_t p0 = begin; p0 < end; p0 += kBatch) {
    const int n = int(std::min<std::size_t>(kBatch, end - p0));
    batch_stencils(s, p0, n, B);
    for (int k = 0; k < n; ++k) body(p0 + std::size_t(k), k, B);
  }
}

// Runs body(strip, begin, end) over the particle range of every strip, strips of one colour
// in parallel (see ScatterPlan).
template <class Body>
void for_each_strip_coloured(const ScatterPlan& plan, Body&& body) {
  for (int colour = 0; colour < 2; ++colour) {
#pragma omp parallel for schedule(dynamic, 1)
    for (int strip = colour; strip < plan.num_strips; strip += 2)
      body(strip, plan.strip_begin[std::size_t(strip)], plan.strip_begin[std::size_t(strip) + 1]);
  }
}

// Velocity-BC time function values at the start and end of the step.
inline double bc_value(const State& s, const NodeBC& e, double t) {
  return s.boundary[std::size_t(e.condition)].velocity(t);
}

// A failure spreads through the grid within one step, so the diagnosis reports every bad
// particle's extent (where it started lies inside) and the worst one, not just the first index.
std::string diagnose_bad_particles(const State& s, double xlo, double xhi, double ylo, double yhi) {
  const Particles& P = s.particles;
  std::size_t nonfinite = 0, outside = 0, first = kNone;
  double bx0 = INFINITY, bx1 = -INFINITY, by0 = INFINITY, by1 = -INFINITY;
  const char* quantity = "velocity";
  for (std::size_t p = 0; p < P.size(); ++p) {
    const bool v_ok = std::isfinite(P.vx[p] + P.vy[p]);
    const bool s_ok = std::isfinite(P.sxx[p] + P.syy[p] + P.sxy[p]);
    const bool in = P.x[p] > xlo && P.x[p] < xhi && P.y[p] > ylo && P.y[p] < yhi;
    if (v_ok && s_ok && in) continue;
    if (first == kNone) first = p;
    if (!v_ok || !s_ok) {
      ++nonfinite;
      if (!s_ok && v_ok) quantity = "stress";
    } else {
      ++outside;
    }
    if (std::isfinite(P.x[p]) && std::isfinite(P.y[p])) {
      bx0 = std::min(bx0, P.x[p]), bx1 = std::max(bx1, P.x[p]);
      by0 = std::min(by0, P.y[p]), by1 = std::max(by1, P.y[p]);
    }
  }
  const std::string where = fmt::format(
      "at step {}, t = {:.6g} s; affected region x in [{:.6g}, {:.6g}], y in [{:.6g}, {:.6g}] m; "
      "first: particle {} (field {}) at (x, y) = ({:.6g}, {:.6g}) m, v = ({:.4g}, {:.4g}) m/s",
      s.step, s.time, bx0, bx1, by0, by1, P.id[first], int(P.field[first]), P.x[first], P.y[first],
      P.vx[first], P.vy[first]);
  if (nonfinite > 0)
    return fmt::format("unstable: non-finite {} in {} particle(s) {}; reduce time.cfl or check the loading",
                       quantity, nonfinite, where);
  return fmt::format(
      "particle left the grid: {} particle(s) {}; the grid with its ghost cells spans x in "
      "[{:.6g}, {:.6g}], y in [{:.6g}, {:.6g}] m",
      outside, where, xlo, xhi, ylo, yhi);
}

}  // namespace

void sort_particles(State& s) {
  ScatterPlan& plan = s.plan;
  Particles& P = s.particles;
  const std::size_t n = P.size();
  const int cx = s.grid.x.cells, cy = s.grid.y.cells, width = plan.strip_cells;
  plan.num_strips = (cx + width - 1) / width;
  const double ox = s.grid.x.origin, oy = s.grid.y.origin;
  const double inv_hx = 1.0 / s.grid.x.h, inv_hy = 1.0 / s.grid.y.h;
  // Bucket (strip, row): strip-major, so every strip is one contiguous particle range.
  auto bucket_of = [&](std::size_t p) {
    const int col = std::clamp(int(std::floor((P.x[p] - ox) * inv_hx)), 0, cx - 1);
    const int row = std::clamp(int(std::floor((P.y[p] - oy) * inv_hy)), 0, cy - 1);
    return std::size_t(col / width) * std::size_t(cy) + std::size_t(row);
  };
  const std::size_t buckets = std::size_t(plan.num_strips) * std::size_t(cy);
  plan.bucket.assign(buckets + 1, 0);
  for (std::size_t p = 0; p < n; ++p) ++plan.bucket[bucket_of(p) + 1];
  for (std::size_t k = 0; k < buckets; ++k) plan.bucket[k + 1] += plan.bucket[k];
  plan.strip_begin.resize(std::size_t(plan.num_strips) + 1);
  for (int k = 0; k <= plan.num_strips; ++k)
    plan.strip_begin[std::size_t(k)] = plan.bucket[std::size_t(k) * std::size_t(cy)];
  // Stable counting sort: particles keep their previous relative order inside a bucket.
  plan.order.resize(n);
  for (std::size_t p = 0; p < n; ++p) plan.order[plan.bucket[bucket_of(p)]++] = std::uint32_t(p);
  P.permute(plan.order, plan.scratch);
  plan.valid = true;
  plan.sorted_step = s.step;
}

void build_scatter_plan(State& s) {
  const ScatterPlan& plan = s.plan;
  if (!plan.valid || s.step - plan.sorted_step >= plan.sort_interval) sort_particles(s);
}

namespace {

// The P2G scatter of one strip goes first into a small node-major tile (one 8-lane vector per
// node: mass, momentum x/y, force x/y), so each particle-node pair is three vector FMAs instead
// of five scalar read-modify-writes on five arrays; the tile is then added to the grid arrays.
// The tile spans the strip's node columns (with the one-column drift tolerance) and, per
// field, the node rows its particles touch.
using Lane8 = double __attribute__((vector_size(64)));

struct StripTile {
  int col0 = 0, cols = 0;          // first node column, number of columns
  std::vector<int> row0, rows;     // per field: first node row, number of rows (0: absent)
  std::vector<std::size_t> start;  // per field: offset of its first node in `nodes`
  std::vector<Lane8> nodes;
};

template <bool kWithForce>
void scatter_mass_momentum_force(State& s) {
  GridFields& G = s.fields;
  const Particles& P = s.particles;
  const int nxi = s.grid.nodes_x(), nyi = s.grid.nodes_y();
  const std::size_t nx = std::size_t(nxi);
  const int width = s.plan.strip_cells, fields = G.num_fields;
  const double oy = s.grid.y.origin, inv_hy = 1.0 / s.grid.y.h;
  for_each_strip_coloured(s.plan, [&](int strip, std::size_t begin, std::size_t end) {
    if (begin == end) return;
    thread_local StripTile T;
    T.col0 = strip * width - 2;
    T.cols = width + 5;
    // Node rows per field: a particle in cell row r touches node rows r-1 .. r+2.
    T.row0.assign(std::size_t(fields), std::numeric_limits<int>::max());
    std::vector<int>& last = T.rows;
    last.assign(std::size_t(fields), std::numeric_limits<int>::min());
    for (std::size_t p = begin; p < end; ++p) {
      const int r = int(std::floor((P.y[p] - oy) * inv_hy));
      const std::size_t f = P.field[p];
      T.row0[f] = std::min(T.row0[f], r - 1);
      last[f] = std::max(last[f], r + 2);
    }
    T.start.assign(std::size_t(fields) + 1, 0);
    for (std::size_t f = 0; f < std::size_t(fields); ++f) {
      const int rows = last[f] >= T.row0[f] ? last[f] - T.row0[f] + 1 : 0;
      last[f] = rows;  // `rows` from here on
      T.start[f + 1] = T.start[f] + std::size_t(rows) * std::size_t(T.cols);
    }
    if (T.nodes.size() < T.start.back()) T.nodes.resize(T.start.back());
    std::fill(T.nodes.begin(), T.nodes.begin() + std::ptrdiff_t(T.start.back()), Lane8{});
    Lane8* tile = T.nodes.data();
    const std::size_t cols = std::size_t(T.cols);
    for_each_in_batches(s, begin, end, [&](std::size_t p, int k, const StencilBatch& B) {
      const double m = P.mass[p], V = P.volume[p];
      const Lane8 A = {m, m * P.vx[p], m * P.vy[p], 0, 0, 0, 0, 0};
      const double vsxx = V * P.sxx[p], vsyy = V * P.syy[p], vsxy = V * P.sxy[p];
      // SPEC E4: f_i = -sum_p V_p sigma_p . grad S_ip
      const Lane8 Fx = {0, 0, 0, -vsxx, -vsxy, 0, 0, 0};
      const Lane8 Fy = {0, 0, 0, -vsxy, -vsyy, 0, 0, 0};
      // Tile position of the particle's first node, recovered from its grid base index.
      const std::size_t f = P.field[p];
      const std::size_t local = B.base[k] - G.offset(int(f));
      const int gx0 = int(local % nx), gy0 = int(local / nx);
      Lane8* t0 = tile + T.start[f] + std::size_t(gy0 - T.row0[f]) * cols + std::size_t(gx0 - T.col0);
      for (int b = 0; b < 3; ++b) {
        Lane8* t = t0 + std::size_t(b) * cols;
        const double wy = B.sy[b][k], gy_b = B.dsy[b][k];
        for (int a = 0; a < 3; ++a) {
          const double w = B.sx[a][k] * wy;
          if constexpr (kWithForce) {
            t[a] += w * A + (B.dsx[a][k] * wy) * Fx + (B.sx[a][k] * gy_b) * Fy;
          } else {
            t[a] += w * A;
          }
        }
      }
    });
    // Add the tile to the grid (strips of one colour never share a node: no race).
    for (std::size_t f = 0; f < std::size_t(fields); ++f) {
      const int rows = last[f];
      for (int r = 0; r < rows; ++r) {
        const int gy = T.row0[f] + r;
        if (gy < 0 || gy >= nyi) continue;
        const Lane8* t = tile + T.start[f] + std::size_t(r) * cols;
        const std::size_t row = G.offset(int(f)) + std::size_t(gy) * nx;
        for (int c = 0; c < T.cols; ++c) {
          const int gx = T.col0 + c;
          if (gx < 0 || gx >= nxi) continue;
          const std::size_t n = row + std::size_t(gx);
          const Lane8 v = t[c];
          G.mass[n] += v[0];
          G.mom_x[n] += v[1];
          G.mom_y[n] += v[2];
          if constexpr (kWithForce) {
            G.force_x[n] += v[3];
            G.force_y[n] += v[4];
          }
        }
      }
    }
  });
}

}  // namespace

void particles_to_grid(State& s, bool with_force) {
  GridFields& G = s.fields;
  std::fill(G.mass.begin(), G.mass.end(), 0.0);
  std::fill(G.mom_x.begin(), G.mom_x.end(), 0.0);
  std::fill(G.mom_y.begin(), G.mom_y.end(), 0.0);
  std::fill(G.force_x.begin(), G.force_x.end(), 0.0);
  std::fill(G.force_y.begin(), G.force_y.end(), 0.0);
  if (with_force)
    scatter_mass_momentum_force<true>(s);
  else
    scatter_mass_momentum_force<false>(s);
}

void particles_to_grid_force(State& s) {
  GridFields& G = s.fields;
  std::fill(G.force_x.begin(), G.force_x.end(), 0.0);
  std::fill(G.force_y.begin(), G.force_y.end(), 0.0);
  const Particles& P = s.particles;
  const std::size_t nx = std::size_t(s.grid.nodes_x());
  double* fx = G.force_x.data();
  double* fy = G.force_y.data();
  for_each_strip_coloured(s.plan, [&](int, std::size_t begin, std::size_t end) {
    for_each_in_batches(s, begin, end, [&](std::size_t p, int k, const StencilBatch& B) {
      const double V = P.volume[p], sxx = P.sxx[p], syy = P.syy[p], sxy = P.sxy[p];
      for (int b = 0; b < 3; ++b) {
        const std::size_t row = B.base[k] + std::size_t(b) * nx;
        for (int a = 0; a < 3; ++a) {
          const double gx = B.dsx[a][k] * B.sy[b][k], gy = B.sx[a][k] * B.dsy[b][k];
          fx[row + a] -= V * (sxx * gx + sxy * gy);
          fy[row + a] -= V * (sxy * gx + syy * gy);
        }
      }
    });
  });
}

void grid_velocity_from_momentum(State& s, double t) {
  GridFields& G = s.fields;
  const long n = long(G.mass.size());
  const double floor = s.mass_floor;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const double m = G.mass[i];
    G.remap_x[i] = m > floor ? G.mom_x[i] / m : 0.0;
    G.remap_y[i] = m > floor ? G.mom_y[i] / m : 0.0;
  }
  for (const NodeBC& e : s.bc_nodes) {
    const std::size_t i = G.offset(e.field) + e.node;
    (e.component == 0 ? G.remap_x : G.remap_y)[i] = bc_value(s, e, t);
  }
}

void integrate_grid(State& s) {
  GridFields& G = s.fields;
  const long n = long(G.mass.size());
  const double dt = s.dt, floor = s.mass_floor;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const double m = G.mass[i];
    if (m > floor) {
      // Nodal momentum update p^{n+1} = p^n + dt f (E4), stored as velocity and increment.
      const double inv_m = 1.0 / m;
      G.dvel_x[i] = dt * G.force_x[i] * inv_m;
      G.dvel_y[i] = dt * G.force_y[i] * inv_m;
      G.vel_x[i] = G.mom_x[i] * inv_m + G.dvel_x[i];
      G.vel_y[i] = G.mom_y[i] * inv_m + G.dvel_y[i];
    } else {
      G.dvel_x[i] = G.dvel_y[i] = G.vel_x[i] = G.vel_y[i] = 0.0;
    }
  }
  apply_velocity_bcs(s);
}

void apply_velocity_bcs(State& s) {
  GridFields& G = s.fields;
  const double t0 = s.time, t1 = s.time + s.dt;
  for (const NodeBC& e : s.bc_nodes) {
    const std::size_t i = G.offset(e.field) + e.node;
    const double m = G.mass[i];
    if (m <= s.mass_floor) continue;
    const double v0 = bc_value(s, e, t0), v1 = bc_value(s, e, t1);
    double& vel = (e.component == 0 ? G.vel_x : G.vel_y)[i];
    double& dvel = (e.component == 0 ? G.dvel_x : G.dvel_y)[i];
    // The constraint's impulse m (V^{n+1} - v_free) acts on a node moving at the mean
    // prescribed velocity over the step: its work is the external work of SPEC E14.
    s.external_work += m * (v1 - vel) * 0.5 * (v0 + v1);
    dvel += v1 - vel;
    vel = v1;
  }
}

namespace {

// kPureFlip: flip == 1, so the PIC part (the gathered velocity) is not needed.
template <bool kPureFlip>
void velocity_update_and_remap(State& s) {
  GridFields& G = s.fields;
  Particles& P = s.particles;
  const std::size_t nx = std::size_t(s.grid.nodes_x());
  const double flip = s.flip;
  const double* vel_x = G.vel_x.data();
  const double* vel_y = G.vel_y.data();
  const double* dvel_x = G.dvel_x.data();
  const double* dvel_y = G.dvel_y.data();
  double* rx = G.remap_x.data();
  double* ry = G.remap_y.data();
  for_each_strip_coloured(s.plan, [&](int, std::size_t begin, std::size_t end) {
    for_each_in_batches(s, begin, end, [&](std::size_t p, int k, const StencilBatch& B) {
      double pic_x = 0, pic_y = 0, dvx = 0, dvy = 0;
      for (int b = 0; b < 3; ++b) {
        const std::size_t row = B.base[k] + std::size_t(b) * nx;
        for (int a = 0; a < 3; ++a) {
          const double w = B.sx[a][k] * B.sy[b][k];
          if constexpr (!kPureFlip) {
            pic_x += w * vel_x[row + a];
            pic_y += w * vel_y[row + a];
          }
          dvx += w * dvel_x[row + a];
          dvy += w * dvel_y[row + a];
        }
      }
      // FLIP/PIC blend of the particle velocity update.
      double vx, vy;
      if constexpr (kPureFlip) {
        vx = P.vx[p] + dvx;
        vy = P.vy[p] + dvy;
      } else {
        vx = flip * (P.vx[p] + dvx) + (1.0 - flip) * pic_x;
        vy = flip * (P.vy[p] + dvy) + (1.0 - flip) * pic_y;
      }
      P.vx[p] = vx;
      P.vy[p] = vy;
      const double m = P.mass[p], mvx = m * vx, mvy = m * vy;
      for (int b = 0; b < 3; ++b) {
        const std::size_t row = B.base[k] + std::size_t(b) * nx;
        for (int a = 0; a < 3; ++a) {
          const double w = B.sx[a][k] * B.sy[b][k];
          rx[row + a] += w * mvx;
          ry[row + a] += w * mvy;
        }
      }
    });
  });
}

}  // namespace

void update_particle_velocity_and_remap(State& s) {
  GridFields& G = s.fields;
  std::fill(G.remap_x.begin(), G.remap_x.end(), 0.0);
  std::fill(G.remap_y.begin(), G.remap_y.end(), 0.0);
  if (s.flip == 1.0)
    velocity_update_and_remap<true>(s);
  else
    velocity_update_and_remap<false>(s);
}

void remapped_grid_velocity(State& s) {
  GridFields& G = s.fields;
  const long n = long(G.mass.size());
  const double floor = s.mass_floor;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const double m = G.mass[i];
    G.remap_x[i] = m > floor ? G.remap_x[i] / m : 0.0;
    G.remap_y[i] = m > floor ? G.remap_y[i] / m : 0.0;
  }
  const double t1 = s.time + s.dt;
  for (const NodeBC& e : s.bc_nodes) {
    const std::size_t i = G.offset(e.field) + e.node;
    if (G.mass[i] <= floor) continue;
    (e.component == 0 ? G.remap_x : G.remap_y)[i] = bc_value(s, e, t1);
  }
}

namespace {

// One specialization per G2PMode, so the node loop carries no mode tests.
template <G2PMode kMode>
void grid_to_particles_impl(State& s, const double* gvx, const double* gvy) {
  Particles& P = s.particles;
  const GridFields& G = s.fields;
  const std::size_t nx = std::size_t(s.grid.nodes_x());
  const double dt = s.dt, flip = s.flip;
  constexpr bool do_velocity =
      kMode == G2PMode::stress_velocity_and_move || kMode == G2PMode::velocity_and_move;
  constexpr bool do_stress = kMode != G2PMode::velocity_and_move;
  constexpr bool do_move = kMode != G2PMode::stress_only;
  // Particles must keep their whole 3-node stencil inside the grid.
  const double xlo = s.grid.x.node(0) + 0.5 * s.grid.x.h;
  const double xhi = s.grid.x.node(s.grid.x.cells) - 0.5 * s.grid.x.h;
  const double ylo = s.grid.y.node(0) + 0.5 * s.grid.y.h;
  const double yhi = s.grid.y.node(s.grid.y.cells) - 0.5 * s.grid.y.h;
  const double ox = s.grid.x.origin, inv_hx = 1.0 / s.grid.x.h;
  const ScatterPlan& plan = s.plan;
  const int width = plan.strip_cells;
  std::size_t bad = kNone;
  bool drifted = false;
#pragma omp parallel for schedule(dynamic, 1) reduction(min : bad) reduction(|| : drifted)
  for (int strip = 0; strip < plan.num_strips; ++strip) {
    // Drift tolerance of the scatter plan: one cell column either side of the strip.
    const double col_lo = double(strip * width - 1), col_hi = double(strip * width + width);
    const std::size_t end = plan.strip_begin[std::size_t(strip) + 1];
    for_each_in_batches(s, plan.strip_begin[std::size_t(strip)], end, [&](std::size_t p, int k,
                                                                          const StencilBatch& B) {
      double L00 = 0, L01 = 0, L10 = 0, L11 = 0;  // velocity gradient L_ij = dv_i/dx_j
      double pic_x = 0, pic_y = 0, dvx = 0, dvy = 0, mvx = 0, mvy = 0;
      for (int b = 0; b < 3; ++b) {
        const std::size_t row = B.base[k] + std::size_t(b) * nx;
        for (int a = 0; a < 3; ++a) {
          const std::size_t i = row + std::size_t(a);
          const double w = B.sx[a][k] * B.sy[b][k];
          if constexpr (do_stress) {
            const double gx = B.dsx[a][k] * B.sy[b][k], gy = B.sx[a][k] * B.dsy[b][k];
            L00 += gvx[i] * gx;
            L01 += gvx[i] * gy;
            L10 += gvy[i] * gx;
            L11 += gvy[i] * gy;
          }
          if constexpr (do_velocity) {
            pic_x += w * G.vel_x[i];
            pic_y += w * G.vel_y[i];
            dvx += w * G.dvel_x[i];
            dvy += w * G.dvel_y[i];
          }
          if constexpr (do_move) {
            mvx += w * G.vel_x[i];
            mvy += w * G.vel_y[i];
          }
        }
      }
      if constexpr (do_velocity) {
        P.vx[p] = flip * (P.vx[p] + dvx) + (1.0 - flip) * pic_x;
        P.vy[p] = flip * (P.vy[p] + dvy) + (1.0 - flip) * pic_y;
      }
      if constexpr (do_stress) {
        // SPEC E5: eps_dot = sym(L), sigma_dot = C : eps_dot (small strain, plane mode in C).
        const ElasticStiffness& C = s.stiffness[P.material[p]];
        const double dexx = L00 * dt, deyy = L11 * dt, dexy = 0.5 * (L01 + L10) * dt;
        P.exx[p] += dexx;
        P.eyy[p] += deyy;
        P.exy[p] += dexy;
        P.sxx[p] += C.c11 * dexx + C.c12 * deyy;
        P.syy[p] += C.c12 * dexx + C.c11 * deyy;
        P.sxy[p] += 2.0 * C.mu * dexy;
        P.szz[p] += C.cz * (dexx + deyy);
        P.volume[p] = P.volume0[p] * (1.0 + P.exx[p] + P.eyy[p]);
      }
      if constexpr (do_move) {
        P.x[p] += dt * mvx;
        P.y[p] += dt * mvy;
        const double col = std::floor((P.x[p] - ox) * inv_hx);
        if (col < col_lo || col > col_hi) drifted = true;
      }
      const bool finite = std::isfinite(P.vx[p] + P.vy[p] + P.sxx[p] + P.syy[p] + P.sxy[p]);
      const bool inside = P.x[p] > xlo && P.x[p] < xhi && P.y[p] > ylo && P.y[p] < yhi;
      if (!finite || !inside) bad = std::min(bad, p);
    });
  }
  if (drifted) s.plan.valid = false;
  if (bad != kNone) throw SimulationError(diagnose_bad_particles(s, xlo, xhi, ylo, yhi));
}

}  // namespace

void grid_to_particles(State& s, const double* gvx, const double* gvy, G2PMode mode) {
  switch (mode) {
    case G2PMode::stress_and_move:
      return grid_to_particles_impl<G2PMode::stress_and_move>(s, gvx, gvy);
    case G2PMode::stress_velocity_and_move:
      return grid_to_particles_impl<G2PMode::stress_velocity_and_move>(s, gvx, gvy);
    case G2PMode::stress_only:
      return grid_to_particles_impl<G2PMode::stress_only>(s, gvx, gvy);
    case G2PMode::velocity_and_move:
      return grid_to_particles_impl<G2PMode::velocity_and_move>(s, gvx, gvy);
  }
}

namespace {
// Wall time of the cohesive phases (forces, ties, interface advance), for the run record.
class CohesiveTimer {
 public:
  explicit CohesiveTimer(State& s) : s_(s), t0_(std::chrono::steady_clock::now()) {}
  ~CohesiveTimer() {
    s_.cohesive_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }
  CohesiveTimer(const CohesiveTimer&) = delete;
  CohesiveTimer& operator=(const CohesiveTimer&) = delete;

 private:
  State& s_;
  std::chrono::steady_clock::time_point t0_;
};

void cohesive_forces_and_ties(State& s) {
  if (s.interfaces.empty()) return;
  CohesiveTimer timer(s);
  add_cohesive_forces(s);  // E7-E9
  tie_bonded_nodes(s, TieWhat::mass_momentum);
  tie_bonded_nodes(s, TieWhat::force);
}
}  // namespace

void step(State& s) {
  build_scatter_plan(s);
  GridFields& G = s.fields;
  switch (s.scheme) {
    case Scheme::MUSL:
      particles_to_grid(s, true);           // E4, per velocity field
      cohesive_forces_and_ties(s);          // E7-E9, bonded stretch
      integrate_grid(s);                    // E4 momentum update + E2 velocity BCs
      update_particle_velocity_and_remap(s);
      if (!s.interfaces.empty()) {
        CohesiveTimer timer(s);
        tie_bonded_nodes(s, TieWhat::remapped_momentum);
      }
      remapped_grid_velocity(s);
      grid_to_particles(s, G.remap_x.data(), G.remap_y.data(), G2PMode::stress_and_move);  // E5
      break;
    case Scheme::USL:
      particles_to_grid(s, true);
      cohesive_forces_and_ties(s);
      integrate_grid(s);
      grid_to_particles(s, G.vel_x.data(), G.vel_y.data(), G2PMode::stress_velocity_and_move);
      break;
    case Scheme::USF:
      particles_to_grid(s, false);
      tie_bonded_nodes(s, TieWhat::mass_momentum);
      grid_velocity_from_momentum(s, s.time);
      grid_to_particles(s, G.remap_x.data(), G.remap_y.data(), G2PMode::stress_only);
      particles_to_grid_force(s);
      add_cohesive_forces(s);
      tie_bonded_nodes(s, TieWhat::force);
      integrate_grid(s);
      grid_to_particles(s, G.vel_x.data(), G.vel_y.data(), G2PMode::velocity_and_move);
      break;
  }
  s.time += s.dt;
  ++s.step;
  if (!s.interfaces.empty()) {
    CohesiveTimer timer(s);
    advance_interfaces(s);  // face nodes follow their fields; jumps and tractions at t^{n+1}
  }
}

}  // namespace rupture
