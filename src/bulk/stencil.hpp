// rupture/bulk/stencil.hpp
// GIMP stencils of a batch of up to kBatch particles, for any dimension (theory E3): per axis d,
// particle k of the batch, stencil node a (0..2) along d: the weight w[d][a][k], its derivative
// dw[d][a][k] (1/m) and the first node first[d][k]. The weight of node n of the 3^dim stencil is
// the product of the axes' weights (bulk/dimension.hpp: stencil_offset), its gradient component
// d the same product with axis d's derivative. Computed axis by axis, SIMD over the particles of
// the batch (the weights are then reused across the batch's node loops), from raw arrays:
// positions and half-widths per axis, starting at the batch's first particle.
#pragma once
#include <algorithm>
#include <cstddef>

#include "grid/grid.hpp"
#include "shape/gimp.hpp"

namespace rupture {

constexpr int kBatch = 16;

template <int dim>
struct StencilBatch {
  alignas(64) double w[dim][3][kBatch];   // weights along each axis, -
  alignas(64) double dw[dim][3][kBatch];  // their derivatives along that axis, 1/m
  int first[dim][kBatch];                 // the stencil's first node along each axis
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

// The batch's stencils along every axis: axis[d] the grid's axis d, x[d] and lp[d] pointing at
// the batch's first particle's position and half-width along it (m); n <= kBatch particles.
template <int dim, bool kGradients = true>
inline void batch_stencils(const Axis* const* axis, const double* const* x, const double* const* lp,
                           int n, StencilBatch<dim>& B) {
  for (int d = 0; d < dim; ++d)
    axis_stencils<kGradients>(*axis[d], x[d], lp[d], n, B.w[d], B.dw[d], B.first[d]);
}

}  // namespace rupture
