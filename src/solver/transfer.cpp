// rupture/solver/transfer.cpp
// Particle -> grid transfers of the time step (SPEC E4) and the MUSL re-map, through the
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

namespace rupture {
using namespace detail;
namespace {

// Strip tiles. Each particle loop works on one strip at a time through a small node-major
// tile that holds, per node, the few values the loop needs packed in one vector (Lane4/Lane8):
// a particle-node pair is then one to three vector FMAs instead of several scalar loads or
// read-modify-writes on separate arrays. Gathers pack the tile from the grid arrays first;
// scatters add the tile to the grid arrays after. A tile spans the strip's node columns (with
// the one-column drift tolerance of ScatterPlan) and, per field, the node rows its particles
// touch.
using Lane8 = double __attribute__((vector_size(64)));
using Lane4 = double __attribute__((vector_size(32)));
using Lane2 = double __attribute__((vector_size(16)));

struct TileLayout {
  int col0 = 0, cols = 0;          // first node column, number of columns
  std::vector<int> row0, rows;     // per field: first node row, number of rows (0: absent)
  std::vector<std::size_t> start;  // per field: offset of its first node in the tile
  std::size_t size() const { return start.back(); }
  // Tile index of grid node (gx, gy) of field f: the first node of a particle's 3 x 3 stencil.
  // Debug builds check that the whole stencil lies in the tile; a particle breaking the GIMP
  // contract (grid/grid.hpp) could write outside it.
  std::size_t index(std::size_t f, int gx, int gy) const {
    assert(f < rows.size());
    assert(gy >= row0[f] && gy + 2 < row0[f] + rows[f] && "stencil rows outside the tile");
    assert(gx >= col0 && gx + 2 < col0 + cols && "stencil columns outside the tile");
    const std::size_t t =
        start[f] + std::size_t(gy - row0[f]) * std::size_t(cols) + std::size_t(gx - col0);
    assert(t + 2 * std::size_t(cols) + 2 < size());
    return t;
  }
};

// Tile offsets of each field from T.rows.
void tile_offsets(TileLayout& T) {
  T.start.assign(T.rows.size() + 1, 0);
  for (std::size_t f = 0; f < T.rows.size(); ++f)
    T.start[f + 1] = T.start[f] + std::size_t(T.rows[f]) * std::size_t(T.cols);
}

void tile_columns(const State& s, int strip, TileLayout& T) {
  T.col0 = strip * s.plan.strip_cells - 2;
  T.cols = s.plan.strip_cells + 5;
}

// The strip's tile, its node rows found from its particles.
void tile_layout(const State& s, int strip, std::size_t begin, std::size_t end, TileLayout& T) {
  const Particles& P = s.particles;
  const int fields = s.fields.num_fields;
  const double oy = s.grid.y.origin, inv_hy = 1.0 / s.grid.y.h;
  const bool graded = s.grid.y.graded();
  tile_columns(s, strip, T);
  // Node rows per field: a particle in cell row r touches node rows r-1 .. r+2. The cell row
  // is monotonic in y, so the rows of a field's lowest and highest particles bound them all
  // (one min/max pass per field present, vectorized, instead of a row per particle).
  T.row0.assign(std::size_t(fields), std::numeric_limits<int>::max());
  T.rows.assign(std::size_t(fields), std::numeric_limits<int>::min());  // last row, then count
  const auto row = [&](double y) {
    return graded ? s.grid.y.cell_of(y) : int((y - oy) * inv_hy);  // > 0: trunc = floor
  };
  const double* __restrict y = P.y.data();
  const std::uint8_t* __restrict field = P.field.data();
  // Two fields per pass (two bodies are the common case: one pass over the strip).
  const auto rows_of = [&](std::size_t f, double lo, double hi) {
    if (lo > hi) return;  // no particle of this field in the strip
    T.row0[f] = row(lo) - 1;
    T.rows[f] = row(hi) + 2;
  };
  for (std::size_t f = 0; f < std::size_t(fields); f += 2) {
    double lo0 = INFINITY, hi0 = -INFINITY, lo1 = INFINITY, hi1 = -INFINITY;
    const std::uint8_t f0 = std::uint8_t(f), f1 = std::uint8_t(f + 1);
#pragma omp simd reduction(min : lo0, lo1) reduction(max : hi0, hi1)
    for (std::size_t p = begin; p < end; ++p) {
      lo0 = std::min(lo0, field[p] == f0 ? y[p] : INFINITY);
      hi0 = std::max(hi0, field[p] == f0 ? y[p] : -INFINITY);
      lo1 = std::min(lo1, field[p] == f1 ? y[p] : INFINITY);
      hi1 = std::max(hi1, field[p] == f1 ? y[p] : -INFINITY);
    }
    rows_of(f, lo0, hi0);
    if (f + 1 < std::size_t(fields)) rows_of(f + 1, lo1, hi1);
  }
  for (std::size_t f = 0; f < std::size_t(fields); ++f)
    T.rows[f] = T.rows[f] >= T.row0[f] ? T.rows[f] - T.row0[f] + 1 : 0;
  tile_offsets(T);
}

// The mass scatter keeps each strip's node rows (ScatterPlan::tile_row0) for the velocity
// gather and re-map of the same step: the particles have not moved between them.
void keep_tile_rows_sized(State& s) {
  const std::size_t n = std::size_t(s.plan.num_strips) * std::size_t(s.fields.num_fields);
  s.plan.tile_row0.resize(n);
  s.plan.tile_rows.resize(n);
  s.plan.tile_step = s.step;
}
void keep_tile_rows(ScatterPlan& plan, int strip, const TileLayout& T) {
  const std::size_t k = std::size_t(strip) * T.rows.size();  // strips write disjoint parts
  std::copy(T.row0.begin(), T.row0.end(), plan.tile_row0.begin() + std::ptrdiff_t(k));
  std::copy(T.rows.begin(), T.rows.end(), plan.tile_rows.begin() + std::ptrdiff_t(k));
}
// The strip's tile: the kept node rows when the mass scatter of this step found them.
void tile_layout_kept(const State& s, int strip, std::size_t begin, std::size_t end, TileLayout& T) {
  const ScatterPlan& plan = s.plan;
  if (plan.tile_step != s.step) return tile_layout(s, strip, begin, end, T);
  const std::size_t fields = std::size_t(s.fields.num_fields), k = std::size_t(strip) * fields;
  tile_columns(s, strip, T);
  T.row0.assign(plan.tile_row0.begin() + std::ptrdiff_t(k), plan.tile_row0.begin() + std::ptrdiff_t(k + fields));
  T.rows.assign(plan.tile_rows.begin() + std::ptrdiff_t(k), plan.tile_rows.begin() + std::ptrdiff_t(k + fields));
  tile_offsets(T);
}

// Calls visit(tile_index, element) for every tile node that lies inside its field's window
// (the window lies inside the grid; the particles' nodes lie inside it).
template <class Visit>
void for_each_tile_node(const State& s, const TileLayout& T, Visit&& visit) {
  const GridFields& G = s.fields;
  for (std::size_t f = 0; f < T.rows.size(); ++f) {
    const int fi = int(f);
    const int r_lo = std::max(T.row0[f], G.row0[f]), r_hi = std::min(T.row0[f] + T.rows[f], G.row0[f] + G.rows[f]);
    const int c_lo = std::max(T.col0, G.col0[f]), c_hi = std::min(T.col0 + T.cols, G.col0[f] + G.cols[f]);
    for (int gy = r_lo; gy < r_hi; ++gy) {
      const std::size_t t = T.start[f] + std::size_t(gy - T.row0[f]) * std::size_t(T.cols) +
                            std::size_t(c_lo - T.col0);
      const std::size_t e = G.index(fi, c_lo, gy);
      for (int c = 0; c < c_hi - c_lo; ++c) visit(t + std::size_t(c), e + std::size_t(c));
    }
  }
}

template <class Lane>
Lane* tile_buffer(std::vector<Lane>& buffer, std::size_t size, bool zero) {
  if (buffer.size() < size) buffer.resize(size);
  if (zero) std::fill(buffer.begin(), buffer.begin() + std::ptrdiff_t(size), Lane{});
  return buffer.data();
}

// -V sigma of particles [p0, p0 + n) (the internal force's factor, SPEC E4), SIMD over the
// batch: the current area V = V0 (1 + tr eps) with tr eps from the stress
// (material/elastic.hpp: strain_trace), m^2 Pa.
struct BatchForce {
  alignas(64) double xx[kBatch], yy[kBatch], xy[kBatch];
};
inline void batch_force(const Particles& P, const ElasticStiffness* stiffness, std::size_t p0,
                        int n, BatchForce& f) {
  alignas(64) double kt[kBatch];
  const std::uint8_t* mat = P.material.data() + p0;
  for (int k = 0; k < n; ++k) kt[k] = stiffness[mat[k]].tr_per_stress;
  const double* __restrict sxx = P.sxx.data() + p0;
  const double* __restrict syy = P.syy.data() + p0;
  const double* __restrict sxy = P.sxy.data() + p0;
  const double* __restrict vol0 = P.volume0.data() + p0;
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    const double V = vol0[k] * (1.0 + (sxx[k] + syy[k]) * kt[k]);
    f.xx[k] = -V * sxx[k], f.yy[k] = -V * syy[k], f.xy[k] = -V * sxy[k];
  }
}

// One strip of the mass, momentum [and force] scatter (strips of one colour run in parallel).
template <bool kWithForce>
void scatter_strip(State& s, int strip, std::size_t begin, std::size_t end) {
  GridFields& G = s.fields;
  const Particles& P = s.particles;
  if (begin == end) return;
  thread_local TileLayout T;
  thread_local std::vector<Lane8> buffer;
  tile_layout(s, strip, begin, end, T);
  keep_tile_rows(s.plan, strip, T);
  Lane8* tile = tile_buffer(buffer, T.size(), true);
  const std::size_t cols = std::size_t(T.cols);
  const ElasticStiffness* stiffness = s.stiffness.data();
  BatchForce f;
  for_each_in_batches(s, begin, end, [&](std::size_t p, int k, const StencilBatch& B) {
    const double m = P.mass[p];
    const Lane8 A = {m, m * P.vx[p], m * P.vy[p], 0, 0, 0, 0, 0};
    // SPEC E4: f_i = -sum_p V_p sigma_p . grad S_ip
    const Lane8 Fx = {0, 0, 0, f.xx[k], f.xy[k], 0, 0, 0};
    const Lane8 Fy = {0, 0, 0, f.xy[k], f.yy[k], 0, 0, 0};
    Lane8* t0 = tile + T.index(P.field[p], B.first_x[k], B.first_y[k]);
    // Node (a, b) takes S A + dS/dx Fx + dS/dy Fy with S = sx_a sy_b, dS/dx = dsx_a sy_b,
    // dS/dy = sx_a dsy_b: the column factors sx_a A + dsx_a Fx and sx_a Fy once per column,
    // then two vector operations per node.
    Lane8 col[3], col_y[3];
    for (int a = 0; a < 3; ++a) {
      col[a] = B.sx[a][k] * A;
      if constexpr (kWithForce) {
        col[a] += B.dsx[a][k] * Fx;
        col_y[a] = B.sx[a][k] * Fy;
      }
    }
    for (int b = 0; b < 3; ++b) {
      Lane8* t = t0 + std::size_t(b) * cols;
      const double wy = B.sy[b][k], gy_b = B.dsy[b][k];
      for (int a = 0; a < 3; ++a) {
        if constexpr (kWithForce)
          t[a] += wy * col[a] + gy_b * col_y[a];
        else
          t[a] += wy * col[a];
      }
    }
  }, [&](std::size_t p0) {
    for (const std::vector<double>* a : {&P.mass, &P.vx, &P.vy, &P.volume0, &P.sxx, &P.syy, &P.sxy})
      prefetch_batch(a->data(), p0);
    prefetch_batch(P.material.data(), p0);
    if constexpr (kWithForce) batch_force(P, stiffness, p0, int(std::min<std::size_t>(kBatch, end - p0)), f);
  });
  // Strips of one colour never share a node: no race.
  for_each_tile_node(s, T, [&](std::size_t t, std::size_t n) {
    const Lane8 v = tile[t];
    G.mass[n] += v[0];
    G.mom_x[n] += v[1];
    G.mom_y[n] += v[2];
    if constexpr (kWithForce) {
      G.force_x[n] += v[3];
      G.force_y[n] += v[4];
    }
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
    keep_tile_rows_sized(*states[l]);
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
    for_each_in_batches(s, begin, end, [&](std::size_t, int k, const StencilBatch& B) {
      for (int b = 0; b < 3; ++b) {
        const std::size_t row = B.base[k] + std::size_t(b) * B.stride[k];
        for (int a = 0; a < 3; ++a) {
          const double gx = B.dsx[a][k] * B.sy[b][k], gy = B.sx[a][k] * B.dsy[b][k];
          fx[row + a] += f.xx[k] * gx + f.xy[k] * gy;
          fy[row + a] += f.xy[k] * gx + f.yy[k] * gy;
        }
      }
    }, [&](std::size_t p0) {
      batch_force(P, s.stiffness.data(), p0, int(std::min<std::size_t>(kBatch, end - p0)), f);
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
  tile_layout_kept(s, strip, begin, end, T);
  In* in = tile_buffer(gather_buffer, T.size(), false);
  Lane2* out = tile_buffer(scatter_buffer, T.size(), true);
  for_each_tile_node(s, T, [&](std::size_t t, std::size_t n) {
    if constexpr (kPureFlip)
      in[t] = In{G.dvel_x[n], G.dvel_y[n]};
    else
      in[t] = In{G.dvel_x[n], G.dvel_y[n], G.vel_x[n], G.vel_y[n]};
  });
  const std::size_t cols = std::size_t(T.cols);
  for_each_in_batches(s, begin, end, [&](std::size_t p, int k, const StencilBatch& B) {
    const std::size_t t0 = T.index(P.field[p], B.first_x[k], B.first_y[k]);
    // sum_b sy_b (sum_a sx_a in(a, b)): a row's sum, then the rows.
    In acc = {};  // dv x, dv y [, v x, v y]
    for (int b = 0; b < 3; ++b) {
      const In* r = in + t0 + std::size_t(b) * cols;
      acc += B.sy[b][k] * (B.sx[0][k] * r[0] + B.sx[1][k] * r[1] + B.sx[2][k] * r[2]);
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
    const Lane2 col[3] = {B.sx[0][k] * mv, B.sx[1][k] * mv, B.sx[2][k] * mv};
    for (int b = 0; b < 3; ++b)
      for (int a = 0; a < 3; ++a) out[t0 + std::size_t(b) * cols + std::size_t(a)] += B.sy[b][k] * col[a];
  }, [&](std::size_t p0) {
    for (const std::vector<double>* a : {&P.mass, &P.vx, &P.vy}) prefetch_batch(a->data(), p0);
  });
  for_each_tile_node(s, T, [&](std::size_t t, std::size_t n) {
    G.remap_x[n] += out[t][0];
    G.remap_y[n] += out[t][1];
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
