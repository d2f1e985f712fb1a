// rupture/solver/grid_update.cpp
// Nodal updates of the time step (theory E4) and the prescribed velocities of the edges (E2),
// plain parallel loops over every field's nodes.
#include "solver/grid_update.hpp"

#include <algorithm>
#include <stdexcept>

#include "solver/rank_exchange.hpp"

namespace rupture {

namespace {

// Whether a node's work is counted here: once per node over the ranks (counts_node), and once
// per tied node (solver/cohesive_step.hpp: both fields' copies hold the summed mass and are
// driven alike, so the impulse on that mass is counted on the upper field's copy only).
bool counts_work(const State& s, int field, std::size_t node) {
  const GridFields& G = s.fields;
  for (const BondedTie& b : s.bonded)
    if (b.lower_field == field && std::binary_search(b.nodes.begin(), b.nodes.end(), node) &&
        G.mass[G.index(b.upper_field, node)] > 0.0 && G.mass[G.index(field, node)] > 0.0)
      return false;  // tied this step (both fields had mass there: cohesive_step.cpp)
  return counts_node(s, field, node);
}

}  // namespace

namespace {

// Velocity-BC time function values at the start and end of the step.
inline double bc_value(const State& s, const NodeBC& e, double t) {
  return s.boundary[std::size_t(e.condition)].velocity(t);
}

// The re-map arrays hold v = p / m of the momentum (px, py) (in place when px is remap_x);
// nodes lighter than the mass floor are empty: velocity 0.
void velocity_into_remap(State& s, const double* px, const double* py) {
  GridFields& G = s.fields;
  const long n = long(G.mass.size());
  const double floor = s.mass_floor;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const double m = G.mass[i];
    G.remap_x[i] = m > floor ? px[i] / m : 0.0;
    G.remap_y[i] = m > floor ? py[i] / m : 0.0;
  }
}

}  // namespace

void grid_velocity_from_momentum(State& s, double t) {
  GridFields& G = s.fields;
  velocity_into_remap(s, G.mom_x.data(), G.mom_y.data());
  for (const NodeBC& e : s.bc_nodes) {
    if (!G.holds(e.field, e.node)) continue;  // outside the field's window: no mass there
    const std::size_t i = G.index(e.field, e.node);
    (e.component == 0 ? G.remap_x : G.remap_y)[i] = bc_value(s, e, t);
  }
}

void integrate_grid(State& s) {
  GridFields& G = s.fields;
  const long n = long(G.mass.size());
  const double dt = s.dt, floor = s.mass_floor;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) integrate_node(G, std::size_t(i), dt, floor);
  apply_absorbing_edges(s);
  apply_velocity_bcs(s);
}

void apply_absorbing_edges(State& s) {
  GridFields& G = s.fields;
  const double dt = s.dt;
  for (AbsorbingNode& a : s.absorbing) {
    if (!G.holds(a.field, a.node)) continue;  // outside the field's window: no mass there
    const std::size_t i = G.index(a.field, a.node);
    const double m = G.mass[i];
    if (m <= s.mass_floor) continue;
    // The dashpot force -C v with v the mean of the step's start and end velocities (the
    // trapezoid, consistent with the central-difference step: second order, where an implicit
    // -C v^{n+1} is first order in dt C / m ~ 2 CFL), per component in the edge's frame:
    // m (v - v_free) = -dt C (v0 + v) / 2, so v = (v_free - b v0) / (1 + b), b = dt C / (2 m):
    // stable for any C (no step limit). docs/faults.md: 4.0 % reflected with the implicit form,
    // 1.2 % with this one, for a P pulse of 16 cells.
    const double tx = -a.ny, ty = a.nx;
    const double vx0 = G.mom_x[i] / m, vy0 = G.mom_y[i] / m;
    const double vn = G.vel_x[i] * a.nx + G.vel_y[i] * a.ny, vn0 = vx0 * a.nx + vy0 * a.ny;
    const double vt = G.vel_x[i] * tx + G.vel_y[i] * ty, vt0 = vx0 * tx + vy0 * ty;
    const double bn = 0.5 * dt * a.c_normal / m, bt = 0.5 * dt * a.c_tangent / m;
    const double vn1 = (vn - bn * vn0) / (1.0 + bn), vt1 = (vt - bt * vt0) / (1.0 + bt);
    const double vx1 = vn1 * a.nx + vt1 * tx, vy1 = vn1 * a.ny + vt1 * ty;
    // The dashpot's impulse m (v - v_free) on a node moving at the step's mean velocity: its
    // (negative) work is external work (E14), as for a prescribed velocity.
    if (counts_work(s, a.field, a.node))  // a shared or tied node's work counted once
      s.external_work += m * ((vx1 - G.vel_x[i]) * 0.5 * (vx0 + vx1) +
                              (vy1 - G.vel_y[i]) * 0.5 * (vy0 + vy1));
    G.dvel_x[i] += vx1 - G.vel_x[i], G.dvel_y[i] += vy1 - G.vel_y[i];
    G.vel_x[i] = vx1, G.vel_y[i] = vy1;
    a.vx = vx1, a.vy = vy1;
  }
}

