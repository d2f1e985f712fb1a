// rupture/solver/transfer.cpp
// Particle -> grid transfers of the time step (theory E4) and the MUSL re-map, through the
// two-colour strip plan of ScatterPlan. The grid -> particle gather (E5) is solver/gather.cpp.
// Stencils: solver/stencil_batch.hpp.
#include "solver/transfer.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <type_traits>

#include "solver/stencil_batch.hpp"
#include "solver/strip_tile.hpp"

namespace rupture {
using namespace detail;
namespace {


// -V sigma of particles [p0, p0 + n) (the internal force's factor, theory E4), SIMD over the
// batch: the current area V = V0 (1 + tr eps) with tr eps from the stress
// (material/elastic.hpp: strain_trace), m^2 Pa.
struct BatchForce {
  alignas(64) double xx[kBatch], yy[kBatch], xy[kBatch];
};
inline void batch_force(const Particles& P, const ElasticStiffness* stiffness, bool one_material,
                        std::size_t p0, int n, BatchForce& f) {
  alignas(64) double kt[kBatch], vol[kBatch];
  const std::uint8_t* mat = P.material.data() + p0;
  for (int k = 0; k < n; ++k) kt[k] = stiffness[one_material ? 0 : mat[k]].tr_per_stress;
  const double* __restrict sxx = P.sxx.data() + p0;
  const double* __restrict syy = P.syy.data() + p0;
  const double* __restrict sxy = P.sxy.data() + p0;
  const double* __restrict vol0 = P.volume0.data() + p0;
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    const double V = vol0[k] * (1.0 + (sxx[k] + syy[k]) * kt[k]);
    vol[k] = V;
    f.xx[k] = -V * sxx[k], f.yy[k] = -V * syy[k], f.xy[k] = -V * sxy[k];
  }
  if (!P.viscous_on) return;
  // Kelvin-Voigt: the viscous stress of the last update joins the elastic one (the explicit
  // central-difference form, docs/theory.md §16).
  const double* __restrict vxx = P.vsxx.data() + p0;
  const double* __restrict vyy = P.vsyy.data() + p0;
  const double* __restrict vxy = P.vsxy.data() + p0;
#pragma omp simd
  for (int k = 0; k < n; ++k) f.xx[k] -= vol[k] * vxx[k], f.yy[k] -= vol[k] * vyy[k], f.xy[k] -= vol[k] * vxy[k];
}

// Adds particle k's contribution to node (a, b) of its stencil, sy_b col_a [+ dsy_b col_y_a],
// to acc (scatter_strip): one fused multiply-add per term into the sum (forming the
// contribution first and adding it took a third more vector operations; measured in
// docs/performance.md, "Choices in the code").
template <bool kWithForce>
inline void add_node_contribution(Lane8& acc, const StencilBatch2& B, int k, int b,
                                  const Lane8& col, const Lane8& col_y) {
  acc += B.w[1][b][k] * col;
  if constexpr (kWithForce) acc += B.dw[1][b][k] * col_y;
}

// One strip of the mass, momentum [and force] scatter (strips of one colour run in parallel).
template <bool kWithForce>
void scatter_strip(State& s, int strip, std::size_t begin, std::size_t end) {
  const Particles& P = s.particles;
  if (begin == end) return;
  thread_local TileLayout T;
  thread_local std::vector<Lane8> buffer;
  tile_layout(s, strip, begin, end, T);
  Lane8* tile = tile_buffer(buffer, T.size(), true);
  const std::size_t cols = std::size_t(T.cols);
  const ElasticStiffness* stiffness = s.stiffness.data();
  const bool one_material = s.stiffness.size() == 1;
  BatchForce f;
  // Particles whose stencils start at the same node are adjacent (sort_particles): a run of
  // them sums its contributions to the nine nodes in registers and adds them to the tile once.
  Lane8 run[9];
  Lane8* run_t0 = nullptr;
  const auto end_run = [&]() {
    if (run_t0 == nullptr) return;
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) run_t0[std::size_t(b) * cols + std::size_t(a)] += run[3 * b + a];
  };
  for_each_in_batches(s, begin, end, [&](std::size_t p, int k, const StencilBatch2& B) {
    const double m = P.mass[p];
    const Lane8 A = {m, m * P.vx[p], m * P.vy[p], 0, 0, 0, 0, 0};
    // theory E4: f_i = -sum_p V_p sigma_p . grad S_ip
    const Lane8 Fx = {0, 0, 0, f.xx[k], f.xy[k], 0, 0, 0};
    const Lane8 Fy = {0, 0, 0, f.xy[k], f.yy[k], 0, 0, 0};
    Lane8* t0 = tile + T.index(P.field[p], B.first[0][k], B.first[1][k]);
    // Node (a, b) takes S A + dS/dx Fx + dS/dy Fy with S = sx_a sy_b, dS/dx = dsx_a sy_b,
    // dS/dy = sx_a dsy_b: the column factors sx_a A + dsx_a Fx and sx_a Fy once per column,
    // then two vector operations per node.
    Lane8 col[3], col_y[3] = {};
    for (int a = 0; a < 3; ++a) {
      col[a] = B.w[0][a][k] * A;
      if constexpr (kWithForce) {
        col[a] += B.dw[0][a][k] * Fx;
        col_y[a] = B.w[0][a][k] * Fy;
      }
    }
    const bool first = t0 != run_t0;
    if (first) {
      end_run();
      run_t0 = t0;
    }
    // (Two loops, not a select per node: the compiler keeps the run in registers then.)
    if (first) {
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) {
          run[3 * b + a] = Lane8{};
          add_node_contribution<kWithForce>(run[3 * b + a], B, k, b, col[a], col_y[a]);
        }
    } else {
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) add_node_contribution<kWithForce>(run[3 * b + a], B, k, b, col[a], col_y[a]);
    }
  }, [&](std::size_t p0) {
    for (const std::vector<double>* a : {&P.mass, &P.vx, &P.vy, &P.volume0, &P.sxx, &P.syy, &P.sxy})
      prefetch_batch(a->data(), p0);
    prefetch_batch(P.material.data(), p0);
    if constexpr (kWithForce) batch_force(P, stiffness, one_material, p0, int(std::min<std::size_t>(kBatch, end - p0)), f);
  });
  end_run();
  // Strips of one colour never share a node: no race.
  GridFields& G = s.fields;
  double* const out[5] = {G.mass.data(), G.mom_x.data(), G.mom_y.data(), G.force_x.data(),
                          G.force_y.data()};
  for_each_tile_row(s, T, [&](std::size_t t, std::size_t e, int count) {
    add_tile_row<kWithForce ? 5 : 3>(tile + t, count, out, e);
  });
}

