// rupture/solver/grid_update.cpp
// Nodal updates of the time step (SPEC E4) and the prescribed velocities of the edges (E2),
// plain parallel loops over every field's nodes.
#include "solver/grid_update.hpp"

namespace rupture {
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
    if (!G.holds(e.field, e.node)) continue;  // outside the field's window: no mass there
    const std::size_t i = G.index(e.field, e.node);
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

void remapped_grid_velocity(State& s) {
  GridFields& G = s.fields;
  velocity_into_remap(s, G.remap_x.data(), G.remap_y.data());  // in place: re-mapped momentum
  const double floor = s.mass_floor;
  const double t1 = s.time + s.dt;
  for (const NodeBC& e : s.bc_nodes) {
    if (!G.holds(e.field, e.node)) continue;  // outside the field's window: no mass there
    const std::size_t i = G.index(e.field, e.node);
    if (G.mass[i] <= floor) continue;
    (e.component == 0 ? G.remap_x : G.remap_y)[i] = bc_value(s, e, t1);
  }
}

}  // namespace rupture
