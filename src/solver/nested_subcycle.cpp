// rupture/solver/nested_subcycle.cpp
// Per-level time steps on nested levels (time.subcycling = "levels", docs/performance.md):
// level l takes one step of period[l] finest steps h (its own CFL step: its cells are
// period[l] times the finest), the interface's level and the finer ones every h.
//
// The grid takes every finest step; a level whose step spans several holds its particles'
// scatter from the start of its step (mass, momentum, internal force: the particles have not
// moved, their stress is that of the step's start) and adds it to the other levels' at each
// finest step. Each finest step, after the condensed nodal update:
//   - the held momentum takes its mass times the step's velocity increment, and the
//     increments are summed per node over the level's step;
//   - a level whose step ends gathers the summed increments (FLIP, theory E5), re-maps, and
//     updates stress and position over its whole step (MUSL, with the re-mapped velocity);
//   - a level whose step goes on re-maps, where finer levels read, the velocity its
//     particles would have now without keeping it (band_remap: exact, and needed for
//     stability).
// Each finest step the condensed nodal momentum changes by h times the nodal force, and that
// change goes, node by node, to the levels in proportion to the mass each put there (held or
// fresh), which is exactly what their particles receive when their step ends: total momentum
// is kept to round-off, as in one step per level. A level's step is never longer than its CFL
// step (h is the smallest of level l's limit / period[l]); every level ends together at the
// run's output times and before particles are due to change level (RunState::sync_by,
// migrate), so outputs, checkpoints and migrations see every particle at one time.
// While a level's step goes on, only its coupled nodes (RunState::coupled: where other
// levels' terms meet it, the band's stencils, the ties) are updated each finest step; its
// other nodes carry its held scatter alone, so they are updated once, when its step ends, over
// the whole span (integrate_ending: the same update to round-off, without the whole-lattice
// passes of every finest step).
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "solver/rank_exchange.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/grid_update.hpp"
#include "solver/nested_phases.hpp"
#include "solver/stencil_batch.hpp"
#include "solver/time_step.hpp"
#include "solver/transfer.hpp"

namespace rupture::detail {
namespace {

// Elementwise loops over a list of elements, split over the threads.
template <class Body>
void parallel_list(const std::vector<std::uint32_t>& list, Body&& body) {
  const long count = long(list.size());
#pragma omp parallel for schedule(static)
  for (long k = 0; k < count; ++k) body(std::size_t(list[std::size_t(k)]));
}

// The held scatter of a level: saved when its step begins, put back at every finest step after
// where condense, the ties and the other levels change it (RunState::coupled; elsewhere
// the arrays keep it: nothing else writes there until the level's step ends).
void hold_scatter(GridFields& G, LevelHold& H, const std::vector<std::uint32_t>& coupled) {
  const std::size_t n = G.mass.size();
  for (std::vector<double>* a : {&H.mass, &H.mom_x, &H.mom_y, &H.force_x, &H.force_y, &H.inc_x, &H.inc_y})
    a->resize(n);
  parallel_list(coupled, [&](std::size_t i) {
    H.mass[i] = G.mass[i], H.mom_x[i] = G.mom_x[i], H.mom_y[i] = G.mom_y[i];
    H.force_x[i] = G.force_x[i], H.force_y[i] = G.force_y[i];
  });
}
void restore_scatter(GridFields& G, const LevelHold& H, const std::vector<std::uint32_t>& coupled) {
  parallel_list(coupled, [&](std::size_t i) {
    G.mass[i] = H.mass[i], G.mom_x[i] = H.mom_x[i], G.mom_y[i] = H.mom_y[i];
    G.force_x[i] = H.force_x[i], G.force_y[i] = H.force_y[i];
  });
}

// E4 for a level whose step goes on: at its coupled elements only, with the finest step (the
// others are not read before its step ends), and their prescribed velocities.
void integrate_coupled(State& s, const std::vector<std::uint32_t>& coupled,
                       const std::vector<unsigned char>& mask) {
  GridFields& G = s.fields;
  const double dt = s.dt, floor = s.mass_floor;
  parallel_list(coupled, [&](std::size_t i) { integrate_node(G, i, dt, floor); });
  apply_velocity_bcs(s, &mask);
}

// E4 for a level whose step ends: its coupled elements over the finest step (their earlier
// increments are summed in LevelHold::inc), the others over the whole span in one update:
// their mass and force are the held ones, their momentum the step's start's, and no other
// level adds to them, so this is the sum of the finest steps' updates to round-off. The
// prescribed velocities are constant over a span longer than h (step_subcycled's rule for
// ramps), so the velocity conditions at t + h hold for the whole span.
void integrate_ending(State& s, const std::vector<unsigned char>& mask, double span) {
  GridFields& G = s.fields;
  const double h = s.dt, floor = s.mass_floor;
  const long n = long(G.mass.size());
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) {
    const std::size_t i = std::size_t(k);
    integrate_node(G, i, mask[i] ? h : span, floor);
  }
  apply_velocity_bcs(s);
}

// After the nodal update (velocity increments distributed to the slaves): the level's summed
// increments, and, for a level whose step goes on, its held momentum advanced by its own mass
// times the increment (what its particles will receive: the FLIP gather of the sums), at its
// coupled elements. When its step ends, every other element's increment is its update over
// the whole span (integrate_ending).
void advance_hold(const GridFields& G, LevelHold& H, bool first, bool goes_on,
                  const std::vector<std::uint32_t>& coupled, const std::vector<unsigned char>& mask) {
  if (goes_on) {
    parallel_list(coupled, [&](std::size_t i) {
      const double dx = G.dvel_x[i], dy = G.dvel_y[i];
      H.inc_x[i] = first ? dx : H.inc_x[i] + dx;
      H.inc_y[i] = first ? dy : H.inc_y[i] + dy;
      H.mom_x[i] += H.mass[i] * dx;
      H.mom_y[i] += H.mass[i] * dy;
    });
    return;
  }
  const long n = long(G.mass.size());
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) {
    const std::size_t i = std::size_t(k);
    const bool whole = first || !mask[i];
    H.inc_x[i] = whole ? G.dvel_x[i] : H.inc_x[i] + G.dvel_x[i];
    H.inc_y[i] = whole ? G.dvel_y[i] : H.inc_y[i] + G.dvel_y[i];
  }
}