// Zeroes the arrays, the threads splitting each one (a serial fill leaves the other threads
// waiting; nested levels' whole-lattice fields are several MB per array).
void zero_parallel(std::initializer_list<std::vector<double>*> arrays) {
#pragma omp parallel
  for (std::vector<double>* a : arrays) {
    const long n = long(a->size());
    double* v = a->data();
#pragma omp for schedule(static) nowait
    for (long i = 0; i < n; ++i) v[i] = 0.0;
  }
}

}  // namespace

void particles_to_grid(State& s, bool with_force) {
  State* one = &s;
  particles_to_grid(&one, 1, with_force);
}

void particles_to_grid(State* const* states, std::size_t count, bool with_force) {
  for (std::size_t l = 0; l < count; ++l) {
    GridFields& G = states[l]->fields;
    zero_parallel({&G.mass, &G.mom_x, &G.mom_y, &G.force_x, &G.force_y});
  }
  if (with_force)
    for_each_strip_coloured(states, count, scatter_strip<true>);
  else
    for_each_strip_coloured(states, count, scatter_strip<false>);
}

void particles_to_grid_force(State& s) {
  GridFields& G = s.fields;
  zero_parallel({&G.force_x, &G.force_y});
  const Particles& P = s.particles;
  double* fx = G.force_x.data();
  double* fy = G.force_y.data();
  State* one = &s;
  for_each_strip_coloured(&one, 1, [&](State&, int, std::size_t begin, std::size_t end) {
    BatchForce f;
    for_each_in_batches(s, begin, end, [&](std::size_t p, int k, const StencilBatch2& B) {
      const int field = P.field[p];
      const std::size_t base = G.index(field, B.first[0][k], B.first[1][k]), stride = G.stride(field);
      for (int b = 0; b < 3; ++b) {
        const std::size_t row = base + std::size_t(b) * stride;
        for (int a = 0; a < 3; ++a) {
          const double gx = B.dw[0][a][k] * B.w[1][b][k], gy = B.w[0][a][k] * B.dw[1][b][k];
          fx[row + a] += f.xx[k] * gx + f.xy[k] * gy;
          fy[row + a] += f.xy[k] * gx + f.yy[k] * gy;
        }
      }
    }, [&](std::size_t p0) {
      batch_force(P, s.stiffness.data(), s.stiffness.size() == 1, p0, int(std::min<std::size_t>(kBatch, end - p0)), f);
    });
  });
}

