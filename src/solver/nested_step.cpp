// rupture/solver/nested_step.cpp
// The phases of the nested levels' time step (solver/nested_phases.hpp): the transitions
// (condense after every scatter, distribute before every gather) and the single-grid MUSL,
// USL and USF steps (solver/step.cpp) run level by level with one dt for every level.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

#include "core/errors.hpp"
#include "parallel/halo.hpp"
#include "solver/cohesive_step.hpp"
#include "solver/grid_update.hpp"
#include "solver/nested_phases.hpp"
#include "solver/time_step.hpp"
#include "solver/transfer.hpp"

namespace rupture::detail {
namespace {
// Fields are whole-lattice on every level: element of (field f, node n) is start[f] + n.
// One column per (field, array) of `arrays`: column c's array on level l starts at
// base[c * levels + l]. The transitions treat up to kMaxColumns columns in one pass, so each
// term's indices are read once for all of them; more columns (many fields) go in chunks of
// kMaxColumns, which gives the same sums (every column is independent of the others).
constexpr std::size_t kMaxColumns = 16;
std::size_t column_bases(NestedState& n, std::initializer_list<NodalArray> arrays,
                         std::vector<double*>& base) {
  const std::size_t levels = n.levels.size(), fields = std::size_t(n.levels[0].fields.num_fields);
  const std::size_t columns = fields * arrays.size();
  base.resize(columns * levels);
  std::size_t c = 0;
  for (std::size_t f = 0; f < fields; ++f)
    for (NodalArray a : arrays) {
      for (std::size_t l = 0; l < levels; ++l) {
        GridFields& G = n.levels[l].fields;
        base[c * levels + l] = (G.*a).data() + G.start[f];
      }
      ++c;
    }
  return columns;
}

}  // namespace

static void condense_columns(NestedState& n, double* const* base, std::size_t columns);
static void distribute_columns(NestedState& n, double* const* base, std::size_t columns);

// grid/nested.hpp's condense over the levels' arrays: every DOF adds c * (slave's value) of
// the slaves it serves, in slave order (the transposed terms: NestedState::dof_start), so the
// threads split the DOFs without sharing one and the sums are those of a loop over the
// slaves; then the slaves are cleared.
void condense_fields(NestedState& n, std::initializer_list<NodalArray> arrays) {
  thread_local std::vector<double*> base_store;
  const std::size_t all = column_bases(n, arrays, base_store), levels = n.levels.size();
  for (std::size_t first = 0; first < all; first += kMaxColumns)
    condense_columns(n, base_store.data() + first * levels, std::min(kMaxColumns, all - first));
}

// The same over `columns` (at most kMaxColumns) columns from `base`.
void condense_columns(NestedState& n, double* const* base, std::size_t columns) {
  const std::size_t levels = n.levels.size();
  const long dofs = long(n.dof_level.size()), slaves = long(n.active_slaves.size());
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (long d = 0; d < dofs; ++d) {
      const std::size_t dl = n.dof_level[std::size_t(d)], dn = n.dof_node[std::size_t(d)];
      double v[kMaxColumns];
      for (std::size_t c = 0; c < columns; ++c) v[c] = base[c * levels + dl][dn];
      for (std::uint32_t j = n.dof_start[std::size_t(d)]; j < n.dof_start[std::size_t(d) + 1]; ++j) {
        const std::uint32_t k = n.dof_slave[j];
        const std::size_t sl = n.slave_level[k], sn = n.slave_node[k];
        const double coef = n.dof_c[j];
        for (std::size_t c = 0; c < columns; ++c) v[c] += coef * base[c * levels + sl][sn];
      }
      for (std::size_t c = 0; c < columns; ++c) base[c * levels + dl][dn] = v[c];
    }
#pragma omp for schedule(static)
    for (long i = 0; i < slaves; ++i) {
      const std::uint32_t k = n.active_slaves[std::size_t(i)];
      const std::size_t sl = n.slave_level[k], sn = n.slave_node[k];
      for (std::size_t c = 0; c < columns; ++c) base[c * levels + sl][sn] = 0.0;
    }
  }
}

// grid/nested.hpp's distribute: every slave from its DOFs (slaves only read DOFs: no race).
void distribute_fields(NestedState& n, std::initializer_list<NodalArray> arrays) {
  thread_local std::vector<double*> base_store;
  const std::size_t all = column_bases(n, arrays, base_store), levels = n.levels.size();
  for (std::size_t first = 0; first < all; first += kMaxColumns)
    distribute_columns(n, base_store.data() + first * levels, std::min(kMaxColumns, all - first));
}

void distribute_columns(NestedState& n, double* const* base, std::size_t columns) {
  const NestedGrid& g = n.grid;
  const std::size_t levels = n.levels.size();
  const long slaves = long(n.active_slaves.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < slaves; ++i) {
    const std::uint32_t k = n.active_slaves[std::size_t(i)];
    double v[kMaxColumns] = {};
    for (std::uint32_t t = g.term_start[k]; t < g.term_start[k + 1]; ++t) {
      const std::size_t tl = n.term_level[t], tn = n.term_node[t];
      const double coef = g.terms[t].c;
      for (std::size_t c = 0; c < columns; ++c) v[c] += coef * base[c * levels + tl][tn];
    }
    const std::size_t sl = n.slave_level[k], sn = n.slave_node[k];
    for (std::size_t c = 0; c < columns; ++c) base[c * levels + sl][sn] = v[c];
  }
}