// The level's particles whose stencil reaches a node of `mixed` (its step begins: they stay
// where they are until it ends), in particle order. Only the first node of each stencil is
// needed (grid/grid.hpp's uniform_stencil_first), looked up in RunState::mixed_reach; the threads take fixed chunks and their lists
// are joined in order.
void find_band(const State& s, const std::vector<unsigned char>& reach, LevelHold& H) {
  const Particles& P = s.particles;
  const int nx = s.grid.nodes_x();
  const double ox = s.grid.x.origin, oy = s.grid.y.origin, ix = 1.0 / s.grid.x.h, iy = 1.0 / s.grid.y.h;
  const auto first = [](double xi) { return int(uniform_stencil_first(xi)); };  // grid/grid.hpp
  std::vector<std::vector<std::uint32_t>> parts;  // shared: one list per thread
  H.band.clear();
#pragma omp parallel
  {
#pragma omp single
    parts.resize(std::size_t(omp_get_num_threads()));
    std::vector<std::uint32_t>& mine = parts[std::size_t(omp_get_thread_num())];
    mine.clear();
#pragma omp for schedule(static)
    for (long p = 0; p < long(P.size()); ++p) {
      const int fx = first((P.x[std::size_t(p)] - ox) * ix), fy = first((P.y[std::size_t(p)] - oy) * iy);
      if (reach[std::size_t(fy) * std::size_t(nx) + std::size_t(fx)]) mine.push_back(std::uint32_t(p));
    }
  }
  for (const std::vector<std::uint32_t>& part : parts) H.band.insert(H.band.end(), part.begin(), part.end());
}