void apply_velocity_bcs(State& s, const std::vector<unsigned char>* only) {
  GridFields& G = s.fields;
  const double t0 = s.time, t1 = s.time + s.dt;
  for (const NodeBC& e : s.bc_nodes) {
    if (!G.holds(e.field, e.node)) continue;  // outside the field's window: no mass there
    const std::size_t i = G.index(e.field, e.node);
    if (only && !(*only)[i]) continue;
    const double m = G.mass[i];
    if (m <= s.mass_floor) continue;
    const double v0 = bc_value(s, e, t0), v1 = bc_value(s, e, t1);
    double& vel = (e.component == 0 ? G.vel_x : G.vel_y)[i];
    double& dvel = (e.component == 0 ? G.dvel_x : G.dvel_y)[i];
    // The constraint's impulse m (V^{n+1} - v_free) acts on a node moving at the mean
    // prescribed velocity over the step: its work is the external work of theory E14.
    if (counts_work(s, e.field, e.node)) s.external_work += m * (v1 - vel) * 0.5 * (v0 + v1);
    dvel += v1 - vel;
    vel = v1;
  }
}

namespace {

// The prescribed velocities at t^{n+1} in the re-mapped velocity (at the elements `only`
// marks, when given).
void remapped_bcs(State& s, const std::vector<unsigned char>* only) {
  GridFields& G = s.fields;
  const double floor = s.mass_floor;
  const double t1 = s.time + s.dt;
  for (const NodeBC& e : s.bc_nodes) {
    if (!G.holds(e.field, e.node)) continue;  // outside the field's window: no mass there
    const std::size_t i = G.index(e.field, e.node);
    if (G.mass[i] <= floor || (only && !(*only)[i])) continue;
    (e.component == 0 ? G.remap_x : G.remap_y)[i] = bc_value(s, e, t1);
  }
}

}  // namespace

void remapped_grid_velocity(State& s, const std::vector<std::uint32_t>& nodes,
                            const std::vector<unsigned char>& only) {
  if (!s.absorbing.empty())  // nested levels refuse absorbing edges (solver/nested_state.hpp)
    throw std::logic_error("remapped_grid_velocity on a node list: absorbing edges");
  GridFields& G = s.fields;
  const long n = long(nodes.size());
  const double floor = s.mass_floor;
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) {
    const std::size_t i = nodes[std::size_t(k)];
    const double m = G.mass[i];
    G.remap_x[i] = m > floor ? G.remap_x[i] / m : 0.0;
    G.remap_y[i] = m > floor ? G.remap_y[i] / m : 0.0;
  }
  remapped_bcs(s, &only);
}

void remapped_grid_velocity(State& s) {
  GridFields& G = s.fields;
  velocity_into_remap(s, G.remap_x.data(), G.remap_y.data());  // in place: re-mapped momentum
  const double floor = s.mass_floor;
  // The absorbing edges keep their dashpot's velocity, as prescribed edges keep theirs: the
  // re-map would otherwise blend it with the inner particles' (FLIP) velocities, and the
  // strain at the edge would not see the absorption (3.4 % reflected instead of 1.2 %, P pulse
  // of 16 cells, docs/faults.md).
  for (const AbsorbingNode& a : s.absorbing) {
    if (!G.holds(a.field, a.node)) continue;
    const std::size_t i = G.index(a.field, a.node);
    if (G.mass[i] <= floor) continue;
    G.remap_x[i] = a.vx, G.remap_y[i] = a.vy;
  }
  // Then the prescribed velocities, as integrate_grid applies them after the dashpots: at a
  // corner of an absorbing edge and a driven one (a roller) the driven component wins in both
  // (the dashpot's velocity there predates it; kept, it made the corner blow up: a plane P
  // pulse between rollers into an absorbing edge, tests/inputs/absorbing_on_levels.toml).
  remapped_bcs(s, nullptr);
}

}  // namespace rupture