namespace {

template <class Phase>
void each_level(NestedState& n, Phase&& phase) {
  for (State& s : n.levels) phase(s);
}

// One dt for every level: the smallest of their limits (SPEC E6), over every rank.
void common_time_step(NestedState& n) {
  double dt = INFINITY;
  each_level(n, [&](State& s) {
    choose_time_step(s);
    dt = std::min(dt, s.dt);
  });
  if (n.levels[0].halo) dt = n.levels[0].halo->comm.min(dt);
  each_level(n, [&](State& s) { s.dt = dt; });
  n.dt = dt;
}

}  // namespace

void sum_levels(NestedState& n, std::initializer_list<NodalArray> arrays) {
  each_level(n, [&](State& s) { halo_sum(s, arrays); });
}

void gather_levels(NestedState& n, const std::function<void()>& gather) {
  if (!n.levels[0].halo) return gather();
  try {
    gather();
  } catch (const SimulationError& e) {
    if (n.levels[0].halo->failure.empty()) n.levels[0].halo->failure = e.what();
  }
}

void tie_and_face_stencils(NestedState& n) {
  each_level(n, [](State& s) {
    tie_bonded_nodes(s, TieWhat::mass_momentum);
    if (s.interfaces.empty()) return;
    update_face_stencils(s);
    check_faces_in_reach(s);  // distributed: faces within this rank's halo
  });
}

void cohesive_forces_and_ties(NestedState& n) {
  each_level(n, [](State& s) {
    if (!s.interfaces.empty()) {
      halo_save(s, {&GridFields::force_x, &GridFields::force_y});
      add_cohesive_forces(s);  // E7-E9 (distributed: the owned faces', summed over the ranks)
      halo_sum_added(s, {&GridFields::force_x, &GridFields::force_y});
    }
    tie_bonded_nodes(s, TieWhat::force);
  });
}

std::vector<State*>& level_pointers(NestedState& n) {
  thread_local std::vector<State*> p;
  p.clear();
  for (State& s : n.levels) p.push_back(&s);
  return p;
}

// MUSL (solver/step.cpp's step_musl), level by level, joined at the transitions.
void step_musl(NestedState& n) {
  std::vector<State*>& all = level_pointers(n);
  particles_to_grid(all.data(), all.size(), true);  // E4
  sum_levels(n, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y, &GridFields::force_x,
                 &GridFields::force_y});
  condense_fields(n, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y,
                      &GridFields::force_x, &GridFields::force_y});
  tie_and_face_stencils(n);                                      // bonded, faces
  common_time_step(n);                                           // dt (E6)
  cohesive_forces_and_ties(n);                                   // E7-E9, bonded
  each_level(n, [](State& s) { integrate_grid(s); });            // E4 + E2 velocity BCs
  distribute_fields(n, {&GridFields::vel_x, &GridFields::vel_y, &GridFields::dvel_x, &GridFields::dvel_y});
  update_particle_velocity_and_remap(all.data(), all.size());
  sum_levels(n, {&GridFields::remap_x, &GridFields::remap_y});
  condense_fields(n, {&GridFields::remap_x, &GridFields::remap_y});
  each_level(n, [](State& s) { tie_bonded_nodes(s, TieWhat::remapped_momentum); });
  each_level(n, [](State& s) { remapped_grid_velocity(s); });    // + E2 at t^{n+1}
  distribute_fields(n, {&GridFields::remap_x, &GridFields::remap_y});
  gather_levels(n, [&] {
    grid_to_particles(all.data(), all.size(), &GridFields::remap_x, &GridFields::remap_y,
                      G2PMode::stress_and_move);  // E5
  });
}

void step_usl(NestedState& n) {
  std::vector<State*>& all = level_pointers(n);
  particles_to_grid(all.data(), all.size(), true);
  sum_levels(n, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y, &GridFields::force_x,
                 &GridFields::force_y});
  condense_fields(n, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y,
                      &GridFields::force_x, &GridFields::force_y});
  tie_and_face_stencils(n);
  common_time_step(n);
  cohesive_forces_and_ties(n);
  each_level(n, [](State& s) { integrate_grid(s); });
  distribute_fields(n, {&GridFields::vel_x, &GridFields::vel_y, &GridFields::dvel_x, &GridFields::dvel_y});
  gather_levels(n, [&] {
    grid_to_particles(all.data(), all.size(), &GridFields::vel_x, &GridFields::vel_y,
                      G2PMode::stress_velocity_and_move);
  });
}

void step_usf(NestedState& n) {
  each_level(n, [](State& s) { particles_to_grid(s, false); });
  sum_levels(n, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y});
  condense_fields(n, {&GridFields::mass, &GridFields::mom_x, &GridFields::mom_y});
  common_time_step(n);
  each_level(n, [](State& s) { grid_velocity_from_momentum(s, s.time); });
  distribute_fields(n, {&GridFields::remap_x, &GridFields::remap_y});
  gather_levels(n, [&] {
    each_level(n, [](State& s) { grid_to_particles(s, &GridFields::remap_x, &GridFields::remap_y, G2PMode::stress_only); });
  });
  each_level(n, [](State& s) { particles_to_grid_force(s); });
  sum_levels(n, {&GridFields::force_x, &GridFields::force_y});
  condense_fields(n, {&GridFields::force_x, &GridFields::force_y});
  each_level(n, [](State& s) { integrate_grid(s); });
  distribute_fields(n, {&GridFields::vel_x, &GridFields::vel_y, &GridFields::dvel_x, &GridFields::dvel_y});
  gather_levels(n, [&] {
    each_level(n, [](State& s) { grid_to_particles(s, &GridFields::vel_x, &GridFields::vel_y, G2PMode::velocity_and_move); });
  });
}


}  // namespace rupture::detail