// The re-mapped momentum of a level whose step goes on, where finer levels' particles may read
// it (theory E5's re-map with the velocity its particles would have now: v_p + sum S_ip inc_i;
// the other particles reach no such node). The particles keep their velocity. Exact, where
// the held momentum (v_p + inc_i lumped per node) is not: mixing the two at a node shared
// with a level that re-maps its particles makes the coupled step unstable (a free vibration
// across a transition grew 106 % in 20 000 steps; docs/performance.md).
void band_remap(State& s, const LevelHold& H, const std::vector<std::uint32_t>& coupled) {
  GridFields& G = s.fields;
  const Particles& P = s.particles;
  // The band's stencils lie in the coupled elements, and nothing reads the others' re-mapped
  // momentum before the level's step ends.
  parallel_list(coupled, [&](std::size_t i) { G.remap_x[i] = 0.0, G.remap_y[i] = 0.0; });
  // The band's particles of band[j0, j1), in batches (their stencils SIMD over the batch).
  const auto remap = [&](std::size_t j0, std::size_t j1) {
    alignas(64) double x[kBatch], y[kBatch], hx[kBatch], hy[kBatch];
    StencilBatch2 B;
    for (; j0 < j1; j0 += std::size_t(kBatch)) {
      const int n = int(std::min<std::size_t>(std::size_t(kBatch), j1 - j0));
      for (int k = 0; k < n; ++k) {
        const std::size_t p = H.band[j0 + std::size_t(k)];
        x[k] = P.x[p], y[k] = P.y[p], hx[k] = P.half_x[p], hy[k] = P.half_y[p];
      }
      const Axis* const axis[2] = {&s.grid.x, &s.grid.y};
      const double* const xy[2] = {x, y};
      const double* const lp[2] = {hx, hy};
      rupture::batch_stencils<2>(axis, xy, lp, n, B);
      for (int k = 0; k < n; ++k) {
        const std::size_t p = H.band[j0 + std::size_t(k)];
        const std::size_t base = G.index(P.field[p], B.first[0][k], B.first[1][k]), stride = G.stride(P.field[p]);
        double vx = P.vx[p], vy = P.vy[p];
        for (int b = 0; b < 3; ++b)
          for (int a = 0; a < 3; ++a) {
            const std::size_t i = base + std::size_t(b) * stride + std::size_t(a);
            const double w = B.w[0][a][k] * B.w[1][b][k];
            vx += w * H.inc_x[i], vy += w * H.inc_y[i];
          }
        const double m = P.mass[p];
        for (int b = 0; b < 3; ++b)
          for (int a = 0; a < 3; ++a) {
            const std::size_t i = base + std::size_t(b) * stride + std::size_t(a);
            const double w = m * B.w[0][a][k] * B.w[1][b][k];
            G.remap_x[i] += w * vx, G.remap_y[i] += w * vy;
          }
      }
    }
  };
  // Strip by strip in the two colours of the level's scatter plan (built when its step began;
  // its particles have not moved since): strips of one colour share no node, so no locks, and
  // each node's sum runs in the same order whatever the number of threads (the scatter's rule).
  const ScatterPlan& plan = s.plan;
  const std::uint32_t* band = H.band.data();
  const std::size_t size = H.band.size();
  const auto band_at = [&](std::size_t p) {
    return std::size_t(std::lower_bound(band, band + size, std::uint32_t(p)) - band);
  };
#pragma omp parallel
  for (int colour = 0; colour < 2; ++colour) {
#pragma omp for schedule(dynamic, 1)
    for (int strip = colour; strip < plan.num_strips; strip += 2)
      remap(band_at(plan.strip_begin[std::size_t(strip)]), band_at(plan.strip_begin[std::size_t(strip) + 1]));
  }
}

// h: the smallest of every level's stability limit (theory E6: its CFL step, and on the
// interface's level the cohesive bound) over its period, within the time left to the end.
void subcycled_time_step(RunState& n) {
  double h = INFINITY;
  const double cap = n.levels[0].dt_cap, forced = n.levels[0].forced_dt;
  for (std::size_t l = 0; l < n.levels.size(); ++l) {
    State& s = n.levels[l];
    s.dt_cap = INFINITY;  // the cap applies to h, not to the level's step
    choose_time_step(s);
    s.dt_cap = cap;
    h = std::min(h, s.dt / double(n.period[l]));
  }
  h = min_over_ranks(n.levels[0], h);  // distributed: one h for all ranks
  if (forced > 0.0) h = forced;
  h = std::min(h, cap);
  for (State& s : n.levels) s.dt = h;
  n.dt = h;
}

}  // namespace