namespace {

// kPureFlip: flip == 1, so the PIC part (the gathered velocity) is not needed and the gather
// tile holds only the velocity increment (two lanes). The scatter tile holds the two momentum
// components. Each lane's sum runs in the same order whatever the lane count.
// One strip of the velocity update and re-map (strips of one colour run in parallel).
template <bool kPureFlip>
void velocity_remap_strip(State& s, int strip, std::size_t begin, std::size_t end) {
  using In = std::conditional_t<kPureFlip, Lane2, Lane4>;
  GridFields& G = s.fields;
  Particles& P = s.particles;
  const double flip = s.flip;
  if (begin == end) return;
  thread_local TileLayout T;
  thread_local std::vector<In> gather_buffer;
  thread_local std::vector<Lane2> scatter_buffer;
  tile_layout(s, strip, begin, end, T);
  In* in = tile_buffer(gather_buffer, T.size(), false);
  Lane2* out = tile_buffer(scatter_buffer, T.size(), true);
  const double* const gathered[4] = {G.dvel_x.data(), G.dvel_y.data(), G.vel_x.data(), G.vel_y.data()};
  for_each_tile_row(s, T, [&](std::size_t t, std::size_t e, int count) {
    pack_tile_row<kPureFlip ? 2 : 4>(in + t, count, gathered, e);
  });
  const std::size_t cols = std::size_t(T.cols);
  // A run of particles sharing a stencil (sort_particles) reads its nine nodes once and sums
  // its re-mapped momentum in registers, added to the tile once.
  std::size_t run_t0 = kNone;
  In node[9] = {};
  Lane2 run[9];
  const auto end_run = [&]() {
    if (run_t0 == kNone) return;
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) out[run_t0 + std::size_t(b) * cols + std::size_t(a)] += run[3 * b + a];
  };
  for_each_in_batches<false>(s, begin, end, [&](std::size_t p, int k, const StencilBatch2& B) {
    const std::size_t t0 = T.index(P.field[p], B.first[0][k], B.first[1][k]);
    const bool first = t0 != run_t0;
    if (first) {
      end_run();
      run_t0 = t0;
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) node[3 * b + a] = in[t0 + std::size_t(b) * cols + std::size_t(a)];
    }
    // sum_b sy_b (sum_a sx_a in(a, b)): a row's sum, then the rows.
    In acc = {};  // dv x, dv y [, v x, v y]
    for (int b = 0; b < 3; ++b) {
      const In* r = node + 3 * b;
      acc += B.w[1][b][k] * (B.w[0][0][k] * r[0] + B.w[0][1][k] * r[1] + B.w[0][2][k] * r[2]);
    }
    // FLIP/PIC blend of the particle velocity update.
    double vx, vy;
    if constexpr (kPureFlip) {
      vx = P.vx[p] + acc[0];
      vy = P.vy[p] + acc[1];
    } else {
      vx = flip * (P.vx[p] + acc[0]) + (1.0 - flip) * acc[2];
      vy = flip * (P.vy[p] + acc[1]) + (1.0 - flip) * acc[3];
    }
    P.vx[p] = vx;
    P.vy[p] = vy;
    const double m = P.mass[p];
    const Lane2 mv = {m * vx, m * vy};
    const Lane2 col[3] = {B.w[0][0][k] * mv, B.w[0][1][k] * mv, B.w[0][2][k] * mv};
    if (first) {
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) run[3 * b + a] = B.w[1][b][k] * col[a];
    } else {
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) run[3 * b + a] += B.w[1][b][k] * col[a];
    }
  }, [&](std::size_t p0) {
    for (const std::vector<double>* a : {&P.mass, &P.vx, &P.vy}) prefetch_batch(a->data(), p0);
  });
  end_run();
  double* const remap[2] = {G.remap_x.data(), G.remap_y.data()};
  for_each_tile_row(s, T, [&](std::size_t t, std::size_t e, int count) {
    add_tile_row<2>(out + t, count, remap, e);
  });
}

}  // namespace

void update_particle_velocity_and_remap(State& s) {
  State* one = &s;
  update_particle_velocity_and_remap(&one, 1);
}

void update_particle_velocity_and_remap(State* const* states, std::size_t count) {
  for (std::size_t l = 0; l < count; ++l) {
    GridFields& G = states[l]->fields;
    zero_parallel({&G.remap_x, &G.remap_y});
  }
  // One FLIP fraction per run (every level's State copies the case's).
  if (count > 0 && states[0]->flip == 1.0)
    for_each_strip_coloured(states, count, velocity_remap_strip<true>);
  else
    for_each_strip_coloured(states, count, velocity_remap_strip<false>);
}

}  // namespace rupture
