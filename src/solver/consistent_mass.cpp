// rupture/solver/consistent_mass.cpp
#include "solver/consistent_mass.hpp"

#include <algorithm>

#include "solver/rank_exchange.hpp"
#include "solver/stencil_batch.hpp"
#include "solver/strip_tile.hpp"

namespace rupture {
using namespace detail;

namespace {

constexpr int kBand = 25;  // (dy + 2) * 5 + (dx + 2), dx, dy in [-2, 2]

// Zeroes a in parallel, resizing it only when the windows changed (no allocation per step).
void zero(std::vector<double>& a, std::size_t n) {
  if (a.size() != n) a.assign(n, 0.0);
  double* v = a.data();
  const long count = long(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < count; ++i) v[i] = 0.0;
}

// y = M_C x for kN components at once, interleaved (x[kN e + c]): one pass over the band, the
// solve's cost (25 doubles per node against kN), the components one vector operation. Rows
// three or more from the window's top and bottom read their 25 neighbours without bounds: a
// neighbour off the window's side wraps to the row above or below, inside the same field,
// where the band holds 0 for it (no particle's stencil joins the two); the three rows at
// either end clip their offsets.
template <int kN>
void apply(const State& s, const double* x, double* y) {
  const GridFields& G = s.fields;
  const double* band = s.consistent_mass.band.data();
  for (int f = 0; f < G.num_fields; ++f) {
    const int cols = G.cols[std::size_t(f)], rows = G.rows[std::size_t(f)];
    const std::size_t start = G.start[std::size_t(f)];
#pragma omp parallel for schedule(static)
    for (int j = 0; j < rows; ++j) {
      const bool inner = j >= 3 && j < rows - 3;
      const int dy0 = std::max(-2, -j), dy1 = std::min(2, rows - 1 - j);
      for (int i = 0; i < cols; ++i) {
        const std::size_t e = start + std::size_t(j) * std::size_t(cols) + std::size_t(i);
        const double* row = band + e * kBand;
        double acc[kN] = {};
        if (inner) {
          for (int dy = -2; dy <= 2; ++dy) {
            const std::size_t n0 = std::size_t(long(e) + long(dy) * cols - 2);
            const double* r = row + (dy + 2) * 5;
            for (int dx = 0; dx < 5; ++dx)
              for (int c = 0; c < kN; ++c) acc[c] += r[dx] * x[kN * (n0 + std::size_t(dx)) + std::size_t(c)];
          }
        } else {
          const int dx0 = std::max(-2, -i), dx1 = std::min(2, cols - 1 - i);
          for (int dy = dy0; dy <= dy1; ++dy) {
            const long n0 = long(e) + long(dy) * cols;
            for (int dx = dx0; dx <= dx1; ++dx) {
              const double m = row[(dy + 2) * 5 + dx + 2];
              for (int c = 0; c < kN; ++c) acc[c] += m * x[kN * std::size_t(n0 + dx) + std::size_t(c)];
            }
          }
        }
        for (int c = 0; c < kN; ++c) y[kN * e + std::size_t(c)] = acc[c];
      }
    }
  }
}

// The prescribed velocities (E2) as known values of the solves: a node component driven by a
// [boundary] condition is not solved for; it holds the prescribed velocity at t (a momentum
// solve) or the prescribed acceleration over the step (a force solve), and its neighbours see
// it through M. Solving it with the rest would spread the constraint's reaction force, which
// the lumped force holds at that node, into its neighbours. Lane kN e + c of `fixed` is 1
// for a known value, set in x. `lanes` maps each solved array to (component, what).
enum class Known { velocity_at_start, velocity_at_end, acceleration };
void set_known(State& s, int kN, const Known* what, double* x, unsigned char* fixed) {
  const GridFields& G = s.fields;
  const double t0 = s.time, t1 = s.time + s.dt;
  for (const NodeBC& e : s.bc_nodes) {
    if (!G.holds(e.field, e.node)) continue;
    const std::size_t i = G.index(e.field, e.node);
    if (!(G.mass[i] > s.mass_floor)) continue;
    const VelocityBC& bc = s.boundary[std::size_t(e.condition)];
    for (int c = e.component; c < kN; c += 2) {
      const std::size_t lane = std::size_t(kN) * i + std::size_t(c);
      fixed[lane] = 1;
      switch (what[c]) {
        case Known::velocity_at_start: x[lane] = bc.velocity(t0); break;
        case Known::velocity_at_end: x[lane] = bc.velocity(t1); break;
        case Known::acceleration: x[lane] = (bc.velocity(t1) - bc.velocity(t0)) / s.dt; break;
      }
    }
  }
}

// Richardson sweeps for kN components: b_c <- M_L (alpha_c M_C + (1 - alpha_c) M_L)^-1 b_c,
// the prescribed node components known (set_known).
template <int kN>
void solve(State& s, double* const* b, const double* alpha, const Known* what) {
  const GridFields& G = s.fields;
  State::ConsistentMass& C = s.consistent_mass;
  const std::size_t n = G.size();
  if (C.x.size() != kN * n) C.x.assign(kN * n, 0.0);
  if (C.r.size() != kN * n) C.r.assign(kN * n, 0.0);
  if (C.fixed.size() != kN * n) C.fixed.assign(kN * n, 0);
  double* x = C.x.data();
  double* r = C.r.data();
  unsigned char* fixed = C.fixed.data();
  const double* m = G.mass.data();
  const double floor = s.mass_floor;
  const long count = long(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < count; ++i) {
    const bool on = m[i] > floor;
    for (int c = 0; c < kN; ++c) x[kN * i + c] = on ? b[c][i] / m[i] : 0.0, fixed[kN * i + c] = 0;
  }
  set_known(s, kN, what, x, fixed);
  for (int sweep = 0; sweep < kMassSweeps; ++sweep) {
    // Each rank's band holds its own particles' products: the partial M x sums over the ranks
    // at the nodes they share (x is the same on every copy), as the momentum does.
    apply<kN>(s, x, r);
    halo_sum_lanes(s, r, kN);
    // x += M_L^-1 (b - M x)
#pragma omp parallel for schedule(static)
    for (long i = 0; i < count; ++i) {
      if (!(m[i] > floor)) continue;
      const double inv = 1.0 / m[i];
      for (int c = 0; c < kN; ++c) {
        if (fixed[kN * i + c]) continue;
        double& xi = x[kN * i + c];
        xi += (b[c][i] - alpha[c] * r[kN * i + c] - (1.0 - alpha[c]) * m[i] * xi) * inv;
      }
    }
  }
#pragma omp parallel for schedule(static)
  for (long i = 0; i < count; ++i)
    for (int c = 0; c < kN; ++c) b[c][i] = m[i] * x[kN * i + c];
}

}  // namespace

void assemble_consistent_mass(State& s) {
  GridFields& G = s.fields;
  State::ConsistentMass& C = s.consistent_mass;
  zero(C.band, G.size() * kBand);
  const Particles& P = s.particles;
  double* band = C.band.data();
  State* one = &s;
  // A particle adds to the band rows of its nine nodes, the nodes its scatter adds to: strips
  // of one colour never share one (ScatterPlan), so no race.
  for_each_strip_coloured(&one, 1, [&](State&, int strip, std::size_t begin, std::size_t end) {
    if (begin == end) return;
    // The strip's rows of the band in its tile (solver/strip_tile.hpp), added to the band
    // after: the band written node row by node row, not across the grid per particle.
    thread_local TileLayout T;
    thread_local std::vector<double> buffer;
    tile_layout(s, strip, begin, end, T);
    const std::size_t size = T.size() * kBand;
    double* tile = tile_buffer(buffer, size, true);
    const std::size_t cols = std::size_t(T.cols);
    // Particles whose stencils start at the same node are adjacent (sort_particles): a run of
    // them sums its products m S_i S_j here (an outer product, vector operations) and adds
    // them to the tile once: node i = (a, b) of the stencil takes j = (c, d) in its band slot
    // (d - b + 2) 5 + c - a + 2, three consecutive slots per stencil row d.
    alignas(64) double run[81];
    std::size_t run_t0 = kNone;
    const auto end_run = [&]() {
      if (run_t0 == kNone) return;
#pragma GCC unroll 9
      for (int i = 0; i < 9; ++i) {
        const int a = i % 3, b = i / 3;
        double* row = tile + (run_t0 + std::size_t(b) * cols + std::size_t(a)) * kBand;
#pragma GCC unroll 3
        for (int d = 0; d < 3; ++d) {
          double* slot = row + (d - b + 2) * 5 + 2 - a;
          const double* from = run + 9 * i + 3 * d;
          slot[0] += from[0], slot[1] += from[1], slot[2] += from[2];
        }
      }
    };
    for_each_in_batches<false>(s, begin, end, [&](std::size_t p, int k, const StencilBatch2& B) {
      const std::size_t t0 = T.index(std::size_t(P.field[p]), B.first[0][k], B.first[1][k]);
      if (t0 != run_t0) {
        end_run();
        run_t0 = t0;
        for (double& v : run) v = 0.0;
      }
      double w[9];
      for (int b = 0; b < 3; ++b)
        for (int a = 0; a < 3; ++a) w[3 * b + a] = B.w[0][a][k] * B.w[1][b][k];
      const double m = P.mass[p];
      for (int i = 0; i < 9; ++i) {
        const double mi = m * w[i];
#pragma omp simd
        for (int j = 0; j < 9; ++j) run[9 * i + j] += mi * w[j];
      }
    }, [](std::size_t) {});
    end_run();
    for_each_tile_row(s, T, [&](std::size_t t, std::size_t e, int count) {
      const double* __restrict from = tile + t * kBand;
      double* __restrict to = band + e * kBand;
      for (std::size_t q = 0; q < std::size_t(count) * kBand; ++q) to[q] += from[q];
    });
  });
}

void apply_consistent_mass(const State& s, const double* x, double* y) { apply<1>(s, x, y); }

void solve_mass(State& s, MassSolve kind, double* bx, double* by) {
  double* b[2] = {bx, by};
  const double a = kind == MassSolve::force ? 0.5 : 1.0;
  const double alpha[2] = {a, a};
  const Known k = kind == MassSolve::force              ? Known::acceleration
                  : kind == MassSolve::momentum_at_end ? Known::velocity_at_end
                                                        : Known::velocity_at_start;
  const Known what[2] = {k, k};
  solve<2>(s, b, alpha, what);
}

void solve_momentum_and_force(State& s) {
  GridFields& G = s.fields;
  double* b[4] = {G.mom_x.data(), G.mom_y.data(), G.force_x.data(), G.force_y.data()};
  const double alpha[4] = {1.0, 1.0, 0.5, 0.5};  // M_C for the momentum, M_A for the force
  const Known what[4] = {Known::velocity_at_start, Known::velocity_at_start, Known::acceleration,
                         Known::acceleration};
  solve<4>(s, b, alpha, what);
}

}  // namespace rupture
