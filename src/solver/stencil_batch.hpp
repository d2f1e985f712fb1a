// rupture/solver/stencil_batch.hpp
// The particle-loop machinery shared by the transfers (solver/transfer.cpp) and the particle
// sort (solver/particle_sort.cpp): GIMP stencils of 16 particles at a time, computed SIMD
// over particles (theory E3), and the two-colour strip loop of ScatterPlan (solver/state.hpp).
// Internal to solver/.
#pragma once
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>

#include "shape/gimp.hpp"
#include "solver/state.hpp"

namespace rupture::detail {

inline constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// Stencils of a batch of consecutive particles, computed SIMD over particles (the weights are
// then reused across the batch's node loops). For particle k: weights sx[a][k], sy[b][k] of
// node (first_x + a, first_y + b) and their derivatives (the field's window holds all nine
// nodes: solver/field_windows.hpp; the loops reach them through their strip's tile,
// solver/strip_tile.hpp).
constexpr int kBatch = 16;
struct StencilBatch {
  alignas(64) double sx[3][kBatch];
  alignas(64) double dsx[3][kBatch];
  alignas(64) double sy[3][kBatch];
  alignas(64) double dsy[3][kBatch];
  int first_x[kBatch], first_y[kBatch];
};

// One axis for n <= kBatch particles: the stencil rule of grid/grid.hpp (stencil()), with
// the weights of gimp_uniform_three written out over plain arrays so the loop vectorizes.
// kGradients = false: dw is left unset where the axis is uniform (the velocity pass reads
// the weights only: a third fewer operations there).
template <bool kGradients = true>
inline void axis_stencils(const Axis& ax, const double* __restrict xp, const double* __restrict lp,
                          int n, double (&w)[3][kBatch], double (&dw)[3][kBatch],
                          int* __restrict first) {
  double* __restrict w0 = w[0];
  double* __restrict w1 = w[1];
  double* __restrict w2 = w[2];
  double* __restrict d0 = dw[0];
  double* __restrict d1 = dw[1];
  double* __restrict d2 = dw[2];
  if (ax.graded()) {
    // Graded axis (theory E3): per particle the first cell, its node and inverse width (table
    // lookups), then the uniform form SIMD over the batch. Where a stencil straddles a change
    // of cell size (cells first-1 .. first+2 not all equal: uniform_from), a batch also looks
    // up the three node coordinates and four widths and takes the graded form (gimp_graded
    // written with selects), SIMD, for those particles.
    alignas(64) double x0[kBatch], xn[3][kBatch], wc[4][kBatch], inv_hl[kBatch], uni[kBatch];
    bool straddles = false;
    const double* coord = ax.coord.data();
    const int last = ax.cells - 1;
    const auto width = [&](int c) {
      c = c < 0 ? 0 : (c > last ? last : c);
      return coord[c + 1] - coord[c];
    };
    // Axis::cell_of(x - lp), its floor and division SIMD over the batch, then the lookups.
    // Clamped first (a NaN to 0), truncation is then floor.
    alignas(64) int unit[kBatch];
    const double origin = ax.origin, h = ax.h, last_unit = double(ax.cell_of_unit.size()) - 1.0;
#pragma omp simd
    for (int k = 0; k < n; ++k) {
      const double q = ((xp[k] - lp[k]) - origin) / h;
      unit[k] = int(!(q >= 0.0) ? 0.0 : (q > last_unit ? last_unit : q));
    }
    for (int k = 0; k < n; ++k) {
      const int c = ax.cell_of_unit[std::size_t(unit[k])];
      first[k] = c;
      x0[k] = coord[c];
      inv_hl[k] = ax.inv_width[std::size_t(c)];
      uni[k] = ax.uniform_from[std::size_t(c)] ? 1.0 : 0.0;
      straddles |= !ax.uniform_from[std::size_t(c)];
    }
#pragma omp simd
    for (int k = 0; k < n; ++k) {
      const double u = (xp[k] - x0[k]) * inv_hl[k], l = lp[k] * inv_hl[k];
      gimp_uniform_three(u - 1.0, l, 0.25 / l, inv_hl[k], w0[k], w1[k], w2[k], d0[k], d1[k], d2[k]);
    }
    if (straddles) {
      for (int k = 0; k < n; ++k) {
        const int c = first[k];
        for (int j = 0; j < 3; ++j) xn[j][k] = coord[std::min(c + j, ax.cells)];
        for (int j = 0; j < 4; ++j) wc[j][k] = width(c + j - 1);
      }
      double* wj[3] = {w0, w1, w2};
      double* dj[3] = {d0, d1, d2};
      for (int j = 0; j < 3; ++j) {
        double* __restrict wo = wj[j];
        double* __restrict dout = dj[j];
        const double* __restrict xj = xn[j];
        const double* __restrict hl = wc[j];
        const double* __restrict hr = wc[j + 1];
#pragma omp simd
        for (int k = 0; k < n; ++k) {
          double s, ds;
          gimp_graded_select(xp[k] - xj[k], hl[k], hr[k], lp[k], s, ds);
          wo[k] = uni[k] != 0.0 ? wo[k] : s;
          dout[k] = uni[k] != 0.0 ? dout[k] : ds;
        }
      }
    }
    return;
  }
  const double inv_h = 1.0 / ax.h, origin = ax.origin;
  double fl[kBatch];
#pragma omp simd
  for (int k = 0; k < n; ++k) {
    const double xi = (xp[k] - origin) * inv_h;
    const double f = uniform_stencil_first(xi);  // grid/grid.hpp (xi > 0: checked after each move)
    fl[k] = f;
    const double u = xi - f, l = lp[k] * inv_h;
    double g0, g1, g2;
    gimp_uniform_three(u - 1.0, l, 0.25 / l, inv_h, w0[k], w1[k], w2[k], g0, g1, g2);
    if constexpr (kGradients) d0[k] = g0, d1[k] = g1, d2[k] = g2;
  }
  for (int k = 0; k < n; ++k) first[k] = int(fl[k]);
}

// Asks for the cache lines a batch kPrefetchAhead particles on will read from one particle
// array. A particle loop streams 10 to 16 arrays at once, more than the hardware prefetchers
// follow; the loads of each batch's first array then stall on memory.
constexpr std::size_t kPrefetchAhead = 64;
template <class T>
inline void prefetch_batch(const T* a, std::size_t p0) {
  static_assert(kBatch * sizeof(double) == 128);
  __builtin_prefetch(a + p0 + kPrefetchAhead);
  if constexpr (sizeof(T) == 8) __builtin_prefetch(a + p0 + kPrefetchAhead + 8);
}

template <bool kGradients = true>
inline void batch_stencils(const State& s, std::size_t p0, int n, StencilBatch& B) {
  const Particles& P = s.particles;
  prefetch_batch(P.x.data(), p0);
  prefetch_batch(P.y.data(), p0);
  prefetch_batch(P.half_x.data(), p0);
  prefetch_batch(P.half_y.data(), p0);
  prefetch_batch(P.field.data(), p0);
  axis_stencils<kGradients>(s.grid.x, P.x.data() + p0, P.half_x.data() + p0, n, B.sx, B.dsx, B.first_x);
  axis_stencils<kGradients>(s.grid.y, P.y.data() + p0, P.half_y.data() + p0, n, B.sy, B.dsy, B.first_y);
#ifndef NDEBUG
  // The 3 x 3 stencil lies in the field's window (the tiles are filled from it).
  const GridFields& G = s.fields;
  for (int k = 0; k < n; ++k) {
    const int f = P.field[p0 + std::size_t(k)];
    assert(G.holds(f, B.first_x[k], B.first_y[k]) && G.holds(f, B.first_x[k] + 2, B.first_y[k] + 2));
  }
#endif
}

// Runs body(p, k, B) for particles [begin, end), batch by batch (k: index in the batch B);
// ahead(p0) first for each batch (the loop's prefetches: prefetch_batch; per-batch factors
// computed SIMD over the batch's particles). kGradients: as in axis_stencils.
template <bool kGradients = true, class Body, class Ahead>
inline void for_each_in_batches(const State& s, std::size_t begin, std::size_t end, Body&& body,
                                Ahead&& ahead) {
  StencilBatch B;
  for (std::size_t p0 = begin; p0 < end; p0 += kBatch) {
    const int n = int(std::min<std::size_t>(kBatch, end - p0));
    ahead(p0);
    batch_stencils<kGradients>(s, p0, n, B);
    for (int k = 0; k < n; ++k) body(p0 + std::size_t(k), k, B);
  }
}

// Runs body(s, strip, begin, end) over the particle range of every strip of every State,
// strips of one colour in parallel (see ScatterPlan). Several States (nested levels) share no
// array: one parallel region, within a colour a thread moves on to the next State's strips
// without waiting for the others, and all wait once per colour.
template <class Body>
void for_each_strip_coloured(State* const* states, std::size_t count, Body&& body) {
#pragma omp parallel
  for (int colour = 0; colour < 2; ++colour) {
    for (std::size_t l = 0; l < count; ++l) {
      State& s = *states[l];
      const ScatterPlan& plan = s.plan;
#pragma omp for schedule(dynamic, 1) nowait
      for (int strip = colour; strip < plan.num_strips; strip += 2)
        body(s, strip, plan.strip_begin[std::size_t(strip)], plan.strip_begin[std::size_t(strip) + 1]);
    }
#pragma omp barrier
  }
}

}  // namespace rupture::detail
