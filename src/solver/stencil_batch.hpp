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

#include "bulk/stencil.hpp"
#include "solver/state.hpp"

namespace rupture::detail {

inline constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// The 2D stencils of a batch of consecutive particles (bulk/stencil.hpp): for particle k the
// weights w[0][a][k], w[1][b][k] of node (first[0][k] + a, first[1][k] + b) and their
// derivatives (the field's window holds all nine nodes: solver/field_windows.hpp; the loops
// reach them through their strip's tile, solver/strip_tile.hpp).
using StencilBatch2 = StencilBatch<2>;

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
inline void batch_stencils(const State& s, std::size_t p0, int n, StencilBatch2& B) {
  const Particles& P = s.particles;
  prefetch_batch(P.x.data(), p0);
  prefetch_batch(P.y.data(), p0);
  prefetch_batch(P.half_x.data(), p0);
  prefetch_batch(P.half_y.data(), p0);
  prefetch_batch(P.field.data(), p0);
  const Axis* const axis[2] = {&s.grid.x, &s.grid.y};
  const double* const x[2] = {P.x.data() + p0, P.y.data() + p0};
  const double* const lp[2] = {P.half_x.data() + p0, P.half_y.data() + p0};
  rupture::batch_stencils<2, kGradients>(axis, x, lp, n, B);
#ifndef NDEBUG
  // The 3 x 3 stencil lies in the field's window (the tiles are filled from it).
  const GridFields& G = s.fields;
  for (int k = 0; k < n; ++k) {
    const int f = P.field[p0 + std::size_t(k)];
    assert(G.holds(f, B.first[0][k], B.first[1][k]) && G.holds(f, B.first[0][k] + 2, B.first[1][k] + 2));
  }
#endif
}

// Runs body(p, k, B) for particles [begin, end), batch by batch (k: index in the batch B);
// ahead(p0) first for each batch (the loop's prefetches: prefetch_batch; per-batch factors
// computed SIMD over the batch's particles). kGradients: as in axis_stencils.
template <bool kGradients = true, class Body, class Ahead>
inline void for_each_in_batches(const State& s, std::size_t begin, std::size_t end, Body&& body,
                                Ahead&& ahead) {
  StencilBatch2 B;
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