void step_subcycled(RunState& n) {
  const std::size_t levels = n.levels.size();
  n.hold.resize(levels);
  thread_local std::vector<State*> starting, ending;
  thread_local std::vector<unsigned char> starts, ends;
  starts.assign(levels, 0), ends.assign(levels, 0);
  starting.clear(), ending.clear();
  for (std::size_t l = 0; l < levels; ++l)
    if (n.substep % n.period[l] == 0) starts[l] = 1, starting.push_back(&n.levels[l]);

  particles_to_grid(starting.data(), starting.size(), true);  // E4: the levels beginning a step
  for (State* s : starting)  // distributed: summed over the ranks before it is held
    halo_sum(*s, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y, &GridFields::force_x,
                  &GridFields::force_y});
  for (std::size_t l = 0; l < levels; ++l) {
    if (n.period[l] == 1) continue;
    if (starts[l]) {
      hold_scatter(n.levels[l].fields, n.hold[l], n.coupled[l]);
      find_band(n.levels[l], n.mixed_reach[l], n.hold[l]);
    } else {
      restore_scatter(n.levels[l].fields, n.hold[l], n.coupled[l]);
    }
  }
  condense_to_dofs(n, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y,
                      &GridFields::force_x, &GridFields::force_y});
  tie_and_face_stencils(levels_of(n));                                  // bonded, faces
  subcycled_time_step(n);                                    // h (E6)

  // Which levels end their step now: their period is over, or every level (the driver's next
  // output or the end of the run, particles due to change level).
  const double h = n.dt;
  double drift = 0.0;
  for (const State& s : n.levels) drift = std::max(drift, s.window_drift);
  int longest = 1;
  for (int p : n.period) longest = std::max(longest, p);
  // While a prescribed edge velocity changes (theory E2: the impact's rise and fall) every level
  // steps every h: a level's step spanning a ramp would strain its particles with the
  // velocity at its end, not over the ramp (62.5 um example: 2.4 % energy balance instead of
  // 1.2 %, all of it from the rise and the fall).
  bool loading = false;
  for (std::size_t l = 0; l < levels && !loading; ++l)
    if (n.period[l] > 1)
      for (const VelocityBC& bc : n.levels[l].boundary)
        loading = loading || bc.velocity(n.time) != bc.velocity(n.time + h);
  const bool all = loading || n.time + h >= n.sync_by || (n.substep + 1) % longest == 0 ||
                   drift >= kSubcycleDrift * kMigrateDrift * n.levels.back().grid.x.h;
  for (std::size_t l = 0; l < levels; ++l) {
    ends[l] = all || (n.substep + 1) % n.period[l] == 0;
    if (ends[l]) ending.push_back(&n.levels[l]);
    if (n.period[l] > 1) n.hold[l].span = starts[l] ? h : n.hold[l].span + h;
  }

  cohesive_forces_and_ties(levels_of(n));  // E7-E9, bonded
  for (std::size_t l = 0; l < levels; ++l) {  // E4 + E2 velocity BCs
    State& s = n.levels[l];
    if (n.period[l] == 1)
      integrate_grid(s);
    else if (ends[l])
      integrate_ending(s, n.coupled_mask[l], n.hold[l].span);
    else
      integrate_coupled(s, n.coupled[l], n.coupled_mask[l]);
  }
  spread_to_slaves(n, {&GridFields::vel_x, &GridFields::vel_y, &GridFields::dvel_x, &GridFields::dvel_y});
  for (std::size_t l = 0; l < levels; ++l) {
    if (n.period[l] == 1) continue;
    LevelHold& H = n.hold[l];
    advance_hold(n.levels[l].fields, H, starts[l] != 0, ends[l] == 0, n.coupled[l], n.coupled_mask[l]);
    if (ends[l]) {  // the gathers read the increments of the whole step
      n.levels[l].fields.dvel_x.swap(H.inc_x);
      n.levels[l].fields.dvel_y.swap(H.inc_y);
    }
  }
  update_particle_velocity_and_remap(ending.data(), ending.size());
  for (std::size_t l = 0; l < levels; ++l)
    if (!ends[l]) band_remap(n.levels[l], n.hold[l], n.coupled[l]);
  // Distributed: every level's re-mapped momentum summed over the ranks (a level whose step
  // goes on: its coupled nodes; its other nodes are not read before its step ends, which
  // clears them).
  for (State& s : n.levels) halo_sum(s, {&GridFields::remap_x, &GridFields::remap_y});
  condense_to_dofs(n, {&GridFields::remap_x, &GridFields::remap_y});
  for (State& s : n.levels) tie_bonded_nodes(s, TieWhat::remapped_momentum);
  for (std::size_t l = 0; l < levels; ++l) {  // + E2 at t + h
    if (ends[l])
      remapped_grid_velocity(n.levels[l]);
    else
      remapped_grid_velocity(n.levels[l], n.coupled[l], n.coupled_mask[l]);
  }
  spread_to_slaves(n, {&GridFields::remap_x, &GridFields::remap_y});
  // The step each ending level's particles take is its span (E5's stress increment and move).
  for (std::size_t l = 0; l < levels; ++l)
    if (ends[l] && n.period[l] > 1) n.levels[l].dt = n.hold[l].span;
  gather(Levels{ending.data(), ending.size(), &n}, &GridFields::remap_x, &GridFields::remap_y,
         G2PMode::stress_and_move);  // E5
  for (State& s : n.levels) s.dt = h;
  n.substep = all ? 0 : n.substep + 1;
}

}  // namespace rupture::detail
